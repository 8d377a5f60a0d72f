// Avatar: a skinned humanoid as the core sees it once a glTF file is loaded — skeleton (with
// canonical-name mapping), inverse bind matrices, one merged skinned mesh, morph targets and the
// body anchors that give every location of the formal model a 3D point.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "skeleton/skeleton.h"

namespace sw::avatar {

// Up to 4 influences per vertex (glTF JOINTS_0/WEIGHTS_0): the budget WebGL2 skinning and the
// SIMD loop are specialised for.
constexpr int kMaxInfluences = 4;

struct Material {
  std::string name;
  glm::vec4 base_color{0.8f, 0.8f, 0.8f, 1.0f};
  float roughness = 0.6f;
  float metallic = 0.0f;
};

struct Primitive {          // a draw call: a range of SkinnedMesh::indices with one material
  std::uint32_t first_index = 0;
  std::uint32_t index_count = 0;
  int material = 0;
};

struct SkinnedMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<std::array<std::uint16_t, kMaxInfluences>> joints;  // skeleton joint indices
  std::vector<glm::vec4> weights;                                 // sum to 1
  std::vector<std::uint32_t> indices;                             // triangles
  std::vector<Primitive> primitives;
  std::vector<Material> materials;
};

struct MorphTarget {
  std::string name;                      // canonical face channel name (face/channels.h)
  std::vector<glm::vec3> position_deltas;  // one per vertex
  std::vector<glm::vec3> normal_deltas;    // one per vertex (may be empty)
};

// A body anchor: a point on the body attached to a joint, so it moves with the skeleton.
struct Anchor {
  std::string name;         // see avatar/body_anchors.h for the naming scheme
  int joint = -1;           // skeleton joint it is attached to
  glm::vec3 offset{0.0f};   // in the joint's bind space (inverse_bind · point), metres:
                            // posed point = model_matrix(joint) · offset, like a rigid vertex
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // outward surface normal at the point, same frame
};

struct Avatar {
  skeleton::Skeleton skeleton;
  // One per skeleton joint; for joints outside the glTF skin (tips, ancestors) the inverse of the
  // rest model matrix, so "bind space" means the same for every joint.
  std::vector<glm::mat4> inverse_bind;
  // canonical joint id (skeleton/humanoid_names.h) -> skeleton joint index, -1 if absent
  std::vector<int> canonical_to_joint;
  SkinnedMesh mesh;
  std::vector<MorphTarget> morphs;
  std::vector<Anchor> anchors;
};

}  // namespace sw::avatar

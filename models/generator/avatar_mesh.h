// Avatar mesh: the polygonised, material-split, simplified body surface plus the eyeballs and the
// tongue, with normals — everything the glTF export needs except skin weights and morphs.
//
// Pipeline: surface nets on a fine grid -> a material per triangle -> vertices duplicated where
// materials meet (identical positions, so meshoptimizer treats the material boundaries as
// attribute seams and simplifies along them without opening cracks) -> meshopt_simplify of the
// whole body to the triangle budget -> normals from the field gradient (smooth across seams).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "implicit_body.h"

namespace sw::avatar_generator {

// Materials of the exported model: the body surfaces, then the separate meshes.
enum class Material : int {
  kSkin = 0,
  kTop,
  kTrousers,
  kShoes,
  kHair,
  kLips,
  kBrows,
  kMouthInner,
  kEyeWhite,
  kIris,
  kTongue,
  kTeeth,
  kCount
};
const char* material_name(Material material);

struct MeshPiece {  // one glTF primitive's worth of geometry
  Material material = Material::kSkin;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<int> nearest_primitive;  // body pieces: field primitive at the vertex; -1 otherwise
  int rigid_joint = -1;                // eyes/tongue: the single joint that carries them
  bool face = false;                   // belongs to the "face" mesh (the one with morph targets)
  std::vector<std::uint32_t> indices;
};

struct AvatarMeshSettings {
  float cell_m = 0.0015f;               // polygonisation grid spacing
  std::size_t triangle_budget = 30000;  // whole model, eyes and tongue included
};

struct AvatarMeshStats {
  std::size_t raw_triangles = 0;
  std::size_t body_triangles = 0;
};

std::vector<MeshPiece> build_avatar_mesh(const ImplicitBody& body, const HumanoidLayout& layout,
                                         const AvatarMeshSettings& settings,
                                         AvatarMeshStats* stats);

}  // namespace sw::avatar_generator

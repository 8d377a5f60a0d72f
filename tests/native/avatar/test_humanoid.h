// A small synthetic humanoid built in code for the avatar and skinning tests: a T-pose figure
// (faces +Z, its left on +X, rest rotations identity) made of tubes and ellipsoids, every joint the
// loader requires plus tips and legs, two materials in two meshes, morph targets that share a name
// across the meshes. It is a tinygltf::Model so tests can mutate it (the malformed-file catalogue)
// before serialising it to GLB bytes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace sw::test {

struct HumanoidOptions {
  enum class Names { Canonical, Mixamo, Vrm1Extension } names = Names::Canonical;
  bool normals = true;                 // write NORMAL (else the loader computes them)
  bool morphs = true;
  std::vector<std::string> omit_joints;  // canonical names of joints to leave out (with subtree)
};

tinygltf::Model make_humanoid_model(const HumanoidOptions& options = {});
std::vector<std::uint8_t> to_glb(const tinygltf::Model& model);
std::vector<std::uint8_t> make_humanoid_glb(const HumanoidOptions& options = {});

// Node index of the joint with this canonical name in make_humanoid_model's output, -1 if absent.
int humanoid_node(const tinygltf::Model& model, const std::string& canonical_name);

// Where the synthetic figure's parts are, for geometric assertions.
struct HumanoidGeometry {
  static constexpr float kHeadCentreY = 1.66f;
  static constexpr float kHeadRadiusZ = 0.095f;
  static constexpr float kTorsoRadiusX = 0.16f;
  static constexpr float kTorsoRadiusZ = 0.10f;
};

}  // namespace sw::test

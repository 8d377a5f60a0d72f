// Synthetic avatar: a small humanoid built in code — a T-pose figure (faces +Z, its left on +X,
// rest rotations identity) of tubes and ellipsoids, with every joint the loader requires plus tips
// and legs, two materials in two meshes, and morph targets sharing a name across the meshes.
// The same bytes natively and in WASM, so it is the input of the native/WASM parity cases, the
// tests (which mutate the tinygltf::Model for the malformed-file catalogue) and the skinning bench
// when models/signweave-avatar.glb is absent. It is NOT the product's avatar (models/ is).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace sw::avatar {

struct SyntheticAvatarOptions {
  enum class Names { Canonical, Mixamo, Vrm1Extension } names = Names::Canonical;
  bool normals = true;                 // write NORMAL (else the loader computes them)
  bool morphs = true;
  std::vector<std::string> omit_joints;  // canonical names of joints to leave out (with subtree)
};

tinygltf::Model make_synthetic_avatar_model(const SyntheticAvatarOptions& options = {});
std::vector<std::uint8_t> synthetic_avatar_to_glb(const tinygltf::Model& model);
std::vector<std::uint8_t> make_synthetic_avatar_glb(const SyntheticAvatarOptions& options = {});

// Node index of the joint with this canonical name in make_synthetic_avatar_model's output, -1 if absent.
int synthetic_avatar_node(const tinygltf::Model& model, const std::string& canonical_name);

// Where the synthetic figure's parts are, for geometric assertions.
struct SyntheticAvatarGeometry {
  static constexpr float kHeadCentreY = 1.61f;  // the eye joints (1.625) just above the centre
  static constexpr float kHeadRadiusZ = 0.095f;
  static constexpr float kTorsoRadiusX = 0.16f;
  static constexpr float kTorsoRadiusZ = 0.10f;
};

}  // namespace sw::avatar

// The project's one procedural humanoid: a 1.70 m adult skeleton with VRM 1.0 joint names, the
// project's bind convention (identity rest rotations, T-pose, arms along +-X, palms down, facing
// +Z, +X the signer's left) and plausible proportions (metres). It is the fixed input of the FK
// benchmark, the native/WASM parity cases and the tests, so none of them depends on an avatar
// file. Two consumers dress it: avatar/synthetic_avatar (a glTF model with a mesh, for the loader
// and skinning tests) and synthesis/reference_humanoid (an Avatar with body anchors, for the
// synthesis tests).
//
// 73 joints with finger metacarpals: hips, spine, chest, upperChest, neck, head, jaw, both eyes;
// per side shoulder, upper arm, lower arm, hand, thumb metacarpal/proximal/distal/tip, for index..
// little metacarpal/proximal/intermediate/distal/tip, upper leg, lower leg, foot, toes. Without
// the finger metacarpals (most rigs have none) it is the 65-joint skeleton issue 2's FK benchmark
// names. Stored depth first, parents before children.
//
// Does not: model a real body's proportions beyond the rough ones a test needs; the product's
// avatar is models/ and src/avatar.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "math/transform.h"
#include "skeleton/skeleton.h"

namespace sw::skeleton {

struct SyntheticHumanoidOptions {
  bool finger_metacarpals = false;  // index..little metacarpals (73 joints instead of 65)
};

Skeleton make_synthetic_humanoid(const SyntheticHumanoidOptions& options = {});

// Model-space bind position of every joint of a skeleton whose rest rotations are identity (as
// make_synthetic_humanoid's are): the sum of the rest translations along the chain.
std::vector<glm::vec3> rest_positions(const Skeleton& skeleton);

// A deterministic pose for it: every joint's rest transform with a rotation of up to max_angle_rad
// about a pseudo-random axis, from a seed (the same numbers natively and in WASM: integer hashing,
// no <random> distributions, whose output is not specified across standard libraries).
std::vector<math::Transform> make_synthetic_pose(const Skeleton& skeleton, std::uint32_t seed,
                                                 float max_angle_rad = 0.6f);

}  // namespace sw::skeleton

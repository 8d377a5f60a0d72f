// A procedurally built 65-joint humanoid skeleton with VRM 1.0 joint names and plausible rest
// offsets (metres, +Y up, facing +Z): the fixed input of the FK benchmark, the native/WASM parity
// cases and the tests, so none of them depends on an avatar file.
//
// 65 joints: hips, spine, chest, upperChest, neck, head, jaw, both eyes; per side shoulder, upper
// arm, lower arm, hand, thumb metacarpal/proximal/distal/tip and for index..little proximal/
// intermediate/distal/tip; per side upper leg, lower leg, foot, toes. Stored depth first.
//
// Does not: model a real body's proportions beyond the rough ones a test needs; the avatar is
// models/ and src/avatar.
#pragma once

#include <cstdint>
#include <vector>

#include "math/transform.h"
#include "skeleton/skeleton.h"

namespace sw::skeleton {

Skeleton make_synthetic_humanoid();

// A deterministic pose for it: every joint's rest transform with a rotation of up to max_angle_rad
// about a pseudo-random axis, from a seed (the same numbers natively and in WASM: integer hashing,
// no <random> distributions, whose output is not specified across standard libraries).
std::vector<math::Transform> make_synthetic_pose(const Skeleton& skeleton, std::uint32_t seed,
                                                 float max_angle_rad = 0.6f);

}  // namespace sw::skeleton

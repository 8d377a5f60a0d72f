// Frame corrections: the mechanics the per-frame collision clearing of a sign (sign_motion.cpp)
// shares: the ramps that spread a correction decided for one frame (a swivel offset, a push of
// the hand's target, a turn of the hand) over its neighbours so it comes on and goes off
// smoothly, and the search for the nearest swivel offset that clears the arm.
#pragma once

#include <functional>
#include <vector>

#include "synthesis/rig.h"

namespace sw::synthesis {

// Weight of a correction `distance` frames away within a ramp of `radius` frames: a smoothstep
// envelope, 1 at distance 0 and 0 from radius + 1 on, with zero slope at both ends (no velocity
// step where the ramp starts, nor at a single frame's peak: a linear tent turns round at its
// peak and the hand reversed there, THANK-YOU's wrist 94 mm change of step in one frame).
float ramp_weight(int distance, int radius);

// Per frame, the largest of the neighbouring corrections (by magnitude, the frame's own
// included) scaled by ramp_weight: every frame keeps at least its own correction, and the
// corrections ease in and out around it.
std::vector<float> ramp_scalars(const std::vector<float>& fix, int radius);
std::vector<glm::vec3> ramp_offsets(const std::vector<glm::vec3>& fix, int radius);
// Turns: the largest neighbouring angle, slerped from identity by the weight.
std::vector<glm::quat> ramp_turns(const std::vector<glm::quat>& fix, int radius);

// The swivel offset that clears an arm: the nearest of 0.1 rad steps (up to 1.2 rad) whose
// depth is at most `clear_m`, searched outwards both ways, the `prefer` side (+1 / -1) first
// (0: the + side first, the nearest wins). With a preferred side, a clear offset on the other
// side is taken only if the preferred side has none within kPreferSlackSteps more steps.
// `depth_at(offset, &usable)` poses the arm at base + offset and returns its depth (m); an
// unusable offset (a touch that no longer touches) is skipped. Without a clear offset, the
// largest improvement over `base_depth_m` wins if it gains at least `min_gain_m` (and more than
// 0.1 mm); none: offset 0. `only_prefer`: the `prefer` side alone is searched (a run of frames
// whose side was chosen as a whole, sign_motion.cpp: the other side is not an option there).
constexpr int kPreferSlackSteps = 3;
struct SwivelChoice {
  float offset_rad = 0.0f;
  float depth_m = 0.0f;
};
SwivelChoice nearest_clear_swivel(float base_depth_m, float clear_m, float prefer, float min_gain_m,
                                  const std::function<float(float offset_rad, bool* usable)>& depth_at,
                                  bool only_prefer = false);

}  // namespace sw::synthesis

// Clip sampler: a clip at any time t -> local joint transforms (rotation slerped between the two
// nearest frames on the shortest path, root translation and morph weights lerped). Runtime in the
// ozz sense: no allocation, writes into caller buffers (the page hands WASM memory views).
#pragma once

#include "math/transform.h"
#include "skeleton/skeleton.h"
#include "synthesis/clip.h"

namespace sw::synthesis {

// Rotations (clip.joint_count()), root translation and morph weights (clip.morph_count()) at t
// seconds; t is clamped to [0, duration]. Any output pointer may be null.
void sample_clip(const Clip& clip, double t_s, glm::quat* rotations, glm::vec3* root_translation,
                 float* morph_weights);

// Full local transforms for `skeleton` (which must be the clip's skeleton: same joint count):
// rest translation and scale, sampled rotation, sampled root translation on joint 0.
// False if the joint counts differ.
bool sample_clip_local(const Clip& clip, const skeleton::Skeleton& skeleton, double t_s,
                       math::Transform* out);

}  // namespace sw::synthesis

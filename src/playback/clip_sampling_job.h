// ClipSamplingJob: the pose of a Clip at any time t — the runtime half of a clip (ozz-animation's
// SamplingJob): per joint the local rotation slerped between the two frames around t, the root
// translation and the morph weights interpolated linearly, written into caller-owned buffers (an
// AvatarInstance's locals and morph weights in the page).
//
//   ClipSamplingJob job;
//   job.clip = &clip; job.skeleton = &avatar.skeleton; job.time_s = t;
//   job.clip_to_morph = ...;              // optional: clip morph channel -> avatar morph index
//   job.output_locals = instance.locals(); job.output_morph_weights = instance.morph_weights();
//   if (!job.run()) ...                    // run() validates first
//
// Time outside [0, duration] is clamped (the page loops by wrapping t itself). Joints the clip does
// not animate keep their rest transform; only joint 0 takes the clip's root translation.
//
// Does not: blend clips, loop, or allocate.
#pragma once

#include <string>

#include "math/span.h"
#include "math/transform.h"
#include "skeleton/skeleton.h"
#include "synthesis/clip.h"

namespace sw::playback {

struct ClipSamplingJob {
  const synthesis::Clip* clip = nullptr;        // required; clip->joint_count() must equal the skeleton's
  const skeleton::Skeleton* skeleton = nullptr; // required: rest transforms for translation and scale
  double time_s = 0.0;
  // Optional: for each clip morph channel, the output index it drives (-1: none).
  math::Span<const int> clip_to_morph;
  math::Span<math::Transform> output_locals;    // skeleton->joint_count() transforms; required
  math::Span<float> output_morph_weights;       // may be empty when clip_to_morph is

  // Empty when run() can proceed; else what is wrong with the configuration.
  std::string validate() const;
  bool run() const;
};

}  // namespace sw::playback

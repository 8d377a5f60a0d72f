// LocalToModelJob: forward kinematics — local joint transforms to model-space matrices, in one pass
// over the parents-before-children joint array (ozz-animation's job of the same name).
//
//   LocalToModelJob job;
//   job.skeleton = &skeleton;
//   job.input = local_transforms;     // one per joint
//   job.output = model_matrices;      // one per joint
//   if (!job.run()) ...               // run() validates first
//
// Partial update: after IK has changed only the right hand's sub-tree, set `from` to the hand's
// index; only that joint and its descendants are recomputed, reading the model matrix of `from`'s
// parent from `output` (so `output` must hold a complete, up-to-date pose from an earlier run).
// `to` stops the pass after that joint index (inclusive), e.g. to skip the legs.
//
// Does not: allocate, own buffers, or read rest poses — the input is the full local pose (start
// from each joint's `rest` for unanimated joints).
#pragma once

#include <glm/glm.hpp>

#include "math/span.h"
#include "math/transform.h"
#include "skeleton/skeleton.h"

namespace sw::skeleton {

struct LocalToModelJob {
  // The joint tree; must outlive run(). Required.
  const Skeleton* skeleton = nullptr;
  // Local transforms (relative to the parent), skeleton->joint_count() of them. Set exactly one of
  // `input` and `input_matrices` (the latter for poses that are already matrices, e.g. from glTF).
  math::Span<const math::Transform> input;
  math::Span<const glm::mat4> input_matrices;
  // Model-space matrices, skeleton->joint_count() of them. Required.
  math::Span<glm::mat4> output;
  // Optional transform applied above the roots (the avatar's placement); nullptr means identity.
  const glm::mat4* root = nullptr;
  // -1: update every joint; else the root joint of the sub-tree to update (see above).
  int from = -1;
  // Last joint index updated (inclusive); the default updates to the end of the array.
  int to = kEndOfSkeleton;

  static constexpr int kEndOfSkeleton = 0x7fffffff;

  // True when the fields describe a job that run() can do: skeleton set, buffers large enough,
  // exactly one input, from in [-1, joint_count), to >= from.
  bool validate() const;
  // Validates, then computes. False (and output untouched) if invalid.
  bool run() const;
};

}  // namespace sw::skeleton

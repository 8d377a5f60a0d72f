// Pose -> matrices: the two jobs between a pose (local joint transforms) and the skinning palette.
//
//   LocalToModelJob     local TRS of every joint -> model-space matrix of every joint (FK),
//                       parents-before-children order makes it one pass (skeleton.h).
//   SkinningMatrixJob   model matrix x inverse bind matrix -> the matrix that takes a bind-pose
//                       vertex to its posed position (glTF 2.0 §3.7.3.3 "jointMatrix").
//
// ozz-style jobs: plain structs whose public fields are the inputs and outputs, which never
// allocate; validate() returns an empty string when the configuration is usable, else what is
// wrong. run() validates first and does nothing (returns false) on an invalid job.
// Does NOT: blend poses, or handle the glTF node above the skeleton root (the loader bakes the
// skeleton root's ancestors into the root's rest transform).
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "math/transform.h"
#include "skeleton/skeleton.h"

namespace sw::skinning {

struct LocalToModelJob {
  const skeleton::Skeleton* skeleton = nullptr;
  const math::Transform* locals = nullptr;   // skeleton->joint_count() local transforms
  int local_count = 0;
  glm::mat4* models = nullptr;               // output, skeleton->joint_count() matrices
  int model_count = 0;
  // Partial update (ozz "from"): only joints with index >= from_joint are recomputed; the
  // models of earlier joints must already be valid (e.g. after IK only the hands change).
  int from_joint = 0;

  std::string validate() const;
  bool run() const;
};

struct SkinningMatrixJob {
  const glm::mat4* models = nullptr;         // joint_count model matrices
  const glm::mat4* inverse_binds = nullptr;  // joint_count inverse bind matrices
  int joint_count = 0;
  glm::mat4* skinning_matrices = nullptr;    // output, joint_count matrices

  std::string validate() const;
  bool run() const;
};

// M = T * R * S (glTF 2.0 §5.25), written out for the FK loop.
glm::mat4 compose_trs(const math::Transform& t);

}  // namespace sw::skinning

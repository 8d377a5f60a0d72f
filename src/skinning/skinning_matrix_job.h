// SkinningMatrixJob: the skinning palette — model matrix x inverse bind matrix for every joint, the
// matrix that takes a bind-pose vertex to its posed position (glTF 2.0 §3.7.3.3 "jointMatrix").
// Forward kinematics before it is skeleton/local_to_model.h.
//
// ozz-style job: a plain struct whose public fields are the inputs and outputs; it never
// allocates; validate() returns an empty string when the configuration is usable, else what is
// wrong; run() validates first and does nothing (returns false) on an invalid job.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace sw::skinning {

struct SkinningMatrixJob {
  const glm::mat4* models = nullptr;         // joint_count model matrices
  const glm::mat4* inverse_binds = nullptr;  // joint_count inverse bind matrices
  int joint_count = 0;
  glm::mat4* skinning_matrices = nullptr;  // output, joint_count matrices

  std::string validate() const;
  bool run() const;
};

}  // namespace sw::skinning

// SkinningMatrixJob: the skinning palette. See skinning_matrix_job.h.
#include "skinning/skinning_matrix_job.h"

namespace sw::skinning {

std::string SkinningMatrixJob::validate() const {
  if (!models) return "SkinningMatrixJob: no model matrices";
  if (!inverse_binds) return "SkinningMatrixJob: no inverse bind matrices";
  if (!skinning_matrices) return "SkinningMatrixJob: no output matrices";
  if (joint_count < 0) return "SkinningMatrixJob: negative joint count";
  return {};
}

bool SkinningMatrixJob::run() const {
  if (!validate().empty()) return false;
  for (int i = 0; i < joint_count; ++i) skinning_matrices[i] = models[i] * inverse_binds[i];
  return true;
}

}  // namespace sw::skinning

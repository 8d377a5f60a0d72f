// Pose -> matrices jobs (FK and skinning palette). See local_to_model_job.h.
#include "skinning/local_to_model_job.h"

#include <glm/gtc/quaternion.hpp>

namespace sw::skinning {

glm::mat4 compose_trs(const math::Transform& t) {
  glm::mat4 m = glm::mat4_cast(t.rotation);
  m[0] *= t.scale.x;
  m[1] *= t.scale.y;
  m[2] *= t.scale.z;
  m[3] = glm::vec4(t.translation, 1.0f);
  return m;
}

std::string LocalToModelJob::validate() const {
  if (!skeleton) return "LocalToModelJob: no skeleton";
  const int n = skeleton->joint_count();
  if (!locals) return "LocalToModelJob: no local transforms";
  if (!models) return "LocalToModelJob: no output matrices";
  if (local_count < n) return "LocalToModelJob: fewer local transforms than joints";
  if (model_count < n) return "LocalToModelJob: output smaller than the joint count";
  if (from_joint < 0 || from_joint > n) return "LocalToModelJob: from_joint out of range";
  for (int i = from_joint; i < n; ++i) {
    const int parent = skeleton->joints[static_cast<std::size_t>(i)].parent;
    if (parent >= i || parent < -1) return "LocalToModelJob: joint parent not before child";
  }
  return {};
}

bool LocalToModelJob::run() const {
  if (!validate().empty()) return false;
  const int n = skeleton->joint_count();
  for (int i = from_joint; i < n; ++i) {
    const int parent = skeleton->joints[static_cast<std::size_t>(i)].parent;
    const glm::mat4 local = compose_trs(locals[i]);
    models[i] = parent < 0 ? local : models[parent] * local;
  }
  return true;
}

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

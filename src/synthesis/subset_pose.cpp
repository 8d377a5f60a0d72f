// SubsetPose: forward kinematics of a subset of joints (see subset_pose.h).
#include "synthesis/subset_pose.h"


#include "math/quat_lanes.h"

namespace sw::synthesis {
SubsetPose::SubsetPose(const Rig& rig, const std::vector<int>& wanted)
    : rig_(rig), model_(static_cast<size_t>(rig.joint_count)), delta_(static_cast<size_t>(rig.joint_count)),
      pos_(static_cast<size_t>(rig.joint_count)), last_local_(static_cast<size_t>(rig.joint_count)),
      recomputed_(static_cast<size_t>(rig.joint_count), 1) {
  std::vector<char> in(static_cast<size_t>(rig.joint_count), 0);
  for (int j : wanted)
    for (int a = j; a >= 0 && a < rig.joint_count && !in[static_cast<size_t>(a)]; a = rig.parent[static_cast<size_t>(a)])
      in[static_cast<size_t>(a)] = 1;
  // Skeleton order puts parents before children (skeleton.h), so index order is FK order.
  for (int j = 0; j < rig.joint_count; ++j)
    if (in[static_cast<size_t>(j)]) joints_.push_back(j);
}

void SubsetPose::set_from_local(const glm::quat* local) {
  const Rig& r = rig_;
  using namespace math::lanes;
  // PoseBuilder::set_from_local, joint for joint (the same incremental rule, the same lane
  // operations in the same order): model = model[p] * local; delta = normalize(model *
  // conjugate(bind)); pos = pos[p] + delta[p] * (bind offset). Positions equal the full pose's to
  // the bit (SubsetPose tests).
  for (int j : joints_) {
    const int p = r.parent[static_cast<size_t>(j)];
    if (last_valid_ && (p < 0 || !recomputed_[static_cast<size_t>(p)]) &&
        math::lanes::same_bits(local[j], last_local_[static_cast<size_t>(j)])) {
      recomputed_[static_cast<size_t>(j)] = 0;
      continue;
    }
    recomputed_[static_cast<size_t>(j)] = 1;
    last_local_[static_cast<size_t>(j)] = local[j];
    const Float4 m = p < 0 ? load4(local[j]) : quat_mul(load4(model_[static_cast<size_t>(p)]), load4(local[j]));
    store4(&model_[static_cast<size_t>(j)], m);
    store4(&delta_[static_cast<size_t>(j)], quat_normalize(quat_mul(m, load4(r.bind_rot_conj[static_cast<size_t>(j)]))));
    if (p < 0) {
      pos_[static_cast<size_t>(j)] = r.bind_pos[static_cast<size_t>(j)];
    } else {
      const Float4 moved = load3(pos_[static_cast<size_t>(p)]) +
                           quat_rotate(load4(delta_[static_cast<size_t>(p)]), load4(r.bind_offset[static_cast<size_t>(j)]));
      pos_[static_cast<size_t>(j)] = glm::vec3(moved[0], moved[1], moved[2]);
    }
  }
  last_valid_ = true;
}

}  // namespace sw::synthesis

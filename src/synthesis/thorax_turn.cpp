// Thorax turn towards the far side (thorax_turn.h).
#include "synthesis/thorax_turn.h"

namespace sw::synthesis {

glm::quat thorax_turn_share(const ThoraxTurn& turn, float s) {
  const float angle = rotation_angle(turn.rotation);
  if (angle < 1e-7f) return glm::quat(1, 0, 0, 0);
  const glm::vec3 axis = glm::normalize(glm::vec3(turn.rotation.x, turn.rotation.y, turn.rotation.z)) *
                         (turn.rotation.w < 0.0f ? -1.0f : 1.0f);
  return glm::angleAxis(s * angle, axis);
}

ThoraxTurn make_thorax_turn(const Rig& rig, float angle_rad, float lean_rad, float head_rad) {
  ThoraxTurn t;
  for (int j : {rig.spine, rig.chest, rig.upper_chest})
    if (j >= 0) t.chain.push_back(j);
  if (t.chain.empty()) return t;
  t.angle_rad = angle_rad;
  t.lean_rad = lean_rad;
  t.head_rad = head_rad;
  t.top = t.chain.back();
  // The twist, then the lean: about the body's left axis, up tips towards forward.
  t.rotation = glm::normalize(axis_angle(rig.left, lean_rad) * axis_angle(rig.up, angle_rad));
  PoseBuilder pb(rig);
  pose_thorax_turn(rig, t, &pb);
  pb.finalize();
  t.pivot_bind = rig.bind_pos[t.top];
  t.pivot_posed = pb.position(t.top);
  return t;
}

void pose_thorax_turn(const Rig& rig, const ThoraxTurn& turn, PoseBuilder* pose) {
  const float n = static_cast<float>(turn.chain.size());
  for (size_t k = 0; k < turn.chain.size(); ++k)
    pose->set(turn.chain[k], thorax_turn_share(turn, static_cast<float>(k + 1) / n));
  if (rig.neck >= 0)
    pose->set(rig.neck, axis_angle(rig.up, turn.head_rad) * thorax_turn_share(turn, 1.0f - kHeadTurnBack));
}

void apply_thorax_turn(const Rig& rig, const ThoraxTurn& turn, glm::quat* locals) {
  if (!turn.active()) return;
  // local_j = L_j R_j^-1 D_p^-1 D_j R_j (rig.h). With the chain and the neck unposed in the
  // thorax frame (D = identity), giving joint j the model-space rotation Q relative to its
  // parent's turned frame makes its local L_j R_j^-1 Q R_j L_j^-1 times the old one; the joints
  // above the upper chest keep their locals (their parent turned with them).
  auto turn_local = [&](int j, const glm::quat& q) {
    const glm::quat m = rig.bind_local_rot[j] * glm::conjugate(rig.bind_rot[j]) * q * rig.bind_rot[j] *
                        glm::conjugate(rig.bind_local_rot[j]);
    locals[j] = glm::normalize(m * locals[j]);
  };
  const float step = 1.0f / static_cast<float>(turn.chain.size());
  for (int j : turn.chain) turn_local(j, thorax_turn_share(turn, step));
  // The neck: pose_thorax_turn's model-space delta H R^(1/4) (H the head's own turn about up)
  // relative to the upper chest's R: R^-1 H R R^(-3/4).
  if (rig.neck >= 0)
    turn_local(rig.neck, glm::conjugate(turn.rotation) * axis_angle(rig.up, turn.head_rad) * turn.rotation *
                             thorax_turn_share(turn, -kHeadTurnBack));
}

}  // namespace sw::synthesis

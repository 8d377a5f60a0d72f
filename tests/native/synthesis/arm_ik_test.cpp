// Arm IK on a path (arm_ik.h ArmTarget::previous): a hand orientation turned through a full turn
// takes the wrist beyond its limits, where the free solve flips the clamped wrist angles from
// one limit to the other between two steps; continuing from the previous pose, no wrist angle
// moves further than the allowed step and the contact point still reaches its target.
#include "synthesis/arm_ik.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

float wrist_change(const ArmPose& a, const ArmPose& b) {
  return std::max({std::fabs(a.twist_rad - b.twist_rad), std::fabs(a.wrist_dev_rad - b.wrist_dev_rad),
                   std::fabs(a.wrist_flex_rad - b.wrist_flex_rad)});
}

TEST(SynthesisArmIk, ContinuedWristNeverFlipsAndStillReaches) {
  avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error)) << error;
  const ArmRig& a = rig.arms[kRight];
  ArmTarget t;
  t.point = rig.bind_pos[a.upper] + 0.35f * rig.forward - 0.15f * rig.up - 0.1f * rig.left;
  t.contact_offset = 0.18f * a.finger_dir;  // a fingertip: orientation moves the wrist round it
  t.auto_swivel = false;
  t.swivel_rad = 0.4f;
  const int steps = 72;
  const float max_step = 0.2f;
  float free_worst = 0.0f, continued_worst = 0.0f, worst_reach = 0.0f;
  ArmPose free_prev, cont_prev;
  for (int k = 0; k <= steps; ++k) {
    const float angle = 2.0f * 3.14159265f * static_cast<float>(k) / steps;
    t.hand_delta = axis_angle(glm::normalize(rig.forward + 0.5f * rig.up), angle);
    ArmTarget free_target = t;
    ArmPose free_pose = solve_arm(rig, kRight, free_target);
    ArmTarget cont_target = t;
    if (k > 0) {
      cont_target.previous = &cont_prev;
      cont_target.max_wrist_step_rad = max_step;
    }
    ArmPose cont_pose = solve_arm(rig, kRight, cont_target);
    if (k > 0) {
      free_worst = std::max(free_worst, wrist_change(free_pose, free_prev));
      continued_worst = std::max(continued_worst, wrist_change(cont_pose, cont_prev));
    }
    worst_reach = std::max(worst_reach, cont_pose.reach_error_m);
    free_prev = free_pose;
    cont_prev = cont_pose;
  }
  // The free solve flips (a request turning 5 degrees a step moves no angle by 1 rad otherwise).
  EXPECT_GT(free_worst, 1.0f);
  EXPECT_LE(continued_worst, max_step + 1e-4f);
  EXPECT_LT(worst_reach, 0.01f);
}

}  // namespace
}  // namespace sw::synthesis

// Arm IK: places a point of the hand (the contact part) on a target with a requested hand
// orientation. Analytic two-bone solve (upper arm, forearm) with the elbow on its swivel circle,
// clavicle (shoulder joint) participation for high and far targets, and the wrist solved for the
// orientation: forearm twist (pronation/supination) takes the roll, the wrist takes flexion and
// deviation, each within anatomical limits; what the limits refuse stays as orientation error.
#pragma once

#include "synthesis/rig.h"

namespace sw::synthesis {

// Anatomical limits (radians; degrees in comments) — joint limits everywhere.
struct ArmLimits {
  float elbow_flex_max = 2.62f;     // 150: a forearm cannot fold further onto the upper arm
  float twist_lo = -1.57f, twist_hi = 1.57f;  // forearm rotation +-90 from the bind's palm-down
  float wrist_flex = 1.31f;         // 75 towards the palm
  float wrist_ext = 1.13f;          // 65 back
  float radial_dev = 0.35f;         // 20
  float ulnar_dev = 0.61f;          // 35
  float clavicle_elevation = 0.35f; // 20: shrug for high targets
  float clavicle_protraction = 0.30f;  // 17: reach forward for far targets
};
const ArmLimits& arm_limits();

struct ArmTarget {
  glm::vec3 point{0.0f};            // where the contact point must go (model space)
  glm::vec3 contact_offset{0.0f};   // contact point minus wrist, hand in its bind orientation
  glm::quat hand_delta{1, 0, 0, 0}; // requested hand orientation (orientation.h)
  bool auto_swivel = true;          // choose the elbow swivel by the comfort heuristic
  float swivel_rad = 0.4f;          // used when !auto_swivel: 0 elbow down, + elbow out
};

struct ArmPose {
  glm::quat shoulder{1, 0, 0, 0}, upper{1, 0, 0, 0}, lower{1, 0, 0, 0}, hand{1, 0, 0, 0};
  float swivel_rad = 0.0f;
  float reach_error_m = 0.0f;        // |achieved contact point - target|
  float orientation_error_rad = 0.0f;// angle between requested and achieved hand rotation
  float elbow_flex_rad = 0.0f, twist_rad = 0.0f, wrist_flex_rad = 0.0f, wrist_dev_rad = 0.0f;
  float clavicle_elevation_rad = 0.0f, clavicle_protraction_rad = 0.0f;
};

ArmPose solve_arm(const Rig& rig, Side side, const ArmTarget& target);
void apply_arm(const Rig& rig, Side side, const ArmPose& pose, PoseBuilder* builder);

}  // namespace sw::synthesis

// Arm IK: places a point of the hand (the contact part) on a target with a requested hand
// orientation. Analytic two-bone solve (upper arm, forearm) with the elbow on its swivel circle,
// clavicle (shoulder joint) participation for high and far targets, and the wrist solved for the
// orientation: forearm twist (pronation/supination) takes the roll, the wrist takes flexion and
// deviation, each within anatomical limits; what the limits refuse stays as orientation error,
// but for a wrist motion's excess, which the shoulder's rotation (the swivel) takes.
#pragma once

#include <cstddef>
#include <memory>

#include "synthesis/collision.h"
#include "synthesis/rig.h"

namespace sw::synthesis {

// Anatomical limits (radians; degrees in comments) — joint limits everywhere. Sources for the
// forearm and wrist values (AAOS normal ranges, Ryu et al. 1991): docs/SYNTHESIS.md.
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

struct ArmPose;

// Every field but `previous` (and previous_wrist, read only with it) is part of ArmSolveMemo's key
// (arm_ik.cpp, Table::key_of): a field added here must be added there too, or a remembered pose
// would answer a different solve; and to Table::at_key_of (the memo of one swivel's solve,
// solve_at) if solve_at reads it without `previous`.
struct ArmTarget {
  glm::vec3 point{0.0f};            // where the contact point must go (model space)
  glm::vec3 contact_offset{0.0f};   // contact point minus wrist, hand in its bind orientation
  glm::quat hand_delta{1, 0, 0, 0}; // requested hand orientation (orientation.h)
  bool auto_swivel = true;          // choose the elbow swivel by the comfort heuristic
  float swivel_rad = 0.4f;          // used when !auto_swivel: 0 elbow down, + elbow out
  // With a body model, the swivel choice also keeps the upper arm and forearm out of the trunk
  // (collision.h arm_trunk_depth); hand_contact: the hand touches the body on purpose.
  const BodyModel* body = nullptr;
  bool hand_contact = false;
  // The same arm one frame earlier, when a path solved frame by frame must continue from it
  // (null: solved free, as key poses are). Where the requested orientation lies beyond the
  // forearm's or wrist's limits, a wrist angle then stays on the limit it was on instead of the
  // one its Euler angle wraps to (LEARN's pinched hand on its way to the forehead, a request 100+
  // degrees out of reach, flipped from full flexion to full extension in one frame, the wrist
  // jumping 17 cm), and no wrist angle (forearm twist, deviation, flexion) changes by more than
  // max_wrist_step_rad from the previous frame's (0: they hold).
  const ArmPose* previous = nullptr;
  float max_wrist_step_rad = 0.0f;
  // With `previous`: solve_at's orientation rounds start from previous_wrist (the previous frame's
  // finished wrist) instead of the wrist the requested orientation puts behind the contact point.
  // With the wrist angles held the hand's orientation follows the forearm, and the damped
  // iteration between the wrist's place and the hand has two answers, the wrist on either side of
  // the contact point; the start decides which (TO-SLEEP2^ swapped sides from frame to frame, its
  // right elbow 437 mm in one). sign_motion.cpp solves a continued frame both ways and keeps this
  // start only where the frame ends no deeper and its wrist nearer the previous frame's. Without
  // `previous` neither does anything (and such a solve is not remembered: previous_wrist is left
  // out of the key like `previous`, the flag is in it).
  bool start_at_previous_wrist = false;
  glm::vec3 previous_wrist{0.0f};
  // The part of hand_delta that is a wrist movement (nod, swing, twist, circle), right-multiplied
  // onto the held orientation (identity: none). The movement then turns the hand as the wrist
  // limits realise the held orientation (the key pose's wrist), and where that takes a wrist
  // angle beyond its limit the other angles are refitted to the request instead of keeping the
  // Euler angles that went with the unclamped one (arm_ik.cpp fit_clamped_wrist). Before, a twist
  // driven into the limits (Й, its hand already at the forearm's, the ulnar and the extension
  // limit) saw the clamped wrist's orientation error jump 0.04 -> 0.47 rad in one frame.
  // What the motion asks beyond the wrist's limits is carried to the shoulder's rotation (the
  // swivel, turned by the motion's own excess, arm_ik.cpp carry_wrist_motion_excess): a twist
  // 0.63 rad past the forearm's range with the arm held out ends 0.07 rad off instead of 0.63.
  glm::quat wrist_motion{1, 0, 0, 0};
  // Swivel continuity (auto_swivel only): the swivel this arm has at a neighbouring pose of the
  // same motion (the sign's key pose before this one). Without it, two poses a few centimetres
  // apart could choose swivels a radian apart at near-equal cost and the elbow swing between them
  // (DEAF on the reference rig: 1.6 rad at the ear, 0.4 at the mouth, the elbow 13 cm in a frame). With it, every radian away from near_swivel_rad costs
  // kSwivelContinuityPerRad (arm_ik.cpp) and the search starts in its basin: the candidates
  // round it first, the whole range only when none of those keeps the arm out of the body or a
  // touch on its target and the hand's orientation within 20 degrees.
  bool has_near_swivel = false;
  float near_swivel_rad = 0.0f;
  // A touch's key pose as written (auto_swivel, no near swivel or its basin left): where the
  // comfort pick leaves the hand more than 10 degrees off, the rest of the swivel range is
  // searched for a pose within 10 degrees that keeps the arm out of the body as the pick does
  // and the touch on its target (arm_ik.cpp solve_arm). Off for the solves that compare
  // placements, turns or swivel fixes: those trade orientation against the body themselves.
  bool seek_orientation_acceptance = false;
};

struct ArmPose {
  glm::quat shoulder{1, 0, 0, 0}, upper{1, 0, 0, 0}, lower{1, 0, 0, 0}, hand{1, 0, 0, 0};
  float swivel_rad = 0.0f;
  float reach_error_m = 0.0f;        // |achieved contact point - target|
  glm::vec3 contact_point{0.0f};     // the achieved contact point (model space)
  float orientation_error_rad = 0.0f;// angle between requested and achieved hand rotation
  float elbow_flex_rad = 0.0f, twist_rad = 0.0f, wrist_flex_rad = 0.0f, wrist_dev_rad = 0.0f;
  float clavicle_elevation_rad = 0.0f, clavicle_protraction_rad = 0.0f;
  float trunk_depth_m = 0.0f;        // arm in the trunk (only when the target had a body model)
  glm::vec3 trunk_push_dir{0.0f};    // the way out for the deepest arm segment
  float body_cost = 0.0f;            // what the body costs this pose (trunk depth, elbow behind)
};

// Joint positions of a solved arm (shoulder joint, elbow, wrist), the trunk in its bind pose.
ArmSegments arm_segments(const Rig& rig, Side side, const ArmPose& pose);

// Cost of an arm's depth in the trunk, in the units of the swivel choice (3 per radian of
// orientation error): 60 per metre beyond a 2 mm tolerance, so 5 cm weighs as much as 1 rad of
// orientation error and a swivel that keeps the arm out of the body wins over a more accurate
// wrist (the 5 mm rule is a hard rule, the orientation a 10 degree acceptance).
inline float arm_trunk_cost(float depth_m) { return 60.0f * (depth_m > 0.002f ? depth_m - 0.002f : 0.0f); }

ArmPose solve_arm(const Rig& rig, Side side, const ArmTarget& target);

// The swivel's zero at a shoulder-wrist direction `axis` (unit): `down`, the way down square to
// the axis (leaned forward near the upward vertical, so it does not turn half round as the wrist
// passes straight over the shoulder joint; straight under it it still does), and `out`,
// the side a positive swivel turns the elbow to: axis x down with ONE handedness per arm (the one
// that points along `out_dir`, the arm's lateral direction, for a wrist in front of the shoulder).
// The old `out` (out_dir's part square to the axis and down) turned half round wherever the wrist
// crossed the shoulder joint's coronal plane, and the same swivel number put the elbow on the
// other side (docs/SYNTHESIS.md elbow-leap, swivel-pref). up, forward: the body's directions (the
// trunk's turn applied where it turns, transition.cpp pose_swivel).
struct SwivelZero {
  glm::vec3 down{0.0f}, out{0.0f};
};
// `fixed_handed` false (the default, Rig::fixed_handed_swivel_zero): the usual zero, whose `out` is
// out_dir's part square to the axis and `down` (half round at the coronal plane), to the bit as
// it was before the choice (docs/SYNTHESIS.md swivel-choice).
SwivelZero swivel_zero(const glm::vec3& axis, const glm::vec3& up, const glm::vec3& forward, const glm::vec3& out_dir,
                       bool fixed_handed);
// The elbow's swivel in this zero for an elbow offset from the shoulder joint (any part along the
// axis is ignored): atan2 of its parts along `out` and `down`.
float swivel_of(const SwivelZero& z, const glm::vec3& elbow_offset);
// How far "out" (the arm's lateral direction) lies along the zero's `out`, as a share in [-1, 1]:
// +1 where out_dir is on the elbow's circle on the positive side (a wrist in front of the
// shoulder), -1 where it is on the negative side (a wrist behind the shoulder joint's coronal
// plane), ramping through 0 where the lateral direction leaves the circle (the wrist in that
// plane). solve_arm's comfort preference ("the elbow down and out") and its candidate range are
// its old numbers times this share (docs/SYNTHESIS.md swivel-pref).
float swivel_out_share(const SwivelZero& z, const glm::vec3& out_dir);

// While one lives (on this thread), solve_arm remembers what it returned for a target solved
// free (no ArmTarget::previous) and returns the same pose when it is asked again with the same
// rig, side and target to the bit: a sign's planning asks for the same solve again and again
// (the key pose solved where it is placed, where the hands are checked, where each swivel fix
// starts; 3,308 of the lexicon's 18,061 solves, each sign alone, right-handed), and solve_arm
// reads nothing else (the rig, the body model behind ArmTarget::body and arm_limits), so the
// remembered pose is the one it would compute. The rig and body model must not change while it
// lives: one sign's planning, whose SynthContext is const. Scopes nest (the inner one is used).
class ArmSolveMemo {
 public:
  ArmSolveMemo();
  ~ArmSolveMemo();
  ArmSolveMemo(const ArmSolveMemo&) = delete;
  ArmSolveMemo& operator=(const ArmSolveMemo&) = delete;
  // Solves answered from the memo so far.
  std::size_t hits() const;
  // One swivel's solves (arm_ik.cpp solve_at, inside solve_arm) answered from the memo so far:
  // the same target solved at the same swivel for a solve_arm that differs in what solve_at does
  // not read (the body model, the touch, the near swivel, the search flags).
  std::size_t swivel_solve_hits() const;

  struct Table;

 private:
  friend ArmPose solve_arm(const Rig& rig, Side side, const ArmTarget& target);
  std::unique_ptr<Table> table_;
  ArmSolveMemo* outer_;
};

// A real conflict with the body, the one turn_hand_out_of_body acts on: the arm deeper in the
// trunk than the 5 mm rule allows, or the elbow clearly behind the body (a graze of a few mm is
// the swivel's and the per-frame fix's business; turning the hand 15 degrees for it would cost
// more than it saves). Searches that would rather move the hand than turn it use the same test.
inline bool arm_in_body_conflict(const ArmPose& p) {
  const float elbow_behind = p.body_cost - arm_trunk_cost(p.trunk_depth_m);
  return p.trunk_depth_m > 0.005f || elbow_behind > 0.03f;
}

// When even the best swivel leaves the arm in the trunk or the elbow behind the body (a fingertip
// touching the chest or forehead with the fingers pointing into it puts the wrist inside), a
// signer turns the hand about its contact point until the arm is free: the smallest turn
// (15..120 degrees, swinging the wrist out of the trunk or forward) that frees the arm and
// scores better than not turning (orientation error against the REQUESTED orientation, reach,
// body cost), else the best-scoring turn if it beats not turning. Returns true (t->hand_delta and *pose updated) when a
// turn won. The orientation error it costs is the price of the 5 mm rule. Needs t->body.
bool turn_hand_out_of_body(const Rig& rig, Side side, ArmTarget* t, ArmPose* pose);
// A touch the arm cannot reach because the elbow cannot fold further: with the requested
// orientation the wrist would be closer to the shoulder joint than the arm folded at its 150
// degree flexion limit reaches (DEAF's index tip on the ear, pointing up, on the reference
// humanoid: the wrist 11 cm from the shoulder joint, the folded arm 14.5 cm; the best swivel
// raised the elbow and missed by 22 mm with the hand 72 degrees off). A signer tilts the hand
// about the fingertip, the wrist forward: the same turns as turn_hand_out_of_body, the smallest
// that reaches within 5 mm with the arm free winning. Only for a touch (t->hand_contact) missing
// by more than 5 mm with the wrist target inside the folded arm's reach; true when a turn won.
bool turn_hand_to_reach(const Rig& rig, Side side, ArmTarget* t, ArmPose* pose);
void apply_arm(const Rig& rig, Side side, const ArmPose& pose, PoseBuilder* builder);

}  // namespace sw::synthesis

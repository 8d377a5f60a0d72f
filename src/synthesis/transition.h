// Transitions between gestures, seed 004 eqs (8)-(10), made smooth and collision-free.
//
//   (8)  theta_i = theta_{i-1} + (theta_beg(G_m) - theta_end(G_l)) / k,   i = 1 .. k-1
//   (9)  coef = k* / L      (states a native signer uses for a distance L at natural speed)
//   (10) k = coef * L_max,  L_max = max over bone end points |S_end(G_l) - S_beg(G_m)|
//
// We keep the seed's state count k (eq. 10) and its start/end states, but interpolate each joint's
// rotation by shortest-path slerp (never Euler blending, which flips at +-180 degrees) with the
// minimum-jerk time law instead of equal steps, so the velocity is zero — hence continuous — where
// the transition meets the holds of the signs. coef: docs/SYNTHESIS.md (30 states per metre).
// L_max is measured along the path the interpolation makes the joints travel, not as the straight
// distance between its ends (transition_path_m): coef is a speed along the hand's path.
// k is then stretched where the states would accelerate an arm joint beyond a human 40 m/s^2
// (transition.cpp kArmPeakAccelMPerS2): the speed factor divides every duration, and a faster
// signer still has a human arm.
// When a state would pass through the body or the other hand, a via-pose (the hand pulled away
// from the body) is inserted and the path routed through it (the seed's remedy); when that still
// cuts through, one or two waypoint poses with the wrists held in front of the trunk, the path a
// chain of slerps through them with rounded corners (the arm comes forward, then across).
// From and back to the rest pose, the hand takes its own path when that is clear of the body:
// waypoints with the wrist on the (forward-bowed) line between its ends, the arm solved by IK in
// the frame of the (possibly turning) trunk; where that is not clear, again with the swivel
// searched and bowed further forward, in front of the body, before any via-pose
// (plan_hand_path in transition.cpp; docs/SYNTHESIS.md, Transitions).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "synthesis/sign_motion.h"

namespace sw::synthesis {

// coef of eq. (9): a natural mean hand speed of 1 m/s sampled at 30 fps gives k* = 30 states for
// L = 1 m. Scaled by fps/30 for other frame rates.
constexpr float kTransitionStatesPerMetre = 30.0f;
// Fewer states cannot carry an ease-in/ease-out profile (k - 1 intermediate states).
constexpr int kMinTransitionStates = 4;

// Eq. (10) as the seed writes it: L_max over all joints (bone end points, model space), the
// straight distance between two frames.
float transition_lmax(const Rig& rig, const glm::quat* from_locals, const glm::quat* to_locals);
// The distance the transition really makes a bone end point travel: the longest path of any joint
// along the direct interpolation (joint rotations slerped, sampled finely). A transition's k uses
// it for L_max: interpolating joint rotations swings the hand along an arc, and from the rest pose
// (arm down, palm to the thigh) up to the chest the fingertip travels 2.7 times the straight
// distance (ME: 1.52 m for 0.57 m). With the chord, the "1 m/s mean speed" of eq. (9)'s coef was
// really up to 2.7 m/s along the path, peaking at 16 cm per frame (5 m/s).
float transition_path_m(const Rig& rig, const glm::quat* from_locals, const glm::quat* to_locals);
// k = ceil(coef * L_max * fps/30 / speed), at least kMinTransitionStates.
int transition_states(float lmax_m, float fps, float speed);

struct TransitionPlan {
  int k = 0;                 // states (eq. 10); k-1 intermediate frames are produced
  float lmax_m = 0.0f;       // eq. (10)'s L_max: the longest joint path (transition_path_m);
                             // on a rest transition's hand path, the arm joints' (transition.cpp)
  int via_points = 0;        // via-poses or waypoint poses the path was routed through
  float max_penetration_m = 0.0f;  // after routing
  std::vector<glm::quat> frames;   // (k-1) * joint_count, frame-major
  std::vector<std::uint8_t> exempt;
};

// The transition from `from` (last frame of a sign) to `to` (first frame of the next).
// exempt_from / exempt_to: intended-contact bits of those frames (a hand leaving or arriving at a
// contact may touch during the first / last third of the transition).
TransitionPlan plan_transition(const SynthContext& ctx, const glm::quat* from, const glm::quat* to,
                               std::uint8_t exempt_from, std::uint8_t exempt_to);

// Deepest unintended penetration over frames (exempt bits as in sign_motion.h); `what` names it.
// With ctx.penetration_memo set, frames it has seen are not posed and tested again.
float max_penetration(const SynthContext& ctx, const glm::quat* frames, int frame_count,
                      const std::uint8_t* exempt, std::string* what, int* worst_frame);

// max_penetration's result for each frame it has checked, found again by the frame's bits. A
// phrase checks its transition frames while planning them and then the whole clip once more
// (after the face layer): most frames of the final check are transition frames seen before.
// A frame is known by the local rotations of the joints the checks read (arms, hands, fingers,
// the capsules' joints) and of their ancestors, and by its exemption bits: the depths are a
// function of exactly those, so a remembered result is the one a new check would compute, to the
// bit. The other joints (eyes, which the face layer turns on every frame, jaw, legs) are not
// part of the key. One memo per synthesis call (not shared between threads).
class PenetrationMemo {
 public:
  explicit PenetrationMemo(const SynthContext& ctx);
  // A frame's deepest penetration (0 if none) and what it was, in max_penetration's terms.
  struct Result {
    float depth_m = 0.0f;
    std::string what;
  };
  const Result* find(const glm::quat* frame, std::uint8_t exempt) const;
  // A frame find() did not know.
  void add(const glm::quat* frame, std::uint8_t exempt, Result result);

 private:
  std::uint32_t key_hash(const glm::quat* frame, std::uint8_t exempt) const;
  bool same(size_t entry, const glm::quat* frame, std::uint8_t exempt) const;
  std::vector<int> joints_;          // the key's joints
  std::vector<int> hash_joints_;     // the arms' upper, lower and hand joints
  std::vector<std::uint32_t> keys_;  // the key joints' rotation bits, 4 words each, per entry
  std::vector<std::uint8_t> exempt_;
  std::vector<Result> results_;
  std::vector<std::uint32_t> hashes_;
  std::vector<std::int32_t> table_;  // open addressing: entry index or -1; size a power of two
};

}  // namespace sw::synthesis

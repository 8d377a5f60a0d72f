// Sign motion: one SignSpec -> the frames of that sign on one avatar. Key states per hand
// (handshape, orientation, location), the movement steps as per-frame hand targets solved by arm
// IK, repetitions, two hands (symmetry, one hand as the place of the other, alternation) and the
// per-frame push-out when a hand would enter the body. Transitions between signs and the phrase
// timeline are in transition.h and synthesize.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "avatar/avatar.h"
#include "notation/sign_spec.h"
#include "synthesis/collision.h"
#include "synthesis/handshape.h"
#include "synthesis/rig.h"
#include "synthesis/synthesize.h"

namespace sw::synthesis {

class PenetrationMemo;

// Everything a synthesis run measures once per avatar.
struct SynthContext {
  const avatar::Avatar* avatar = nullptr;
  Rig rig;
  BodyModel body;
  SynthesisOptions options;
  std::vector<glm::quat> rest_locals;  // the rest pose (arms down, hands relaxed)
  // Optional, per synthesis call: max_penetration's per-frame results (transition.h).
  PenetrationMemo* penetration_memo = nullptr;
};
bool make_context(const avatar::Avatar& avatar, const SynthesisOptions& options, SynthContext* ctx,
                  std::string* error);
// Options a synthesis can run with (fps 5..240, speed 0.1..10); `error` says which is wrong.
bool validate_options(const SynthesisOptions& options, std::string* error);

// Per-frame exemption from the penetration rule (intended contact), bit per side and kind.
constexpr std::uint8_t exempt_bit(Side s, bool other_hand) {
  return static_cast<std::uint8_t>(1u << (static_cast<int>(s) * 2 + (other_hand ? 1 : 0)));
}

struct SignMotion {
  int frame_count = 0;
  std::vector<glm::quat> rotations;   // frame-major, rig.joint_count per frame
  std::vector<std::uint8_t> exempt;   // per frame, exempt_bit()s
  float max_reach_error_m = 0.0f;     // touch contacts at the key pose
  std::vector<float> contact_distance_m;  // per hand with a body/hand location: part -> anchor
  // Per frame, the worst hand's arm IK orientation error (radians): the angle between the hand
  // orientation the frame asked the arm for and the one the joint limits let it realise (arm_ik.h
  // ArmPose::orientation_error_rad, of the frame's first solve; frame 0 is the key pose).
  std::vector<float> orientation_error_rad;
  std::vector<std::string> warnings;
  int pushes = 0;                     // frames pushed out of the body
  // The deepest frame of the sign's own clip as the phrase measures it (after the elbow's path;
  // sign_motion.cpp sign_depth_and_step), where synthesize_sign_motion measured it; -1: not.
  float sign_depth_m = -1.0f;
};

// Synthesises one sign's frames (no transitions in or out). `where` prefixes error locations.
// `usual_alternative` (optional): where a hand caught between two capsules was sent out by the
// jam rule (sign_motion.cpp) and that clip kept, the clip solved without the rule, for the caller
// to judge the two with the transitions next to the sign; otherwise left empty (frame_count 0).
bool synthesize_sign_motion(const SynthContext& ctx, const notation::SignSpec& sign,
                            const std::string& where, SignMotion* out,
                            std::vector<SynthesisError>* errors, SignMotion* usual_alternative = nullptr);

// A sign's own clip's deepest frame as the phrase measures it (m.sign_depth_m where
// synthesize_sign_motion measured it, else measured here).
float sign_motion_depth(const SynthContext& ctx, const SignMotion& m);

// Name of the body anchor for a location (`body/chest/right`, `space/centre`), mirrored when the
// hand's side is mirrored; empty for places on the other hand.
std::string body_anchor_name(const notation::Location& loc, bool mirror_x);

}  // namespace sw::synthesis

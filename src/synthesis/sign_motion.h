// Sign motion: one SignSpec -> the frames of that sign on one avatar. Key states per hand
// (handshape, orientation, location), the movement steps as per-frame hand targets solved by arm
// IK, repetitions, two hands (symmetry, one hand as the place of the other, alternation) and the
// per-frame push-out when a hand would enter the body. Transitions between signs and the phrase
// timeline are in transition.h and synthesize.cpp.
#pragma once

#include <algorithm>
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
  // A mirror pair written at one place is laid apart to both sides (sign_motion.cpp
  // lay_mirror_pair_apart); off, the dominant hand alone moves out of the way (the other solve
  // synthesize_sign_motion compares it with).
  bool mirror_pairs_apart = true;
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
  bool mirror_laid_apart = false;     // the key pose's mirror pair was laid apart to both sides
  // ... and that pair's fingers cross at its one place (sign_motion.cpp mirror_fingers_cross).
  bool mirror_fingers_cross = false;
  // The deepest frame of the sign's own clip as the phrase measures it (after the elbow's path;
  // sign_motion.cpp sign_depth_and_step), where synthesize_sign_motion measured it; -1: not.
  float sign_depth_m = -1.0f;
};

// A sign's clip's largest arm step in one frame (a wrist or elbow; clip_steps.h) over which it
// is solved again in the other swivel zero (docs/SYNTHESIS.md swivel-choice, leap): no signer's
// elbow moves 15 cm in a frame (at 30 fps, 4.5 m/s); the lexicon's largest step is 68 mm.
constexpr float kSwivelChoiceStepM = 0.15f;
// How much deeper a sign's second solve (the other branch of its continued wrist flips, the other
// swivel zero) may go than the first and still be kept: 0.5 mm, as for one frame's choice.
constexpr float kBranchSignSlackM = 0.0005f;

// The sign solved in the swivel zero synthesize_sign_motion did not keep, with its clip without
// the jam rule (as `usual_alternative` below), for the phrase to judge with the transitions
// (synthesize.cpp). `solved` false: the sign was solved in one zero only.
struct OtherZeroSolve {
  bool solved = false;
  bool kept_fixed = false;  // solved: the kept clip is the fixed zero's (this one the usual's)
  // The shoulder girdle's zone the sign was solved in (Rig::protraction_zone: a wider one where
  // the phrase took the sign's solve in it, synthesize.cpp choose_wide_protraction), so that the
  // phrase's solves again of the sign are made in it too.
  int protraction_zone = 0;
  SignMotion motion, usual_alternative;
};

// Whether the laid-apart clip (its deepest frame and largest wrist or elbow step in one frame) is
// kept over the escape's: no deeper (0.1 mm, rounding), and stepping no more in a frame, or at most
// 1 cm more while that stays within 100 mm (3 m/s at 30 fps: the corpus census's first bound; a
// step past it must not grow, NGT VOORKOMEN 147.4 -> 151.0 mm with the slack alone). Measured on
// the HamNoSys corpus (docs/SYNTHESIS.md, sign-hands; the rule then for hamsymmlr pairs only,
// uncrossed by 1 cm): with no more step allowed, 94 signs over 5 mm; with 1 cm, 90; with the
// shallower clip kept whatever its step, 89, but two signs newly step over 100 mm in a frame
// (TO-SLEEP2^ 56 -> 164 mm for 0.5 mm less depth).
inline bool mirror_apart_is_kept(float apart_depth_m, float apart_step_m, float other_depth_m,
                                 float other_step_m) {
  constexpr float kStepSlackM = 0.01f, kStepSlackBelowM = 0.1f;
  return apart_depth_m <= other_depth_m + 1e-4f &&
         (apart_step_m <= other_step_m ||
          apart_step_m <= std::min(other_step_m + kStepSlackM, kStepSlackBelowM));
}
// The same for the laid-apart clip `apart`: where its fingers cross at one place
// (SignMotion::mirror_fingers_cross) the escape, the dominant hand laid on top, is the signer's
// way, and it is kept wherever it is clean (within kBranchSignSlackM, 0.5 mm) and passes the step
// rule against the laid-apart clip. Judged as the other way round (the escape kept only where no
// deeper than the laid-apart clip), 50 corpus signs took an escape that a later choice (the wider
// protraction, solved only for deep clips) left deep while it would have cleared the laid-apart
// one (montaż 1.8 -> 13.3 mm; docs/SYNTHESIS.md sign-hands, crossed fingers).
inline bool mirror_apart_is_kept(const SignMotion& apart, float apart_depth_m, float apart_step_m,
                                 float other_depth_m, float other_step_m) {
  constexpr float kCleanEscapeM = 0.0005f;
  if (apart.mirror_fingers_cross && other_depth_m <= kCleanEscapeM &&
      mirror_apart_is_kept(0.0f, other_step_m, 0.0f, apart_step_m))
    return false;
  return mirror_apart_is_kept(apart_depth_m, apart_step_m, other_depth_m, other_step_m);
}

// Synthesises one sign's frames (no transitions in or out). `where` prefixes error locations.
// `usual_alternative` (optional): where a hand caught between two capsules was sent out by the
// jam rule (sign_motion.cpp) and that clip kept, the clip solved without the rule, for the caller
// to judge the two with the transitions next to the sign; otherwise left empty (frame_count 0).
// `other_zero` (optional): filled where the sign was solved in both swivel zeros.
// `mirror_judged_by_caller`: where the key pose's pair was laid apart to both sides
// (SignMotion::mirror_laid_apart), the caller judges that clip against the old escape's
// (synthesize_sign_motion_escaping) with the transitions next to the sign; otherwise the two are
// judged here, on the sign's own frames (mirror_apart_is_kept).
bool synthesize_sign_motion(const SynthContext& ctx, const notation::SignSpec& sign,
                            const std::string& where, SignMotion* out,
                            std::vector<SynthesisError>* errors, SignMotion* usual_alternative = nullptr,
                            OtherZeroSolve* other_zero = nullptr, bool mirror_judged_by_caller = false);
// The sign with a symmetric pair's key pose laid out of the way by the dominant hand alone (the
// escape, SynthContext::mirror_pairs_apart off), `usual_alternative` and `other_zero` as above;
// `errors` repeat the first solve's.
bool synthesize_sign_motion_escaping(const SynthContext& ctx, const notation::SignSpec& sign,
                                     const std::string& where, SignMotion* out,
                                     std::vector<SynthesisError>* errors, SignMotion* usual_alternative,
                                     OtherZeroSolve* other_zero);

// The sign solved in ctx's swivel zero only (no zero choice), with more last ramp rounds where
// the last one's own corrections jump between frames and the sign's clip leaps (an arm step over
// kSwivelChoiceStepM): those corrections come on at once, nothing ramps them (sign_motion.cpp
// ramp_rounds). For the phrase to judge with the transitions (synthesize.cpp); `errors` repeat
// the first solve's.
bool synthesize_sign_motion_ramped_again(const SynthContext& ctx, const notation::SignSpec& sign,
                                         const std::string& where, SignMotion* out,
                                         std::vector<SynthesisError>* errors, SignMotion* usual_alternative);

// A sign's own clip's deepest frame as the phrase measures it (m.sign_depth_m where
// synthesize_sign_motion measured it, else measured here).
float sign_motion_depth(const SynthContext& ctx, const SignMotion& m);

// Name of the body anchor for a location (`body/chest/right`, `space/centre`), mirrored when the
// hand's side is mirrored; empty for places on the other hand.
std::string body_anchor_name(const notation::Location& loc, bool mirror_x);

}  // namespace sw::synthesis

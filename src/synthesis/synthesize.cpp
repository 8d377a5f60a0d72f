// Synthesis entry points: the phrase timeline — rest pose, signs, transitions (seed eqs 8-10),
// holds, pauses at punctuation, global speed — into one Clip with caption segments.
#include "synthesis/synthesize.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "face/face_track.h"
#include "skeleton/humanoid_names.h"
#include "synthesis/clip_steps.h"
#include "synthesis/elbow_path.h"
#include "synthesis/sign_motion.h"
#include "synthesis/transition.h"

namespace sw::synthesis {

namespace {

struct Timeline {
  int joints = 0;
  std::vector<glm::quat> frames;
  std::vector<std::uint8_t> exempt;
  int count() const { return joints ? static_cast<int>(frames.size() / joints) : 0; }
  const glm::quat* last() const { return &frames[frames.size() - joints]; }
  void append(const glm::quat* f, int n, const std::uint8_t* ex) {
    frames.insert(frames.end(), f, f + static_cast<size_t>(n) * joints);
    exempt.insert(exempt.end(), ex, ex + n);
  }
};

ClipSegment::Kind segment_kind(PhraseItem::Kind k) {
  return k == PhraseItem::Kind::Letter ? ClipSegment::Kind::Letter
       : k == PhraseItem::Kind::Pause  ? ClipSegment::Kind::Pause
                                       : ClipSegment::Kind::Sign;
}

}  // namespace

namespace {

SynthesisResult run_phrase(const SynthContext& ctx, const std::vector<PhraseItem>& items);

}  // namespace

Synthesizer::Synthesizer(const avatar::Avatar& avatar, const SynthesisOptions& options)
    : ctx_(new SynthContext) {
  if (!make_context(avatar, options, ctx_, &error_)) error_ = error_.empty() ? "invalid avatar" : error_;
}

Synthesizer::~Synthesizer() { delete ctx_; }

SynthesisResult Synthesizer::phrase(const std::vector<PhraseItem>& items, const SynthesisOptions& options) const {
  SynthesisResult result;
  if (!ok()) {
    result.errors.push_back({"avatar", error_});
    return result;
  }
  std::string error;
  if (!validate_options(options, &error)) {
    result.errors.push_back({"options", error});
    return result;
  }
  // The avatar measurements do not depend on the options: reuse them with this call's options.
  SynthContext ctx = *ctx_;
  ctx.options = options;
  PenetrationMemo memo(ctx);  // this call's own: the final check reuses the transitions' results
  ctx.penetration_memo = &memo;
  return run_phrase(ctx, items);
}

SynthesisResult Synthesizer::sign(const notation::SignSpec& sign, const SynthesisOptions& options) const {
  PhraseItem item;
  item.kind = PhraseItem::Kind::Sign;
  item.sign = sign;
  item.label = sign.gloss;
  item.word_index = 0;
  return phrase({item}, options);
}

SynthesisResult synthesize_phrase(const std::vector<PhraseItem>& items, const avatar::Avatar& avatar,
                                  const SynthesisOptions& options) {
  Synthesizer synth(avatar, options);
  return synth.phrase(items, options);
}

namespace {

// A sign's clip with the transitions the phrase builds next to it (from the frame before, to the
// frame after; either may be absent), as the phrase's final check measures it: the elbow's path
// made continuous (carry_elbows), then the deepest unintended penetration and the
// largest wrist or elbow step in one frame.
// With `sides`, also how far each wrist goes out to its own side in the transitions (from the
// midline, their widest frame) and whether it is across the midline where the sign starts or
// ends (choose_wide_protraction; it measures with carry_elbows, as sign_depth_and_step measures
// a sign, so a choice made on it is the same with and without the elbow's path).
struct WithTransitions {
  float depth_m = 0.0f, step_m = 0.0f, change_m = 0.0f;
  float wrist_out_m[2] = {0.0f, 0.0f};
  bool across[2] = {false, false};  // the wrist past the midline at the sign's first or last frame
};
WithTransitions measure_with_transitions(const SynthContext& ctx, const SignMotion& m, const glm::quat* before,
                                         std::uint8_t before_exempt, const glm::quat* after,
                                         std::uint8_t after_exempt, bool carry_elbows, bool sides) {
  Timeline seg;
  seg.joints = ctx.rig.joint_count;
  if (before) {
    seg.append(before, 1, &before_exempt);
    TransitionPlan in = plan_transition(ctx, before, m.rotations.data(), before_exempt, m.exempt[0]);
    if (in.k > 1) seg.append(in.frames.data(), in.k - 1, in.exempt.data());
  }
  const int sign_first = seg.count();
  seg.append(m.rotations.data(), m.frame_count, m.exempt.data());
  const int sign_last = seg.count() - 1;
  if (after) {
    TransitionPlan out = plan_transition(ctx, seg.last(), after, seg.exempt.back(), after_exempt);
    if (out.k > 1) seg.append(out.frames.data(), out.k - 1, out.exempt.data());
    seg.append(after, 1, &after_exempt);
  }
  Clip c;
  c.fps = ctx.options.fps;
  c.frame_count = seg.count();
  c.rotations = std::move(seg.frames);
  if (carry_elbows) continue_elbow_paths(ctx.rig, &ctx.body, c.fps, c.frame_count, &c.rotations);
  WithTransitions w;
  if (sides) {
    PoseBuilder pb(ctx.rig);
    const int J = ctx.rig.joint_count;
    for (int side = 0; side < 2; ++side) w.wrist_out_m[side] = -1e30f;
    for (int f = 0; f < c.frame_count; ++f) {
      const bool sign_end = f == sign_first || f == sign_last;
      if (f > sign_first && f < sign_last) continue;  // the transitions, and the sign's two ends
      pb.set_from_local(&c.rotations[static_cast<size_t>(f) * J]);
      for (int side = 0; side < 2; ++side) {
        const float out = glm::dot(pb.position(ctx.rig.arms[side].hand), side == kLeft ? ctx.rig.left : -ctx.rig.left);
        if (sign_end) w.across[side] = w.across[side] || out < 0.0f;
        else w.wrist_out_m[side] = std::max(w.wrist_out_m[side], out);
      }
    }
  }
  w.depth_m = max_penetration(ctx, c.rotations.data(), c.frame_count, seg.exempt.data(), nullptr, nullptr);
  const FrameSteps steps = measure_frame_steps(ctx.rig, c);
  w.step_m = steps.step_m;
  w.change_m = steps.change_m;
  return w;
}

// The frames the phrase joins sign i to: the last frame of the sign before (or the rest pose, from
// rest) and the first of the sign after (or the rest pose); null where there is none.
struct Neighbours {
  const glm::quat* before = nullptr;
  std::uint8_t before_exempt = 0;
  const glm::quat* after = nullptr;
  std::uint8_t after_exempt = 0;
};
Neighbours neighbours_of(const SynthContext& ctx, const std::vector<PhraseItem>& items,
                         const std::vector<SignMotion>& motions, size_t i) {
  auto is_sign = [&](size_t j) {
    return items[j].kind != PhraseItem::Kind::Pause && motions[j].frame_count > 0;
  };
  Neighbours n;
  for (size_t j = i; j-- > 0 && !n.before;)
    if (is_sign(j)) {
      const SignMotion& p = motions[j];
      n.before = &p.rotations[static_cast<size_t>(p.frame_count - 1) * ctx.rig.joint_count];
      n.before_exempt = p.exempt.back();
    }
  if (!n.before && ctx.options.start_from_rest) n.before = ctx.rest_locals.data();
  for (size_t j = i + 1; j < items.size() && !n.after; ++j)
    if (is_sign(j)) {
      n.after = motions[j].rotations.data();
      n.after_exempt = motions[j].exempt[0];
    }
  if (!n.after && ctx.options.start_from_rest) n.after = ctx.rest_locals.data();
  return n;
}

// carry_elbows: the elbow's path made continuous as the phrase does it (the options'), or always
// (the swivel zero's choice and the wider protraction's, measured as the clip has it by default
// whatever the options).
WithTransitions measure_with_transitions(const SynthContext& ctx, const SignMotion& m, const Neighbours& n,
                                         bool carry_elbows, bool sides = false) {
  return measure_with_transitions(ctx, m, n.before, n.before_exempt, n.after, n.after_exempt, carry_elbows, sides);
}

// The jam rule's clip (sign_motion.h usual_alternative) was chosen on the sign's own frames; the
// transitions next to the sign start and end at its first and last frames, which the rule moves
// too (a hand caught at the chin holds the key pose): chosen on the sign alone it left 7 HamNoSys
// corpus signs 2-3.5 mm deeper in their rest transitions (docs/SYNTHESIS.md push-side). So each
// such sign is judged again with its neighbouring transitions built for both clips (from the
// sign before, or the rest pose, to the sign after, or the rest pose, as below), in phrase order
// (a sign's choice is the next one's start); the rule's clip stays where that is no deeper (0.1
// mm: rounding) and steps no more in a frame (its own frames already step less). Signs without a
// jam cost nothing.
void choose_jam_with_transitions(const SynthContext& ctx, const Neighbours& n, bool carry_elbows, SignMotion* motion,
                                 SignMotion* usual) {
  if (usual->frame_count == 0) return;
  const WithTransitions jam = measure_with_transitions(ctx, *motion, n, carry_elbows);
  const WithTransitions plain = measure_with_transitions(ctx, *usual, n, carry_elbows);
  if (!(jam.depth_m <= plain.depth_m + 1e-4f && jam.step_m <= plain.step_m)) *motion = std::move(*usual);
  *usual = SignMotion{};
}

void choose_with_transitions(const SynthContext& ctx, const std::vector<PhraseItem>& items,
                             std::vector<SignMotion>* motions, std::vector<SignMotion>* usual_clips) {
  std::vector<SignMotion>& usual = *usual_clips;
  for (size_t i = 0; i < items.size(); ++i) {
    if (usual[i].frame_count == 0 || items[i].kind == PhraseItem::Kind::Pause || (*motions)[i].frame_count == 0)
      continue;
    choose_jam_with_transitions(ctx, neighbours_of(ctx, items, *motions, i), ctx.options.carry_elbows,
                                &(*motions)[i], &usual[i]);
  }
}

// Where the phrase's clip still leaps (an arm step over kSwivelChoiceStepM, measured as the clip
// has it: transitions and the elbow's path over the whole clip), each sign whose clip with its
// transitions leaps is judged with them in the other swivel zero: the one synthesize_sign_motion
// solved and did not keep, or, where the sign's own clip did not leap, the fixed-handed zero
// solved now. The other zero's clip (through the same jam judgement) is kept where, with the
// transitions, it is no deeper (kBranchSignSlackM) and steps less. The sign's own choice stands
// everywhere else (the trigger is either measure: the sign alone, synthesize_sign_motion, or with
// its transitions, here), so a sign whose own clip leaps keeps the zero that serves it alone
// (swivel-judge: judged only with the transitions, z góry went 0.6 -> 4.6 mm deep and boczek's
// and wyjechać's leaps came back). Where a sign's own clip steps little its leap can still be in
// the clip: kelner's hand at the shoulder top, the elbow taken up and behind by the rest
// transition and the whole clip's elbow path unable to carry it (docs/SYNTHESIS.md leap).
// Returns whether a sign's clip was changed. Only phrases that leap pay anything (the lexicon's
// largest step is 68 mm).
bool choose_zero_with_transitions(const SynthContext& ctx, const std::vector<PhraseItem>& items,
                                  std::vector<SignMotion>* motions, std::vector<OtherZeroSolve>* others) {
  bool changed = false;
  for (size_t i = 0; i < items.size(); ++i) {
    if (items[i].kind == PhraseItem::Kind::Pause || (*motions)[i].frame_count == 0) continue;
    const Neighbours n = neighbours_of(ctx, items, *motions, i);
    const WithTransitions kept = measure_with_transitions(ctx, (*motions)[i], n, true);
    if (!(kept.step_m > kSwivelChoiceStepM)) continue;
    OtherZeroSolve& o = (*others)[i];
    const std::string where = "sign " + std::to_string(i + 1) + (items[i].label.empty() ? "" : " '" + items[i].label + "'");
    // Both zeros in the shoulder girdle's zone the sign's clip was solved in (a wider one where
    // choose_wide_protraction took it, so the other zero and the rounds are solved in it too).
    std::unique_ptr<SynthContext> zoned;
    if (o.protraction_zone != 0) {
      zoned = std::make_unique<SynthContext>(ctx);
      zoned->rig.protraction_zone = o.protraction_zone;
    }
    const SynthContext& usual_zero = zoned ? *zoned : ctx;
    SynthContext fixed = usual_zero;
    fixed.rig.fixed_handed_swivel_zero = true;
    bool in_fixed = o.solved && o.kept_fixed;  // the zero of the kept clip
    if (!o.solved) {
      std::vector<SynthesisError> repeated;  // the same sign and key pose: the first solve's errors
      o.solved = true;
      if (!synthesize_sign_motion(fixed, items[i].sign, where, &o.motion, &repeated, &o.usual_alternative))
        o.motion = SignMotion{};
    }
    WithTransitions best = kept;
    // A candidate clip through the same jam judgement as the phrase's (choose_with_transitions),
    // measured with the elbow's path, and kept where no deeper and stepping less.
    auto consider = [&](SignMotion* m, SignMotion* m_usual) {
      if (m->frame_count == 0) return false;
      choose_jam_with_transitions(ctx, n, ctx.options.carry_elbows, m, m_usual);
      const WithTransitions w = measure_with_transitions(ctx, *m, n, true);
      if (!(w.depth_m <= best.depth_m + kBranchSignSlackM && w.step_m < best.step_m)) return false;
      (*motions)[i] = std::move(*m);
      best = w;
      changed = true;
      return true;
    };
    if (consider(&o.motion, &o.usual_alternative)) in_fixed = !in_fixed;
    o = OtherZeroSolve{};
    // Then, where it still leaps, each zero's solve with the extra last ramp rounds (the last
    // round's own corrections come on at once: sign_motion.h synthesize_sign_motion_ramped_again),
    // the kept zero's first: the zero a sign's own clip chose can lose to the other's with the
    // rounds (UPPER-BACK1A^: the fixed zero's 179 mm against the usual zero's 102).
    for (bool zero_fixed : {in_fixed, !in_fixed}) {
      if (!(best.step_m > kSwivelChoiceStepM)) break;
      SignMotion again, again_usual;
      std::vector<SynthesisError> repeated;
      if (synthesize_sign_motion_ramped_again(zero_fixed ? fixed : usual_zero, items[i].sign, where, &again,
                                              &repeated, &again_usual))
        consider(&again, &again_usual);
    }
  }
  return changed;
}

// The shoulder girdle's wider protraction as a per-sign alternative (Rig::protraction_zone,
// docs/SYNTHESIS.md arm-side). A sign whose own frames leave an arm deeper than kWideFromM in the
// body is solved once more in each wider zone (arm_ik.cpp kProtractionZones: the girdle
// protracted for wrists across the body further in front of the shoulder and higher up), and the
// shallowest alternative is kept where the sign with its transitions (built as the phrase builds
// them) is shallower by kWideGainM and
// - steps no more in a frame, nor changes its step more (kWideStepSlackM), or stays within
//   kWideStepFreeMPerS and kWideChangeFreeMPerS2 (under the 3 m/s and 50 m/s^2 the smoothness
//   tests hold; at 30 fps 90 and 50 mm a frame, under the corpus census's 100 and 56 mm);
// - takes no wrist that is across the body where the sign starts or ends further out to its own
//   side in the transitions (kWideOutSlackM), or not beyond kWideOutFromRestM out from the rest
//   pose's wrist (the bound of SynthesisCollision.FarSideRestTransitionsBringTheHandAcrossInFront:
//   a rest transition routed round the body's side instead of across its front; a hand on its
//   own side may go out, as the hands parted on the way do);
// - leaves a touch no further off its place (kWideStepSlackM) and a hand held off no further out
//   of the 3-10 cm band than it was (the alternative's key pose is placed afresh).
// Signs within the bound cost nothing: the lexicon's are, on both rigs.
constexpr float kWideFromM = 0.005f;
constexpr float kWideGainM = 0.001f;
constexpr float kWideStepSlackM = 0.002f;
constexpr float kWideOutSlackM = 0.01f, kWideOutFromRestM = 0.04f;
constexpr float kWideStepFreeMPerS = 2.7f, kWideChangeFreeMPerS2 = 45.0f;
constexpr float kHeldOffNearM = 0.03f, kHeldOffFarM = 0.10f;
bool no_worse_placed(const SignMotion& now, const SignMotion& alt) {
  if (alt.max_reach_error_m > now.max_reach_error_m + kWideStepSlackM) return false;
  if (alt.contact_distance_m.size() != now.contact_distance_m.size()) return false;
  for (size_t k = 0; k < alt.contact_distance_m.size(); ++k) {
    const float a = alt.contact_distance_m[k], n = now.contact_distance_m[k];
    if (a > std::max(n, kHeldOffFarM) + 1e-4f) return false;
    if (n >= kHeldOffNearM && a < kHeldOffNearM - 1e-4f) return false;
  }
  return true;
}
// A sign taken in a wider zone has its OtherZeroSolve (`others`) replaced by that solve's, so
// that choose_zero_with_transitions, after it, judges the other zero and the extra rounds in the
// zone the sign now has.
void choose_wide_protraction(const SynthContext& ctx, const std::vector<PhraseItem>& items,
                             std::vector<SignMotion>* motions, std::vector<OtherZeroSolve>* others) {
  if (!ctx.options.avoid_collisions || ctx.rig.protraction_zone != 0) return;
  std::unique_ptr<SynthContext> wide[2];
  float rest_out[2] = {0.0f, 0.0f};  // the rest pose's wrists out to their sides (with `wide`)
  for (size_t i = 0; i < items.size(); ++i) {
    if (items[i].kind == PhraseItem::Kind::Pause || (*motions)[i].frame_count == 0) continue;
    if (!(sign_motion_depth(ctx, (*motions)[i]) > kWideFromM)) continue;
    if (!wide[0]) {
      PoseBuilder rest(ctx.rig);
      rest.set_from_local(ctx.rest_locals.data());
      for (int side = 0; side < 2; ++side)
        rest_out[side] = glm::dot(rest.position(ctx.rig.arms[side].hand), side == kLeft ? ctx.rig.left : -ctx.rig.left);
    }
    const Neighbours n = neighbours_of(ctx, items, *motions, i);
    const WithTransitions now = measure_with_transitions(ctx, (*motions)[i], n, true, true);
    SignMotion best;
    OtherZeroSolve best_other;
    float best_depth = now.depth_m - kWideGainM;
    for (int zone = 1; zone <= 2; ++zone) {
      std::unique_ptr<SynthContext>& wctx = wide[zone - 1];
      if (!wctx) {
        wctx = std::make_unique<SynthContext>(ctx);
        wctx->rig.protraction_zone = zone;
      }
      SignMotion alt;
      OtherZeroSolve alt_other;
      std::vector<SynthesisError> repeated;
      if (!synthesize_sign_motion(*wctx, items[i].sign, "", &alt, &repeated, nullptr, &alt_other) ||
          alt.frame_count == 0)
        continue;
      if (!no_worse_placed((*motions)[i], alt)) continue;
      const WithTransitions w = measure_with_transitions(ctx, alt, n, true, true);
      bool out_ok = true;
      for (int side = 0; side < 2; ++side)
        out_ok = out_ok && (!(now.across[side] || w.across[side]) ||
                            w.wrist_out_m[side] <= std::max(now.wrist_out_m[side] + kWideOutSlackM,
                                                            rest_out[side] + kWideOutFromRestM));
      const float fps = ctx.options.fps;
      const bool step_ok = w.step_m <= now.step_m + kWideStepSlackM || w.step_m <= kWideStepFreeMPerS / fps;
      const bool change_ok =
          w.change_m <= now.change_m + kWideStepSlackM || w.change_m <= kWideChangeFreeMPerS2 / (fps * fps);
      if (w.depth_m < best_depth && step_ok && change_ok && out_ok) {
        best_depth = w.depth_m;
        best = std::move(alt);
        best_other = std::move(alt_other);
      }
    }
    if (best.frame_count > 0) {
      (*motions)[i] = std::move(best);
      (*others)[i] = std::move(best_other);
    }
  }
}

// A symmetric pair laid apart to both sides at its key pose (SignMotion::mirror_laid_apart) is
// judged against the clip with the dominant hand alone moved out of the way (the escape, solved
// here: synthesize_sign_motion_escaping), both with the transitions next to the sign, as the jam
// rule's clips are (the escape's own jam choice made first, as choose_with_transitions makes it):
// the laid-apart clip stays where mirror_apart_is_kept says so. Judged on the sign alone, 4
// HamNoSys corpus signs were 2.8-3.8 mm deeper with their rest transitions (PEACE1^ 0.0 -> 3.8 mm,
// potem 1.9 -> 4.8; docs/SYNTHESIS.md sign-hands). A laid-apart clip that is clean with its
// transitions (0.1 mm) and steps at most kCleanStepM in a frame is kept without the escape's
// solve: the escape could win only on a smaller step, and under kCleanStepM (the lexicon's largest
// step is 68 mm) that is not worth a second solve and its transitions (they were 3.9 % of the
// lexicon's instructions; measured, the one corpus sign that then keeps the laid-apart clip steps
// 45 -> 56 mm, nothing deeper). Where the escape is kept, so is its other-zero solve.
constexpr float kCleanStepM = 0.06f;
void choose_mirror_apart(const SynthContext& ctx, const std::vector<PhraseItem>& items,
                         std::vector<SignMotion>* motions, std::vector<OtherZeroSolve>* others) {
  for (size_t i = 0; i < items.size(); ++i) {
    if (items[i].kind == PhraseItem::Kind::Pause || (*motions)[i].frame_count == 0 ||
        !(*motions)[i].mirror_laid_apart || !ctx.mirror_pairs_apart || !ctx.options.avoid_collisions)
      continue;
    const Neighbours n = neighbours_of(ctx, items, *motions, i);
    const WithTransitions apart = measure_with_transitions(ctx, (*motions)[i], n, ctx.options.carry_elbows);
    // Crossing fingers are judged against the escape even where the laid-apart clip is clean.
    if (apart.depth_m <= 1e-4f && apart.step_m <= kCleanStepM &&
        !(*motions)[i].mirror_fingers_cross)
      continue;
    SignMotion escape, escape_usual;
    OtherZeroSolve escape_other;
    std::vector<SynthesisError> repeated;  // the same sign: the first solve's errors
    const std::string where = "sign " + std::to_string(i + 1);
    if (!synthesize_sign_motion_escaping(ctx, items[i].sign, where, &escape, &repeated, &escape_usual,
                                         &escape_other) ||
        escape.frame_count == 0)
      continue;
    choose_jam_with_transitions(ctx, n, ctx.options.carry_elbows, &escape, &escape_usual);
    const WithTransitions other = measure_with_transitions(ctx, escape, n, ctx.options.carry_elbows);
    if (!mirror_apart_is_kept((*motions)[i], apart.depth_m, apart.step_m, other.depth_m,
                              other.step_m)) {
      (*motions)[i] = std::move(escape);
      (*others)[i] = std::move(escape_other);
    }
  }
}

SynthesisResult run_phrase(const SynthContext& ctx, const std::vector<PhraseItem>& items) {
  SynthesisResult result;
  const SynthesisOptions& options = ctx.options;
  const Rig& rig = ctx.rig;
  const int J = rig.joint_count;
  const float fps = options.fps;

  // Every sign first, so all errors are reported together.
  std::vector<SignMotion> motions(items.size()), usual(items.size());
  std::vector<OtherZeroSolve> others(items.size());
  for (size_t i = 0; i < items.size(); ++i) {
    if (items[i].kind == PhraseItem::Kind::Pause) continue;
    std::string where = "sign " + std::to_string(i + 1) +
                        (items[i].label.empty() ? "" : " '" + items[i].label + "'");
    synthesize_sign_motion(ctx, items[i].sign, where, &motions[i], &result.errors, &usual[i], &others[i], true);
  }
  if (!result.errors.empty()) return result;
  // Each sign's choices, in this order (docs/SYNTHESIS.md arm-side, merged with leap; sign-hands):
  // the jam rule's clip judged with the transitions, a symmetric pair laid apart to both sides
  // against the old escape, then a deep sign's wider protraction zones, before
  // the clip is built; then, where the built clip still leaps, the other swivel zero and the
  // extra last ramp rounds (choose_zero_with_transitions, below), in the zone the sign then has,
  // and the clip built again only where they changed a sign.
  choose_with_transitions(ctx, items, &motions, &usual);
  choose_mirror_apart(ctx, items, &motions, &others);
  choose_wide_protraction(ctx, items, &motions, &others);

  Timeline tl;
  tl.joints = J;
  // Room for a one-sign phrase from rest and back (the lexicon's: 72 frames on average), so the
  // frames are not copied as the timeline grows (speed-wasm); a longer phrase grows as before.
  tl.frames.reserve(static_cast<size_t>(128) * static_cast<size_t>(J));
  tl.exempt.reserve(128);
  Clip& clip = result.clip;
  std::vector<face::FaceCue> face_cues;  // one per sign and pause, for the face layer
  auto add_segment = [&](ClipSegment::Kind kind, const std::string& label, int word, int first, int last) {
    ClipSegment seg;
    seg.kind = kind;
    seg.label = label;
    seg.word_index = word;
    seg.start_s = first / static_cast<double>(fps);
    seg.end_s = last / static_cast<double>(fps);
    clip.segments.push_back(seg);
  };
  auto add_face_cue = [&](const PhraseItem& item) {
    face::FaceCue cue;
    cue.start_s = clip.segments.back().start_s;
    cue.end_s = clip.segments.back().end_s;
    cue.is_pause = item.kind == PhraseItem::Kind::Pause;
    if (!cue.is_pause) cue.nonmanual = item.sign.nonmanual;
    // Signers commonly mouth the word a sign stands for; a sign's own mouth picture wins, and a
    // fingerspelled letter is not mouthed letter by letter.
    if (options.mouthing && item.kind == PhraseItem::Kind::Sign && cue.nonmanual.mouthing.empty())
      cue.nonmanual.mouthing = item.label;
    if (!options.mouthing) cue.nonmanual.mouthing.clear();
    face_cues.push_back(cue);
  };
  auto transition_to = [&](const glm::quat* target, std::uint8_t target_exempt) {
    if (tl.count() == 0) return;
    TransitionPlan plan = plan_transition(ctx, tl.last(), target, tl.exempt.back(), target_exempt);
    result.report.transition_states += plan.k;
    result.report.via_points_inserted += plan.via_points;
    int first = tl.count() - 1;
    if (plan.k > 1) tl.append(plan.frames.data(), plan.k - 1, plan.exempt.data());
    add_segment(ClipSegment::Kind::Transition, "", -1, first, tl.count());
  };

  // The phrase's clip from the signs' clips and the transitions between them; returns its largest
  // arm step (clip_steps.h). Built again where a sign's clip changes below.
  const SynthesisReport report_before = result.report;
  std::vector<std::uint8_t> none(1, 0);
  auto assemble = [&]() -> float {
    result.report = report_before;
    clip.segments.clear();
    face_cues.clear();
    tl.frames.clear();
    tl.exempt.clear();
    if (options.start_from_rest) tl.append(ctx.rest_locals.data(), 1, none.data());
    for (size_t i = 0; i < items.size(); ++i) {
      const PhraseItem& item = items[i];
      if (item.kind == PhraseItem::Kind::Pause) {
        if (tl.count() == 0) continue;
        int n = std::max(1, static_cast<int>(std::lround(options.pause_s * fps / options.speed)));
        int first = tl.count() - 1;
        std::vector<glm::quat> hold(tl.last(), tl.last() + J);
        for (int f = 0; f < n; ++f) tl.append(hold.data(), 1, &tl.exempt.back());
        add_segment(ClipSegment::Kind::Pause, item.label, item.word_index, first, tl.count() - 1);
        add_face_cue(item);
        continue;
      }
      const SignMotion& m = motions[i];
      if (m.frame_count == 0) continue;
      transition_to(m.rotations.data(), m.exempt[0]);
      int first = tl.count();
      tl.append(m.rotations.data(), m.frame_count, m.exempt.data());
      add_segment(segment_kind(item.kind), item.label, item.word_index, first, tl.count() - 1);
      add_face_cue(item);
      result.report.max_reach_error_m = std::max(result.report.max_reach_error_m, m.max_reach_error_m);
      result.report.contact_distances_m.insert(result.report.contact_distances_m.end(),
                                               m.contact_distance_m.begin(), m.contact_distance_m.end());
      result.report.warnings.insert(result.report.warnings.end(), m.warnings.begin(), m.warnings.end());
    }
    if (options.start_from_rest && tl.count() > 1) {
      transition_to(ctx.rest_locals.data(), 0);
      tl.append(ctx.rest_locals.data(), 1, none.data());
    }
    if (tl.count() == 0) tl.append(ctx.rest_locals.data(), 1, none.data());

    clip.fps = fps;
    clip.frame_count = tl.count();
    clip.joint_names = rig.names;
    clip.rotations = std::move(tl.frames);
    // Every stage above interpolates swivel numbers, whose zero turns half round for a wrist across
    // the body at the shoulder joint's coronal plane: the elbow's path is made continuous here, on
    // the whole clip (signs, transitions and holds), before the penetration check measures it.
    float step_m = 0.0f;
    if (options.carry_elbows)
      result.report.elbow_frames_carried =
          continue_elbow_paths(rig, &ctx.body, fps, clip.frame_count, &clip.rotations, &step_m);
    else {
      // Measured as the clip has it by default, so that the choice below is the same with and
      // without the elbow's path (as sign_motion.cpp sign_depth_and_step).
      std::vector<glm::quat> carried = clip.rotations;
      continue_elbow_paths(rig, &ctx.body, fps, clip.frame_count, &carried, &step_m);
    }
    return step_m;
  };
  const float step_m = assemble();
  if (options.avoid_collisions && !rig.fixed_handed_swivel_zero && step_m > kSwivelChoiceStepM &&
      choose_zero_with_transitions(ctx, items, &motions, &others))
    assemble();
  clip.root_translation.assign(clip.frame_count, rig.root_translation);
  if (options.face) {
    // The face layer after the body: head gestures and gaze ride on the synthesised neck.
    const avatar::Avatar& avatar = *ctx.avatar;
    auto joint_of = [&](int canonical) {
      return canonical < static_cast<int>(avatar.canonical_to_joint.size())
                 ? avatar.canonical_to_joint[static_cast<std::size_t>(canonical)]
                 : -1;
    };
    face::FaceRig face_rig;
    face_rig.head = joint_of(skeleton::kHead);
    face_rig.left_eye = joint_of(skeleton::kLeftEye);
    face_rig.right_eye = joint_of(skeleton::kRightEye);
    face::FaceOptions face_options;
    face_options.emotion = options.emotion;
    face_options.intensity = options.emotion_intensity;
    face_options.mouthing = options.mouthing;
    if (!face::add_face_tracks(clip, avatar.skeleton, face_rig, face_cues, face_options))
      result.report.warnings.push_back("face tracks skipped: the clip does not match the skeleton");
  }
  result.report.intended_contact = tl.exempt;
  std::string what;
  result.report.max_penetration_m =
      max_penetration(ctx, clip.rotations.data(), clip.frame_count, tl.exempt.data(), &what, nullptr);
  if (result.report.max_penetration_m > 0.005f)
    result.report.warnings.push_back("penetration of " +
                                     std::to_string(result.report.max_penetration_m * 1000.0f) +
                                     " mm: " + what);
  return result;
}

}  // namespace

SynthesisResult synthesize_sign(const notation::SignSpec& sign, const avatar::Avatar& avatar,
                                const SynthesisOptions& options) {
  PhraseItem item;
  item.kind = PhraseItem::Kind::Sign;
  item.sign = sign;
  item.label = sign.gloss;
  item.word_index = 0;
  return synthesize_phrase({item}, avatar, options);
}

}  // namespace sw::synthesis

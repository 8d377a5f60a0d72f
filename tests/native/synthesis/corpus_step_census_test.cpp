// Diagnostic, not a check (docs/SYNTHESIS.md, step-census): with SIGNWEAVE_STEP_CENSUS=1, every
// corpus sign whose largest arm step (clip_steps.h, the measure `signweave-cli check` reports) is
// over SIGNWEAVE_STEP_CENSUS_MIN_MM (default 100) is listed with where that step is and what made
// it. Where: the phase (rest-in: a step arriving at the sign's first frame or before it; rest-out;
// else inside the sign, with the frame's offset and the sign's movement kinds). What, for the arm
// that steps:
// - "wrist": the wrist itself moves more than half the step (its target moved, or the hand turned
//   about its contact point);
// - "zero-turn": the elbow swings with the wrist nearly still and the swivel's zero (arm_ik.cpp
//   solve_chain: the lateral direction square to the shoulder-wrist line and the way down) turned
//   by 0.5 rad or more between the frames, more than the swivel number read in each frame's own
//   zero changed (the elbow-flip family: the same number, the other side);
// - "number": the swivel number read in each frame's own zero jumped by 0.5 rad or more;
// - "reach": neither (the elbow moves with the shoulder-wrist distance, the clavicle or the trunk).
// And which stage: the same sign synthesised without collision avoidance (no body in the swivel
// choice, no per-frame clearing, pushes or via points): its largest step over the whole clip (and
// at that frame where the frame counts agree; they mostly do not, avoidance times transitions);
// whether the trunk (thorax turn) moves at that frame; whether the arm is a hand placed on the
// other hand. SIGNWEAVE_STEP_CENSUS_ONLY=<gloss> lists one sign's frames;
// SIGNWEAVE_STEP_CENSUS_FILE=<jsonl> reads another file with a "hamnosys" field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "notation/parse.h"
#include "synthesis/arm_ik.h"
#include "synthesis/clip_steps.h"
#include "synthesis/collision.h"
#include "synthesis/sign_motion.h"
#include "synthesis/synthesize.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

glm::vec3 reject_from(const glm::vec3& v, const glm::vec3& n) { return v - glm::dot(v, n) * n; }

// The swivel's zero of an arm whose shoulder joint is at `shoulder` and wrist at `wrist`, as
// arm_ik.cpp solve_chain builds it (the way down leaning forward near the vertical, the lateral
// direction square to both): `down` and `outp`.
void swivel_zero(const Rig& rig, Side side, const glm::vec3& shoulder, const glm::vec3& wrist,
                 glm::vec3* down, glm::vec3* outp) {
  const glm::vec3 out_dir = side == kLeft ? rig.left : -rig.left;
  const glm::vec3 to = wrist - shoulder;
  const glm::vec3 axis = glm::length(to) > 1e-6f ? glm::normalize(to) : out_dir;
  const float upright = std::clamp((glm::dot(axis, rig.up) - 0.93f) / (0.99f - 0.93f), 0.0f, 1.0f);
  const float lean = 0.5f * upright * upright * (3.0f - 2.0f * upright);
  glm::vec3 d = reject_from(-rig.up + lean * rig.forward, axis);
  if (glm::length(d) < 1e-3f) d = reject_from(-rig.forward, axis);
  d = glm::normalize(d);
  glm::vec3 o = reject_from(reject_from(out_dir, axis), d);
  o = glm::length(o) > 1e-6f ? glm::normalize(o) : glm::normalize(glm::cross(axis, d));
  *down = d;
  *outp = o;
}

// The elbow's swivel number in the zero of the shoulder-wrist line (radians, 0 down, + out).
float swivel_number(const Rig& rig, Side side, const ArmSegments& a, const glm::vec3& zero_wrist) {
  glm::vec3 down, outp;
  swivel_zero(rig, side, a.shoulder, zero_wrist, &down, &outp);
  const glm::vec3 e = a.elbow - a.shoulder;
  return std::atan2(glm::dot(e, outp), glm::dot(e, down));
}

float angle_between(float a, float b) {
  float d = std::fmod(std::fabs(a - b), 2.0f * 3.14159265f);
  return d > 3.14159265f ? 2.0f * 3.14159265f - d : d;
}

const char* kind_name(notation::MovementKind k) {
  using K = notation::MovementKind;
  switch (k) {
    case K::Straight:
      return "straight";
    case K::Arc:
      return "arc";
    case K::Circle:
      return "circle";
    case K::Ellipse:
      return "ellipse";
    case K::Wavy:
      return "wavy";
    case K::Zigzag:
      return "zigzag";
    case K::Spiral:
      return "spiral";
    case K::FingerPlay:
      return "fingerplay";
    case K::WristNod:
      return "nod";
    case K::WristSwing:
      return "swing";
    case K::WristTwist:
      return "twist";
    case K::WristCircle:
      return "wcircle";
    case K::Replace:
      return "replace";
    case K::Target:
      return "target";
  }
  return "?";
}

TEST(CorpusStepCensus, ListsLargeArmStepsByCause) {
  const char* on = std::getenv("SIGNWEAVE_STEP_CENSUS");
  if (!on || std::string(on) != "1") GTEST_SKIP() << "set SIGNWEAVE_STEP_CENSUS=1";
  const char* min_env = std::getenv("SIGNWEAVE_STEP_CENSUS_MIN_MM");
  const float min_m = (min_env ? std::atof(min_env) : 100.0f) / 1000.0f;
  const char* only = std::getenv("SIGNWEAVE_STEP_CENSUS_ONLY");
  const char* file_env = std::getenv("SIGNWEAVE_STEP_CENSUS_FILE");
  testing::ProjectAvatar project = testing::load_project_avatar();
  if (!project.present || !project.error.empty())
    GTEST_SKIP() << "the project avatar is absent or does not load";
  const Synthesizer synth(project.avatar);
  SynthContext ctx;
  std::string error;
  ASSERT_TRUE(make_context(project.avatar, SynthesisOptions{}, &ctx, &error)) << error;
  const Rig& rig = ctx.rig;
  const int J = rig.joint_count;
  std::ifstream in(file_env ? std::string(file_env)
                            : std::string(SIGNWEAVE_SHARED_DIR) + "/corpus/hamnosys-dev.jsonl");
  if (!in) GTEST_SKIP() << "../shared/corpus/hamnosys-dev.jsonl not found";
  SynthesisOptions no_avoid;
  no_avoid.avoid_collisions = false;
  std::map<std::string, int> by_cause;
  std::string line;
  int listed = 0;
  while (std::getline(in, line)) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object()) continue;
    std::string h = j.value("hamnosys", "");
    const std::string gloss = j.value("gloss", "");
    if (h.empty()) continue;
    if (only && gloss != only) continue;
    std::replace(h.begin(), h.end(), '\n', ' ');
    std::replace(h.begin(), h.end(), '\r', ' ');
    const auto parsed = notation::parse_signs(h, notation::NotationFormat::HamNoSys);
    if (parsed.empty() || !parsed[0].ok() || !parsed[0].spec) continue;
    const notation::SignSpec& spec = *parsed[0].spec;
    const SynthesisResult r = synth.sign(spec, SynthesisOptions{});
    if (!r.ok()) continue;
    const Clip& c = r.clip;
    const FrameSteps steps = measure_frame_steps(rig, c);
    if (steps.step_m <= min_m) continue;
    // "right elbow at frame 42"
    const Side side = steps.step_what.rfind("left", 0) == 0 ? kLeft : kRight;
    const bool elbow = steps.step_what.find("elbow") != std::string::npos;
    const int f = std::atoi(steps.step_what.substr(steps.step_what.rfind(' ') + 1).c_str());
    if (f < 1 || f >= c.frame_count) continue;
    PoseBuilder pb(rig);
    pb.set_from_local(&c.rotations[static_cast<size_t>(f - 1) * J]);
    const ArmSegments a0 = posed_arm(pb, side);
    const glm::quat chest0 = rig.chest >= 0 ? pb.delta(rig.chest) : glm::quat(1, 0, 0, 0);
    pb.set_from_local(&c.rotations[static_cast<size_t>(f) * J]);
    const ArmSegments a1 = posed_arm(pb, side);
    const glm::quat chest1 = rig.chest >= 0 ? pb.delta(rig.chest) : glm::quat(1, 0, 0, 0);
    const float wrist_step = glm::length(a1.wrist - a0.wrist);
    const float elbow_step = glm::length(a1.elbow - a0.elbow);
    const float shoulder_step = glm::length(a1.shoulder - a0.shoulder);
    // The number in each frame's own zero, and the previous elbow read in this frame's zero.
    const float n0 = swivel_number(rig, side, a0, a0.wrist);
    const float n1 = swivel_number(rig, side, a1, a1.wrist);
    const float n0_in_1 = swivel_number(rig, side, a0, a1.wrist);
    const float zero_turn = angle_between(n0, n0_in_1);
    const float number_jump = angle_between(n0, n1);
    std::string what;
    if (!elbow || wrist_step > 0.5f * steps.step_m)
      what = "wrist";
    else if (zero_turn >= 0.5f && zero_turn > number_jump)
      what = "zero-turn";
    else if (number_jump >= 0.5f)
      what = "number";
    else
      what = "reach";
    // The phase.
    int sign_first = 0, sign_last = c.frame_count - 1;
    for (const ClipSegment& s : c.segments)
      if (s.kind == ClipSegment::Kind::Sign) {
        sign_first = static_cast<int>(std::lround(s.start_s * c.fps));
        sign_last = static_cast<int>(std::lround(s.end_s * c.fps));
      }
    std::string phase;
    if (f <= sign_first)
      phase = "rest-in";
    else if (f > sign_last)
      phase = "rest-out";
    else
      phase = "sign+" + std::to_string(f - sign_first);
    // Collision avoidance off: the step at the same frame of the same joint.
    std::string stage;
    const SynthesisResult bare = synth.sign(spec, no_avoid);
    if (bare.ok() && bare.clip.frame_count == c.frame_count) {
      PoseBuilder pbb(rig);
      pbb.set_from_local(&bare.clip.rotations[static_cast<size_t>(f - 1) * J]);
      const ArmSegments b0 = posed_arm(pbb, side);
      pbb.set_from_local(&bare.clip.rotations[static_cast<size_t>(f) * J]);
      const ArmSegments b1 = posed_arm(pbb, side);
      const float bare_step =
          elbow ? glm::length(b1.elbow - b0.elbow) : glm::length(b1.wrist - b0.wrist);
      const FrameSteps bare_all = measure_frame_steps(rig, bare.clip);
      stage = bare_step <= 0.1f ? (bare_all.step_m <= 0.1f ? "collision" : "collision*")
                                : "not-collision";
      char buf[64];
      std::snprintf(buf, sizeof buf, " bare %.0f/%.0f", bare_step * 1000.0f,
                    bare_all.step_m * 1000.0f);
      stage += buf;
    } else if (bare.ok()) {
      // Avoidance changes the frame count (via points): the bare clip's largest step only.
      const FrameSteps bare_all = measure_frame_steps(rig, bare.clip);
      char buf[64];
      std::snprintf(buf, sizeof buf, "frames-differ bare -/%.0f", bare_all.step_m * 1000.0f);
      stage = buf;
    }
    const glm::quat trunk_rel = glm::inverse(chest0) * chest1;
    const float trunk_turn = 2.0f * std::acos(std::min(1.0f, std::fabs(trunk_rel.w)));
    std::string placed;
    const notation::HandSpec* hs =
        side == kRight ? &spec.dominant : (spec.nondominant ? &*spec.nondominant : nullptr);
    if (hs && hs->location.kind == notation::Location::Kind::OtherHand) placed = " placed";
    std::string kinds;
    for (const notation::MovementStep& ms : spec.movements)
      for (const notation::Movement& m :
           side == kRight || ms.nondominant.empty() ? ms.dominant : ms.nondominant)
        kinds += std::string(kinds.empty() ? "" : ",") + kind_name(m.kind);
    ++by_cause[what + " " + phase.substr(0, phase.find('+'))];
    ++listed;
    std::printf(
        "STEP %-24s %5.0f mm %-22s %-9s %-9s wrist %3.0f elbow %3.0f shoulder %3.0f mm | number "
        "%+.2f -> %+.2f, zero turned %.2f | %s | trunk %.3f rad%s | moves %s | depth %.1f\n",
        gloss.substr(0, 24).c_str(), steps.step_m * 1000.0f, steps.step_what.c_str(), phase.c_str(),
        what.c_str(), wrist_step * 1000.0f, elbow_step * 1000.0f, shoulder_step * 1000.0f, n0, n1,
        zero_turn, stage.c_str(), trunk_turn, placed.c_str(), kinds.empty() ? "-" : kinds.c_str(),
        r.report.max_penetration_m * 1000.0f);
    if (only)
      for (int g = 0; g < c.frame_count; ++g) {
        pb.set_from_local(&c.rotations[static_cast<size_t>(g) * J]);
        const ArmSegments a = posed_arm(pb, side);
        std::printf("  f%3d s(%.3f %.3f %.3f) e(%.3f %.3f %.3f) w(%.3f %.3f %.3f) number %+.2f\n",
                    g, a.shoulder.x, a.shoulder.y, a.shoulder.z, a.elbow.x, a.elbow.y, a.elbow.z,
                    a.wrist.x, a.wrist.y, a.wrist.z, swivel_number(rig, side, a, a.wrist));
      }
  }
  for (const auto& [cause, n] : by_cause) std::printf("STEP cause %s: %d\n", cause.c_str(), n);
  std::printf("STEP listed %d\n", listed);
}

}  // namespace
}  // namespace sw::synthesis

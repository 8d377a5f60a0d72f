// Diagnostic, not a check (docs/SYNTHESIS.md, Real signs): with SIGNWEAVE_CORPUS_DIAGNOSE=1, each
// sampled clean corpus sign deeper than SIGNWEAVE_CORPUS_MIN_MM (default 5) is listed with its
// deepest frame, the phase it is in (rest-in, the key pose, inside the sign, rest-out), what
// penetrates, and the depths of the sign's first and last frames (the floors a rest transition is
// judged against); SIGNWEAVE_CORPUS_STRIDE (default 2) samples as CorpusSynthesis does, and
// SIGNWEAVE_CORPUS_ONLY=<index of the clean sign> prints that sign's every frame with its depth and
// its arms' shoulder, elbow and wrist. Without the switch, the corpus or the avatar it skips.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "notation/parse.h"
#include "synthesis/sign_motion.h"
#include "synthesis/synthesize.h"
#include "synthesis/transition.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

TEST(CorpusDiagnose, ListsDeepFramesByPhase) {
  const char* on = std::getenv("SIGNWEAVE_CORPUS_DIAGNOSE");
  if (!on || std::string(on) != "1") GTEST_SKIP() << "set SIGNWEAVE_CORPUS_DIAGNOSE=1";
  const char* stride_env = std::getenv("SIGNWEAVE_CORPUS_STRIDE");
  const int stride = stride_env ? std::max(1, std::atoi(stride_env)) : 2;
  const char* min_env = std::getenv("SIGNWEAVE_CORPUS_MIN_MM");
  const float min_m = (min_env ? std::atof(min_env) : 5.0f) / 1000.0f;
  testing::ProjectAvatar project = testing::load_project_avatar();
  if (!project.present || !project.error.empty())
    GTEST_SKIP() << "the project avatar is absent or does not load";
  const Synthesizer synth(project.avatar);
  SynthContext ctx;
  std::string error;
  ASSERT_TRUE(make_context(project.avatar, SynthesisOptions{}, &ctx, &error)) << error;
  for (const Capsule& cap : ctx.body.trunk)
    std::printf("CAPSULE %s a(%.2f %.2f %.2f) b(%.2f %.2f %.2f) r=%.3f\n", cap.name.c_str(),
                cap.a.x, cap.a.y, cap.a.z, cap.b.x, cap.b.y, cap.b.z, cap.radius_m);
  std::printf("ARMS upper r=%.3f fore r=%.3f skip %.3f fskip %.3f\n",
              ctx.body.upper_arm[1].radius_m, ctx.body.forearm[1].radius_m,
              ctx.body.upper_arm_skip_m[1], ctx.body.forearm_contact_skip_m);
  std::ifstream in(std::string(SIGNWEAVE_SHARED_DIR) + "/corpus/hamnosys-dev.jsonl");
  if (!in) GTEST_SKIP() << "../shared/corpus/hamnosys-dev.jsonl not found";
  std::string line;
  int clean = 0;
  std::map<std::string, int> by_phase;
  while (std::getline(in, line)) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object()) continue;
    std::string h = j.value("hamnosys", "");
    if (h.empty()) continue;
    std::replace(h.begin(), h.end(), '\n', ' ');
    std::replace(h.begin(), h.end(), '\r', ' ');
    const auto parsed = notation::parse_signs(h, notation::NotationFormat::HamNoSys);
    if (parsed.empty() || !parsed[0].ok() || !parsed[0].spec) continue;
    const int index = clean++;
    const char* only = std::getenv("SIGNWEAVE_CORPUS_ONLY");
    if (only && std::atoi(only) != index) continue;
    if (!only && index % stride != 0) continue;
    const SynthesisResult r = synth.sign(*parsed[0].spec, SynthesisOptions{});
    if (!r.ok() || r.report.max_penetration_m <= min_m) continue;
    const Clip& c = r.clip;
    std::string what;
    int worst = -1;
    const float d = max_penetration(ctx, c.rotations.data(), c.frame_count,
                                    r.report.intended_contact.data(), &what, &worst);
    int sign_first = 0, sign_last = c.frame_count - 1;
    for (const ClipSegment& s : c.segments)
      if (s.kind == ClipSegment::Kind::Sign) {
        sign_first = static_cast<int>(std::lround(s.start_s * c.fps));
        sign_last = static_cast<int>(std::lround(s.end_s * c.fps));
      }
    std::string phase;
    if (worst < sign_first)
      phase = "rest-in";
    else if (worst > sign_last)
      phase = "rest-out";
    else
      phase = worst == sign_first ? "key" : "sign";
    const int J = c.joint_count();
    std::string w0, w1;
    const float d0 = max_penetration(ctx, &c.rotations[static_cast<size_t>(sign_first) * J], 1,
                                     &r.report.intended_contact[sign_first], &w0, nullptr);
    const float d1 = max_penetration(ctx, &c.rotations[static_cast<size_t>(sign_last) * J], 1,
                                     &r.report.intended_contact[sign_last], &w1, nullptr);
    ++by_phase[phase];
    if (only) {
      std::printf("HNS %s\n", h.c_str());
      for (int f = 0; f < c.frame_count; ++f) {
        std::string w;
        const float df = max_penetration(ctx, &c.rotations[static_cast<size_t>(f) * J], 1,
                                         &r.report.intended_contact[f], &w, nullptr);
        PoseBuilder pb(ctx.rig);
        pb.set_from_local(&c.rotations[static_cast<size_t>(f) * J]);
        const ArmSegments ra = posed_arm(pb, kRight), la = posed_arm(pb, kLeft);
        std::printf(
            "  f%3d ex%d %6.1f %-28s R s(%.2f %.2f %.2f) e(%.2f %.2f %.2f) w(%.2f %.2f %.2f) L "
            "e(%.2f %.2f %.2f) w(%.2f %.2f %.2f)\n",
            f, r.report.intended_contact[f], df * 1000.0f, w.c_str(), ra.shoulder.x, ra.shoulder.y,
            ra.shoulder.z, ra.elbow.x, ra.elbow.y, ra.elbow.z, ra.wrist.x, ra.wrist.y, ra.wrist.z,
            la.elbow.x, la.elbow.y, la.elbow.z, la.wrist.x, la.wrist.y, la.wrist.z);
      }
    }
    std::printf(
        "DIAG %5d %-24s %6.1f mm %-8s f%d [%d..%d of %d] via=%d %-32s | first %.1f %s | last %.1f "
        "%s\n",
        index, j.value("gloss", "").substr(0, 24).c_str(), d * 1000.0f, phase.c_str(), worst,
        sign_first, sign_last, c.frame_count, r.report.via_points_inserted, what.c_str(),
        d0 * 1000.0f, w0.c_str(), d1 * 1000.0f, w1.c_str());
  }
  for (const auto& [phase, n] : by_phase) std::printf("DIAG phase %s: %d\n", phase.c_str(), n);
}

}  // namespace
}  // namespace sw::synthesis

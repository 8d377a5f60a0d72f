// Sign structure in synthesis: which hand signs a one-handed sign of the non-dominant hand
// (HamNoSys hamnondominant, G-SiGML <sign_manual nondominant="true">).
#include <gtest/gtest.h>

#include <string>

#include "notation/parse.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace sw::synthesis::testing;

// How far each index fingertip travels over the sign's frames (left, right).
std::array<float, 2> tip_paths(const notation::SignSpec& sign) {
  avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  EXPECT_TRUE(build_rig(av, &rig, &error)) << error;
  SynthesisResult r = synthesize_sign(sign, av);
  EXPECT_TRUE(r.ok());
  std::array<float, 2> path{0.0f, 0.0f};
  if (!r.ok()) return path;
  const int first = first_sign_frame(r.clip), last = last_sign_frame(r.clip);
  PoseBuilder prev = frame_pose(rig, r.clip, first);
  for (int f = first + 1; f <= last; ++f) {
    PoseBuilder pb = frame_pose(rig, r.clip, f);
    path[0] += glm::length(pb.tip(kLeft, 1) - prev.tip(kLeft, 1));
    path[1] += glm::length(pb.tip(kRight, 1) - prev.tip(kRight, 1));
    prev = pb;
  }
  return path;
}

notation::SignSpec parsed(const std::string& text, notation::NotationFormat format) {
  const notation::ParseOutcome out = notation::parse_notation(text, format);
  EXPECT_TRUE(out.ok() && out.signs.size() == 1u) << text;
  return out.signs.empty() ? notation::SignSpec{} : out.signs[0];
}

TEST(SignStructure, NondominantOneHandedSignMovesTheLeftHand) {
  const std::string gsigml =
      "<sigml><hamgestural_sign gloss=\"T\"><sign_manual nondominant=\"true\">"
      "<handconfig handshape=\"finger2\" extfidir=\"u\" palmor=\"r\"/>"
      "<location_bodyarm location=\"chest\"/><directedmotion direction=\"o\" size=\"big\"/>"
      "</sign_manual></hamgestural_sign></sigml>";
  const notation::SignSpec g = parsed(gsigml, notation::NotationFormat::GSiGML);
  EXPECT_TRUE(g.one_hand_is_nondominant);
  const auto gp = tip_paths(g);
  EXPECT_GT(gp[0], 0.15f) << "the non-dominant (left) hand must make the movement";
  EXPECT_LT(gp[1], 0.02f) << "the dominant (right) hand must rest";

  const notation::SignSpec h =
      parsed("hamnondominant hamfinger2 hamextfingeru hampalmr hamchest hammoveo hamlargemod",
             notation::NotationFormat::HamNoSys);
  EXPECT_TRUE(h.one_hand_is_nondominant);
  const auto hp = tip_paths(h);
  EXPECT_GT(hp[0], 0.15f);
  EXPECT_LT(hp[1], 0.02f);

  // Without the mark the dominant hand signs, as before.
  notation::SignSpec d = h;
  d.one_hand_is_nondominant = false;
  const auto dp = tip_paths(d);
  EXPECT_GT(dp[1], 0.15f);
  EXPECT_LT(dp[0], 0.02f);
}

}  // namespace
}  // namespace sw::synthesis

// PoseBuilder (rig.h): set_from_local is incremental — a builder posed frame after frame
// recomputes only the joints whose local rotation changed and their descendants. Whatever the
// order of the frames, and after set(), its pose must be exactly (bit for bit) the pose a fresh
// builder computes from the same frame, on rigs with and without rest rotations.
#include "synthesis/rig.h"

#include <gtest/gtest.h>

#include <cstring>

#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;

// Positions and deltas of every joint, compared bitwise.
::testing::AssertionResult same_pose(const PoseBuilder& a, const PoseBuilder& b, int joints) {
  for (int j = 0; j < joints; ++j) {
    if (std::memcmp(&a.position(j), &b.position(j), sizeof(glm::vec3)) != 0)
      return ::testing::AssertionFailure() << "position of joint " << j << " differs";
    if (std::memcmp(&a.delta(j), &b.delta(j), sizeof(glm::quat)) != 0)
      return ::testing::AssertionFailure() << "delta of joint " << j << " differs";
  }
  return ::testing::AssertionSuccess();
}

class SynthesisPoseBuilder : public ::testing::TestWithParam<int> {};

TEST_P(SynthesisPoseBuilder, PosingFrameAfterFrameGivesTheFreshPose) {
  avatar::Avatar av = GetParam() == 0 ? make_reference_humanoid() : make_rotated_variant(0.9f);
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error)) << error;
  // Both hands moving (a mirrored circle), holds, transitions from and to rest.
  PhraseText t = phrase_from_text(
      "R(H(flat), E(o), P(u), Loc(neutral, centre, none), M(circle axis=o cw)) Sym(lr)\n"
      "R(H(finger2), E(u), P(o), Loc(chin, centre, touch))", {});
  ASSERT_TRUE(t.ok());
  SynthesisResult r = synthesize_phrase(t.items, av, {});
  ASSERT_TRUE(r.ok());
  const Clip& clip = r.clip;
  ASSERT_GT(clip.frame_count, 20);
  PoseBuilder walker(rig);
  int recomputed_less = 0;  // frames where the walker really skipped joints
  auto check = [&](int f) {
    walker.set_from_local(&clip.rotations[static_cast<size_t>(f) * rig.joint_count]);
    PoseBuilder fresh = frame_pose(rig, clip, f);
    int recomputed = 0;
    for (int j = 0; j < rig.joint_count; ++j) recomputed += walker.recomputed(j);
    recomputed_less += recomputed < rig.joint_count;
    return same_pose(walker, fresh, rig.joint_count);
  };
  for (int f = 0; f < clip.frame_count; ++f) ASSERT_TRUE(check(f)) << "forwards, frame " << f;
  for (int f = clip.frame_count - 1; f >= 0; f -= 7) ASSERT_TRUE(check(f)) << "backwards, frame " << f;
  EXPECT_GT(recomputed_less, clip.frame_count / 2);  // the incremental path was exercised
  // set() changes a delta behind set_from_local's back: the next pose is a full one.
  const int hand = rig.arms[kRight].hand;
  walker.set_from_local(&clip.rotations[0]);
  walker.set(hand, axis_angle(rig.up, 0.7f));
  ASSERT_TRUE(check(0));
  for (int j = 0; j < rig.joint_count; ++j) EXPECT_TRUE(walker.recomputed(j)) << j;
}

INSTANTIATE_TEST_SUITE_P(Rigs, SynthesisPoseBuilder, ::testing::Values(0, 1));

}  // namespace
}  // namespace sw::synthesis

// measure_frame_steps (synthesis/clip_steps.h): the arms' per-frame steps that the smoothness
// tests bound and `signweave-cli check` reports. A clip whose only motion is one forearm turned
// at the elbow between two frames: the wrist, |wrist - elbow| from the turn's centre, moves
// 2 |wrist - elbow| sin(angle / 2) in that frame, the elbow not at all; the step's change is that
// whole step twice (moving from still, then still again), first at the frame it moves in.
#include "synthesis/clip_steps.h"

#include <gtest/gtest.h>

#include <cmath>

#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;

// Four frames at rest except frames 2 and 3, where `side`'s forearm is turned by `angle_rad`
// about an axis square to the forearm (in the elbow joint's own frame).
Clip forearm_turned_at_frame_2(const Rig& rig, Side side, float angle_rad) {
  Clip clip;
  clip.frame_count = 4;
  const int J = rig.joint_count;
  clip.joint_names.assign(static_cast<size_t>(J), "");
  for (int f = 0; f < clip.frame_count; ++f)
    clip.rotations.insert(clip.rotations.end(), rig.bind_local_rot.begin(),
                          rig.bind_local_rot.end());
  const int elbow = rig.arms[side].lower, wrist = rig.arms[side].hand;
  const glm::vec3 forearm_local =
      glm::conjugate(rig.bind_rot[elbow]) * (rig.bind_pos[wrist] - rig.bind_pos[elbow]);
  glm::vec3 across = glm::cross(forearm_local, glm::vec3(0.0f, 0.0f, 1.0f));
  if (glm::length(across) < 1e-3f * glm::length(forearm_local))
    across = glm::cross(forearm_local, glm::vec3(1.0f, 0.0f, 0.0f));
  const glm::quat turn = axis_angle(glm::normalize(across), angle_rad);
  for (int f = 2; f < 4; ++f) {
    glm::quat& q = clip.rotations[static_cast<size_t>(f) * J + elbow];
    q = q * turn;
  }
  return clip;
}

TEST(SynthesisClipSteps, AForearmTurnedInOneFrameMovesTheWristByItsChord) {
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(make_reference_humanoid(), &rig, &error)) << error;
  const float angle = 0.6f;
  const Clip clip = forearm_turned_at_frame_2(rig, kRight, angle);
  const int elbow = rig.arms[kRight].lower, wrist = rig.arms[kRight].hand;
  const float chord_m =
      2.0f * glm::length(rig.bind_pos[wrist] - rig.bind_pos[elbow]) * std::sin(angle / 2.0f);

  const FrameSteps arms = measure_frame_steps(rig, clip);
  EXPECT_NEAR(arms.step_m, chord_m, 1e-4f);
  EXPECT_EQ(arms.step_what, "right wrist at frame 2");
  EXPECT_NEAR(arms.change_m, chord_m, 1e-4f);
  EXPECT_EQ(arms.change_what, "right wrist at frame 2");

  // The fingertips are further from the elbow than the wrist: they move further.
  const FrameSteps tips = measure_frame_steps(rig, clip, 0, -1, StepTrack::Fingertips);
  EXPECT_GT(tips.step_m, chord_m + 0.01f);
  EXPECT_NE(tips.step_what.find("right"), std::string::npos) << tips.step_what;

  // Frames 2..3 hold the turned pose: nothing moves within them.
  const FrameSteps held = measure_frame_steps(rig, clip, 2, 3);
  EXPECT_EQ(held.step_m, 0.0f);
  EXPECT_EQ(held.change_m, 0.0f);

  // The other arm is measured the same way.
  const FrameSteps left = measure_frame_steps(rig, forearm_turned_at_frame_2(rig, kLeft, angle));
  EXPECT_EQ(left.step_what, "left wrist at frame 2");
}

}  // namespace
}  // namespace sw::synthesis

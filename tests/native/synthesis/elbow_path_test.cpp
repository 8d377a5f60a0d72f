// continue_elbow_paths (synthesis/elbow_path.h): an elbow that a clip swings half round its circle
// about the shoulder-wrist line between two frames (what a swivel number read in a turned zero
// does) is carried round at a bounded speed instead, the wrist as the clip has it in every frame,
// the wrist joint bent no further than the clip bends it anywhere, and the clip's own elbow
// reached again.
#include "synthesis/elbow_path.h"

#include <gtest/gtest.h>

#include <cmath>

#include "synthesis/clip_steps.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;

constexpr float kPi = 3.14159265358979f;

// 40 frames of the right arm with its elbow bent a right angle; from frame 10 on, the whole arm
// (and the hand with it) turned half round about the shoulder-wrist line: the elbow on the other
// side of its circle, the wrist where it was.
Clip elbow_flipped_at_frame_10(const Rig& rig) {
  Clip clip;
  clip.fps = 30.0f;
  clip.frame_count = 40;
  const int J = rig.joint_count;
  clip.joint_names.assign(static_cast<size_t>(J), "");
  const ArmRig& arm = rig.arms[kRight];
  std::vector<glm::quat> bent(rig.bind_local_rot);
  const glm::vec3 forearm_local =
      glm::conjugate(rig.bind_rot[arm.lower]) * (rig.bind_pos[arm.hand] - rig.bind_pos[arm.lower]);
  const glm::vec3 across = glm::normalize(glm::cross(forearm_local, glm::vec3(0.0f, 0.0f, 1.0f)));
  bent[arm.lower] = bent[arm.lower] * axis_angle(across, 0.5f * kPi);
  PoseBuilder pb(rig);
  pb.set_from_local(bent.data());
  const glm::vec3 line = glm::normalize(pb.position(arm.hand) - pb.position(arm.upper));
  // The upper arm's local rotation for a model-space turn of the unposed shoulder's child.
  const glm::quat flip = axis_angle(line, kPi);
  std::vector<glm::quat> flipped(bent);
  flipped[arm.upper] =
      glm::normalize(rig.bind_local_rot[arm.upper] * glm::conjugate(rig.bind_rot[arm.upper]) *
                     glm::conjugate(pb.delta(rig.parent[arm.upper])) * flip * pb.delta(arm.upper) *
                     rig.bind_rot[arm.upper]);
  for (int f = 0; f < clip.frame_count; ++f) {
    const std::vector<glm::quat>& frame = f < 10 ? bent : flipped;
    clip.rotations.insert(clip.rotations.end(), frame.begin(), frame.end());
  }
  return clip;
}

TEST(SynthesisElbowPath, AnElbowFlippedInOneFrameIsCarriedRoundItsCircle) {
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(make_reference_humanoid(), &rig, &error)) << error;
  const Clip written = elbow_flipped_at_frame_10(rig);
  const FrameSteps before = measure_frame_steps(rig, written);
  ASSERT_GT(before.step_m, 0.3f) << before.step_what;  // the flip: the elbow across its circle

  Clip carried = written;
  EXPECT_GT(
      continue_elbow_paths(rig, nullptr, carried.fps, carried.frame_count, &carried.rotations), 0);
  const FrameSteps after = measure_frame_steps(rig, carried);
  // Within the smoothness tests' bounds (100 mm a frame, a change of step of 56 mm at 30 fps).
  EXPECT_LE(after.step_m, 0.100f) << after.step_what;
  EXPECT_LE(after.change_m, 0.056f) << after.change_what;

  const ArmRig& arm = rig.arms[kRight];
  const int J = rig.joint_count;
  PoseBuilder a(rig), b(rig);
  for (int f = 0; f < written.frame_count; ++f) {
    a.set_from_local(&written.rotations[static_cast<size_t>(f) * J]);
    b.set_from_local(&carried.rotations[static_cast<size_t>(f) * J]);
    SCOPED_TRACE("frame " + std::to_string(f));
    // The wrist where it was written. The clip never bends the wrist joint (the hand turned with
    // the arm), so the swing may not either: the hand turns with the forearm. Keeping the hand's
    // orientation in space instead bent the wrist up to half a turn, far past its limits.
    EXPECT_LT(glm::length(a.position(arm.hand) - b.position(arm.hand)), 1e-4f);
    const glm::quat written_hand = written.rotations[static_cast<size_t>(f) * J + arm.hand];
    const glm::quat carried_hand = carried.rotations[static_cast<size_t>(f) * J + arm.hand];
    EXPECT_GT(std::fabs(glm::dot(written_hand, carried_hand)), 1.0f - 1e-5f);
  }
  // The written elbow again once the swing has arrived.
  a.set_from_local(&written.rotations[static_cast<size_t>(written.frame_count - 1) * J]);
  b.set_from_local(&carried.rotations[static_cast<size_t>(written.frame_count - 1) * J]);
  EXPECT_LT(glm::length(a.position(arm.lower) - b.position(arm.lower)), 1e-4f);
}

TEST(SynthesisElbowPath, AClipWithoutASwingIsLeftAsItIs) {
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(make_reference_humanoid(), &rig, &error)) << error;
  Clip written = elbow_flipped_at_frame_10(rig);
  written.frame_count = 10;  // the frames before the flip
  written.rotations.resize(static_cast<size_t>(10 * rig.joint_count));
  Clip carried = written;
  EXPECT_EQ(
      continue_elbow_paths(rig, nullptr, carried.fps, carried.frame_count, &carried.rotations), 0);
  for (size_t k = 0; k < written.rotations.size(); ++k)
    EXPECT_EQ(written.rotations[k], carried.rotations[k]);
}

}  // namespace
}  // namespace sw::synthesis

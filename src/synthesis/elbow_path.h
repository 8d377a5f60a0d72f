// The elbow's path through a clip: continuous, whatever the swivel numbers that made it.
//
// Every stage that fills the frames between two poses (a sign's key changes, its movements, the
// rest and inter-sign transitions, the frames' swivel fixes) interpolates swivel NUMBERS, and the
// swivel's zero (arm_ik.cpp solve_chain: the way down, turned towards the lateral direction) turns
// half round where the shoulder-wrist line runs along the lateral direction (a wrist across the
// body passing the shoulder joint's coronal plane). There the same number puts the elbow on the
// other side of the arm, and the elbow crossed it in one frame (szkoła's flat hand at the far
// shoulder turning palm up: 471 mm, behind the neck). This pass works on the elbow's position
// instead: where a frame's elbow would swing about the shoulder-wrist line by more than a signer's
// elbow does in a frame, it is held where the previous frame left it and moved round the circle
// towards the frame's own elbow at a bounded speed and acceleration (over several frames), then
// hands back to the frames as solved. The swing is a rotation of the upper arm and forearm about
// the shoulder-wrist line, so the wrist's path is unchanged; the hand keeps its orientation in
// space as far as the wrist joint can take the swing back without bending further than the clip
// bends it anywhere, and turns with the forearm beyond that (a swing is refused if that takes the
// hand deeper into the body).
#pragma once

#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "synthesis/collision.h"
#include "synthesis/rig.h"

namespace sw::synthesis {

// Frame-major local rotations (rig.joint_count per frame, a Clip's layout), sampled at fps.
// With a body model, a swing that starts picks the way round the circle that keeps the arm
// shallower in the trunk. Returns the number of frames whose arm it changed (both arms counted).
// `largest_arm_step_m` (optional): the largest step of a wrist or elbow in one frame over the
// frames as the pass leaves them (clip_steps.h measure_frame_steps' arm measure), read from the
// positions the pass poses anyway (a clip that no elbow swings in is not posed again).
int continue_elbow_paths(const Rig& rig, const BodyModel* body, float fps, int frame_count,
                         std::vector<glm::quat>* rotations, float* largest_arm_step_m = nullptr);

}  // namespace sw::synthesis

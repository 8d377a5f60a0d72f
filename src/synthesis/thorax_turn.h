// Thorax turn: the upper body turning about the body's vertical axis towards the far side, and
// leaning forward, as a signer's does to reach a place low on the other side of the body (the
// right hand beside the left hip); and the head's own turn at the neck, which presents the far
// ear to the hand that reaches it (sign_motion.cpp far_side_turns decides which a sign takes).
// The arm IK, the collision model and the sign's frames all work with the trunk in its bind
// pose; the turn is therefore applied as a change of frame. The spine, chest and upper chest
// share the turn (each a third, cumulative), and everything rigid with the upper chest — the
// shoulders, both arms, the torso capsules (collision.cpp attaches them to the top trunk joint)
// — turns with it rigidly. A sign is solved in that frame ("thorax frame"), where the trunk is
// in its bind pose: only the body anchors on the joints below the upper chest (the stomach on
// the chest, the belly and waist on the spine, below the waist on the hips) and on the head
// are mapped into it, posed on the turned body and then seen from the turned upper chest. So a
// place low on the far side comes forward relative to the shoulder (below the waist by the
// anchor's sideways distance times sin(turn)) while every touch still lands on its anchor on the
// turned body. The clip's local rotations then carry the turn in the spine chain, and the neck
// turns the head three quarters of the way back towards the addressee (and up again from a
// lean), plus the head's own turn. The head and neck capsules are not turned in the sign's own
// frames (the capsule stands nearly on the neck's vertical axis); the clip's check sees them
// turned.
#pragma once

#include <vector>

#include "synthesis/rig.h"

namespace sw::synthesis {

struct ThoraxTurn {
  float angle_rad = 0.0f;          // about rig.up; + turns the chest towards the signer's left
  float lean_rad = 0.0f;           // forward bend about rig.left, after the twist; + leans forward
  float head_rad = 0.0f;           // the head's own turn about rig.up at the neck (+: to the left)
  int top = -1;                    // the upper chest (or the highest trunk joint present)
  std::vector<int> chain;          // spine, chest, upper chest (those present), hips side first
  glm::quat rotation{1, 0, 0, 0};  // the top joint's model-space delta
  glm::vec3 pivot_bind{0.0f}, pivot_posed{0.0f};  // the top joint, bind and turned
  bool active() const { return (angle_rad != 0.0f || lean_rad != 0.0f || head_rad != 0.0f) && top >= 0; }
  // A turned-body point / direction (model space) as seen in the thorax frame.
  glm::vec3 to_thorax_point(const glm::vec3& p) const {
    return glm::conjugate(rotation) * (p - pivot_posed) + pivot_bind;
  }
  glm::vec3 to_thorax_dir(const glm::vec3& d) const { return glm::conjugate(rotation) * d; }
};

// The share of the turn the neck gives back, so the face stays towards the addressee.
constexpr float kHeadTurnBack = 0.75f;

ThoraxTurn make_thorax_turn(const Rig& rig, float angle_rad, float lean_rad = 0.0f, float head_rad = 0.0f);

// The share `s` (0..1) of the turn's rotation: the same axis, s times the angle.
glm::quat thorax_turn_share(const ThoraxTurn& turn, float s);

// Sets the trunk chain's and the neck's deltas of the turned body (pose->finalize() after).
void pose_thorax_turn(const Rig& rig, const ThoraxTurn& turn, PoseBuilder* pose);

// Turns one frame of local rotations (rig.joint_count entries) solved in the thorax frame, whose
// trunk chain and neck are unposed there, into the turned body's.
void apply_thorax_turn(const Rig& rig, const ThoraxTurn& turn, glm::quat* locals);

}  // namespace sw::synthesis

// Rig: what synthesis needs to know about a loaded humanoid, derived from its BIND POSE only —
// joint indices of the canonical humanoid chains, model-space bind positions and rotations, the
// body frame (up / left / forward), per-arm lengths and the hand frame (finger direction, palm
// normal, radial direction) — plus PoseBuilder, which turns model-space "delta" rotations into the
// local joint rotations a Clip stores.
//
// Why deltas: a posed joint's model rotation is D_j * R_j(bind). Working with D (a rotation of the
// bind-pose geometry) lets every solver reason with bind-pose directions measured on the avatar
// itself, so nothing depends on how a particular rig orients its joint axes (any glTF humanoid).
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "avatar/avatar.h"

namespace sw::synthesis {

enum Side { kLeft = 0, kRight = 1 };
inline Side other(Side s) { return s == kLeft ? kRight : kLeft; }

// One finger: three flexing bones (fingers: proximal, intermediate, distal; thumb: metacarpal,
// proximal, distal) and the tip point (-1 if the avatar has no tip joint: extrapolated).
struct FingerChain {
  std::array<int, 3> bones{-1, -1, -1};
  int tip = -1;
};

struct ArmRig {
  int shoulder = -1, upper = -1, lower = -1, hand = -1;
  std::array<FingerChain, 5> fingers;  // thumb, index, middle, ring, little
  float upper_len_m = 0.0f, lower_len_m = 0.0f;
  // Bind-pose hand frame (model space): fingers point along finger_dir, the palm faces
  // palm_normal, radial points from the little finger towards the index (thumb side).
  glm::vec3 finger_dir{0.0f}, palm_normal{0.0f}, radial{0.0f};
  float palm_length_m = 0.0f;   // wrist to the middle knuckle
  float palm_width_m = 0.0f;    // index knuckle to little knuckle
  float finger_radius_m = 0.0f; // half the thickness of a finger (collision and contact offsets)
};

struct Rig {
  int joint_count = 0;
  std::vector<int> parent;
  std::vector<glm::vec3> bind_pos;        // model space
  std::vector<glm::quat> bind_rot;        // model space
  std::vector<glm::quat> bind_local_rot;  // local rest rotations (what an unposed clip holds)
  std::vector<std::string> names;
  glm::vec3 root_translation{0.0f};
  int hips = -1, spine = -1, chest = -1, upper_chest = -1, neck = -1, head = -1;
  std::array<ArmRig, 2> arms;             // kLeft, kRight
  glm::vec3 up{0, 1, 0}, left{1, 0, 0}, forward{0, 0, 1};  // measured body frame
  float shoulder_width_m = 0.0f;
  // The arm solve's swivel zero (arm_ik.h swivel_zero): false, the usual one (its "out" the arm's
  // lateral side, half round where the wrist crosses the shoulder joint's coronal plane); true,
  // the zero of fixed handedness (no half turn there), the per-sign alternative that
  // synthesize_sign_motion tries where the usual zero's clip leaps (docs/SYNTHESIS.md
  // swivel-choice). Not a property of the body: set on a copy of the context for that solve.
  bool fixed_handed_swivel_zero = false;
  // Where the shoulder girdle protracts for a wrist across the body (arm_ik.cpp solve_chain,
  // kProtractionZones): 0, the usual zone (wrists up to 27% of the reach in front of the shoulder,
  // not above it); 1 and 2, wider ones, the per-sign alternatives run_phrase tries where a sign's
  // own frames put an arm in the body (docs/SYNTHESIS.md arm-side). Not a property of the body:
  // set on a copy of the context for that solve.
  int protraction_zone = 0;
  // Bind-pose terms the pose builders read for every joint they pose (PoseBuilder::
  // set_from_local and finalize, SubsetPose), worked out once per rig instead of per joint per
  // call (docs/SYNTHESIS.md speed-exact): bind_offset[j] = bind_pos[j] - bind_pos[parent] with w 0
  // (the lanes' load3 of that difference; the root's is 0) and bind_rot_conj[j] =
  // conjugate(bind_rot[j]) in the lanes' arithmetic, so every pose keeps its bits. build_rig
  // fills them; code that edits parent, bind_pos or bind_rot afterwards (tests nudging a
  // fingertip) must call refresh_bind_cache(), or poses read the old geometry.
  std::vector<glm::vec4> bind_offset;
  std::vector<glm::quat> bind_rot_conj;
  void refresh_bind_cache();

  // Tip position in the bind pose (the tip joint, or the distal bone extended).
  glm::vec3 bind_tip(Side side, int finger) const;
};

// Builds the rig; returns false with `error` set when a required joint is missing.
bool build_rig(const avatar::Avatar& avatar, Rig* rig, std::string* error);

// Index of the joint with this canonical VRM humanoid name, or -1.
int find_canonical_joint(const avatar::Avatar& avatar, const std::string& canonical_name);

// A pose under construction: model-space delta rotations per joint. Unset joints follow their
// parent (a rigid child). finalize() computes positions and local rotations.
//
// set_from_local is incremental: a builder posed from one frame and then from the next (the
// collision check and the path measurements walk clips frame by frame) recomputes only the joints
// whose local rotation differs, bit for bit, from the previous frame's, and their descendants.
// The rest keep their values, which are exactly what recomputing them would give (same inputs,
// same arithmetic), so the pose is identical to a full pass. set() and finalize() end the
// incremental run (the next set_from_local is a full pass).
struct PoseBuilder {
  explicit PoseBuilder(const Rig& rig);
  void set(int joint, const glm::quat& delta);
  void finalize();
  // Poses from a frame of local rotations (a Clip frame): deltas and positions by FK.
  void set_from_local(const glm::quat* local);
  const glm::quat& delta(int joint) const { return delta_[joint]; }
  const glm::vec3& position(int joint) const { return pos_[joint]; }
  // Whether the last set_from_local recomputed `joint` (false: its pose is the previous frame's).
  bool recomputed(int joint) const { return !last_local_valid_ || recomputed_[joint] != 0; }
  // Posed model-space point rigidly attached to `joint`, given in the bind pose. Inline: the
  // collision checks call it a few thousand times per sign.
  glm::vec3 attached(int joint, const glm::vec3& bind_point) const {
    return pos_[joint] + delta_[joint] * (bind_point - rig->bind_pos[joint]);
  }
  glm::vec3 tip(Side side, int finger) const;
  void local_rotations(glm::quat* out) const;  // rig.joint_count entries
  glm::quat local_rotation(int joint) const;  // one joint's entry of local_rotations

  const Rig* rig;
 private:
  std::vector<glm::quat> delta_;
  std::vector<char> is_set_;
  std::vector<glm::vec3> pos_;
  std::vector<glm::quat> scratch_;  // model rotations for set_from_local (no per-call allocation)
  // The previous set_from_local input and, per joint, whether that call recomputed it.
  std::vector<glm::quat> last_local_;
  std::vector<char> recomputed_;
  bool last_local_valid_ = false;
};

// Small vector helpers shared by the solvers. Inline: the arm IK calls them a few dozen times per
// chain solve and thousands of chain solves per sign; out of line, the calls were a tenth of the
// synthesis time.
inline glm::vec3 reject(const glm::vec3& v, const glm::vec3& unit_axis) {
  return v - glm::dot(v, unit_axis) * unit_axis;
}
inline glm::vec3 safe_normalize(const glm::vec3& v, const glm::vec3& fallback) {
  float len = glm::length(v);
  return len > 1e-6f ? v / len : fallback;
}
glm::quat axis_angle(const glm::vec3& unit_axis, float angle_rad);
// Rotation taking orthonormal frame (a0, b0, a0 x b0) onto (a1, b1, a1 x b1); b's are
// orthogonalised against a's first.
glm::quat frame_to_frame(const glm::vec3& a0, const glm::vec3& b0, const glm::vec3& a1,
                         const glm::vec3& b1);
// The orthonormal frame (a, b, a x b) of frame_to_frame, and frame_to_frame from such a frame
// worked out once (a bind-pose frame the arm IK maps onto every candidate pose).
glm::mat3 orthonormal_frame(const glm::vec3& a, const glm::vec3& b);
glm::quat frame_to_frame(const glm::mat3& frame0, const glm::vec3& a1, const glm::vec3& b1);
// Shortest-path slerp (never the long way round, never a flip at +-180 degrees).
glm::quat slerp_shortest(const glm::quat& a, const glm::quat& b, float t);
// Angle of a rotation, radians in [0, pi].
float rotation_angle(const glm::quat& q);

}  // namespace sw::synthesis

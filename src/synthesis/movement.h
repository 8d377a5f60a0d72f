// Movement: HamNoSys movements (seed 004 "trajectory and character of movement") as smooth hand
// paths and wrist/finger motions, parameterised by s in [0, 1], timed by the minimum-jerk profile
// (Flash & Hogan 1985: s = 10t^3 - 15t^4 + 6t^5, zero velocity and acceleration at both ends),
// sized relative to the avatar (a fraction of its forearm length).
#pragma once

#include "notation/sign_spec.h"
#include "synthesis/handshape.h"
#include "synthesis/rig.h"

namespace sw::synthesis {

// Minimum-jerk time law and its derivative ds/dt for t in [0, 1].
float minimum_jerk(float t);
float minimum_jerk_velocity(float t);

// Path size (m) on this avatar: small 0.25, normal 0.45, large 0.75 forearm lengths.
float movement_size_m(const Rig& rig, notation::Size size);

// Duration (s) of one movement at speed 1, by kind, size and manner.
float movement_duration_s(const notation::Movement& m);
// Extra hold after a movement (halt: a sudden stop that is held).
float movement_hold_s(const notation::Movement& m);

// Mirror flags for the hand that carries the movement: x (left/right), y (up/down), z (in/out).
struct MirrorAxes {
  bool x = false, y = false, z = false;
};
glm::vec3 mirrored_direction(const Rig& rig, notation::Direction d, const MirrorAxes& m);

// Displacement of the hand from where the movement started, at path parameter s (model space).
// `reference` is a direction perpendicular-ish to the path used when the movement leaves the
// plane undefined (the hand's palm normal).
// `outward` (unit, or zero): for a hand touching the body, the place's outward normal. A circle
// whose plane holds that normal then starts at its point nearest the body (its centre off the
// skin along the normal), so it brushes the body and goes round in front of it; started at its
// top (the centre below, as without it) half the circle ran into the body (HAPPY's circle on the
// chest 3.3 cm deep, the reference humanoid's forearm 8.9 mm in the torso). The sense of
// rotation is kept.
glm::vec3 movement_offset(const Rig& rig, const notation::Movement& m, const MirrorAxes& mirror,
                          float s, const glm::vec3& reference, const glm::vec3& outward = glm::vec3(0.0f));

// Wrist motions (nod, swing, twist, circle): rotation in the hand's bind frame, right-multiplied
// onto the hand delta. Identity for other kinds. `s` in [0, 1]: two cycles. sign_motion gives
// every wrist motion the step's time (a constant rate; the amplitude is eased in and out over the
// first and last quarter) and passes the rotation to the arm IK as ArmTarget::wrist_motion.
glm::quat wrist_motion(const Rig& rig, Side side, const notation::Movement& m, float s);

// Finger play: the fingers flex in a wave, index to little.
HandAngles finger_play(const HandAngles& base, float s);

// Whether the path returns to its start at s = 1 (circles, wrist and finger motions).
bool movement_is_cyclic(const notation::Movement& m);

}  // namespace sw::synthesis

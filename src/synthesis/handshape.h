// Handshape: seed 004 eq. (4) — the hand as a superposition of per-finger states F_i^k(t) — made
// into anatomical joint angles with joint limits, posed on the avatar's finger chains by forward
// kinematics. Thumb-contact states (F_1^1, thumb on middle/ring/little) are solved by a small IK
// that puts the thumb tip onto the target finger's pad.
//
// Angles are measured from the avatar's own bind pose: flexion 0 = the bone in the palm plane,
// abduction 0 = parallel to the hand's finger direction (rig.h), so a flat hand is flat and closed
// on any humanoid, whatever its bind pose does with the fingers.
#pragma once

#include <array>

#include "notation/sign_spec.h"
#include "synthesis/rig.h"

namespace sw::synthesis {

struct FingerAngles {        // radians
  float mcp_flex = 0, pip_flex = 0, dip_flex = 0;
  float abduction = 0;       // + towards the thumb side (radial)
};
struct ThumbAngles {         // radians
  float cmc_flex = 0;        // in the palm plane, + across the palm towards the little finger
  float cmc_abd = 0;         // palmar abduction, + away from the palm plane towards the palm side
  float opposition = 0;      // rotation about the thumb's own axis, + turns the pad to the fingers
  float mcp_flex = 0, ip_flex = 0;
};
struct HandAngles {
  ThumbAngles thumb;
  std::array<FingerAngles, 4> fingers;  // index, middle, ring, little
};

// Anatomical ranges (degrees in the comments): a joint never leaves them.
struct FingerLimits { float lo, hi; };
struct HandLimits {
  FingerLimits mcp{-0.35f, 1.66f};   // -20 (hyperextension) .. 95
  FingerLimits pip{0.0f, 1.92f};     // 0 .. 110
  FingerLimits dip{0.0f, 1.48f};     // 0 .. 85
  FingerLimits abd{-0.44f, 0.44f};   // -25 .. 25
  FingerLimits cmc_flex{-0.70f, 1.05f};  // -40 (thumb out, radial) .. 60 (across the palm)
  FingerLimits cmc_abd{-0.17f, 1.31f};   // -10 .. 75
  FingerLimits opposition{-0.17f, 1.40f};// -10 .. 80
  FingerLimits thumb_mcp{-0.17f, 1.05f}; // -10 .. 60
  FingerLimits thumb_ip{-0.26f, 1.48f};  // -15 .. 85
};
const HandLimits& hand_limits();
// True if every angle is within hand_limits() (plus `tolerance_rad`).
bool within_limits(const HandAngles& a, float tolerance_rad = 1e-4f);

// Target angles for a handshape (thumb contact NOT yet solved). Clamped to the limits.
HandAngles handshape_angles(const notation::HandShape& shape);
// Which finger (1..4) the thumb must touch for this shape, or -1.
int thumb_contact_finger(const notation::HandShape& shape);

// Hand-bind relative posing: deltas of the finger joints for a hand whose own delta is `hand`.
void pose_fingers(const Rig& rig, Side side, const HandAngles& angles, const glm::quat& hand,
                  PoseBuilder* pose);

// The full solve: preset angles, then the thumb-contact IK when the shape asks for it (the target
// finger may curl a little further to meet the thumb, as in the seed's F_1^1 which bends Index1-3).
HandAngles solve_handshape(const Rig& rig, Side side, const notation::HandShape& shape);

// Linear blend of two angle sets (replace movements, finger play).
HandAngles mix(const HandAngles& a, const HandAngles& b, float t);

// Palm centre in the bind pose (between the wrist and the knuckles, on the palm surface side).
glm::vec3 bind_palm_centre(const Rig& rig, Side side);

}  // namespace sw::synthesis

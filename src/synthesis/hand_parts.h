// Hand parts: the named places of a hand and arm (palm, back, thumb/little side, fingertip, pad,
// nail, base, middle joint, side of a finger, wrist, forearm, elbow, upper arm) as posed points
// with an outward normal. Used twice: for the part of THIS hand that makes contact, and for the
// place on the OTHER hand/arm that is the location (HamNoSys location on the hand, seed 004
// two-handed signs). Avatar anchors `hand/...` / `arm/...` take precedence when the avatar has them.
#pragma once

#include <string>

#include "avatar/avatar.h"
#include "notation/sign_spec.h"
#include "synthesis/rig.h"

namespace sw::synthesis {

struct PartPoint {
  glm::vec3 point{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
};

// Posed point of `place` (finger 0..4 for per-finger places; -1 = index) on `side`'s hand/arm.
PartPoint hand_part(const PoseBuilder& pose, Side side, notation::HandPlace place, int finger);

// The anchor name the brief gives this place (`hand/right/tip/index`, `arm/left/elbow`, ...).
std::string hand_part_anchor_name(Side side, notation::HandPlace place, int finger);

// Posed position of a named avatar anchor; false if the avatar has none by that name.
bool anchor_point(const avatar::Avatar& avatar, const PoseBuilder& pose, const std::string& name,
                  PartPoint* out);

}  // namespace sw::synthesis

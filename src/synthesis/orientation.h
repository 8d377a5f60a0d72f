// Orientation: seed 004's palm positions D1-D5 and HamNoSys's extended-finger direction (26) +
// palm orientation (projected onto the plane perpendicular to the finger direction) -> a target
// hand frame -> the hand's model-space delta rotation (rig.h), measured on the avatar's own bind
// hand frame so any humanoid gets the same visible orientation.
#pragma once

#include "notation/sign_spec.h"
#include "synthesis/rig.h"

namespace sw::synthesis {

struct HandFrame {
  glm::vec3 finger{0, 1, 0};  // unit: where straight fingers point
  glm::vec3 palm{0, 0, 1};    // unit, perpendicular to finger: where the palm faces
};

// A signer-space direction (x = signer's left, y = up, z = away from the body) in model space,
// through the rig's measured body frame. mirror_x flips left and right (left-handed signer,
// mirror symmetry). Zero directions give {0,0,0}.
glm::vec3 signer_direction(const Rig& rig, notation::Direction d, bool mirror_x);

// The frame an Orientation asks for. `side` is the hand that carries it (D5 "to the side" faces
// the body's midline), `mirror_x` as above.
HandFrame orientation_frame(const Rig& rig, const notation::Orientation& o, Side side, bool mirror_x);

// Delta rotation taking the bind hand frame of `side` onto `frame`.
glm::quat hand_delta_for(const Rig& rig, Side side, const HandFrame& frame);

// Frame of a posed hand (delta applied to the bind hand frame).
HandFrame posed_hand_frame(const Rig& rig, Side side, const glm::quat& hand_delta);

}  // namespace sw::synthesis

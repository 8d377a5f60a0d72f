// Orientation: directions -> target hand frame -> hand delta rotation.
#include "synthesis/orientation.h"

#include <cmath>

namespace sw::synthesis {

glm::vec3 signer_direction(const Rig& rig, notation::Direction d, bool mirror_x) {
  float x = mirror_x ? -d.x : d.x;
  glm::vec3 v = x * rig.left + static_cast<float>(d.y) * rig.up + static_cast<float>(d.z) * rig.forward;
  float len = glm::length(v);
  return len > 1e-6f ? v / len : glm::vec3(0.0f);
}

HandFrame orientation_frame(const Rig& rig, const notation::Orientation& o, Side side, bool mirror_x) {
  using notation::Direction;
  using notation::SeedPalm;
  Direction finger = o.extended_finger, palm = o.palm;
  // Seed 004 (5): D1 up, D2 standard (towards the addressee), D3 down, D4 towards oneself,
  // D5 to the side (towards the body's midline). With the palm up or down the fingers point
  // away from the body; otherwise up.
  // The medial direction for the hand that carries it (+X, the signer's left, for the right hand);
  // mirror_x is applied by signer_direction below, so undo it here to stay medial.
  std::int8_t medial = static_cast<std::int8_t>((side == kRight) != mirror_x ? 1 : -1);
  switch (o.seed_palm) {
    case SeedPalm::D1: palm = {0, 1, 0}; finger = {0, 0, 1}; break;
    case SeedPalm::D2: palm = {0, 0, 1}; finger = {0, 1, 0}; break;
    case SeedPalm::D3: palm = {0, -1, 0}; finger = {0, 0, 1}; break;
    case SeedPalm::D4: palm = {0, 0, -1}; finger = {0, 1, 0}; break;
    case SeedPalm::D5: palm = {medial, 0, 0}; finger = {0, 1, 0}; break;
    case SeedPalm::None: break;
  }
  HandFrame f;
  f.finger = signer_direction(rig, finger, mirror_x);
  if (glm::length(f.finger) < 0.5f) f.finger = glm::normalize(rig.up + rig.forward);
  glm::vec3 p = signer_direction(rig, palm, mirror_x);
  // HamNoSys palm orientation is relative to the finger direction: keep the part perpendicular.
  glm::vec3 perp = reject(p, f.finger);
  if (glm::length(perp) < 1e-3f) {
    // Palm along the fingers is impossible: face the palm towards the body's midline instead,
    // or down if the fingers point sideways.
    glm::vec3 med = signer_direction(rig, {medial, 0, 0}, mirror_x);
    perp = reject(med, f.finger);
    if (glm::length(perp) < 1e-3f) perp = reject(-rig.up, f.finger);
  }
  f.palm = glm::normalize(perp);
  return f;
}

glm::quat hand_delta_for(const Rig& rig, Side side, const HandFrame& frame) {
  const ArmRig& a = rig.arms[side];
  return frame_to_frame(a.finger_dir, a.palm_normal, frame.finger, frame.palm);
}

HandFrame posed_hand_frame(const Rig& rig, Side side, const glm::quat& d) {
  const ArmRig& a = rig.arms[side];
  return HandFrame{d * a.finger_dir, d * a.palm_normal};
}

}  // namespace sw::synthesis

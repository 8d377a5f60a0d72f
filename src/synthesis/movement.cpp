// Movement: paths, wrist and finger motions, durations (see movement.h).
#include "synthesis/movement.h"

#include <cmath>

namespace sw::synthesis {

using notation::Manner;
using notation::MovementKind;
using notation::Size;

namespace {
constexpr float kTwoPi = 6.28318530718f;

float size_factor(Size s) { return s == Size::Small ? 0.6f : s == Size::Large ? 1.4f : 1.0f; }

// A unit direction perpendicular to `d`, preferring up, then forward.
glm::vec3 perpendicular(const Rig& rig, const glm::vec3& d) {
  glm::vec3 p = reject(rig.up, d);
  if (glm::length(p) < 0.2f) p = reject(rig.forward, d);
  return glm::normalize(p);
}

int mirror_parity(const MirrorAxes& m) { return (m.x ? 1 : 0) + (m.y ? 1 : 0) + (m.z ? 1 : 0); }

// The wrist motions' amplitude envelope at s: 0 at both ends, 1 from the first quarter to the
// last, a smoothstep between (zero slope at both ends).
float wrist_motion_envelope(float s) {
  const float edge = std::min(s, 1.0f - s) / 0.25f;
  return edge >= 1.0f ? 1.0f : edge <= 0.0f ? 0.0f : edge * edge * (3.0f - 2.0f * edge);
}

float triangle_wave(float x) {  // period 1, range [-1, 1], 0 at x = 0
  float f = x - std::floor(x);
  return f < 0.25f ? 4.0f * f : f < 0.75f ? 2.0f - 4.0f * f : 4.0f * f - 4.0f;
}
}  // namespace

float minimum_jerk(float t) {
  t = std::min(1.0f, std::max(0.0f, t));
  return t * t * t * (10.0f + t * (-15.0f + 6.0f * t));
}

float minimum_jerk_velocity(float t) {
  t = std::min(1.0f, std::max(0.0f, t));
  return 30.0f * t * t * (1.0f - t) * (1.0f - t);
}

float movement_size_m(const Rig& rig, Size size) {
  float forearm = 0.5f * (rig.arms[0].lower_len_m + rig.arms[1].lower_len_m);
  return forearm * (size == Size::Small ? 0.25f : size == Size::Large ? 0.75f : 0.45f);
}

float movement_duration_s(const notation::Movement& m) {
  float base = 0.45f;
  switch (m.kind) {
    case MovementKind::Straight: case MovementKind::Arc: case MovementKind::Target: base = 0.45f; break;
    case MovementKind::Circle: case MovementKind::Ellipse: base = 0.8f; break;
    case MovementKind::Spiral: base = 1.1f; break;
    case MovementKind::Wavy: case MovementKind::Zigzag: base = 0.8f; break;
    case MovementKind::FingerPlay: base = 0.9f; break;
    case MovementKind::WristNod: case MovementKind::WristSwing: case MovementKind::WristTwist:
    case MovementKind::WristCircle: base = 0.7f; break;
    case MovementKind::Replace: base = 0.35f; break;
  }
  float size = m.size == Size::Small ? 0.8f : m.size == Size::Large ? 1.25f : 1.0f;
  float manner = 1.0f;
  switch (m.manner) {
    case Manner::Fast: manner = 0.6f; break;
    case Manner::Slow: manner = 1.7f; break;
    case Manner::Tense: manner = 1.35f; break;
    case Manner::Halt: manner = 0.75f; break;
    case Manner::Rest: manner = 1.2f; break;
    case Manner::Normal: break;
  }
  return base * size * manner;
}

float movement_hold_s(const notation::Movement& m) {
  return m.manner == Manner::Halt ? 0.2f : m.manner == Manner::Tense ? 0.1f : 0.0f;
}

glm::vec3 mirrored_direction(const Rig& rig, notation::Direction d, const MirrorAxes& m) {
  float x = m.x ? -d.x : d.x, y = m.y ? -d.y : d.y, z = m.z ? -d.z : d.z;
  glm::vec3 v = x * rig.left + y * rig.up + z * rig.forward;
  float len = glm::length(v);
  return len > 1e-6f ? v / len : glm::vec3(0.0f);
}

bool movement_is_cyclic(const notation::Movement& m) {
  switch (m.kind) {
    case MovementKind::Circle: case MovementKind::Ellipse: case MovementKind::FingerPlay:
    case MovementKind::WristNod: case MovementKind::WristSwing: case MovementKind::WristTwist:
    case MovementKind::WristCircle: return true;
    default: return false;
  }
}

glm::vec3 movement_offset(const Rig& rig, const notation::Movement& m, const MirrorAxes& mirror,
                          float s, const glm::vec3& reference, const glm::vec3& outward) {
  const float R = movement_size_m(rig, m.size);
  glm::vec3 dir = mirrored_direction(rig, m.direction, mirror);
  if (glm::length(dir) < 0.5f) dir = rig.forward;
  switch (m.kind) {
    case MovementKind::Straight: return s * R * dir;
    case MovementKind::Arc: {
      glm::vec3 bulge = mirrored_direction(rig, m.arc_bulge, mirror);
      bulge = glm::length(reject(bulge, dir)) > 0.2f ? glm::normalize(reject(bulge, dir)) : perpendicular(rig, dir);
      return s * R * dir + 4.0f * s * (1.0f - s) * 0.3f * R * bulge;
    }
    case MovementKind::Wavy: return s * R * dir + std::sin(kTwoPi * 2.0f * s) * 0.12f * R * perpendicular(rig, dir);
    case MovementKind::Zigzag: return s * R * dir + triangle_wave(3.0f * s) * 0.12f * R * perpendicular(rig, dir);
    case MovementKind::Circle: case MovementKind::Ellipse: case MovementKind::Spiral: {
      glm::vec3 axis = mirrored_direction(rig, m.circle_axis, mirror);
      if (glm::length(axis) < 0.5f) axis = rig.forward;
      glm::vec3 e1 = perpendicular(rig, axis);
      if (m.kind == MovementKind::Ellipse) {  // the long axis as written, in the circle's plane
        glm::vec3 longer = reject(mirrored_direction(rig, m.ellipse_axis, mirror), axis);
        if (glm::length(longer) > 0.2f) e1 = glm::normalize(longer);
      }
      // A circle on the body: the start (at +e1, the centre at -e1) nearest the body. Only when
      // the normal lies well in the circle's plane (a circle facing the body keeps its start).
      if (m.kind == MovementKind::Circle && glm::length(reject(outward, axis)) > 0.5f)
        e1 = -glm::normalize(reject(outward, axis));
      glm::vec3 e2 = glm::cross(axis, e1);
      // Looking along the axis, a positive (right-hand) rotation appears clockwise; a mirror image
      // turns the other way.
      float sense = m.clockwise ? 1.0f : -1.0f;
      if (mirror_parity(mirror) % 2 == 1) sense = -sense;
      float r = 0.5f * R;
      float turns = m.kind == MovementKind::Spiral ? 2.0f : 1.0f;
      float phi = sense * kTwoPi * turns * s;
      float r_s = m.kind == MovementKind::Spiral ? r * (0.4f + 0.6f * s) : r;
      float r_0 = m.kind == MovementKind::Spiral ? 0.4f * r : r;
      float squash = m.kind == MovementKind::Ellipse ? 0.5f : 1.0f;
      return r_s * std::cos(phi) * e1 + squash * r_s * std::sin(phi) * e2 - r_0 * e1;
    }
    default: (void)reference; return glm::vec3(0.0f);
  }
}

glm::quat wrist_motion(const Rig& rig, Side side, const notation::Movement& m, float s) {
  const ArmRig& a = rig.arms[side];
  // Two cycles of s. Every wrist motion is given the step's time (sign_motion.cpp): warped by the
  // minimum-jerk law, the middle cycle ran 1.9 times faster than the first and last, and at 30
  // fps WALK's flapping fingertips moved 30, 68, 30 mm in three frames. The amplitude eases in
  // over the first quarter and out over the last (a smoothstep, zero slope at both ends), so the
  // wrist starts and stops at rest: velocity continuous where the movement meets a hold. Twists
  // too, since the wrist's limits are refitted during wrist motions (arm_ik.h
  // ArmTarget::wrist_limit_fit): on the minimum-jerk parameter they had been kept because their
  // fast middle let the flip rule hide the clamped wrist's jumps.
  float k = size_factor(m.size) * wrist_motion_envelope(s);
  glm::vec3 flex_axis = glm::normalize(glm::cross(a.finger_dir, a.palm_normal));
  float w = std::sin(kTwoPi * 2.0f * s);
  switch (m.kind) {
    case MovementKind::WristNod: return axis_angle(flex_axis, 0.35f * k * w);
    case MovementKind::WristSwing: return axis_angle(a.palm_normal, 0.25f * k * w);
    case MovementKind::WristTwist: return axis_angle(a.finger_dir, 0.6f * k * w);
    case MovementKind::WristCircle: {
      float c = std::cos(kTwoPi * 2.0f * s) - 1.0f;
      return axis_angle(flex_axis, 0.25f * k * w) * axis_angle(a.palm_normal, 0.2f * k * c);
    }
    default: return glm::quat(1, 0, 0, 0);
  }
}

HandAngles finger_play(const HandAngles& base, float s) {
  HandAngles out = base;
  for (int f = 0; f < 4; ++f) {
    float phase = kTwoPi * (2.0f * s) - 0.9f * static_cast<float>(f);
    float wave = 0.5f * (1.0f - std::cos(phase));
    float envelope = std::sin(3.14159265f * s);  // starts and ends on the base shape
    out.fingers[f].mcp_flex = std::min(1.6f, base.fingers[f].mcp_flex + 0.6f * wave * envelope);
    out.fingers[f].pip_flex = std::min(1.9f, base.fingers[f].pip_flex + 0.4f * wave * envelope);
  }
  return out;
}

}  // namespace sw::synthesis

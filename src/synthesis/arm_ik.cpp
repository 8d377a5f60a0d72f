// Arm IK: clavicle + analytic two-bone + swivel + wrist/forearm split (see arm_ik.h).
#include "synthesis/arm_ik.h"

#include <algorithm>
#include <cmath>

namespace sw::synthesis {
namespace {

constexpr float kPi = 3.14159265358979f;
float clampf(float v, float lo, float hi) { return std::min(hi, std::max(lo, v)); }

struct Solved {
  ArmPose pose;
  glm::vec3 wrist;
};

// One solve at a fixed swivel angle.
Solved solve_at(const Rig& rig, Side side, const ArmTarget& t, float swivel) {
  const ArmRig& a = rig.arms[side];
  const ArmLimits& lim = arm_limits();
  const float l1 = a.upper_len_m, l2 = a.lower_len_m;
  const glm::vec3 s0 = rig.bind_pos[a.upper];
  const glm::vec3 out_dir = side == kLeft ? rig.left : -rig.left;  // lateral, away from the body
  ArmPose p;
  p.swivel_rad = swivel;
  glm::quat hand = t.hand_delta;
  glm::vec3 wrist_target = t.point - hand * t.contact_offset;
  glm::vec3 shoulder_pos = s0, elbow(0.0f), wrist(0.0f);
  for (int iter = 0; iter < 3; ++iter) {
    // Clavicle: shrug for targets above the shoulder, protract for far ones (comfort first: the
    // shoulder moves only when the arm alone would be near its reach).
    if (a.shoulder >= 0) {
      glm::vec3 pivot = rig.bind_pos[a.shoulder];
      glm::vec3 v = wrist_target - s0;
      float reach = glm::length(v) / (l1 + l2);
      float height = glm::dot(v, rig.up) / (l1 + l2);
      float fwd = std::max(0.0f, glm::dot(safe_normalize(v, rig.forward), rig.forward));
      p.clavicle_elevation_rad = clampf(0.6f * (height + 0.15f), 0.0f, lim.clavicle_elevation);
      p.clavicle_protraction_rad = clampf(1.2f * (reach - 0.75f) * fwd, 0.0f, lim.clavicle_protraction);
      glm::vec3 c = safe_normalize(s0 - pivot, out_dir);
      glm::vec3 elev_axis = safe_normalize(glm::cross(c, rig.up), rig.forward);
      glm::vec3 prot_axis = safe_normalize(glm::cross(c, rig.forward), rig.up);
      p.shoulder = axis_angle(prot_axis, p.clavicle_protraction_rad) *
                   axis_angle(elev_axis, p.clavicle_elevation_rad);
      shoulder_pos = pivot + p.shoulder * (s0 - pivot);
    }
    // Two-bone: distance clamped between full extension and the elbow's flexion limit.
    glm::vec3 to = wrist_target - shoulder_pos;
    float d_max = 0.9995f * (l1 + l2);
    float d_min = std::sqrt(std::max(1e-8f, l1 * l1 + l2 * l2 - 2.0f * l1 * l2 * std::cos(kPi - lim.elbow_flex_max)));
    float d = clampf(glm::length(to), d_min, d_max);
    glm::vec3 axis = safe_normalize(to, out_dir);
    float cos_a = clampf((l1 * l1 + d * d - l2 * l2) / (2.0f * l1 * d), -1.0f, 1.0f);
    float sin_a = std::sqrt(std::max(0.0f, 1.0f - cos_a * cos_a));
    glm::vec3 down = reject(-rig.up, axis);
    if (glm::length(down) < 1e-3f) down = reject(-rig.forward, axis);
    down = glm::normalize(down);
    glm::vec3 outp = reject(out_dir, axis);
    outp = safe_normalize(reject(outp, down), glm::cross(axis, down));
    glm::vec3 sw = std::cos(swivel) * down + std::sin(swivel) * outp;
    elbow = shoulder_pos + l1 * (cos_a * axis + sin_a * sw);
    wrist = shoulder_pos + d * axis;
    p.elbow_flex_rad = kPi - std::acos(clampf((l1 * l1 + l2 * l2 - d * d) / (2.0f * l1 * l2), -1.0f, 1.0f));

    // Upper arm: bind (bone dir, elbow-bend dir = body forward) -> posed (bone dir, towards the
    // side the forearm folds to). A T/A-posed elbow flexes towards the body's front.
    glm::vec3 u1 = safe_normalize(rig.bind_pos[a.lower] - s0, out_dir);
    glm::vec3 b1 = safe_normalize(reject(rig.forward, u1), rig.forward);
    glm::vec3 u1p = safe_normalize(elbow - shoulder_pos, axis);
    glm::vec3 b1p = safe_normalize(reject(-sw, u1p), -sw);
    p.upper = frame_to_frame(u1, b1, u1p, b1p);
    glm::vec3 hinge_bind = glm::normalize(glm::cross(u1, b1));
    glm::vec3 hinge = p.upper * hinge_bind;
    glm::vec3 u2 = safe_normalize(rig.bind_pos[a.hand] - rig.bind_pos[a.lower], u1);
    glm::vec3 u2p = safe_normalize(wrist - elbow, u1p);
    glm::quat lower0 = frame_to_frame(u2, glm::cross(hinge_bind, u2), u2p, glm::cross(hinge, u2p));

    // Wrist: R_rel = lower^-1 * hand, decomposed in the bind frame (e1 forearm axis, e2 palm
    // normal, e3 = e1 x e2) as twist(e1) * deviation(e2) * flexion(e3); each clamped.
    glm::vec3 e1 = u2;
    glm::vec3 e2 = safe_normalize(reject(a.palm_normal, e1), a.palm_normal);
    glm::vec3 e3 = glm::cross(e1, e2);
    glm::mat3 basis(e1, e2, e3);
    glm::quat rel = glm::conjugate(lower0) * t.hand_delta;
    glm::mat3 m = glm::transpose(basis) * glm::mat3_cast(rel) * basis;
    auto R = [&](int r, int c) { return m[c][r]; };
    float twist = std::atan2(-R(1, 2), R(2, 2));
    float dev = std::asin(clampf(R(0, 2), -1.0f, 1.0f));
    float flex = std::atan2(-R(0, 1), R(0, 0));
    // Positive dev moves the fingers towards -e3: ulnar for a right hand, radial for a left one.
    float radial_sign = glm::dot(e3, a.radial) > 0.0f ? -1.0f : 1.0f;  // dev * radial_sign = radial
    twist = clampf(twist, lim.twist_lo, lim.twist_hi);
    float radial = clampf(dev * radial_sign, -lim.ulnar_dev, lim.radial_dev);
    dev = radial * radial_sign;
    flex = clampf(flex, -lim.wrist_ext, lim.wrist_flex);
    glm::quat q_twist = axis_angle(e1, twist), q_dev = axis_angle(e2, dev), q_flex = axis_angle(e3, flex);
    p.lower = lower0 * q_twist;
    hand = p.lower * q_dev * q_flex;
    p.twist_rad = twist;
    p.wrist_dev_rad = radial;
    p.wrist_flex_rad = flex;
    wrist_target = t.point - hand * t.contact_offset;
  }
  p.hand = hand;
  glm::vec3 achieved = wrist + hand * t.contact_offset;
  p.reach_error_m = glm::length(achieved - t.point);
  p.orientation_error_rad = rotation_angle(glm::conjugate(t.hand_delta) * hand);
  return Solved{p, wrist};
}

}  // namespace

const ArmLimits& arm_limits() {
  static const ArmLimits limits;
  return limits;
}

ArmPose solve_arm(const Rig& rig, Side side, const ArmTarget& t) {
  if (!t.auto_swivel) return solve_at(rig, side, t, t.swivel_rad).pose;
  // Comfort heuristic: the elbow hangs down and a little out (25 deg), rising outwards for
  // targets above the shoulder; among candidates, the one that best realises the requested
  // orientation (wrist within limits) and reaches, close to that preference, wins.
  const ArmRig& a = rig.arms[side];
  glm::vec3 v = t.point - rig.bind_pos[a.upper];
  float height = glm::dot(v, rig.up) / (a.upper_len_m + a.lower_len_m);
  float preferred = 0.44f + 0.6f * clampf(1.5f * (height + 0.2f), 0.0f, 1.0f);
  ArmPose best;
  float best_cost = 1e30f;
  for (int i = 0; i < 9; ++i) {
    float swivel = -0.2f + 0.2f * static_cast<float>(i);  // -11 .. 80 degrees
    ArmPose p = solve_at(rig, side, t, swivel).pose;
    float cost = 3.0f * p.orientation_error_rad + 0.6f * std::fabs(swivel - preferred) +
                 20.0f * p.reach_error_m;
    if (cost < best_cost) {
      best_cost = cost;
      best = p;
    }
  }
  return best;
}

void apply_arm(const Rig& rig, Side side, const ArmPose& p, PoseBuilder* b) {
  const ArmRig& a = rig.arms[side];
  if (a.shoulder >= 0) b->set(a.shoulder, p.shoulder);
  // Deltas are absolute (model space); PoseBuilder places the upper arm through the clavicle's
  // delta, so it starts where the clavicle put it, as solve_at assumed.
  b->set(a.upper, p.upper);
  b->set(a.lower, p.lower);
  b->set(a.hand, p.hand);
}

}  // namespace sw::synthesis

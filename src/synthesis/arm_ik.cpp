// Arm IK: clavicle + analytic two-bone + swivel + wrist/forearm split (see arm_ik.h).
#include "synthesis/arm_ik.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace sw::synthesis {
namespace {

constexpr float kPi = 3.14159265358979f;
float clampf(float v, float lo, float hi) { return std::min(hi, std::max(lo, v)); }

struct Solved {
  ArmPose pose;
  glm::vec3 wrist;
  glm::vec3 swivel_axis;  // the chain's (Chain::swivel_axis) at this pose
};

// Shoulder girdle + two-bone chain for one wrist target at one swivel angle.
struct Chain {
  glm::quat shoulder{1, 0, 0, 0}, upper{1, 0, 0, 0}, lower0{1, 0, 0, 0};
  glm::vec3 wrist{0.0f};
  // The swivel turns the whole arm about the shoulder-wrist line: a swivel larger by ds turns
  // the upper arm and the forearm (and a hand on fixed wrist angles) by ds about this unit axis.
  glm::vec3 swivel_axis{0.0f};
  float elbow_flex = 0.0f, elevation = 0.0f, protraction = 0.0f;
};

// What solve_chain needs of one arm's bind pose: constant for a rig, so worked out once instead of
// on every call (a sign solves the chain a few thousand times: every swivel candidate, every
// frame, every iteration of solve_at). Kept per thread for the last rig seen, and checked against
// every input it is made from, so a different (or rebuilt) rig never reads a stale one.
struct ChainBind {
  // Inputs.
  glm::vec3 s0{0.0f}, pivot{0.0f}, elbow{0.0f}, wrist{0.0f}, up{0.0f}, forward{0.0f}, left{0.0f};
  float l1 = -1.0f, l2 = -1.0f;
  bool has_shoulder = false;
  // Derived.
  glm::vec3 out_dir{0.0f}, elev_axis{0.0f}, prot_axis{0.0f}, u1{0.0f}, u2{0.0f}, hinge_bind{0.0f};
  glm::mat3 upper_frame{1.0f}, lower_frame{1.0f};  // orthonormal_frame of the bind bones
  float d_min = 0.0f, d_max = 0.0f;
  bool made_from(const Rig& rig, const ArmRig& a) const {
    return l1 == a.upper_len_m && l2 == a.lower_len_m && has_shoulder == (a.shoulder >= 0) &&
           s0 == rig.bind_pos[a.upper] && (!has_shoulder || pivot == rig.bind_pos[a.shoulder]) &&
           elbow == rig.bind_pos[a.lower] && wrist == rig.bind_pos[a.hand] && up == rig.up &&
           forward == rig.forward && left == rig.left;
  }
};

const ChainBind& chain_bind(const Rig& rig, Side side) {
  thread_local ChainBind cache[2];
  ChainBind& b = cache[side];
  const ArmRig& a = rig.arms[side];
  if (b.made_from(rig, a)) return b;
  const ArmLimits& lim = arm_limits();
  b = ChainBind{};
  b.s0 = rig.bind_pos[a.upper];
  b.has_shoulder = a.shoulder >= 0;
  if (b.has_shoulder) b.pivot = rig.bind_pos[a.shoulder];
  b.elbow = rig.bind_pos[a.lower];
  b.wrist = rig.bind_pos[a.hand];
  b.up = rig.up;
  b.forward = rig.forward;
  b.left = rig.left;
  b.l1 = a.upper_len_m;
  b.l2 = a.lower_len_m;
  const float l1 = b.l1, l2 = b.l2;
  b.out_dir = side == kLeft ? rig.left : -rig.left;  // lateral, away from the body
  if (b.has_shoulder) {
    glm::vec3 cl = safe_normalize(b.s0 - b.pivot, b.out_dir);
    b.elev_axis = safe_normalize(glm::cross(cl, rig.up), rig.forward);
    b.prot_axis = safe_normalize(glm::cross(cl, rig.forward), rig.up);
  }
  b.d_max = 0.9995f * (l1 + l2);
  b.d_min = std::sqrt(std::max(1e-8f, l1 * l1 + l2 * l2 - 2.0f * l1 * l2 * std::cos(kPi - lim.elbow_flex_max)));
  // Upper arm bind frame (bone dir, elbow-bend dir = body forward): a T/A-posed elbow flexes
  // towards the body's front.
  b.u1 = safe_normalize(b.elbow - b.s0, b.out_dir);
  glm::vec3 b1 = safe_normalize(reject(rig.forward, b.u1), rig.forward);
  b.upper_frame = orthonormal_frame(b.u1, b1);
  b.hinge_bind = glm::normalize(glm::cross(b.u1, b1));
  b.u2 = safe_normalize(b.wrist - b.elbow, b.u1);
  b.lower_frame = orthonormal_frame(b.u2, glm::cross(b.hinge_bind, b.u2));
  return b;
}

// Where the shoulder girdle protracts for a wrist across the body (solve_chain), by
// Rig::protraction_zone: from `medial_from` of the arm's reach medial of the shoulder joint,
// rising by `slope` per reach (to the limit), full up to `front_to` - `front_fade` of the reach in
// front of the shoulder and none from `front_to`, full up to `above_to` - 0.3 above it and none
// from `above_to`. Zone 0 is the usual one (every solve); 1 and 2 the per-sign alternatives
// synthesize.cpp choose_wide_protraction tries where a sign's own frames leave an arm in the body
// (docs/SYNTHESIS.md arm-side): 1 reaches wrists far in front and up to the face, 2 also those
// less far across, with a gentler onset.
struct ProtractionZone {
  float medial_from, slope, front_to, front_fade, above_to;
};
const ProtractionZone kProtractionZones[3] = {{0.52f, 8.0f, 0.27f, 0.09f, 0.1f},
                                              {0.52f, 8.0f, 0.6f, 0.25f, 0.4f},
                                              {0.40f, 4.0f, 0.6f, 0.25f, 0.4f}};

// `bind` is chain_bind(rig, side) and cos_swivel, sin_swivel the swivel's cosine and sine: the
// caller (solve_at) looks them up once for its rounds, which all solve at the same swivel.
Chain solve_chain(const Rig& rig, const ChainBind& bind, const glm::vec3& wrist_target, float cos_swivel,
                  float sin_swivel) {
  const float l1 = bind.l1, l2 = bind.l2;
  const glm::vec3 s0 = bind.s0;
  const glm::vec3 out_dir = bind.out_dir;
  const ArmLimits& lim = arm_limits();
  Chain c;
  glm::vec3 shoulder_pos = s0;
  // Clavicle: shrug for targets above the shoulder, protract for far ones (comfort first: the
  // shoulder moves only when the arm alone would be near its reach or high).
  if (bind.has_shoulder) {
    glm::vec3 pivot = bind.pivot;
    glm::vec3 v = wrist_target - s0;
    float reach = glm::length(v) / (l1 + l2);
    float height = glm::dot(v, rig.up) / (l1 + l2);
    float fwd = std::max(0.0f, glm::dot(safe_normalize(v, rig.forward), rig.forward));
    c.elevation = clampf(0.6f * (height + 0.15f), 0.0f, lim.clavicle_elevation);
    // Across the body (a hand beside the far side of the chest, belly or shoulder): the upper arm
    // adducts across the chest, and the shoulder girdle protracts with it (horizontal adduction
    // takes the scapula forward round the ribcage), bringing the shoulder joint forward so that
    // the upper arm passes in front of the chest, not through it. Only for wrists far across
    // (from 52% of the arm's reach medial of the shoulder joint, full protraction from 56%: a
    // steep onset measured better than a gradual one, which leaves the shoulder back for the
    // nearer far-side places; from 50% it also moves THANK-YOU's wrist at the chin),
    // near the body's depth (full up to 18% of the reach in front of the shoulder, none beyond
    // 27%) and not above the shoulder (full from 20% below it, none from 10% above): a hand far
    // in front, at the face or over the head crosses with the arm alone.
    const float medial = glm::dot(v, -out_dir) / (l1 + l2);
    const ProtractionZone& z = kProtractionZones[rig.protraction_zone];  // 0, 1 or 2 (rig.h)
    const float near_body = clampf((z.front_to - glm::dot(v, rig.forward) / (l1 + l2)) / z.front_fade, 0.0f, 1.0f);
    const float not_above = clampf((z.above_to - height) / 0.3f, 0.0f, 1.0f);
    const float across = z.slope * (medial - z.medial_from) * near_body * not_above;
    c.protraction = clampf(std::max(1.2f * (reach - 0.75f) * fwd, across), 0.0f, lim.clavicle_protraction);
    c.shoulder = axis_angle(bind.prot_axis, c.protraction) * axis_angle(bind.elev_axis, c.elevation);
    shoulder_pos = pivot + c.shoulder * (s0 - pivot);
  }
  // Two-bone: distance clamped between full extension and the elbow's flexion limit.
  glm::vec3 to = wrist_target - shoulder_pos;
  float d = clampf(glm::length(to), bind.d_min, bind.d_max);
  glm::vec3 axis = safe_normalize(to, out_dir);
  float cos_a = clampf((l1 * l1 + d * d - l2 * l2) / (2.0f * l1 * d), -1.0f, 1.0f);
  float sin_a = std::sqrt(std::max(0.0f, 1.0f - cos_a * cos_a));
  // The swivel's zero (swivel_zero below: the way down, leaned near the verticals, and an "out"
  // of fixed handedness).
  const SwivelZero zero = swivel_zero(axis, rig.up, rig.forward, out_dir, rig.fixed_handed_swivel_zero);
  const glm::vec3 down = zero.down, outp = zero.out;
  glm::vec3 sw = cos_swivel * down + sin_swivel * outp;
  c.swivel_axis = glm::cross(down, outp);  // d sw / d swivel = swivel_axis x sw
  glm::vec3 elbow = shoulder_pos + l1 * (cos_a * axis + sin_a * sw);
  c.wrist = shoulder_pos + d * axis;
  c.elbow_flex = kPi - std::acos(clampf((l1 * l1 + l2 * l2 - d * d) / (2.0f * l1 * l2), -1.0f, 1.0f));
  // Upper arm: bind frame -> posed (bone dir, towards the side the forearm folds to).
  glm::vec3 u1p = safe_normalize(elbow - shoulder_pos, axis);
  glm::vec3 b1p = safe_normalize(reject(-sw, u1p), -sw);
  c.upper = frame_to_frame(bind.upper_frame, u1p, b1p);
  glm::vec3 hinge = c.upper * bind.hinge_bind;
  glm::vec3 u2p = safe_normalize(c.wrist - elbow, u1p);
  c.lower0 = frame_to_frame(bind.lower_frame, u2p, glm::cross(hinge, u2p));
  return c;
}

// Wrist frame in the bind pose: e1 forearm axis, e2 palm normal, e3 = e1 x e2.
struct WristFrame {
  glm::vec3 e1, e2, e3;
  float radial_sign;  // dev * radial_sign = radial deviation
};
WristFrame wrist_frame(const Rig& rig, Side side) {
  const ArmRig& a = rig.arms[side];
  WristFrame w;
  w.e1 = safe_normalize(rig.bind_pos[a.hand] - rig.bind_pos[a.lower], a.finger_dir);
  w.e2 = safe_normalize(reject(a.palm_normal, w.e1), a.palm_normal);
  w.e3 = glm::cross(w.e1, w.e2);
  // Positive dev moves the fingers towards -e3: ulnar for a right hand, radial for a left one.
  w.radial_sign = glm::dot(w.e3, a.radial) > 0.0f ? -1.0f : 1.0f;
  return w;
}

// An angle of a joint limited to [lo, hi], read from atan2 (so in (-pi, pi]). Inside its limits
// it is kept. Beyond them it goes to a limit: without a previous value, the one on its side of
// zero (the key poses' choice); with one (a path solved frame by frame), the limit with the least
// angle to go round the circle plus the distance from the previous value. The requested angle
// wrapping through +-pi then no longer flips the joint from one limit to the other in a frame:
// it switches only when the other limit is nearer by the whole range (a continuous path of
// requests gives a continuous path of poses until then).
float clamp_limited(float a, float lo, float hi, const float* previous) {
  if (a >= lo && a <= hi) return a;
  if (!previous) return a > hi ? hi : lo;
  auto around = [](float x) { return x - 2.0f * kPi * std::floor(x / (2.0f * kPi)); };  // [0, 2 pi)
  float to_hi = around(a - hi) + std::fabs(hi - *previous);
  float to_lo = around(lo - a) + std::fabs(lo - *previous);
  return to_hi <= to_lo ? hi : lo;
}

// The angle about unit axis u that best realises target = a * R(u, angle) * b (the least rotation
// between them): with m = a^-1 * target * b^-1, the product's quaternion dot with the target is
// m.w cos(angle/2) + (m.xyz . u) sin(angle/2), largest at angle = 2 atan2(m.xyz . u, m.w); the
// error grows with the circular distance from there, so within [lo, hi] the best is that angle
// or the limit nearer to it round the circle.
float best_limited_angle(const glm::quat& a, const glm::quat& target, const glm::quat& b, const glm::vec3& u,
                         float lo, float hi) {
  const glm::quat m = glm::conjugate(a) * target * glm::conjugate(b);
  float best = 2.0f * std::atan2(glm::dot(glm::vec3(m.x, m.y, m.z), u), m.w);
  if (best > kPi) best -= 2.0f * kPi;
  if (best <= -kPi) best += 2.0f * kPi;
  if (best >= lo && best <= hi) return best;
  auto around = [](float x) { return x - 2.0f * kPi * std::floor(x / (2.0f * kPi)); };  // [0, 2 pi)
  return around(best - hi) <= around(lo - best) ? hi : lo;
}

// When a wrist angle was clamped, the other two of the Euler decomposition no longer fit: they
// are the angles that go with the unclamped one, and the clamped product can miss the request by
// far more than the request lies beyond the limits. Near a limit the miss then moves faster
// than the request (Й's twist, its hand at three limits at once: the orientation error 0.04 ->
// 0.47 rad in one frame, the ring tip's step changed by 46 mm; in arm_ik_test 3.1 times the
// request's rate). Each angle in turn is set to its best within its limits given the other two
// (coordinate descent: every step lowers the error, so the result is never worse than the
// clamped Euler angles it starts from), which leaves the error near the request's distance from
// the reachable range, so it moves no faster than the request does. Two sweeps: a third changed
// no smoothness figure of the lexicon or the alphabets by 0.1 mm and cost 1.8 % of a 20-sign
// phrase's instructions.
constexpr int kWristFitSweeps = 2;
void fit_clamped_wrist(const WristFrame& w, const glm::quat& rel, float* twist, float* radial, float* flex) {
  const ArmLimits& lim = arm_limits();
  const glm::quat id(1, 0, 0, 0);
  // The deviation's own angle about e2 is radial * radial_sign; its limits follow the sign.
  const float dev_lo = w.radial_sign > 0.0f ? -lim.ulnar_dev : -lim.radial_dev;
  const float dev_hi = w.radial_sign > 0.0f ? lim.radial_dev : lim.ulnar_dev;
  float dev = *radial * w.radial_sign;
  for (int sweep = 0; sweep < kWristFitSweeps; ++sweep) {
    const glm::quat d = axis_angle(w.e2, dev), f = axis_angle(w.e3, *flex);
    *twist = best_limited_angle(id, rel, d * f, w.e1, lim.twist_lo, lim.twist_hi);
    const glm::quat t = axis_angle(w.e1, *twist);
    dev = best_limited_angle(t, rel, f, w.e2, dev_lo, dev_hi);
    *flex = best_limited_angle(t * axis_angle(w.e2, dev), rel, id, w.e3, -lim.wrist_ext, lim.wrist_flex);
  }
  *radial = dev * w.radial_sign;
}

// R_rel decomposed as twist(e1) * deviation(e2) * flexion(e3), each clamped (towards the
// previous frame's angles when there is one, see clamp_limited). True when a limit held.
bool clamped_euler(const WristFrame& w, const glm::quat& rel, const ArmPose* previous, float* twist, float* radial,
                   float* flex) {
  const ArmLimits& lim = arm_limits();
  glm::mat3 basis(w.e1, w.e2, w.e3);
  glm::mat3 m = glm::transpose(basis) * glm::mat3_cast(rel) * basis;
  auto R = [&](int r, int c) { return m[c][r]; };
  float tw = std::atan2(-R(1, 2), R(2, 2));
  float dev = std::asin(clampf(R(0, 2), -1.0f, 1.0f));
  float fl = std::atan2(-R(0, 1), R(0, 0));
  *twist = clamp_limited(tw, lim.twist_lo, lim.twist_hi, previous ? &previous->twist_rad : nullptr);
  *radial = clampf(dev * w.radial_sign, -lim.ulnar_dev, lim.radial_dev);
  *flex = clamp_limited(fl, -lim.wrist_ext, lim.wrist_flex, previous ? &previous->wrist_flex_rad : nullptr);
  return *twist != tw || *radial != dev * w.radial_sign || *flex != fl;
}

// R_rel = lower^-1 * hand decomposed as clamped_euler does. With a wrist motion (a nod, swing,
// twist or circle: `motion`, the part of hand_delta right-multiplied onto the held orientation,
// ArmTarget::wrist_motion) the motion turns the hand as the limits realise the held orientation
// (its clamped angles, the key pose's wrist) and, where the turned hand is beyond a limit, the
// angles are refitted to it (fit_clamped_wrist). So the motion starts and ends on the key pose's
// wrist, and near a limit the hand stops on it instead of jumping (Й's twist).
void solve_wrist(const WristFrame& w, const glm::quat& lower0, const glm::quat& hand_delta, const glm::quat& motion,
                 const ArmPose* previous, float max_step, float* twist, float* radial, float* flex) {
  glm::quat rel = glm::conjugate(lower0) * hand_delta;
  const bool moving = motion != glm::quat(1, 0, 0, 0);
  if (moving) {
    float t0, r0, f0;
    clamped_euler(w, rel * glm::conjugate(motion), previous, &t0, &r0, &f0);
    rel = axis_angle(w.e1, t0) * axis_angle(w.e2, r0 * w.radial_sign) * axis_angle(w.e3, f0) * motion;
  }
  if (clamped_euler(w, rel, previous, twist, radial, flex) && moving) fit_clamped_wrist(w, rel, twist, radial, flex);
  if (!previous) return;
  // On a path the wrist turns at a human speed: each angle moves at most max_step from the
  // previous frame's. Where the request is out of reach, the clamped angles can still change
  // branch (near deviation +-90 degrees, twist and flexion swing through half a turn between two
  // frames: LEARN's wrist moved 12-17 cm in one frame); the wrist then turns through its range
  // over a few frames, and the reach rounds of solve_at keep the contact point on its target.
  *twist = clampf(*twist, previous->twist_rad - max_step, previous->twist_rad + max_step);
  *radial = clampf(*radial, previous->wrist_dev_rad - max_step, previous->wrist_dev_rad + max_step);
  *flex = clampf(*flex, previous->wrist_flex_rad - max_step, previous->wrist_flex_rad + max_step);
}

void compose(const WristFrame& w, const Chain& c, float twist, float radial, float flex, ArmPose* p) {
  p->shoulder = c.shoulder;
  p->upper = c.upper;
  p->lower = c.lower0 * axis_angle(w.e1, twist);
  p->hand = p->lower * axis_angle(w.e2, radial * w.radial_sign) * axis_angle(w.e3, flex);
  p->twist_rad = twist;
  p->wrist_dev_rad = radial;
  p->wrist_flex_rad = flex;
  p->elbow_flex_rad = c.elbow_flex;
  p->clavicle_elevation_rad = c.elevation;
  p->clavicle_protraction_rad = c.protraction;
}

// The wrist target depends on the hand orientation the wrist limits allow, which depends on the
// forearm, which depends on the wrist target. Phase 1: a damped fixed-point iteration on the
// requested orientation (undamped it can cycle when a limit is active). Phase 2, only if the
// contact point still misses: keep the wrist angles and correct the wrist target by the residual
// (reach before orientation: a touch must touch). The most accurate iterate is kept.
constexpr int kOrientationRounds = 12;
constexpr int kReachRounds = 8;
constexpr float kDamping = 0.5f;

// solve_at's own work; solve_at (below the memo) answers a free solve it has already done.
Solved solve_at_uncached(const Rig& rig, Side side, const ArmTarget& t, float swivel) {
  const WristFrame w = wrist_frame(rig, side);
  const ChainBind& bind = chain_bind(rig, side);
  const float cos_swivel = std::cos(swivel), sin_swivel = std::sin(swivel);
  Solved best;
  best.pose.reach_error_m = 1e30f;
  // A contact part on the forearm (the elbow, the forearm: DAY's elbow on the back of the other
  // hand) moves with the forearm, not the hand: carried by the hand's rotation it rode on a
  // forearm-long lever that the wrist's flexion and deviation swung (the wrist 12-19 cm in a
  // frame as the wrist angles moved). Behind the wrist along the forearm axis (2 cm: the wrist's
  // own places are within that) is on the forearm.
  const bool on_forearm = glm::dot(t.contact_offset, w.e1) < -0.02f;
  auto carried = [&](const ArmPose& p) { return (on_forearm ? p.lower : p.hand) * t.contact_offset; };
  auto consider = [&](const Chain& c, float tw, float rd, float fl) {
    ArmPose p;
    p.swivel_rad = swivel;
    compose(w, c, tw, rd, fl, &p);
    p.contact_point = c.wrist + carried(p);
    p.reach_error_m = glm::length(p.contact_point - t.point);
    p.orientation_error_rad = rotation_angle(glm::conjugate(t.hand_delta) * p.hand);
    if (p.reach_error_m < best.pose.reach_error_m - 1e-5f) best = Solved{p, c.wrist, c.swivel_axis};
    return p;
  };
  glm::vec3 wrist_target = t.point - t.hand_delta * t.contact_offset;
  if (t.previous && t.start_at_previous_wrist) wrist_target = t.previous_wrist;
  float tw = 0, rd = 0, fl = 0;
  for (int iter = 0; iter < kOrientationRounds; ++iter) {
    Chain c = solve_chain(rig, bind, wrist_target, cos_swivel, sin_swivel);
    solve_wrist(w, c.lower0, t.hand_delta, t.wrist_motion, t.previous, t.max_wrist_step_rad, &tw, &rd, &fl);
    ArmPose p = consider(c, tw, rd, fl);
    glm::vec3 next = t.point - carried(p);
    float step = glm::length(next - wrist_target);
    wrist_target += (iter == 0 ? 1.0f : kDamping) * (next - wrist_target);
    if (step < 2e-4f) break;
  }
  if (best.pose.reach_error_m > 2e-3f) {
    tw = best.pose.twist_rad, rd = best.pose.wrist_dev_rad, fl = best.pose.wrist_flex_rad;
    wrist_target = best.wrist;
    for (int iter = 0; iter < kReachRounds && best.pose.reach_error_m > 5e-4f; ++iter) {
      glm::vec3 achieved = best.wrist + carried(best.pose);
      wrist_target += t.point - achieved;
      Chain c = solve_chain(rig, bind, wrist_target, cos_swivel, sin_swivel);
      consider(c, tw, rd, fl);
    }
  }
  return best;
}

// solve_at_uncached, answered from the live ArmSolveMemo for a free solve (defined below it).
Solved solve_at(const Rig& rig, Side side, const ArmTarget& t, float swivel);

}  // namespace

const ArmLimits& arm_limits() {
  static const ArmLimits limits;
  return limits;
}

ArmSegments arm_segments(const Rig& rig, Side side, const ArmPose& p) {
  const ArmRig& a = rig.arms[side];
  const glm::vec3 s0 = rig.bind_pos[a.upper];
  ArmSegments seg;
  seg.shoulder = a.shoulder >= 0 ? rig.bind_pos[a.shoulder] + p.shoulder * (s0 - rig.bind_pos[a.shoulder]) : s0;
  seg.elbow = seg.shoulder + p.upper * (rig.bind_pos[a.lower] - s0);
  seg.wrist = seg.elbow + p.lower * (rig.bind_pos[a.hand] - rig.bind_pos[a.lower]);
  return seg;
}

// The way down square to the axis. With the wrist straight above the shoulder joint that way
// vanishes and turned half round as the line passed the vertical (the wrist going from in front
// of the shoulder to behind it): at a constant swivel the elbow swung across in one frame (a
// pinched hand at the forehead replaced in place by a flat hand pointing forward: the elbow 194
// mm in a frame, 243 mm change of step, on the project avatar). Within 21 degrees of the vertical
// (kSwivelZeroUpright and up) the way down leans forward, where it points for a wrist in front of
// the shoulder, by up to kSwivelZeroLean, so the zero keeps pointing forward as the line passes
// the vertical. A zero square to the line must vanish somewhere (the hairy-ball theorem): this
// moves the turn from straight up to some 15 degrees behind the vertical (measured: the forehead
// replace's wrist goes 11 degrees behind). Leaning from 32 degrees (0.85) moved the forehead
// replace's elbow less evenly (104 mm a frame on the reference humanoid, over the 100 mm bound);
// a lean of 3 for wrists behind the vertical only, from 60 degrees, put the turn 50 degrees
// behind but swung the reference's elbow (77 mm change of step).
// Straight UNDER the joint the way down is the wrist's few-cm horizontal offset reversed and
// still turns half round as the wrist passes under the joint (with `out`, so the zero turns by
// pi there). Leaning it back there too (for a wrist behind the joint only, 2 per unit of the
// axis's backward part, up to 0.5) was measured and not kept (docs/SYNTHESIS.md swivel-pref): it
// moves the turn some 15 degrees behind the downward vertical, where the reference humanoid's
// hanging fist in gołąb then leapt 460 mm.
// The "out" side: axis x down, with the handedness that points along out_dir for a wrist in
// front of the shoulder (the old zero's there), fixed, so it turns with the axis continuously.
// The usual zero's "out" (fixed_handed false): out_dir's part square to the axis and to down,
// which turns half round where the wrist crosses the shoulder joint's coronal plane (elbow-leap).
SwivelZero swivel_zero(const glm::vec3& axis, const glm::vec3& up, const glm::vec3& forward, const glm::vec3& out_dir,
                       bool fixed_handed) {
  constexpr float kSwivelZeroUpright = 0.93f, kSwivelZeroLean = 0.5f;
  auto smooth_lean = [&](float along) {
    const float u = clampf((along - kSwivelZeroUpright) / (0.99f - kSwivelZeroUpright), 0.0f, 1.0f);
    return kSwivelZeroLean * u * u * (3.0f - 2.0f * u);
  };
  const float lean = smooth_lean(glm::dot(axis, up));
  SwivelZero z;
  glm::vec3 down = reject(-up + lean * forward, axis);
  if (glm::length(down) < 1e-3f) down = reject(-forward, axis);
  z.down = glm::normalize(down);
  if (!fixed_handed) {
    z.out = safe_normalize(reject(reject(out_dir, axis), z.down), glm::cross(axis, z.down));
    return z;
  }
  const float handed = glm::dot(out_dir, glm::cross(forward, -up)) < 0.0f ? -1.0f : 1.0f;
  z.out = handed * safe_normalize(glm::cross(axis, z.down), out_dir);
  return z;
}

float swivel_of(const SwivelZero& z, const glm::vec3& elbow_offset) {
  return std::atan2(glm::dot(elbow_offset, z.out), glm::dot(elbow_offset, z.down));
}

// The lateral direction's part along `out` (the cosine of the angle between them), over
// kOutShareBand: wrists whose lateral direction is within asin(kOutShareBand) of leaving the
// elbow's circle blend the two sides' meanings.
constexpr float kOutShareBand = 0.3f;
float swivel_out_share(const SwivelZero& z, const glm::vec3& out_dir) {
  return clampf(glm::dot(out_dir, z.out) / kOutShareBand, -1.0f, 1.0f);
}

namespace {

// Swivel candidates (radians, 0 elbow down, + elbow out): from the elbow in front of the body
// (-92 deg: shoulder internal rotation; for a hand near the shoulder the "out" side of the circle
// is behind the body, so "in" is where the elbow comes forward) to the elbow raised out to the
// side (115 deg: a hand at the chin or the opposite cheek with the upper arm clear of the chest).
// The body cost decides among them when the elbow would enter the trunk.
constexpr float kSwivelLo = -1.6f, kSwivelStep = 0.2f;
constexpr int kSwivelCandidates = 19;
// Behind the shoulder joint's coronal plane the range is mirrored, [-2.0, 1.6]: shifted down by
// the range's asymmetry (solve_arm_uncached, docs/SYNTHESIS.md swivel-pref).
constexpr float kSwivelMirrorShift = 0.4f;
// The cost of a swivel away from the neighbouring pose's (ArmTarget::near_swivel_rad), per
// radian: a radian of elbow swing weighs as much as two thirds of a radian of orientation error,
// so a pose keeps its neighbour's swivel unless another realises the hand clearly better or keeps
// the arm out of the body (the body cost is steeper). Measured on the lexicon (both rigs): 1.0
// left DEAF's elbow swinging between the ear and the mouth on the reference rig (26 cm change of
// step), 3.0 held LEARN's hand at the forehead in the palm's basin (12 cm).
constexpr float kSwivelContinuityPerRad = 2.0f;
// The neighbouring swivel's basin is left (the whole range searched) when its best pose misses
// the requested orientation by more than this (20 degrees, twice the orientation acceptance):
// LEARN's pinched hand at the forehead kept the palm's swivel at 59 degrees off and the arm
// solve broke away on the way (elbow 10 cm in a frame).
constexpr float kNearBasinMaxOrientationErrorRad = 0.35f;
// Issue 4's acceptance for the hand's orientation (10 degrees), which solve_arm's acceptance
// search aims for where the comfort pick misses it.
constexpr float kOrientationAcceptanceRad = 0.1745f;
// Signers keep the elbow beside the body, not behind it: an elbow swung behind the body (the
// arm wrapped round the head to realise an orientation the wrist cannot) is shoulder extension
// with horizontal abduction near its limit. Beyond 12 cm behind the shoulder joint (a hand held at
// the chest lets the elbow hang a little behind the body's mid-plane), each upper arm
// length costs as much as 1 rad of orientation error, so the hand gives way first.
float elbow_behind_cost(const Rig& rig, Side side, const ArmPose& p) {
  const ArmRig& a = rig.arms[side];
  ArmSegments seg = arm_segments(rig, side, p);
  float behind = -glm::dot(seg.elbow - seg.shoulder, rig.forward) - 0.12f;
  return behind > 0.0f ? 3.0f * behind / a.upper_len_m : 0.0f;
}

// The forearm's twist excess carried to the shoulder. A signer whose pronation or supination
// runs out takes the rest with the shoulder's internal/external rotation; with the wrist where the
// target puts it, what the shoulder can still turn is the swivel: the whole arm turned about the
// shoulder-wrist line, which rolls the forearm about its own axis in proportion to the cosine of
// the angle between the two (all of it with the elbow straight, where the swivel is the upper
// arm's own rotation; none with the forearm across that line, which only swings the hand). Where
// the wrist's limits leave the hand off the request by the world rotation
// e = requested * achieved^-1, turning the arm by ds about the swivel axis n (the wrist angles
// kept) leaves angle(e^-1 R(n, ds)), least at ds = 2 atan2(e.xyz . n, e.w) (the closed form of
// best_limited_angle).
float swivel_towards(const glm::quat& requested, const glm::quat& hand, const glm::vec3& swivel_axis) {
  const glm::quat e = requested * glm::conjugate(hand);
  float ds = 2.0f * std::atan2(glm::dot(glm::vec3(e.x, e.y, e.z), swivel_axis), e.w);
  if (ds > kPi) ds -= 2.0f * kPi;
  if (ds <= -kPi) ds += 2.0f * kPi;
  return ds;
}

// A wrist motion (ArmTarget::wrist_motion) that the wrist's limits cannot follow: the excess is
// carried to the swivel. Only the motion's own excess: the swivel moves until what the turned
// request still asks of it equals what the held orientation (the key pose's, which the swivel
// search already traded against comfort and the body) asks at the frame's own swivel, so the
// carry is 0 where the motion is (its ends) and grows with it. Each round moves the swivel by
// that difference weighted by |cos|^3 of the angle between the forearm and the shoulder-wrist
// line (the swivel's hold on the forearm's roll): the rest of a swivel swings the hand sideways,
// which costs the elbow's travel for little of the roll. PLAY's forearm runs across that line and
// its twists come back and forth: carried in full, its elbow swung 0.27 rad in 3 frames (72 m/s^2
// at 60 fps x 1.25 on the reference humanoid); weighted by cos^2, 52.3 m/s^2 on the project avatar
// (the smoothness bound is 50.4); by |cos|^3 it keeps under it, and a twist about a forearm 26
// degrees off the line is still carried to 0.07 rad (arm_ik_test). The swivel stays within the shoulder's range (the swivel candidates', -92 to +115
// degrees); a round is kept when the hand comes nearer its orientation and the contact point
// stays on its target (reach no worse by 1 mm).
constexpr int kCarryRounds = 3;
Solved carry_wrist_motion_excess(const Rig& rig, Side side, const ArmTarget& t, Solved s, float lo, float hi) {
  if (t.wrist_motion == glm::quat(1, 0, 0, 0) || s.pose.orientation_error_rad < 1e-3f) return s;
  // The held orientation as the wrist realises it on this forearm (solve_wrist's clamped angles of
  // the held orientation, before the motion turns the hand).
  const WristFrame w = wrist_frame(rig, side);
  const glm::quat held = t.hand_delta * glm::conjugate(t.wrist_motion);
  const glm::quat lower0 = s.pose.lower * glm::conjugate(axis_angle(w.e1, s.pose.twist_rad));
  float t0, r0, f0;
  clamped_euler(w, glm::conjugate(lower0) * held, t.previous, &t0, &r0, &f0);
  const glm::quat held_hand =
      lower0 * axis_angle(w.e1, t0) * axis_angle(w.e2, r0 * w.radial_sign) * axis_angle(w.e3, f0);
  const float held_asks = swivel_towards(held, held_hand, s.swivel_axis);
  const float range_lo = std::min(lo, s.pose.swivel_rad), range_hi = std::max(hi, s.pose.swivel_rad);
  for (int round = 0; round < kCarryRounds; ++round) {
    const float hold = glm::dot(s.pose.lower * w.e1, s.swivel_axis);
    const float ds = hold * hold * std::fabs(hold) * (swivel_towards(t.hand_delta, s.pose.hand, s.swivel_axis) - held_asks);
    const float swivel = clampf(s.pose.swivel_rad + ds, range_lo, range_hi);
    if (std::fabs(swivel - s.pose.swivel_rad) < 1e-3f) break;
    Solved next = solve_at(rig, side, t, swivel);
    if (next.pose.orientation_error_rad > s.pose.orientation_error_rad || next.pose.reach_error_m > s.pose.reach_error_m + 0.001f)
      break;
    s = next;
  }
  return s;
}

ArmPose solve_arm_uncached(const Rig& rig, Side side, const ArmTarget& t) {
  auto clearance = [&](ArmPose* p) {
    if (!t.body) return 0.0f;
    p->trunk_depth_m = arm_trunk_depth(*t.body, side, arm_segments(rig, side, *p), t.hand_contact,
                                       &p->trunk_push_dir);
    return arm_trunk_cost(p->trunk_depth_m);
  };
  // The candidates' range and the comfort preference were numbers in the old zero, whose "out"
  // was the lateral direction's side of the elbow's circle: behind the shoulder joint's coronal
  // plane that is the negative side of swivel_zero's. Both are the old numbers times the
  // lateral direction's share of `out` (swivel_out_share, +1 in front, -1 behind, through 0 in
  // the plane), read at the wrist the target asks for (solve_at's first wrist), so they keep
  // their meaning, "the elbow down and out", on both sides and move continuously across.
  const ArmRig& a = rig.arms[side];
  const ChainBind& bind = chain_bind(rig, side);
  const glm::vec3 wrist_guess = t.point - t.hand_delta * t.contact_offset;
  const glm::vec3 axis_guess = safe_normalize(wrist_guess - bind.s0, bind.out_dir);
  // In the usual zero (the default) the numbers are the old ones as they are: share 1.
  const float out_share =
      rig.fixed_handed_swivel_zero
          ? swivel_out_share(swivel_zero(axis_guess, rig.up, rig.forward, bind.out_dir, true), bind.out_dir)
          : 1.0f;
  // The old range [kSwivelLo, kSwivelLo + 3.6] in front, mirrored behind.
  const float mirror = 0.5f * (1.0f - out_share);
  const float lo = kSwivelLo - kSwivelMirrorShift * mirror;
  const float hi = lo + kSwivelStep * static_cast<float>(kSwivelCandidates - 1);
  if (!t.auto_swivel) {
    ArmPose p = carry_wrist_motion_excess(rig, side, t, solve_at(rig, side, t, t.swivel_rad), lo, hi).pose;
    if (t.body) p.body_cost = clearance(&p) + elbow_behind_cost(rig, side, p);
    return p;
  }
  // Comfort heuristic: the elbow hangs down and a little out (25 deg), rising outwards for
  // targets above the shoulder; among candidates, the one that best realises the requested
  // orientation (wrist within limits), reaches and keeps the arm out of the trunk, close to that
  // preference (and to the neighbouring pose's swivel, ArmTarget::near_swivel_rad), wins.
  glm::vec3 v = t.point - rig.bind_pos[a.upper];
  float height = glm::dot(v, rig.up) / (a.upper_len_m + a.lower_len_m);
  float preferred = out_share * (0.44f + 0.6f * clampf(1.5f * (height + 0.2f), 0.0f, 1.0f));
  ArmPose best;
  float best_cost = 1e30f;
  // The pose at a swivel and its cost.
  auto score = [&](float swivel, ArmPose* out) {
    ArmPose& p = *out;
    p = solve_at(rig, side, t, swivel).pose;
    p.body_cost = clearance(&p) + elbow_behind_cost(rig, side, p);
    // For a touch, reach beyond 5 mm is steep (300 per metre): with the trunk cost in play a
    // swivel that misses the touch by 2 cm could otherwise win, and a touch must touch (< 1 cm).
    // A hand held off the body keeps the old trade (a centimetre or two is within its band).
    float steep = t.hand_contact ? 300.0f * std::max(0.0f, p.reach_error_m - 0.005f) : 0.0f;
    float cost = 3.0f * p.orientation_error_rad + 0.6f * std::fabs(swivel - preferred) +
                 20.0f * p.reach_error_m + steep + p.body_cost;
    if (t.has_near_swivel) cost += kSwivelContinuityPerRad * std::fabs(swivel - t.near_swivel_rad);
    return cost;
  };
  // The grid candidates scored so far that missed the orientation acceptance (the acceptance
  // search below does not solve them again).
  bool missed[kSwivelCandidates] = {};
  auto consider = [&](float swivel) {
    if (swivel < lo - 1e-4f || swivel > hi + 1e-4f) return;
    ArmPose p;
    const float cost = score(swivel, &p);
    const float grid = (swivel - lo) / kSwivelStep;
    const int g = static_cast<int>(std::lround(grid));
    if (std::fabs(grid - static_cast<float>(g)) < 1e-3f) missed[g] = p.orientation_error_rad > kOrientationAcceptanceRad;
    if (cost < best_cost) {
      best_cost = cost;
      best = p;
    }
  };
  if (t.has_near_swivel) {
    // The neighbouring pose's basin first: its swivel (on the candidate grid's range) and two
    // steps either side. It is left only when none of them keeps the arm out of the body and a
    // touch on its target (then the whole range below decides, the continuity cost still in).
    const float near = clampf(t.near_swivel_rad, lo, hi);
    for (float d : {0.0f, -kSwivelStep, kSwivelStep, -2.0f * kSwivelStep, 2.0f * kSwivelStep}) consider(near + d);
    const bool leave = best.body_cost > 0.03f || (t.hand_contact && best.reach_error_m > 0.005f) ||
                       best.orientation_error_rad > kNearBasinMaxOrientationErrorRad;
    if (!leave) {
      const float centre = best.swivel_rad;
      for (float d : {-0.5f * kSwivelStep, 0.5f * kSwivelStep}) consider(centre + d);
      return best;
    }
  }
  // Coarse to fine (the per-sign time budget): every other candidate first, then the two
  // neighbours of the best one.
  for (int i = 0; i < kSwivelCandidates; i += 2) consider(lo + kSwivelStep * static_cast<float>(i));
  const float coarse = best.swivel_rad;
  for (float d : {-kSwivelStep, kSwivelStep}) consider(coarse + d);
  if (!t.seek_orientation_acceptance || best.orientation_error_rad <= kOrientationAcceptanceRad) return best;
  // The comfort pick leaves the hand more than 10 degrees off (issue 4's palm bound): the rest of
  // the swivel range is searched for a pose that realises it within the bound while keeping
  // what the pick keeps, the arm out of the body (its body cost and its depth in the trunk no
  // higher, and that depth within the 2 mm the body cost forgives: a pose in the trunk is
  // turn_hand_out_of_body's to free; taken from a deeper pick, the reference humanoid's fist
  // beside the far side below the waist went 7.6 -> 8.0 mm with the palm still 78 degrees off)
  // and a touch on its target (within 5 mm, or no further off than the pick), and the
  // cheapest of those by the same cost wins: the elbow's comfort is traded for the wrist's
  // orientation only where a human arm can realise it. Bounded: the grid's 19 candidates,
  // once (those already scored over 10 degrees off not again), only for a key pose's own solve (ArmTarget::seek_orientation_acceptance) that the pick
  // leaves over 10 degrees off. DOG's flat hand
  // patting the thigh, fingers down and palm in (the project avatar): at the comfortable swivel
  // the wrist is at its ulnar limit, 14 degrees off; with the elbow swung out, exact.
  // (Scored apart from the pick: a cheaper pose elsewhere on the grid is not taken for its
  // cost alone, or hands the search leaves as they were would get a new pick.)
  const float reach_ok = std::max(0.005f, best.reach_error_m + 0.001f);
  ArmPose within, p;
  float within_cost = 1e30f;
  for (int i = 0; i < kSwivelCandidates; ++i) {
    if (missed[i]) continue;
    const float cost = score(lo + kSwivelStep * static_cast<float>(i), &p);
    if (p.orientation_error_rad > kOrientationAcceptanceRad || p.body_cost > best.body_cost + 1e-4f ||
        p.trunk_depth_m > std::min(best.trunk_depth_m + 1e-4f, 0.002f) ||
        (t.hand_contact && p.reach_error_m > reach_ok) || p.reach_error_m > best.reach_error_m + 0.01f ||
        cost >= within_cost)
      continue;
    within_cost = cost;
    within = p;
  }
  return within_cost < 1e30f ? within : best;
}

// The innermost live ArmSolveMemo on this thread (null: solve_arm remembers nothing).
thread_local ArmSolveMemo* active_memo = nullptr;
// Its table (solve_at, outside the memo's friends, reads it here).
thread_local ArmSolveMemo::Table* active_table = nullptr;

// A flat open-addressing table of remembered results keyed on input bits (entries in the order
// added, slots holding entry indices).
template <std::size_t kWords, typename Value>
struct FlatMemoTable {
  using Key = std::array<std::uint32_t, kWords>;
  struct Entry {
    Key key;
    Value value;
  };
  std::vector<Entry> entries;
  std::vector<std::uint32_t> hashes;  // per entry, checked before the key
  std::vector<std::int32_t> slots;    // entry index or -1; a power of two, at most half full
  std::size_t hits = 0;

  static std::uint32_t hash_of(const Key& k) {
    std::uint32_t h = 2166136261u;  // FNV-1a over the words
    for (std::uint32_t w : k) h = (h ^ w) * 16777619u;
    return h;
  }

  void clear() {
    entries.clear();
    hashes.clear();
    if (slots.empty()) slots.assign(256, -1);
    else std::fill(slots.begin(), slots.end(), -1);
    hits = 0;
  }

  // The remembered value for `key`, or null.
  const Value* find(const Key& key, std::uint32_t h) const {
    const std::size_t mask = slots.size() - 1;
    for (std::size_t i = h & mask;; i = (i + 1) & mask) {
      const std::int32_t e = slots[i];
      if (e < 0) return nullptr;
      const std::size_t at = static_cast<std::size_t>(e);
      if (hashes[at] == h && entries[at].key == key) return &entries[at].value;
    }
  }

  // A key find() did not know.
  void add(const Key& key, std::uint32_t h, const Value& value) {
    if (2 * (entries.size() + 1) > slots.size()) {
      std::vector<std::int32_t> bigger(2 * slots.size(), -1);
      const std::size_t mask = bigger.size() - 1;
      for (std::size_t e = 0; e < hashes.size(); ++e) {
        std::size_t i = hashes[e] & mask;
        while (bigger[i] >= 0) i = (i + 1) & mask;
        bigger[i] = static_cast<std::int32_t>(e);
      }
      slots.swap(bigger);
    }
    const std::size_t mask = slots.size() - 1;
    std::size_t i = h & mask;
    while (slots[i] >= 0) i = (i + 1) & mask;
    slots[i] = static_cast<std::int32_t>(entries.size());
    entries.push_back(Entry{key, value});
    hashes.push_back(h);
  }
};

// Writes the inputs' bits into a key, in order.
struct KeyWriter {
  unsigned char* out;
  void put(const void* p, std::size_t n) {
    std::memcpy(out, p, n);
    out += n;
  }
};

}  // namespace

// Every input of a free solve, as bits (so -0 and +0, or two NaNs, are told apart only by
// being different bits: a miss, solved as before). A flat open-addressing table, not a node per
// pose: the node allocations and the map's bookkeeping were most of the memo's own cost (about
// 12 M instructions of the lexicon's 1.6 G). A table outlives its memo on a spare list of the
// thread, emptied and reused by the next memo (the next sign), so its storage is allocated once,
// not per sign.
//
// `at` remembers solve_at (one swivel's fixed-point solve) for free solves too: solve_arm's
// callers ask the same target again with only the body, the touch flag, the near swivel or the
// search flags changed, which solve_at does not read, so its swivels' solves repeat (speed-key's
// count: 1,657 of the lexicon's 25,381 solve_at calls, right-handed). Its key is every input
// solve_at reads without ArmTarget::previous: the rig, the side, the point, the contact offset,
// the requested orientation, the wrist motion and the swivel (max_wrist_step_rad,
// start_at_previous_wrist and previous_wrist are read only with `previous`, which is never
// remembered).
struct ArmSolveMemo::Table {
  FlatMemoTable<24, ArmPose> solves;
  FlatMemoTable<18, Solved> at;

  void clear() {
    solves.clear();
    at.clear();
  }

  static FlatMemoTable<24, ArmPose>::Key key_of(const Rig& rig, Side side, const ArmTarget& t) {
    FlatMemoTable<24, ArmPose>::Key k{};
    KeyWriter w{reinterpret_cast<unsigned char*>(k.data())};
    const Rig* rig_ptr = &rig;
    const BodyModel* body = t.body;
    const std::uint32_t flags = static_cast<std::uint32_t>(side) | (t.auto_swivel ? 1u << 8 : 0u) |
                                (t.hand_contact ? 1u << 9 : 0u) | (t.has_near_swivel ? 1u << 10 : 0u) |
                                (t.seek_orientation_acceptance ? 1u << 11 : 0u) |
                                (t.start_at_previous_wrist ? 1u << 12 : 0u) |
                                // A solve in one swivel zero is never answered with the other's
                                // (docs/SYNTHESIS.md swivel-choice), whatever the rig's address.
                                (rig.fixed_handed_swivel_zero ? 1u << 13 : 0u) |
                                (static_cast<std::uint32_t>(rig.protraction_zone & 3) << 14);
    w.put(&rig_ptr, sizeof rig_ptr);
    w.put(&body, sizeof body);
    w.put(&flags, sizeof flags);
    w.put(&t.point, sizeof t.point);
    w.put(&t.contact_offset, sizeof t.contact_offset);
    w.put(&t.hand_delta, sizeof t.hand_delta);
    w.put(&t.wrist_motion, sizeof t.wrist_motion);
    w.put(&t.swivel_rad, sizeof t.swivel_rad);
    w.put(&t.near_swivel_rad, sizeof t.near_swivel_rad);
    w.put(&t.max_wrist_step_rad, sizeof t.max_wrist_step_rad);
    return k;
  }

  static FlatMemoTable<18, Solved>::Key at_key_of(const Rig& rig, Side side, const ArmTarget& t, float swivel) {
    FlatMemoTable<18, Solved>::Key k{};
    KeyWriter w{reinterpret_cast<unsigned char*>(k.data())};
    const Rig* rig_ptr = &rig;
    // The side, and the swivel zero the chain is solved in (as key_of's flags).
    const std::uint32_t s = static_cast<std::uint32_t>(side) | (rig.fixed_handed_swivel_zero ? 1u << 13 : 0u) |
                            (static_cast<std::uint32_t>(rig.protraction_zone & 3) << 14);
    w.put(&rig_ptr, sizeof rig_ptr);
    w.put(&s, sizeof s);
    w.put(&t.point, sizeof t.point);
    w.put(&t.contact_offset, sizeof t.contact_offset);
    w.put(&t.hand_delta, sizeof t.hand_delta);
    w.put(&t.wrist_motion, sizeof t.wrist_motion);
    w.put(&swivel, sizeof swivel);
    return k;
  }
};

namespace {

// Tables of memos that have ended, kept for the next memo on this thread.
thread_local std::vector<std::unique_ptr<ArmSolveMemo::Table>> spare_tables;

std::unique_ptr<ArmSolveMemo::Table> take_table() {
  std::unique_ptr<ArmSolveMemo::Table> t;
  if (spare_tables.empty()) {
    t = std::make_unique<ArmSolveMemo::Table>();
  } else {
    t = std::move(spare_tables.back());
    spare_tables.pop_back();
  }
  t->clear();
  return t;
}

}  // namespace

ArmSolveMemo::ArmSolveMemo() : table_(take_table()), outer_(active_memo) {
  active_memo = this;
  active_table = table_.get();
}
ArmSolveMemo::~ArmSolveMemo() {
  active_memo = outer_;
  active_table = outer_ ? outer_->table_.get() : nullptr;
  spare_tables.push_back(std::move(table_));
}
std::size_t ArmSolveMemo::hits() const { return table_->solves.hits; }
std::size_t ArmSolveMemo::swivel_solve_hits() const { return table_->at.hits; }

namespace {

Solved solve_at(const Rig& rig, Side side, const ArmTarget& t, float swivel) {
  if (!active_table || t.previous) return solve_at_uncached(rig, side, t, swivel);
  auto& table = active_table->at;
  const auto key = ArmSolveMemo::Table::at_key_of(rig, side, t, swivel);
  const std::uint32_t h = table.hash_of(key);
  if (const Solved* found = table.find(key, h)) {
    ++table.hits;
    return *found;
  }
  const Solved s = solve_at_uncached(rig, side, t, swivel);
  table.add(key, h, s);
  return s;
}

}  // namespace

ArmPose solve_arm(const Rig& rig, Side side, const ArmTarget& t) {
  // A solve continuing a path (t.previous) reads the previous pose too: not remembered.
  if (!active_memo || t.previous) return solve_arm_uncached(rig, side, t);
  auto& table = active_memo->table_->solves;
  const auto key = ArmSolveMemo::Table::key_of(rig, side, t);
  const std::uint32_t h = table.hash_of(key);
  if (const ArmPose* found = table.find(key, h)) {
    ++table.hits;
    return *found;
  }
  const ArmPose pose = solve_arm_uncached(rig, side, t);
  table.add(key, h, pose);
  return pose;
}

namespace {

// The turns of the hand about its contact point shared by turn_hand_out_of_body and
// turn_hand_to_reach. `must_reach`: a turn frees the pose only if the touch then reaches (5 mm).
bool turn_about_contact(const Rig& rig, Side side, ArmTarget* t, ArmPose* pose, bool must_reach) {
  // Two ways to swing the wrist out about the contact point: along the deepest segment's way
  // out of the trunk, and forward (away from the body, which also brings an elbow from behind
  // the body to its side).
  const glm::vec3 contact_to_wrist = -(t->hand_delta * t->contact_offset);
  glm::vec3 axes[2];
  int n_axes = 0;
  for (const glm::vec3& out : {pose->trunk_push_dir, rig.forward}) {
    glm::vec3 axis = glm::cross(contact_to_wrist, out);
    if (glm::length(axis) > 1e-5f) axes[n_axes++] = glm::normalize(axis);
  }
  // Scored against the REQUESTED orientation; a pose that leaves the arm in conflict pays a
  // flat 1.0 (a third of a radian) on top of its body cost: breaking the 5 mm rule weighs more
  // than the last few degrees of orientation.
  auto score = [&](const ArmPose& p) {
    return 3.0f * rotation_angle(glm::conjugate(t->hand_delta) * p.hand) + 20.0f * p.reach_error_m +
           (t->hand_contact ? 300.0f * std::max(0.0f, p.reach_error_m - 0.005f) : 0.0f) + p.body_cost +
           (p.body_cost > 0.03f ? 1.0f : 0.0f);
  };
  ArmTarget turned = *t;
  turned.has_near_swivel = false;
  ArmPose best = *pose;
  float best_score = score(*pose);
  glm::quat best_delta = t->hand_delta;
  // The smallest turn (15 degree steps, up to 120) that frees the arm and scores better than not
  // turning wins outright: a clear criterion, where comparing scores alone would let near-equal
  // alternatives flip with the compiler's rounding. Failing that, the best-scoring turn.
  bool freed = false;
  for (int k = 1; k <= 8 && !freed; ++k) {
    for (int i = 0; i < n_axes && !freed; ++i) {
      turned.hand_delta = axis_angle(axes[i], 0.26f * static_cast<float>(k)) * t->hand_delta;
      ArmPose p = solve_arm(rig, side, turned);
      if (p.reach_error_m > pose->reach_error_m + 0.002f) continue;  // a touch must still touch
      float sc = score(p);
      if (p.body_cost <= 0.03f && (!must_reach || p.reach_error_m <= 0.005f) && sc < score(*pose)) {
        freed = true;
      } else if (!(sc < best_score - 1e-3f)) {
        continue;
      }
      best_score = sc;
      best = p;
      best_delta = turned.hand_delta;
    }
  }
  if (best_delta == t->hand_delta) return false;
  t->hand_delta = best_delta;
  *pose = best;
  return true;
}

}  // namespace

bool turn_hand_out_of_body(const Rig& rig, Side side, ArmTarget* t, ArmPose* pose) {
  if (!t->body || !arm_in_body_conflict(*pose)) return false;  // only for a real conflict
  return turn_about_contact(rig, side, t, pose, false);
}

bool turn_hand_to_reach(const Rig& rig, Side side, ArmTarget* t, ArmPose* pose) {
  // Only a touch that misses by more than the 5 mm the swivel search already allows, and only
  // when the wrist target the requested orientation puts the wrist at is closer to the shoulder
  // joint than the folded arm reaches (the elbow's flexion limit; a target beyond the stretched
  // arm is not brought nearer by turning the hand).
  if (!t->hand_contact || pose->reach_error_m <= 0.005f) return false;
  const ArmRig& a = rig.arms[side];
  const float folded = chain_bind(rig, side).d_min;
  const glm::vec3 wrist_target = t->point - t->hand_delta * t->contact_offset;
  // (Measured from the upper arm's bind position: the clavicle's shrug moves it a centimetre.)
  if (glm::length(wrist_target - rig.bind_pos[a.upper]) >= folded + 0.01f) return false;
  return turn_about_contact(rig, side, t, pose, true);
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

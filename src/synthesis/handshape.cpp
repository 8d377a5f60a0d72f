// Handshape: per-finger states (seed 004 eq. 4) -> joint angles -> finger FK; thumb-contact IK.
#include "synthesis/handshape.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace sw::synthesis {
namespace {

constexpr float kDeg = 3.14159265358979f / 180.0f;

float clampf(float v, FingerLimits l) { return std::min(l.hi, std::max(l.lo, v)); }

FingerAngles finger_deg(float mcp, float pip, float dip, float abd = 0.0f) {
  return FingerAngles{mcp * kDeg, pip * kDeg, dip * kDeg, abd * kDeg};
}
ThumbAngles thumb_deg(float cf, float ca, float op, float mcp, float ip) {
  return ThumbAngles{cf * kDeg, ca * kDeg, op * kDeg, mcp * kDeg, ip * kDeg};
}

FingerAngles lerp(const FingerAngles& a, const FingerAngles& b, float t) {
  return FingerAngles{a.mcp_flex + t * (b.mcp_flex - a.mcp_flex),
                      a.pip_flex + t * (b.pip_flex - a.pip_flex),
                      a.dip_flex + t * (b.dip_flex - a.dip_flex),
                      a.abduction + t * (b.abduction - a.abduction)};
}
ThumbAngles lerp(const ThumbAngles& a, const ThumbAngles& b, float t) {
  return ThumbAngles{a.cmc_flex + t * (b.cmc_flex - a.cmc_flex), a.cmc_abd + t * (b.cmc_abd - a.cmc_abd),
                     a.opposition + t * (b.opposition - a.opposition),
                     a.mcp_flex + t * (b.mcp_flex - a.mcp_flex), a.ip_flex + t * (b.ip_flex - a.ip_flex)};
}

// Spread fan (degrees of abduction per finger at spread = 1): the index moves radially, the middle
// stays nearly put, ring and little move ulnarly — the way a hand opens.
constexpr float kFanDeg[4] = {15.0f, 3.0f, -11.0f, -24.0f};
// Flexed fingers converge towards the palm's middle (they point at the scaphoid when flexed): a
// radial tilt of the flexion plane moves a curled finger's tip ulnarly (it lies behind the
// knuckle), so the index tilts radially and the little finger ulnarly, scaled by the PIP flexion.
constexpr float kConvergeDeg[4] = {12.0f, 4.0f, -4.0f, -12.0f};

// Begin/end states of the finger configurations (seed eq. 4: t interpolates begin -> end).
// Config 0 is the seed's pressed (t=0) -> straight (t=1); other configs go straight -> state.
void finger_states(int id, int finger, FingerAngles* beg, FingerAngles* end) {
  FingerAngles straight = finger_deg(0, 0, 0);
  *beg = straight;
  switch (id) {
    case notation::kFingerPressedToStraight: *beg = finger_deg(90, 100, 65); *end = straight; return;
    case notation::kFingerHorizontal: *end = finger_deg(90, 0, 0); return;
    case notation::kFingerSpread: *end = finger_deg(0, 0, 0, kFanDeg[finger]); return;
    case notation::kFingerCrossed:  // the middle finger crosses over the straight index
      *end = finger == 1 ? finger_deg(8, 0, 0, 20) : finger_deg(0, 0, 0, 0); return;
    case notation::kFingerRound: *end = finger_deg(45, 55, 30); return;
    case notation::kFingerHooked: *end = finger_deg(0, 95, 70); return;
    case notation::kFingerDoubleBent: *end = finger_deg(85, 95, 10); return;
    case notation::kFingerDoubleHooked: *end = finger_deg(60, 105, 80); return;
    default: *end = straight; return;
  }
}

void thumb_states(int id, ThumbAngles* beg, ThumbAngles* end) {
  ThumbAngles alongside = thumb_deg(15, 0, 0, 0, 0);
  *beg = alongside;
  switch (id) {
    case notation::kThumbPressedToStraight: *beg = thumb_deg(35, 30, 40, 30, 20); *end = alongside; return;
    case notation::kThumbAgainstPalm: *end = thumb_deg(55, 15, 30, 20, 15); return;
    case notation::kThumbOut: *end = thumb_deg(-35, 5, 0, 0, 0); return;
    case notation::kThumbAcross: *end = thumb_deg(45, 35, 45, 35, 25); return;
    case notation::kThumbOpposed: *end = thumb_deg(5, 55, 45, 10, 10); return;
    case notation::kThumbPadOnIndex:
    case notation::kThumbOnMiddle:
    case notation::kThumbOnRing:
    case notation::kThumbOnLittle: *end = thumb_deg(25, 45, 50, 20, 20); return;
    default: *end = alongside; return;
  }
}

// Finger geometry measured once per call from the bind pose (hand-relative, hand delta identity).
struct FingerGeom {
  glm::vec3 p[4];       // joint positions b0, b1, b2, tip (bind)
  glm::vec3 d0, s0, kb; // bind bone direction, its palmar normal, flexion axis
  float flex_bind[3];
};

FingerGeom finger_geom(const Rig& rig, Side side, int f) {
  const ArmRig& a = rig.arms[side];
  const FingerChain& c = a.fingers[f];
  FingerGeom g;
  for (int i = 0; i < 3; ++i) g.p[i] = rig.bind_pos[c.bones[i]];
  g.p[3] = rig.bind_tip(side, f);
  glm::vec3 n = a.palm_normal;
  g.d0 = safe_normalize(g.p[1] - g.p[0], a.finger_dir);
  g.s0 = safe_normalize(reject(n, g.d0), n);
  g.kb = glm::normalize(glm::cross(g.d0, g.s0));
  g.flex_bind[0] = 0.0f;
  glm::vec3 prev = g.d0;
  for (int i = 1; i < 3; ++i) {
    glm::vec3 d = safe_normalize(g.p[i + 1] - g.p[i], prev);
    g.flex_bind[i] = std::atan2(glm::dot(glm::cross(prev, d), g.kb), glm::dot(prev, d));
    prev = d;
  }
  return g;
}

// The finger and thumb kinematics are templates on the scalar: float to pose, double inside the
// thumb solver. Why double there: the solve's end point moves with the rounding of the chain's
// positions (float: ~1e-8 m, amplified ~500x along the directions only the prior holds), and
// glibc's and musl's sinf/cosf round differently, which left native and WASM 5.8e-6 rad apart —
// inside the 1e-5 parity tolerance, but with little room. In double the difference is ~1e-13.
template <typename T> using Vec3 = glm::vec<3, T, glm::defaultp>;
template <typename T> using Quat = glm::qua<T, glm::defaultp>;

// rig.h's axis_angle, safe_normalize and frame_to_frame for any scalar (same formulas).
template <typename T>
Quat<T> axis_angle_t(const Vec3<T>& unit_axis, T angle_rad) {
  T h = T(0.5) * angle_rad, s = std::sin(h);
  return Quat<T>(std::cos(h), unit_axis.x * s, unit_axis.y * s, unit_axis.z * s);
}
template <typename T>
Vec3<T> safe_normalize_t(const Vec3<T>& v, const Vec3<T>& fallback) {
  T len = glm::length(v);
  return len > T(1e-6) ? v / len : fallback;
}
template <typename T>
Quat<T> frame_to_frame_t(const Vec3<T>& a0, const Vec3<T>& b0, const Vec3<T>& a1, const Vec3<T>& b1) {
  auto basis = [](const Vec3<T>& a, const Vec3<T>& b) {
    Vec3<T> x = safe_normalize_t(a, Vec3<T>(1, 0, 0));
    Vec3<T> helper = std::fabs(x.y) < T(0.9) ? Vec3<T>(0, 1, 0) : Vec3<T>(1, 0, 0);
    Vec3<T> y = safe_normalize_t(b - glm::dot(b, x) * x,
                                 safe_normalize_t(helper - glm::dot(helper, x) * x, Vec3<T>(0, 0, 1)));
    return glm::mat<3, 3, T, glm::defaultp>(x, y, glm::cross(x, y));
  };
  return glm::normalize(glm::quat_cast(basis(a1, b1) * glm::transpose(basis(a0, b0))));
}

// Rotations (relative to the hand, in the bind frame) of a finger's three bones; angles are
// mcp, pip, dip flexion and abduction.
template <typename T>
void finger_rotations_t(const ArmRig& a, const FingerGeom& g, const T fa[4], Quat<T> out[3]) {
  const T mcp = fa[0], pip = fa[1], dip = fa[2], abd = fa[3];
  Vec3<T> n(a.palm_normal);
  Vec3<T> gdir = std::cos(abd) * Vec3<T>(a.finger_dir) + std::sin(abd) * Vec3<T>(a.radial);
  Vec3<T> d0p = std::cos(mcp) * gdir + std::sin(mcp) * n;
  Vec3<T> s0p = -std::sin(mcp) * gdir + std::cos(mcp) * n;
  Vec3<T> kb(g.kb);
  out[0] = frame_to_frame_t(Vec3<T>(g.d0), Vec3<T>(g.s0), d0p, s0p);
  out[1] = out[0] * axis_angle_t(kb, pip - T(g.flex_bind[1]));
  out[2] = out[1] * axis_angle_t(kb, dip - T(g.flex_bind[2]));
}
void finger_rotations(const Rig& rig, Side side, const FingerGeom& g, const FingerAngles& fa,
                      glm::quat out[3]) {
  const float v[4] = {fa.mcp_flex, fa.pip_flex, fa.dip_flex, fa.abduction};
  finger_rotations_t(rig.arms[side], g, v, out);
}

struct ThumbGeom {
  glm::vec3 p[4];
  glm::vec3 u[3];
  glm::quat align;        // bind metacarpal frame -> neutral thumb frame
  glm::vec3 neutral_dir, neutral_pad, kt;
  glm::vec3 flex_axis;    // CMC flexion axis (palm normal, signed)
  float opp_sign;
  glm::quat straighten[3];
};

ThumbGeom thumb_geom(const Rig& rig, Side side) {
  const ArmRig& a = rig.arms[side];
  const FingerChain& c = a.fingers[0];
  ThumbGeom g;
  for (int i = 0; i < 3; ++i) g.p[i] = rig.bind_pos[c.bones[i]];
  g.p[3] = rig.bind_tip(side, 0);
  for (int i = 0; i < 3; ++i) g.u[i] = safe_normalize(g.p[i + 1] - g.p[i], a.finger_dir);
  glm::vec3 n = a.palm_normal;
  // Neutral thumb: in the palm plane, 25 degrees radial of the fingers, pad facing ulnar-palmar.
  const float neutral = 25.0f * kDeg;
  g.neutral_dir = std::cos(neutral) * a.finger_dir + std::sin(neutral) * a.radial;
  glm::vec3 radial_perp = safe_normalize(reject(a.radial, g.neutral_dir), a.radial);
  g.neutral_pad = glm::normalize(0.5f * n - 0.87f * radial_perp);
  glm::vec3 bind_pad = safe_normalize(reject(n - a.radial, g.u[0]), n);
  g.align = frame_to_frame(g.u[0], bind_pad, g.neutral_dir, g.neutral_pad);
  g.kt = glm::normalize(glm::cross(g.neutral_dir, g.neutral_pad));  // flexes towards the pad
  float s = glm::dot(glm::cross(n, g.neutral_dir), -radial_perp) > 0.0f ? 1.0f : -1.0f;
  g.flex_axis = s * n;
  // Opposition turns the pad from ulnar-palmar towards the palm side.
  glm::vec3 probe = axis_angle(g.neutral_dir, 0.1f) * g.neutral_pad;
  g.opp_sign = glm::dot(probe, n) > glm::dot(g.neutral_pad, n) ? 1.0f : -1.0f;
  g.straighten[0] = glm::quat(1, 0, 0, 0);
  for (int i = 1; i < 3; ++i) {
    glm::vec3 from = g.u[i], to = g.u[0];
    float d = glm::dot(from, to);
    glm::vec3 ax = glm::cross(from, to);
    g.straighten[i] = glm::length(ax) < 1e-6f ? glm::quat(1, 0, 0, 0)
                                             : axis_angle(glm::normalize(ax), std::acos(std::min(1.0f, std::max(-1.0f, d))));
  }
  return g;
}

// Thumb bone rotations; angles are cmc_flex, cmc_abd, opposition, mcp, ip.
template <typename T>
void thumb_rotations_t(const ThumbGeom& g, const Vec3<T>& n, const T t[5], Quat<T> out[3]) {
  const Vec3<T> neutral_dir(g.neutral_dir), kt(g.kt);
  const Quat<T> align(g.align);
  Quat<T> flex = axis_angle_t(Vec3<T>(g.flex_axis), t[0]);
  Vec3<T> dir1 = flex * neutral_dir;
  Vec3<T> abd_axis = safe_normalize_t(glm::cross(dir1, n), kt);
  Quat<T> cmc = axis_angle_t(abd_axis, t[1]) * flex * axis_angle_t(neutral_dir, T(g.opp_sign) * t[2]);
  // In the neutral frame the flexion axis is kt; carried by the align rotation back to bind space.
  Quat<T> e0 = cmc * align;
  Vec3<T> kt_bind = glm::conjugate(align) * kt;
  out[0] = e0;
  out[1] = e0 * axis_angle_t(kt_bind, t[3]) * Quat<T>(g.straighten[1]);
  out[2] = e0 * axis_angle_t(kt_bind, t[3] + t[4]) * Quat<T>(g.straighten[2]);
}
void thumb_rotations(const ThumbGeom& g, const glm::vec3& n, const ThumbAngles& t, glm::quat out[3]) {
  const float v[5] = {t.cmc_flex, t.cmc_abd, t.opposition, t.mcp_flex, t.ip_flex};
  thumb_rotations_t(g, n, v, out);
}

// Positions (hand-relative, hand delta identity) of a chain's points given its bone rotations.
template <typename T>
void chain_points(const Vec3<T> bind[4], const Quat<T> rot[3], Vec3<T> out[4]) {
  out[0] = bind[0];
  for (int i = 0; i < 3; ++i) out[i + 1] = out[i] + rot[i] * (bind[i + 1] - bind[i]);
}

// Thumb IK (see solve_handshape). Why not a search with accept/reject steps: the solve used to
// be a coordinate descent that halved its step when no move improved the cost by a 1e-3 margin
// and stopped on a step tolerance. Every one of those choices is a discontinuity: the path (and
// the local minimum it ends in) jumped when the cost moved by one rounding, and the WASM SIMD
// build (where LLVM's SLP vectoriser compiles the inlined cost differently from the out-of-line
// copy that scored the start) ended 0.68 rad away from native (docs/SYNTHESIS.md).
// This solve is a fixed schedule of damped Gauss-Newton (Levenberg-Marquardt) steps with no
// branch on a value: no accept/reject, no early stop, the joint limits applied by a projection
// (a clamp, continuous) after each step. The result is a continuous function of the rig and the
// shape, so a last-bit difference in any build stays a small difference (tested: a 1e-6 change
// of the input moves the pose < 1e-4 rad). Tried and rejected: limits as a one-sided quadratic
// penalty (an unpenalised step past a limit threw the iterates 1000 rad away) and a step-length
// cap with it (it stalled in a local minimum 5 cm from a reachable fingertip).
constexpr int kThumbVars = 6;
// Pull towards the preset angles (per rad^2; for the finger curl per unit of curl). It makes the
// minimum unique (the tip position fixes 3 of the 6 variables), conditions the flat directions
// (opposition barely moves the tip) and keeps the pose near the configured one. J^T J is ~1e-3,
// so the pull costs ~2% of the preset's miss (< 1 mm for a pinch).
constexpr double kThumbPrior = 2e-5;
// Levenberg-Marquardt damping (m^2 per rad^2) on a fixed decreasing schedule, and the iteration
// count. The Jacobian's entries are ~0.02-0.06 m/rad (J^T J ~ 1e-3): 1e-4 damps the first
// steps from a far preset; the damping then falls below the prior (x0.6 a step) so the last
// steps are Gauss-Newton steps that converge along the prior's shallow valley too (with a
// constant damping above the prior, the end point depends on where the path stopped). The
// floor keeps the steps damped where the target is out of reach (a buried fingertip in a fist:
// a large residual, where the Gauss-Newton model is poor).
constexpr double kThumbDamping = 1e-4;
constexpr double kThumbDampingDecay = 0.6;
constexpr double kThumbDampingFloor = 1e-6;
constexpr int kThumbIterations = 40;
// Central-difference step for the Jacobian (rad). The solve runs in double (see Vec3<T>), but
// the step was chosen in float, where the tip's ~1e-8 m rounding put 1e-6 m/rad of noise into
// each difference at 1e-2 (1e-5 at 1e-3, enough to move an unreachable-target solution by 2e-4
// rad); the truncation error (~h^2/6 = 2e-5 relative) is smooth and only biases the path.
constexpr double kJacobianStep = 1e-2;

// Solves A y = b for a symmetric positive definite A by Cholesky: no pivoting, hence no
// data-dependent choice (A = J^T J + damping + prior is positive definite by construction).
void solve_spd(double A[kThumbVars][kThumbVars], const double b[kThumbVars], double y[kThumbVars]) {
  double L[kThumbVars][kThumbVars] = {};
  for (int i = 0; i < kThumbVars; ++i)
    for (int j = 0; j <= i; ++j) {
      double sum = A[i][j];
      for (int k = 0; k < j; ++k) sum -= L[i][k] * L[j][k];
      L[i][j] = i == j ? std::sqrt(std::max(sum, 1e-24)) : sum / L[j][j];
    }
  double z[kThumbVars];
  for (int i = 0; i < kThumbVars; ++i) {
    double sum = b[i];
    for (int k = 0; k < i; ++k) sum -= L[i][k] * z[k];
    z[i] = sum / L[i][i];
  }
  for (int i = kThumbVars - 1; i >= 0; --i) {
    double sum = z[i];
    for (int k = i + 1; k < kThumbVars; ++k) sum -= L[k][i] * y[k];
    y[i] = sum / L[i][i];
  }
}

// Minimises |error(x)|^2 + prior |x - x0|^2 within the bounds; x holds the start and the result.
// error(x) returns two 3-vectors (two points' misses; the contact solve leaves the second zero).
using ThumbError = std::array<glm::dvec3, 2>;
template <typename ErrorFn>
void solve_thumb_lm(const ErrorFn& error, const double x0[kThumbVars],
                    const FingerLimits bounds[kThumbVars], double x[kThumbVars]) {
  double damping = kThumbDamping;
  for (int iter = 0; iter < kThumbIterations; ++iter) {
    ThumbError e = error(x);
    ThumbError J[kThumbVars];
    for (int i = 0; i < kThumbVars; ++i) {
      // The probe may leave the bounds: the kinematics are smooth beyond them, and a one-sided
      // difference at a bound would be a switch.
      double saved = x[i];
      x[i] = saved + kJacobianStep;
      ThumbError plus = error(x);
      x[i] = saved - kJacobianStep;
      ThumbError minus = error(x);
      x[i] = saved;
      for (int k = 0; k < 2; ++k) J[i][k] = (plus[k] - minus[k]) * (0.5 / kJacobianStep);
    }
    double A[kThumbVars][kThumbVars], g[kThumbVars], dx[kThumbVars];
    for (int i = 0; i < kThumbVars; ++i) {
      for (int j = 0; j < kThumbVars; ++j) A[i][j] = glm::dot(J[i][0], J[j][0]) + glm::dot(J[i][1], J[j][1]);
      A[i][i] += damping + kThumbPrior;
      g[i] = -(glm::dot(J[i][0], e[0]) + glm::dot(J[i][1], e[1]) + kThumbPrior * (x[i] - x0[i]));
    }
    solve_spd(A, g, dx);
    for (int i = 0; i < kThumbVars; ++i) x[i] = std::min<double>(bounds[i].hi, std::max<double>(bounds[i].lo, x[i] + dx[i]));
    damping = std::max(kThumbDampingFloor, damping * kThumbDampingDecay);  // the schedule, not a test
  }
}

}  // namespace

const HandLimits& hand_limits() {
  static const HandLimits limits;
  return limits;
}

bool within_limits(const HandAngles& a, float tol) {
  const HandLimits& l = hand_limits();
  auto in = [tol](float v, FingerLimits r) { return v >= r.lo - tol && v <= r.hi + tol; };
  const ThumbAngles& t = a.thumb;
  if (!in(t.cmc_flex, l.cmc_flex) || !in(t.cmc_abd, l.cmc_abd) || !in(t.opposition, l.opposition) ||
      !in(t.mcp_flex, l.thumb_mcp) || !in(t.ip_flex, l.thumb_ip))
    return false;
  for (const auto& f : a.fingers)
    if (!in(f.mcp_flex, l.mcp) || !in(f.pip_flex, l.pip) || !in(f.dip_flex, l.dip) ||
        !in(f.abduction, l.abd))
      return false;
  return true;
}

static void clamp_all(HandAngles* a) {
  const HandLimits& l = hand_limits();
  ThumbAngles& t = a->thumb;
  t.cmc_flex = clampf(t.cmc_flex, l.cmc_flex);
  t.cmc_abd = clampf(t.cmc_abd, l.cmc_abd);
  t.opposition = clampf(t.opposition, l.opposition);
  t.mcp_flex = clampf(t.mcp_flex, l.thumb_mcp);
  t.ip_flex = clampf(t.ip_flex, l.thumb_ip);
  for (auto& f : a->fingers) {
    f.mcp_flex = clampf(f.mcp_flex, l.mcp);
    f.pip_flex = clampf(f.pip_flex, l.pip);
    f.dip_flex = clampf(f.dip_flex, l.dip);
    f.abduction = clampf(f.abduction, l.abd);
  }
}

HandAngles handshape_angles(const notation::HandShape& shape) {
  HandAngles out;
  for (int k = 0; k < notation::kFingerCount; ++k) {
    const notation::FingerConfig& c = shape.fingers[k];
    float t = c.has_t ? std::min(1.0f, std::max(0.0f, c.t)) : 1.0f;
    if (k == 0) {
      ThumbAngles b, e;
      thumb_states(c.id, &b, &e);
      out.thumb = lerp(b, e, t);
      out.thumb.cmc_flex -= 0.35f * std::min(1.0f, std::max(0.0f, c.spread));  // spread opens the thumb
    } else {
      FingerAngles b, e;
      finger_states(c.id, k - 1, &b, &e);
      FingerAngles f = lerp(b, e, t);
      f.abduction += std::min(1.0f, std::max(0.0f, c.spread)) * kFanDeg[k - 1] * kDeg;
      f.abduction += kConvergeDeg[k - 1] * kDeg * std::min(1.0f, f.pip_flex / (100.0f * kDeg));
      out.fingers[k - 1] = f;
    }
  }
  clamp_all(&out);
  return out;
}

int thumb_contact_finger(const notation::HandShape& shape) {
  switch (shape.fingers[0].id) {
    case notation::kThumbPadOnIndex: return 1;
    case notation::kThumbOnMiddle: return 2;
    case notation::kThumbOnRing: return 3;
    case notation::kThumbOnLittle: return 4;
    default: return -1;
  }
}

HandAngles mix(const HandAngles& a, const HandAngles& b, float t) {
  HandAngles out;
  out.thumb = lerp(a.thumb, b.thumb, t);
  for (int i = 0; i < 4; ++i) out.fingers[i] = lerp(a.fingers[i], b.fingers[i], t);
  return out;
}

glm::vec3 bind_palm_centre(const Rig& rig, Side side) {
  const ArmRig& a = rig.arms[side];
  glm::vec3 knuckles(0.0f);
  for (int f = 1; f < 5; ++f) knuckles += 0.25f * rig.bind_pos[a.fingers[f].bones[0]];
  // The palm starts a little distal of the wrist joint (the carpus), so its middle lies 58% of
  // the way from the wrist joint to the knuckles.
  glm::vec3 centre = rig.bind_pos[a.hand] + 0.58f * (knuckles - rig.bind_pos[a.hand]);
  return centre + a.palm_normal * (0.17f * a.palm_width_m);  // half the palm's thickness
}

namespace {

// The finger and thumb geometry pose_fingers poses with, remembered: it is a function of the bind
// pose alone (the chains' points, the hand frame), and pose_fingers runs for every posed frame
// (about 18 k times in a lexicon pass), where measuring it again (two atan2 a finger, the thumb's
// frame_to_frame and acos) was a quarter of pose_fingers' instructions. The key is the bits of
// every input finger_geom and thumb_geom read, so a remembered geometry is the one they compute.
constexpr int kHandGeomKeyFloats = (5 * 4 + 3) * 3;
using HandGeomKey = std::array<float, kHandGeomKeyFloats>;

// The bind-pose points both memos key on (hand_geom_key here, thumb_solve_key below): every
// finger chain's bind positions and tip, then the arm's bind hand frame. One list, so a point a
// geometry reads cannot be added to one key and forgotten in the other; `put` takes a vec3.
template <class PutVec>
void put_hand_bind_points(const Rig& rig, Side side, PutVec&& put) {
  const ArmRig& a = rig.arms[side];
  for (int f = 0; f < 5; ++f) {
    for (int i = 0; i < 3; ++i) put(rig.bind_pos[a.fingers[f].bones[i]]);
    put(rig.bind_tip(side, f));
  }
  put(a.finger_dir);
  put(a.palm_normal);
  put(a.radial);
}

HandGeomKey hand_geom_key(const Rig& rig, Side side) {
  HandGeomKey key{};
  int n = 0;
  put_hand_bind_points(rig, side, [&](const glm::vec3& v) {
    for (int k = 0; k < 3; ++k) key[n++] = v[k];
  });
  return key;
}

struct HandGeom {
  HandGeomKey key;
  std::array<FingerGeom, 5> fingers;  // [0] unused: the thumb is `thumb`
  ThumbGeom thumb;
};

const HandGeom& hand_geom(const Rig& rig, Side side) {
  // A page poses one or two rigs, both sides: a few entries; past that many the table starts
  // again (a bound on memory, not a policy the results depend on).
  constexpr size_t kRemembered = 8;
  thread_local std::vector<HandGeom> remembered;
  const HandGeomKey key = hand_geom_key(rig, side);
  for (const HandGeom& g : remembered)
    if (std::memcmp(g.key.data(), key.data(), sizeof key) == 0) return g;
  if (remembered.size() >= kRemembered) remembered.clear();
  HandGeom g;
  g.key = key;
  for (int f = 1; f < 5; ++f) g.fingers[f] = finger_geom(rig, side, f);
  g.thumb = thumb_geom(rig, side);
  remembered.push_back(g);
  return remembered.back();
}

}  // namespace

void pose_fingers(const Rig& rig, Side side, const HandAngles& angles, const glm::quat& hand,
                  PoseBuilder* pose) {
  const ArmRig& a = rig.arms[side];
  const HandGeom& geom = hand_geom(rig, side);
  for (int f = 1; f < 5; ++f) {
    glm::quat r[3];
    finger_rotations(rig, side, geom.fingers[f], angles.fingers[f - 1], r);
    for (int i = 0; i < 3; ++i) pose->set(a.fingers[f].bones[i], hand * r[i]);
  }
  glm::quat r[3];
  thumb_rotations(geom.thumb, a.palm_normal, angles.thumb, r);
  for (int i = 0; i < 3; ++i) pose->set(a.fingers[0].bones[i], hand * r[i]);
}

namespace {

// Thumb across (HamNoSys thumb-across modifier; ASL S, A-variants, B, E, U, V): the thumb lies
// across the front of the curled fingers (S: over the index and middle middle phalanges) or, when
// the fingers are straight or only hooked (B, E), across the palm. The preset angles cannot do
// both — the front of a fist is ~4 cm palmar of the palm — and before this solve the preset put
// the thumb tip 8.8 cm straight out of the palm. So the thumb tip is placed by the thumb IK on a
// target computed from the posed fingers:
//   front_k = middle of finger k's middle phalanx + palm normal x (finger + thumb radius),
//   F = sum w_k front_k / sum w_k with w_k = the finger's knuckle flexion / 90 deg (curled ones),
//   P = on the palm at the ring finger's line, thumb radius above the palm surface,
//   goal = P + min(1, sum w_k) (F - P), and the thumb's IP joint one distal phalanx radial of it
// — every weight continuous, so the pose is continuous in the shape.
ThumbAngles solve_thumb_across(const Rig& rig, Side side, const HandAngles& angles) {
  const ArmRig& a = rig.arms[side];
  const HandLimits& lim = hand_limits();
  const glm::vec3 n = a.palm_normal;
  const float thumb_radius = 1.2f * a.finger_radius_m;  // the thumb is thicker than a finger
  glm::vec3 front_sum(0.0f);
  float weight_sum = 0.0f;
  for (int f = 1; f < 5; ++f) {
    FingerGeom fg = finger_geom(rig, side, f);
    glm::quat fr[3];
    finger_rotations(rig, side, fg, angles.fingers[f - 1], fr);
    glm::vec3 fp[4];
    chain_points(fg.p, fr, fp);
    float w = std::min(1.0f, std::max(0.0f, angles.fingers[f - 1].mcp_flex / (90.0f * kDeg)));
    front_sum += w * (0.5f * (fp[1] + fp[2]) + (a.finger_radius_m + thumb_radius) * n);
    weight_sum += w;
  }
  const glm::vec3 centre = bind_palm_centre(rig, side);
  const glm::vec3 ring_knuckle = rig.bind_pos[a.fingers[3].bones[0]];
  const glm::vec3 on_palm = centre + glm::dot(ring_knuckle - centre, a.radial) * a.radial + thumb_radius * n;
  const float eps = 1e-3f;  // keeps the mean defined (and continuous) when no finger is curled
  const glm::vec3 front = (front_sum + eps * on_palm) / (weight_sum + eps);
  const glm::vec3 goal = on_palm + std::min(1.0f, weight_sum) * (front - on_palm);

  ThumbGeom tg = thumb_geom(rig, side);
  glm::dvec3 thumb_rel[4];
  for (int i = 0; i < 4; ++i) thumb_rel[i] = glm::dvec3(tg.p[i]) - glm::dvec3(tg.p[0]);
  const glm::dvec3 goal_rel = glm::dvec3(goal) - glm::dvec3(tg.p[0]);
  // The distal phalanx lies across the hand too (its IP joint radial of the tip): with the tip
  // alone as the target, the thumb reached the front of the fist from inside it, its distal
  // phalanx 13 mm deep in the middle finger.
  // Only in front of curled fingers (weighted like the goal): on a flat palm (B, E) the thumb
  // cannot fold that far across in the palm plane and the two targets pulled it outwards.
  const glm::dvec3 ip_goal_rel = goal_rel + glm::length(thumb_rel[3] - thumb_rel[2]) * glm::dvec3(a.radial);
  const double in_front = std::min(1.0f, weight_sum);
  ThumbAngles start;
  { ThumbAngles unused; thumb_states(notation::kThumbAcross, &unused, &start); }
  // The sixth variable (a finger curl in the contact solve) is unused here: held at 0.
  const double x0[kThumbVars] = {start.cmc_flex, start.cmc_abd, start.opposition, start.mcp_flex, start.ip_flex, 0.0};
  const FingerLimits bounds[kThumbVars] = {lim.cmc_flex, lim.cmc_abd, lim.opposition, lim.thumb_mcp,
                                           lim.thumb_ip, FingerLimits{0.0f, 0.0f}};
  const glm::dvec3 nd(n);
  auto error = [&](const double* v) {
    glm::dquat tr[3];
    thumb_rotations_t(tg, nd, v, tr);
    glm::dvec3 tp[4];
    chain_points(thumb_rel, tr, tp);
    return ThumbError{tp[3] - goal_rel, in_front * (tp[2] - ip_goal_rel)};
  };
  double x[kThumbVars];
  std::copy(x0, x0 + kThumbVars, x);
  solve_thumb_lm(error, x0, bounds, x);
  return ThumbAngles{static_cast<float>(x[0]), static_cast<float>(x[1]), static_cast<float>(x[2]),
                     static_cast<float>(x[3]), static_cast<float>(x[4])};
}

}  // namespace

static HandAngles solve_handshape_uncached(const Rig& rig, Side side,
                                           const notation::HandShape& shape) {
  HandAngles angles = handshape_angles(shape);
  if (shape.fingers[0].id == notation::kThumbAcross) {
    // F^1(t) across: t blends from the state's begin (alongside) to the solved across pose.
    const notation::FingerConfig& c = shape.fingers[0];
    float t = c.has_t ? std::min(1.0f, std::max(0.0f, c.t)) : 1.0f;
    ThumbAngles beg, end;
    thumb_states(notation::kThumbAcross, &beg, &end);
    ThumbAngles solved = solve_thumb_across(rig, side, angles);
    angles.thumb = lerp(beg, solved, t);
    angles.thumb.cmc_flex -= 0.35f * std::min(1.0f, std::max(0.0f, c.spread));  // as handshape_angles
    clamp_all(&angles);
    return angles;
  }
  int target = thumb_contact_finger(shape);
  if (target < 0) return angles;
  const ArmRig& a = rig.arms[side];
  const HandLimits& lim = hand_limits();
  FingerGeom fg = finger_geom(rig, side, target);
  ThumbGeom tg = thumb_geom(rig, side);
  const FingerAngles configured = angles.fingers[target - 1];
  const FingerAngles curled = finger_deg(50, 60, 35);  // how far the finger may curl to meet it
  // Tips meet as in a pinch: the thumb tip sits just off the target tip on its palmar side (the
  // two pads' skin touching just behind the tip points).
  const float gap = 0.8f * a.finger_radius_m;

  // x = thumb cmc_flex, cmc_abd, opposition, mcp, ip, target finger curl (0 configured, 1 curled).
  const double x0[kThumbVars] = {angles.thumb.cmc_flex, angles.thumb.cmc_abd, angles.thumb.opposition,
                                 angles.thumb.mcp_flex, angles.thumb.ip_flex, 0.0};
  const FingerLimits bounds[kThumbVars] = {lim.cmc_flex, lim.cmc_abd, lim.opposition, lim.thumb_mcp,
                                             lim.thumb_ip, FingerLimits{0.0f, 1.0f}};
  // Contact error (thumb tip minus goal), with the chains measured from the thumb base so that
  // the metre-scale model coordinates do not cost precision in the Jacobian's differences.
  glm::dvec3 thumb_rel[4], finger_rel[4];
  for (int i = 0; i < 4; ++i) {
    thumb_rel[i] = glm::dvec3(tg.p[i]) - glm::dvec3(tg.p[0]);
    finger_rel[i] = glm::dvec3(fg.p[i]) - glm::dvec3(tg.p[0]);
  }
  const glm::dvec3 nd(a.palm_normal), s0(fg.s0);
  const double f_conf[4] = {configured.mcp_flex, configured.pip_flex, configured.dip_flex, configured.abduction};
  const double f_curl[4] = {curled.mcp_flex, curled.pip_flex, curled.dip_flex, curled.abduction};
  auto contact_error = [&](const double* v) {
    double f[4];
    for (int k = 0; k < 4; ++k) f[k] = f_conf[k] + v[5] * (f_curl[k] - f_conf[k]);  // lerp
    glm::dquat tr[3], fr[3];
    thumb_rotations_t(tg, nd, v, tr);
    finger_rotations_t(a, fg, f, fr);
    glm::dvec3 tp[4], fp[4];
    chain_points(thumb_rel, tr, tp);
    chain_points(finger_rel, fr, fp);
    glm::dvec3 pad = fr[2] * s0;  // palmar side of the distal phalanx
    return ThumbError{tp[3] - (fp[3] + double(gap) * pad), glm::dvec3(0.0)};
  };
  double x[kThumbVars];
  std::copy(x0, x0 + kThumbVars, x);
  solve_thumb_lm(contact_error, x0, bounds, x);
  angles.thumb = ThumbAngles{static_cast<float>(x[0]), static_cast<float>(x[1]), static_cast<float>(x[2]),
                             static_cast<float>(x[3]), static_cast<float>(x[4])};
  angles.fingers[target - 1] = lerp(configured, curled, static_cast<float>(x[5]));
  clamp_all(&angles);
  return angles;
}

namespace {

// solve_handshape's thumb solves remembered (issue 4's "under 1 ms per sign"): a thumb-contact or
// thumb-across shape costs a Levenberg-Marquardt solve (40 steps of 13 error evaluations, about
// 0.27 M instructions), and the same few shapes come back in every sign that uses them (a page's
// lexicon, the bench's repeated calls). The key holds the bits of every input the solve reads:
// the arm's bind hand frame (finger_dir, palm_normal, radial), its palm width and finger radius,
// the hand joint's and every finger chain's bind positions and tips, and each finger's
// configuration (id, has_t, t, spread). The solve is a fixed arithmetic on those inputs (no
// state, no branch on anything else), so a remembered result is the one it would compute: the
// clips are unchanged to the bit. Keyed on values, not on the rig's address, a remembered solve
// cannot outlive what it was computed from; the table lives for the thread.
constexpr int kThumbSolveKeyWords = (1 + 5 * 4 + 3) * 3 + 2 + 4 * notation::kFingerCount;
using ThumbSolveKey = std::array<std::uint32_t, kThumbSolveKeyWords>;

ThumbSolveKey thumb_solve_key(const Rig& rig, Side side, const notation::HandShape& shape) {
  ThumbSolveKey key{};
  int n = 0;
  auto put_float = [&](float v) { std::memcpy(&key[n++], &v, sizeof v); };
  auto put_vec = [&](const glm::vec3& v) {
    for (int k = 0; k < 3; ++k) put_float(v[k]);
  };
  const ArmRig& a = rig.arms[side];
  put_vec(rig.bind_pos[a.hand]);
  put_hand_bind_points(rig, side, put_vec);
  put_float(a.palm_width_m);
  put_float(a.finger_radius_m);
  for (const notation::FingerConfig& c : shape.fingers) {
    key[n++] = static_cast<std::uint32_t>(c.id);
    key[n++] = c.has_t ? 1u : 0u;
    put_float(c.t);
    put_float(c.spread);
  }
  return key;
}

struct RememberedThumbSolve {
  std::uint32_t hash;
  ThumbSolveKey key;
  HandAngles angles;
};

// A lexicon uses a few dozen thumb shapes per rig and side; past this many the table starts
// again (a bound on memory for a long-lived page, not a cache policy the results depend on).
constexpr size_t kRememberedThumbSolves = 512;

}  // namespace

HandAngles solve_handshape(const Rig& rig, Side side, const notation::HandShape& shape) {
  if (shape.fingers[0].id != notation::kThumbAcross && thumb_contact_finger(shape) < 0)
    return solve_handshape_uncached(rig, side, shape);  // preset angles: nothing to solve
  thread_local std::vector<RememberedThumbSolve> remembered;
  const ThumbSolveKey key = thumb_solve_key(rig, side, shape);
  std::uint32_t hash = 2166136261u;  // FNV-1a over the key's words
  for (std::uint32_t w : key) hash = (hash ^ w) * 16777619u;
  for (const RememberedThumbSolve& r : remembered)
    if (r.hash == hash && r.key == key) return r.angles;
  if (remembered.size() >= kRememberedThumbSolves) remembered.clear();
  remembered.push_back({hash, key, solve_handshape_uncached(rig, side, shape)});
  return remembered.back().angles;
}

}  // namespace sw::synthesis

// Collision: capsule body from skeleton + mesh extents; hand-sphere penetration queries.
#include "synthesis/collision.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "synthesis/handshape.h"

namespace sw::synthesis {

float segment_distance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  glm::vec3 ab = b - a;
  float len2 = glm::dot(ab, ab);
  float t = len2 > 1e-12f ? std::min(1.0f, std::max(0.0f, glm::dot(p - a, ab) / len2)) : 0.0f;
  return glm::length(p - (a + t * ab));
}

float segment_segment_distance(const glm::vec3& p1, const glm::vec3& q1, const glm::vec3& p2,
                               const glm::vec3& q2, glm::vec3* on1, glm::vec3* on2) {
  // Minimise |(p1 + s d1) - (p2 + t d2)| over s, t in [0, 1]: the unconstrained optimum of s
  // clamped, t from it, and s recomputed whenever t had to be clamped (the distance is convex,
  // so the clamped-then-reprojected pair is the constrained minimum).
  const glm::vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const float a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  constexpr float kTiny = 1e-12f;
  auto clamp01 = [](float v) { return std::min(1.0f, std::max(0.0f, v)); };
  float s = 0.0f, t = 0.0f;
  if (a <= kTiny && e <= kTiny) {
    s = t = 0.0f;
  } else if (a <= kTiny) {
    t = clamp01(f / e);
  } else {
    const float c = glm::dot(d1, r);
    if (e <= kTiny) {
      s = clamp01(-c / a);
    } else {
      const float b = glm::dot(d1, d2);
      const float denom = a * e - b * b;
      // Parallel segments (denom ~ 0): any s gives the same line distance; s = 0 and the
      // clamping below find the closest pair of the overlapping parts.
      s = denom > 1e-7f * a * e ? clamp01((b * f - c * e) / denom) : 0.0f;
      t = (b * s + f) / e;
      if (t < 0.0f) {
        t = 0.0f;
        s = clamp01(-c / a);
      } else if (t > 1.0f) {
        t = 1.0f;
        s = clamp01((b - c) / a);
      }
    }
  }
  const glm::vec3 c1 = p1 + s * d1, c2 = p2 + t * d2;
  if (on1) *on1 = c1;
  if (on2) *on2 = c2;
  return glm::length(c1 - c2);
}

static glm::vec3 closest_on_segment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  glm::vec3 ab = b - a;
  float len2 = glm::dot(ab, ab);
  float t = len2 > 1e-12f ? std::min(1.0f, std::max(0.0f, glm::dot(p - a, ab) / len2)) : 0.0f;
  return a + t * ab;
}

namespace {

// Vertices whose strongest influence is one of `joints` (the skin around those bones).
std::vector<glm::vec3> skin_of(const avatar::Avatar& avatar, const std::vector<int>& joints) {
  std::vector<glm::vec3> out;
  const auto& m = avatar.mesh;
  if (m.weights.size() != m.positions.size() || m.joints.size() != m.positions.size()) return out;
  for (size_t v = 0; v < m.positions.size(); ++v) {
    int best = 0;
    for (int k = 1; k < avatar::kMaxInfluences; ++k)
      if (m.weights[v][k] > m.weights[v][best]) best = k;
    int j = m.joints[v][best];
    if (std::find(joints.begin(), joints.end(), j) != joints.end()) out.push_back(m.positions[v]);
  }
  return out;
}

// The radius that holds `fraction` of the skin points around the segment (robust to outliers).
float percentile_radius(const std::vector<glm::vec3>& pts, const glm::vec3& a, const glm::vec3& b,
                        float fraction, float fallback) {
  if (pts.size() < 16) return fallback;
  std::vector<float> d;
  d.reserve(pts.size());
  for (const auto& p : pts) d.push_back(segment_distance(p, a, b));
  size_t k = std::min(d.size() - 1, static_cast<size_t>(fraction * d.size()));
  std::nth_element(d.begin(), d.begin() + k, d.end());
  return d[k];
}

float percentile_abs(const std::vector<float>& values, float fraction, float fallback) {
  if (values.size() < 16) return fallback;
  std::vector<float> v = values;
  for (auto& x : v) x = std::fabs(x);
  size_t k = std::min(v.size() - 1, static_cast<size_t>(fraction * v.size()));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

}  // namespace

BodyModel build_body_model(const avatar::Avatar& avatar, const Rig& rig) {
  BodyModel body;
  const float w = std::max(0.1f, rig.shoulder_width_m);  // fallback proportions scale with it
  const glm::vec3 hips = rig.bind_pos[rig.hips];
  const glm::vec3 neck = rig.bind_pos[rig.neck];
  const glm::vec3 head = rig.bind_pos[rig.head];
  const int top_joint = rig.upper_chest >= 0 ? rig.upper_chest : (rig.chest >= 0 ? rig.chest : rig.spine);

  for (int s = 0; s < 2; ++s) {
    const ArmRig& a = rig.arms[s];
    glm::vec3 sh = rig.bind_pos[a.upper], el = rig.bind_pos[a.lower], wr = rig.bind_pos[a.hand];
    float ur = percentile_radius(skin_of(avatar, {a.upper}), sh, el, 0.6f, 0.13f * w);
    float fr = percentile_radius(skin_of(avatar, {a.lower}), el, wr, 0.6f, 0.10f * w);
    body.upper_arm[s] = Capsule{s == kLeft ? "left upper arm" : "right upper arm", a.upper, sh, el, ur};
    body.forearm[s] = Capsule{s == kLeft ? "left forearm" : "right forearm", a.lower, el, wr, fr};
    // The shoulder ball and the deltoid over it: one arm radius out from the joint centre the
    // upper arm is still the shoulder, joined to the torso (see BodyModel).
    body.upper_arm_skip_m[s] = ur;
  }

  // Torso: two capsules side by side (a torso is wider than deep), radius = half the depth.
  std::vector<int> torso_joints = {rig.hips, rig.spine};
  if (rig.chest >= 0) torso_joints.push_back(rig.chest);
  if (rig.upper_chest >= 0) torso_joints.push_back(rig.upper_chest);
  std::vector<glm::vec3> torso_skin = skin_of(avatar, torso_joints);
  // Only the part of the skin between hips and neck (legs/arms weighted to hips are excluded by
  // height and by the lateral cut below).
  std::vector<float> depth, width;
  for (const auto& p : torso_skin) {
    float h = glm::dot(p - hips, rig.up);
    if (h < 0.05f || h > glm::dot(neck - hips, rig.up)) continue;
    float lat = glm::dot(p - hips, rig.left);
    if (std::fabs(lat) > 0.6f * w + 0.05f) continue;
    depth.push_back(glm::dot(p - hips, rig.forward));
    width.push_back(lat);
  }
  float half_depth = percentile_abs(depth, 0.85f, 0.30f * w);
  float half_width = percentile_abs(width, 0.85f, 0.48f * w);
  // The ribcage ends where the hanging upper arm begins: a torso wider than the shoulder joints'
  // half distance minus the upper arm's radius would put a relaxed arm inside the body (the
  // fallback proportions do, on the procedural humanoid: 3.7 cm at rest). Measured skins stay
  // within this bound anyway (the project avatar's 85th percentile is at it).
  float shoulder_half = 0.5f * std::fabs(glm::dot(rig.bind_pos[rig.arms[kLeft].upper] -
                                                  rig.bind_pos[rig.arms[kRight].upper], rig.left));
  half_width = std::min(half_width, std::max(0.05f, shoulder_half - std::max(body.upper_arm[kLeft].radius_m,
                                                                             body.upper_arm[kRight].radius_m)));
  half_depth = std::min(half_depth, half_width);
  float lateral = std::max(0.0f, half_width - half_depth);
  glm::vec3 bottom = hips + rig.up * (0.5f * half_depth);
  glm::vec3 top = neck - rig.up * (0.6f * half_depth);
  for (int s = 0; s < 2; ++s) {
    glm::vec3 off = rig.left * (s == 0 ? lateral : -lateral);
    body.trunk.push_back(Capsule{s == 0 ? "torso left" : "torso right", top_joint, bottom + off, top + off, half_depth});
  }
  // Neck and head.
  std::vector<glm::vec3> neck_skin = skin_of(avatar, {rig.neck});
  float neck_r = percentile_radius(neck_skin, neck, head, 0.7f, 0.16f * w);
  body.trunk.push_back(Capsule{"neck", rig.neck, neck, head, neck_r});
  std::vector<glm::vec3> head_skin = skin_of(avatar, {rig.head});
  float head_height = 0.5f * w;
  if (head_skin.size() >= 16) {
    float hi = 0.0f;
    for (const auto& p : head_skin) hi = std::max(hi, glm::dot(p - head, rig.up));
    head_height = hi;
  }
  // The lower end sits at the head joint, a little forward: with the radius it covers the jaw
  // and chin without swallowing the space in front of the shoulders.
  glm::vec3 head_a = head + rig.forward * (0.12f * head_height);
  glm::vec3 head_b = head + rig.up * (0.5f * head_height);
  float head_r = percentile_radius(head_skin, head_a, head_b, 0.7f, 0.27f * w);
  body.trunk.push_back(Capsule{"head", rig.head, head_a, head_b, head_r});

  const ArmRig& ra = rig.arms[kRight];
  body.hand_sphere_radius_m = ra.finger_radius_m;
  body.palm_sphere_radius_m = 0.3f * ra.palm_width_m;
  // A palm on the body puts the wrist half a palm thickness off the skin; the forearm's last
  // stretch (a forearm radius plus a palm's width) then lies along the same skin.
  body.forearm_contact_skip_m = std::max(body.forearm[kLeft].radius_m, body.forearm[kRight].radius_m) + ra.palm_width_m;
  return body;
}

namespace {

struct Sphere {
  glm::vec3 c;
  float r;
};

int hand_spheres(const BodyModel& body, const PoseBuilder& pose, Side side, Sphere* out) {
  const Rig& rig = *pose.rig;
  const ArmRig& a = rig.arms[side];
  int n = 0;
  // Sphere centres sit inside the hand (palm: on the bone plane; tips: one radius back from the
  // tip point), so a hand whose skin touches a surface does not count as penetrating it.
  const float half_thick = 0.17f * a.palm_width_m;
  glm::vec3 palm_surface = pose.attached(a.hand, bind_palm_centre(rig, side));
  glm::vec3 n_palm = pose.delta(a.hand) * a.palm_normal;
  out[n++] = Sphere{palm_surface - half_thick * n_palm, half_thick};
  const float r = body.hand_sphere_radius_m;
  for (int f = 0; f < 5; ++f) {
    for (int b = f == 0 ? 1 : 0; b < 3; ++b) out[n++] = Sphere{pose.position(a.fingers[f].bones[b]), r};
    glm::vec3 distal = pose.position(a.fingers[f].bones[2]), tip = pose.tip(side, f);
    out[n++] = Sphere{tip - r * safe_normalize(tip - distal, n_palm), r};
  }
  return n;
}

}  // namespace

Penetration hand_penetration(const BodyModel& body, const PoseBuilder& pose, Side side,
                             bool check_trunk, bool check_other_hand) {
  Penetration worst;
  Sphere mine[24];
  int n = hand_spheres(body, pose, side, mine);
  // Bounding sphere of the hand: capsules and the other hand farther than that are skipped
  // (most frames of most signs touch nothing; this keeps the per-frame check cheap).
  glm::vec3 centre(0.0f);
  for (int i = 0; i < n; ++i) centre += mine[i].c;
  centre /= static_cast<float>(n);
  float bound = 0.0f;
  for (int i = 0; i < n; ++i) bound = std::max(bound, glm::length(mine[i].c - centre) + mine[i].r);
  auto consider = [&](const Sphere& s, const glm::vec3& a, const glm::vec3& b, float r,
                      const std::string& what) {
    glm::vec3 q = closest_on_segment(s.c, a, b);
    float d = glm::length(s.c - q);
    float depth = s.r + r - d;
    if (depth > worst.depth_m) {
      worst.depth_m = depth;
      worst.push_dir = safe_normalize(s.c - q, pose.rig->forward);
      worst.what = what;
    }
  };
  if (check_trunk) {
    for (const Capsule& c : body.trunk) {
      glm::vec3 a = pose.attached(c.joint, c.a), b = pose.attached(c.joint, c.b);
      if (segment_distance(centre, a, b) > bound + c.radius_m) continue;
      for (int i = 0; i < n; ++i) consider(mine[i], a, b, c.radius_m, c.name);
    }
  }
  if (check_other_hand) {
    Side o = other(side);
    const Capsule& fc = body.forearm[o];
    glm::vec3 fa = pose.attached(fc.joint, fc.a), fb = pose.attached(fc.joint, fc.b);
    if (segment_distance(centre, fa, fb) <= bound + fc.radius_m)
      for (int i = 0; i < n; ++i) consider(mine[i], fa, fb, fc.radius_m, fc.name);
    glm::vec3 other_palm = pose.attached(pose.rig->arms[o].hand, bind_palm_centre(*pose.rig, o));
    if (glm::length(other_palm - centre) <= bound + 0.25f) {  // 0.25 m: more than a hand's reach
      Sphere theirs[24];
      int m = hand_spheres(body, pose, o, theirs);
      // The other hand's bounding sphere: a sphere of mine farther from its centre than its
      // radius plus mine cannot overlap any of theirs (depth <= 0, never kept), so its 21 pair
      // tests are skipped (1e-4 m of slack for rounding). Hands near each other but not
      // touching are most frames of a two-handed sign.
      glm::vec3 their_centre(0.0f);
      for (int j = 0; j < m; ++j) their_centre += theirs[j].c;
      their_centre /= static_cast<float>(m);
      float their_bound = 0.0f;
      for (int j = 0; j < m; ++j)
        their_bound = std::max(their_bound, glm::length(theirs[j].c - their_centre) + theirs[j].r);
      bool from_other_hand = false;
      for (int i = 0; i < n; ++i) {
        if (glm::length(mine[i].c - their_centre) > their_bound + mine[i].r + 1e-4f) continue;
        for (int j = 0; j < m; ++j) {
          float before = worst.depth_m;
          consider(mine[i], theirs[j].c, theirs[j].c, theirs[j].r, "other hand");
          if (worst.depth_m > before) from_other_hand = true;
        }
      }
      // Hands side by side (their centres farther apart than kSideBySide times their mean
      // bounding radius) are parted along the line between their centres: the worst sphere
      // pair's direction jumps from one pair to the next as the hands interleave (fingers past
      // fingers), so successive pushes zig-zag and a hand walks far for a small overlap. Hands
      // closer than that are interlocked or one inside the other's curl, where the centre line
      // does not part them and the worst pair's direction does. 1.1 is measured, not derived
      // (docs/SYNTHESIS.md, centre-push: 1.0 made more signs 20 mm deep, 1.15-1.3 fewer shallower).
      constexpr float kSideBySide = 1.1f;
      if (from_other_hand &&
          glm::length(centre - their_centre) > kSideBySide * 0.5f * (bound + their_bound))
        worst.push_dir = safe_normalize(centre - their_centre, worst.push_dir);
    }
  }
  return worst;
}

float hands_swept_gap(const BodyModel& body, const PoseBuilder& pose, const glm::vec3& dir, float travel_m) {
  Sphere l[24], r[24];
  const int n = hand_spheres(body, pose, kLeft, l), m = hand_spheres(body, pose, kRight, r);
  const glm::vec3 origin(0.0f), sweep = travel_m * dir;
  float gap = std::numeric_limits<float>::infinity();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      // The left sphere's centre relative to the right one's, along the sweep.
      const glm::vec3 at = l[i].c - r[j].c;
      gap = std::min(gap, glm::length(closest_on_segment(origin, at, at + sweep)) - l[i].r - r[j].r);
    }
  // Each hand against the other forearm, which comes along with its own hand. (Not the trunk:
  // a hand on the body at the sign has it exempt, and the waypoints are checked against it.)
  for (int side = 0; side < 2; ++side) {
    const Sphere* mine = side == kLeft ? l : r;
    const int count = side == kLeft ? n : m;
    const glm::vec3 away = side == kLeft ? sweep : -sweep;
    const Capsule& fc = body.forearm[other(static_cast<Side>(side))];
    const glm::vec3 fa = pose.attached(fc.joint, fc.a), fb = pose.attached(fc.joint, fc.b);
    for (int i = 0; i < count; ++i)
      gap = std::min(gap, segment_segment_distance(mine[i].c, mine[i].c + away, fa, fb) - mine[i].r - fc.radius_m);
  }
  return gap;
}

ArmSegments posed_arm(const PoseBuilder& pose, Side side) {
  const ArmRig& a = pose.rig->arms[side];
  return ArmSegments{pose.position(a.upper), pose.position(a.lower), pose.position(a.hand)};
}

namespace {

// The deepest segment-in-capsule overlap so far; names are pointers so that the per-frame check
// builds its message string once, not per capsule pair.
struct Deepest {
  float depth_m = 0.0f;
  glm::vec3 push_dir{0.0f};
  const std::string* segment = nullptr;
  const std::string* into = nullptr;
  Penetration result() const {
    Penetration p;
    p.depth_m = depth_m;
    p.push_dir = push_dir;
    if (segment && into) p.what = *segment + " in " + *into;
    return p;
  }
};

// Segment [a, b] with radius r against capsule [ca, cb] with radius cr: keeps the deepest.
void segment_in_capsule(const glm::vec3& a, const glm::vec3& b, float r, const glm::vec3& ca,
                        const glm::vec3& cb, float cr, const std::string* segment,
                        const std::string* into, const glm::vec3& fallback_dir, Deepest* worst) {
  glm::vec3 on_seg, on_cap;
  float d = segment_segment_distance(a, b, ca, cb, &on_seg, &on_cap);
  float depth = r + cr - d;
  if (depth > worst->depth_m) {
    worst->depth_m = depth;
    worst->push_dir = safe_normalize(on_seg - on_cap, fallback_dir);
    worst->segment = segment;
    worst->into = into;
  }
}

// The parts of an arm that count against the trunk (see BodyModel::upper_arm_skip_m).
void checked_parts(const BodyModel& body, Side side, const ArmSegments& arm, bool hand_contact,
                   glm::vec3* upper_a, glm::vec3* fore_b, bool* upper_checked) {
  glm::vec3 u = arm.elbow - arm.shoulder;
  float lu = glm::length(u);
  float skip = body.upper_arm_skip_m[side];
  *upper_checked = lu > skip + 1e-4f;
  *upper_a = *upper_checked ? arm.shoulder + (skip / lu) * u : arm.elbow;
  glm::vec3 f = arm.wrist - arm.elbow;
  float lf = glm::length(f);
  float fskip = hand_contact ? std::min(body.forearm_contact_skip_m, lf) : 0.0f;
  *fore_b = lf > 1e-6f ? arm.wrist - (fskip / lf) * f : arm.wrist;
}

}  // namespace

Penetration arm_penetration(const BodyModel& body, const PoseBuilder& pose, Side side,
                            bool check_trunk, bool hand_contact, bool check_other_forearm) {
  Deepest worst;
  const Rig& rig = *pose.rig;
  const ArmSegments arm = posed_arm(pose, side);
  const Capsule& uc = body.upper_arm[side];
  const Capsule& fc = body.forearm[side];
  if (check_trunk) {
    glm::vec3 upper_a, fore_b;
    bool upper_checked = false;
    checked_parts(body, side, arm, hand_contact, &upper_a, &fore_b, &upper_checked);
    for (const Capsule& c : body.trunk) {
      glm::vec3 ca = pose.attached(c.joint, c.a), cb = pose.attached(c.joint, c.b);
      if (upper_checked)
        segment_in_capsule(upper_a, arm.elbow, uc.radius_m, ca, cb, c.radius_m, &uc.name, &c.name,
                           rig.forward, &worst);
      segment_in_capsule(arm.elbow, fore_b, fc.radius_m, ca, cb, c.radius_m, &fc.name, &c.name,
                         rig.forward, &worst);
      if (hand_contact)
        segment_in_capsule(fore_b, arm.wrist, 0.0f, ca, cb, c.radius_m, &fc.name, &c.name, rig.forward, &worst);
    }
  }
  if (check_other_forearm) {
    const ArmSegments o = posed_arm(pose, other(side));
    const Capsule& oc = body.forearm[other(side)];
    segment_in_capsule(arm.elbow, arm.wrist, fc.radius_m, o.elbow, o.wrist, oc.radius_m, &fc.name,
                       &oc.name, rig.forward, &worst);
  }
  return worst.result();
}

float arm_trunk_depth(const BodyModel& body, Side side, const ArmSegments& arm, bool hand_contact,
                      glm::vec3* push_dir) {
  glm::vec3 upper_a, fore_b;
  bool upper_checked = false;
  checked_parts(body, side, arm, hand_contact, &upper_a, &fore_b, &upper_checked);
  const float ur = body.upper_arm[side].radius_m, fr = body.forearm[side].radius_m;
  Deepest worst;
  for (const Capsule& c : body.trunk) {
    if (upper_checked)
      segment_in_capsule(upper_a, arm.elbow, ur, c.a, c.b, c.radius_m, nullptr, nullptr, glm::vec3(0.0f), &worst);
    segment_in_capsule(arm.elbow, fore_b, fr, c.a, c.b, c.radius_m, nullptr, nullptr, glm::vec3(0.0f), &worst);
    if (hand_contact)
      segment_in_capsule(fore_b, arm.wrist, 0.0f, c.a, c.b, c.radius_m, nullptr, nullptr, glm::vec3(0.0f), &worst);
  }
  if (push_dir) *push_dir = worst.push_dir;
  return worst.depth_m;
}

TrunkCrossing trunk_crossing(const BodyModel& body, const PoseBuilder& pose, const glm::vec3& from,
                             const glm::vec3& to, float allowed_m) {
  // Capsules as segments (a, b) and radii: the trunk's, posed, and the shoulders'.
  constexpr size_t kMax = 10;
  std::array<glm::vec3, kMax> a{}, b{};
  std::array<float, kMax> r{};
  size_t n = 0;
  for (const Capsule& c : body.trunk) {
    if (n == kMax) break;
    a[n] = pose.attached(c.joint, c.a);
    b[n] = pose.attached(c.joint, c.b);
    r[n++] = c.radius_m;
  }
  // The shoulders too: the torso capsules' round tops leave the gap between the neck and each
  // shoulder joint open, and a movement "in" at the shoulders (CHANCE1's, BIRTHDAY5's hamshoulders
  // hamclose hammovei hamtouch) passed over the torso beside the neck and out behind the body, the
  // elbow up behind the head. Each shoulder: the neck's base to the shoulder joint, as thick as
  // the upper arm (joined to the torso there, it is not part of the trunk's collision checks).
  const Rig& rig = *pose.rig;
  for (const Capsule& c : body.trunk) {
    if (c.name != "neck") continue;
    for (int side = 0; side < 2 && n < kMax; ++side) {
      const Capsule& u = body.upper_arm[side];
      if (u.joint < 0 || rig.parent[u.joint] < 0) continue;
      a[n] = pose.attached(c.joint, c.a);
      b[n] = pose.attached(rig.parent[u.joint], u.a);
      r[n++] = u.radius_m;
    }
    break;
  }
  // A point's depth: the deepest capsule's (radius minus axis distance), and which capsule.
  auto depth = [&](const glm::vec3& p, size_t* which) {
    float d = -1.0f;
    for (size_t i = 0; i < n; ++i) {
      const float di = r[i] - segment_distance(p, a[i], b[i]);
      if (di > d) {
        d = di;
        if (which) *which = i;
      }
    }
    return d;
  };
  TrunkCrossing out;
  out.stop = to;
  const float limit = std::max(depth(from, nullptr), 0.0f) + allowed_m;
  // Most lines of most signs pass no capsule that deep anywhere: one segment distance each says so.
  bool near = false;
  for (size_t i = 0; i < n && !near; ++i) near = r[i] - segment_segment_distance(from, to, a[i], b[i]) > limit;
  if (!near) return out;
  // Samples 1 cm or closer along the line (a capsule is 8-20 cm across: none is stepped over),
  // then the crossing bisected to 1 mm.
  const float length = glm::length(to - from);
  const int samples = std::max(1, std::min(64, static_cast<int>(std::ceil(length / 0.01f))));
  float lo = 0.0f;
  for (int k = 1; k <= samples; ++k) {
    const float s = static_cast<float>(k) / samples;
    size_t which = 0;
    if (depth(from + s * (to - from), &which) <= limit) {
      lo = s;
      continue;
    }
    // Through: `to` on the far side of the capsule's axis from `from` (more than 105 degrees
    // round it). A line from one place on the body to another round it (DEAF's ear to the mouth,
    // 90 degrees round the head) cuts the capsule's chord but does not go through.
    const glm::vec3 axis_from = closest_on_segment(from, a[which], b[which]);
    const glm::vec3 axis_to = closest_on_segment(to, a[which], b[which]);
    out.through = glm::dot(safe_normalize(from - axis_from, rig.forward), safe_normalize(to - axis_to, rig.forward)) <
                  -0.25f;
    float hi = s;
    while ((hi - lo) * length > 0.001f) {
      const float mid = 0.5f * (lo + hi);
      (depth(from + mid * (to - from), nullptr) <= limit ? lo : hi) = mid;
    }
    out.stop = from + lo * (to - from);
    return out;
  }
  return out;
}

}  // namespace sw::synthesis

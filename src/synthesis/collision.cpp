// Collision: capsule body from skeleton + mesh extents; hand-sphere penetration queries.
#include "synthesis/collision.h"

#include <algorithm>
#include <cmath>

#include "synthesis/handshape.h"

namespace sw::synthesis {

float segment_distance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  glm::vec3 ab = b - a;
  float len2 = glm::dot(ab, ab);
  float t = len2 > 1e-12f ? std::min(1.0f, std::max(0.0f, glm::dot(p - a, ab) / len2)) : 0.0f;
  return glm::length(p - (a + t * ab));
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

  for (int s = 0; s < 2; ++s) {
    const ArmRig& a = rig.arms[s];
    glm::vec3 sh = rig.bind_pos[a.upper], el = rig.bind_pos[a.lower], wr = rig.bind_pos[a.hand];
    float ur = percentile_radius(skin_of(avatar, {a.upper}), sh, el, 0.6f, 0.13f * w);
    float fr = percentile_radius(skin_of(avatar, {a.lower}), el, wr, 0.6f, 0.10f * w);
    body.upper_arm[s] = Capsule{s == kLeft ? "left upper arm" : "right upper arm", a.upper, sh, el, ur};
    body.forearm[s] = Capsule{s == kLeft ? "left forearm" : "right forearm", a.lower, el, wr, fr};
  }
  const ArmRig& ra = rig.arms[kRight];
  body.hand_sphere_radius_m = ra.finger_radius_m;
  body.palm_sphere_radius_m = 0.3f * ra.palm_width_m;
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
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) consider(mine[i], theirs[j].c, theirs[j].c, theirs[j].r, "other hand");
    }
  }
  return worst;
}

}  // namespace sw::synthesis

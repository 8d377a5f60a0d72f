// Implicit body: the primitives of every body part (anthropometric sizes, metres) and the field
// evaluation. See implicit_body.h for the blending tree.
#include "implicit_body.h"

#include <algorithm>
#include <cmath>

namespace sw::avatar_generator {

namespace {

constexpr float kFar = 1e9f;

// Polynomial smooth minimum (Quilez): equals min(a, b) wherever |a - b| >= k, so a blend never
// reaches farther than k from where two surfaces meet.
float smooth_min(float a, float b, float k) {
  if (k <= 0.0f) return std::min(a, b);
  const float h = std::max(k - std::fabs(a - b), 0.0f) / k;
  return std::min(a, b) - h * h * k * 0.25f;
}

float smooth_max(float a, float b, float k) { return -smooth_min(-a, -b, k); }

float dot2(glm::vec3 v) { return glm::dot(v, v); }

// Round cone (a sphere of radius r1 at a swept to radius r2 at b), exact distance (Quilez).
float round_cone(glm::vec3 p, glm::vec3 a, glm::vec3 b, float r1, float r2) {
  const glm::vec3 ba = b - a;
  const float l2 = glm::dot(ba, ba);
  const float rr = r1 - r2;
  const float a2 = l2 - rr * rr;
  const float il2 = 1.0f / l2;
  const glm::vec3 pa = p - a;
  const float y = glm::dot(pa, ba);
  const float z = y - l2;
  const float x2 = dot2(pa * l2 - ba * y);
  const float y2 = y * y * l2;
  const float z2 = z * z * l2;
  const float k = (rr > 0 ? 1.0f : (rr < 0 ? -1.0f : 0.0f)) * rr * rr * x2;
  if ((z > 0 ? 1.0f : (z < 0 ? -1.0f : 0.0f)) * a2 * z2 > k) return std::sqrt(x2 + z2) * il2 - r2;
  if ((y > 0 ? 1.0f : (y < 0 ? -1.0f : 0.0f)) * a2 * y2 < k) return std::sqrt(x2 + y2) * il2 - r1;
  return (std::sqrt(x2 * a2 * il2) + y * rr) * il2 - r1;
}

// Ellipsoid, the usual first-order distance estimate (Quilez): exact on the surface.
float ellipsoid(glm::vec3 p, glm::vec3 centre, glm::vec3 radii) {
  const glm::vec3 q = p - centre;
  const float k0 = glm::length(q / radii);
  const float k1 = glm::length(q / (radii * radii));
  if (k1 < 1e-12f) return -std::min(radii.x, std::min(radii.y, radii.z));
  return k0 * (k0 - 1.0f) / k1;
}

}  // namespace

int ImplicitBody::add_part(const std::string& name, int parent, float blend_k, float inner_k) {
  parts_.push_back({name, parent, blend_k, inner_k});
  cull_margin_ = std::max(cull_margin_, std::max(blend_k, inner_k));
  return static_cast<int>(parts_.size()) - 1;
}

void ImplicitBody::add(ImplicitPrimitive primitive) {
  if (primitive.kind == ImplicitPrimitive::Kind::kRoundCone) {
    const float r = std::max(primitive.radius_a, primitive.radius_b);
    primitive.box_min = glm::min(primitive.a, primitive.b) - glm::vec3(r);
    primitive.box_max = glm::max(primitive.a, primitive.b) + glm::vec3(r);
  } else {
    primitive.box_min = primitive.a - primitive.radii;
    primitive.box_max = primitive.a + primitive.radii;
  }
  if (!primitive.carve) {
    bounds_min_ = glm::min(bounds_min_, primitive.box_min);
    bounds_max_ = glm::max(bounds_max_, primitive.box_max);
  }
  cull_margin_ = std::max(cull_margin_, primitive.carve_k);
  primitives_.push_back(primitive);
}

ImplicitBody::ImplicitBody(const HumanoidLayout& layout) : layout_(layout) {
  auto J = [&](const std::string& name) { return layout.position(name); };
  auto cone = [&](int part, glm::vec3 a, glm::vec3 b, float ra, float rb, Surface s,
                  float squash = 1.0f, glm::vec3 squash_axis = {0, 1, 0}) {
    ImplicitPrimitive p;
    p.kind = ImplicitPrimitive::Kind::kRoundCone;
    p.a = a;
    p.b = b;
    p.radius_a = ra;
    p.radius_b = rb;
    p.squash = squash;
    p.squash_axis = squash_axis;
    p.part = part;
    p.surface = s;
    add(p);
  };
  auto blob = [&](int part, glm::vec3 centre, glm::vec3 radii, Surface s) {
    ImplicitPrimitive p;
    p.kind = ImplicitPrimitive::Kind::kEllipsoid;
    p.a = centre;
    p.radii = radii;
    p.part = part;
    p.surface = s;
    add(p);
  };
  auto carve = [&](int part, glm::vec3 centre, glm::vec3 radii, float k, Surface s) {
    ImplicitPrimitive p;
    p.kind = ImplicitPrimitive::Kind::kEllipsoid;
    p.a = centre;
    p.radii = radii;
    p.part = part;
    p.carve = true;
    p.carve_k = k;
    p.surface = s;
    add(p);
  };

  // Trunk: pelvis, belly, rib cage, shoulder girdle (chest depth 0.22 m, shoulder breadth 0.38 m).
  const int torso = add_part("torso", -1, 0.0f, 0.06f);
  blob(torso, {0.0f, 0.950f, -0.008f}, {0.160f, 0.105f, 0.105f}, Surface::kTrousers);
  blob(torso, {0.0f, 1.070f, 0.000f}, {0.135f, 0.110f, 0.098f}, Surface::kTop);
  blob(torso, {0.0f, 1.235f, 0.000f}, {0.150f, 0.150f, 0.105f}, Surface::kTop);
  cone(torso, {-0.130f, 1.360f, -0.015f}, {0.130f, 1.360f, -0.015f}, 0.058f, 0.058f, Surface::kTop);
  for (float side : {1.0f, -1.0f}) {
    blob(torso, {side * 0.070f, 0.900f, -0.055f}, {0.085f, 0.095f, 0.070f}, Surface::kTrousers);
    blob(torso, {side * 0.060f, 1.270f, 0.040f}, {0.070f, 0.060f, 0.060f}, Surface::kTop);
  }

  // Neck and head: head height chin-to-vertex 0.23 m, breadth 0.15 m, depth 0.195 m.
  const int neck_part = add_part("neck", torso, 0.035f, 0.02f);
  cone(neck_part, {0.0f, 1.380f, -0.018f}, {0.0f, 1.560f, -0.008f}, 0.058f, 0.054f, Surface::kSkin);
  const int head_part = add_part("head", neck_part, 0.03f, 0.03f);
  blob(head_part, {0.0f, 1.612f, -0.012f}, {0.075f, 0.094f, 0.096f}, Surface::kSkin);
  blob(head_part, {0.0f, 1.585f, 0.020f}, {0.068f, 0.080f, 0.076f}, Surface::kSkin);
  // Mandible: a jaw ellipsoid and the chin; both follow the jaw bone.
  blob(head_part, {0.0f, 1.526f, 0.030f}, {0.056f, 0.036f, 0.060f}, Surface::kSkin);
  blob(head_part, {0.0f, 1.496f, 0.076f}, {0.019f, 0.015f, 0.014f}, Surface::kSkin);
  // Forehead: keeps the brow-to-hairline profile near vertical instead of sloping back.
  blob(head_part, {0.0f, 1.648f, 0.018f}, {0.066f, 0.048f, 0.072f}, Surface::kSkin);
  for (float side : {1.0f, -1.0f}) {
    // cheek bones and the soft cheeks
    blob(head_part, {side * 0.046f, 1.585f, 0.066f}, {0.024f, 0.018f, 0.022f}, Surface::kSkin);
    blob(head_part, {side * 0.040f, 1.550f, 0.060f}, {0.026f, 0.026f, 0.022f}, Surface::kSkin);
  }
  // Ears: flat discs at the sides, centred at eye-to-nose height.
  const int ear_part = add_part("ears", head_part, 0.006f, 0.004f);
  for (float side : {1.0f, -1.0f}) {
    blob(ear_part, {side * 0.076f, 1.585f, -0.008f}, {0.010f, 0.030f, 0.019f}, Surface::kSkin);
  }
  // Nose: bridge to tip, nostril wings.
  const int nose_part = add_part("nose", head_part, 0.010f, 0.008f);
  cone(nose_part, {0.0f, 1.606f, 0.090f}, {0.0f, 1.566f, 0.116f}, 0.0070f, 0.0105f, Surface::kSkin);
  for (float side : {1.0f, -1.0f})
    blob(nose_part, {side * 0.0125f, 1.563f, 0.101f}, {0.0076f, 0.0068f, 0.0078f}, Surface::kSkin);
  // Brow ridges: slight, so the brows catch the light.
  const int brow_part = add_part("brows", head_part, 0.010f, 0.006f);
  for (float side : {1.0f, -1.0f})
    cone(brow_part, {side * 0.013f, 1.622f, 0.091f}, {side * 0.052f, 1.628f, 0.073f}, 0.0052f,
         0.0038f, Surface::kBrows);
  // Lips: upper and lower lip as curved chains of round cones meeting at the mouth corners.
  const int lips_part = add_part("lips", head_part, 0.006f, 0.004f);
  const float mouth_y = kMouthY;
  for (float side : {1.0f, -1.0f}) {
    cone(lips_part, {0.0f, mouth_y + 0.0042f, 0.0985f}, {side * 0.013f, mouth_y + 0.0036f, 0.0960f},
         0.0048f, 0.0040f, Surface::kLips);
    cone(lips_part, {side * 0.013f, mouth_y + 0.0036f, 0.0960f},
         {side * 0.0235f, mouth_y + 0.0004f, 0.0880f}, 0.0040f, 0.0022f, Surface::kLips);
    cone(lips_part, {0.0f, mouth_y - 0.0048f, 0.0965f}, {side * 0.013f, mouth_y - 0.0042f, 0.0940f},
         0.0054f, 0.0046f, Surface::kLips);
    cone(lips_part, {side * 0.013f, mouth_y - 0.0042f, 0.0940f},
         {side * 0.0235f, mouth_y - 0.0004f, 0.0880f}, 0.0046f, 0.0022f, Surface::kLips);
  }
  // The mouth slit: a thin pocket between the lips, 5 cm wide, 3 cm deep; its walls are the dark
  // inner mouth that shows when the jaw opens.
  carve(head_part, {0.0f, mouth_y, 0.082f}, {0.0225f, 0.0014f, 0.030f}, 0.0012f,
        Surface::kMouthInner);
  // The mouth cavity behind the lips, joined to the slit: room for the teeth and the tongue,
  // hidden while the lips are together.
  carve(head_part, {0.0f, mouth_y - 0.0005f, 0.060f}, {0.0190f, 0.0105f, 0.0200f}, 0.003f,
        Surface::kMouthInner);
  // Eyelids: a skin shell hugging each eyeball (1.2 mm outside it), opened by an almond slit that
  // shows the eyeball (a separate mesh on the eye joint). The slit's rim is the lid margin;
  // the blink morph rotates the upper shell about the eye centre (face_morphs.cpp).
  const int lid_part = add_part("eyelids", head_part, 0.006f, 0.0f);
  for (float side : {1.0f, -1.0f}) {
    const glm::vec3 eye = J(side > 0 ? "leftEye" : "rightEye");
    blob(lid_part, eye, glm::vec3(kEyelidRadius), Surface::kSkin);
    carve(head_part, eye + glm::vec3(side * 0.0008f, 0.0f, 0.0125f), {0.0145f, 0.0062f, 0.0085f},
          0.0012f, Surface::kSkin);
  }
  // Hair: a cap over the cranium, a little fuller at the back.
  const int hair_part = add_part("hair", head_part, 0.010f, 0.02f);
  blob(hair_part, {0.0f, 1.628f, -0.020f}, {0.080f, 0.088f, 0.098f}, Surface::kHair);

  // Arms and hands.
  for (int s = 0; s < 2; ++s) {
    const std::string p = s == 0 ? "left" : "right";
    const float side = s == 0 ? 1.0f : -1.0f;
    auto H = [&](glm::vec3 v) { return J(p + "Hand") + glm::vec3(side * v.x, v.y, v.z); };
    const int arm = add_part(p + "Arm", torso, 0.045f, 0.035f);
    // Deltoid: caps the joint without rising above the acromion (about 4 cm over the joint).
    blob(arm, J(p + "UpperArm") + glm::vec3(side * -0.004f, -0.004f, 0.0f),
         {0.058f, 0.046f, 0.054f}, Surface::kTop);
    cone(arm, J(p + "UpperArm"), J(p + "LowerArm"), 0.046f, 0.037f, Surface::kTop);
    // Forearm: muscular near the elbow, flattened at the wrist (wrist 56 mm wide, 38 mm deep).
    cone(arm, J(p + "LowerArm"), J(p + "LowerArm") + glm::vec3(side * 0.09f, 0.0f, 0.0f), 0.040f,
         0.038f, Surface::kTop, 0.85f);
    cone(arm, J(p + "LowerArm") + glm::vec3(side * 0.09f, 0.0f, 0.0f), J(p + "Hand"), 0.038f,
         0.027f, Surface::kTop, 0.70f);

    // Palm: metacarpal rays flattened into a plate 28 mm thick, plus thenar/hypothenar pads.
    const int palm = add_part(p + "Palm", arm, 0.014f, 0.012f);
    for (int f = 1; f < 5; ++f) {
      const std::string finger = p + kFingerNames[f];
      cone(palm, J(finger + "Metacarpal") + glm::vec3(side * -0.008f, -0.003f, 0.0f),
           J(finger + "Proximal"), 0.0135f, 0.0105f - 0.0004f * f, Surface::kSkin, 0.62f);
    }
    blob(palm, H({0.035f, -0.007f, 0.019f}), {0.030f, 0.012f, 0.017f}, Surface::kSkin);
    blob(palm, H({0.045f, -0.006f, -0.022f}), {0.034f, 0.010f, 0.013f}, Surface::kSkin);
    blob(palm, H({0.010f, 0.000f, 0.000f}), {0.022f, 0.015f, 0.026f}, Surface::kSkin);

    // Fingers: radii taper from the proximal phalanx to the tip (index 16 mm wide at the base).
    const float base_radius[5] = {0.0100f, 0.0082f, 0.0084f, 0.0080f, 0.0070f};
    for (int f = 0; f < 5; ++f) {
      const std::string finger = p + kFingerNames[f];
      const int part = add_part(finger, palm, f == 0 ? 0.012f : 0.007f, 0.003f);
      const char* const segments[4] = {f == 0 ? "Metacarpal" : "Proximal",
                                       f == 0 ? "Proximal" : "Intermediate", "Distal", "Tip"};
      const float r0 = base_radius[f];
      // The thumb's metacarpal is part of the flesh too (the thenar web); the other metacarpals
      // are inside the palm plate.
      const float radii[4] = {f == 0 ? 0.0130f : r0, f == 0 ? r0 : r0 * 0.93f,
                              f == 0 ? r0 * 0.93f : r0 * 0.87f, r0 * 0.80f};
      for (int seg = 0; seg < 3; ++seg) {
        const std::string from = finger + segments[seg];
        const std::string to =
            (seg == 2) ? p + kFingerNames[f] + "Tip" : finger + segments[seg + 1];
        glm::vec3 end = J(to);
        // The tip joint is the end of the flesh: keep the cone's cap inside it.
        if (seg == 2) end -= glm::normalize(J(to) - J(from)) * radii[3];
        cone(part, J(from), end, radii[seg], radii[seg + 1], Surface::kSkin);
      }
    }
  }

  // Legs and feet (shoes).
  for (int s = 0; s < 2; ++s) {
    const std::string p = s == 0 ? "left" : "right";
    const float side = s == 0 ? 1.0f : -1.0f;
    const int leg = add_part(p + "Leg", torso, 0.05f, 0.04f);
    cone(leg, J(p + "UpperLeg") + glm::vec3(0.0f, 0.03f, -0.005f), J(p + "LowerLeg"), 0.082f,
         0.052f, Surface::kTrousers);
    cone(leg, J(p + "LowerLeg"), J(p + "Foot"), 0.050f, 0.034f, Surface::kTrousers);
    blob(leg, J(p + "LowerLeg") + glm::vec3(side * 0.004f, -0.11f, -0.022f),
         {0.048f, 0.10f, 0.046f}, Surface::kTrousers);
    const int shoe = add_part(p + "Foot", leg, 0.025f, 0.03f);
    const glm::vec3 ankle = J(p + "Foot");
    cone(shoe, ankle + glm::vec3(0.0f, -0.035f, -0.045f),
         J(p + "Toes") + glm::vec3(0, 0.008f, 0.0f), 0.040f, 0.038f, Surface::kShoes, 0.72f,
         {0, 1, 0});
    cone(shoe, J(p + "Toes") + glm::vec3(0, 0.008f, 0.0f),
         J(p + "Toes") + glm::vec3(side * -0.005f, 0.006f, 0.050f), 0.036f, 0.030f, Surface::kShoes,
         0.62f, {0, 1, 0});
  }
}

float ImplicitBody::primitive_distance(const ImplicitPrimitive& q, glm::vec3 p) const {
  if (q.kind == ImplicitPrimitive::Kind::kEllipsoid) return ellipsoid(p, q.a, q.radii);
  if (q.squash == 1.0f) return round_cone(p, q.a, q.b, q.radius_a, q.radius_b);
  // Squashed cross-section: scale the offset along the squash axis (made perpendicular to the
  // cone axis) before measuring; the result is scaled back conservatively.
  const glm::vec3 axis = glm::normalize(q.b - q.a);
  glm::vec3 across = q.squash_axis - axis * glm::dot(q.squash_axis, axis);
  across = glm::normalize(across);
  const glm::vec3 pa = p - q.a;
  const glm::vec3 scaled = pa + across * (glm::dot(pa, across) * (1.0f / q.squash - 1.0f));
  return round_cone(q.a + scaled, q.a, q.b, q.radius_a, q.radius_b) * q.squash;
}

SurfaceSample ImplicitBody::sample(glm::vec3 p) const {
  std::vector<int> all(primitives_.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return sample(p, all);
}

SurfaceSample ImplicitBody::sample(glm::vec3 p, const std::vector<int>& active) const {
  // Small fixed-size scratch: the avatar has a few dozen parts and a handful of carves.
  constexpr int kMaxParts = 64;
  constexpr int kMaxCarves = 8;
  float own[kMaxParts];
  const int part_count = static_cast<int>(parts_.size());
  for (int i = 0; i < part_count; ++i) own[i] = kFar;
  struct CarveHit {
    int primitive;
    float value;  // -distance: the subtracted field
  };
  CarveHit carves[kMaxCarves];
  int carve_count = 0;
  SurfaceSample result;
  float nearest = kFar;
  for (int index : active) {
    const ImplicitPrimitive& q = primitives_[static_cast<size_t>(index)];
    const float d = primitive_distance(q, p);
    if (q.carve) {
      if (carve_count < kMaxCarves) carves[carve_count++] = {index, -d};
      continue;
    }
    own[q.part] = smooth_min(own[q.part], d, parts_[static_cast<size_t>(q.part)].inner_k);
    if (d < nearest) {
      nearest = d;
      result.nearest_primitive = index;
    }
  }
  // Bottom-up: every part blends with its own parent's primitives only (see header). Carves are
  // subtracted one by one, each with its own smoothing, after the part's children joined it.
  float combined[kMaxParts];
  for (int i = 0; i < part_count; ++i) combined[i] = own[i];
  for (int i = part_count - 1; i >= 0; --i) {
    for (int c = 0; c < carve_count; ++c) {
      const ImplicitPrimitive& q = primitives_[static_cast<size_t>(carves[c].primitive)];
      if (q.part != i) continue;
      // Where the carve shapes the surface, the surface is the carve's (the inside of the mouth).
      if (carves[c].value > combined[i] - q.carve_k) result.nearest_primitive = carves[c].primitive;
      combined[i] = smooth_max(combined[i], carves[c].value, q.carve_k);
    }
    const int parent = parts_[static_cast<size_t>(i)].parent;
    if (parent < 0) continue;
    const float blended =
        smooth_min(own[parent], combined[i], parts_[static_cast<size_t>(i)].blend_k);
    combined[parent] = std::min(combined[parent], blended);
  }
  result.distance = combined[0];
  return result;
}

glm::vec3 ImplicitBody::gradient(glm::vec3 p, const std::vector<int>& active, float step) const {
  glm::vec3 g;
  for (int axis = 0; axis < 3; ++axis) {
    glm::vec3 offset(0.0f);
    offset[axis] = step;
    g[axis] = sample(p + offset, active).distance - sample(p - offset, active).distance;
  }
  const float length = glm::length(g);
  return length > 0.0f ? g / length : glm::vec3(0, 1, 0);
}

std::vector<int> ImplicitBody::primitives_near(glm::vec3 box_min, glm::vec3 box_max,
                                               float margin) const {
  std::vector<int> result;
  for (size_t i = 0; i < primitives_.size(); ++i) {
    const ImplicitPrimitive& q = primitives_[i];
    if (q.box_min.x - margin > box_max.x || q.box_max.x + margin < box_min.x) continue;
    if (q.box_min.y - margin > box_max.y || q.box_max.y + margin < box_min.y) continue;
    if (q.box_min.z - margin > box_max.z || q.box_max.z + margin < box_min.z) continue;
    result.push_back(static_cast<int>(i));
  }
  return result;
}

// Brows and lip red are drawn as bands in the face's front view (x, y), so their edges are
// clean curves whatever primitive happens to be nearest.
static Surface face_colour_at(glm::vec3 p) {
  if (p.z < 0.060f) return Surface::kSkin;
  const float ax = std::fabs(p.x);
  // Brow: from the inner end (13 mm from the midline) arching to the tail (55 mm).
  if (ax > 0.012f && ax < 0.055f && p.z > 0.066f) {
    const float t = (ax - 0.012f) / 0.043f;
    const float centre_y = 1.6225f + 0.0075f * std::sin(t * 2.4f) - 0.002f * t;
    const float half_thickness = 0.0036f - 0.0020f * t * t;
    if (std::fabs(p.y - centre_y) < half_thickness) return Surface::kBrows;
  }
  // Lip red: the vermilion between the lip line and its border, upper with a Cupid's bow.
  const float half_width = 0.0238f;
  if (ax < half_width && p.z > 0.082f) {
    const float u = ax / half_width;
    const float profile = std::sqrt(std::max(0.0f, 1.0f - u * u * u));
    const float bow = 0.0012f * std::exp(-std::pow((ax - 0.0045f) / 0.003f, 2.0f)) -
                      0.0008f * std::exp(-std::pow(ax / 0.002f, 2.0f));
    const float upper = (0.0072f + bow) * profile, lower = 0.0088f * profile;
    if (p.y > kMouthY - lower && p.y < kMouthY + upper) return Surface::kLips;
  }
  return Surface::kSkin;
}

Surface ImplicitBody::surface_at(glm::vec3 p, int nearest_primitive) const {
  if (nearest_primitive < 0) return Surface::kSkin;
  const ImplicitPrimitive& q = primitives_[static_cast<size_t>(nearest_primitive)];
  if (q.carve) return q.surface;  // the walls of the mouth slit, the lid margins
  const std::string& part = parts_[static_cast<size_t>(q.part)].name;
  // Garment lines are planes or simple curves so the edges read as hems, not as blend seams.
  const float waist_y = 1.005f;
  if (part == "torso") {
    if (p.y < waist_y) return Surface::kTrousers;
    return Surface::kTop;
  }
  if (part == "neck") {
    // Crew neckline: lower at the front.
    const float neckline = 1.405f - 0.025f * glm::clamp(p.z / 0.05f, 0.0f, 1.0f);
    return p.y < neckline ? Surface::kTop : Surface::kSkin;
  }
  if (part == "leftArm" || part == "rightArm") {
    const float cuff = layout_.position("leftHand").x - 0.03f;
    return std::fabs(p.x) < cuff ? Surface::kTop : Surface::kSkin;
  }
  if (part == "leftLeg" || part == "rightLeg")
    return p.y > 0.115f ? Surface::kTrousers : Surface::kShoes;
  if (part == "head" || part == "eyelids" || part == "nose") {
    const Surface face = face_colour_at(p);
    if (face != Surface::kSkin) return face;
  }
  if (part == "head" || part == "hair" || part == "ears") {
    // Hairline: high at the forehead, over the ears at the sides, low at the nape.
    const float front = 1.655f, side = 1.625f, back = 1.545f;
    const float side_mix = glm::clamp((std::fabs(p.x) - 0.035f) / 0.035f, 0.0f, 1.0f);
    const float back_mix = glm::clamp((0.02f - p.z) / 0.08f, 0.0f, 1.0f);
    float hairline = glm::mix(front, side, side_mix);
    hairline = glm::mix(hairline, back, back_mix);
    if (part == "ears") return Surface::kSkin;
    if (p.y > hairline) return Surface::kHair;
    if (part == "hair") return p.y > hairline - 0.01f ? Surface::kHair : Surface::kSkin;
    return Surface::kSkin;
  }
  if (part == "brows" || part == "lips") return face_colour_at(p);
  return q.surface;
}

}  // namespace sw::avatar_generator

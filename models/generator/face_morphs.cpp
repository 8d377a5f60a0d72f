// Face morphs; see face_morphs.h. Sizes are millimetre-scale displacements typical of FACS
// action-unit intensity E (maximum) on an adult face.
#include "face_morphs.h"

#include <cmath>

#include "face/channels.h"
#include "face_regions.h"
#include "implicit_body.h"

namespace sw::avatar_generator {

namespace {

constexpr float kDeg = 3.14159265358979f / 180.0f;

float smoothstep(float e0, float e1, float x) {
  const float t = glm::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Anisotropic Gaussian bump around `centre`, only on the front of the face.
float bump(glm::vec3 p, glm::vec3 centre, glm::vec2 sigma_xy) {
  const glm::vec2 d((p.x - centre.x) / sigma_xy.x, (p.y - centre.y) / sigma_xy.y);
  const float depth = smoothstep(centre.z - 0.035f, centre.z - 0.012f, p.z);
  const float value = std::exp(-glm::dot(d, d)) * depth;
  return value < 2e-3f ? 0.0f : value;
}

// Below the hairline nothing moves on the scalp; keeps the face/hair seam closed.
float below_hairline(glm::vec3 p) { return 1.0f - smoothstep(1.632f, 1.648f, p.y); }

glm::vec3 rotate_about_x(glm::vec3 p, glm::vec3 pivot, float angle) {
  const glm::vec3 q = p - pivot;
  const float c = std::cos(angle), s = std::sin(angle);
  return pivot + glm::vec3(q.x, q.y * c - q.z * s, q.y * s + q.z * c);
}

// Eyelids. The lid slit (implicit_body.cpp) spans elevation ±phi_rim(x) on the lid shell; a lid
// vertex rotates about the eye centre's X axis, fully at the margin, fading out towards the brow
// (or the cheek) slowly enough that the lid never folds over itself (rotation slope < 1).
struct LidMotion {
  float upper = 0.0f;  // rotation of the upper lid margin in units of phi_rim (+ = down/closing)
  float lower = 0.0f;  // rotation of the lower lid margin in units of phi_rim (+ = up/closing)
};

glm::vec3 lid_delta(const HumanoidLayout& layout, glm::vec3 p, bool left, LidMotion motion) {
  const glm::vec3 eye = layout.position(left ? "leftEye" : "rightEye");
  const glm::vec3 q = p - eye;
  if ((q.x > 0.0f) != left && std::fabs(q.x) > 0.02f) return glm::vec3(0.0f);
  const float r = glm::length(q);
  const float radial = 1.0f - smoothstep(0.0150f, 0.0225f, r);
  if (radial <= 0.0f) return glm::vec3(0.0f);
  const float half_width = 0.0145f, half_height = 0.0062f;  // the slit in implicit_body.cpp
  const float lateral = glm::clamp(q.x / half_width, -1.0f, 1.0f);
  const float rim_height = half_height * std::sqrt(std::max(0.0f, 1.0f - lateral * lateral));
  const float phi_rim = std::asin(glm::clamp(rim_height / kEyelidRadius, 0.0f, 1.0f));
  const float phi = std::atan2(q.y, q.z);  // elevation about the eye's X axis, 0 = gaze
  float angle = 0.0f;
  if (phi >= 0.0f) {
    const float falloff = 1.0f - smoothstep(phi_rim + 4.0f * kDeg, 110.0f * kDeg, phi);
    angle = motion.upper * phi_rim * falloff;  // positive = downwards (towards -y)
  } else {
    const float falloff = 1.0f - smoothstep(phi_rim + 4.0f * kDeg, 80.0f * kDeg, -phi);
    angle = -motion.lower * phi_rim * falloff;
  }
  angle *= radial;
  // A right-handed rotation about +X by +a turns +Z towards -Y: positive closes the upper lid.
  return rotate_about_x(p, eye, angle) - p;
}

// Lip regions.
float upper_lip(glm::vec3 p) {
  return bump(p, {0.0f, kMouthY + 0.006f, 0.100f}, {0.024f, 0.011f}) * (1.0f - below_lip_line(p));
}
float lower_lip(glm::vec3 p) {
  return bump(p, {0.0f, kMouthY - 0.007f, 0.098f}, {0.024f, 0.012f}) * below_lip_line(p);
}
float lips(glm::vec3 p) { return bump(p, {0.0f, kMouthY, 0.097f}, {0.026f, 0.014f}); }
float corner(glm::vec3 p, float side) {
  return bump(p, {side * 0.025f, kMouthY, 0.090f}, {0.016f, 0.014f});
}

glm::vec3 jaw_open(const HumanoidLayout& layout, glm::vec3 p, Material material, float amount) {
  // 0.30 rad opens about 28 mm between the incisors (hinge to lips about 95 mm). Teeth and
  // tongue are rigid: all of the lower row and the tongue turn with the jaw, the upper row not.
  const bool rigid = material == Material::kTongue || material == Material::kTeeth;
  const float mask = rigid ? (p.y < kMouthY ? 1.0f : 0.0f) : jaw_mask(p);
  const float angle = 0.30f * amount * mask;
  return rotate_about_x(p, layout.position("jaw"), angle) - p;
}

// The mouth shapes the visemes are made of, at full weight.
glm::vec3 pucker(glm::vec3 p) {
  const float m = lips(p);
  return m * glm::vec3(-0.35f * p.x, -0.25f * (p.y - kMouthY), 0.008f);
}
glm::vec3 stretch(glm::vec3 p) {
  return corner(p, 1.0f) * glm::vec3(0.006f, -0.0015f, -0.002f) +
         corner(p, -1.0f) * glm::vec3(-0.006f, -0.0015f, -0.002f);
}
glm::vec3 press(glm::vec3 p) {
  return upper_lip(p) * glm::vec3(0.0f, -0.0012f, -0.0015f) +
         lower_lip(p) * glm::vec3(0.0f, 0.0012f, -0.0015f);
}
glm::vec3 smile(glm::vec3 p, float side) {
  return corner(p, side) * glm::vec3(side * 0.006f, 0.005f, -0.003f) +
         bump(p, {side * 0.040f, 1.560f, 0.080f}, {0.018f, 0.018f}) *
             glm::vec3(side * 0.001f, 0.002f, 0.0015f);
}
glm::vec3 upper_up(glm::vec3 p) { return upper_lip(p) * glm::vec3(0.0f, 0.003f, 0.001f); }
glm::vec3 lower_down(glm::vec3 p) { return lower_lip(p) * glm::vec3(0.0f, -0.004f, 0.0008f); }
// Teeth on lip (F, V): the lower lip rolls up and back under the upper incisors.
glm::vec3 lip_tuck(glm::vec3 p) { return lower_lip(p) * glm::vec3(0.0f, 0.0025f, -0.0045f); }
glm::vec3 tongue_out(glm::vec3 p, Material material) {
  if (material != Material::kTongue) return glm::vec3(0.0f);
  // The tip travels furthest; the root stays.
  const float along = smoothstep(0.045f, 0.095f, p.z);
  return glm::vec3(0.0f, 0.002f, 0.024f) * (0.4f + 0.6f * along);
}

struct MouthMix {
  float jaw = 0, pucker = 0, stretch = 0, press = 0, smile = 0, upper_up = 0, lower_down = 0,
        tuck = 0, tongue = 0;
};

glm::vec3 mouth(const HumanoidLayout& layout, glm::vec3 p, Material material, const MouthMix& m) {
  glm::vec3 d = jaw_open(layout, p, material, m.jaw);
  if (material == Material::kTeeth) return d;
  d += m.pucker * pucker(p) + m.stretch * stretch(p) + m.press * press(p) +
       m.smile * 0.5f * (smile(p, 1.0f) + smile(p, -1.0f)) + m.upper_up * upper_up(p) +
       m.lower_down * lower_down(p) + m.tuck * lip_tuck(p) + m.tongue * tongue_out(p, material);
  return d;
}

}  // namespace

std::vector<std::string> face_morph_names() {
  std::vector<std::string> names;
  for (std::string_view n : face::kExpressionChannels) names.emplace_back(n);
  for (std::string_view n : face::kVisemeChannels) names.emplace_back(n);
  return names;
}

glm::vec3 face_morph_delta(const HumanoidLayout& layout, int channel, glm::vec3 p,
                           Material material) {
  if (!in_face_region(p)) return glm::vec3(0.0f);
  const std::string name = face_morph_names()[static_cast<size_t>(channel)];
  const bool rigid = material == Material::kTongue || material == Material::kTeeth;
  if (rigid && name != "tongueOut" && name.rfind("viseme_", 0) != 0 && name != "jawOpen")
    return glm::vec3(0.0f);
  const float hair = below_hairline(p);
  auto side_of = [&](const std::string& n) {
    return n.find("Right") != std::string::npos ? -1.0f : 1.0f;
  };

  if (name == "browInnerUp") {
    const float m = bump(p, {0.016f, 1.626f, 0.092f}, {0.014f, 0.014f}) +
                    bump(p, {-0.016f, 1.626f, 0.092f}, {0.014f, 0.014f});
    return std::min(m, 1.0f) * hair * glm::vec3(0.0f, 0.006f, 0.0005f);
  }
  if (name == "browDownLeft" || name == "browDownRight") {
    const float s = side_of(name);
    const float m = bump(p, {s * 0.026f, 1.625f, 0.090f}, {0.020f, 0.014f});
    return m * hair * glm::vec3(-s * 0.002f, -0.005f, 0.001f);
  }
  if (name == "browOuterUpLeft" || name == "browOuterUpRight") {
    const float s = side_of(name);
    return bump(p, {s * 0.046f, 1.628f, 0.078f}, {0.015f, 0.014f}) * hair *
           glm::vec3(0.0f, 0.006f, 0.0f);
  }
  if (name == "eyeBlinkLeft" || name == "eyeBlinkRight")
    return lid_delta(layout, p, name == "eyeBlinkLeft", {1.68f, 0.35f});
  if (name == "eyeSquintLeft" || name == "eyeSquintRight") {
    const float s = side_of(name);
    return lid_delta(layout, p, s > 0, {0.15f, 0.55f}) +
           bump(p, {s * 0.034f, 1.585f, 0.085f}, {0.016f, 0.008f}) * glm::vec3(0, 0.0015f, 0.0005f);
  }
  if (name == "eyeWideLeft" || name == "eyeWideRight")
    return lid_delta(layout, p, name == "eyeWideLeft", {-0.45f, -0.12f});
  if (name == "cheekSquintLeft" || name == "cheekSquintRight") {
    const float s = side_of(name);
    return bump(p, {s * 0.040f, 1.572f, 0.080f}, {0.018f, 0.016f}) *
               glm::vec3(0.0f, 0.003f, 0.0015f) +
           lid_delta(layout, p, s > 0, {0.0f, 0.25f});
  }
  if (name == "noseSneerLeft" || name == "noseSneerRight") {
    const float s = side_of(name);
    return bump(p, {s * 0.013f, 1.572f, 0.100f}, {0.011f, 0.014f}) *
           glm::vec3(s * 0.0005f, 0.0035f, -0.0005f);
  }
  if (name == "mouthUpperUp") return upper_up(p);
  if (name == "mouthSmileLeft" || name == "mouthSmileRight") return smile(p, side_of(name));
  if (name == "mouthFrownLeft" || name == "mouthFrownRight") {
    const float s = side_of(name);
    return corner(p, s) * glm::vec3(s * 0.001f, -0.005f, -0.001f);
  }
  if (name == "mouthStretch") return stretch(p);
  if (name == "mouthPucker") return pucker(p);
  if (name == "mouthPress") return press(p);
  if (name == "mouthLowerDown") return lower_down(p);
  if (name == "jawOpen") return jaw_open(layout, p, material, 1.0f);
  if (name == "tongueOut") return tongue_out(p, material);

  // Visemes (Oculus set): mixes of the mouth shapes above.
  MouthMix m;
  if (name == "viseme_sil") {
    m.press = 0.5f;
  }  // rest: lips lightly together
  else if (name == "viseme_PP") {
    m.press = 1.0f;
    m.pucker = 0.15f;
  } else if (name == "viseme_FF") {
    m.jaw = 0.08f;
    m.tuck = 1.0f;
    m.upper_up = 0.35f;
  } else if (name == "viseme_TH") {
    m.jaw = 0.18f;
    m.tongue = 0.45f;
    m.stretch = 0.15f;
  } else if (name == "viseme_DD") {
    m.jaw = 0.25f;
    m.stretch = 0.25f;
  } else if (name == "viseme_kk") {
    m.jaw = 0.32f;
    m.stretch = 0.3f;
  } else if (name == "viseme_CH") {
    m.jaw = 0.15f;
    m.pucker = 0.55f;
    m.upper_up = 0.35f;
  } else if (name == "viseme_SS") {
    m.jaw = 0.1f;
    m.stretch = 0.5f;
    m.smile = 0.25f;
  } else if (name == "viseme_nn") {
    m.jaw = 0.2f;
    m.stretch = 0.15f;
  } else if (name == "viseme_RR") {
    m.jaw = 0.2f;
    m.pucker = 0.45f;
  } else if (name == "viseme_aa") {
    m.jaw = 0.75f;
    m.lower_down = 0.3f;
  } else if (name == "viseme_E") {
    m.jaw = 0.35f;
    m.stretch = 0.55f;
    m.upper_up = 0.2f;
  } else if (name == "viseme_I") {
    m.jaw = 0.2f;
    m.stretch = 0.7f;
    m.smile = 0.3f;
  } else if (name == "viseme_O") {
    m.jaw = 0.5f;
    m.pucker = 0.8f;
  } else if (name == "viseme_U") {
    m.jaw = 0.18f;
    m.pucker = 1.0f;
  }
  return mouth(layout, p, material, m);
}

}  // namespace sw::avatar_generator

// Humanoid layout: anthropometric joint positions of the Signweave avatar (see humanoid_layout.h
// for the bind-pose convention). Figures are adult averages rounded to millimetres: stature
// 1.70 m, hip joint at 0.53 of stature, knee at 0.285, upper arm 0.285 m,
// forearm 0.25 m, shoulder joint 1.39 m, hand 0.19 m (wrist centre to middle fingertip), hand
// breadth at the knuckles about 0.08 m, phalanx ratios proximal : intermediate : distal about 1 :
// 0.6 : 0.48.
#include "humanoid_layout.h"

#include <cmath>
#include <stdexcept>

namespace sw::avatar_generator {

int HumanoidLayout::find(const std::string& name) const {
  for (size_t i = 0; i < joints.size(); ++i)
    if (joints[i].name == name) return static_cast<int>(i);
  return -1;
}

const LayoutJoint& HumanoidLayout::at(const std::string& name) const {
  const int index = find(name);
  if (index < 0) throw std::runtime_error("humanoid layout has no joint named " + name);
  return joints[static_cast<size_t>(index)];
}

namespace {

struct Builder {
  HumanoidLayout layout;
  int add(const std::string& name, const std::string& parent, glm::vec3 position,
          bool deforming = true) {
    const int parent_index = parent.empty() ? -1 : layout.find(parent);
    if (!parent.empty() && parent_index < 0)
      throw std::runtime_error("layout parent missing: " + parent);
    layout.joints.push_back({name, parent_index, position, deforming});
    return static_cast<int>(layout.joints.size()) - 1;
  }
};

// One finger in the hand frame of the LEFT hand (along = +X from the wrist, front = +Z, up = +Y).
struct FingerSpec {
  const char* name;
  glm::vec3 metacarpal_base;  // carpometacarpal joint
  glm::vec3 knuckle;          // metacarpophalangeal joint (thumb: its CMC->MCP is "metacarpal")
  float fan_rad;              // angle of the straight finger in the palm plane, + towards the thumb
  float proximal_m, intermediate_m, distal_m;  // joint-to-joint, distal = joint to fingertip
};

// Fingers fan slightly apart in a relaxed flat hand (about 4° between neighbours), which also
// keeps the polygonised fingers clearly separated.
constexpr FingerSpec kFingers[4] = {
    {"Index", {0.022f, 0.004f, 0.014f}, {0.090f, 0.003f, 0.0275f}, 0.07f, 0.040f, 0.023f, 0.019f},
    {"Middle", {0.022f, 0.006f, 0.004f}, {0.094f, 0.004f, 0.0085f}, 0.0f, 0.046f, 0.028f, 0.022f},
    {"Ring", {0.020f, 0.005f, -0.007f}, {0.089f, 0.002f, -0.0105f}, -0.07f, 0.042f, 0.026f, 0.020f},
    {"Little",
     {0.018f, 0.002f, -0.017f},
     {0.080f, -0.002f, -0.0285f},
     -0.15f,
     0.033f,
     0.019f,
     0.018f},
};

}  // namespace

HumanoidLayout make_signweave_layout() {
  Builder b;
  // Trunk and head: the spine runs up the body's mid-plane.
  b.add("hips", "", {0.0f, 0.960f, 0.000f});
  b.add("spine", "hips", {0.0f, 1.040f, 0.000f});
  b.add("chest", "spine", {0.0f, 1.160f, 0.000f});
  b.add("upperChest", "chest", {0.0f, 1.280f, -0.005f});
  b.add("neck", "upperChest", {0.0f, 1.440f, -0.012f});
  b.add("head", "neck", {0.0f, 1.530f, -0.005f});
  // Temporomandibular hinge: in front of the ear canal, about 3 cm below the eyes.
  b.add("jaw", "head", {0.0f, 1.570f, 0.010f});
  // Interpupillary distance 64 mm; eyeball centre 12 mm behind the cornea.
  b.add("leftEye", "head", {0.032f, 1.603f, 0.076f});
  b.add("rightEye", "head", {-0.032f, 1.603f, 0.076f});

  for (int s = 0; s < 2; ++s) {
    const float side = s == 0 ? 1.0f : -1.0f;  // left = +X
    const std::string p = s == 0 ? "left" : "right";
    auto m = [side](glm::vec3 v) { return glm::vec3(side * v.x, v.y, v.z); };
    // Glenohumeral centre about 3 cm below the acromion (acromial height 0.82 of stature).
    b.add(p + "Shoulder", "upperChest", m({0.022f, 1.380f, 0.010f}));
    b.add(p + "UpperArm", p + "Shoulder", m({0.175f, 1.392f, -0.005f}));
    b.add(p + "LowerArm", p + "UpperArm", m({0.460f, 1.392f, -0.005f}));
    const glm::vec3 wrist{0.710f, 1.392f, -0.005f};
    b.add(p + "Hand", p + "LowerArm", m(wrist));

    // Thumb: CMC joint on the palm side near the wrist; the flat-hand thumb points about 45°
    // between the fingers and the front, a little towards the palm.
    {
      glm::vec3 joint = wrist + glm::vec3(0.024f, -0.012f, 0.020f);
      const glm::vec3 dirs[3] = {glm::normalize(glm::vec3(0.62f, -0.16f, 0.72f)),
                                 glm::normalize(glm::vec3(0.76f, -0.09f, 0.62f)),
                                 glm::normalize(glm::vec3(0.86f, -0.05f, 0.50f))};
      const float lengths[3] = {0.046f, 0.032f, 0.030f};
      const char* parts[3] = {"Metacarpal", "Proximal", "Distal"};
      std::string parent = p + "Hand";
      for (int i = 0; i < 3; ++i) {
        const std::string name = p + "Thumb" + parts[i];
        b.add(name, parent, m(joint));
        joint += dirs[i] * lengths[i];
        parent = name;
      }
      b.add(p + "ThumbTip", parent, m(joint), false);
    }
    for (const FingerSpec& f : kFingers) {
      const std::string base = p + f.name;
      b.add(base + "Metacarpal", p + "Hand", m(wrist + f.metacarpal_base));
      const glm::vec3 dir{std::cos(f.fan_rad), 0.0f, std::sin(f.fan_rad)};
      glm::vec3 joint = wrist + f.knuckle;
      b.add(base + "Proximal", base + "Metacarpal", m(joint));
      joint += dir * f.proximal_m;
      b.add(base + "Intermediate", base + "Proximal", m(joint));
      joint += dir * f.intermediate_m;
      b.add(base + "Distal", base + "Intermediate", m(joint));
      joint += dir * f.distal_m;
      b.add(p + f.name + "Tip", base + "Distal", m(joint), false);
    }
  }
  for (int s = 0; s < 2; ++s) {
    const float side = s == 0 ? 1.0f : -1.0f;
    const std::string p = s == 0 ? "left" : "right";
    auto m = [side](glm::vec3 v) { return glm::vec3(side * v.x, v.y, v.z); };
    b.add(p + "UpperLeg", "hips", m({0.088f, 0.905f, 0.005f}));
    b.add(p + "LowerLeg", p + "UpperLeg", m({0.095f, 0.485f, 0.000f}));
    b.add(p + "Foot", p + "LowerLeg", m({0.100f, 0.080f, -0.025f}));
    b.add(p + "Toes", p + "Foot", m({0.105f, 0.022f, 0.115f}));
  }
  return b.layout;
}

}  // namespace sw::avatar_generator

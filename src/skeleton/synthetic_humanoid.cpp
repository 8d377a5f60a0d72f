// The synthetic humanoid skeleton and deterministic poses for it (synthetic_humanoid.h).
#include "skeleton/synthetic_humanoid.h"

#include <cmath>
#include <string>

namespace sw::skeleton {
namespace {

// Builds the skeleton from model-space bind positions (the way proportions are measured); the
// rest translation of a joint is its offset from its parent.
struct Builder {
  Skeleton skeleton;
  std::vector<glm::vec3> model;
  int add(const std::string& name, int parent, glm::vec3 model_pos) {
    Joint j;
    j.name = name;
    j.parent = parent;
    j.rest.translation =
        parent < 0 ? model_pos : model_pos - model[static_cast<std::size_t>(parent)];
    skeleton.joints.push_back(j);
    model.push_back(model_pos);
    return skeleton.joint_count() - 1;
  }
};

void add_arm(Builder& b, int upper_chest, bool left, bool finger_metacarpals) {
  const float x = left ? 1.0f : -1.0f;  // +X is the signer's left (the figure faces +Z)
  const std::string p = left ? "left" : "right";
  const int sh = b.add(p + "Shoulder", upper_chest, {x * 0.03f, 1.43f, 0});
  const int ua = b.add(p + "UpperArm", sh, {x * 0.17f, 1.43f, 0});
  const int la = b.add(p + "LowerArm", ua, {x * 0.46f, 1.43f, 0});
  const int hand = b.add(p + "Hand", la, {x * 0.72f, 1.43f, 0});
  // Thumb: forward (+Z) and slightly down from the wrist, as in a relaxed T-pose hand.
  const int t0 = b.add(p + "ThumbMetacarpal", hand, {x * 0.74f, 1.42f, 0.022f});
  const int t1 = b.add(p + "ThumbProximal", t0, {x * 0.775f, 1.412f, 0.045f});
  const int t2 = b.add(p + "ThumbDistal", t1, {x * 0.805f, 1.406f, 0.062f});
  b.add(p + "ThumbTip", t2, {x * 0.833f, 1.402f, 0.076f});
  const char* fn[4] = {"Index", "Middle", "Ring", "Little"};
  const float z[4] = {0.028f, 0.009f, -0.010f, -0.026f};
  const float knuckle[4] = {0.092f, 0.095f, 0.090f, 0.087f};  // wrist to knuckle
  const float len[4][3] = {{0.045f, 0.026f, 0.022f},
                           {0.050f, 0.030f, 0.024f},
                           {0.046f, 0.029f, 0.023f},
                           {0.040f, 0.024f, 0.021f}};
  for (int f = 0; f < 4; ++f) {
    const std::string n = p + fn[f];
    const int m =
        finger_metacarpals ? b.add(n + "Metacarpal", hand, {x * 0.74f, 1.43f, z[f] * 0.6f}) : hand;
    float xx = 0.72f + knuckle[f];
    const int j1 = b.add(n + "Proximal", m, {x * xx, 1.43f, z[f]});
    xx += len[f][0];
    const int j2 = b.add(n + "Intermediate", j1, {x * xx, 1.43f, z[f]});
    xx += len[f][1];
    const int j3 = b.add(n + "Distal", j2, {x * xx, 1.43f, z[f]});
    xx += len[f][2];
    b.add(n + "Tip", j3, {x * xx, 1.43f, z[f]});
  }
}

void add_leg(Builder& b, int hips, bool left) {
  const float x = left ? 1.0f : -1.0f;
  const std::string p = left ? "left" : "right";
  const int ul = b.add(p + "UpperLeg", hips, {x * 0.09f, 0.95f, 0});
  const int ll = b.add(p + "LowerLeg", ul, {x * 0.09f, 0.52f, 0});
  const int ft = b.add(p + "Foot", ll, {x * 0.09f, 0.09f, 0});
  b.add(p + "Toes", ft, {x * 0.09f, 0.02f, 0.12f});
}

// splitmix32-style integer hash -> [0, 1): identical on every platform.
float unit_hash(std::uint32_t& state) {
  state += 0x9e3779b9u;
  std::uint32_t z = state;
  z = (z ^ (z >> 16)) * 0x85ebca6bu;
  z = (z ^ (z >> 13)) * 0xc2b2ae35u;
  z ^= z >> 16;
  return float(z >> 8) * (1.0f / 16777216.0f);
}

}  // namespace

Skeleton make_synthetic_humanoid(const SyntheticHumanoidOptions& options) {
  Builder b;
  const int hips = b.add("hips", -1, {0, 1.00f, 0});
  const int spine = b.add("spine", hips, {0, 1.10f, 0});
  const int chest = b.add("chest", spine, {0, 1.22f, 0});
  const int upper_chest = b.add("upperChest", chest, {0, 1.34f, 0});
  const int neck = b.add("neck", upper_chest, {0, 1.46f, 0});
  const int head = b.add("head", neck, {0, 1.56f, 0});
  b.add("jaw", head, {0, 1.54f, 0.04f});
  b.add("leftEye", head, {0.032f, 1.625f, 0.075f});
  b.add("rightEye", head, {-0.032f, 1.625f, 0.075f});
  add_arm(b, upper_chest, true, options.finger_metacarpals);
  add_leg(b, hips, true);
  add_arm(b, upper_chest, false, options.finger_metacarpals);
  add_leg(b, hips, false);
  return b.skeleton;
}

std::vector<glm::vec3> rest_positions(const Skeleton& skeleton) {
  std::vector<glm::vec3> model(skeleton.joints.size());
  for (std::size_t i = 0; i < skeleton.joints.size(); ++i) {
    const Joint& j = skeleton.joints[i];
    model[i] = j.rest.translation +
               (j.parent < 0 ? glm::vec3(0.0f) : model[static_cast<std::size_t>(j.parent)]);
  }
  return model;
}

std::vector<math::Transform> make_synthetic_pose(const Skeleton& skeleton, std::uint32_t seed,
                                                 float max_angle_rad) {
  std::vector<math::Transform> pose;
  pose.reserve(skeleton.joints.size());
  std::uint32_t state = seed;
  for (const Joint& j : skeleton.joints) {
    math::Transform t = j.rest;
    // One draw per statement: the evaluation order of function arguments is unspecified (g++ and
    // clang differ), and the pose must be the same natively and in WASM.
    const float ax = unit_hash(state) - 0.5f;
    const float ay = unit_hash(state) - 0.5f;
    const float az = unit_hash(state) - 0.5f;
    const float angle = (2.0f * unit_hash(state) - 1.0f) * max_angle_rad;
    const glm::vec3 axis(ax, ay, az);
    const float len = glm::length(axis);
    if (len > 1e-3f) t.rotation = glm::angleAxis(angle, axis / len) * t.rotation;
    pose.push_back(t);
  }
  return pose;
}

}  // namespace sw::skeleton

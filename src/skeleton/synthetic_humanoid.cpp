// The synthetic 65-joint humanoid and deterministic poses for it (synthetic_humanoid.h).
#include "skeleton/synthetic_humanoid.h"

#include <cmath>
#include <string>

namespace sw::skeleton {
namespace {

int add(Skeleton& s, const std::string& name, int parent, glm::vec3 offset_m) {
  Joint j;
  j.name = name;
  j.parent = parent;
  j.rest.translation = offset_m;
  s.joints.push_back(j);
  return s.joint_count() - 1;
}

void add_arm(Skeleton& s, int upper_chest, bool left) {
  // +X is the signer's left (the avatar faces +Z).
  const float x = left ? 1.0f : -1.0f;
  const std::string side = left ? "left" : "right";
  const int shoulder = add(s, side + "Shoulder", upper_chest, {0.02f * x, 0.12f, 0.0f});
  const int upper = add(s, side + "UpperArm", shoulder, {0.10f * x, 0.0f, 0.0f});
  const int lower = add(s, side + "LowerArm", upper, {0.27f * x, 0.0f, 0.0f});
  const int hand = add(s, side + "Hand", lower, {0.25f * x, 0.0f, 0.0f});
  int p = add(s, side + "ThumbMetacarpal", hand, {0.02f * x, -0.01f, 0.025f});
  p = add(s, side + "ThumbProximal", p, {0.035f * x, 0.0f, 0.02f});
  p = add(s, side + "ThumbDistal", p, {0.03f * x, 0.0f, 0.01f});
  add(s, side + "ThumbTip", p, {0.025f * x, 0.0f, 0.005f});
  const char* fingers[] = {"Index", "Middle", "Ring", "Little"};
  for (int f = 0; f < 4; ++f) {
    const float z = 0.03f - 0.02f * float(f);
    const float scale = 1.0f - 0.1f * float(f > 1 ? f - 1 : 0);
    int q = add(s, side + fingers[f] + "Proximal", hand, {0.09f * x, 0.0f, z});
    q = add(s, side + fingers[f] + "Intermediate", q, {0.04f * scale * x, 0.0f, 0.0f});
    q = add(s, side + fingers[f] + "Distal", q, {0.025f * scale * x, 0.0f, 0.0f});
    add(s, side + fingers[f] + "Tip", q, {0.02f * scale * x, 0.0f, 0.0f});
  }
}

void add_leg(Skeleton& s, int hips, bool left) {
  const float x = left ? 1.0f : -1.0f;
  const std::string side = left ? "left" : "right";
  int p = add(s, side + "UpperLeg", hips, {0.09f * x, -0.05f, 0.0f});
  p = add(s, side + "LowerLeg", p, {0.0f, -0.42f, 0.0f});
  p = add(s, side + "Foot", p, {0.0f, -0.40f, 0.0f});
  add(s, side + "Toes", p, {0.0f, -0.05f, 0.12f});
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

Skeleton make_synthetic_humanoid() {
  Skeleton s;
  const int hips = add(s, "hips", -1, {0.0f, 0.95f, 0.0f});
  const int spine = add(s, "spine", hips, {0.0f, 0.10f, 0.0f});
  const int chest = add(s, "chest", spine, {0.0f, 0.12f, 0.0f});
  const int upper_chest = add(s, "upperChest", chest, {0.0f, 0.12f, 0.0f});
  const int neck = add(s, "neck", upper_chest, {0.0f, 0.15f, 0.0f});
  const int head = add(s, "head", neck, {0.0f, 0.08f, 0.0f});
  add(s, "jaw", head, {0.0f, -0.02f, 0.05f});
  add(s, "leftEye", head, {0.03f, 0.07f, 0.08f});
  add(s, "rightEye", head, {-0.03f, 0.07f, 0.08f});
  add_arm(s, upper_chest, true);
  add_arm(s, upper_chest, false);
  add_leg(s, hips, true);
  add_leg(s, hips, false);
  return s;
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

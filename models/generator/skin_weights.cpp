// Skin weights; see skin_weights.h.
#include "skin_weights.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace sw::avatar_generator {

namespace {

struct Segment {
  glm::vec3 a{0}, b{0};
};

float distance_to_segment(glm::vec3 p, const Segment& s) {
  const glm::vec3 ab = s.b - s.a;
  const float length2 = glm::dot(ab, ab);
  const float t = length2 > 0.0f ? glm::clamp(glm::dot(p - s.a, ab) / length2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (s.a + ab * t));
}

float smoothstep(float e0, float e1, float x) {
  const float t = glm::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace

SkinWeights compute_skin_weights(const HumanoidLayout& layout, const ImplicitBody& body,
                                 const std::vector<glm::vec3>& positions,
                                 const std::vector<int>& nearest_primitive,
                                 const std::vector<std::uint32_t>& triangles,
                                 float (*jaw_mask)(glm::vec3)) {
  const size_t joint_count = layout.joints.size();
  auto J = [&](const std::string& n) { return layout.position(n); };
  auto id = [&](const std::string& n) { return layout.find(n); };

  // Bone segments: each deforming joint to the joint that continues its chain.
  std::vector<Segment> segments(joint_count);
  for (size_t j = 0; j < joint_count; ++j) {
    segments[j].a = segments[j].b = layout.joints[j].position;
    for (size_t c = j + 1; c < joint_count; ++c)
      if (layout.joints[c].parent == static_cast<int>(j)) {
        segments[j].b = layout.joints[c].position;
        break;
      }
  }
  const std::map<std::string, std::string> chain_end = {
      {"hips", "spine"},      {"spine", "chest"}, {"chest", "upperChest"},
      {"upperChest", "neck"}, {"neck", "head"},
  };
  for (const auto& [from, to] : chain_end) segments[static_cast<size_t>(id(from))].b = J(to);
  segments[static_cast<size_t>(id("head"))].b = J("head") + glm::vec3(0.0f, 0.15f, 0.0f);
  for (const char* side : {"left", "right"}) {
    const std::string p = side;
    const float sign = p == "left" ? 1.0f : -1.0f;
    segments[static_cast<size_t>(id(p + "Shoulder"))].b = J(p + "UpperArm");
    segments[static_cast<size_t>(id(p + "Hand"))].b =
        J(p + "Hand") + glm::vec3(sign * 0.035f, 0, 0);
    segments[static_cast<size_t>(id(p + "UpperLeg"))].b = J(p + "LowerLeg");
    segments[static_cast<size_t>(id(p + "Toes"))].b = J(p + "Toes") + glm::vec3(0, 0, 0.05f);
  }

  // Candidate joints per body part.
  std::map<std::string, std::vector<int>> candidates;
  candidates["torso"] = {id("hips"),         id("spine"),        id("chest"),
                         id("upperChest"),   id("leftShoulder"), id("rightShoulder"),
                         id("leftUpperLeg"), id("rightUpperLeg")};
  candidates["neck"] = {id("upperChest"), id("neck"), id("head")};
  for (const char* part : {"head", "ears", "nose", "brows", "lips", "hair", "eyelids"})
    candidates[part] = {id("head")};
  for (const char* side : {"left", "right"}) {
    const std::string p = side;
    candidates[p + "Arm"] = {id(p + "Shoulder"), id(p + "UpperArm"), id(p + "LowerArm"),
                             id(p + "Hand"), id("upperChest")};
    std::vector<int> palm = {id(p + "LowerArm"), id(p + "Hand"), id(p + "ThumbMetacarpal")};
    for (int f = 1; f < 5; ++f) {
      palm.push_back(id(p + kFingerNames[f] + "Metacarpal"));
      palm.push_back(id(p + kFingerNames[f] + "Proximal"));
    }
    candidates[p + "Palm"] = palm;
    candidates[p + "Thumb"] = {id(p + "Hand"), id(p + "ThumbMetacarpal"), id(p + "ThumbProximal"),
                               id(p + "ThumbDistal")};
    for (int f = 1; f < 5; ++f) {
      const std::string finger = p + kFingerNames[f];
      candidates[finger] = {id(finger + "Metacarpal"), id(finger + "Proximal"),
                            id(finger + "Intermediate"), id(finger + "Distal")};
    }
    candidates[p + "Leg"] = {id("hips"), id(p + "UpperLeg"), id(p + "LowerLeg"), id(p + "Foot")};
    candidates[p + "Foot"] = {id(p + "LowerLeg"), id(p + "Foot"), id(p + "Toes")};
  }

  const size_t n = positions.size();
  std::vector<float> dense(n * joint_count, 0.0f);
  for (size_t v = 0; v < n; ++v) {
    const glm::vec3 p = positions[v];
    float* w = &dense[v * joint_count];
    const int prim = nearest_primitive[v];
    const std::string& part =
        body.parts()[static_cast<size_t>(body.primitives()[static_cast<size_t>(prim)].part)].name;
    const auto found = candidates.find(part);
    const std::vector<int>& list = found != candidates.end() ? found->second : candidates["torso"];
    float total = 0.0f;
    for (int j : list) {
      const float d = distance_to_segment(p, segments[static_cast<size_t>(j)]) + 1e-4f;
      const float inv = 1.0f / (d * d * d * d);
      w[j] += inv;
      total += inv;
    }
    for (int j : list) w[j] /= total;
    // Shoulder cap: the top of the deltoid hangs from the acromion, so near the shoulder joint the
    // upper arm's share is reduced in favour of the shoulder (clavicle) — lowering the arm then
    // rounds the shoulder instead of lifting a point above it.
    if (part == "leftArm" || part == "rightArm") {
      const std::string side = part == "leftArm" ? "left" : "right";
      const int upper_arm = id(side + "UpperArm"), shoulder = id(side + "Shoulder");
      const float along = std::fabs(p.x) - std::fabs(J(side + "UpperArm").x);
      const float keep = 0.45f + 0.55f * smoothstep(-0.01f, 0.09f, along);
      const float moved = w[upper_arm] * (1.0f - keep);
      w[upper_arm] -= moved;
      w[shoulder] += moved;
    }
    if (list.size() == 1 && list[0] == id("head")) {
      const float jaw = jaw_mask(p);
      w[id("head")] = 1.0f - jaw;
      w[id("jaw")] = jaw;
    }
    // Forearm: let the hand carry a growing share over the distal half of the forearm, so a
    // twist of the hand is spread along the forearm instead of pinching the wrist (LBS shrinks a
    // 50/50 blend by cos(angle/2): spread over 12 cm the pinch is gentle, not a candy wrapper).
    if (part == "leftArm" || part == "rightArm") {
      const std::string p_side = part == "leftArm" ? "left" : "right";
      const glm::vec3 elbow = J(p_side + "LowerArm"), wrist = J(p_side + "Hand");
      const float t = glm::dot(p - elbow, wrist - elbow) / glm::dot(wrist - elbow, wrist - elbow);
      const float hand_share = 0.5f * smoothstep(0.5f, 1.0f, t);
      const int hand = id(p_side + "Hand");
      if (w[hand] < hand_share) {
        const float rest = 1.0f - w[hand];
        const float scale = rest > 0.0f ? (1.0f - hand_share) / rest : 0.0f;
        for (int j : list) w[j] *= scale;
        w[hand] = hand_share;
      }
    }
  }

  // Smooth along mesh edges: removes weight steps where two parts' candidate sets differ.
  std::vector<std::vector<std::uint32_t>> neighbours(n);
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = triangles[t + static_cast<size_t>(e)];
      const std::uint32_t b = triangles[t + static_cast<size_t>((e + 1) % 3)];
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  for (auto& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  std::vector<float> next(dense.size());
  for (int iteration = 0; iteration < 4; ++iteration) {
    for (size_t v = 0; v < n; ++v) {
      float* out = &next[v * joint_count];
      const float* own = &dense[v * joint_count];
      if (neighbours[v].empty()) {
        std::copy(own, own + joint_count, out);
        continue;
      }
      const float share = 0.5f / static_cast<float>(neighbours[v].size());
      for (size_t j = 0; j < joint_count; ++j) out[j] = 0.5f * own[j];
      for (std::uint32_t u : neighbours[v]) {
        const float* other = &dense[u * joint_count];
        for (size_t j = 0; j < joint_count; ++j) out[j] += share * other[j];
      }
    }
    dense.swap(next);
  }

  SkinWeights result;
  result.joints.resize(n);
  result.weights.resize(n);
  for (size_t v = 0; v < n; ++v) {
    const float* w = &dense[v * joint_count];
    std::array<int, 4> best = {-1, -1, -1, -1};
    for (size_t j = 0; j < joint_count; ++j) {
      if (w[j] <= 0.0f) continue;
      for (int slot = 0; slot < 4; ++slot) {
        if (best[slot] < 0 || w[j] > w[best[slot]]) {
          for (int move = 3; move > slot; --move) best[move] = best[move - 1];
          best[slot] = static_cast<int>(j);
          break;
        }
      }
    }
    float total = 0.0f;
    for (int slot = 0; slot < 4; ++slot)
      if (best[slot] >= 0) total += w[best[slot]];
    for (int slot = 0; slot < 4; ++slot) {
      result.joints[v][slot] = static_cast<std::uint16_t>(best[slot] >= 0 ? best[slot] : 0);
      result.weights[v][slot] = best[slot] >= 0 ? w[best[slot]] / total : 0.0f;
    }
  }
  return result;
}

}  // namespace sw::avatar_generator

// The committed avatar (models/signweave-avatar.glb) against issue 3's model requirements:
// canonical skeleton, proportions, triangle budget, skin weights, face morph targets and the bind
// pose convention of models/README.md. The file is read with a small GLB reader of its own (JSON
// chunk via nlohmann + the binary chunk), independent of the core's loader, so a loader bug and a
// model bug cannot hide each other.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "face/channels.h"

namespace {

using nlohmann::json;

struct Glb {
  json document;
  std::vector<std::uint8_t> binary;
  std::size_t file_bytes = 0;
  std::string error;
};

std::uint32_t read_u32(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return static_cast<std::uint32_t>(bytes[at]) | static_cast<std::uint32_t>(bytes[at + 1]) << 8 |
         static_cast<std::uint32_t>(bytes[at + 2]) << 16 |
         static_cast<std::uint32_t>(bytes[at + 3]) << 24;
}

Glb load_glb(const std::string& path) {
  Glb glb;
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    glb.error = "cannot open " + path;
    return glb;
  }
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                  std::istreambuf_iterator<char>());
  glb.file_bytes = bytes.size();
  if (bytes.size() < 20 || read_u32(bytes, 0) != 0x46546C67u || read_u32(bytes, 4) != 2 ||
      read_u32(bytes, 8) != bytes.size()) {
    glb.error = "not a glTF 2.0 binary of consistent length";
    return glb;
  }
  const std::uint32_t json_length = read_u32(bytes, 12);
  if (read_u32(bytes, 16) != 0x4E4F534Au || 20u + json_length + 8u > bytes.size()) {
    glb.error = "bad JSON chunk";
    return glb;
  }
  glb.document = json::parse(bytes.begin() + 20, bytes.begin() + 20 + json_length);
  const std::size_t bin_at = 20 + json_length;
  const std::uint32_t bin_length = read_u32(bytes, bin_at);
  if (read_u32(bytes, bin_at + 4) != 0x004E4942u || bin_at + 8 + bin_length > bytes.size()) {
    glb.error = "bad BIN chunk";
    return glb;
  }
  glb.binary.assign(bytes.begin() + static_cast<long>(bin_at + 8),
                    bytes.begin() + static_cast<long>(bin_at + 8 + bin_length));
  return glb;
}

// Reads any accessor as floats (componentType float, u8, u16, u32; no normalisation needed here).
std::vector<float> read_accessor(const Glb& glb, int index, int* components = nullptr) {
  const json& accessor = glb.document["accessors"][static_cast<std::size_t>(index)];
  static const std::map<std::string, int> kComponents = {
      {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT4", 16}};
  const int n = kComponents.at(accessor["type"].get<std::string>());
  if (components) *components = n;
  const std::size_t count = accessor["count"].get<std::size_t>();
  std::vector<float> out(count * static_cast<std::size_t>(n), 0.0f);
  if (!accessor.contains("bufferView")) return out;  // glTF §3.6.2.3: all zeros
  const json& view = glb.document["bufferViews"][accessor["bufferView"].get<std::size_t>()];
  const int type = accessor["componentType"].get<int>();
  const std::size_t size = type == 5126 || type == 5125 ? 4 : type == 5123 ? 2 : 1;
  const std::size_t stride = view.value("byteStride", size * static_cast<std::size_t>(n));
  const std::size_t base =
      view.value("byteOffset", std::size_t{0}) + accessor.value("byteOffset", std::size_t{0});
  EXPECT_LE(base + (count - 1) * stride + size * static_cast<std::size_t>(n), glb.binary.size());
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < n; ++c) {
      const std::uint8_t* p = &glb.binary[base + i * stride + static_cast<std::size_t>(c) * size];
      float value = 0.0f;
      if (type == 5126) {
        std::memcpy(&value, p, 4);
      } else if (type == 5125) {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        value = static_cast<float>(v);
      } else if (type == 5123) {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        value = static_cast<float>(v);
      } else {
        value = static_cast<float>(*p);
      }
      out[i * static_cast<std::size_t>(n) + static_cast<std::size_t>(c)] = value;
    }
  return out;
}

std::vector<std::string> canonical_joint_names() {
  std::vector<std::string> names = {"hips", "spine", "chest",   "upperChest", "neck",
                                    "head", "jaw",   "leftEye", "rightEye"};
  for (const std::string side : {"left", "right"}) {
    for (const char* part :
         {"Shoulder", "UpperArm", "LowerArm", "Hand", "ThumbMetacarpal", "ThumbProximal",
          "ThumbDistal", "ThumbTip", "UpperLeg", "LowerLeg", "Foot", "Toes"})
      names.push_back(side + part);
    for (const char* finger : {"Index", "Middle", "Ring", "Little"})
      for (const char* part : {"Metacarpal", "Proximal", "Intermediate", "Distal", "Tip"})
        names.push_back(side + finger + part);
  }
  return names;
}

class AvatarModel : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    glb_ = new Glb(load_glb(std::string(SIGNWEAVE_SOURCE_DIR) + "/models/signweave-avatar.glb"));
  }
  static void TearDownTestSuite() {
    delete glb_;
    glb_ = nullptr;
  }
  void SetUp() override { ASSERT_TRUE(glb_->error.empty()) << glb_->error; }

  const json& doc() const { return glb_->document; }

  // Model-space bind positions of the nodes (translations only: the bind rotations are identity,
  // which a test below checks).
  std::map<std::string, glm::vec3> joint_positions() const {
    std::map<std::string, glm::vec3> result;
    const json& nodes = doc()["nodes"];
    std::vector<int> parent(nodes.size(), -1);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      for (const json& child : nodes[i].value("children", json::array()))
        parent[child.get<std::size_t>()] = static_cast<int>(i);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      glm::vec3 p(0.0f);
      for (int n = static_cast<int>(i); n >= 0; n = parent[static_cast<std::size_t>(n)]) {
        const json& t =
            nodes[static_cast<std::size_t>(n)].value("translation", json::array({0, 0, 0}));
        p += glm::vec3(t[0].get<float>(), t[1].get<float>(), t[2].get<float>());
      }
      result[nodes[i].value("name", "")] = p;
    }
    return result;
  }

  std::vector<std::string> skin_joint_names() const {
    std::vector<std::string> names;
    for (const json& j : doc()["skins"][0]["joints"])
      names.push_back(doc()["nodes"][j.get<std::size_t>()]["name"].get<std::string>());
    return names;
  }

  struct SkinnedVertices {
    std::vector<glm::vec3> rest, posed;
  };

  // Linear blend skinning (glTF 2.0 §3.7.3) of every vertex with one joint rotated in its local
  // frame — what the core and the page do, written out here so the weights are judged on their own.
  SkinnedVertices skin_with(const std::string& joint_name, const glm::quat& rotation) const {
    const json& nodes = doc()["nodes"];
    std::vector<int> parent(nodes.size(), -1);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      for (const json& child : nodes[i].value("children", json::array()))
        parent[child.get<std::size_t>()] = static_cast<int>(i);
    std::vector<glm::mat4> world(nodes.size(), glm::mat4(1.0f));
    std::vector<bool> done(nodes.size(), false);
    std::function<glm::mat4(std::size_t)> world_of = [&](std::size_t i) -> glm::mat4 {
      if (done[i]) return world[i];
      const json& t = nodes[i].value("translation", json::array({0, 0, 0}));
      glm::mat4 local = glm::translate(
          glm::mat4(1.0f), glm::vec3(t[0].get<float>(), t[1].get<float>(), t[2].get<float>()));
      if (nodes[i].value("name", "") == joint_name) local = local * glm::mat4_cast(rotation);
      world[i] = parent[i] >= 0 ? world_of(static_cast<std::size_t>(parent[i])) * local : local;
      done[i] = true;
      return world[i];
    };
    const json& skin = doc()["skins"][0];
    const std::vector<float> inverse = read_accessor(*glb_, skin["inverseBindMatrices"].get<int>());
    std::vector<glm::mat4> palette;
    for (std::size_t j = 0; j < skin["joints"].size(); ++j) {
      glm::mat4 ib;
      std::memcpy(&ib[0][0], &inverse[j * 16], sizeof(float) * 16);
      palette.push_back(world_of(skin["joints"][j].get<std::size_t>()) * ib);
    }
    SkinnedVertices out;
    for (const json& mesh : doc()["meshes"])
      for (const json& primitive : mesh["primitives"]) {
        const json& a = primitive["attributes"];
        const std::vector<float> p = read_accessor(*glb_, a["POSITION"].get<int>());
        const std::vector<float> j4 = read_accessor(*glb_, a["JOINTS_0"].get<int>());
        const std::vector<float> w4 = read_accessor(*glb_, a["WEIGHTS_0"].get<int>());
        for (std::size_t v = 0; v < p.size() / 3; ++v) {
          const glm::vec4 rest(p[3 * v], p[3 * v + 1], p[3 * v + 2], 1.0f);
          glm::vec4 posed(0.0f);
          for (std::size_t k = 0; k < 4; ++k)
            posed += w4[4 * v + k] * (palette[static_cast<std::size_t>(j4[4 * v + k])] * rest);
          out.rest.emplace_back(rest);
          out.posed.emplace_back(posed);
        }
      }
    return out;
  }

  static Glb* glb_;
};

Glb* AvatarModel::glb_ = nullptr;

TEST_F(AvatarModel, SkeletonHasEveryCanonicalJointAndAPlausibleCount) {
  const std::vector<std::string> joints = skin_joint_names();
  EXPECT_GE(joints.size(), 55u);
  EXPECT_LE(joints.size(), 80u);
  const std::set<std::string> present(joints.begin(), joints.end());
  EXPECT_EQ(present.size(), joints.size()) << "duplicate joint names";
  for (const std::string& name : canonical_joint_names())
    EXPECT_TRUE(present.count(name)) << "missing canonical joint " << name;
}

TEST_F(AvatarModel, VrmHumanoidMapsBonesToNodesOfTheSameName) {
  const json& bones = doc()["extensions"]["VRMC_vrm"]["humanoid"]["humanBones"];
  ASSERT_TRUE(bones.is_object());
  EXPECT_GE(bones.size(), 50u);
  for (const char* required : {"hips", "spine", "head", "leftHand", "rightHand", "leftUpperLeg"})
    EXPECT_TRUE(bones.contains(required)) << required;
  for (const auto& [bone, entry] : bones.items())
    EXPECT_EQ(doc()["nodes"][entry["node"].get<std::size_t>()]["name"].get<std::string>(), bone);
}

TEST_F(AvatarModel, BindPoseHasIdentityRotationsAndTranslationInverseBinds) {
  for (const json& node : doc()["nodes"]) {
    if (node.contains("rotation")) {
      const json& r = node["rotation"];
      EXPECT_NEAR(r[3].get<float>(), 1.0f, 1e-6f) << node["name"];
    }
    EXPECT_FALSE(node.contains("matrix")) << node["name"];
    EXPECT_FALSE(node.contains("scale")) << node["name"];
  }
  const std::map<std::string, glm::vec3> bind = joint_positions();
  const std::vector<float> inverse =
      read_accessor(*glb_, doc()["skins"][0]["inverseBindMatrices"].get<int>());
  const std::vector<std::string> joints = skin_joint_names();
  ASSERT_EQ(inverse.size(), joints.size() * 16);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const float* m = &inverse[j * 16];  // column-major: translation in elements 12..14
    const glm::vec3 p = bind.at(joints[j]);
    EXPECT_NEAR(m[12], -p.x, 1e-5f) << joints[j];
    EXPECT_NEAR(m[13], -p.y, 1e-5f) << joints[j];
    EXPECT_NEAR(m[14], -p.z, 1e-5f) << joints[j];
    EXPECT_NEAR(m[0] + m[5] + m[10], 3.0f, 1e-6f) << joints[j];
  }
}

TEST_F(AvatarModel, TPoseLeftHandAtPlusXPalmDownThumbForward) {
  const std::map<std::string, glm::vec3> p = joint_positions();
  EXPECT_GT(p.at("leftHand").x, 0.6f);
  EXPECT_LT(p.at("rightHand").x, -0.6f);
  EXPECT_NEAR(p.at("leftHand").y, p.at("leftUpperArm").y, 0.02f) << "arms horizontal";
  EXPECT_GT(p.at("leftMiddleTip").x, p.at("leftHand").x + 0.15f) << "fingers along +X";
  EXPECT_GT(p.at("leftThumbTip").z, p.at("leftHand").z + 0.04f) << "thumb towards +Z";
  EXPECT_GT(p.at("rightThumbTip").z, p.at("rightHand").z + 0.04f) << "thumb towards +Z";
  EXPECT_GT(p.at("leftEye").z, p.at("head").z) << "faces +Z";
  EXPECT_GT(p.at("leftEye").x, 0.0f) << "+X is the left";
  for (const auto& [name, position] : p) EXPECT_GE(position.y, -1e-4f) << name;
}

TEST_F(AvatarModel, AdultProportions) {
  const std::map<std::string, glm::vec3> p = joint_positions();
  const float hand_length = glm::length(p.at("leftMiddleTip") - p.at("leftHand"));
  EXPECT_NEAR(hand_length, 0.19f, 0.01f);
  EXPECT_NEAR(glm::length(p.at("rightMiddleTip") - p.at("rightHand")), hand_length, 1e-5f);
  const float upper_arm = glm::length(p.at("leftLowerArm") - p.at("leftUpperArm"));
  const float forearm = glm::length(p.at("leftHand") - p.at("leftLowerArm"));
  EXPECT_NEAR(upper_arm, 0.29f, 0.03f);
  EXPECT_NEAR(forearm, 0.25f, 0.03f);
  // Fingers: middle longest, little shortest (anthropometric order).
  auto finger = [&](const char* f) {
    return glm::length(p.at(std::string("left") + f + "Tip") -
                       p.at(std::string("left") + f + "Proximal"));
  };
  EXPECT_GT(finger("Middle"), finger("Index"));
  EXPECT_GT(finger("Middle"), finger("Ring"));
  EXPECT_GT(finger("Ring"), finger("Little"));
  // Stature from the mesh: feet on the floor, top of the head at about 1.70 m.
  float lowest = 1e9f, highest = -1e9f;
  for (const json& mesh : doc()["meshes"])
    for (const json& primitive : mesh["primitives"]) {
      const json& accessor =
          doc()["accessors"][primitive["attributes"]["POSITION"].get<std::size_t>()];
      lowest = std::min(lowest, accessor["min"][1].get<float>());
      highest = std::max(highest, accessor["max"][1].get<float>());
    }
  EXPECT_NEAR(lowest, 0.0f, 0.01f);
  EXPECT_NEAR(highest, 1.70f, 0.03f);
}

TEST_F(AvatarModel, TriangleBudgetAndFileSize) {
  std::size_t triangles = 0;
  for (const json& mesh : doc()["meshes"])
    for (const json& primitive : mesh["primitives"]) {
      EXPECT_EQ(primitive.value("mode", 4), 4);
      const std::vector<float> indices = read_accessor(*glb_, primitive["indices"].get<int>());
      EXPECT_EQ(indices.size() % 3, 0u);
      triangles += indices.size() / 3;
    }
  EXPECT_GT(triangles, 10000u) << "too coarse to be the avatar";
  EXPECT_LE(triangles, 30000u);
  EXPECT_LT(glb_->file_bytes, 2500000u);
}

TEST_F(AvatarModel, SkinWeightsNormalisedFourInfluencesAndTipsCarryNothing) {
  const std::vector<std::string> joints = skin_joint_names();
  std::set<std::size_t> tips;
  for (std::size_t j = 0; j < joints.size(); ++j)
    if (joints[j].size() > 3 && joints[j].compare(joints[j].size() - 3, 3, "Tip") == 0)
      tips.insert(j);
  EXPECT_EQ(tips.size(), 10u);
  std::set<std::size_t> used;
  std::size_t vertices = 0;
  for (const json& mesh : doc()["meshes"])
    for (const json& primitive : mesh["primitives"]) {
      const json& attributes = primitive["attributes"];
      EXPECT_FALSE(attributes.contains("JOINTS_1")) << "more than 4 influences";
      int jn = 0, wn = 0;
      const std::vector<float> j4 = read_accessor(*glb_, attributes["JOINTS_0"].get<int>(), &jn);
      const std::vector<float> w4 = read_accessor(*glb_, attributes["WEIGHTS_0"].get<int>(), &wn);
      ASSERT_EQ(jn, 4);
      ASSERT_EQ(wn, 4);
      ASSERT_EQ(j4.size(), w4.size());
      const std::vector<float> indices = read_accessor(*glb_, primitive["indices"].get<int>());
      for (float i : indices) ASSERT_LT(static_cast<std::size_t>(i) * 4, j4.size());
      for (std::size_t v = 0; v < w4.size() / 4; ++v) {
        float sum = 0.0f;
        for (int k = 0; k < 4; ++k) {
          const float w = w4[v * 4 + static_cast<std::size_t>(k)];
          const auto joint = static_cast<std::size_t>(j4[v * 4 + static_cast<std::size_t>(k)]);
          ASSERT_GE(w, 0.0f);
          ASSERT_LT(joint, joints.size());
          if (w > 0.0f) {
            EXPECT_FALSE(tips.count(joint)) << "tip point " << joints[joint] << " deforms skin";
            used.insert(joint);
          }
          sum += w;
        }
        ASSERT_NEAR(sum, 1.0f, 1e-4f) << "vertex " << v;
      }
      vertices += w4.size() / 4;
    }
  EXPECT_GT(vertices, 5000u);
  // Every finger phalanx actually moves skin (a finger that does not bend is a lost sign).
  for (const std::string& name : canonical_joint_names()) {
    if (name.find("Proximal") == std::string::npos &&
        name.find("Intermediate") == std::string::npos && name.find("Distal") == std::string::npos)
      continue;
    const auto it = std::find(joints.begin(), joints.end(), name);
    ASSERT_NE(it, joints.end());
    EXPECT_TRUE(used.count(static_cast<std::size_t>(it - joints.begin())))
        << name << " moves no skin";
  }
}

TEST_F(AvatarModel, EveryFaceChannelIsAMorphTargetThatMovesTheFace) {
  const json* face = nullptr;
  for (const json& mesh : doc()["meshes"])
    if (mesh.contains("extras") && mesh["extras"].contains("targetNames")) face = &mesh;
  ASSERT_NE(face, nullptr) << "no mesh with extras.targetNames";
  const std::vector<std::string> names =
      (*face)["extras"]["targetNames"].get<std::vector<std::string>>();
  std::vector<std::string> expected;
  for (std::string_view n : sw::face::kExpressionChannels) expected.emplace_back(n);
  for (std::string_view n : sw::face::kVisemeChannels) expected.emplace_back(n);
  EXPECT_EQ(names.size(), 41u);
  for (const std::string& name : expected)
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << "missing morph " << name;

  std::vector<float> largest(names.size(), 0.0f);
  for (const json& primitive : (*face)["primitives"]) {
    ASSERT_EQ(primitive["targets"].size(), names.size());
    for (std::size_t t = 0; t < names.size(); ++t) {
      const std::vector<float> d =
          read_accessor(*glb_, primitive["targets"][t]["POSITION"].get<int>());
      for (std::size_t v = 0; v + 2 < d.size(); v += 3)
        largest[t] = std::max(largest[t], glm::length(glm::vec3(d[v], d[v + 1], d[v + 2])));
    }
  }
  for (std::size_t t = 0; t < names.size(); ++t) {
    EXPECT_GT(largest[t], 0.0005f) << names[t] << " barely moves";
    EXPECT_LT(largest[t], 0.04f) << names[t] << " moves too far for a face";
  }
}

// Rest pose skins to the bind pose: the inverse binds and the skeleton agree.
TEST_F(AvatarModel, RestPoseSkinsToTheBindPose) {
  const SkinnedVertices s = skin_with("", glm::quat(1, 0, 0, 0));
  ASSERT_FALSE(s.rest.empty());
  for (std::size_t v = 0; v < s.rest.size(); ++v)
    ASSERT_NEAR(glm::length(s.posed[v] - s.rest[v]), 0.0f, 1e-5f) << "vertex " << v;
}

// 90° elbow flexion (forearm forward): the arm must not collapse through the joint — every arm
// vertex stays well outside the elbow's bone, at least 40 % of the arm's rest radius there.
TEST_F(AvatarModel, ElbowFlexionDoesNotCollapse) {
  const glm::vec3 elbow = joint_positions().at("leftLowerArm");
  const SkinnedVertices s =
      skin_with("leftLowerArm", glm::angleAxis(glm::radians(-90.0f), glm::vec3(0, 1, 0)));
  float rest_radius = 1e9f, posed_min = 1e9f;
  std::size_t near_elbow = 0;
  for (std::size_t v = 0; v < s.rest.size(); ++v) {
    const glm::vec3 r = s.rest[v] - elbow;
    if (std::fabs(r.x) > 0.06f || glm::length(glm::vec2(r.y, r.z)) > 0.08f) continue;
    ++near_elbow;
    rest_radius = std::min(rest_radius, glm::length(glm::vec2(r.y, r.z)));
    posed_min = std::min(posed_min, glm::length(s.posed[v] - elbow));
  }
  ASSERT_GT(near_elbow, 50u);
  EXPECT_GT(posed_min, 0.4f * rest_radius) << "rest radius " << rest_radius;
  // The forearm really went forward (+Z): the hand's skin follows.
  const glm::vec3 wrist = joint_positions().at("leftHand");
  float farthest_forward = -1e9f;
  for (std::size_t v = 0; v < s.rest.size(); ++v)
    if (glm::length(s.rest[v] - wrist) < 0.03f)
      farthest_forward = std::max(farthest_forward, s.posed[v].z);
  EXPECT_GT(farthest_forward, elbow.z + 0.2f);
}

// 90° twist of the hand about the forearm axis. Linear blend skinning shrinks a vertex blended
// w : 1-w between two joints twisted by θ to sqrt(1 - 2w(1-w)(1 - cos θ)) of its radius: at most
// to cos(θ/2) = 0.707 for θ = 90°, at a 50/50 blend. With the hand's share spread along the distal
// forearm (skin_weights.cpp) nothing may shrink more than that bound — a gentle narrowing over
// centimetres, not the candy wrapper that a narrow or overshooting blend gives. (Dual-quaternion
// skinning in the core removes even that.)
TEST_F(AvatarModel, ForearmTwistDoesNotCandyWrap) {
  const std::map<std::string, glm::vec3> bind = joint_positions();
  const glm::vec3 elbow = bind.at("leftLowerArm"), wrist = bind.at("leftHand");
  const SkinnedVertices s =
      skin_with("leftHand", glm::angleAxis(glm::radians(90.0f), glm::vec3(1, 0, 0)));
  const float length = wrist.x - elbow.x;
  std::size_t checked = 0;
  for (std::size_t v = 0; v < s.rest.size(); ++v) {
    const glm::vec3 r = s.rest[v];
    if (r.x < elbow.x + 0.3f * length || r.x > wrist.x + 0.005f) continue;
    const float rest_radius = glm::length(glm::vec2(r.y - wrist.y, r.z - wrist.z));
    if (rest_radius > 0.06f) continue;
    const glm::vec3 p = s.posed[v];
    const float posed_radius = glm::length(glm::vec2(p.y - wrist.y, p.z - wrist.z));
    ++checked;
    EXPECT_GT(posed_radius, 0.70f * rest_radius) << "vertex at x=" << r.x;
  }
  EXPECT_GT(checked, 50u);
}

// Rotating one finger joint moves only skin weighted to it (and its descendants): the
// neighbouring finger stays exactly where it was, which is what keeps fingers separate in a sign.
TEST_F(AvatarModel, BendingOneFingerLeavesTheNeighbourAlone) {
  const std::map<std::string, glm::vec3> bind = joint_positions();
  const SkinnedVertices s =
      skin_with("leftIndexProximal", glm::angleAxis(glm::radians(-90.0f), glm::vec3(0, 0, 1)));
  const glm::vec3 a = bind.at("leftMiddleIntermediate"), b = bind.at("leftMiddleTip");
  std::size_t middle = 0, index_moved = 0;
  for (std::size_t v = 0; v < s.rest.size(); ++v) {
    const glm::vec3 ab = b - a;
    const float t = glm::clamp(glm::dot(s.rest[v] - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    if (glm::length(s.rest[v] - (a + ab * t)) < 0.0095f) {
      ++middle;
      EXPECT_NEAR(glm::length(s.posed[v] - s.rest[v]), 0.0f, 1e-6f);
    }
    if (glm::length(s.rest[v] - bind.at("leftIndexTip")) < 0.012f &&
        glm::length(s.posed[v] - s.rest[v]) > 0.03f)
      ++index_moved;
  }
  EXPECT_GT(middle, 30u);
  EXPECT_GT(index_moved, 5u) << "the bent index finger's tip did not move";
}

}  // namespace

// The synthetic avatar. See synthetic_avatar.h.
#include "avatar/synthetic_avatar.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>

#include "skeleton/synthetic_humanoid.h"

namespace sw::avatar {
namespace {

struct JointSpec {
  std::string canonical;
  std::string mixamo;
  std::string parent;  // canonical name, "" for the root
  glm::vec3 position;  // model space, T-pose
};

// Mixamo's name for a canonical joint name, for the Mixamo naming option (the loader maps it back
// through skeleton/humanoid_names).
std::string mixamo_name(const std::string& canonical) {
  static const std::pair<const char*, const char*> kTrunk[] = {
      {"hips", "Hips"}, {"spine", "Spine"}, {"chest", "Spine1"}, {"upperChest", "Spine2"},
      {"neck", "Neck"}, {"head", "Head"}, {"jaw", "Jaw"}, {"leftEye", "LeftEye"}, {"rightEye", "RightEye"}};
  for (const auto& [c, m] : kTrunk)
    if (canonical == c) return m;
  const bool left = canonical.rfind("left", 0) == 0;
  const std::string side = left ? "Left" : "Right";
  const std::string part = canonical.substr(left ? 4 : 5);
  static const std::pair<const char*, const char*> kLimb[] = {
      {"Shoulder", "Shoulder"}, {"UpperArm", "Arm"}, {"LowerArm", "ForeArm"}, {"Hand", "Hand"},
      {"UpperLeg", "UpLeg"}, {"LowerLeg", "Leg"}, {"Foot", "Foot"}, {"Toes", "ToeBase"},
      {"ThumbMetacarpal", "HandThumb1"}, {"ThumbProximal", "HandThumb2"}, {"ThumbDistal", "HandThumb3"},
      {"ThumbTip", "HandThumb4"}};
  for (const auto& [c, m] : kLimb)
    if (part == c) return side + m;
  static const std::pair<const char*, const char*> kFinger[] = {
      {"Index", "Index"}, {"Middle", "Middle"}, {"Ring", "Ring"}, {"Little", "Pinky"}};
  static const std::pair<const char*, const char*> kPhalanx[] = {
      {"Metacarpal", "0"}, {"Proximal", "1"}, {"Intermediate", "2"}, {"Distal", "3"}, {"Tip", "4"}};
  for (const auto& [f, mf] : kFinger)
    for (const auto& [ph, n] : kPhalanx)
      if (part == std::string(f) + ph) return side + "Hand" + mf + n;
  return canonical;
}

// The joints of the project's synthetic humanoid (with finger metacarpals), as specs.
std::vector<JointSpec> joint_specs() {
  const skeleton::Skeleton s = skeleton::make_synthetic_humanoid({/*finger_metacarpals=*/true});
  const std::vector<glm::vec3> model = skeleton::rest_positions(s);
  std::vector<JointSpec> specs;
  for (std::size_t i = 0; i < s.joints.size(); ++i) {
    const skeleton::Joint& j = s.joints[i];
    specs.push_back({j.name, mixamo_name(j.name), j.parent < 0 ? "" : s.joints[static_cast<std::size_t>(j.parent)].name,
                     model[i]});
  }
  return specs;
}

struct MeshBuilder {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::array<std::uint16_t, 4>> joints;
  std::vector<glm::vec4> weights;
  std::vector<std::uint32_t> indices;

  void vertex(glm::vec3 p, glm::vec3 n, int j0, int j1 = -1, float w1 = 0.0f) {
    positions.push_back(p);
    normals.push_back(glm::normalize(n));
    const auto a = static_cast<std::uint16_t>(j0);
    const auto b = static_cast<std::uint16_t>(j1 < 0 ? j0 : j1);
    joints.push_back({a, b, 0, 0});
    weights.push_back({1.0f - w1, w1, 0.0f, 0.0f});
  }

  // An open elliptic tube from a to b; `up` picks the first radius direction. Vertices weigh on
  // joint_a; the last ring blends 50/50 with joint_b when given (a bending joint).
  void tube(glm::vec3 a, glm::vec3 b, float ra, float rb, glm::vec3 up, int joint_a, int joint_b = -1) {
    const int rings = 4, sides = 12;
    const glm::vec3 axis = glm::normalize(b - a);
    const glm::vec3 u = glm::normalize(up - axis * glm::dot(up, axis));
    const glm::vec3 v = glm::cross(axis, u);
    const auto first = static_cast<std::uint32_t>(positions.size());
    for (int r = 0; r <= rings; ++r) {
      const float t = float(r) / rings;
      for (int s = 0; s < sides; ++s) {
        const float angle = 6.2831853f * float(s) / sides;
        const float c = std::cos(angle), sn = std::sin(angle);
        const glm::vec3 p = a + (b - a) * t + u * (ra * c) + v * (rb * sn);
        const glm::vec3 n = u * (c / ra) + v * (sn / rb);
        const bool blend = r == rings && joint_b >= 0;
        vertex(p, n, joint_a, blend ? joint_b : -1, blend ? 0.5f : 0.0f);
      }
    }
    for (int r = 0; r < rings; ++r) {
      for (int s = 0; s < sides; ++s) {
        const std::uint32_t i0 = first + static_cast<std::uint32_t>(r * sides + s);
        const std::uint32_t i1 = first + static_cast<std::uint32_t>(r * sides + (s + 1) % sides);
        const std::uint32_t i2 = i0 + sides, i3 = i1 + sides;
        indices.insert(indices.end(), {i0, i1, i2, i1, i3, i2});
      }
    }
  }

  // A closed ellipsoid (UV sphere), weighted rigidly on one joint.
  void ellipsoid(glm::vec3 centre, glm::vec3 radii, int joint) {
    const int stacks = 16, slices = 24;
    const auto first = static_cast<std::uint32_t>(positions.size());
    for (int i = 0; i <= stacks; ++i) {
      const float phi = 3.14159265f * float(i) / stacks;
      for (int k = 0; k < slices; ++k) {
        const float theta = 6.2831853f * float(k) / slices;
        const glm::vec3 unit(std::sin(phi) * std::sin(theta), std::cos(phi), std::sin(phi) * std::cos(theta));
        vertex(centre + unit * radii, unit / radii, joint);
      }
    }
    for (int i = 0; i < stacks; ++i) {
      for (int k = 0; k < slices; ++k) {
        const std::uint32_t i0 = first + static_cast<std::uint32_t>(i * slices + k);
        const std::uint32_t i1 = first + static_cast<std::uint32_t>(i * slices + (k + 1) % slices);
        const std::uint32_t i2 = i0 + slices, i3 = i1 + slices;
        indices.insert(indices.end(), {i0, i2, i1, i1, i2, i3});
      }
    }
  }
};

// Appends raw bytes as a bufferView + accessor; returns the accessor index.
int add_accessor(tinygltf::Model& model, const void* data, std::size_t bytes, int component_type, int type,
                 std::size_t count, bool normalized = false) {
  tinygltf::Buffer& buffer = model.buffers[0];
  while (buffer.data.size() % 4) buffer.data.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.data.size();
  view.byteLength = bytes;
  const auto* p = static_cast<const unsigned char*>(data);
  buffer.data.insert(buffer.data.end(), p, p + bytes);
  model.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = static_cast<int>(model.bufferViews.size()) - 1;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = count;
  accessor.normalized = normalized;
  if (type == TINYGLTF_TYPE_VEC3 && component_type == TINYGLTF_COMPONENT_TYPE_FLOAT && count > 0) {
    const auto* v = static_cast<const glm::vec3*>(data);
    glm::vec3 lo = v[0], hi = v[0];
    for (std::size_t i = 0; i < count; ++i) { lo = glm::min(lo, v[i]); hi = glm::max(hi, v[i]); }
    accessor.minValues = {lo.x, lo.y, lo.z};
    accessor.maxValues = {hi.x, hi.y, hi.z};
  }
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size()) - 1;
}

void add_mesh(tinygltf::Model& model, const MeshBuilder& m, int material, const std::string& name,
              const std::vector<std::pair<std::string, std::vector<glm::vec3>>>& targets, bool normals, int skin) {
  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  prim.material = material;
  const std::size_t n = m.positions.size();
  prim.attributes["POSITION"] = add_accessor(model, m.positions.data(), n * 12, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  if (normals)
    prim.attributes["NORMAL"] = add_accessor(model, m.normals.data(), n * 12, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  prim.attributes["JOINTS_0"] = add_accessor(model, m.joints.data(), n * 8, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4, n);
  prim.attributes["WEIGHTS_0"] = add_accessor(model, m.weights.data(), n * 16, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, n);
  prim.indices = add_accessor(model, m.indices.data(), m.indices.size() * 4, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                              TINYGLTF_TYPE_SCALAR, m.indices.size());
  tinygltf::Value::Array names;
  for (const auto& [target_name, deltas] : targets) {
    std::map<std::string, int> target;
    target["POSITION"] = add_accessor(model, deltas.data(), n * 12, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
    prim.targets.push_back(target);
    names.push_back(tinygltf::Value(target_name));
  }
  tinygltf::Mesh mesh;
  mesh.name = name;
  mesh.primitives.push_back(prim);
  if (!targets.empty()) {
    tinygltf::Value::Object extras;
    extras["targetNames"] = tinygltf::Value(names);
    mesh.extras = tinygltf::Value(extras);
    mesh.weights.assign(targets.size(), 0.0);
  }
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.name = name;
  node.mesh = static_cast<int>(model.meshes.size()) - 1;
  node.skin = skin;
  model.nodes.push_back(node);
  model.scenes[0].nodes.push_back(static_cast<int>(model.nodes.size()) - 1);
}

}  // namespace

tinygltf::Model make_synthetic_avatar_model(const SyntheticAvatarOptions& options) {
  std::vector<JointSpec> specs = joint_specs();
  // Drop omitted joints and their subtrees.
  std::vector<std::string> dropped = options.omit_joints;
  for (bool changed = true; changed;) {
    changed = false;
    for (const JointSpec& s : specs) {
      const bool parent_dropped = std::find(dropped.begin(), dropped.end(), s.parent) != dropped.end();
      const bool self_dropped = std::find(dropped.begin(), dropped.end(), s.canonical) != dropped.end();
      if (parent_dropped && !self_dropped) { dropped.push_back(s.canonical); changed = true; }
    }
  }
  specs.erase(std::remove_if(specs.begin(), specs.end(), [&](const JointSpec& s) {
                return std::find(dropped.begin(), dropped.end(), s.canonical) != dropped.end();
              }), specs.end());

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "signweave test humanoid";
  model.buffers.resize(1);
  model.scenes.resize(1);
  model.defaultScene = 0;

  std::map<std::string, int> node_of;   // canonical -> node index (== skin joint index)
  std::map<std::string, glm::vec3> pos_of;
  for (const JointSpec& s : specs) {
    tinygltf::Node node;
    node.name = options.names == SyntheticAvatarOptions::Names::Mixamo ? "mixamorig:" + s.mixamo : s.canonical;
    if (options.names == SyntheticAvatarOptions::Names::Vrm1Extension) node.name = "bone_" + std::to_string(model.nodes.size());
    const glm::vec3 parent_pos = s.parent.empty() ? glm::vec3(0.0f) : pos_of[s.parent];
    const glm::vec3 local = s.position - parent_pos;
    node.translation = {local.x, local.y, local.z};
    node_of[s.canonical] = static_cast<int>(model.nodes.size());
    pos_of[s.canonical] = s.position;
    model.nodes.push_back(node);
    if (s.parent.empty()) {
      model.scenes[0].nodes.push_back(node_of[s.canonical]);
    } else {
      model.nodes[static_cast<std::size_t>(node_of[s.parent])].children.push_back(node_of[s.canonical]);
    }
  }

  tinygltf::Skin skin;
  skin.name = "humanoid";
  std::vector<glm::mat4> inverse_binds;
  for (const JointSpec& s : specs) {
    skin.joints.push_back(node_of[s.canonical]);
    glm::mat4 ibm(1.0f);
    ibm[3] = glm::vec4(-s.position, 1.0f);
    inverse_binds.push_back(ibm);
  }
  skin.inverseBindMatrices = add_accessor(model, inverse_binds.data(), inverse_binds.size() * 64,
                                          TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_MAT4, inverse_binds.size());
  model.skins.push_back(skin);

  tinygltf::Material skin_material;
  skin_material.name = "skin";
  skin_material.pbrMetallicRoughness.baseColorFactor = {0.8, 0.6, 0.5, 1.0};
  skin_material.pbrMetallicRoughness.roughnessFactor = 0.7;
  skin_material.pbrMetallicRoughness.metallicFactor = 0.0;
  tinygltf::Material cloth = skin_material;
  cloth.name = "cloth";
  cloth.pbrMetallicRoughness.baseColorFactor = {0.1, 0.2, 0.5, 1.0};
  model.materials = {skin_material, cloth};

  auto has = [&](const std::string& c) { return node_of.count(c) > 0; };
  auto J = [&](const std::string& c) { return has(c) ? node_of[c] : node_of["hips"]; };
  auto P = [&](const std::string& c) { return pos_of.count(c) ? pos_of[c] : glm::vec3(0.0f); };

  MeshBuilder body, clothes;
  // Head and neck (skin).
  const glm::vec3 head_centre(0.0f, SyntheticAvatarGeometry::kHeadCentreY, 0.01f);
  body.ellipsoid(head_centre, {0.08f, 0.11f, SyntheticAvatarGeometry::kHeadRadiusZ}, J("head"));
  body.tube({0.0f, 1.43f, 0.0f}, {0.0f, 1.58f, 0.0f}, 0.05f, 0.05f, {0, 0, 1}, J("neck"));
  // Torso (clothes), one tube per spine segment.
  const char* spine[] = {"hips", "spine", "chest", "upperChest"};
  const float spine_y[] = {0.85f, 1.05f, 1.20f, 1.32f, 1.46f};
  for (int k = 0; k < 4; ++k) {
    if (!has(spine[k])) continue;
    clothes.tube({0.0f, spine_y[k], 0.0f}, {0.0f, spine_y[k + 1], 0.0f}, SyntheticAvatarGeometry::kTorsoRadiusX,
                 SyntheticAvatarGeometry::kTorsoRadiusZ, {1, 0, 0}, J(spine[k]), k < 3 && has(spine[k + 1]) ? J(spine[k + 1]) : -1);
  }
  // The shoulder yoke closes the torso's top.
  if (has("upperChest")) clothes.ellipsoid({0.0f, 1.46f, 0.0f}, {SyntheticAvatarGeometry::kTorsoRadiusX, 0.03f, SyntheticAvatarGeometry::kTorsoRadiusZ}, J("upperChest"));
  for (const std::string side : {"left", "right"}) {
    if (has(side + "UpperArm") && has(side + "LowerArm"))
      clothes.tube(P(side + "UpperArm"), P(side + "LowerArm"), 0.045f, 0.045f, {0, 1, 0}, J(side + "UpperArm"), J(side + "LowerArm"));
    if (has(side + "LowerArm") && has(side + "Hand"))
      clothes.tube(P(side + "LowerArm"), P(side + "Hand"), 0.038f, 0.038f, {0, 1, 0}, J(side + "LowerArm"), J(side + "Hand"));
    if (has(side + "Hand")) {
      const glm::vec3 wrist = P(side + "Hand");
      const glm::vec3 knuckles = wrist + glm::vec3(side == "left" ? 0.10f : -0.10f, 0.0f, 0.0f);
      body.tube(wrist, knuckles, 0.015f, 0.045f, {0, 1, 0}, J(side + "Hand"));
    }
    for (const std::string f : {"Thumb", "Index", "Middle", "Ring", "Little"}) {
      const std::vector<std::string> chain =
          f == "Thumb" ? std::vector<std::string>{"Metacarpal", "Proximal", "Distal", "Tip"}
                       : std::vector<std::string>{"Proximal", "Intermediate", "Distal", "Tip"};
      for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
        const std::string a = side + f + chain[k], b = side + f + chain[k + 1];
        if (has(a) && has(b)) body.tube(P(a), P(b), 0.009f, 0.009f, {0, 1, 0}, J(a));
      }
    }
    if (has(side + "UpperLeg") && has(side + "LowerLeg"))
      clothes.tube(P(side + "UpperLeg"), P(side + "LowerLeg"), 0.07f, 0.07f, {0, 0, 1}, J(side + "UpperLeg"), J(side + "LowerLeg"));
    if (has(side + "LowerLeg") && has(side + "Foot"))
      clothes.tube(P(side + "LowerLeg"), P(side + "Foot"), 0.05f, 0.05f, {0, 0, 1}, J(side + "LowerLeg"));
  }

  std::vector<std::pair<std::string, std::vector<glm::vec3>>> body_targets, cloth_targets;
  if (options.morphs) {
    std::vector<glm::vec3> jaw(body.positions.size(), glm::vec3(0.0f)), blink = jaw;
    for (std::size_t v = 0; v < body.positions.size(); ++v) {
      const glm::vec3 p = body.positions[v];
      if (glm::length(p - head_centre) < 0.12f && p.y < head_centre.y - 0.03f && p.z > 0.0f) jaw[v] = {0.0f, -0.01f, 0.0f};
      if (glm::length(p - head_centre) < 0.12f && p.y > head_centre.y && p.x > 0.02f && p.z > 0.05f) blink[v] = {0.0f, -0.002f, 0.0f};
    }
    body_targets = {{"jawOpen", jaw}, {"eyeBlinkLeft", blink}};
    std::vector<glm::vec3> collar(clothes.positions.size(), glm::vec3(0.0f));
    for (std::size_t v = 0; v < clothes.positions.size(); ++v) {
      if (clothes.positions[v].y > 1.40f && std::abs(clothes.positions[v].x) < 0.2f) collar[v] = {0.0f, 0.0f, 0.001f};
    }
    cloth_targets = {{"jawOpen", collar}};
  }
  add_mesh(model, body, 0, "body", body_targets, options.normals, 0);
  add_mesh(model, clothes, 1, "clothes", cloth_targets, options.normals, 0);

  if (options.names == SyntheticAvatarOptions::Names::Vrm1Extension) {
    tinygltf::Value::Object bones;
    for (const JointSpec& s : specs) {
      if (s.canonical.find("Tip") != std::string::npos) continue;  // tips are not VRM bones
      tinygltf::Value::Object bone;
      bone["node"] = tinygltf::Value(node_of[s.canonical]);
      bones[s.canonical] = tinygltf::Value(bone);
    }
    tinygltf::Value::Object humanoid;
    humanoid["humanBones"] = tinygltf::Value(bones);
    tinygltf::Value::Object vrm;
    vrm["specVersion"] = tinygltf::Value(std::string("1.0"));
    vrm["humanoid"] = tinygltf::Value(humanoid);
    model.extensions["VRMC_vrm"] = tinygltf::Value(vrm);
    model.extensionsUsed.push_back("VRMC_vrm");
  }
  return model;
}

std::vector<std::uint8_t> synthetic_avatar_to_glb(const tinygltf::Model& model) {
  tinygltf::TinyGLTF writer;
  std::ostringstream out;
  writer.WriteGltfSceneToStream(&model, out, false, true);
  const std::string s = out.str();
  return std::vector<std::uint8_t>(s.begin(), s.end());
}

std::vector<std::uint8_t> make_synthetic_avatar_glb(const SyntheticAvatarOptions& options) {
  return synthetic_avatar_to_glb(make_synthetic_avatar_model(options));
}

int synthetic_avatar_node(const tinygltf::Model& model, const std::string& canonical_name) {
  // Nodes are written in joint_specs() order, so find the spec index among kept joints by name;
  // names differ per naming option, so match through the canonical spec list.
  const std::vector<JointSpec> specs = joint_specs();
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const std::string& name = model.nodes[i].name;
    for (const JointSpec& s : specs) {
      if (s.canonical != canonical_name) continue;
      if (name == s.canonical || name == "mixamorig:" + s.mixamo) return static_cast<int>(i);
    }
  }
  return -1;
}

}  // namespace sw::avatar

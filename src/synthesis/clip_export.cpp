// Clip export: BVH (skeleton/bvh.h writer) and GLB (glTF 2.0 binary, own minimal writer).
#include "synthesis/clip_export.h"

#include <cstring>

#include <nlohmann/json.hpp>

#include "skeleton/bvh.h"
#include "synthesis/clip_sampler.h"

namespace sw::synthesis {
namespace {

std::string check(const Clip& clip, const avatar::Avatar& avatar) {
  const auto& joints = avatar.skeleton.joints;
  if (clip.joint_count() != static_cast<int>(joints.size()))
    return "the clip has " + std::to_string(clip.joint_count()) + " joints, the avatar " +
           std::to_string(joints.size());
  for (size_t j = 0; j < joints.size(); ++j)
    if (clip.joint_names[j] != joints[j].name)
      return "joint " + std::to_string(j) + " is '" + clip.joint_names[j] + "' in the clip but '" +
             joints[j].name + "' in the avatar";
  if (clip.frame_count <= 0) return "the clip has no frames";
  if (clip.rotations.size() != static_cast<size_t>(clip.frame_count) * joints.size())
    return "the clip's rotation array does not match frame_count x joints";
  return "";
}

}  // namespace

ExportResult export_bvh(const Clip& clip, const avatar::Avatar& avatar) {
  ExportResult out;
  out.error = check(clip, avatar);
  if (!out.ok()) return out;
  const auto& joints = avatar.skeleton.joints;
  constexpr double kCentimetresPerMetre = 100.0;  // BVH files are conventionally in centimetres
  skeleton::Bvh bvh;
  using C = skeleton::BvhChannel;
  for (size_t j = 0; j < joints.size(); ++j) {
    skeleton::BvhJoint b;
    b.name = joints[j].name;
    b.parent = joints[j].parent;
    b.offset = glm::dvec3(joints[j].rest.translation) * kCentimetresPerMetre;
    if (b.parent < 0) b.channels = {C::Xposition, C::Yposition, C::Zposition};
    b.channels.insert(b.channels.end(), {C::Zrotation, C::Xrotation, C::Yrotation});
    bvh.joints.push_back(b);
  }
  bvh.frame_count = clip.frame_count;
  bvh.frame_time_s = 1.0 / clip.fps;
  bvh.values.assign(static_cast<size_t>(bvh.frame_count) * bvh.channel_count(), 0.0);
  std::vector<math::Transform> local(joints.size());
  for (int f = 0; f < clip.frame_count; ++f) {
    sample_clip_local(clip, avatar.skeleton, f / static_cast<double>(clip.fps), local.data());
    if (!skeleton::local_to_frame(local, 1.0 / kCentimetresPerMetre, bvh, f)) {
      out.error = "frame " + std::to_string(f) + " could not be written";
      return out;
    }
  }
  std::string text = skeleton::write_bvh(bvh);
  out.bytes.assign(text.begin(), text.end());
  return out;
}

namespace {

struct BinWriter {
  std::vector<std::uint8_t> bin;
  nlohmann::json views = nlohmann::json::array(), accessors = nlohmann::json::array();
  // Appends raw data as a buffer view + accessor; returns the accessor index.
  int add(const void* data, size_t bytes, int component, int count, const char* type,
          int target = 0, const nlohmann::json& min = nullptr, const nlohmann::json& max = nullptr) {
    while (bin.size() % 4) bin.push_back(0);
    size_t offset = bin.size();
    bin.resize(offset + bytes);
    std::memcpy(bin.data() + offset, data, bytes);
    nlohmann::json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
    if (target) view["target"] = target;
    views.push_back(view);
    nlohmann::json acc = {{"bufferView", views.size() - 1}, {"componentType", component},
                          {"count", count}, {"type", type}};
    if (!min.is_null()) acc["min"] = min;
    if (!max.is_null()) acc["max"] = max;
    accessors.push_back(acc);
    return static_cast<int>(accessors.size()) - 1;
  }
};

constexpr int kFloat = 5126, kUShort = 5123, kUInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

}  // namespace

ExportResult export_glb(const Clip& clip, const avatar::Avatar& avatar) {
  ExportResult out;
  out.error = check(clip, avatar);
  if (!out.ok()) return out;
  const auto& joints = avatar.skeleton.joints;
  const int J = static_cast<int>(joints.size());
  BinWriter w;
  nlohmann::json nodes = nlohmann::json::array();
  std::vector<std::vector<int>> children(J);
  nlohmann::json roots = nlohmann::json::array();
  for (int j = 0; j < J; ++j) {
    if (joints[j].parent >= 0) children[joints[j].parent].push_back(j);
    else roots.push_back(j);
  }
  for (int j = 0; j < J; ++j) {
    const auto& r = joints[j].rest;
    nlohmann::json n = {{"name", joints[j].name},
                        {"translation", {r.translation.x, r.translation.y, r.translation.z}},
                        {"rotation", {r.rotation.x, r.rotation.y, r.rotation.z, r.rotation.w}},
                        {"scale", {r.scale.x, r.scale.y, r.scale.z}}};
    if (!children[j].empty()) n["children"] = children[j];
    nodes.push_back(n);
  }
  nlohmann::json gltf = {{"asset", {{"version", "2.0"}, {"generator", "Signweave synthesis"}}}};

  // Skin (and the mesh, when the avatar has one, so any glTF viewer shows the signing body).
  std::vector<float> ibm;
  for (int j = 0; j < J; ++j) {
    glm::mat4 m = j < static_cast<int>(avatar.inverse_bind.size()) ? avatar.inverse_bind[j] : glm::mat4(1.0f);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) ibm.push_back(m[c][r]);
  }
  std::vector<int> joint_nodes(J);
  for (int j = 0; j < J; ++j) joint_nodes[j] = j;
  int ibm_acc = w.add(ibm.data(), ibm.size() * 4, kFloat, J, "MAT4");
  gltf["skins"] = {{{"joints", joint_nodes}, {"inverseBindMatrices", ibm_acc}}};
  const auto& mesh = avatar.mesh;
  const size_t V = mesh.positions.size();
  bool has_mesh = V > 0 && mesh.normals.size() == V && mesh.joints.size() == V &&
                  mesh.weights.size() == V && !mesh.indices.empty();
  if (has_mesh) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const auto& p : mesh.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    int pos = w.add(mesh.positions.data(), V * 12, kFloat, static_cast<int>(V), "VEC3", kArrayBuffer,
                    {lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z});
    int nrm = w.add(mesh.normals.data(), V * 12, kFloat, static_cast<int>(V), "VEC3", kArrayBuffer);
    int jnt = w.add(mesh.joints.data(), V * 8, kUShort, static_cast<int>(V), "VEC4", kArrayBuffer);
    int wgt = w.add(mesh.weights.data(), V * 16, kFloat, static_cast<int>(V), "VEC4", kArrayBuffer);
    nlohmann::json prims = nlohmann::json::array(), materials = nlohmann::json::array();
    for (const auto& m : mesh.materials)
      materials.push_back({{"name", m.name},
                           {"pbrMetallicRoughness", {{"baseColorFactor", {m.base_color.r, m.base_color.g, m.base_color.b, m.base_color.a}},
                                                     {"metallicFactor", m.metallic}, {"roughnessFactor", m.roughness}}}});
    std::vector<avatar::Primitive> ranges = mesh.primitives;
    if (ranges.empty()) ranges.push_back({0, static_cast<std::uint32_t>(mesh.indices.size()), 0});
    for (const auto& pr : ranges) {
      if (pr.first_index + static_cast<size_t>(pr.index_count) > mesh.indices.size()) continue;
      int idx = w.add(mesh.indices.data() + pr.first_index, pr.index_count * 4u, kUInt,
                      static_cast<int>(pr.index_count), "SCALAR", kElementArrayBuffer);
      nlohmann::json p = {{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"JOINTS_0", jnt}, {"WEIGHTS_0", wgt}}},
                          {"indices", idx}};
      if (pr.material >= 0 && pr.material < static_cast<int>(materials.size())) p["material"] = pr.material;
      prims.push_back(p);
    }
    gltf["meshes"] = {{{"name", "avatar"}, {"primitives", prims}}};
    if (!materials.empty()) gltf["materials"] = materials;
    nodes.push_back({{"name", "avatar"}, {"mesh", 0}, {"skin", 0}});
    roots.push_back(J);
  }

  // Animation: one time accessor shared by all samplers.
  std::vector<float> times(clip.frame_count);
  for (int f = 0; f < clip.frame_count; ++f) times[f] = f / clip.fps;
  int input = w.add(times.data(), times.size() * 4, kFloat, clip.frame_count, "SCALAR", 0,
                    {times.front()}, {times.back()});
  nlohmann::json samplers = nlohmann::json::array(), channels = nlohmann::json::array();
  std::vector<float> rot(static_cast<size_t>(clip.frame_count) * 4);
  for (int j = 0; j < J; ++j) {
    for (int f = 0; f < clip.frame_count; ++f) {
      const glm::quat& q = clip.rotations[static_cast<size_t>(f) * J + j];
      rot[f * 4 + 0] = q.x;
      rot[f * 4 + 1] = q.y;
      rot[f * 4 + 2] = q.z;
      rot[f * 4 + 3] = q.w;
    }
    int acc = w.add(rot.data(), rot.size() * 4, kFloat, clip.frame_count, "VEC4");
    samplers.push_back({{"input", input}, {"output", acc}, {"interpolation", "LINEAR"}});
    channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", j}, {"path", "rotation"}}}});
  }
  if (clip.root_translation.size() == static_cast<size_t>(clip.frame_count)) {
    int acc = w.add(clip.root_translation.data(), clip.root_translation.size() * 12, kFloat,
                    clip.frame_count, "VEC3");
    samplers.push_back({{"input", input}, {"output", acc}, {"interpolation", "LINEAR"}});
    channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", 0}, {"path", "translation"}}}});
  }
  gltf["animations"] = {{{"name", "signweave"}, {"samplers", samplers}, {"channels", channels}}};
  gltf["nodes"] = nodes;
  gltf["scenes"] = {{{"nodes", roots}}};
  gltf["scene"] = 0;
  while (w.bin.size() % 4) w.bin.push_back(0);
  gltf["buffers"] = {{{"byteLength", w.bin.size()}}};
  gltf["bufferViews"] = w.views;
  gltf["accessors"] = w.accessors;

  std::string json = gltf.dump();
  while (json.size() % 4) json.push_back(' ');  // GLB: JSON chunk padded with spaces
  auto put32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.bytes.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  };
  const std::uint32_t total = 12 + 8 + static_cast<std::uint32_t>(json.size()) + 8 + static_cast<std::uint32_t>(w.bin.size());
  put32(0x46546C67u);  // "glTF"
  put32(2);
  put32(total);
  put32(static_cast<std::uint32_t>(json.size()));
  put32(0x4E4F534Au);  // "JSON"
  out.bytes.insert(out.bytes.end(), json.begin(), json.end());
  put32(static_cast<std::uint32_t>(w.bin.size()));
  put32(0x004E4942u);  // "BIN\0"
  out.bytes.insert(out.bytes.end(), w.bin.begin(), w.bin.end());
  return out;
}

}  // namespace sw::synthesis

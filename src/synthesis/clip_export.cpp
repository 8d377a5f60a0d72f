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
  // Appends a buffer view without an accessor; returns the view index.
  int add_view(const void* data, size_t bytes) {
    while (bin.size() % 4) bin.push_back(0);
    size_t offset = bin.size();
    bin.resize(offset + bytes);
    if (bytes) std::memcpy(bin.data() + offset, data, bytes);
    views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
    return static_cast<int>(views.size()) - 1;
  }
  // A VEC3 float accessor of `count` elements, zero except at `indices` (strictly increasing),
  // stored sparse (glTF 2.0 3.6.2.3): a face morph moves a few hundred of the ~17,000 merged
  // vertices, and 41 dense targets with normals would make the file ~17 MB instead of ~1 MB.
  int add_sparse_vec3(int count, const std::vector<std::uint32_t>& indices, const std::vector<glm::vec3>& values,
                      bool with_bounds) {
    nlohmann::json acc = {{"componentType", 5126}, {"count", count}, {"type", "VEC3"}};
    if (!indices.empty()) {
      int iv = add_view(indices.data(), indices.size() * 4);
      int vv = add_view(values.data(), values.size() * 12);
      acc["sparse"] = {{"count", indices.size()},
                       {"indices", {{"bufferView", iv}, {"componentType", 5125}}},
                       {"values", {{"bufferView", vv}}}};
    }
    if (with_bounds) {  // POSITION targets must carry min/max; the implicit zeros count too
      glm::vec3 lo(0.0f), hi(0.0f);
      for (const glm::vec3& v : values) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
      }
      acc["min"] = {lo.x, lo.y, lo.z};
      acc["max"] = {hi.x, hi.y, hi.z};
    }
    accessors.push_back(acc);
    return static_cast<int>(accessors.size()) - 1;
  }
};

// The non-zero entries of a per-vertex delta array (exactly zero ones are left to the sparse
// accessor's implicit zeros, so the file reads back bit for bit).
void nonzero_entries(const std::vector<glm::vec3>& deltas, std::vector<std::uint32_t>* indices,
                     std::vector<glm::vec3>* values) {
  indices->clear();
  values->clear();
  for (size_t v = 0; v < deltas.size(); ++v) {
    if (deltas[v] == glm::vec3(0.0f)) continue;
    indices->push_back(static_cast<std::uint32_t>(v));
    values->push_back(deltas[v]);
  }
}

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
  std::vector<std::string> morph_names;  // the mesh's morph targets, in their order
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
    // Face morph targets (shared by every primitive: the mesh is merged) with their names, so the
    // clip's morph weights can animate them.
    nlohmann::json targets = nlohmann::json::array(), target_names = nlohmann::json::array();
    for (const avatar::MorphTarget& m : avatar.morphs) {
      if (m.position_deltas.size() != V) continue;
      std::vector<std::uint32_t> idx;
      std::vector<glm::vec3> val;
      nonzero_entries(m.position_deltas, &idx, &val);
      nlohmann::json t = {{"POSITION", w.add_sparse_vec3(static_cast<int>(V), idx, val, true)}};
      if (m.normal_deltas.size() == V) {
        nonzero_entries(m.normal_deltas, &idx, &val);
        t["NORMAL"] = w.add_sparse_vec3(static_cast<int>(V), idx, val, false);
      }
      targets.push_back(t);
      target_names.push_back(m.name);
      morph_names.push_back(m.name);
    }
    std::vector<avatar::Primitive> ranges = mesh.primitives;
    if (ranges.empty()) ranges.push_back({0, static_cast<std::uint32_t>(mesh.indices.size()), 0});
    for (const auto& pr : ranges) {
      if (pr.first_index + static_cast<size_t>(pr.index_count) > mesh.indices.size()) continue;
      int idx = w.add(mesh.indices.data() + pr.first_index, pr.index_count * 4u, kUInt,
                      static_cast<int>(pr.index_count), "SCALAR", kElementArrayBuffer);
      nlohmann::json p = {{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"JOINTS_0", jnt}, {"WEIGHTS_0", wgt}}},
                          {"indices", idx}};
      if (pr.material >= 0 && pr.material < static_cast<int>(materials.size())) p["material"] = pr.material;
      if (!targets.empty()) p["targets"] = targets;
      prims.push_back(p);
    }
    gltf["meshes"] = {{{"name", "avatar"}, {"primitives", prims}}};
    if (!targets.empty()) {
      gltf["meshes"][0]["weights"] = std::vector<float>(targets.size(), 0.0f);
      gltf["meshes"][0]["extras"] = {{"targetNames", target_names}};  // the names viewers show
    }
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
  // The face: the clip's morph weights on the mesh node's targets (by name; a target the clip
  // does not drive stays at 0), one weight per target per frame (glTF's "weights" path).
  if (!morph_names.empty() && clip.morph_count() > 0 &&
      clip.morph_weights.size() >= static_cast<size_t>(clip.frame_count) * clip.morph_count()) {
    const size_t M = morph_names.size();
    std::vector<int> from_clip(M, -1);
    for (size_t m = 0; m < M; ++m)
      for (int c = 0; c < clip.morph_count(); ++c)
        if (clip.morph_names[c] == morph_names[m]) from_clip[m] = c;
    std::vector<float> weights(static_cast<size_t>(clip.frame_count) * M, 0.0f);
    for (int f = 0; f < clip.frame_count; ++f)
      for (size_t m = 0; m < M; ++m)
        if (from_clip[m] >= 0)
          weights[f * M + m] = clip.morph_weights[static_cast<size_t>(f) * clip.morph_count() + from_clip[m]];
    int acc = w.add(weights.data(), weights.size() * 4, kFloat, static_cast<int>(weights.size()), "SCALAR");
    samplers.push_back({{"input", input}, {"output", acc}, {"interpolation", "LINEAR"}});
    channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", J}, {"path", "weights"}}}});
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

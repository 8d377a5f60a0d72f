// Avatar pack: writer and checked reader (avatar_pack.h has the layout and the reasons).
#include "avatar/avatar_pack.h"

#include <cmath>
#include <cstring>
#include <type_traits>

#include "skeleton/humanoid_names.h"

namespace sw::avatar {
namespace {

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "avatar_pack reads and writes the host's own floats: little-endian hosts only (avatar_pack.h)"
#endif

constexpr char kMagic[8] = {'S', 'W', 'A', 'V', 'P', 'A', 'C', 'K'};
// A name longer than this is no joint, material, morph or anchor name; it bounds the allocation.
constexpr std::uint32_t kMaxNameBytes = 1024;
// Anchors: ~150 body points plus per-finger ones; far below, and bounds a hostile count.
constexpr std::uint32_t kMaxAnchors = 1u << 16;
constexpr std::uint32_t kMaxMaterials = 1u << 16;

// ----------------------------------------------------------------------------------------- writer
class Writer {
 public:
  template <typename T>
  void pod(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
    out_.insert(out_.end(), p, p + sizeof(T));
  }
  void u32(std::size_t value) { pod(static_cast<std::uint32_t>(value)); }
  void text(const std::string& s) {
    u32(s.size());
    out_.insert(out_.end(), s.begin(), s.end());
  }
  template <typename T>
  void array(const std::vector<T>& values) {   // no count: the caller wrote it
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const std::uint8_t*>(values.data());
    out_.insert(out_.end(), p, p + values.size() * sizeof(T));
  }
  std::vector<std::uint8_t> take() { return std::move(out_); }

 private:
  std::vector<std::uint8_t> out_;
};

bool all_bits_zero(const glm::vec3& v) {
  static constexpr glm::vec3 kZero{0.0f};
  return std::memcmp(&v, &kZero, sizeof v) == 0;   // -0.0 is kept, so the round trip is exact
}

// ----------------------------------------------------------------------------------------- reader
// Reads forward through the bytes; the first failure is kept and every later read fails too, so
// the caller checks once per section. Where names the field for the message.
class Reader {
 public:
  Reader(const std::uint8_t* bytes, std::size_t size) : at_(bytes), end_(bytes + size) {}

  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }
  std::size_t left() const { return static_cast<std::size_t>(end_ - at_); }
  bool at_end() const { return at_ == end_; }

  bool fail(const std::string& where, const std::string& what) {
    if (error_.empty()) error_ = "avatar pack: " + where + ": " + what;
    return false;
  }

  template <typename T>
  bool pod(T* value, const std::string& where) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (failed()) return false;
    if (left() < sizeof(T)) return fail(where, "the file ends early (truncated?)");
    std::memcpy(value, at_, sizeof(T));
    at_ += sizeof(T);
    return true;
  }

  // A count whose items take at least item_bytes each: bounded by the bytes left and by `limit`.
  bool count(std::uint32_t* n, std::size_t item_bytes, std::size_t limit, const std::string& where) {
    if (!pod(n, where)) return false;
    if (*n > limit) return fail(where, std::to_string(*n) + " exceeds the limit of " + std::to_string(limit));
    if (item_bytes && std::size_t(*n) > left() / item_bytes) {
      return fail(where, std::to_string(*n) + " items do not fit in the " + std::to_string(left()) + " bytes left (truncated?)");
    }
    return true;
  }

  bool text(std::string* s, const std::string& where) {
    std::uint32_t n = 0;
    if (!count(&n, 1, kMaxNameBytes, where + " length")) return false;
    s->assign(reinterpret_cast<const char*>(at_), n);
    at_ += n;
    return true;
  }

  template <typename T>
  bool array(std::vector<T>* values, std::size_t n, const std::string& where) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (failed()) return false;
    if (n > left() / sizeof(T)) return fail(where, "the file ends early (truncated?)");
    values->resize(n);
    std::memcpy(values->data(), at_, n * sizeof(T));
    at_ += n * sizeof(T);
    return true;
  }

 private:
  const std::uint8_t* at_;
  const std::uint8_t* end_;
  std::string error_;
};

bool finite(const float* v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}

template <typename Vec>
bool finite_all(const std::vector<Vec>& values, std::size_t* bad) {
  static_assert(sizeof(Vec) % sizeof(float) == 0);
  constexpr std::size_t kFloats = sizeof(Vec) / sizeof(float);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!finite(reinterpret_cast<const float*>(&values[i]), kFloats)) {
      *bad = i;
      return false;
    }
  }
  return true;
}

std::string at(const char* field, std::size_t i) { return std::string(field) + "[" + std::to_string(i) + "]"; }

bool read_skeleton(Reader& r, const LoaderLimits& limits, Avatar* a) {
  // name length + parent + 10 floats: 48 bytes at least per joint.
  std::uint32_t n = 0;
  if (!r.count(&n, 48, limits.max_joints, "joint count")) return false;
  a->skeleton.joints.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    skeleton::Joint& j = a->skeleton.joints[i];
    const std::string where = at("joints", i);
    float t[10];
    if (!r.text(&j.name, where + ".name") || !r.pod(&j.parent, where + ".parent") || !r.pod(&t, where + ".rest")) {
      return false;
    }
    j.rest.translation = {t[0], t[1], t[2]};
    j.rest.rotation = glm::quat(t[3], t[4], t[5], t[6]);
    j.rest.scale = {t[7], t[8], t[9]};
  }
  if (const std::string problem = a->skeleton.validate(); !problem.empty()) return r.fail("skeleton", problem);
  if (!r.array(&a->inverse_bind, n, "inverse_bind")) return false;
  if (std::size_t bad = 0; !finite_all(a->inverse_bind, &bad)) return r.fail(at("inverse_bind", bad), "not finite");
  std::uint32_t canonical = 0;
  if (!r.count(&canonical, 4, std::size_t(skeleton::kHumanoidJointCount), "canonical joint count")) return false;
  if (canonical != std::uint32_t(skeleton::kHumanoidJointCount)) {
    return r.fail("canonical joint count", std::to_string(canonical) + ", expected " +
                                               std::to_string(skeleton::kHumanoidJointCount));
  }
  if (!r.array(&a->canonical_to_joint, canonical, "canonical joints")) return false;
  for (std::size_t id = 0; id < a->canonical_to_joint.size(); ++id) {
    const int j = a->canonical_to_joint[id];
    if (j < -1 || j >= int(n)) return r.fail(at("canonical joints", id), "joint " + std::to_string(j) + " of " + std::to_string(n));
  }
  return true;
}

bool read_mesh(Reader& r, const LoaderLimits& limits, std::size_t joint_count, SkinnedMesh* m) {
  std::uint32_t n = 0;
  // position + normal + joints + weights: 48 bytes per vertex.
  if (!r.count(&n, 48, limits.max_vertices, "vertex count")) return false;
  if (!r.array(&m->positions, n, "positions") || !r.array(&m->normals, n, "normals") ||
      !r.array(&m->joints, n, "joints") || !r.array(&m->weights, n, "weights")) {
    return false;
  }
  std::size_t bad = 0;
  if (!finite_all(m->positions, &bad)) return r.fail(at("positions", bad), "not finite");
  if (!finite_all(m->normals, &bad)) return r.fail(at("normals", bad), "not finite");
  if (!finite_all(m->weights, &bad)) return r.fail(at("weights", bad), "not finite");
  for (std::size_t v = 0; v < m->joints.size(); ++v) {
    for (std::uint16_t j : m->joints[v]) {
      if (j >= joint_count) return r.fail(at("joints", v), "joint " + std::to_string(j) + " of " + std::to_string(joint_count));
    }
  }
  std::uint32_t index_count = 0;
  if (!r.count(&index_count, 4, limits.max_indices, "index count")) return false;
  if (index_count % 3 != 0) return r.fail("index count", std::to_string(index_count) + " is not a multiple of 3 (triangles)");
  if (!r.array(&m->indices, index_count, "indices")) return false;
  for (std::size_t i = 0; i < m->indices.size(); ++i) {
    if (m->indices[i] >= n) return r.fail(at("indices", i), "vertex " + std::to_string(m->indices[i]) + " of " + std::to_string(n));
  }
  std::uint32_t primitive_count = 0, material_count = 0;
  if (!r.count(&primitive_count, sizeof(Primitive), index_count / 3 + 1, "primitive count")) return false;
  if (!r.array(&m->primitives, primitive_count, "primitives")) return false;
  // name length + 6 floats: 28 bytes at least per material.
  if (!r.count(&material_count, 28, kMaxMaterials, "material count")) return false;
  m->materials.resize(material_count);
  for (std::uint32_t i = 0; i < material_count; ++i) {
    Material& mat = m->materials[i];
    float f[6];
    if (!r.text(&mat.name, at("materials", i) + ".name") || !r.pod(&f, at("materials", i))) return false;
    if (!finite(f, 6)) return r.fail(at("materials", i), "not finite");
    mat.base_color = {f[0], f[1], f[2], f[3]};
    mat.roughness = f[4];
    mat.metallic = f[5];
  }
  for (std::size_t i = 0; i < m->primitives.size(); ++i) {
    const Primitive& p = m->primitives[i];
    if (std::uint64_t(p.first_index) + p.index_count > index_count) {
      return r.fail(at("primitives", i), "indices " + std::to_string(p.first_index) + " + " +
                                             std::to_string(p.index_count) + " beyond " + std::to_string(index_count));
    }
    if (p.material < 0 || std::size_t(p.material) >= m->materials.size()) {
      return r.fail(at("primitives", i), "material " + std::to_string(p.material) + " of " + std::to_string(m->materials.size()));
    }
  }
  return true;
}

bool read_morphs(Reader& r, const LoaderLimits& limits, std::size_t vertex_count, std::vector<MorphTarget>* morphs) {
  std::uint32_t n = 0;
  // name length + flag + entry count: 9 bytes at least per morph.
  if (!r.count(&n, 9, limits.max_morph_targets, "morph count")) return false;
  // The dense deltas the Avatar holds: bounded like the glTF loader's (max_morph_floats).
  if (std::size_t(n) * vertex_count * 6 > limits.max_morph_floats) {
    return r.fail("morph count", std::to_string(n) + " morphs of " + std::to_string(vertex_count) +
                                     " vertices exceed the morph delta limit");
  }
  morphs->resize(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    MorphTarget& m = (*morphs)[i];
    const std::string where = at("morphs", i);
    std::uint8_t has_normals = 0;
    std::uint32_t entries = 0;
    if (!r.text(&m.name, where + ".name") || !r.pod(&has_normals, where + ".has_normals")) return false;
    if (has_normals > 1) return r.fail(where + ".has_normals", std::to_string(has_normals) + " is not 0 or 1");
    const std::size_t entry_floats = has_normals ? 6 : 3;
    if (!r.count(&entries, 4 + 4 * entry_floats, vertex_count, where + ".entry count")) return false;
    m.position_deltas.assign(vertex_count, glm::vec3(0.0f));
    if (has_normals) m.normal_deltas.assign(vertex_count, glm::vec3(0.0f));
    std::int64_t previous = -1;
    for (std::uint32_t e = 0; e < entries; ++e) {
      std::uint32_t vertex = 0;
      float d[6];
      if (!r.pod(&vertex, where + ".vertex")) return false;
      if (std::int64_t(vertex) <= previous || vertex >= vertex_count) {
        return r.fail(at((where + ".entries").c_str(), e), "vertex " + std::to_string(vertex) +
                                                              " is out of range or not after the previous one");
      }
      previous = vertex;
      if (!r.pod(&d[0], where) || !r.pod(&d[1], where) || !r.pod(&d[2], where)) return false;
      if (has_normals && (!r.pod(&d[3], where) || !r.pod(&d[4], where) || !r.pod(&d[5], where))) return false;
      if (!finite(d, entry_floats)) return r.fail(at((where + ".entries").c_str(), e), "delta not finite");
      m.position_deltas[vertex] = {d[0], d[1], d[2]};
      if (has_normals) m.normal_deltas[vertex] = {d[3], d[4], d[5]};
    }
  }
  return true;
}

bool read_anchors(Reader& r, std::size_t joint_count, std::vector<Anchor>* anchors) {
  std::uint32_t n = 0;
  // name length + joint + 6 floats: 32 bytes at least per anchor.
  if (!r.count(&n, 32, kMaxAnchors, "anchor count")) return false;
  anchors->resize(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    Anchor& a = (*anchors)[i];
    const std::string where = at("anchors", i);
    float f[6];
    if (!r.text(&a.name, where + ".name") || !r.pod(&a.joint, where + ".joint") || !r.pod(&f, where)) return false;
    if (a.joint < 0 || std::size_t(a.joint) >= joint_count) {
      return r.fail(where, "joint " + std::to_string(a.joint) + " of " + std::to_string(joint_count));
    }
    if (!finite(f, 6)) return r.fail(where, "not finite");
    a.offset = {f[0], f[1], f[2]};
    a.normal = {f[3], f[4], f[5]};
  }
  return true;
}

}  // namespace

bool is_avatar_pack(const std::uint8_t* bytes, std::size_t size) {
  return bytes && size >= sizeof kMagic && std::memcmp(bytes, kMagic, sizeof kMagic) == 0;
}

std::vector<std::uint8_t> pack_avatar(const Avatar& a) {
  Writer w;
  for (char c : kMagic) w.pod(c);
  w.pod(kAvatarPackVersion);
  w.u32(a.skeleton.joints.size());
  for (const skeleton::Joint& j : a.skeleton.joints) {
    w.text(j.name);
    w.pod(std::int32_t(j.parent));
    const math::Transform& t = j.rest;
    const float rest[10] = {t.translation.x, t.translation.y, t.translation.z, t.rotation.w, t.rotation.x,
                            t.rotation.y,    t.rotation.z,    t.scale.x,       t.scale.y,    t.scale.z};
    w.pod(rest);
  }
  w.array(a.inverse_bind);
  w.u32(a.canonical_to_joint.size());
  w.array(a.canonical_to_joint);
  const SkinnedMesh& m = a.mesh;
  w.u32(m.positions.size());
  w.array(m.positions);
  w.array(m.normals);
  w.array(m.joints);
  w.array(m.weights);
  w.u32(m.indices.size());
  w.array(m.indices);
  w.u32(m.primitives.size());
  w.array(m.primitives);
  w.u32(m.materials.size());
  for (const Material& mat : m.materials) {
    w.text(mat.name);
    const float f[6] = {mat.base_color.r, mat.base_color.g, mat.base_color.b, mat.base_color.a, mat.roughness, mat.metallic};
    w.pod(f);
  }
  w.u32(a.morphs.size());
  for (const MorphTarget& morph : a.morphs) {
    const bool normals = !morph.normal_deltas.empty();
    w.text(morph.name);
    w.pod(std::uint8_t(normals ? 1 : 0));
    std::vector<std::uint32_t> moved;
    for (std::size_t v = 0; v < morph.position_deltas.size(); ++v) {
      if (!all_bits_zero(morph.position_deltas[v]) || (normals && !all_bits_zero(morph.normal_deltas[v]))) {
        moved.push_back(static_cast<std::uint32_t>(v));
      }
    }
    w.u32(moved.size());
    for (std::uint32_t v : moved) {
      w.pod(v);
      w.pod(morph.position_deltas[v]);
      if (normals) w.pod(morph.normal_deltas[v]);
    }
  }
  w.u32(a.anchors.size());
  for (const Anchor& anchor : a.anchors) {
    w.text(anchor.name);
    w.pod(std::int32_t(anchor.joint));
    const float f[6] = {anchor.offset.x, anchor.offset.y, anchor.offset.z, anchor.normal.x, anchor.normal.y, anchor.normal.z};
    w.pod(f);
  }
  return w.take();
}

UnpackResult unpack_avatar(const std::uint8_t* bytes, std::size_t size, const LoaderLimits& limits) {
  UnpackResult result;
  if (!is_avatar_pack(bytes, size)) {
    result.error = "avatar pack: not an avatar pack (the file does not start with SWAVPACK)";
    return result;
  }
  if (size > limits.max_file_bytes) {
    result.error = "avatar pack: " + std::to_string(size) + " bytes exceed the limit of " + std::to_string(limits.max_file_bytes);
    return result;
  }
  Reader r(bytes + sizeof kMagic, size - sizeof kMagic);
  std::uint32_t version = 0;
  if (r.pod(&version, "version") && version != kAvatarPackVersion) {
    r.fail("version", std::to_string(version) + ", this reader knows " + std::to_string(kAvatarPackVersion) +
                          " (rebuild the pack: signweave-cli pack-avatar)");
  }
  Avatar& a = result.avatar;
  if (!r.failed() && read_skeleton(r, limits, &a) &&
      read_mesh(r, limits, a.skeleton.joints.size(), &a.mesh) &&
      read_morphs(r, limits, a.mesh.positions.size(), &a.morphs) &&
      read_anchors(r, a.skeleton.joints.size(), &a.anchors) && !r.at_end()) {
    r.fail("end", std::to_string(r.left()) + " bytes after the last section");
  }
  if (r.failed()) {
    result.error = r.error();
    result.avatar = Avatar{};
  }
  return result;
}

}  // namespace sw::avatar

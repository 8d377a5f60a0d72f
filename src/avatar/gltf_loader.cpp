// glTF loader: validation-first reading of a skinned humanoid. See gltf_loader.h.
//
// Two passes over the JSON. First our own: nlohmann in no-throw mode checks the container, the
// nesting depth, the buffers, and drops `images` (tinygltf 2.7.0 would index `img.at(0)` on an empty
// image and throw, which aborts in WASM); the cleaned JSON is handed to tinygltf (compiled here with
// TINYGLTF_NOEXCEPTION so its parse reports instead of throwing). Then everything tinygltf gives us
// is checked before it is indexed.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NOEXCEPTION
#include "avatar/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <utility>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "skeleton/humanoid_names.h"

namespace sw::avatar {
namespace {

using nlohmann::json;

// ----------------------------------------------------------------------------------------------
// Errors as values: each check returns false after recording "where: what".
struct Context {
  const LoaderLimits& limits;
  LoadResult& result;
  bool fail(const std::string& where, const std::string& what) {
    if (result.error.empty()) result.error = where + ": " + what;
    return false;
  }
  void warn(const std::string& what) {
    if (result.warnings.size() < 64) result.warnings.push_back(what);
  }
};

std::uint32_t read_u32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}
void write_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

// One pass over the JSON tree without recursion (a hostile "[[[[..." must not overflow our stack):
// its depth, and whether it holds a number no glTF field can take. Counts, offsets and indices
// are at most 2^32 (the file is at most 4 GiB) and factors/matrices are moderate; larger numbers
// would be cast to size_t/int inside tinygltf, which is undefined behaviour natively.
struct JsonShape {
  int depth = 0;
  bool number_out_of_range = false;
};

JsonShape json_shape(const json& root) {
  JsonShape shape;
  std::vector<std::pair<const json*, int>> stack{{&root, 1}};
  while (!stack.empty()) {
    auto [node, depth] = stack.back();
    stack.pop_back();
    shape.depth = std::max(shape.depth, depth);
    if (depth > 1024) return shape;
    if (node->is_number_float()) {
      if (!(std::abs(node->get<double>()) < 1e15)) shape.number_out_of_range = true;
    } else if (node->is_number_unsigned()) {
      if (node->get<std::uint64_t>() > 0xFFFFFFFFull) shape.number_out_of_range = true;
    } else if (node->is_number_integer()) {
      const std::int64_t v = node->get<std::int64_t>();
      if (v < -0x7FFFFFFFll || v > 0xFFFFFFFFll) shape.number_out_of_range = true;
    } else if (node->is_array() || node->is_object()) {
      for (const auto& child : *node) stack.push_back({&child, depth + 1});
    }
  }
  return shape;
}

const json* find_key(const json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

// The GLB container (glTF 2.0 §4.4): 12-byte header, a JSON chunk, an optional BIN chunk.
struct Container {
  std::string json_text;
  const std::uint8_t* bin = nullptr;
  std::size_t bin_size = 0;
  bool binary = false;
  // The file as given, when tinygltf can read it as it is (GLB chunks 4-byte aligned and adjacent:
  // what any conforming writer makes): then it is handed over without a rebuilt copy.
  const std::uint8_t* file = nullptr;
  std::uint32_t file_length = 0;
  bool tinygltf_can_read_as_is = false;
  bool json_changed = false;  // preflight edited the document (dropped images): pass its dump
};

bool split_container(Context& ctx, const std::uint8_t* bytes, std::size_t size, Container& out) {
  if (size >= 4 && std::memcmp(bytes, "glTF", 4) == 0) {
    out.binary = true;
    if (size < 20) return ctx.fail("GLB header", "file too short (" + std::to_string(size) + " bytes)");
    const std::uint32_t version = read_u32(bytes + 4);
    const std::uint32_t length = read_u32(bytes + 8);
    if (version != 2) return ctx.fail("GLB header", "version " + std::to_string(version) + ", expected 2");
    if (length > size) return ctx.fail("GLB header", "declared length " + std::to_string(length) +
                                                          " exceeds the " + std::to_string(size) + " bytes given");
    const std::uint32_t json_length = read_u32(bytes + 12);
    if (read_u32(bytes + 16) != 0x4E4F534Au) return ctx.fail("GLB chunk 0", "first chunk is not JSON");
    if (std::uint64_t(20) + json_length > length) return ctx.fail("GLB chunk 0", "JSON chunk runs past the end of the file");
    out.json_text.assign(reinterpret_cast<const char*>(bytes + 20), json_length);
    std::uint64_t next = 20ull + json_length;
    next = (next + 3) & ~std::uint64_t(3);
    if (next + 8 <= length) {
      const std::uint32_t bin_length = read_u32(bytes + next);
      const std::uint32_t bin_type = read_u32(bytes + next + 4);
      if (bin_type != 0x004E4942u) return ctx.fail("GLB chunk 1", "second chunk is not BIN");
      if (next + 8 + bin_length > length) return ctx.fail("GLB chunk 1", "BIN chunk runs past the end of the file");
      out.bin = bytes + next + 8;
      out.bin_size = bin_length;
    }
    // tinygltf's own GLB reader (LoadBinaryFromMemory) wants the JSON chunk to end on a 4-byte
    // boundary with the BIN chunk right after it, a whole number of words long, and nothing but
    // those two chunks; anything else this reader tolerates goes through the rebuilt GLB.
    const bool json_aligned = json_length % 4 == 0;
    const bool no_bin = 20ull + json_length == length;
    const bool bin_adjacent = out.bin && next == 20ull + json_length && out.bin_size >= 4 &&
                              out.bin_size % 4 == 0 && next + 8 + out.bin_size == length;
    out.file = bytes;
    out.file_length = length;
    out.tinygltf_can_read_as_is = json_aligned && (no_bin || bin_adjacent);
    return true;
  }
  out.json_text.assign(reinterpret_cast<const char*>(bytes), size);
  return true;
}

// First pass: JSON well-formed and shallow, buffers embedded and non-empty, images dropped.
bool preflight(Context& ctx, Container& container, json& doc) {
  doc = json::parse(container.json_text.begin(), container.json_text.end(), nullptr, false);
  if (doc.is_discarded()) return ctx.fail("JSON", "not well-formed JSON");
  if (!doc.is_object()) return ctx.fail("JSON", "the root is not an object");
  const JsonShape shape = json_shape(doc);
  if (shape.depth > ctx.limits.max_json_depth)
    return ctx.fail("JSON", "nested " + std::to_string(shape.depth) + " levels deep (limit " +
                                std::to_string(ctx.limits.max_json_depth) + ")");
  if (shape.number_out_of_range)
    return ctx.fail("JSON", "a number out of range for any glTF property (above 2^32, or 1e15 for decimals)");
  if (const json* buffers = find_key(doc, "buffers")) {
    if (!buffers->is_array()) return ctx.fail("buffers", "not an array");
    for (std::size_t i = 0; i < buffers->size(); ++i) {
      const json& b = (*buffers)[i];
      const std::string where = "buffers[" + std::to_string(i) + "]";
      const json* length = find_key(b, "byteLength");
      if (!length || !length->is_number_unsigned() || length->get<std::uint64_t>() < 1)
        return ctx.fail(where, "byteLength missing or < 1");
      if (length->get<std::uint64_t>() > ctx.limits.max_file_bytes)
        return ctx.fail(where, "byteLength larger than the file limit");
      const json* uri = find_key(b, "uri");
      if (uri) {
        if (!uri->is_string()) return ctx.fail(where, "uri is not a string");
        const std::string& text = uri->get_ref<const std::string&>();
        if (text.rfind("data:", 0) != 0)
          return ctx.fail(where, "external buffer '" + text.substr(0, 80) +
                                     "' is not supported: embed the buffers (.glb or data: URIs)");
      } else if (!container.binary || !container.bin) {
        return ctx.fail(where, "no uri and no GLB BIN chunk to read it from");
      } else if (i != 0) {
        return ctx.fail(where, "only buffers[0] may refer to the GLB BIN chunk");
      }
    }
  }
  if (doc.contains("images")) {
    ctx.warn("images ignored: the avatar uses material factors only");
    doc.erase("images");
    container.json_changed = true;
  }
  return true;
}

// The checked JSON into tinygltf. A document preflight did not change goes in as the bytes given
// (no dump, no rebuilt GLB: on the page's avatar those were a tenth of the load, and more code for
// WebAssembly to compile on the first call); an edited one is dumped and, for a GLB, a GLB is
// rebuilt around the original BIN chunk.
bool parse_with_tinygltf(Context& ctx, const Container& container, const json& doc, tinygltf::Model& model) {
  tinygltf::TinyGLTF loader;
  tinygltf::FsCallbacks no_files{};
  no_files.FileExists = [](const std::string&, void*) { return false; };
  no_files.ExpandFilePath = [](const std::string& path, void*) { return path; };
  no_files.ReadWholeFile = [](std::vector<unsigned char>*, std::string* err, const std::string&, void*) {
    if (err) *err += "external files are not read";
    return false;
  };
  no_files.WriteWholeFile = [](std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
    return false;
  };
  loader.SetFsCallbacks(no_files);
  std::string err, warn;
  bool ok;
  if (!container.json_changed && container.binary && container.tinygltf_can_read_as_is) {
    ok = loader.LoadBinaryFromMemory(&model, &err, &warn, container.file, container.file_length, "");
  } else if (!container.json_changed && !container.binary) {
    ok = loader.LoadASCIIFromString(&model, &err, &warn, container.json_text.data(),
                                    static_cast<unsigned int>(container.json_text.size()), "");
  } else if (container.binary) {
    const std::string text = doc.dump(-1, ' ', false, json::error_handler_t::replace);
    std::vector<std::uint8_t> glb;
    const std::uint32_t json_padded = static_cast<std::uint32_t>((text.size() + 3) & ~std::size_t(3));
    const std::uint32_t bin_padded = static_cast<std::uint32_t>((container.bin_size + 3) & ~std::size_t(3));
    const std::uint32_t total = 12 + 8 + json_padded + (container.bin ? 8 + bin_padded : 0);
    glb.reserve(total);
    glb.insert(glb.end(), {'g', 'l', 'T', 'F'});
    write_u32(glb, 2);
    write_u32(glb, total);
    write_u32(glb, json_padded);
    write_u32(glb, 0x4E4F534Au);
    glb.insert(glb.end(), text.begin(), text.end());
    glb.resize(20 + json_padded, ' ');
    if (container.bin) {
      write_u32(glb, bin_padded);
      write_u32(glb, 0x004E4942u);
      glb.insert(glb.end(), container.bin, container.bin + container.bin_size);
      glb.resize(total, 0);
    }
    ok = loader.LoadBinaryFromMemory(&model, &err, &warn, glb.data(), static_cast<unsigned int>(glb.size()), "");
  } else {
    const std::string text = doc.dump(-1, ' ', false, json::error_handler_t::replace);
    ok = loader.LoadASCIIFromString(&model, &err, &warn, text.data(), static_cast<unsigned int>(text.size()), "");
  }
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    return ctx.fail("glTF", err.empty() ? "tinygltf rejected the file" : err);
  }
  return true;
}

// ----------------------------------------------------------------------------------------------
// Accessors: every byte they name is checked to lie inside its buffer before it is read.

int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

int component_bytes(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

// A checked view of one accessor's elements.
struct AccessorView {
  const std::uint8_t* data = nullptr;  // null: all zeros (accessor without bufferView)
  std::size_t count = 0;
  std::size_t stride = 0;
  int components = 0;
  int component_type = 0;
  bool normalized = false;

  // Component c of element i as float (normalised integers to [0,1] / [-1,1], glTF §3.11).
  float get(std::size_t i, int c) const {
    if (!data) return 0.0f;
    const std::uint8_t* p = data + i * stride + static_cast<std::size_t>(c) * static_cast<std::size_t>(component_bytes(component_type));
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); return f; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0f : float(p[0]);
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const float v = float(static_cast<std::int8_t>(p[0]));
        return normalized ? std::max(v / 127.0f, -1.0f) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t u; std::memcpy(&u, p, 2); return normalized ? u / 65535.0f : float(u);
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t s; std::memcpy(&s, p, 2);
        return normalized ? std::max(s / 32767.0f, -1.0f) : float(s);
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t u; std::memcpy(&u, p, 4); return float(u); }
      default: return 0.0f;
    }
  }
  // Component c of element i as an unsigned integer (indices, joints).
  std::uint32_t get_uint(std::size_t i, int c) const {
    if (!data) return 0;
    const std::uint8_t* p = data + i * stride + static_cast<std::size_t>(c) * static_cast<std::size_t>(component_bytes(component_type));
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t u; std::memcpy(&u, p, 2); return u; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t u; std::memcpy(&u, p, 4); return u; }
      default: return 0;
    }
  }
};

// Allowed shapes: a list of component types and the element type.
bool view_accessor(Context& ctx, const tinygltf::Model& model, int index, const std::string& what,
                   int type, std::initializer_list<int> component_types, std::size_t max_count,
                   AccessorView& view) {
  const std::string where = what + " (accessors[" + std::to_string(index) + "])";
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
    return ctx.fail(what, "accessor index " + std::to_string(index) + " out of range");
  const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
  if (a.sparse.isSparse) return ctx.fail(where, "sparse accessors are not supported");
  if (a.type != type) return ctx.fail(where, "element type " + std::to_string(a.type) + " is not the one " + what + " needs");
  if (std::find(component_types.begin(), component_types.end(), a.componentType) == component_types.end())
    return ctx.fail(where, "component type " + std::to_string(a.componentType) + " not allowed for " + what);
  if (a.count < 1) return ctx.fail(where, "count is 0");
  if (a.count > max_count)
    return ctx.fail(where, "count " + std::to_string(a.count) + " exceeds the limit " + std::to_string(max_count));
  view = AccessorView{};
  view.count = a.count;
  view.components = component_count(type);
  view.component_type = a.componentType;
  view.normalized = a.normalized;
  const std::size_t element = static_cast<std::size_t>(view.components) * static_cast<std::size_t>(component_bytes(a.componentType));
  if (a.bufferView < 0) return true;  // glTF §3.6.2.3: no bufferView means zeros
  if (static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size())
    return ctx.fail(where, "bufferView " + std::to_string(a.bufferView) + " out of range");
  const tinygltf::BufferView& bv = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const std::string bv_where = "bufferViews[" + std::to_string(a.bufferView) + "]";
  if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= model.buffers.size())
    return ctx.fail(bv_where, "buffer " + std::to_string(bv.buffer) + " out of range");
  const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(bv.buffer)].data;
  const std::uint64_t view_end = std::uint64_t(bv.byteOffset) + std::uint64_t(bv.byteLength);
  if (bv.byteOffset > buffer.size() || view_end > buffer.size())
    return ctx.fail(bv_where, "byteOffset + byteLength (" + std::to_string(view_end) +
                                  ") beyond its buffer (" + std::to_string(buffer.size()) + " bytes)");
  const std::size_t stride = bv.byteStride ? bv.byteStride : element;
  if (stride < element || stride > 252)  // glTF §5.11.4: byteStride in [4, 252]
    return ctx.fail(bv_where, "byteStride " + std::to_string(stride) + " invalid for " +
                                  std::to_string(element) + "-byte elements");
  const std::uint64_t needed = std::uint64_t(a.byteOffset) + std::uint64_t(stride) * (a.count - 1) + element;
  if (needed > bv.byteLength)
    return ctx.fail(where, "byteOffset/count reach byte " + std::to_string(needed) + " of a " +
                               std::to_string(bv.byteLength) + "-byte bufferView");
  view.data = buffer.data() + bv.byteOffset + a.byteOffset;
  view.stride = stride;
  return true;
}

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// ----------------------------------------------------------------------------------------------
// Node graph and skeleton.

bool node_local(Context& ctx, const tinygltf::Node& node, int index, math::Transform& out) {
  const std::string where = "nodes[" + std::to_string(index) + "]";
  out = math::Transform{};
  if (node.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) {
      const double v = node.matrix[static_cast<std::size_t>(i)];
      if (!std::isfinite(v)) return ctx.fail(where, "matrix has a non-finite value");
      glm::value_ptr(m)[i] = static_cast<float>(v);
    }
    // Decompose (no shear, glTF §5.25): translation, per-axis scale, rotation of the rest.
    out.translation = glm::vec3(m[3]);
    glm::vec3 axes[3] = {glm::vec3(m[0]), glm::vec3(m[1]), glm::vec3(m[2])};
    for (int k = 0; k < 3; ++k) out.scale[k] = glm::length(axes[k]);
    if (glm::dot(glm::cross(axes[0], axes[1]), axes[2]) < 0.0f) out.scale.x = -out.scale.x;
    for (int k = 0; k < 3; ++k) {
      if (out.scale[k] == 0.0f) return ctx.fail(where, "matrix has a zero scale axis");
      axes[k] /= out.scale[k];
    }
    out.rotation = glm::normalize(glm::quat_cast(glm::mat3(axes[0], axes[1], axes[2])));
    return true;
  }
  if (!node.matrix.empty()) return ctx.fail(where, "matrix must have 16 values");
  if (!node.translation.empty()) {
    if (node.translation.size() != 3) return ctx.fail(where, "translation must have 3 values");
    out.translation = glm::vec3(float(node.translation[0]), float(node.translation[1]), float(node.translation[2]));
  }
  if (!node.rotation.empty()) {
    if (node.rotation.size() != 4) return ctx.fail(where, "rotation must have 4 values");
    const glm::quat q(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]), float(node.rotation[2]));
    const float len = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    if (!std::isfinite(len) || len < 1e-6f) return ctx.fail(where, "rotation is not a usable quaternion");
    out.rotation = q / len;
  }
  if (!node.scale.empty()) {
    if (node.scale.size() != 3) return ctx.fail(where, "scale must have 3 values");
    out.scale = glm::vec3(float(node.scale[0]), float(node.scale[1]), float(node.scale[2]));
  }
  if (!finite3(out.translation) || !finite3(out.scale)) return ctx.fail(where, "non-finite translation or scale");
  return true;
}

// parent[i] for every node, checking child indices, single parents and the absence of cycles.
bool node_parents(Context& ctx, const tinygltf::Model& model, std::vector<int>& parent) {
  const std::size_t n = model.nodes.size();
  parent.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    for (int child : model.nodes[i].children) {
      const std::string where = "nodes[" + std::to_string(i) + "]";
      if (child < 0 || static_cast<std::size_t>(child) >= n)
        return ctx.fail(where, "child index " + std::to_string(child) + " out of range");
      if (static_cast<std::size_t>(child) == i) return ctx.fail(where, "node is its own child");
      if (parent[static_cast<std::size_t>(child)] != -1)
        return ctx.fail("nodes[" + std::to_string(child) + "]", "node has two parents");
      parent[static_cast<std::size_t>(child)] = static_cast<int>(i);
    }
  }
  // With single parents, a cycle is a walk up that does not reach a root within n steps.
  for (std::size_t i = 0; i < n; ++i) {
    int p = static_cast<int>(i);
    std::size_t steps = 0;
    while (p >= 0 && steps <= n) { p = parent[static_cast<std::size_t>(p)]; ++steps; }
    if (p >= 0) return ctx.fail("nodes[" + std::to_string(i) + "]", "the node hierarchy has a cycle");
  }
  return true;
}

// ----------------------------------------------------------------------------------------------
// Canonical mapping from the VRM extensions (node index -> canonical id).

std::map<int, int> vrm_humanoid(Context& ctx, const json& doc) {
  std::map<int, int> node_to_id;
  const json* extensions = find_key(doc, "extensions");
  if (!extensions) return node_to_id;
  if (const json* vrm1 = find_key(*extensions, "VRMC_vrm")) {
    const json* bones = find_key(*vrm1, "humanoid");
    bones = bones ? find_key(*bones, "humanBones") : nullptr;
    if (bones && bones->is_object()) {
      for (auto it = bones->begin(); it != bones->end(); ++it) {
        const int id = skeleton::canonical_joint_id(it.key());
        const json* node = find_key(it.value(), "node");
        if (id < 0 || !node || !node->is_number_integer()) {
          ctx.warn("VRMC_vrm humanBones." + it.key() + " ignored");
          continue;
        }
        node_to_id[node->get<int>()] = id;
      }
      return node_to_id;
    }
  }
  if (const json* vrm0 = find_key(*extensions, "VRM")) {
    const json* bones = find_key(*vrm0, "humanoid");
    bones = bones ? find_key(*bones, "humanBones") : nullptr;
    if (bones && bones->is_array()) {
      for (const json& entry : *bones) {
        const json* bone = find_key(entry, "bone");
        const json* node = find_key(entry, "node");
        if (!bone || !bone->is_string() || !node || !node->is_number_integer()) continue;
        const int id = skeleton::canonical_joint_id_vrm0(bone->get_ref<const std::string&>());
        if (id >= 0) node_to_id[node->get<int>()] = id;
      }
    }
  }
  return node_to_id;
}

// targetNames of a mesh (mesh.extras.targetNames, the de-facto convention; glTF §3.7.2.2 leaves
// names to extras). Missing or malformed names fall back to "<mesh>_target<k>".
std::vector<std::string> target_names(const json& doc, int mesh_index, const std::string& mesh_name, std::size_t count) {
  std::vector<std::string> names(count);
  const json* meshes = find_key(doc, "meshes");
  const json* names_json = nullptr;
  if (meshes && meshes->is_array() && static_cast<std::size_t>(mesh_index) < meshes->size()) {
    const json* extras = find_key((*meshes)[static_cast<std::size_t>(mesh_index)], "extras");
    names_json = extras ? find_key(*extras, "targetNames") : nullptr;
  }
  for (std::size_t k = 0; k < count; ++k) {
    if (names_json && names_json->is_array() && k < names_json->size() && (*names_json)[k].is_string()) {
      names[k] = (*names_json)[k].get<std::string>();
    } else {
      names[k] = (mesh_name.empty() ? "mesh" + std::to_string(mesh_index) : mesh_name) + "_target" + std::to_string(k);
    }
  }
  return names;
}

// ----------------------------------------------------------------------------------------------

struct Loader {
  Loader(Context& c, const tinygltf::Model& m, const json& d, Avatar& a) : ctx(c), model(m), doc(d), avatar(a) {}
  Context& ctx;
  const tinygltf::Model& model;
  const json& doc;
  Avatar& avatar;
  std::vector<int> node_parent;
  std::vector<int> node_to_joint;      // -1 if the node is not in the skeleton
  std::vector<int> skin_to_joint;      // skin.joints[i] -> skeleton index
  int skin_index = -1;
  std::map<std::string, std::size_t> morph_by_name;
  std::size_t reserve_vertices = 0;    // expected_vertices(), once read_meshes starts

  bool run() {
    if (model.nodes.empty()) return ctx.fail("nodes", "the file has no nodes");
    if (model.nodes.size() > 65536) return ctx.fail("nodes", "more than 65536 nodes");
    if (!node_parents(ctx, model, node_parent)) return false;
    if (!choose_skin()) return false;
    if (!build_skeleton()) return false;
    if (!read_inverse_binds()) return false;
    read_materials();
    if (!read_meshes()) return false;
    if (avatar.mesh.positions.empty()) return ctx.fail("meshes", "no skinned triangles using the skin");
    return map_canonical();
  }

  bool choose_skin() {
    if (model.skins.empty()) return ctx.fail("skins", "the file has no skin (a skinned humanoid is required)");
    // The skin of the first skinned mesh node; other skins' meshes are skipped with a warning.
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      const tinygltf::Node& node = model.nodes[i];
      if (node.mesh >= 0 && node.skin >= 0) {
        if (static_cast<std::size_t>(node.skin) >= model.skins.size())
          return ctx.fail("nodes[" + std::to_string(i) + "]", "skin index " + std::to_string(node.skin) + " out of range");
        skin_index = node.skin;
        return true;
      }
    }
    return ctx.fail("nodes", "no node has both a mesh and a skin");
  }

  bool build_skeleton() {
    const tinygltf::Skin& skin = model.skins[static_cast<std::size_t>(skin_index)];
    const std::string where = "skins[" + std::to_string(skin_index) + "]";
    if (skin.joints.empty()) return ctx.fail(where, "no joints");
    if (skin.joints.size() > ctx.limits.max_joints)
      return ctx.fail(where, std::to_string(skin.joints.size()) + " joints exceed the limit " + std::to_string(ctx.limits.max_joints));
    const std::size_t n = model.nodes.size();
    std::vector<char> in_skeleton(n, 0);
    std::vector<char> in_skin(n, 0);
    for (int j : skin.joints) {
      if (j < 0 || static_cast<std::size_t>(j) >= n)
        return ctx.fail(where, "joint node " + std::to_string(j) + " out of range");
      if (in_skin[static_cast<std::size_t>(j)]) return ctx.fail(where, "joint node " + std::to_string(j) + " listed twice");
      in_skin[static_cast<std::size_t>(j)] = 1;
      // The joint and its ancestors (an "Armature" node often carries the units scale).
      for (int p = j; p >= 0; p = node_parent[static_cast<std::size_t>(p)]) in_skeleton[static_cast<std::size_t>(p)] = 1;
    }
    // Non-deforming descendants of joints (fingertip points, "_end" nodes) join too; mesh
    // nodes do not (they are what is skinned, not bones).
    for (std::size_t i = 0; i < n; ++i) {
      if (in_skeleton[i] || model.nodes[i].mesh >= 0) continue;
      bool under_joint = false;
      for (int p = node_parent[i]; p >= 0; p = node_parent[static_cast<std::size_t>(p)]) {
        if (in_skin[static_cast<std::size_t>(p)]) { under_joint = true; break; }
        if (model.nodes[static_cast<std::size_t>(p)].mesh >= 0) break;
      }
      if (under_joint) in_skeleton[i] = 1;
    }
    // Parents before children: depth-first from each root, children in file order.
    node_to_joint.assign(n, -1);
    std::vector<int> order;
    std::vector<int> stack;
    for (std::size_t root = 0; root < n; ++root) {
      if (!in_skeleton[root] || (node_parent[root] >= 0 && in_skeleton[static_cast<std::size_t>(node_parent[root])])) continue;
      stack.push_back(static_cast<int>(root));
      while (!stack.empty()) {
        const int node = stack.back();
        stack.pop_back();
        order.push_back(node);
        const auto& children = model.nodes[static_cast<std::size_t>(node)].children;
        for (auto it = children.rbegin(); it != children.rend(); ++it) {
          if (in_skeleton[static_cast<std::size_t>(*it)]) stack.push_back(*it);
        }
      }
    }
    if (order.size() > ctx.limits.max_joints)
      return ctx.fail(where, "skeleton of " + std::to_string(order.size()) + " nodes exceeds the joint limit");
    avatar.skeleton.joints.clear();
    for (std::size_t k = 0; k < order.size(); ++k) node_to_joint[static_cast<std::size_t>(order[k])] = static_cast<int>(k);
    for (int node_index : order) {
      const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(node_index)];
      skeleton::Joint joint;
      joint.name = node.name.empty() ? "node" + std::to_string(node_index) : node.name;
      const int p = node_parent[static_cast<std::size_t>(node_index)];
      joint.parent = p >= 0 ? node_to_joint[static_cast<std::size_t>(p)] : -1;
      if (!node_local(ctx, node, node_index, joint.rest)) return false;
      avatar.skeleton.joints.push_back(std::move(joint));
    }
    // A skeleton root's non-skeleton ancestors cannot exist (ancestors of joints were added), so
    // the roots' rest transforms are already in scene space.
    skin_to_joint.clear();
    for (int j : skin.joints) skin_to_joint.push_back(node_to_joint[static_cast<std::size_t>(j)]);
    return true;
  }

  std::vector<glm::mat4> rest_model_matrices() const {
    std::vector<glm::mat4> models(avatar.skeleton.joints.size());
    for (std::size_t i = 0; i < models.size(); ++i) {
      const skeleton::Joint& joint = avatar.skeleton.joints[i];
      const math::Transform& t = joint.rest;
      glm::mat4 local = glm::mat4_cast(t.rotation);
      local[0] *= t.scale.x; local[1] *= t.scale.y; local[2] *= t.scale.z;
      local[3] = glm::vec4(t.translation, 1.0f);
      models[i] = joint.parent >= 0 ? models[static_cast<std::size_t>(joint.parent)] * local : local;
    }
    return models;
  }

  bool read_inverse_binds() {
    const tinygltf::Skin& skin = model.skins[static_cast<std::size_t>(skin_index)];
    // Joints outside the glTF skin get the inverse of their rest model matrix, so an anchor or
    // tip attached to them has the same "bind space" meaning as for skinned joints.
    const std::vector<glm::mat4> rest = rest_model_matrices();
    avatar.inverse_bind.resize(rest.size());
    for (std::size_t i = 0; i < rest.size(); ++i) avatar.inverse_bind[i] = glm::inverse(rest[i]);
    if (skin.inverseBindMatrices < 0) return true;  // glTF §5.24: absent means identity
    AccessorView view;
    if (!view_accessor(ctx, model, skin.inverseBindMatrices, "inverseBindMatrices", TINYGLTF_TYPE_MAT4,
                       {TINYGLTF_COMPONENT_TYPE_FLOAT}, ctx.limits.max_joints, view))
      return false;
    if (view.count != skin.joints.size())
      return ctx.fail("inverseBindMatrices", std::to_string(view.count) + " matrices for " +
                                                 std::to_string(skin.joints.size()) + " joints");
    for (std::size_t j = 0; j < view.count; ++j) {
      glm::mat4 m;
      for (int c = 0; c < 16; ++c) {
        const float v = view.get(j, c);
        if (!std::isfinite(v)) return ctx.fail("inverseBindMatrices", "matrix " + std::to_string(j) + " has a non-finite value");
        glm::value_ptr(m)[c] = v;
      }
      avatar.inverse_bind[static_cast<std::size_t>(skin_to_joint[j])] = m;
    }
    return true;
  }

  void read_materials() {
    for (const tinygltf::Material& m : model.materials) {
      Material out;
      out.name = m.name;
      const auto& f = m.pbrMetallicRoughness.baseColorFactor;
      if (f.size() == 4) {
        for (int k = 0; k < 4; ++k) {
          const double v = f[static_cast<std::size_t>(k)];
          if (std::isfinite(v)) out.base_color[k] = static_cast<float>(std::clamp(v, 0.0, 1.0));
        }
      }
      if (std::isfinite(m.pbrMetallicRoughness.roughnessFactor))
        out.roughness = static_cast<float>(std::clamp(m.pbrMetallicRoughness.roughnessFactor, 0.0, 1.0));
      if (std::isfinite(m.pbrMetallicRoughness.metallicFactor))
        out.metallic = static_cast<float>(std::clamp(m.pbrMetallicRoughness.metallicFactor, 0.0, 1.0));
      avatar.mesh.materials.push_back(out);
    }
  }

  int default_material_index = -1;
  int default_material() {
    // One grey default after the file's materials, added on first use (glTF §3.9.6).
    if (default_material_index < 0) {
      Material m;
      m.name = "default";
      avatar.mesh.materials.push_back(m);
      default_material_index = static_cast<int>(avatar.mesh.materials.size()) - 1;
    }
    return default_material_index;
  }

  bool read_meshes() {
    reserve_vertices = expected_vertices();
    auto& m = avatar.mesh;
    m.positions.reserve(reserve_vertices);
    m.normals.reserve(reserve_vertices);
    m.joints.reserve(reserve_vertices);
    m.weights.reserve(reserve_vertices);
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      const tinygltf::Node& node = model.nodes[i];
      if (node.mesh < 0) continue;
      const std::string where = "nodes[" + std::to_string(i) + "]";
      if (static_cast<std::size_t>(node.mesh) >= model.meshes.size())
        return ctx.fail(where, "mesh index " + std::to_string(node.mesh) + " out of range");
      if (node.skin != skin_index) {
        ctx.warn(where + " '" + node.name + "': mesh not skinned by the avatar's skin, ignored");
        continue;
      }
      const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(node.mesh)];
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        if (!read_primitive(node.mesh, mesh, p)) return false;
      }
    }
    // Morph targets cover every vertex: primitives added before a target first appeared, or
    // without it, get zero deltas.
    const std::size_t n = avatar.mesh.positions.size();
    for (MorphTarget& t : avatar.morphs) {
      t.position_deltas.resize(n, glm::vec3(0.0f));
      if (!t.normal_deltas.empty()) t.normal_deltas.resize(n, glm::vec3(0.0f));
    }
    return true;
  }

  // The merged vertex count the skinned primitives declare, to size the arrays once: growing every
  // morph target's deltas primitive by primitive re-copied them at each step, which was the
  // largest cost of loading the avatar in the page. Only a hint (accessors are checked when read),
  // so it is capped by the vertex limit, and 0 when the declared counts make no sense.
  std::size_t expected_vertices() const {
    std::size_t total = 0;
    for (const tinygltf::Node& node : model.nodes) {
      if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= model.meshes.size() || node.skin != skin_index) continue;
      for (const tinygltf::Primitive& prim : model.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
        const auto pos = prim.attributes.find("POSITION");
        if (pos == prim.attributes.end() || pos->second < 0 || static_cast<std::size_t>(pos->second) >= model.accessors.size())
          continue;
        total += model.accessors[static_cast<std::size_t>(pos->second)].count;
        if (total > ctx.limits.max_vertices) return 0;
      }
    }
    return total;
  }

  // Room for a morph target's full deltas, if the delta budget allows that many targets at the
  // expected size (otherwise the budget check in read_primitive reports the problem).
  void reserve_deltas(std::vector<glm::vec3>& deltas) const {
    if (deltas.capacity() >= reserve_vertices) return;
    if (reserve_vertices * 6 * avatar.morphs.size() > ctx.limits.max_morph_floats) return;
    deltas.reserve(reserve_vertices);
  }

  bool read_vec3s(int accessor, const std::string& what, std::size_t count, std::vector<glm::vec3>& out,
                  std::initializer_list<int> component_types = {TINYGLTF_COMPONENT_TYPE_FLOAT}) {
    AccessorView view;
    if (!view_accessor(ctx, model, accessor, what, TINYGLTF_TYPE_VEC3, component_types, ctx.limits.max_vertices, view))
      return false;
    if (view.count != count)
      return ctx.fail(what, "accessors[" + std::to_string(accessor) + "] has " + std::to_string(view.count) +
                                " elements for " + std::to_string(count) + " vertices");
    out.resize(count);
    // Plain floats (every position, normal and morph delta of a usual file): one 12-byte copy per
    // element instead of three converted reads — the same values, a sixth of the avatar's load.
    const bool plain_floats = view.data && view.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT;
    for (std::size_t v = 0; v < count; ++v) {
      if (plain_floats) std::memcpy(&out[v], view.data + v * view.stride, sizeof(glm::vec3));
      else out[v] = glm::vec3(view.get(v, 0), view.get(v, 1), view.get(v, 2));
      if (!finite3(out[v])) return ctx.fail(what, "vertex " + std::to_string(v) + " is not finite");
    }
    return true;
  }

  bool read_primitive(int mesh_index, const tinygltf::Mesh& mesh, std::size_t p) {
    const tinygltf::Primitive& prim = mesh.primitives[p];
    const std::string where = "meshes[" + std::to_string(mesh_index) + "].primitives[" + std::to_string(p) + "]";
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
      ctx.warn(where + ": mode " + std::to_string(prim.mode) + " is not TRIANGLES, skipped");
      return true;
    }
    const auto attr = [&](const char* name) {
      const auto it = prim.attributes.find(name);
      return it == prim.attributes.end() ? -1 : it->second;
    };
    const int position_accessor = attr("POSITION");
    if (position_accessor < 0) return ctx.fail(where, "no POSITION attribute");
    if (attr("JOINTS_0") < 0 || attr("WEIGHTS_0") < 0) return ctx.fail(where, "no JOINTS_0/WEIGHTS_0 (not skinned)");
    if (position_accessor >= static_cast<int>(model.accessors.size()))
      return ctx.fail(where, "POSITION accessor out of range");
    const std::size_t count = model.accessors[static_cast<std::size_t>(position_accessor)].count;
    const std::size_t base = avatar.mesh.positions.size();
    if (count > ctx.limits.max_vertices || base + count > ctx.limits.max_vertices)
      return ctx.fail(where, "vertex count exceeds the limit " + std::to_string(ctx.limits.max_vertices));

    std::vector<glm::vec3> positions, normals;
    if (!read_vec3s(position_accessor, where + " POSITION", count, positions)) return false;
    if (attr("NORMAL") >= 0 && !read_vec3s(attr("NORMAL"), where + " NORMAL", count, normals)) return false;

    // Influences: JOINTS_0/WEIGHTS_0 and, if present, JOINTS_1/WEIGHTS_1; keep the 4 strongest.
    std::vector<std::array<std::uint16_t, kMaxInfluences>> joints(count);
    std::vector<glm::vec4> weights(count);
    std::vector<std::pair<float, std::uint32_t>> influences;
    AccessorView jv[2], wv[2];
    int sets = 0;
    for (int s = 0; s < 2; ++s) {
      const int ja = attr(s == 0 ? "JOINTS_0" : "JOINTS_1");
      const int wa = attr(s == 0 ? "WEIGHTS_0" : "WEIGHTS_1");
      if (ja < 0 || wa < 0) break;
      const std::string set = where + (s == 0 ? " JOINTS_0/WEIGHTS_0" : " JOINTS_1/WEIGHTS_1");
      if (!view_accessor(ctx, model, ja, set, TINYGLTF_TYPE_VEC4,
                         {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                         ctx.limits.max_vertices, jv[s]) ||
          !view_accessor(ctx, model, wa, set, TINYGLTF_TYPE_VEC4,
                         {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                         ctx.limits.max_vertices, wv[s]))
        return false;
      if (jv[s].count != count || wv[s].count != count)
        return ctx.fail(set, "element counts differ from the " + std::to_string(count) + " positions");
      if (wv[s].component_type != TINYGLTF_COMPONENT_TYPE_FLOAT && !wv[s].normalized)
        return ctx.fail(set, "integer weights must be normalized");
      ++sets;
    }
    const std::size_t skin_joints = skin_to_joint.size();
    for (std::size_t v = 0; v < count; ++v) {
      influences.clear();
      for (int s = 0; s < sets; ++s) {
        for (int k = 0; k < 4; ++k) {
          const std::uint32_t j = jv[s].get_uint(v, k);
          const float w = wv[s].get(v, k);
          if (!std::isfinite(w) || w < 0.0f)
            return ctx.fail(where, "vertex " + std::to_string(v) + " has a negative or non-finite weight");
          if (w == 0.0f) continue;
          if (j >= skin_joints)
            return ctx.fail(where, "vertex " + std::to_string(v) + " uses joint " + std::to_string(j) +
                                       " of a skin with " + std::to_string(skin_joints) + " joints");
          influences.push_back({w, static_cast<std::uint32_t>(skin_to_joint[j])});
        }
      }
      std::sort(influences.begin(), influences.end(),
                [](const auto& a, const auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); });
      if (influences.size() > kMaxInfluences) influences.resize(kMaxInfluences);
      float sum = 0.0f;
      for (const auto& inf : influences) sum += inf.first;
      if (!(sum > 1e-6f))
        return ctx.fail(where, "vertex " + std::to_string(v) + " has no positive weight");
      joints[v].fill(static_cast<std::uint16_t>(influences[0].second));  // unused slots: weight 0
      weights[v] = glm::vec4(0.0f);
      for (std::size_t k = 0; k < influences.size(); ++k) {
        joints[v][k] = static_cast<std::uint16_t>(influences[k].second);
        weights[v][static_cast<int>(k)] = influences[k].first / sum;
      }
    }

    // Indices (absent: the vertices in order, glTF §3.7.2.1).
    std::vector<std::uint32_t> indices;
    if (prim.indices >= 0) {
      AccessorView iv;
      if (!view_accessor(ctx, model, prim.indices, where + " indices", TINYGLTF_TYPE_SCALAR,
                         {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                         ctx.limits.max_indices, iv))
        return false;
      indices.resize(iv.count);
      for (std::size_t i = 0; i < iv.count; ++i) {
        indices[i] = iv.get_uint(i, 0);
        if (indices[i] >= count)
          return ctx.fail(where + " indices", "index " + std::to_string(indices[i]) + " at " + std::to_string(i) +
                                                  " out of range for " + std::to_string(count) + " vertices");
      }
    } else {
      indices.resize(count);
      for (std::size_t i = 0; i < count; ++i) indices[i] = static_cast<std::uint32_t>(i);
    }
    if (indices.size() % 3 != 0) return ctx.fail(where + " indices", "count " + std::to_string(indices.size()) + " is not a multiple of 3");
    if (avatar.mesh.indices.size() + indices.size() > ctx.limits.max_indices)
      return ctx.fail(where, "index count exceeds the limit " + std::to_string(ctx.limits.max_indices));

    if (normals.empty()) normals = smooth_normals(positions, indices);

    // Morph targets of this primitive, merged by name across primitives.
    const std::vector<std::string> names = target_names(doc, mesh_index, mesh.name, prim.targets.size());
    for (std::size_t k = 0; k < prim.targets.size(); ++k) {
      const auto& target = prim.targets[k];
      const std::string twhere = where + " targets[" + std::to_string(k) + "]";
      std::size_t slot;
      const auto found = morph_by_name.find(names[k]);
      if (found == morph_by_name.end()) {
        if (avatar.morphs.size() >= ctx.limits.max_morph_targets)
          return ctx.fail(twhere, "more than " + std::to_string(ctx.limits.max_morph_targets) + " morph targets");
        slot = avatar.morphs.size();
        morph_by_name[names[k]] = slot;
        MorphTarget t;
        t.name = names[k];
        avatar.morphs.push_back(std::move(t));
      } else {
        slot = found->second;
      }
      MorphTarget& out = avatar.morphs[slot];
      // Dense deltas cost 2 x 3 floats per vertex per target: cap the total.
      const std::size_t floats_after = (base + count) * 6 * avatar.morphs.size();
      if (floats_after > ctx.limits.max_morph_floats)
        return ctx.fail(twhere, "morph targets would need " + std::to_string(floats_after) + " floats (limit " +
                                    std::to_string(ctx.limits.max_morph_floats) + ")");
      std::vector<glm::vec3> deltas;
      const auto pos = target.find("POSITION");
      if (pos != target.end()) {
        if (!read_vec3s(pos->second, twhere + " POSITION", count, deltas,
                        {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT}))
          return false;
        reserve_deltas(out.position_deltas);
        out.position_deltas.resize(base, glm::vec3(0.0f));
        out.position_deltas.insert(out.position_deltas.end(), deltas.begin(), deltas.end());
      }
      const auto nrm = target.find("NORMAL");
      if (nrm != target.end()) {
        if (!read_vec3s(nrm->second, twhere + " NORMAL", count, deltas,
                        {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT}))
          return false;
        reserve_deltas(out.normal_deltas);
        out.normal_deltas.resize(base, glm::vec3(0.0f));
        out.normal_deltas.insert(out.normal_deltas.end(), deltas.begin(), deltas.end());
      }
    }

    Primitive out_prim;
    out_prim.first_index = static_cast<std::uint32_t>(avatar.mesh.indices.size());
    out_prim.index_count = static_cast<std::uint32_t>(indices.size());
    if (prim.material >= 0 && static_cast<std::size_t>(prim.material) < model.materials.size()) {
      out_prim.material = prim.material;
    } else {
      if (prim.material >= 0) ctx.warn(where + ": material index out of range, default used");
      out_prim.material = default_material();
    }
    avatar.mesh.primitives.push_back(out_prim);
    for (std::uint32_t i : indices) avatar.mesh.indices.push_back(static_cast<std::uint32_t>(base) + i);
    auto& m = avatar.mesh;
    m.positions.insert(m.positions.end(), positions.begin(), positions.end());
    m.normals.insert(m.normals.end(), normals.begin(), normals.end());
    m.joints.insert(m.joints.end(), joints.begin(), joints.end());
    m.weights.insert(m.weights.end(), weights.begin(), weights.end());
    return true;
  }

  // Area-weighted vertex normals for primitives without NORMAL (glTF §3.7.2.1 says flat normals;
  // a skin reads better smooth, and the avatar's own file always has normals).
  static std::vector<glm::vec3> smooth_normals(const std::vector<glm::vec3>& positions,
                                               const std::vector<std::uint32_t>& indices) {
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
      const glm::vec3& a = positions[indices[t]];
      const glm::vec3& b = positions[indices[t + 1]];
      const glm::vec3& c = positions[indices[t + 2]];
      const glm::vec3 n = glm::cross(b - a, c - a);
      for (int k = 0; k < 3; ++k) normals[indices[t + static_cast<std::size_t>(k)]] += n;
    }
    for (glm::vec3& n : normals) {
      const float len = glm::length(n);
      n = len > 1e-20f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    return normals;
  }

  bool map_canonical() {
    avatar.canonical_to_joint.assign(skeleton::kHumanoidJointCount, -1);
    const std::map<int, int> vrm = vrm_humanoid(ctx, doc);
    if (!vrm.empty()) {
      for (const auto& [node, id] : vrm) {
        if (node < 0 || static_cast<std::size_t>(node) >= node_to_joint.size() || node_to_joint[static_cast<std::size_t>(node)] < 0) {
          ctx.warn("VRM humanoid bone " + std::string(skeleton::humanoid_joint_name(id)) + " is not in the skeleton");
          continue;
        }
        avatar.canonical_to_joint[static_cast<std::size_t>(id)] = node_to_joint[static_cast<std::size_t>(node)];
      }
      // Tips are not VRM bones: take them from names when the extension lacks them.
      std::vector<std::string> names;
      for (const auto& j : avatar.skeleton.joints) names.push_back(j.name);
      const std::vector<int> ids = skeleton::map_humanoid_names(names);
      for (std::size_t j = 0; j < ids.size(); ++j) {
        if (ids[j] >= 0 && avatar.canonical_to_joint[static_cast<std::size_t>(ids[j])] < 0)
          avatar.canonical_to_joint[static_cast<std::size_t>(ids[j])] = static_cast<int>(j);
      }
    } else {
      std::vector<std::string> names;
      for (const auto& j : avatar.skeleton.joints) names.push_back(j.name);
      const std::vector<int> ids = skeleton::map_humanoid_names(names);
      for (std::size_t j = 0; j < ids.size(); ++j) {
        if (ids[j] >= 0) avatar.canonical_to_joint[static_cast<std::size_t>(ids[j])] = static_cast<int>(j);
      }
    }
    std::string missing;
    for (int id = 0; id < skeleton::kHumanoidJointCount; ++id) {
      if (skeleton::humanoid_joint_required(id) && avatar.canonical_to_joint[static_cast<std::size_t>(id)] < 0) {
        if (!missing.empty()) missing += ", ";
        missing += skeleton::humanoid_joint_name(id);
      }
    }
    if (!missing.empty()) return ctx.fail("skeleton", "missing required joints: " + missing);
    return true;
  }
};

}  // namespace

LoadResult load_avatar(const std::uint8_t* bytes, std::size_t size, const LoaderLimits& limits) {
  LoadResult result;
  Context ctx{limits, result};
  if (!bytes || size == 0) { ctx.fail("file", "empty"); return result; }
  if (size > limits.max_file_bytes) { ctx.fail("file", std::to_string(size) + " bytes exceed the limit"); return result; }
  if (size > 0xFFFFFFF0u) { ctx.fail("file", "larger than 4 GiB"); return result; }
  Container container;
  json doc;
  tinygltf::Model model;
  if (!split_container(ctx, bytes, size, container) || !preflight(ctx, container, doc) ||
      !parse_with_tinygltf(ctx, container, doc, model))
    return result;
  Loader loader(ctx, model, doc, result.avatar);
  if (!loader.run()) result.avatar = Avatar{};
  return result;
}

LoadResult load_avatar_file(const std::string& path, const LoaderLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    LoadResult r;
    r.error = path + ": cannot be opened";
    return r;
  }
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return load_avatar(bytes.data(), bytes.size(), limits);
}

}  // namespace sw::avatar

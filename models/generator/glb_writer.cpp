// GLB writer; see glb_writer.h.
#include "glb_writer.h"

#include <cstring>
#include <fstream>

namespace sw::avatar_generator {

namespace {
constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

void append_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}
}  // namespace

int GlbBuilder::add_view(const void* data, std::size_t bytes, int target, std::size_t stride) {
  while (binary_.size() % 4 != 0) binary_.push_back(0);  // §3.6.2.4 alignment
  nlohmann::json view = {{"buffer", 0}, {"byteOffset", binary_.size()}, {"byteLength", bytes}};
  if (target != 0) view["target"] = target;
  if (stride != 0) view["byteStride"] = stride;
  const auto* begin = static_cast<const std::uint8_t*>(data);
  binary_.insert(binary_.end(), begin, begin + bytes);
  auto& views = document_["bufferViews"];
  views.push_back(view);
  return static_cast<int>(views.size()) - 1;
}

int GlbBuilder::add_accessor(int view, int component_type, std::size_t count, const char* type) {
  nlohmann::json accessor = {{"componentType", component_type}, {"count", count}, {"type", type}};
  if (view >= 0) accessor["bufferView"] = view;
  auto& accessors = document_["accessors"];
  accessors.push_back(accessor);
  return static_cast<int>(accessors.size()) - 1;
}

int GlbBuilder::add_vec3(const std::vector<glm::vec3>& values, bool with_bounds,
                         bool vertex_attribute) {
  const int view = add_view(values.data(), values.size() * sizeof(glm::vec3),
                            vertex_attribute ? kArrayBuffer : 0);
  const int accessor = add_accessor(view, kFloat, values.size(), "VEC3");
  if (with_bounds && !values.empty()) {
    glm::vec3 lo = values[0], hi = values[0];
    for (const glm::vec3& v : values) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
    document_["accessors"][accessor]["min"] = {lo.x, lo.y, lo.z};
    document_["accessors"][accessor]["max"] = {hi.x, hi.y, hi.z};
  }
  return accessor;
}

int GlbBuilder::add_vec4(const std::vector<glm::vec4>& values) {
  const int view = add_view(values.data(), values.size() * sizeof(glm::vec4), kArrayBuffer);
  return add_accessor(view, kFloat, values.size(), "VEC4");
}

int GlbBuilder::add_joints_u16(const std::vector<std::uint16_t>& values_x4) {
  const int view = add_view(values_x4.data(), values_x4.size() * 2, kArrayBuffer);
  return add_accessor(view, kUnsignedShort, values_x4.size() / 4, "VEC4");
}

int GlbBuilder::add_mat4(const std::vector<glm::mat4>& values) {
  const int view = add_view(values.data(), values.size() * sizeof(glm::mat4), 0);
  return add_accessor(view, kFloat, values.size(), "MAT4");
}

int GlbBuilder::add_indices(const std::vector<std::uint32_t>& indices) {
  std::uint32_t largest = 0;
  for (std::uint32_t i : indices) largest = std::max(largest, i);
  if (largest < 65535) {
    std::vector<std::uint16_t> narrow(indices.begin(), indices.end());
    const int view = add_view(narrow.data(), narrow.size() * 2, kElementArrayBuffer);
    return add_accessor(view, kUnsignedShort, narrow.size(), "SCALAR");
  }
  const int view = add_view(indices.data(), indices.size() * 4, kElementArrayBuffer);
  return add_accessor(view, kUnsignedInt, indices.size(), "SCALAR");
}

std::vector<std::uint8_t> GlbBuilder::serialise() const {
  nlohmann::json document = document_;
  std::vector<std::uint8_t> binary = binary_;
  while (binary.size() % 4 != 0) binary.push_back(0);
  document["buffers"] = nlohmann::json::array({{{"byteLength", binary.size()}}});
  std::string json = document.dump();
  while (json.size() % 4 != 0) json.push_back(' ');

  std::vector<std::uint8_t> out;
  const std::size_t total = 12 + 8 + json.size() + 8 + binary.size();
  out.reserve(total);
  append_u32(out, 0x46546C67u);  // "glTF"
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(total));
  append_u32(out, static_cast<std::uint32_t>(json.size()));
  append_u32(out, 0x4E4F534Au);  // "JSON"
  out.insert(out.end(), json.begin(), json.end());
  append_u32(out, static_cast<std::uint32_t>(binary.size()));
  append_u32(out, 0x004E4942u);  // "BIN\0"
  out.insert(out.end(), binary.begin(), binary.end());
  return out;
}

bool GlbBuilder::write(const std::string& path, std::string* error) const {
  const std::vector<std::uint8_t> bytes = serialise();
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) {
    if (error) *error = "cannot open " + path + " for writing";
    return false;
  }
  file.write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
  if (!file) {
    if (error) *error = "write to " + path + " failed";
    return false;
  }
  return true;
}

}  // namespace sw::avatar_generator

// GLB writer: a minimal, deterministic glTF 2.0 binary container builder — a JSON document
// (nlohmann, keys sorted, so the same model gives the same bytes) plus one binary buffer.
//
// Owns: buffer views, accessors (with the min/max glTF requires for POSITION) and the GLB
// framing (glTF 2.0 §4.4: 12-byte header, JSON chunk padded with spaces, BIN chunk padded with
// zeros, every chunk 4-byte aligned). Does not: validate the scene graph it is given, write
// textures or images (the avatar uses flat PBR colours).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace sw::avatar_generator {

class GlbBuilder {
 public:
  nlohmann::json& document() { return document_; }

  // Accessors append their data to the one binary buffer, each in its own buffer view.
  int add_vec3(const std::vector<glm::vec3>& values, bool with_bounds, bool vertex_attribute);
  int add_vec4(const std::vector<glm::vec4>& values);
  int add_joints_u16(const std::vector<std::uint16_t>& values_x4);
  int add_mat4(const std::vector<glm::mat4>& values);
  int add_indices(const std::vector<std::uint32_t>& indices);  // u16 when every index fits
  // Serialises to GLB bytes; then writes them. Returns false with `error` on I/O failure.
  std::vector<std::uint8_t> serialise() const;
  bool write(const std::string& path, std::string* error) const;

 private:
  int add_view(const void* data, std::size_t bytes, int target, std::size_t stride = 0);
  int add_accessor(int view, int component_type, std::size_t count, const char* type);

  nlohmann::json document_ = nlohmann::json::object();
  std::vector<std::uint8_t> binary_;
};

}  // namespace sw::avatar_generator

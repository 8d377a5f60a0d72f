// MorphJob: applies morph targets (glTF 2.0 §3.7.2.2) to the rest mesh before skinning —
//   p = p_rest + Σ_k w_k Δp_k,   n = n_rest + Σ_k w_k Δn_k
// into caller-owned buffers. Targets with a zero weight cost nothing, and each target may carry
// the vertex range its non-zero deltas span (face morphs touch only the head's vertices), so a
// frame with a few active face channels costs a few thousand vertices, not the whole mesh.
//
// Does NOT: renormalise normals (the skinning output is normalised by the page's shader).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "avatar/avatar.h"

namespace sw::skinning {

// Half-open range [first, end) of vertices with a non-zero delta in a morph target.
struct VertexRange {
  std::uint32_t first = 0;
  std::uint32_t end = 0;
};

// The range of vertices each target actually moves (end == first when it moves none).
std::vector<VertexRange> morph_vertex_ranges(const std::vector<avatar::MorphTarget>& targets);

struct MorphJob {
  int vertex_count = 0;
  const glm::vec3* rest_positions = nullptr;  // vertex_count
  const glm::vec3* rest_normals = nullptr;    // vertex_count, or null: no normal output
  const avatar::MorphTarget* targets = nullptr;
  int target_count = 0;
  const VertexRange* ranges = nullptr;  // optional, target_count (morph_vertex_ranges)
  const float* weights = nullptr;       // target_count, finite
  glm::vec3* out_positions = nullptr;   // vertex_count
  glm::vec3* out_normals = nullptr;     // vertex_count when rest_normals is set

  std::string validate() const;
  bool run() const;
};

}  // namespace sw::skinning

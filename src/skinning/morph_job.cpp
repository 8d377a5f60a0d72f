// MorphJob: morph targets before skinning. See morph_job.h.
#include "skinning/morph_job.h"

#include <cmath>
#include <cstring>

namespace sw::skinning {

std::vector<VertexRange> morph_vertex_ranges(const std::vector<avatar::MorphTarget>& targets) {
  // Scanned inward from both ends: a face target moves a few hundred vertices of ~20,000, so
  // the first and last moved vertex are found without reading the still middle (the avatar's
  // load ran this over every delta of every target, a tenth of the page's avatar start-up).
  std::vector<VertexRange> ranges(targets.size());
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const avatar::MorphTarget& target = targets[t];
    const std::size_t n = target.position_deltas.size();
    auto moves = [&target](std::size_t v) {
      return target.position_deltas[v] != glm::vec3(0.0f) ||
             (v < target.normal_deltas.size() && target.normal_deltas[v] != glm::vec3(0.0f));
    };
    std::size_t first = 0;
    while (first < n && !moves(first)) ++first;
    if (first == n) {
      ranges[t] = VertexRange{0, 0};
      continue;
    }
    std::size_t last = n - 1;
    while (last > first && !moves(last)) --last;
    ranges[t] =
        VertexRange{static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(last + 1)};
  }
  return ranges;
}

std::string MorphJob::validate() const {
  if (vertex_count < 0) return "MorphJob: negative vertex count";
  if (!rest_positions || !out_positions) return "MorphJob: missing position buffers";
  if (rest_normals && !out_normals) return "MorphJob: rest normals given without an output";
  if (target_count < 0) return "MorphJob: negative target count";
  if (target_count > 0 && (!targets || !weights)) return "MorphJob: targets or weights missing";
  const auto n = static_cast<std::size_t>(vertex_count);
  for (int t = 0; t < target_count; ++t) {
    if (!std::isfinite(weights[t]))
      return "MorphJob: weight " + std::to_string(t) + " is not finite";
    const avatar::MorphTarget& target = targets[t];
    if (target.position_deltas.size() != n)
      return "MorphJob: target '" + target.name +
             "' has a delta count different from the vertex count";
    if (!target.normal_deltas.empty() && target.normal_deltas.size() != n)
      return "MorphJob: target '" + target.name +
             "' has a normal delta count different from the vertex count";
    if (ranges && (ranges[t].first > ranges[t].end || ranges[t].end > n))
      return "MorphJob: vertex range of target '" + target.name + "' out of bounds";
  }
  return {};
}

bool MorphJob::run() const {
  if (!validate().empty()) return false;
  const auto n = static_cast<std::size_t>(vertex_count);
  if (out_positions != rest_positions)
    std::memcpy(out_positions, rest_positions, n * sizeof(glm::vec3));
  if (rest_normals && out_normals != rest_normals)
    std::memcpy(out_normals, rest_normals, n * sizeof(glm::vec3));
  for (int t = 0; t < target_count; ++t) {
    const float w = weights[t];
    if (w == 0.0f) continue;
    const avatar::MorphTarget& target = targets[t];
    const std::size_t first = ranges ? ranges[t].first : 0;
    const std::size_t end = ranges ? ranges[t].end : n;
    const glm::vec3* dp = target.position_deltas.data();
    for (std::size_t v = first; v < end; ++v) out_positions[v] += w * dp[v];
    if (rest_normals && !target.normal_deltas.empty()) {
      const glm::vec3* dn = target.normal_deltas.data();
      for (std::size_t v = first; v < end; ++v) out_normals[v] += w * dn[v];
    }
  }
  return true;
}

}  // namespace sw::skinning

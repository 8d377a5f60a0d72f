// Surface nets over a sparse block grid; see surface_nets.h.
#include "surface_nets.h"

#include <array>
#include <cmath>
#include <unordered_map>

namespace sw::avatar_generator {

namespace {

constexpr int kBlock = 16;  // cells per block edge

struct CellKey {
  static std::uint64_t make(int i, int j, int k) {
    return (static_cast<std::uint64_t>(i) << 42) | (static_cast<std::uint64_t>(j) << 21) |
           static_cast<std::uint64_t>(k);
  }
};

struct SignEdge {
  int i, j, k;        // lower grid point
  int axis;           // 0 x, 1 y, 2 z
  bool inside_first;  // the lower grid point is inside (negative)
};

}  // namespace

RawMesh polygonise_surface_nets(const ImplicitBody& body, float cell_m) {
  const float pad = 4.0f * cell_m;
  const glm::vec3 origin = body.bounds_min() - glm::vec3(pad);
  const glm::vec3 extent = body.bounds_max() + glm::vec3(pad) - origin;
  const glm::ivec3 cells(static_cast<int>(std::ceil(extent.x / cell_m)),
                         static_cast<int>(std::ceil(extent.y / cell_m)),
                         static_cast<int>(std::ceil(extent.z / cell_m)));
  const glm::ivec3 blocks = (cells + glm::ivec3(kBlock - 1)) / kBlock;
  auto grid_point = [&](int i, int j, int k) {
    return origin +
           glm::vec3(static_cast<float>(i), static_cast<float>(j), static_cast<float>(k)) * cell_m;
  };

  RawMesh mesh;
  std::unordered_map<std::uint64_t, std::uint32_t> cell_vertex;
  std::vector<SignEdge> edges;
  std::vector<float> values(static_cast<size_t>((kBlock + 1) * (kBlock + 1) * (kBlock + 1)));
  auto at = [&](int i, int j, int k) -> float& {
    return values[static_cast<size_t>((i * (kBlock + 1) + j) * (kBlock + 1) + k)];
  };
  const float half_diagonal = 0.5f * std::sqrt(3.0f) * kBlock * cell_m;
  const float margin = 2.0f * body.cull_margin() + 2.0f * cell_m;

  for (int bi = 0; bi < blocks.x; ++bi)
    for (int bj = 0; bj < blocks.y; ++bj)
      for (int bk = 0; bk < blocks.z; ++bk) {
        const glm::vec3 block_min = grid_point(bi * kBlock, bj * kBlock, bk * kBlock);
        const glm::vec3 block_max = block_min + glm::vec3(kBlock * cell_m);
        const std::vector<int> near =
            body.primitives_near(block_min, block_max, half_diagonal + margin);
        if (near.empty()) continue;
        const glm::vec3 centre = 0.5f * (block_min + block_max);
        // The field is not exactly Euclidean (ellipsoids, blends): the 1.25 factor keeps the skip
        // test conservative.
        if (std::fabs(body.sample(centre, near).distance) > 1.25f * half_diagonal + cell_m)
          continue;
        const std::vector<int> active = body.primitives_near(block_min, block_max, margin);
        for (int i = 0; i <= kBlock; ++i)
          for (int j = 0; j <= kBlock; ++j)
            for (int k = 0; k <= kBlock; ++k)
              at(i, j, k) =
                  body.sample(grid_point(bi * kBlock + i, bj * kBlock + j, bk * kBlock + k), active)
                      .distance;
        for (int i = 0; i < kBlock; ++i)
          for (int j = 0; j < kBlock; ++j)
            for (int k = 0; k < kBlock; ++k) {
              const int gi = bi * kBlock + i, gj = bj * kBlock + j, gk = bk * kBlock + k;
              // Edges owned by this grid point (+x, +y, +z), kept for the quad pass.
              const float v0 = at(i, j, k);
              const float ends[3] = {at(i + 1, j, k), at(i, j + 1, k), at(i, j, k + 1)};
              for (int axis = 0; axis < 3; ++axis)
                if ((v0 < 0.0f) != (ends[axis] < 0.0f))
                  edges.push_back({gi, gj, gk, axis, v0 < 0.0f});
              // Cell vertex: mean of the crossings on the cell's 12 edges.
              glm::vec3 sum(0.0f);
              int crossings = 0;
              static const int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                                {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
              static const int kEdge[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                               {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
              float corner[8];
              for (int c = 0; c < 8; ++c)
                corner[c] = at(i + kCorner[c][0], j + kCorner[c][1], k + kCorner[c][2]);
              for (const auto& e : kEdge) {
                const float a = corner[e[0]], b = corner[e[1]];
                if ((a < 0.0f) == (b < 0.0f)) continue;
                const float t = a / (a - b);
                const glm::vec3 pa(kCorner[e[0]][0], kCorner[e[0]][1], kCorner[e[0]][2]);
                const glm::vec3 pb(kCorner[e[1]][0], kCorner[e[1]][1], kCorner[e[1]][2]);
                sum += pa + (pb - pa) * t;
                ++crossings;
              }
              if (crossings == 0) continue;
              const glm::vec3 position = grid_point(gi, gj, gk) + (sum / float(crossings)) * cell_m;
              cell_vertex.emplace(CellKey::make(gi, gj, gk),
                                  static_cast<std::uint32_t>(mesh.positions.size()));
              mesh.positions.push_back(position);
              mesh.nearest_primitive.push_back(body.sample(position, active).nearest_primitive);
            }
      }

  // Quads: the four cells around each sign-changing edge.
  for (const SignEdge& e : edges) {
    // The two axes perpendicular to the edge, ordered so (axis, u, v) is right-handed.
    const int u = (e.axis + 1) % 3, v = (e.axis + 2) % 3;
    std::array<std::uint32_t, 4> quad{};
    bool complete = true;
    const int offsets[4][2] = {{0, 0}, {-1, 0}, {-1, -1}, {0, -1}};
    for (int c = 0; c < 4 && complete; ++c) {
      int index[3] = {e.i, e.j, e.k};
      index[u] += offsets[c][0];
      index[v] += offsets[c][1];
      if (index[0] < 0 || index[1] < 0 || index[2] < 0) {
        complete = false;
        break;
      }
      const auto found = cell_vertex.find(CellKey::make(index[0], index[1], index[2]));
      if (found == cell_vertex.end()) {
        complete = false;
        break;
      }
      quad[static_cast<size_t>(c)] = found->second;
    }
    if (!complete) continue;
    // Going (0,0) -> (-1,0) -> (-1,-1) -> (0,-1) turns clockwise about +axis; the outside is on
    // the positive side when the lower point is inside, so flip accordingly.
    if (!e.inside_first) std::swap(quad[1], quad[3]);
    // Split along the shorter diagonal for better-shaped triangles.
    const float d02 = glm::length(mesh.positions[quad[0]] - mesh.positions[quad[2]]);
    const float d13 = glm::length(mesh.positions[quad[1]] - mesh.positions[quad[3]]);
    if (d02 <= d13) {
      mesh.indices.insert(mesh.indices.end(),
                          {quad[0], quad[1], quad[2], quad[0], quad[2], quad[3]});
    } else {
      mesh.indices.insert(mesh.indices.end(),
                          {quad[0], quad[1], quad[3], quad[1], quad[2], quad[3]});
    }
  }
  return mesh;
}

}  // namespace sw::avatar_generator

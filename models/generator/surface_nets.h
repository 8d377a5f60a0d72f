// Surface nets: polygonises the implicit body into a closed, shared-vertex triangle mesh.
//
// One vertex per grid cell the surface crosses (the mean of the cell's edge crossings), one quad
// per grid edge with a sign change (Gibson 1998, "Constrained elastic surface nets"). The grid is
// sparse: it is visited in blocks, and a block whose centre is farther from the surface than its
// half-diagonal (plus the culling margin) is skipped, so only the narrow band around the skin is
// evaluated — a 1.5 mm grid over a whole body in a few seconds.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "implicit_body.h"

namespace sw::avatar_generator {

struct RawMesh {
  std::vector<glm::vec3> positions;
  std::vector<int> nearest_primitive;  // per vertex, from the field at the vertex
  std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside
};

// cell_m: grid spacing in metres. Deterministic: blocks are visited in a fixed order.
RawMesh polygonise_surface_nets(const ImplicitBody& body, float cell_m);

}  // namespace sw::avatar_generator

// Avatar mesh pipeline; see avatar_mesh.h.
#include "avatar_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include <meshoptimizer.h>

#include "face_regions.h"
#include "surface_nets.h"

namespace sw::avatar_generator {

const char* material_name(Material material) {
  switch (material) {
    case Material::kSkin:
      return "skin";
    case Material::kTop:
      return "top";
    case Material::kTrousers:
      return "trousers";
    case Material::kShoes:
      return "shoes";
    case Material::kHair:
      return "hair";
    case Material::kLips:
      return "lips";
    case Material::kBrows:
      return "brows";
    case Material::kMouthInner:
      return "mouthInner";
    case Material::kEyeWhite:
      return "eyeWhite";
    case Material::kIris:
      return "iris";
    case Material::kTongue:
      return "tongue";
    case Material::kTeeth:
      return "teeth";
    case Material::kCount:
      break;
  }
  return "unknown";
}

namespace {

constexpr float kPi = 3.14159265358979f;

// Eyeball: a sphere with its pole on +Z (the gaze), so the iris edge is one latitude ring.
void add_eyeball(glm::vec3 centre, int joint, std::vector<MeshPiece>& pieces) {
  constexpr int kSegments = 20;
  // Polar angles of the rings from the gaze axis: fine near the cornea, coarse behind.
  const float rings[] = {0.0f,  0.22f, 0.36f, 0.48f, 0.62f, 0.85f, 1.1f,
                         1.35f, 1.6f,  1.9f,  2.25f, 2.65f, kPi};
  const int ring_count = static_cast<int>(sizeof(rings) / sizeof(rings[0]));
  const float iris_angle = 0.48f;  // 11.1 mm iris on a 12 mm-radius eyeball
  MeshPiece white, iris;
  white.material = Material::kEyeWhite;
  iris.material = Material::kIris;
  white.rigid_joint = iris.rigid_joint = joint;
  for (MeshPiece* piece : {&white, &iris}) {
    const bool is_iris = piece == &iris;
    std::vector<std::vector<std::uint32_t>> ring_index;
    for (int r = 0; r < ring_count; ++r) {
      const float theta = rings[r];
      if (is_iris ? theta > iris_angle + 1e-6f : theta < iris_angle - 1e-6f) continue;
      std::vector<std::uint32_t> indices;
      const int count = (theta == 0.0f || theta == kPi) ? 1 : kSegments;
      for (int s = 0; s < count; ++s) {
        const float phi = 2.0f * kPi * static_cast<float>(s) / kSegments;
        const glm::vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                          std::cos(theta));
        indices.push_back(static_cast<std::uint32_t>(piece->positions.size()));
        piece->positions.push_back(centre + n * kEyeballRadius);
        piece->normals.push_back(n);
        piece->nearest_primitive.push_back(-1);
      }
      ring_index.push_back(indices);
    }
    for (size_t r = 0; r + 1 < ring_index.size(); ++r) {
      const auto& a = ring_index[r];
      const auto& b = ring_index[r + 1];
      for (int s = 0; s < kSegments; ++s) {
        const int s1 = (s + 1) % kSegments;
        auto A = [&](int i) { return a.size() == 1 ? a[0] : a[static_cast<size_t>(i)]; };
        auto B = [&](int i) { return b.size() == 1 ? b[0] : b[static_cast<size_t>(i)]; };
        // Outward-facing (counter-clockwise seen from outside).
        if (a.size() != 1) piece->indices.insert(piece->indices.end(), {A(s), B(s), A(s1)});
        if (b.size() != 1) piece->indices.insert(piece->indices.end(), {A(s1), B(s), B(s1)});
      }
    }
    pieces.push_back(*piece);
  }
}

// Tongue: a flattened ellipsoid resting on the floor of the mouth, carried by the jaw.
void add_tongue(const HumanoidLayout& layout, std::vector<MeshPiece>& pieces) {
  MeshPiece tongue;
  tongue.material = Material::kTongue;
  tongue.rigid_joint = layout.find("jaw");
  tongue.face = true;
  const glm::vec3 centre(0.0f, kMouthY - 0.0050f, 0.056f);
  const glm::vec3 radii(0.0150f, 0.0040f, 0.020f);
  constexpr int kRings = 8, kSegments = 14;
  for (int r = 0; r <= kRings; ++r) {
    const float theta = kPi * static_cast<float>(r) / kRings;
    for (int s = 0; s < kSegments; ++s) {
      const float phi = 2.0f * kPi * static_cast<float>(s) / kSegments;
      const glm::vec3 unit(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                           std::cos(theta));
      tongue.positions.push_back(centre + unit * radii);
      tongue.normals.push_back(glm::normalize(unit / radii));
      tongue.nearest_primitive.push_back(-1);
    }
  }
  for (int r = 0; r < kRings; ++r)
    for (int s = 0; s < kSegments; ++s) {
      const auto i = [&](int rr, int ss) {
        return static_cast<std::uint32_t>(rr * kSegments + (ss % kSegments));
      };
      tongue.indices.insert(tongue.indices.end(), {i(r, s), i(r + 1, s), i(r, s + 1)});
      tongue.indices.insert(tongue.indices.end(), {i(r, s + 1), i(r + 1, s), i(r + 1, s + 1)});
    }
  pieces.push_back(tongue);
}

// Vertex-cache order for the triangles, then vertices in first-use order (meshoptimizer's
// recommended sequence: optimizeVertexCache, then optimizeVertexFetch).
void optimise_for_gpu(MeshPiece& piece) {
  const size_t vertex_count = piece.positions.size();
  meshopt_optimizeVertexCache(piece.indices.data(), piece.indices.data(), piece.indices.size(),
                              vertex_count);
  std::vector<unsigned int> remap(vertex_count);
  const size_t unique = meshopt_optimizeVertexFetchRemap(remap.data(), piece.indices.data(),
                                                         piece.indices.size(), vertex_count);
  meshopt_remapIndexBuffer(piece.indices.data(), piece.indices.data(), piece.indices.size(),
                           remap.data());
  std::vector<glm::vec3> positions(unique), normals(unique);
  std::vector<int> nearest(unique);
  for (size_t v = 0; v < vertex_count; ++v) {
    if (remap[v] == ~0u) continue;  // unused vertex
    positions[remap[v]] = piece.positions[v];
    normals[remap[v]] = piece.normals[v];
    nearest[remap[v]] = piece.nearest_primitive[v];
  }
  piece.positions.swap(positions);
  piece.normals.swap(normals);
  piece.nearest_primitive.swap(nearest);
}

// Per-triangle materials on a 1.5 mm grid give staircase edges (hairline, cuffs, lips). Smoothing
// the vertices where materials meet along their own band, then pulling them back onto the
// surface (Newton steps along the field gradient), turns the staircase into a smooth line
// without changing the shape; the triangles keep their materials.
void straighten_material_seams(const ImplicitBody& body, const std::vector<std::uint32_t>& indices,
                               const std::vector<int>& triangle_key,
                               std::vector<glm::vec3>& positions) {
  const size_t n = positions.size();
  std::vector<int> first_key(n, -1);
  std::vector<char> seam(n, 0);
  for (size_t t = 0; t < triangle_key.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = indices[3 * t + static_cast<size_t>(c)];
      if (first_key[v] < 0)
        first_key[v] = triangle_key[t];
      else if (first_key[v] != triangle_key[t])
        seam[v] = 1;
    }
  std::map<std::uint32_t, std::vector<std::uint32_t>> neighbours;
  for (size_t t = 0; t < triangle_key.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t a = indices[3 * t + static_cast<size_t>(c)];
      const std::uint32_t b = indices[3 * t + static_cast<size_t>((c + 1) % 3)];
      if (!seam[a] || !seam[b]) continue;
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  for (auto& [v, list] : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  std::vector<int> all(body.primitives().size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  for (int iteration = 0; iteration < 4; ++iteration) {
    std::vector<std::pair<std::uint32_t, glm::vec3>> moved;
    moved.reserve(neighbours.size());
    for (const auto& [v, list] : neighbours) {
      glm::vec3 mean(0.0f);
      for (std::uint32_t u : list) mean += positions[u];
      mean /= static_cast<float>(list.size());
      moved.emplace_back(v, 0.5f * positions[v] + 0.5f * mean);
    }
    for (const auto& [v, p] : moved) positions[v] = p;
  }
  for (const auto& [v, list] : neighbours) {
    const std::vector<int> near =
        body.primitives_near(positions[v] - glm::vec3(0.01f), positions[v] + glm::vec3(0.01f),
                             body.cull_margin() * 2.0f);
    for (int step = 0; step < 3; ++step) {
      const float d = body.sample(positions[v], near).distance;
      positions[v] -= d * body.gradient(positions[v], near, 0.0003f);
    }
  }
}

// Teeth: upper and lower dental arches as curved bands just behind the lips, inside the mouth
// cavity (implicit_body.cpp); the upper row rides on the head, the lower on the jaw. Seen only
// when the mouth opens (visemes, jawOpen), where they make the mouth read as a mouth.
void add_teeth(const HumanoidLayout& layout, std::vector<MeshPiece>& pieces) {
  for (int row = 0; row < 2; ++row) {
    const bool upper = row == 0;
    MeshPiece teeth;
    teeth.material = Material::kTeeth;
    teeth.rigid_joint = layout.find(upper ? "head" : "jaw");
    teeth.face = true;
    const float arch_radius = upper ? 0.0235f : 0.0220f;  // the lower arch sits inside the upper
    const glm::vec3 arch_centre(0.0f, 0.0f, 0.0540f);
    const float y_edge = kMouthY + (upper ? 0.0018f : -0.0020f);  // biting edge, off the slit
    const float y_root = kMouthY + (upper ? 0.0095f : -0.0085f);
    const float thickness = 0.0045f;
    constexpr int kSteps = 16;
    const float sweep = 1.05f;  // radians each side of the midline: incisors to premolars
    // Four corners of the cross-section (outer edge, outer root, inner root, inner edge).
    for (int i = 0; i <= kSteps; ++i) {
      const float a = -sweep + 2.0f * sweep * static_cast<float>(i) / kSteps;
      const glm::vec3 out(std::sin(a), 0.0f, std::cos(a));
      const glm::vec3 corners[4] = {
          arch_centre + out * arch_radius + glm::vec3(0, y_edge, 0),
          arch_centre + out * arch_radius + glm::vec3(0, y_root, 0),
          arch_centre + out * (arch_radius - thickness) + glm::vec3(0, y_root, 0),
          arch_centre + out * (arch_radius - thickness) + glm::vec3(0, y_edge, 0)};
      const glm::vec3 up(0.0f, upper ? 1.0f : -1.0f, 0.0f);
      const glm::vec3 normals[4] = {
          glm::normalize(out - 0.3f * up), glm::normalize(out + 0.3f * up),
          glm::normalize(-out + 0.3f * up), glm::normalize(-out - 0.3f * up)};
      for (int c = 0; c < 4; ++c) {
        teeth.positions.push_back(corners[c]);
        teeth.normals.push_back(normals[c]);
        teeth.nearest_primitive.push_back(-1);
      }
    }
    for (int i = 0; i < kSteps; ++i)
      for (int c = 0; c < 4; ++c) {
        const auto a = static_cast<std::uint32_t>(4 * i + c);
        const auto b = static_cast<std::uint32_t>(4 * i + (c + 1) % 4);
        const std::uint32_t a2 = a + 4, b2 = b + 4;
        // Winding chosen per row so the faces point out of the band (the rows mirror in y).
        if (upper) {
          teeth.indices.insert(teeth.indices.end(), {a, a2, b, b, a2, b2});
        } else {
          teeth.indices.insert(teeth.indices.end(), {a, b, a2, b, b2, a2});
        }
      }
    pieces.push_back(teeth);
  }
}

}  // namespace

std::vector<MeshPiece> build_avatar_mesh(const ImplicitBody& body, const HumanoidLayout& layout,
                                         const AvatarMeshSettings& settings,
                                         AvatarMeshStats* stats) {
  std::vector<MeshPiece> pieces;
  add_eyeball(layout.position("leftEye"), layout.find("leftEye"), pieces);
  add_eyeball(layout.position("rightEye"), layout.find("rightEye"), pieces);
  add_tongue(layout, pieces);
  add_teeth(layout, pieces);
  std::size_t fixed_triangles = 0;
  for (const MeshPiece& piece : pieces) fixed_triangles += piece.indices.size() / 3;

  const RawMesh raw = polygonise_surface_nets(body, settings.cell_m);
  if (stats) stats->raw_triangles = raw.indices.size() / 3;

  // Material per vertex, then per triangle (majority of its corners); face-region triangles of
  // the materials the morphs move get their own key, so the face mesh is split off along a seam.
  std::vector<int> vertex_surface(raw.positions.size());
  for (size_t v = 0; v < raw.positions.size(); ++v)
    vertex_surface[v] =
        static_cast<int>(body.surface_at(raw.positions[v], raw.nearest_primitive[v]));
  const size_t triangle_count = raw.indices.size() / 3;
  constexpr int kFaceKey = 100;  // key = surface, + kFaceKey for face-mesh triangles
  std::vector<int> triangle_surface(triangle_count);
  for (size_t t = 0; t < triangle_count; ++t) {
    const int a = vertex_surface[raw.indices[3 * t]], b = vertex_surface[raw.indices[3 * t + 1]],
              c = vertex_surface[raw.indices[3 * t + 2]];
    int key = (b == c) ? b : a;
    const glm::vec3 centroid =
        (raw.positions[raw.indices[3 * t]] + raw.positions[raw.indices[3 * t + 1]] +
         raw.positions[raw.indices[3 * t + 2]]) /
        3.0f;
    const Surface s = static_cast<Surface>(key);
    const bool face_material = s == Surface::kSkin || s == Surface::kLips || s == Surface::kBrows ||
                               s == Surface::kMouthInner;
    if (face_material && in_face_region(centroid)) key += kFaceKey;
    triangle_surface[t] = key;
  }

  std::vector<glm::vec3> raw_positions = raw.positions;
  straighten_material_seams(body, raw.indices, triangle_surface, raw_positions);

  // Duplicate every vertex once per material that uses it: the material boundaries become
  // seams (same position, different vertex), which meshopt_simplify preserves.
  std::vector<glm::vec3> positions;
  std::vector<int> nearest, surface;
  std::vector<std::uint32_t> indices(raw.indices.size());
  std::map<std::pair<std::uint32_t, int>, std::uint32_t> split;
  for (size_t t = 0; t < triangle_count; ++t)
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = raw.indices[3 * t + static_cast<size_t>(c)];
      const auto key = std::make_pair(v, triangle_surface[t]);
      auto found = split.find(key);
      if (found == split.end()) {
        found = split.emplace(key, static_cast<std::uint32_t>(positions.size())).first;
        positions.push_back(raw_positions[v]);
        nearest.push_back(raw.nearest_primitive[v]);
        surface.push_back(triangle_surface[t]);
      }
      indices[3 * t + static_cast<size_t>(c)] = found->second;
    }

  if (fixed_triangles >= settings.triangle_budget)
    throw std::runtime_error("triangle budget smaller than the eyes and tongue alone");
  const size_t target_indices = (settings.triangle_budget - fixed_triangles) * 3;
  std::vector<std::uint32_t> simplified(indices.size());
  float error = 0.0f;
  // Error is relative to the mesh extent; 1.0 lets the triangle budget be the only limit.
  const size_t kept =
      meshopt_simplify(simplified.data(), indices.data(), indices.size(), &positions[0].x,
                       positions.size(), sizeof(glm::vec3), target_indices, 1.0f, 0, &error);
  simplified.resize(kept);
  if (stats) stats->body_triangles = kept / 3;

  // One piece per body material, each with its own compact vertex range.
  const std::vector<int> active = [&] {
    std::vector<int> all(body.primitives().size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    return all;
  }();
  for (int key = 0; key < kFaceKey + static_cast<int>(Surface::kCount); ++key) {
    if (key % kFaceKey >= static_cast<int>(Surface::kCount)) continue;
    MeshPiece piece;
    piece.material = static_cast<Material>(key % kFaceKey);
    piece.face = key >= kFaceKey;
    std::map<std::uint32_t, std::uint32_t> remap;
    for (size_t t = 0; t + 2 < simplified.size(); t += 3) {
      if (surface[simplified[t]] != key) continue;
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t v = simplified[t + static_cast<size_t>(c)];
        auto found = remap.find(v);
        if (found == remap.end()) {
          found = remap.emplace(v, static_cast<std::uint32_t>(piece.positions.size())).first;
          piece.positions.push_back(positions[v]);
          piece.nearest_primitive.push_back(nearest[v]);
        }
        piece.indices.push_back(found->second);
      }
    }
    if (piece.indices.empty()) continue;
    // Normals from the field gradient: smooth, and identical on both sides of a seam.
    piece.normals.resize(piece.positions.size());
    for (size_t v = 0; v < piece.positions.size(); ++v)
      piece.normals[v] = body.gradient(piece.positions[v], active, 0.0004f);
    pieces.push_back(std::move(piece));
  }
  for (MeshPiece& piece : pieces) optimise_for_gpu(piece);
  return pieces;
}

}  // namespace sw::avatar_generator

// glTF loader: any glTF 2.0 skinned humanoid (.glb, or .gltf with embedded data: URIs) into an
// Avatar — skeleton, inverse binds, every skinned primitive merged into one SkinnedMesh, materials,
// morph targets merged by name, and the canonical joint mapping.
//
// Use:
//   sw::avatar::LoadResult r = sw::avatar::load_avatar(bytes, size);
//   if (!r.ok()) print(r.message());           // "missing required joints: leftThumbDistal, ..."
//   else use(r.avatar);                         // anchors are NOT computed here: body_anchors.h
//
// The file is hostile until proven otherwise (uploads, WASM where an exception aborts): every
// index, count, offset and stride is checked before it is used, floats are checked finite, and
// nothing throws. Canonical names come from the VRMC_vrm 1.0 humanoid extension when present,
// else the VRM 0.x extension, else the joint names through skeleton/humanoid_names.h.
//
// Does NOT: load external files (buffers must be embedded: a page upload has no neighbours),
// decode images (materials keep their factors only), support sparse accessors, or read more than
// 8 influences (JOINTS_0/1; the 4 strongest are kept, kMaxInfluences).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "avatar/avatar.h"

namespace sw::avatar {

// Limits, each with its reason. A humanoid within the project's budget (30,000 triangles,
// < 100 joints) is far inside all of them; they exist so a hostile file cannot make the loader
// allocate gigabytes from a small header.
struct LoaderLimits {
  std::size_t max_file_bytes = 256u << 20;   // 256 MiB: far above any avatar; bounds the WASM heap
  std::size_t max_vertices = 1u << 20;       // 1 M merged vertices (budget: ~20 k)
  std::size_t max_indices = 6u << 20;        // 2 M triangles
  std::size_t max_joints = 1024;             // joints are u16 in the mesh; palettes stay < 64 KiB
  std::size_t max_morph_targets = 512;       // dense deltas: 512 x 1 M x 24 B would be 12 GB, so
  std::size_t max_morph_floats = 64u << 20;  // the total delta floats are capped too (256 MiB)
  int max_json_depth = 64;                   // the JSON printer and tinygltf recurse per level
};

struct LoadResult {
  Avatar avatar;
  std::string error;                  // empty on success; "where: what was wrong" otherwise
  std::vector<std::string> warnings;  // accepted oddities (skipped non-triangle primitives, ...)
  bool ok() const { return error.empty(); }
  const std::string& message() const { return error; }
};

// Loads .glb bytes or .gltf JSON text (told apart by the GLB magic).
LoadResult load_avatar(const std::uint8_t* bytes, std::size_t size, const LoaderLimits& limits = {});
// Reads a file natively then load_avatar(); an unreadable file is an error value too.
LoadResult load_avatar_file(const std::string& path, const LoaderLimits& limits = {});

}  // namespace sw::avatar

// Avatar pack: an Avatar (anchors included) in a compact binary form that loads by copying arrays.
//
// Why it exists: the page's first avatar load ran tinygltf's JSON parser and the glTF loader on the
// main thread while the browser compiled that code (V8 compiles WebAssembly lazily, and tiers the
// hot functions up in the background on the same few cores): 0.5-1.3 s before the first signing
// frame, against ~25 ms once warm. The build packs models/signweave-avatar.glb once (CLI
// `pack-avatar`, run by ./signweave build into web/gen/), so the page reads arrays instead.
//
//   std::vector<std::uint8_t> bytes = sw::avatar::pack_avatar(avatar);   // anchors already computed
//   sw::avatar::UnpackResult r = sw::avatar::unpack_avatar(bytes.data(), bytes.size());
//   if (!r.ok()) print(r.error);             // "avatar pack: mesh.indices[12]: vertex 99999 of 17000"
//
// unpack(pack(a)) equals a bit for bit (tests/native/avatar/avatar_pack_test.cpp). The bytes are
// hostile until checked, like a glTF file: every count is bounded by the bytes left and by
// LoaderLimits, every index is range-checked, floats must be finite, and nothing throws.
//
// Layout (little-endian; strings are u32 length + UTF-8 bytes; counts are u32):
//   "SWAVPACK" u32 version
//   joints:      count, per joint {name, i32 parent, f32 translation[3], rotation wxyz[4], scale[3]}
//   inverse_bind f32[16] per joint (column-major, as glm)
//   canonical:   count, i32 per canonical joint id (-1 absent)
//   mesh:        vertex count, f32 positions[3n], normals[3n], u16 joints[4n], f32 weights[4n];
//                index count, u32 indices; primitive count, {u32 first, u32 count, i32 material};
//                material count, {name, f32 base_color[4], roughness, metallic}
//   morphs:      count, per morph {name, u8 has_normals, entry count, per entry {u32 vertex
//                (strictly increasing), f32 position delta[3], normal delta[3] if has_normals}}:
//                sparse, since a face morph moves a few hundred of the ~17,000 merged vertices
//                and the Avatar holds it dense (41 dense morphs would be 17 MB).
//   anchors:     count, per anchor {name, i32 joint, f32 offset[3], f32 normal[3]}
//
// Does NOT: carry warnings of the load that made it, compress (the HTTP layer gzips), or run on a
// big-endian host (the bytes are read as the host's floats; WASM, x86 and ARM are little-endian).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "avatar/avatar.h"
#include "avatar/gltf_loader.h"

namespace sw::avatar {

// Bumped whenever the layout changes: an older pack is refused with a message saying to rebuild.
constexpr std::uint32_t kAvatarPackVersion = 1;

struct UnpackResult {
  Avatar avatar;
  std::string error;   // empty on success; "avatar pack: where: what was wrong" otherwise
  bool ok() const { return error.empty(); }
};

// True when the bytes start with the pack's magic (then unpack_avatar, not the glTF loader).
bool is_avatar_pack(const std::uint8_t* bytes, std::size_t size);

std::vector<std::uint8_t> pack_avatar(const Avatar& avatar);

// The same limits as the glTF loader bound what a pack may make the reader allocate.
UnpackResult unpack_avatar(const std::uint8_t* bytes, std::size_t size, const LoaderLimits& limits = {});

}  // namespace sw::avatar

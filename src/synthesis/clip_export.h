// Clip export: a synthesised clip as a BVH motion file (foundation's writer: centimetres, ZXY
// Euler channels) or as a binary glTF 2.0 (.glb) holding the avatar's skeleton as nodes, its
// skinned mesh when it has one (with the face's morph targets, stored as sparse accessors), and
// the clip as an animation (rotation per joint, root translation, and the face's morph weights on
// the mesh's targets, matched by name; LINEAR samplers at the clip's frame times). Errors are
// values.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "avatar/avatar.h"
#include "synthesis/clip.h"

namespace sw::synthesis {

struct ExportResult {
  std::vector<std::uint8_t> bytes;
  std::string error;  // empty on success
  bool ok() const { return error.empty(); }
};

// BVH text (bytes are UTF-8). The clip must belong to the avatar's skeleton.
ExportResult export_bvh(const Clip& clip, const avatar::Avatar& avatar);
// GLB bytes.
ExportResult export_glb(const Clip& clip, const avatar::Avatar& avatar);

}  // namespace sw::synthesis

// BVH (Biovision Hierarchy) motion files: the format seed 004's capture data comes in and the one
// `signweave synth --out F.bvh` writes. Reader (bvh_reader.cpp), writer (bvh_writer.cpp) and the
// conversions between channel values and local Transforms.
//
//   HIERARCHY
//   ROOT Hips
//   {
//     OFFSET 0 90 0
//     CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
//     JOINT Spine { OFFSET ... CHANNELS 3 ... End Site { OFFSET ... } }
//   }
//   MOTION
//   Frames: 2
//   Frame Time: 0.033333
//   <one line per frame: every joint's channel values, joints in file order>
//
// Conventions: rotations in degrees, composed in the order the channels list them (math/euler.h: a
// joint with "Zrotation Xrotation Yrotation" has R = Rz * Rx * Ry). Position channels replace the
// joint's OFFSET as its local translation. Lengths are in the file's unit (often centimetres); the
// conversions take a scale to metres.
//
// Errors are values: a malformed file yields BvhError with the 1-based line and a message, never an
// exception or abort (the reader runs in WASM, where exceptions abort). Limits, with reasons:
//   - every number finite and |v| <= kMaxMagnitude (1e6): beyond it a float keeps no sub-millimetre
//     (centimetre files) or sub-degree precision, and no capture produces such values;
//   - at most kMaxJoints joints (1024): the largest production rigs (full face + hands) have a few
//     hundred; more means a corrupt or hostile file;
//   - at most kMaxValues channel values in total (64 Mi, 512 MiB as double), so a forged
//     "Frames: 999999999" cannot exhaust memory.
//
// Does not: read scale channels or non-standard channel types, or joint names containing spaces;
// a file with them is rejected with the line. One frame is one line, as every exporter writes it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "math/euler.h"
#include "math/span.h"
#include "math/transform.h"
#include "skeleton/skeleton.h"

namespace sw::skeleton {

enum class BvhChannel { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };

const char* bvh_channel_name(BvhChannel channel);

struct BvhJoint {
  std::string name;
  int parent = -1;         // index into Bvh::joints, -1 for a ROOT
  glm::dvec3 offset{0.0};  // OFFSET, in the file's unit
  std::vector<BvhChannel>
      channels;               // as listed by CHANNELS (3 rotations, or 3 positions + 3 rotations)
  bool has_end_site = false;  // an "End Site { OFFSET ... }" child block
  glm::dvec3 end_site_offset{0.0};

  // The order its rotation channels are listed in (math/euler.h convention).
  math::EulerOrder rotation_order() const;
  bool has_position() const;
};

struct Bvh {
  std::vector<BvhJoint> joints;  // file order: parents before children
  int frame_count = 0;
  double frame_time_s = 1.0 / 30.0;
  // frame_count * channel_count() values, frame-major, each frame's channels in joint order.
  std::vector<double> values;

  static constexpr double kMaxMagnitude = 1e6;
  static constexpr int kMaxJoints = 1024;
  static constexpr std::size_t kMaxValues = std::size_t{64} << 20;

  int channel_count() const;
  // Index of the joint's first channel within a frame.
  int channel_offset(int joint) const;
  // Pointer to one frame's channel_count() values.
  const double* frame(int index) const {
    return values.data() + std::size_t(index) * std::size_t(channel_count());
  }
  double* frame(int index) {
    return values.data() + std::size_t(index) * std::size_t(channel_count());
  }
  int find(std::string_view name) const;
};

struct BvhError {
  int line = 0;  // 1-based line of the input where the problem was found
  std::string message;
  // "line 12: ..." for logs and the CLI.
  std::string format() const;
};

struct BvhReadResult {
  Bvh bvh;         // valid only when ok
  BvhError error;  // set when !ok
  bool ok = false;
};

BvhReadResult read_bvh(std::string_view text);

struct BvhWriteOptions {
  // Digits after the decimal point for every number. The default keeps a micro-unit (1e-6 cm or
  // degree), below what a float Transform resolves.
  int decimals = 6;
};

// Always succeeds for a Bvh the reader could have produced; reading the output back gives the same
// structure and the values rounded to `decimals`, and writing that again gives identical text.
std::string write_bvh(const Bvh& bvh, const BvhWriteOptions& options = {});

// The hierarchy as a Skeleton: rest translation = OFFSET * scale_to_m, rest rotation identity.
// With include_end_sites, each End Site also becomes a joint named "<parent>_end", appended after
// all the file joints so that skeleton joint i is still BVH joint i.
Skeleton to_skeleton(const Bvh& bvh, double scale_to_m = 1.0, bool include_end_sites = false);

// Local transforms of one frame, one per BVH joint (the first bvh.joints.size() entries of out).
// False if the frame is out of range or out is too small.
bool frame_to_local(const Bvh& bvh, int frame, double scale_to_m, math::Span<math::Transform> out);

// The inverse: fills one frame's channels from local transforms (translation goes to position
// channels where the joint has them; rotation to Euler angles in the joint's channel order, chosen
// nearest the previous frame's angles so that tracks stay continuous — fill frames in order).
bool local_to_frame(math::Span<const math::Transform> local, double scale_to_m, Bvh& bvh,
                    int frame);

}  // namespace sw::skeleton

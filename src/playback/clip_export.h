// Clip export: the current clip written for other tools — BVH (motion capture's lingua franca:
// Blender, MotionBuilder, the seed's capture pipeline) and glTF 2.0 binary with the skeleton as
// nodes and one animation (three.js, Blender, Unity, Godot import it as is).
//
//   skeleton::Bvh bvh = clip_to_bvh(clip, avatar.skeleton);     // then skeleton::write_bvh(bvh)
//   std::vector<std::uint8_t> glb = clip_to_glb(clip, avatar.skeleton);
//
// Conventions: BVH lengths in centimetres (what BVH tools assume), rotations as ZXY Euler angles
// in degrees (the common BVH order), the root with three position channels; every frame of the
// clip becomes a BVH frame. glTF keeps metres and quaternions (glTF 2.0 §3.11: rotation outputs are
// unit quaternions, LINEAR interpolation means slerp), one keyframe per clip frame.
//
// Does not: write the mesh or skin (the avatar file has them; the animation targets its joints by
// name), morph-target animation in BVH (BVH has no such channels), or resample the clip.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "skeleton/bvh.h"
#include "skeleton/skeleton.h"
#include "synthesis/clip.h"

namespace sw::playback {

// BVH lengths are written in centimetres: 1 BVH unit = 0.01 m.
constexpr double kBvhUnitToMetres = 0.01;

// Empty `error` on success. Fails (error set, result empty) when the clip does not fit the skeleton.
skeleton::Bvh clip_to_bvh(const synthesis::Clip& clip, const skeleton::Skeleton& skeleton, std::string* error);

std::vector<std::uint8_t> clip_to_glb(const synthesis::Clip& clip, const skeleton::Skeleton& skeleton,
                                      std::string* error);

}  // namespace sw::playback

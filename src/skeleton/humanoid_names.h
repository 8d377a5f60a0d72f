// Humanoid names: the canonical joint set every part of Signweave speaks (VRM 1.0 humanoid bone
// names, plus index..little metacarpals and non-deforming fingertip points), and the alias tables
// that map other rigs' joint names onto it (Mixamo, VRM 0.x, 3ds Max Biped, CMU/cgspeed BVH,
// Blender-style `.L`/`_r` suffixes).
//
// Use:
//   int id = sw::skeleton::canonical_joint_id("mixamorig:LeftForeArm");   // kLeftLowerArm
//   std::string_view name = sw::skeleton::humanoid_joint_name(id);        // "leftLowerArm"
//   auto ids = sw::skeleton::map_humanoid_names(all_node_names);          // whole-rig mapping
//
// Does NOT: guess from geometry (a joint called "bone_17" stays unmapped), or map non-humanoid
// extras (hair, clothing); those get -1.
//
// Thumb naming differs between conventions (VRM 1.0 §humanoid): VRM 0.x calls the thumb's three
// segments Proximal/Intermediate/Distal where VRM 1.0 says Metacarpal/Proximal/Distal. A single
// name cannot tell which is meant, so canonical_joint_id() reads VRM 1.0, canonical_joint_id_vrm0()
// reads VRM 0.x, and map_humanoid_names() detects the convention from the whole rig
// (a "ThumbIntermediate" only exists in VRM 0.x naming).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sw::skeleton {

// The X-macro tables are laid out by hand, a row per joint group: clang-format leaves them.
// clang-format off
// X-macro: order is the canonical id order (stable: synthesis and the page index by it).
// Torso and head first, then each arm with its hand (fingers metacarpal..tip), then the legs.
#define SW_HUMANOID_SIDE_ARM(S, s)                                                          \
  X(k##S##Shoulder, #s "Shoulder") X(k##S##UpperArm, #s "UpperArm")                          \
  X(k##S##LowerArm, #s "LowerArm") X(k##S##Hand, #s "Hand")                                  \
  X(k##S##ThumbMetacarpal, #s "ThumbMetacarpal") X(k##S##ThumbProximal, #s "ThumbProximal")  \
  X(k##S##ThumbDistal, #s "ThumbDistal") X(k##S##ThumbTip, #s "ThumbTip")                    \
  X(k##S##IndexMetacarpal, #s "IndexMetacarpal") X(k##S##IndexProximal, #s "IndexProximal")  \
  X(k##S##IndexIntermediate, #s "IndexIntermediate") X(k##S##IndexDistal, #s "IndexDistal")  \
  X(k##S##IndexTip, #s "IndexTip")                                                          \
  X(k##S##MiddleMetacarpal, #s "MiddleMetacarpal") X(k##S##MiddleProximal, #s "MiddleProximal") \
  X(k##S##MiddleIntermediate, #s "MiddleIntermediate") X(k##S##MiddleDistal, #s "MiddleDistal") \
  X(k##S##MiddleTip, #s "MiddleTip")                                                        \
  X(k##S##RingMetacarpal, #s "RingMetacarpal") X(k##S##RingProximal, #s "RingProximal")      \
  X(k##S##RingIntermediate, #s "RingIntermediate") X(k##S##RingDistal, #s "RingDistal")      \
  X(k##S##RingTip, #s "RingTip")                                                            \
  X(k##S##LittleMetacarpal, #s "LittleMetacarpal") X(k##S##LittleProximal, #s "LittleProximal") \
  X(k##S##LittleIntermediate, #s "LittleIntermediate") X(k##S##LittleDistal, #s "LittleDistal") \
  X(k##S##LittleTip, #s "LittleTip")

#define SW_HUMANOID_SIDE_LEG(S, s)                                                 \
  X(k##S##UpperLeg, #s "UpperLeg") X(k##S##LowerLeg, #s "LowerLeg")                 \
  X(k##S##Foot, #s "Foot") X(k##S##Toes, #s "Toes")

#define SW_HUMANOID_JOINTS                                                              \
  X(kHips, "hips") X(kSpine, "spine") X(kChest, "chest") X(kUpperChest, "upperChest")   \
  X(kNeck, "neck") X(kHead, "head") X(kJaw, "jaw") X(kLeftEye, "leftEye")               \
  X(kRightEye, "rightEye")                                                              \
  SW_HUMANOID_SIDE_ARM(Left, left) SW_HUMANOID_SIDE_ARM(Right, right)                   \
  SW_HUMANOID_SIDE_LEG(Left, left) SW_HUMANOID_SIDE_LEG(Right, right)
// clang-format on

enum HumanoidJoint : int {
#define X(id, name) id,
  SW_HUMANOID_JOINTS
#undef X
      kHumanoidJointCount
};

// "leftUpperArm" for kLeftUpperArm; empty for an id out of range.
std::string_view humanoid_joint_name(int id);

// Canonical id of any joint name (canonical VRM 1.0, Mixamo, Biped, BVH, Blender suffixes), case
// and separator tolerant; -1 when the name is not a humanoid joint. Thumbs read as VRM 1.0.
int canonical_joint_id(std::string_view any_name);

// A VRM 0.x humanoid bone name (as in the VRM extension's humanBones[].bone) to the canonical id.
int canonical_joint_id_vrm0(std::string_view vrm0_bone_name);

// Maps a whole rig's joint names at once: result[i] is the canonical id of names[i] or -1.
// Detects VRM 0.x thumb naming, and when two names map to the same id only the first keeps it
// (the others get -1), so the result is injective.
std::vector<int> map_humanoid_names(const std::vector<std::string>& names);

// Fingers and segments, for code that walks the hand (handshapes, anchors).
enum class Finger : int { Thumb = 0, Index, Middle, Ring, Little };
enum class FingerSegment : int { Metacarpal = 0, Proximal, Intermediate, Distal, Tip };
constexpr int kFingerCount = 5;
constexpr int kFingerSegmentCount = 5;

// Canonical id of a finger segment; -1 for the thumb's Intermediate (VRM 1.0 thumbs have
// metacarpal, proximal, distal and the tip).
int finger_joint_id(bool left, Finger finger, FingerSegment segment);

// Canonical parent in the VRM 1.0 hierarchy (optional joints skipped to their nearest required
// ancestor is NOT done here: this is the direct parent), -1 for hips and for bad ids.
int humanoid_parent(int id);

// Joints a model must have for Signweave to sign with it: hips, spine, neck, head, both upper and
// lower arms and hands, and every finger's proximal/intermediate/distal (thumb: metacarpal,
// proximal, distal). Metacarpals of index..little, tips, chest, shoulders, eyes, jaw and legs are
// optional (the loader and anchors work without them).
bool humanoid_joint_required(int id);

}  // namespace sw::skeleton

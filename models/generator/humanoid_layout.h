// Humanoid layout: the Signweave avatar's skeleton — every joint's name, parent and bind position —
// derived from adult anthropometry (about 1.70 m tall, hand 0.19 m from wrist to middle fingertip).
//
// BIND POSE CONVENTION (the loader, synthesis and the page rely on it):
//   * every joint's rest LOCAL ROTATION IS IDENTITY and its scale is 1: joint frames are aligned
//   with
//     the model axes in the bind pose, all offsets live in the translations;
//   * T-pose: arms straight out sideways along ±X (the avatar's LEFT hand at +X), palms facing down
//     (-Y), fingers along ±X with a slight natural fan, thumbs towards +Z;
//   * the avatar faces +Z, +Y is up, feet stand on y = 0, metres (glTF 2.0 §3.4).
// The right side is the mirror image (x -> -x) of the left side.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sw::avatar_generator {

struct LayoutJoint {
  std::string name;       // canonical VRM 1.0 humanoid name (ARCHITECTURE.md)
  int parent = -1;        // index into HumanoidLayout::joints; parents come before children
  glm::vec3 position{0};  // bind position in model space, metres
  bool deforming = true;  // false for the fingertip points: they carry no skin weights
};

struct HumanoidLayout {
  std::vector<LayoutJoint> joints;

  int find(const std::string& name) const;  // -1 if absent
  const LayoutJoint& at(const std::string& name) const;
  glm::vec3 position(const std::string& name) const { return at(name).position; }
};

// The one avatar the project ships. Deterministic: no randomness, no environment.
HumanoidLayout make_signweave_layout();

// Names of the five fingers as they appear in joint names, thumb first.
constexpr const char* kFingerNames[5] = {"Thumb", "Index", "Middle", "Ring", "Little"};

}  // namespace sw::avatar_generator

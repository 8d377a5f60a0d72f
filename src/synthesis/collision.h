// Collision: the body as capsules (torso, neck, head, upper arms, forearms) and the hands as sets of
// spheres on their joints, measured from the skeleton and — when the avatar has a skinned mesh —
// from the mesh extents around each bone. Synthesis uses it to find frames where a hand passes
// through the body or the other hand (seed 004: "hand into body", "hands crossing") and to route
// such transitions through intermediate states.
#pragma once

#include <string>
#include <vector>

#include "avatar/avatar.h"
#include "synthesis/rig.h"

namespace sw::synthesis {

struct Capsule {
  std::string name;
  int joint = -1;       // moves rigidly with this joint
  glm::vec3 a{0.0f}, b{0.0f};  // segment end points in the bind pose (model space)
  float radius_m = 0.0f;
};

struct BodyModel {
  std::vector<Capsule> trunk;            // torso halves, neck, head (never touched by a hand
                                         // except at an intended contact)
  std::array<Capsule, 2> upper_arm, forearm;
  float hand_sphere_radius_m = 0.01f;    // fingers
  float palm_sphere_radius_m = 0.02f;    // palm centre
};

BodyModel build_body_model(const avatar::Avatar& avatar, const Rig& rig);

// Distance from p to segment ab.
float segment_distance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b);

struct Penetration {
  float depth_m = 0.0f;                 // > 0: how far a hand sphere is inside something
  glm::vec3 push_dir{0.0f};             // direction that would take the hand out
  std::string what;                     // "right hand in torso", "hands", ...
};

// Deepest penetration of `side`'s hand into the trunk and (if `other_hand`) into the other
// hand/forearm, for a finalized pose.
Penetration hand_penetration(const BodyModel& body, const PoseBuilder& pose, Side side,
                             bool check_trunk, bool check_other_hand);

}  // namespace sw::synthesis

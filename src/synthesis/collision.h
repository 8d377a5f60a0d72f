// Collision: the body as capsules (torso, neck, head, upper arms, forearms) and the hands as sets of
// spheres on their joints, measured from the skeleton and — when the avatar has a skinned mesh —
// from the mesh extents around each bone. Synthesis uses it to find frames where a hand passes
// through the body or the other hand (seed 004: "hand into body", "hands crossing"), or where an
// arm does (an elbow or forearm inside the torso when the hand crosses the body, crossed forearms
// through each other), to choose an elbow swivel that keeps the arm outside, and to route such
// transitions through intermediate states.
#pragma once

#include <array>
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
  // Arm segments checked against the trunk: the upper arm's first `upper_arm_skip_m` (from the
  // shoulder joint) is the shoulder itself, joined to the torso, and is not a collision; the
  // forearm's last `forearm_contact_skip_m` (to the wrist) may rest on the body while the hand
  // touches it (an intended contact: palm on the chest with the wrist against it) — its skin may
  // sink in, but its axis must stay outside.
  std::array<float, 2> upper_arm_skip_m{0.0f, 0.0f};
  float forearm_contact_skip_m = 0.0f;
};

BodyModel build_body_model(const avatar::Avatar& avatar, const Rig& rig);

// Distance from p to segment ab.
float segment_distance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b);

// Distance between segments p1q1 and p2q2 (capsule-capsule distance is this minus the radii);
// the closest points are written to on1 / on2 when given. Degenerate segments are points.
float segment_segment_distance(const glm::vec3& p1, const glm::vec3& q1, const glm::vec3& p2,
                               const glm::vec3& q2, glm::vec3* on1 = nullptr, glm::vec3* on2 = nullptr);

// Where one arm's capsules are: shoulder joint -> elbow (upper arm), elbow -> wrist (forearm).
struct ArmSegments {
  glm::vec3 shoulder{0.0f}, elbow{0.0f}, wrist{0.0f};
};
ArmSegments posed_arm(const PoseBuilder& pose, Side side);

struct Penetration {
  float depth_m = 0.0f;                 // > 0: how far a hand sphere is inside something
  glm::vec3 push_dir{0.0f};             // direction that would take the hand out
  std::string what;                     // "right hand in torso", "hands", ...
};

// Deepest penetration of `side`'s hand into the trunk and (if `other_hand`) into the other
// hand/forearm, for a finalized pose.
Penetration hand_penetration(const BodyModel& body, const PoseBuilder& pose, Side side,
                             bool check_trunk, bool check_other_hand);

// Deepest penetration of `side`'s arm: upper arm and forearm capsules into the trunk capsules
// (check_trunk), and its forearm into the other forearm (check_other_forearm). hand_contact: the
// hand touches the body on purpose, so the forearm's wrist end (forearm_contact_skip_m) may touch
// too. push_dir points the offending segment out.
Penetration arm_penetration(const BodyModel& body, const PoseBuilder& pose, Side side,
                            bool check_trunk, bool hand_contact, bool check_other_forearm);

// How far the two hands of `pose` keep apart (the least gap between a sphere of one and one of the
// other; negative: overlap) while the left hand moves straight away from the right by up to
// `travel_m` along `dir` (the hands' relative motion of a straight approach along -dir that ends
// at `pose`, each hand turned as in `pose`).
float hands_swept_gap(const BodyModel& body, const PoseBuilder& pose, const glm::vec3& dir, float travel_m);

// The same arm-trunk depth for an arm given by its joint positions against the trunk in its
// bind pose (the arm IK's key poses leave the trunk unposed): cheap enough to score every swivel
// candidate.
// push_dir (optional) receives the direction that takes the deepest segment out.
float arm_trunk_depth(const BodyModel& body, Side side, const ArmSegments& arm, bool hand_contact,
                      glm::vec3* push_dir = nullptr);

// A point moving in a straight line from `from` to `to` (a hand's contact point on a movement,
// model space) against the trunk capsules (posed as in `pose`) and the shoulders (the neck's base
// to each shoulder joint, as thick as the upper arm): `stop`, where the line first goes deeper
// than `from` is plus `allowed_m` (to 1 mm; `to` when it never does), and `through`, whether it
// goes through there (`to` on the far side of that capsule's axis). A hand touches the body, it
// does not pass through it: HamNoSys's contact ends a movement at the body (HamNoSys 4 manual,
// contact), and a movement "in" from a place close to the shoulders (the corpus's hamshoulders
// hamclose hammovei hamtouch) took the touching hand, exempt from the trunk, out behind the body,
// the elbow 28 cm behind the shoulder; the rest transition from there swung the arm up to 135 mm
// through the torso (sign_motion.cpp stops such a hand's movements at `stop`).
struct TrunkCrossing {
  glm::vec3 stop{0.0f};
  bool through = false;
};
TrunkCrossing trunk_crossing(const BodyModel& body, const PoseBuilder& pose, const glm::vec3& from,
                             const glm::vec3& to, float allowed_m);

}  // namespace sw::synthesis

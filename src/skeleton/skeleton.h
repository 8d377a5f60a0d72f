// Skeleton: the kinematic tree S = D(V, E) of seed 004 — joints with a parent and a rest pose.
//
// Joints are stored parents-before-children (a topological order), so forward kinematics is one
// pass over the array. Joint names are the avatar's own; skeleton/humanoid_names.h maps them onto
// the canonical VRM 1.0 humanoid set.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "math/transform.h"

namespace sw::skeleton {

struct Joint {
  std::string name;
  int parent = -1;       // index into Skeleton::joints, -1 for a root
  math::Transform rest;  // local rest transform relative to the parent
};

struct Skeleton {
  std::vector<Joint> joints;

  int joint_count() const { return static_cast<int>(joints.size()); }
  // Index of the joint with this exact name, or -1.
  int find(std::string_view name) const;
  // Empty when valid; else what is wrong (parent after child, out of range, duplicate name...).
  std::string validate() const;
};

}  // namespace sw::skeleton

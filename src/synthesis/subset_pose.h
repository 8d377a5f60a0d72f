// SubsetPose: forward kinematics of a few joints of a rig (and their ancestors) from a frame of
// local rotations, with PoseBuilder::set_from_local's arithmetic, so each position is the one the
// full pose gives, bit for bit. For the transition measures that read only some joints: eq. (10)'s
// L_max of a rest transition reads the arm joints (shoulders, upper arms, forearms, wrists), the
// acceleration bound the arms and fingertips; a full pose also placed the legs, head, eyes and
// (for L_max) the thirty finger joints, about four fifths of the work, and those measures posed
// tens of thousands of frames per lexicon pass (issue 4: under 1 ms per sign in WASM).
#pragma once

#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "synthesis/rig.h"

namespace sw::synthesis {

class SubsetPose {
 public:
  // `wanted`: joint indices; their ancestors are posed with them.
  SubsetPose(const Rig& rig, const std::vector<int>& wanted);
  // Poses the subset from a frame of rig.joint_count local rotations (a Clip frame).
  void set_from_local(const glm::quat* local);
  // A posed joint's model-space position: defined for the wanted joints and their ancestors.
  const glm::vec3& position(int joint) const { return pos_[static_cast<size_t>(joint)]; }
  // The joints posed, parents before children.
  const std::vector<int>& joints() const { return joints_; }

 private:
  const Rig& rig_;
  std::vector<int> joints_;
  std::vector<glm::quat> model_, delta_;  // indexed by joint (only the subset's entries are set)
  std::vector<glm::vec3> pos_;
  // PoseBuilder's incremental rule: the previous frame's local rotations and, per joint, whether
  // that call recomputed it; a joint with the same local rotation (bit for bit) under a parent
  // left alone keeps its values (the trunk's, in a transition whose ends share it).
  std::vector<glm::quat> last_local_;
  std::vector<char> recomputed_;
  bool last_valid_ = false;
};

}  // namespace sw::synthesis

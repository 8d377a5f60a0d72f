// Forward kinematics: model[i] = model[parent(i)] * local[i], parents first (seed 004: each link's
// transition matrix from its parent; glTF 2.0 §3.7.3 global transforms).
#include "skeleton/local_to_model.h"

namespace sw::skeleton {
namespace {

// True when `joint` lies in the sub-tree rooted at `root`. Parents precede children, so every
// ancestor has a smaller index and the walk stops as soon as it passes below `root`.
bool in_subtree(const Skeleton& s, int joint, int root) {
  while (joint > root) joint = s.joints[static_cast<std::size_t>(joint)].parent;
  return joint == root;
}

}  // namespace

bool LocalToModelJob::validate() const {
  if (skeleton == nullptr) return false;
  const std::size_t count = static_cast<std::size_t>(skeleton->joint_count());
  const bool has_transforms = input.data != nullptr || input.size != 0;
  const bool has_matrices = input_matrices.data != nullptr || input_matrices.size != 0;
  if (has_transforms == has_matrices) return false;  // exactly one input
  if (has_transforms && (input.data == nullptr || input.size < count)) return false;
  if (has_matrices && (input_matrices.data == nullptr || input_matrices.size < count)) return false;
  if (count > 0 && (output.data == nullptr || output.size < count)) return false;
  if (from < -1 || from >= static_cast<int>(count)) return false;
  if (to < from) return false;
  // FK reads output[parent] before writing output[i]: a parent at or after its child (or out of
  // range) would read garbage or out of bounds. Cheap integer checks, unlike Skeleton::validate().
  for (std::size_t i = 0; i < count; ++i) {
    const int p = skeleton->joints[i].parent;
    if (p < -1 || p >= static_cast<int>(i)) return false;
  }
  return true;
}

bool LocalToModelJob::run() const {
  if (!validate()) return false;
  const Skeleton& s = *skeleton;
  const int count = s.joint_count();
  const int last = to < count - 1 ? to : count - 1;
  const glm::mat4 identity(1.0f);
  const glm::mat4& above_roots = root != nullptr ? *root : identity;

  const auto local = [&](int i) -> glm::mat4 {
    return input_matrices.data != nullptr ? input_matrices[static_cast<std::size_t>(i)]
                                          : input[static_cast<std::size_t>(i)].to_matrix();
  };
  const auto parent_model = [&](int i) -> const glm::mat4& {
    const int p = s.joints[static_cast<std::size_t>(i)].parent;
    return p < 0 ? above_roots : output[static_cast<std::size_t>(p)];
  };

  const int first = from < 0 ? 0 : from;
  for (int i = first; i <= last; ++i) {
    // In a partial update, joints after `from` that are not its descendants keep their matrices.
    if (from >= 0 && i != from && !in_subtree(s, i, from)) continue;
    output[static_cast<std::size_t>(i)] = parent_model(i) * local(i);
  }
  return true;
}

}  // namespace sw::skeleton

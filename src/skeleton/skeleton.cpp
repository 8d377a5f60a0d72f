// Skeleton lookup and validation: the checks every loader (glTF, BVH) runs before FK trusts the
// parents-before-children order.
#include "skeleton/skeleton.h"

#include <cmath>
#include <unordered_map>

namespace sw::skeleton {
namespace {

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string describe(const Skeleton& s, int index) {
  return "joint " + std::to_string(index) + " '" + s.joints[static_cast<std::size_t>(index)].name +
         "'";
}

}  // namespace

int Skeleton::find(std::string_view name) const {
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::string Skeleton::validate() const {
  std::unordered_map<std::string_view, int> seen;
  for (int i = 0; i < joint_count(); ++i) {
    const Joint& j = joints[static_cast<std::size_t>(i)];
    if (j.name.empty()) return "joint " + std::to_string(i) + " has an empty name";
    const auto [it, inserted] = seen.emplace(j.name, i);
    if (!inserted) {
      return describe(*this, i) + ": duplicate name (also joint " + std::to_string(it->second) +
             ")";
    }
    if (j.parent < -1 || j.parent >= joint_count()) {
      return describe(*this, i) + ": parent index " + std::to_string(j.parent) + " is out of range";
    }
    if (j.parent == i) return describe(*this, i) + ": is its own parent";
    if (j.parent > i) {
      return describe(*this, i) + ": parent " + describe(*this, j.parent) +
             " comes after it (joints must be stored parents before children)";
    }
    const glm::quat& q = j.rest.rotation;
    const float q_len = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    if (!finite(j.rest.translation) || !finite(j.rest.scale) || !std::isfinite(q_len)) {
      return describe(*this, i) + ": rest transform has a non-finite value";
    }
    // 1e-3: a unit quaternion stored as float and re-normalised by any tool is well within this;
    // anything further off was not meant as a rotation.
    if (std::fabs(q_len - 1.0f) > 1e-3f) {
      return describe(*this, i) + ": rest rotation is not a unit quaternion (length " +
             std::to_string(q_len) + ")";
    }
  }
  return {};
}

}  // namespace sw::skeleton

// Shortest rotation between two directions (seed 004, "Euler angles between two vectors").
#include "math/vector_rotation.h"

#include <cmath>

namespace sw::math {
namespace {

bool usable_direction(const glm::dvec3& v) {
  const double len = glm::length(v);
  return std::isfinite(len) && len > 0.0;
}

// An axis perpendicular to u: u × e, with e the coordinate axis least aligned with u (the cross
// product is then never small).
glm::dvec3 any_perpendicular(const glm::dvec3& u) {
  const glm::dvec3 a = glm::abs(u);
  glm::dvec3 e(0.0);
  if (a.x <= a.y && a.x <= a.z) {
    e.x = 1.0;
  } else if (a.y <= a.z) {
    e.y = 1.0;
  } else {
    e.z = 1.0;
  }
  return glm::normalize(glm::cross(u, e));
}

// 1 + cos(angle) below this: r1 and r2 are opposite to within ~1e-8 rad, where the cross product
// has lost its direction to rounding.
constexpr double kOppositeTolerance = 1e-15;

}  // namespace

glm::dquat rotation_between(const glm::dvec3& r1, const glm::dvec3& r2) {
  if (!usable_direction(r1) || !usable_direction(r2)) return glm::dquat(1.0, 0.0, 0.0, 0.0);
  const glm::dvec3 u = glm::normalize(r1), v = glm::normalize(r2);
  const double cos_angle = glm::dot(u, v);
  if (1.0 + cos_angle < kOppositeTolerance) {
    const glm::dvec3 axis = any_perpendicular(u);
    return glm::dquat(0.0, axis.x, axis.y, axis.z);  // 180°: w = cos 90° = 0, xyz = axis
  }
  // Half-angle form: q = (1 + cos θ, u × v) normalised equals (cos θ/2, sin θ/2 · axis), because
  // |u × v| = sin θ = 2 sin θ/2 cos θ/2 and 1 + cos θ = 2 cos² θ/2. It needs no acos and is exact
  // for parallel vectors (q = identity).
  const glm::dvec3 axis = glm::cross(u, v);
  return glm::normalize(glm::dquat(1.0 + cos_angle, axis.x, axis.y, axis.z));
}

glm::quat rotation_between(const glm::vec3& r1, const glm::vec3& r2) {
  return glm::quat(rotation_between(glm::dvec3(r1), glm::dvec3(r2)));
}

glm::dvec3 euler_between(const glm::dvec3& r1, const glm::dvec3& r2, EulerOrder order) {
  return euler_from_quat(rotation_between(r1, r2), order);
}

}  // namespace sw::math

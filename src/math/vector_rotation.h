// The rotation that takes one direction onto another, and its Euler angles — seed 004's problem
// "find φx, φy, φz that rotate r1 onto r2" for every order (SOURCES.md §1). The key-state capture
// of the seed turns each bone's old and new direction into these angles.
//
// The seed's printed t-terms are garbled, so this derives it: the shortest rotation about the axis
// r1 × r2 by the angle between them, then its Euler decomposition (math/euler.h) in the order
// asked. Degenerate pairs: parallel → identity; opposite → 180° about an axis perpendicular to r1
// (there are infinitely many; the one chosen is perpendicular to r1 and to the coordinate axis
// least aligned with r1, so the choice is deterministic and well conditioned).
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "math/euler.h"

namespace sw::math {

// r1, r2 need not be unit length but must be non-zero and finite; a zero or non-finite vector has
// no direction, and the identity is returned.
glm::dquat rotation_between(const glm::dvec3& r1, const glm::dvec3& r2);
glm::quat rotation_between(const glm::vec3& r1, const glm::vec3& r2);

// Euler angles (radians, per axis, math/euler.h convention) of rotation_between(r1, r2).
glm::dvec3 euler_between(const glm::dvec3& r1, const glm::dvec3& r2, EulerOrder order);

}  // namespace sw::math

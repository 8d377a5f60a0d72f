// Rotation between two directions and its Euler angles (math/vector_rotation.h, seed 004).
#include "math/vector_rotation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace sw::math {
namespace {

glm::dvec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  for (;;) {
    const glm::dvec3 v(n(rng), n(rng), n(rng));
    if (glm::length(v) > 1e-3) return glm::normalize(v);
  }
}

// Applies the Euler angles the way a BVH player would: rebuild the matrix from the angles.
glm::dvec3 apply_angles(const glm::dvec3& angles, EulerOrder order, const glm::dvec3& v) {
  return matrix_from_euler(angles, order) * v;
}

void expect_reproduces(const glm::dvec3& r1, const glm::dvec3& r2, const char* what) {
  for (EulerOrder order : kAllEulerOrders) {
    const glm::dvec3 angles = euler_between(r1, r2, order);
    const glm::dvec3 moved = apply_angles(angles, order, glm::normalize(r1));
    EXPECT_LT(glm::length(moved - glm::normalize(r2)), 1e-6)
        << what << " order " << euler_order_name(order);
  }
}

TEST(RotationBetween, RandomPairsEveryOrderReproduceR2) {
  std::mt19937 rng(4);
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 r1 = random_unit(rng), r2 = random_unit(rng);
    expect_reproduces(r1, r2, "random");
  }
}

TEST(RotationBetween, ParallelIsIdentity) {
  std::mt19937 rng(5);
  for (int i = 0; i < 100; ++i) {
    const glm::dvec3 r = random_unit(rng);
    const glm::dquat q = rotation_between(r, r);
    EXPECT_NEAR(std::fabs(q.w), 1.0, 1e-12);
    expect_reproduces(r, r, "parallel");
    expect_reproduces(r, r * 3.5, "parallel, different lengths");
  }
}

TEST(RotationBetween, OppositeIsHalfTurnAboutAPerpendicular) {
  std::mt19937 rng(6);
  std::vector<glm::dvec3> cases = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, 0, -1}};
  for (int i = 0; i < 100; ++i) cases.push_back(random_unit(rng));
  for (const glm::dvec3& r : cases) {
    const glm::dquat q = rotation_between(r, -r);
    EXPECT_NEAR(q.w, 0.0, 1e-12);                                     // 180°
    EXPECT_NEAR(glm::dot(glm::dvec3(q.x, q.y, q.z), r), 0.0, 1e-12);  // axis perpendicular to r
    expect_reproduces(r, -r, "opposite");
  }
}

TEST(RotationBetween, NearParallelAndNearOpposite) {
  std::mt19937 rng(8);
  for (int i = 0; i < 200; ++i) {
    const glm::dvec3 r = random_unit(rng);
    const glm::dvec3 side = glm::normalize(glm::cross(r, random_unit(rng)));
    for (double eps : {1e-4, 1e-7, 1e-10, 1e-13}) {
      expect_reproduces(r, glm::normalize(r + eps * side), "near-parallel");
      expect_reproduces(r, glm::normalize(-r + eps * side), "near-opposite");
    }
  }
}

TEST(RotationBetween, IsTheShortestRotation) {
  // The angle of the rotation equals the angle between the vectors (axis r1 x r2).
  const glm::dvec3 r1(1, 0, 0), r2 = glm::normalize(glm::dvec3(1, 1, 0));
  const glm::dquat q = rotation_between(r1, r2);
  EXPECT_NEAR(glm::angle(q), std::acos(glm::dot(r1, r2)), 1e-12);
  const glm::dvec3 axis = glm::axis(q);
  EXPECT_NEAR(axis.z, 1.0, 1e-12);
}

TEST(RotationBetween, SeedZyxFormulaAgrees) {
  // Seed 004's ZYX formulas: phi_x = atan(t32/t33), phi_y = atan(-t31/sqrt(t11^2+t21^2)),
  // phi_z = atan(t21/t11), with T the rotation matrix (1-based row, column).
  std::mt19937 rng(9);
  for (int i = 0; i < 200; ++i) {
    const glm::dvec3 r1 = random_unit(rng), r2 = random_unit(rng);
    const glm::dmat3 t = glm::mat3_cast(rotation_between(r1, r2));
    const auto T = [&](int row, int col) { return t[col - 1][row - 1]; };
    const glm::dvec3 seed(std::atan2(T(3, 2), T(3, 3)),
                          std::atan2(-T(3, 1), std::sqrt(T(1, 1) * T(1, 1) + T(2, 1) * T(2, 1))),
                          std::atan2(T(2, 1), T(1, 1)));
    EXPECT_LT(glm::length(euler_between(r1, r2, EulerOrder::ZYX) - seed), 1e-9);
  }
}

TEST(RotationBetween, ZeroOrNonFiniteVectorGivesIdentity) {
  const glm::dquat q1 = rotation_between(glm::dvec3(0.0), glm::dvec3(1, 0, 0));
  const glm::dquat q2 = rotation_between(glm::dvec3(1, 0, 0), glm::dvec3(NAN, 0, 0));
  EXPECT_EQ(q1.w, 1.0);
  EXPECT_EQ(q2.w, 1.0);
}

TEST(RotationBetween, FloatOverloadMatches) {
  const glm::quat q = rotation_between(glm::vec3(0, 1, 0), glm::vec3(0, 0, 1));
  const glm::vec3 moved = q * glm::vec3(0, 1, 0);
  EXPECT_NEAR(moved.z, 1.0f, 1e-6f);
}

}  // namespace
}  // namespace sw::math

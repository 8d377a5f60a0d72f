// Euler angles in six orders (math/euler.h): convention, round trips, gimbal lock.
#include "math/euler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace sw::math {
namespace {

constexpr double kPi = 3.14159265358979323846;

double quat_distance(const glm::dquat& a, const glm::dquat& b) {
  // q and -q are the same rotation: compare up to sign.
  const glm::dvec4 va(a.w, a.x, a.y, a.z), vb(b.w, b.x, b.y, b.z);
  return std::min(glm::length(va - vb), glm::length(va + vb));
}

glm::dmat3 rx(double a) {
  return glm::dmat3(1, 0, 0, 0, std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a));
}
glm::dmat3 ry(double a) {
  return glm::dmat3(std::cos(a), 0, -std::sin(a), 0, 1, 0, std::sin(a), 0, std::cos(a));
}
glm::dmat3 rz(double a) {
  return glm::dmat3(std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a), 0, 0, 0, 1);
}

double matrix_distance(const glm::dmat3& a, const glm::dmat3& b) {
  double d = 0;
  for (int c = 0; c < 3; ++c) d = std::max(d, glm::length(a[c] - b[c]));
  return d;
}

TEST(EulerOrderNames, ParseAndPrintAllSix) {
  for (EulerOrder order : kAllEulerOrders) {
    const std::optional<EulerOrder> parsed = parse_euler_order(euler_order_name(order));
    ASSERT_TRUE(parsed.has_value());
    EXPECT_EQ(*parsed, order);
  }
  EXPECT_EQ(parse_euler_order("zxy"), EulerOrder::ZXY);
  EXPECT_FALSE(parse_euler_order("XXY").has_value());
  EXPECT_FALSE(parse_euler_order("XY").has_value());
  EXPECT_FALSE(parse_euler_order("XYW").has_value());
}

TEST(EulerConvention, OrderNamesTheCompositionLeftToRight) {
  // XYZ means Rx * Ry * Rz (the BVH channel order as listed), checked against explicit matrices.
  const glm::dvec3 a(0.3, -0.7, 1.1);
  EXPECT_LT(matrix_distance(matrix_from_euler(a, EulerOrder::XYZ), rx(a.x) * ry(a.y) * rz(a.z)),
            1e-12);
  EXPECT_LT(matrix_distance(matrix_from_euler(a, EulerOrder::XZY), rx(a.x) * rz(a.z) * ry(a.y)),
            1e-12);
  EXPECT_LT(matrix_distance(matrix_from_euler(a, EulerOrder::YXZ), ry(a.y) * rx(a.x) * rz(a.z)),
            1e-12);
  EXPECT_LT(matrix_distance(matrix_from_euler(a, EulerOrder::YZX), ry(a.y) * rz(a.z) * rx(a.x)),
            1e-12);
  EXPECT_LT(matrix_distance(matrix_from_euler(a, EulerOrder::ZXY), rz(a.z) * rx(a.x) * ry(a.y)),
            1e-12);
  EXPECT_LT(matrix_distance(matrix_from_euler(a, EulerOrder::ZYX), rz(a.z) * ry(a.y) * rx(a.x)),
            1e-12);
}

TEST(EulerConvention, PositiveAngleIsRightHanded) {
  // +90° about Z takes +X to +Y (right-handed, glTF).
  const glm::dvec3 v =
      matrix_from_euler(glm::dvec3(0, 0, kPi / 2), EulerOrder::XYZ) * glm::dvec3(1, 0, 0);
  EXPECT_NEAR(v.x, 0.0, 1e-12);
  EXPECT_NEAR(v.y, 1.0, 1e-12);
}

TEST(EulerConvention, QuaternionAndMatrixAgree) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (EulerOrder order : kAllEulerOrders) {
    for (int i = 0; i < 100; ++i) {
      const glm::dvec3 a(angle(rng), angle(rng), angle(rng));
      EXPECT_LT(
          matrix_distance(glm::mat3_cast(quat_from_euler(a, order)), matrix_from_euler(a, order)),
          1e-12);
    }
  }
}

// The acceptance: 10,000 random rotations x 6 orders, angles -> quat -> angles -> quat,
// within 1e-5 (single precision, what the runtime stores).
TEST(EulerRoundTrip, TenThousandRandomRotationsInEveryOrderFloat) {
  std::mt19937 rng(2012);
  std::uniform_real_distribution<float> angle(-3.14159f, 3.14159f);
  for (EulerOrder order : kAllEulerOrders) {
    double worst = 0.0;
    for (int i = 0; i < 10000; ++i) {
      const glm::vec3 a(angle(rng), angle(rng), angle(rng));
      const glm::quat q = quat_from_euler(a, order);
      const glm::vec3 back = euler_from_quat(q, order);
      const glm::quat q2 = quat_from_euler(back, order);
      worst = std::max(worst, quat_distance(glm::dquat(q), glm::dquat(q2)));
    }
    EXPECT_LT(worst, 1e-5) << euler_order_name(order);
  }
}

TEST(EulerRoundTrip, RandomRotationsInEveryOrderDouble) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (EulerOrder order : kAllEulerOrders) {
    for (int i = 0; i < 2000; ++i) {
      const glm::dvec3 a(angle(rng), angle(rng), angle(rng));
      const glm::dquat q = quat_from_euler(a, order);
      EXPECT_LT(quat_distance(q, quat_from_euler(euler_from_quat(q, order), order)), 1e-12);
    }
  }
}

TEST(EulerRoundTrip, AnglesInTheCanonicalRangeComeBackUnchanged) {
  // Away from gimbal lock the decomposition is unique with the middle angle in (-pi/2, pi/2).
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> outer(-3.1, 3.1), middle(-1.5, 1.5);
  for (EulerOrder order : kAllEulerOrders) {
    for (int i = 0; i < 1000; ++i) {
      glm::dvec3 a;
      a[euler_axis(order, 0)] = outer(rng);
      a[euler_axis(order, 1)] = middle(rng);
      a[euler_axis(order, 2)] = outer(rng);
      const glm::dvec3 back = euler_from_quat(quat_from_euler(a, order), order);
      EXPECT_LT(glm::length(back - a), 1e-9) << euler_order_name(order);
    }
  }
}

TEST(EulerGimbalLock, MiddleAngleAtPlusMinus90IsDeterministicAndExact) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (EulerOrder order : kAllEulerOrders) {
    for (double middle : {kPi / 2, -kPi / 2}) {
      for (int i = 0; i < 200; ++i) {
        glm::dvec3 a;
        a[euler_axis(order, 0)] = angle(rng);
        a[euler_axis(order, 1)] = middle;
        a[euler_axis(order, 2)] = angle(rng);
        const glm::dquat q = quat_from_euler(a, order);
        const glm::dvec3 back = euler_from_quat(q, order);
        // The consistent choice: the first angle is 0, the middle one is kept.
        EXPECT_NEAR(back[euler_axis(order, 0)], 0.0, 1e-6) << euler_order_name(order);
        EXPECT_NEAR(back[euler_axis(order, 1)], middle, 1e-6) << euler_order_name(order);
        EXPECT_LT(quat_distance(q, quat_from_euler(back, order)), 1e-6) << euler_order_name(order);
        // The float path is exact to float precision too.
        const glm::quat qf(q);
        EXPECT_LT(quat_distance(glm::dquat(qf),
                                glm::dquat(quat_from_euler(euler_from_quat(qf, order), order))),
                  1e-5);
      }
    }
  }
}

TEST(EulerGimbalLock, NearLockStaysExact) {
  for (EulerOrder order : kAllEulerOrders) {
    for (double eps : {1e-3, 1e-5, 1e-7, 1e-9}) {
      glm::dvec3 a;
      a[euler_axis(order, 0)] = 0.4;
      a[euler_axis(order, 1)] = kPi / 2 - eps;
      a[euler_axis(order, 2)] = -1.2;
      const glm::dquat q = quat_from_euler(a, order);
      EXPECT_LT(quat_distance(q, quat_from_euler(euler_from_quat(q, order), order)), 1e-6)
          << euler_order_name(order) << " eps " << eps;
    }
  }
}

TEST(EulerFromMatrix, AcceptsMatricesAndQuaternionsAlike) {
  const glm::dvec3 a(0.2, 0.5, -0.9);
  for (EulerOrder order : kAllEulerOrders) {
    const glm::dvec3 from_matrix = euler_from_matrix(matrix_from_euler(a, order), order);
    const glm::dvec3 from_quat = euler_from_quat(quat_from_euler(a, order), order);
    EXPECT_LT(glm::length(from_matrix - a), 1e-12);
    EXPECT_LT(glm::length(from_quat - a), 1e-12);
  }
}

TEST(EulerFromQuat, UnnormalisedQuaternionIsNormalisedFirst) {
  const glm::dvec3 a(0.2, 0.5, -0.9);
  const glm::dquat q = quat_from_euler(a, EulerOrder::ZXY) * 3.0;
  EXPECT_LT(glm::length(euler_from_quat(q, EulerOrder::ZXY) - a), 1e-12);
}

TEST(EulerNear, ReproducesTheRotationAndStaysWithinHalfATurnOfTheReference) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> angle(-kPi, kPi), far(-20.0, 20.0);
  for (EulerOrder order : kAllEulerOrders) {
    for (int i = 0; i < 2000; ++i) {
      const glm::dquat q = quat_from_euler(glm::dvec3(angle(rng), angle(rng), angle(rng)), order);
      const glm::dvec3 reference(far(rng), far(rng), far(rng));
      const glm::dvec3 near = euler_from_quat_near(q, order, reference);
      EXPECT_LT(quat_distance(q, quat_from_euler(near, order)), 1e-9) << euler_order_name(order);
      for (int axis = 0; axis < 3; ++axis)
        EXPECT_LE(std::fabs(near[axis] - reference[axis]), kPi + 1e-9);
    }
  }
}

TEST(EulerNear, ReferenceEqualToASolutionReturnsIt) {
  // Angles outside the principal range (middle beyond 90°, outer beyond 180°) come back unchanged.
  const glm::dvec3 a(4.0, 2.0, -3.5);
  for (EulerOrder order : kAllEulerOrders) {
    const glm::dvec3 back = euler_from_quat_near(quat_from_euler(a, order), order, a);
    EXPECT_LT(glm::length(back - a), 1e-9) << euler_order_name(order);
  }
}

TEST(EulerNear, SmoothMotionGivesContinuousAngles) {
  // What BVH export needs: a joint spinning two full turns, and one bending through the middle
  // axis' 90° (where the principal decomposition flips), give angle tracks without jumps.
  for (EulerOrder order : kAllEulerOrders) {
    glm::dvec3 previous(0.0);
    for (int step = 0; step <= 720; ++step) {
      glm::dvec3 a;
      a[euler_axis(order, 0)] = 0.3;
      a[euler_axis(order, 1)] = 0.005 * step;  // 0 .. 3.6 rad, through pi/2
      a[euler_axis(order, 2)] = 0.02 * step;   // two turns and more
      const glm::dquat q = quat_from_euler(a, order);
      const glm::dvec3 now = euler_from_quat_near(q, order, previous);
      if (step > 0) {
        EXPECT_LT(glm::length(now - previous), 0.05) << euler_order_name(order) << " step " << step;
      }
      EXPECT_LT(quat_distance(q, quat_from_euler(now, order)), 1e-9);
      previous = now;
    }
  }
}

TEST(EulerNear, AtGimbalLockKeepsTheReferenceFirstAngle) {
  for (EulerOrder order : kAllEulerOrders) {
    glm::dvec3 a;
    a[euler_axis(order, 0)] = 0.7;
    a[euler_axis(order, 1)] = kPi / 2;
    a[euler_axis(order, 2)] = -0.4;
    const glm::dquat q = quat_from_euler(a, order);
    const glm::dvec3 near = euler_from_quat_near(q, order, a);
    EXPECT_NEAR(near[euler_axis(order, 0)], 0.7, 1e-9);
    EXPECT_LT(glm::length(near - a), 1e-6) << euler_order_name(order);
  }
}

}  // namespace
}  // namespace sw::math

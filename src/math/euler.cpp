// Euler angles <-> rotation, all six Tait-Bryan orders from one parametrised formula.
//
// For R = Ri(a) * Rj(b) * Rk(c) with (i, j, k) a permutation of the axes, let s = +1 when (i, j, k)
// is cyclic (XYZ, YZX, ZXY) and s = -1 otherwise. Writing R[r][c] for row r, column c:
//   row i of R is row i of Rj(b)*Rk(c), so  R[i][k] = s*sin b,  R[i][i]^2 + R[i][j]^2 = cos^2 b;
//   column k of R is Ri(a) applied to Rj(b) e_k, so  -s*R[j][k] = sin a cos b,  R[k][k] = cos a cos
//   b; with a known, M = Ri(-a) * R = Rj(b) * Rk(c), and row j of M is row j of Rk(c): s*M[j][i] =
//   sin c, M[j][j] = cos c.
// Taking c from M rather than from row i of R is what keeps the decomposition exact near gimbal
// lock: whatever a is, c is the angle that makes Ri(a) Rj(b) Rk(c) equal R.
// For ZYX this reduces to seed 004's φx = atan(t32/t33), φy = atan(−t31/sqrt(t11²+t21²)),
// φz = atan(t21/t11), with atan2 choosing the quadrant the paper leaves as "+ nπ".
#include "math/euler.h"

#include <cctype>
#include <cmath>

namespace sw::math {
namespace {

struct Axes {
  int i, j, k;
  double parity;  // +1 for cyclic orders, -1 for the others
};

Axes axes_of(EulerOrder order) {
  switch (order) {
    case EulerOrder::XYZ:
      return {0, 1, 2, 1.0};
    case EulerOrder::XZY:
      return {0, 2, 1, -1.0};
    case EulerOrder::YXZ:
      return {1, 0, 2, -1.0};
    case EulerOrder::YZX:
      return {1, 2, 0, 1.0};
    case EulerOrder::ZXY:
      return {2, 0, 1, 1.0};
    case EulerOrder::ZYX:
      return {2, 1, 0, -1.0};
  }
  return {0, 1, 2, 1.0};
}

// glm matrices are column-major: m[column][row]. These keep the formulas in row/column order.
double at(const glm::dmat3& m, int row, int column) { return m[column][row]; }

glm::dvec3 unit_axis(int axis) {
  glm::dvec3 v(0.0);
  v[axis] = 1.0;
  return v;
}

glm::dmat3 axis_rotation(int axis, double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  const int p = (axis + 1) % 3, q = (axis + 2) % 3;
  glm::dmat3 m(1.0);
  m[p][p] = c;   // column p, row p
  m[p][q] = s;   // column p, row q: R e_p = c e_p + s e_q
  m[q][p] = -s;  // column q, row p: R e_q = -s e_p + c e_q
  m[q][q] = c;
  return m;
}

// Below this cos(middle angle) the first and third axes are treated as aligned. The input is at
// best double-rounded float data (|error| ~ 1e-7 per element), so smaller values carry no
// information about the split between the first and third angle.
constexpr double kGimbalLockCos = 1e-7;
constexpr double kPi = 3.14159265358979323846;

// The decomposition with the first angle fixed to `a`: the middle and third angles follow from
// M = Ri(-a) * R = Rj(b) * Rk(c) (row j of M is row j of Rk(c); column k is Rj(b) e_k).
glm::dvec3 decompose_with_first(const glm::dmat3& r, const Axes& x, double a) {
  const double s = x.parity;
  const glm::dmat3 m = axis_rotation(x.i, -a) * r;
  const double c = std::atan2(s * at(m, x.j, x.i), at(m, x.j, x.j));
  const double b = std::atan2(s * at(m, x.i, x.k), at(m, x.k, x.k));
  glm::dvec3 angles;
  angles[x.i] = a;
  angles[x.j] = b;
  angles[x.k] = c;
  return angles;
}

}  // namespace

const char* euler_order_name(EulerOrder order) {
  switch (order) {
    case EulerOrder::XYZ:
      return "XYZ";
    case EulerOrder::XZY:
      return "XZY";
    case EulerOrder::YXZ:
      return "YXZ";
    case EulerOrder::YZX:
      return "YZX";
    case EulerOrder::ZXY:
      return "ZXY";
    case EulerOrder::ZYX:
      return "ZYX";
  }
  return "XYZ";
}

std::optional<EulerOrder> parse_euler_order(std::string_view name) {
  if (name.size() != 3) return std::nullopt;
  int axis[3];
  for (int p = 0; p < 3; ++p) {
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(name[p])));
    if (c < 'X' || c > 'Z') return std::nullopt;
    axis[p] = c - 'X';
  }
  return euler_order_from_axes(axis[0], axis[1], axis[2]);
}

int euler_axis(EulerOrder order, int position) {
  const Axes a = axes_of(order);
  return position == 0 ? a.i : position == 1 ? a.j : a.k;
}

std::optional<EulerOrder> euler_order_from_axes(int a, int b, int c) {
  for (EulerOrder order : kAllEulerOrders) {
    const Axes x = axes_of(order);
    if (x.i == a && x.j == b && x.k == c) return order;
  }
  return std::nullopt;
}

glm::dmat3 matrix_from_euler(const glm::dvec3& angles_rad, EulerOrder order) {
  const Axes a = axes_of(order);
  return axis_rotation(a.i, angles_rad[a.i]) * axis_rotation(a.j, angles_rad[a.j]) *
         axis_rotation(a.k, angles_rad[a.k]);
}

glm::dquat quat_from_euler(const glm::dvec3& angles_rad, EulerOrder order) {
  const Axes a = axes_of(order);
  return glm::angleAxis(angles_rad[a.i], unit_axis(a.i)) *
         glm::angleAxis(angles_rad[a.j], unit_axis(a.j)) *
         glm::angleAxis(angles_rad[a.k], unit_axis(a.k));
}

glm::dvec3 euler_from_matrix(const glm::dmat3& r, EulerOrder order) {
  const Axes x = axes_of(order);
  const double s = x.parity;
  const double cos_b =
      std::sqrt(at(r, x.i, x.i) * at(r, x.i, x.i) + at(r, x.i, x.j) * at(r, x.i, x.j));
  const double b = std::atan2(s * at(r, x.i, x.k), cos_b);
  double a = 0.0;  // gimbal lock: the first angle is 0 by choice, the third carries the rotation
  if (cos_b > kGimbalLockCos) a = std::atan2(-s * at(r, x.j, x.k), at(r, x.k, x.k));
  const glm::dmat3 m = axis_rotation(x.i, -a) * r;
  const double c = std::atan2(s * at(m, x.j, x.i), at(m, x.j, x.j));
  glm::dvec3 angles;
  angles[x.i] = a;
  angles[x.j] = b;
  angles[x.k] = c;
  return angles;
}

glm::dvec3 euler_from_quat_near(const glm::dquat& rotation, EulerOrder order,
                                const glm::dvec3& reference) {
  constexpr double kTwoPi = 6.283185307179586;
  const Axes x = axes_of(order);
  const glm::dmat3 r = glm::mat3_cast(glm::normalize(rotation));
  const auto nearest_turn = [&](double angle, double ref) {
    return angle + kTwoPi * std::round((ref - angle) / kTwoPi);
  };
  const auto shifted = [&](glm::dvec3 angles) {
    for (int axis = 0; axis < 3; ++axis) angles[axis] = nearest_turn(angles[axis], reference[axis]);
    return angles;
  };
  const glm::dvec3 principal = euler_from_matrix(r, order);
  const double cos_b = std::cos(principal[x.j]);
  if (cos_b <= kGimbalLockCos) {
    // Only the combination of first and third angle is determined: keep the reference's first.
    return shifted(decompose_with_first(r, x, reference[x.i]));
  }
  // Ri(a + pi) Rj(pi - b) Rk(c + pi) = Ri(a) Rj(b) Rk(c), since Ri(pi) Rj(pi - b) Rk(pi) = Rj(b).
  glm::dvec3 alternative = principal;
  alternative[x.i] += kPi;
  alternative[x.j] = kPi - principal[x.j];
  alternative[x.k] += kPi;
  const glm::dvec3 first = shifted(principal), second = shifted(alternative);
  const glm::dvec3 d1 = first - reference, d2 = second - reference;
  return glm::dot(d1, d1) <= glm::dot(d2, d2) ? first : second;
}

glm::dvec3 euler_from_quat(const glm::dquat& rotation, EulerOrder order) {
  return euler_from_matrix(glm::mat3_cast(glm::normalize(rotation)), order);
}

glm::mat3 matrix_from_euler(const glm::vec3& angles_rad, EulerOrder order) {
  return glm::mat3(matrix_from_euler(glm::dvec3(angles_rad), order));
}
glm::quat quat_from_euler(const glm::vec3& angles_rad, EulerOrder order) {
  return glm::quat(quat_from_euler(glm::dvec3(angles_rad), order));
}
glm::vec3 euler_from_matrix(const glm::mat3& rotation, EulerOrder order) {
  return glm::vec3(euler_from_matrix(glm::dmat3(rotation), order));
}
glm::vec3 euler_from_quat(const glm::quat& rotation, EulerOrder order) {
  return glm::vec3(euler_from_quat(glm::dquat(rotation), order));
}

}  // namespace sw::math

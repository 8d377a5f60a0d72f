// Euler angles in the six Tait-Bryan orders, to and from quaternions and rotation matrices.
//
// Convention (the BVH one, seed 004 §"Skeleton"): the order names the rotations as composed left to
// right. Order XYZ means R = Rx(x) * Ry(y) * Rz(z) acting on column vectors, which is how a BVH
// file listing "Xrotation Yrotation Zrotation" is read: rotate about the parent's X, then the new
// Y, then the newer Z (intrinsic), equivalently Z first in fixed axes.
//
// Angles are always stored per axis — angles.x is the angle about X whatever the order — in
// radians.
//
// Gimbal lock: when the middle angle is ±90°, the first and third axes coincide and only their sum
// (or difference) is determined. The decomposition then sets the first angle to 0 and puts the
// whole rotation into the third, so the result is deterministic and reproduces the rotation
// exactly.
//
// Does not: handle proper Euler orders (XYX, ZXZ ...) — BVH and the seed use only Tait-Bryan
// orders.
#pragma once

#include <optional>
#include <string_view>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace sw::math {

enum class EulerOrder { XYZ, XZY, YXZ, YZX, ZXY, ZYX };

inline constexpr EulerOrder kAllEulerOrders[] = {EulerOrder::XYZ, EulerOrder::XZY, EulerOrder::YXZ,
                                                 EulerOrder::YZX, EulerOrder::ZXY, EulerOrder::ZYX};

// "XYZ" ... "ZYX".
const char* euler_order_name(EulerOrder order);
// Inverse of euler_order_name (upper or lower case); nullopt for anything else.
std::optional<EulerOrder> parse_euler_order(std::string_view name);
// The axis (0 = X, 1 = Y, 2 = Z) applied at position 0, 1, 2 of the composition.
int euler_axis(EulerOrder order, int position);
// The order whose axes are a, b, c (each 0..2, all different); nullopt if they repeat.
std::optional<EulerOrder> euler_order_from_axes(int a, int b, int c);

// Double precision: the reference implementation (tests, BVH, offline tools).
glm::dmat3 matrix_from_euler(const glm::dvec3& angles_rad, EulerOrder order);
glm::dquat quat_from_euler(const glm::dvec3& angles_rad, EulerOrder order);
// The middle angle lies in [-pi/2, pi/2], the other two in (-pi, pi].
glm::dvec3 euler_from_matrix(const glm::dmat3& rotation, EulerOrder order);
glm::dvec3 euler_from_quat(const glm::dquat& rotation, EulerOrder order);

// The decomposition closest to `reference` (e.g. the previous frame's angles): of the two
// Tait-Bryan solutions (a, b, c) and (a + pi, pi - b, c + pi), each angle shifted by whole turns,
// the one nearest the reference; at gimbal lock the first angle is the reference's. Angles are then
// not limited to (-pi, pi]: an animation turning through 180° keeps turning instead of flipping,
// which BVH players (interpolating angles) need.
glm::dvec3 euler_from_quat_near(const glm::dquat& rotation, EulerOrder order,
                                const glm::dvec3& reference);

// Single precision: what the runtime (Transform, Clip) stores. Computed in double internally.
glm::mat3 matrix_from_euler(const glm::vec3& angles_rad, EulerOrder order);
glm::quat quat_from_euler(const glm::vec3& angles_rad, EulerOrder order);
glm::vec3 euler_from_matrix(const glm::mat3& rotation, EulerOrder order);
glm::vec3 euler_from_quat(const glm::quat& rotation, EulerOrder order);

}  // namespace sw::math

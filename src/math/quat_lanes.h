// glm's quaternion arithmetic four lanes at a time, to the bit: GCC/Clang vector extensions that
// g++ lowers to SSE and em++ to WebAssembly SIMD (-msimd128) or, in the scalar build, to scalar
// code (as skeleton/local_to_model.cpp does). Each lane does the products and sums glm does for
// that component, in glm's order (glm/detail/type_quat.inl operator*=, quaternion normalize,
// quat * vec3 by two cross products), so a result is glm's own; only the lanes run side by side.
// The synthesis hot loops (frame-by-frame FK, transition slerps) use it; they must not change a
// bit of the motion. glm stores a quaternion x, y, z, w, and so do the lanes.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace sw::math::lanes {

typedef float Float4 __attribute__((vector_size(16)));

inline Float4 load4(const glm::quat& q) {
  Float4 r;
  std::memcpy(&r, &q, sizeof r);
  return r;
}
inline Float4 load4(const glm::vec4& v) {
  Float4 r;
  std::memcpy(&r, &v, sizeof r);
  return r;
}
inline void store4(glm::quat* q, Float4 v) { std::memcpy(q, &v, sizeof v); }
inline Float4 load3(const glm::vec3& v) { return Float4{v.x, v.y, v.z, 0.0f}; }

// p * q: lane x = ((pw qx + px qw) + py qz) - pz qy, and so on; lane w = ((pw qw - px qx) - py qy)
// - pz qz, the subtractions as additions of the negated product (IEEE: the same result).
inline Float4 quat_mul(Float4 p, Float4 q) {
  const Float4 minus_w{1.0f, 1.0f, 1.0f, -1.0f};
  const Float4 t1 = __builtin_shufflevector(p, p, 3, 3, 3, 3) * q;
  const Float4 t2 = __builtin_shufflevector(p, p, 0, 1, 2, 0) *
                    __builtin_shufflevector(q, q, 3, 3, 3, 0) * minus_w;
  const Float4 t3 = __builtin_shufflevector(p, p, 1, 2, 0, 1) *
                    __builtin_shufflevector(q, q, 2, 0, 1, 1) * minus_w;
  const Float4 t4 =
      __builtin_shufflevector(p, p, 2, 0, 1, 2) * __builtin_shufflevector(q, q, 1, 2, 0, 2);
  return ((t1 + t2) + t3) - t4;
}

// glm::conjugate: x, y, z negated.
inline Float4 quat_conjugate(Float4 q) { return q * Float4{-1.0f, -1.0f, -1.0f, 1.0f}; }

// glm::normalize(quat): length sqrt((w w + x x) + (y y + z z)), the identity for a zero length.
// The four squares in one product and the two inner sums side by side (lanes 0 and 1: w w + x x
// and y y + z z; an IEEE sum is the same either way round), then their sum: the same operations
// as the scalar formula, without taking the lanes apart first (PoseBuilder::set_from_local
// spent more on the scalar length than on one of its quaternion products; callgrind, lexicon).
inline Float4 quat_normalize(Float4 q) {
  const Float4 squares = q * q;
  const Float4 halves = __builtin_shufflevector(squares, squares, 3, 1, 3, 1) +
                        __builtin_shufflevector(squares, squares, 0, 2, 0, 2);
  const float len = std::sqrt(halves[0] + halves[1]);
  if (len <= 0.0f) return Float4{0.0f, 0.0f, 0.0f, 1.0f};
  const float inverse = 1.0f / len;
  return q * inverse;
}

// glm::cross(a, b) in lanes x y z: (a.y b.z - b.y a.z, a.z b.x - b.z a.x, a.x b.y - b.x a.y).
inline Float4 cross3(Float4 a, Float4 b) {
  return __builtin_shufflevector(a, a, 1, 2, 0, 3) * __builtin_shufflevector(b, b, 2, 0, 1, 3) -
         __builtin_shufflevector(b, b, 1, 2, 0, 3) * __builtin_shufflevector(a, a, 2, 0, 1, 3);
}

// glm's q * v: v + ((uv * w) + uuv) * 2 with uv = cross(q.xyz, v), uuv = cross(q.xyz, uv).
inline Float4 quat_rotate(Float4 q, Float4 v) {
  const Float4 uv = cross3(q, v), uuv = cross3(q, uv);
  return v + ((uv * q[3]) + uuv) * 2.0f;
}

// Bitwise equality of two quaternions: the incremental posing rule (PoseBuilder, SubsetPose)
// keeps a joint whose local rotation has the same bits. Not memcmp: em++ keeps that a libc call
// per joint, which cost more than it saved; four integer compares inline everywhere.
inline bool same_bits(const glm::quat& a, const glm::quat& b) {
  std::uint32_t x[4], y[4];
  std::memcpy(x, &a, sizeof x);
  std::memcpy(y, &b, sizeof y);
  return ((x[0] ^ y[0]) | (x[1] ^ y[1]) | (x[2] ^ y[2]) | (x[3] ^ y[3])) == 0;
}

}  // namespace sw::math::lanes

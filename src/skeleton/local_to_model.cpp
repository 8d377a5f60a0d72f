// Forward kinematics: model[i] = model[parent(i)] * local[i], parents first (seed 004: each link's
// transition matrix from its parent; glTF 2.0 §3.7.3 global transforms).
#include "skeleton/local_to_model.h"

#include <cstring>

namespace sw::skeleton {
namespace {

// True when `joint` lies in the sub-tree rooted at `root`. Parents precede children, so every
// ancestor has a smaller index and the walk stops as soon as it passes below `root`.
bool in_subtree(const Skeleton& s, int joint, int root) {
  while (joint > root) joint = s.joints[static_cast<std::size_t>(joint)].parent;
  return joint == root;
}

// The hot loop, written with GCC/Clang vector extensions: one source that g++ lowers to SSE and
// em++ to WebAssembly SIMD (-msimd128) or to scalar code in the scalar build. A column of the
// product is a sum of parent columns scaled by the local column's entries.
typedef float Float4 __attribute__((vector_size(16)));

inline Float4 load(const glm::vec4& v) {
  Float4 r;
  std::memcpy(&r, &v, sizeof r);
  return r;
}
inline void store(glm::vec4& v, Float4 r) { std::memcpy(&v, &r, sizeof r); }

// out = parent * T * R * S. The local matrix is affine (bottom row 0 0 0 1), so each of its first
// three columns needs three multiply-adds and the translation column one more: 12 instead of 16.
inline void model_times_transform(const glm::mat4& parent, const math::Transform& local,
                                  glm::mat4& out) {
  const glm::mat3 r = glm::mat3_cast(local.rotation);
  const Float4 p0 = load(parent[0]), p1 = load(parent[1]), p2 = load(parent[2]),
               p3 = load(parent[3]);
  for (int c = 0; c < 3; ++c) {
    const glm::vec3 column = r[c] * local.scale[c];
    store(out[c], p0 * column.x + p1 * column.y + p2 * column.z);
  }
  const glm::vec3& t = local.translation;
  store(out[3], p0 * t.x + p1 * t.y + p2 * t.z + p3);
}

// out = parent * local for a general local matrix.
inline void model_times_matrix(const glm::mat4& parent, const glm::mat4& local, glm::mat4& out) {
  const Float4 p0 = load(parent[0]), p1 = load(parent[1]), p2 = load(parent[2]),
               p3 = load(parent[3]);
  for (int c = 0; c < 4; ++c) {
    const glm::vec4& l = local[c];
    store(out[c], p0 * l.x + p1 * l.y + p2 * l.z + p3 * l.w);
  }
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
  const int first = from < 0 ? 0 : from;
  const bool from_transforms = input_matrices.data == nullptr;

  for (int i = first; i <= last; ++i) {
    // In a partial update, joints after `from` that are not its descendants keep their matrices.
    if (from >= 0 && i != from && !in_subtree(s, i, from)) continue;
    const std::size_t joint = static_cast<std::size_t>(i);
    const int p = s.joints[joint].parent;
    const glm::mat4& parent = p < 0 ? above_roots : output[static_cast<std::size_t>(p)];
    if (from_transforms) {
      model_times_transform(parent, input[joint], output[joint]);
    } else {
      model_times_matrix(parent, input_matrices[joint], output[joint]);
    }
  }
  return true;
}

}  // namespace sw::skeleton

// Embind API of the core's foundation: version, Euler conversions, seed 004's vector-to-vector
// angles, and FK on the synthetic humanoid (for the node parity tests and the WASM benchmark).
// Thin by rule (ARCHITECTURE.md): argument conversion only; the logic is in src/math, src/skeleton.
//
// JS sees angles in radians as plain arrays [x, y, z] (per axis, math/euler.h), quaternions as
// [w, x, y, z], orders as the strings "XYZ" ... "ZYX"; a bad order name gives null, not an abort.
// Matrices come back as a Float32Array VIEW into WASM memory (column-major, 16 floats per joint):
// no copy, valid until the next call that may grow memory.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "math/euler.h"
#include "math/vector_rotation.h"
#include "skeleton/local_to_model.h"
#include "skeleton/synthetic_humanoid.h"

namespace {

using emscripten::val;

val to_array(std::initializer_list<double> values) {
  val out = val::array();
  unsigned i = 0;
  for (double v : values) out.set(i++, v);
  return out;
}

std::string version() { return SIGNWEAVE_VERSION; }

val quat_from_euler(float x, float y, float z, const std::string& order_name) {
  const auto order = sw::math::parse_euler_order(order_name);
  if (!order) return val::null();
  const glm::quat q = sw::math::quat_from_euler(glm::vec3(x, y, z), *order);
  return to_array({q.w, q.x, q.y, q.z});
}

val euler_from_quat(float w, float x, float y, float z, const std::string& order_name) {
  const auto order = sw::math::parse_euler_order(order_name);
  if (!order) return val::null();
  const glm::vec3 a = sw::math::euler_from_quat(glm::quat(w, x, y, z), *order);
  return to_array({a.x, a.y, a.z});
}

val euler_between(double x1, double y1, double z1, double x2, double y2, double z2, const std::string& order_name) {
  const auto order = sw::math::parse_euler_order(order_name);
  if (!order) return val::null();
  const glm::dvec3 a = sw::math::euler_between(glm::dvec3(x1, y1, z1), glm::dvec3(x2, y2, z2), *order);
  return to_array({a.x, a.y, a.z});
}

// The synthetic 65-joint humanoid with a pose buffer and its model matrices, so JS can drive the
// LocalToModelJob without marshalling a skeleton.
class SyntheticHumanoidFk {
 public:
  SyntheticHumanoidFk() : skeleton_(sw::skeleton::make_synthetic_humanoid()) {
    local_ = sw::skeleton::make_synthetic_pose(skeleton_, 0, 0.0f);
    model_.resize(local_.size(), glm::mat4(1.0f));
    job_.skeleton = &skeleton_;
    job_.input = local_;
    job_.output = model_;
  }
  SyntheticHumanoidFk(const SyntheticHumanoidFk&) = delete;  // the job points into this object
  SyntheticHumanoidFk& operator=(const SyntheticHumanoidFk&) = delete;

  int joint_count() const { return skeleton_.joint_count(); }
  int find(const std::string& name) const { return skeleton_.find(name); }
  void set_pose(std::uint32_t seed) {
    // Copied into the existing buffer: the job's input span must keep pointing at it.
    const std::vector<sw::math::Transform> pose = sw::skeleton::make_synthetic_pose(skeleton_, seed);
    std::copy(pose.begin(), pose.end(), local_.begin());
  }
  // from = -1: the whole skeleton; else the root joint of the sub-tree to recompute.
  bool run(int from) {
    job_.from = from;
    return job_.run();
  }
  // Benchmark helper: the loop stays inside WASM, so the figure is FK and not the JS->WASM call.
  bool run_repeatedly(int from, int count) {
    job_.from = from;
    bool ok = true;
    for (int i = 0; i < count; ++i) ok = job_.run() && ok;
    return ok;
  }
  val model_view() const {
    return val(emscripten::typed_memory_view(model_.size() * 16, reinterpret_cast<const float*>(model_.data())));
  }

 private:
  sw::skeleton::Skeleton skeleton_;
  std::vector<sw::math::Transform> local_;
  std::vector<glm::mat4> model_;
  sw::skeleton::LocalToModelJob job_;
};

bool simd_build() {
#ifdef SIGNWEAVE_SIMD
  return true;
#else
  return false;
#endif
}

}  // namespace

EMSCRIPTEN_BINDINGS(core_api) {
  emscripten::function("version", &version);
  emscripten::function("simd", &simd_build);
  emscripten::function("quatFromEuler", &quat_from_euler);
  emscripten::function("eulerFromQuat", &euler_from_quat);
  emscripten::function("eulerBetween", &euler_between);
  emscripten::class_<SyntheticHumanoidFk>("SyntheticHumanoidFk")
      .constructor<>()
      .function("jointCount", &SyntheticHumanoidFk::joint_count)
      .function("find", &SyntheticHumanoidFk::find)
      .function("setPose", &SyntheticHumanoidFk::set_pose)
      .function("run", &SyntheticHumanoidFk::run)
      .function("runRepeatedly", &SyntheticHumanoidFk::run_repeatedly)
      .function("modelView", &SyntheticHumanoidFk::model_view);
}

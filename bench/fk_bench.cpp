// Forward kinematics on the synthetic 65-joint humanoid (skeleton/synthetic_humanoid.h): the cost
// of one full pose update, and of a partial update of the right hand's sub-tree (what the page pays
// after hand IK). Same workload as bench/fk_bench.mjs runs in WASM.
#include <algorithm>
#include <functional>
#include <vector>

#include "bench.h"
#include "math/euler.h"
#include "skeleton/local_to_model.h"
#include "skeleton/synthetic_humanoid.h"

namespace {

// The machine is shared (2 cores, several builds at once): the fastest of several short timings
// estimates the cost of the work itself; a mean would mostly measure the neighbours.
double best_ns_per_call(const std::function<void()>& body) {
  double best = sw::bench::time_ns_per_call(body, 0.05);
  for (int i = 0; i < 9; ++i) best = std::min(best, sw::bench::time_ns_per_call(body, 0.05));
  return best;
}

}  // namespace

SW_BENCH("fk") {
  using namespace sw;
  const skeleton::Skeleton s = skeleton::make_synthetic_humanoid();
  const std::vector<math::Transform> local = skeleton::make_synthetic_pose(s, 1);
  std::vector<glm::mat4> model(local.size());
  skeleton::LocalToModelJob job;
  job.skeleton = &s;
  job.input = local;
  job.output = model;
  const double full_ns = best_ns_per_call([&] { job.run(); });
  job.from = s.find("rightHand");
  const double hand_ns = best_ns_per_call([&] { job.run(); });
  return {{"fk_65_joints_native", full_ns, "ns/update"},
          {"fk_right_hand_subtree_native", hand_ns, "ns/update"}};
}

SW_BENCH("euler") {
  using namespace sw;
  glm::vec3 angles(0.3f, -0.7f, 1.1f);
  glm::vec3 sink(0.0f);
  const double ns = best_ns_per_call([&] {
    const glm::quat q = math::quat_from_euler(angles, math::EulerOrder::ZXY);
    sink += math::euler_from_quat(q, math::EulerOrder::ZXY);
    angles.x += 1e-6f;
  });
  // Keep `sink` observable so the loop is not optimised away.
  return {{"euler_round_trip_native", ns + (sink.x == 12345.0f ? 1.0 : 0.0), "ns/conversion"}};
}

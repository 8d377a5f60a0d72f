// Forward kinematics on the synthetic 65-joint humanoid (skeleton/synthetic_humanoid.h): the cost
// of one full pose update, and of a partial update of the right hand's sub-tree (what the page pays
// after hand IK). Same workload as bench/fk_bench.mjs runs in WASM.
#include <vector>

#include "bench.h"
#include "math/euler.h"
#include "skeleton/local_to_model.h"
#include "skeleton/synthetic_humanoid.h"

SW_BENCH("fk") {
  using namespace sw;
  const skeleton::Skeleton s = skeleton::make_synthetic_humanoid();
  const std::vector<math::Transform> local = skeleton::make_synthetic_pose(s, 1);
  std::vector<glm::mat4> model(local.size());
  skeleton::LocalToModelJob job;
  job.skeleton = &s;
  job.input = local;
  job.output = model;
  const double full_ns = bench::time_ns_per_call([&] { job.run(); });
  job.from = s.find("rightHand");
  const double hand_ns = bench::time_ns_per_call([&] { job.run(); });
  return {{"fk_65_joints_native", full_ns, "ns/update"},
          {"fk_right_hand_subtree_native", hand_ns, "ns/update"}};
}

SW_BENCH("euler") {
  using namespace sw;
  glm::vec3 angles(0.3f, -0.7f, 1.1f);
  glm::vec3 sink(0.0f);
  const double ns = bench::time_ns_per_call([&] {
    const glm::quat q = math::quat_from_euler(angles, math::EulerOrder::ZXY);
    sink += math::euler_from_quat(q, math::EulerOrder::ZXY);
    angles.x += 1e-6f;
  });
  // Keep `sink` observable so the loop is not optimised away.
  return {{"euler_round_trip_native", ns + (sink.x == 12345.0f ? 1.0 : 0.0), "ns/conversion"}};
}

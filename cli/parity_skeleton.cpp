// Parity cases for src/skeleton: forward kinematics of the synthetic 65-joint humanoid, full and
// partial (the right hand's sub-tree), as the WASM API's SyntheticHumanoidFk computes them.
#include <cstdint>

#include "parity.h"
#include "skeleton/local_to_model.h"
#include "skeleton/synthetic_humanoid.h"

namespace sw::cli {
namespace {

nlohmann::json matrices_json(const std::vector<glm::mat4>& matrices) {
  nlohmann::json out = nlohmann::json::array();
  for (const glm::mat4& m : matrices) {
    nlohmann::json flat = nlohmann::json::array();
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) flat.push_back(m[c][r]);  // column-major, as WebGL expects
    out.push_back(flat);
  }
  return out;
}

nlohmann::json fk_case() {
  const skeleton::Skeleton s = skeleton::make_synthetic_humanoid();
  nlohmann::json poses = nlohmann::json::array();
  std::vector<glm::mat4> model(static_cast<std::size_t>(s.joint_count()));
  skeleton::LocalToModelJob job;
  job.skeleton = &s;
  job.output = model;
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    const auto local = skeleton::make_synthetic_pose(s, seed);
    job.input = local;
    job.from = -1;
    job.run();
    poses.push_back({{"seed", seed}, {"model", matrices_json(model)}});
  }
  // Partial: a full pose from seed 1, then only the right hand's sub-tree from seed 2's local pose.
  const auto first = skeleton::make_synthetic_pose(s, 1), second = skeleton::make_synthetic_pose(s, 2);
  job.input = first;
  job.from = -1;
  job.run();
  job.input = second;
  job.from = s.find("rightHand");
  job.run();
  return {{"joint_count", s.joint_count()},
          {"full", poses},
          {"partial", {{"base_seed", 1}, {"subtree_seed", 2}, {"from", "rightHand"}, {"model", matrices_json(model)}}}};
}

}  // namespace

SW_PARITY_CASE("fk", "synthetic 65-joint humanoid: FK for seeds 1-3, and a partial right-hand update", fk_case);

}  // namespace sw::cli

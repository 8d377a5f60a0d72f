// Parity cases for src/avatar and src/skinning: the synthetic avatar (avatar/synthetic_avatar.h)
// loaded, its anchors computed, posed with foundation's deterministic poses, morphed and skinned —
// as the WASM API's avatarLoadSynthetic / avatarSetSyntheticPose / avatarUpdate compute them.
#include <cstdint>
#include <vector>

#include "avatar/body_anchors.h"
#include "avatar/gltf_loader.h"
#include "avatar/synthetic_avatar.h"
#include "parity.h"
#include "skeleton/synthetic_humanoid.h"
#include "skinning/avatar_instance.h"

namespace sw::cli {
namespace {

constexpr int kVertexStride = 17;  // every 17th vertex: the whole mesh would be 20k numbers a pose

nlohmann::json sampled(const std::vector<float>& xyz, int stride) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t v = 0; 3 * v + 2 < xyz.size(); v += static_cast<std::size_t>(stride))
    out.push_back({xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]});
  return out;
}

nlohmann::json avatar_skinning_case() {
  const std::vector<std::uint8_t> glb = avatar::make_synthetic_avatar_glb();
  avatar::LoadResult loaded = avatar::load_avatar(glb.data(), glb.size());
  if (!loaded.ok()) return {{"error", loaded.message()}};
  avatar::Avatar& a = loaded.avatar;
  a.anchors = avatar::compute_body_anchors(a);
  skinning::AvatarInstance instance(a);
  const float max_angle_rad = 0.5f;
  const std::vector<float> morph_weights = {0.8f, 0.3f};
  nlohmann::json joint_names = nlohmann::json::array(), morph_names = nlohmann::json::array();
  for (const auto& j : a.skeleton.joints) joint_names.push_back(j.name);
  for (const auto& m : a.morphs) morph_names.push_back(m.name);
  nlohmann::json poses = nlohmann::json::array();
  for (std::uint32_t seed : {1u, 2u}) {
    const auto pose = skeleton::make_synthetic_pose(a.skeleton, seed, max_angle_rad);
    std::copy(pose.begin(), pose.end(), instance.locals().begin());
    for (std::size_t k = 0; k < morph_weights.size() && k < instance.morph_weights().size(); ++k)
      instance.morph_weights()[k] = morph_weights[k];
    instance.update();
    nlohmann::json joints = nlohmann::json::array();
    for (const glm::mat4& m : instance.model_matrices()) joints.push_back(m[3][0]), joints.push_back(m[3][1]), joints.push_back(m[3][2]);
    poses.push_back({{"seed", seed},
                     {"positions", sampled(instance.positions(), kVertexStride)},
                     {"normals", sampled(instance.normals(), kVertexStride)},
                     {"anchors", sampled(instance.anchor_positions(), 1)},
                     {"joint_translations", joints}});
  }
  return {{"inputs", {{"max_angle_rad", max_angle_rad}, {"morph_weights", morph_weights}, {"vertex_stride", kVertexStride}}},
          {"vertex_count", a.mesh.positions.size()},
          {"triangle_count", a.mesh.indices.size() / 3},
          {"joint_names", joint_names},
          {"morph_names", morph_names},
          {"anchor_count", a.anchors.size()},
          {"poses", poses}};
}

}  // namespace

SW_PARITY_CASE("avatar_skinning",
               "synthetic avatar: load, anchors, synthetic poses 1-2 (0.5 rad), morphs 0.8/0.3, LBS; sampled vertices",
               avatar_skinning_case);

}  // namespace sw::cli

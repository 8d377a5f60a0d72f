// Skinning cost natively: linear blend skinning of positions + normals with 4 influences, in ns
// per vertex, scalar and SIMD, on the real avatar (models/signweave-avatar.glb) — or, when the
// model has not been generated, on the synthetic avatar, and the result names say "synthetic".
// Plus one whole frame (FK, palette, morphs, LBS, anchors). bench/skinning_bench.mjs is the WASM twin.
#include <fstream>
#include <string>

#include "avatar/body_anchors.h"
#include "avatar/gltf_loader.h"
#include "avatar/synthetic_avatar.h"
#include "bench.h"
#include "skeleton/synthetic_humanoid.h"
#include "skinning/avatar_instance.h"

SW_BENCH("skinning") {
  using namespace sw;
  const std::string path = std::string(SIGNWEAVE_SOURCE_DIR) + "/models/signweave-avatar.glb";
  avatar::LoadResult loaded;
  std::string label = "avatar";
  if (std::ifstream(path).good()) loaded = avatar::load_avatar_file(path);
  if (!loaded.ok() || loaded.avatar.mesh.positions.empty()) {
    const std::vector<std::uint8_t> glb = avatar::make_synthetic_avatar_glb();
    loaded = avatar::load_avatar(glb.data(), glb.size());
    label = "synthetic";
  }
  if (!loaded.ok()) return {};
  avatar::Avatar& a = loaded.avatar;
  a.anchors = avatar::compute_body_anchors(a);
  skinning::AvatarInstance instance(a);
  const auto pose = skeleton::make_synthetic_pose(a.skeleton, 3, 0.5f);
  std::copy(pose.begin(), pose.end(), instance.locals().begin());
  instance.update();

  const std::size_t n = a.mesh.positions.size();
  std::vector<float> out_p(3 * n), out_n(3 * n);
  skinning::SkinningJob job;
  job.vertex_count = static_cast<int>(n);
  job.skinning_matrices = instance.skinning_matrices().data();
  job.joint_count = static_cast<int>(instance.skinning_matrices().size());
  job.in_positions = a.mesh.positions.data();
  job.in_normals = a.mesh.normals.data();
  job.joints = a.mesh.joints.data();
  job.weights = a.mesh.weights.data();
  job.out_positions = out_p.data();
  job.out_normals = out_n.data();
  job.path = skinning::SkinningPath::Scalar;
  const double scalar_ns = bench::time_ns_per_call([&] { job.run(); }) / double(n);
  job.path = skinning::SkinningPath::Simd;
  const double simd_ns = bench::time_ns_per_call([&] { job.run(); }) / double(n);
  const double frame_us = bench::time_ns_per_call([&] { instance.update(skinning::SkinningPath::Simd); }) / 1000.0;
  return {{"skinning_lbs_native_scalar_" + label, scalar_ns, "ns/vertex"},
          {"skinning_lbs_native_simd_" + label, simd_ns, "ns/vertex"},
          {"skinning_frame_native_simd_" + label + "_" + std::to_string(n) + "_vertices", frame_us, "us/frame"}};
}

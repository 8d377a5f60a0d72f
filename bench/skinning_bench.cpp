// Skinning cost natively: linear blend skinning of positions + normals with 4 influences, in ns
// per vertex, scalar and SIMD, on the real avatar (models/signweave-avatar.glb) — or, when the
// model has not been generated, on the synthetic avatar, and the result names say "synthetic".
// Plus one whole frame (FK, palette, morphs, LBS, anchors). bench/skinning_bench.mjs is the WASM twin.
#include <ctime>
#include <fstream>
#include <functional>
#include <string>

#include "avatar/body_anchors.h"
#include "avatar/gltf_loader.h"
#include "avatar/synthetic_avatar.h"
#include "bench.h"
#include "skeleton/synthetic_humanoid.h"
#include "skinning/avatar_instance.h"

namespace {

// CPU time of this thread per call: the machines running the benches are shared (load averages
// above 10 on 2 cores were seen), and wall-clock time then measures the other processes too.
double thread_cpu_ns_per_call(const std::function<void()>& body, double min_seconds = 0.3) {
  const auto now = [] {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e9 + double(t.tv_nsec);
  };
  for (int i = 0; i < 5; ++i) body();
  long iterations = 0;
  const double start = now();
  double elapsed = 0.0;
  while (elapsed < min_seconds * 1e9) {
    body();
    ++iterations;
    elapsed = now() - start;
  }
  return elapsed / double(iterations);
}

}  // namespace

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
  // The worst case: every vertex blends 4 matrices, whatever the model's weights.
  const std::vector<glm::vec4> four(n, glm::vec4(0.4f, 0.3f, 0.2f, 0.1f));
  job.weights = four.data();
  const double simd_four_ns = bench::time_ns_per_call([&] { job.run(); }) / double(n);
  job.path = skinning::SkinningPath::Scalar;
  const double scalar_four_ns = bench::time_ns_per_call([&] { job.run(); }) / double(n);
  job.path = skinning::SkinningPath::Simd;
  job.weights = a.mesh.weights.data();
  const double simd_cpu_ns = thread_cpu_ns_per_call([&] { job.run(); }) / double(n);
  job.weights = four.data();
  const double simd_four_cpu_ns = thread_cpu_ns_per_call([&] { job.run(); }) / double(n);
  const double frame_us = bench::time_ns_per_call([&] { instance.update(skinning::SkinningPath::Simd); }) / 1000.0;
  return {{"skinning_lbs_native_scalar_" + label, scalar_ns, "ns/vertex"},
          {"skinning_lbs_native_simd_" + label, simd_ns, "ns/vertex"},
          {"skinning_lbs_native_scalar_" + label + "_all_4_influences", scalar_four_ns, "ns/vertex"},
          {"skinning_lbs_native_simd_" + label + "_all_4_influences", simd_four_ns, "ns/vertex"},
          {"skinning_lbs_native_simd_" + label + "_thread_cpu_time", simd_cpu_ns, "ns/vertex"},
          {"skinning_lbs_native_simd_" + label + "_all_4_influences_thread_cpu_time", simd_four_cpu_ns, "ns/vertex"},
          {"skinning_frame_native_simd_" + label + "_" + std::to_string(n) + "_vertices", frame_us, "us/frame"}};
}

// The skinning inputs of bench/skinning_bench.cpp (the project's avatar, the same synthetic pose),
// written to build/bench/skinning-inputs.bin so that bench/skinning_ozz_bench.mjs can time our
// SkinningJob and ozz-animation's on exactly the same vertices, joints, weights and skinning
// matrices, natively and in WebAssembly. Layout (little-endian, no padding):
//   "SWSKIN01", int32 vertex_count, int32 joint_count,
//   positions (3 float each), normals (3 float), joints (4 uint16), weights (4 float),
//   skinning matrices (16 float each, column-major as glm::mat4).
// Prints the vertex and joint counts; nothing is written when the avatar is absent.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "avatar/body_anchors.h"
#include "avatar/gltf_loader.h"
#include "bench.h"
#include "skeleton/synthetic_humanoid.h"
#include "skinning/avatar_instance.h"

namespace {

template <typename T>
void write_array(std::ofstream& out, const T* data, std::size_t count) {
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(count * sizeof(T)));
}

}  // namespace

SW_BENCH("skinning_inputs") {
  using namespace sw;
  const std::string model = std::string(SIGNWEAVE_SOURCE_DIR) + "/models/signweave-avatar.glb";
  avatar::LoadResult loaded = avatar::load_avatar_file(model);
  if (!loaded.ok() || loaded.avatar.mesh.positions.empty()) {
    std::fprintf(stderr, "skinning_inputs: skipped, %s did not load\n", model.c_str());
    return {};
  }
  avatar::Avatar& a = loaded.avatar;
  a.anchors = avatar::compute_body_anchors(a);
  skinning::AvatarInstance instance(a);
  const auto pose = skeleton::make_synthetic_pose(a.skeleton, 3, 0.5f);
  std::copy(pose.begin(), pose.end(), instance.locals().begin());
  instance.update();
  const avatar::SkinnedMesh& m = a.mesh;
  const std::int32_t vertices = static_cast<std::int32_t>(m.positions.size());
  const std::int32_t joints = static_cast<std::int32_t>(instance.skinning_matrices().size());
  const std::string path = std::string(SIGNWEAVE_SOURCE_DIR) + "/build/bench/skinning-inputs.bin";
  std::error_code ignored;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ignored);
  std::ofstream out(path, std::ios::binary);
  if (!out) {
    std::fprintf(stderr, "skinning_inputs: cannot write %s\n", path.c_str());
    return {};
  }
  out.write("SWSKIN01", 8);
  write_array(out, &vertices, 1);
  write_array(out, &joints, 1);
  write_array(out, m.positions.data(), m.positions.size());
  write_array(out, m.normals.data(), m.normals.size());
  write_array(out, m.joints.data(), m.joints.size());
  write_array(out, m.weights.data(), m.weights.size());
  write_array(out, instance.skinning_matrices().data(), instance.skinning_matrices().size());
  return {{"skinning_inputs_avatar_vertices", double(vertices), "vertices"},
          {"skinning_inputs_avatar_joints", double(joints), "joints"}};
}

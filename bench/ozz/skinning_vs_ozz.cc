// Our SkinningJob against ozz-animation's ozz::geometry::SkinningJob on the same data, in one
// process, timed the same way (issue 27). Built by bench/skinning_ozz_bench.mjs into build/ozz/
// (natively, and with em++ for WebAssembly SIMD) from ../shared/peers/ozz-animation and
// src/skinning/skinning_job.cpp; never part of the project's build (the .cc extension keeps it out
// of CMake's bench/*.cpp glob), and no ozz code is committed.
//
// Input: build/bench/skinning-inputs.bin (bench/skinning_inputs_bench.cpp: the avatar's vertices,
// joints, weights and the skinning matrices of a synthetic pose). Both jobs skin positions and
// normals from the same arrays (ozz reads our interleaved arrays through its strides: joints
// 4 x uint16, weights the first 3 of 4 floats, the 4th derived as ozz does).
// Workloads:
//   all_4_influences  every vertex blends 4 matrices (weights 0.4/0.3/0.2/0.1): the same arithmetic
//                     for both, the figure the issue asks for;
//   avatar_weights    the avatar's own weights. Ours skips the zero weights per vertex; ozz is run
//                     as its own samples run it, the mesh split into parts by influence count
//                     (one job per part, influences_count 1..4), which is ozz at its best.
// Timing: process CPU time (cpu_seconds()) of whole passes, best of 7 rounds of 0.3 s after 20
// warm-up passes, the method of ozz's own driver; the engines alternate round by round so that the
// machine's load falls on both alike. Prints JSON lines {"name","value","unit"}; argv[1] the input
// file, argv[2] a label ("native", "wasm_simd").
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#if defined(__EMSCRIPTEN__)
#include <emscripten.h>
#endif

#include "ozz/base/maths/simd_math.h"
#include "ozz/base/span.h"
#include "ozz/geometry/runtime/skinning_job.h"
#include "skinning/skinning_job.h"

namespace {

struct Inputs {
  int vertices = 0, joints = 0;
  std::vector<glm::vec3> positions, normals;
  std::vector<std::array<std::uint16_t, 4>> joint_indices;
  std::vector<glm::vec4> weights;
  std::vector<glm::mat4> matrices;
};

template <typename T>
bool read_array(std::FILE* f, std::vector<T>* v, int count) {
  v->resize(static_cast<std::size_t>(count));
  return std::fread(v->data(), sizeof(T), v->size(), f) == v->size();
}

bool read_inputs(const char* path, Inputs* in) {
  std::FILE* f = std::fopen(path, "rb");
  if (!f) return false;
  char magic[8] = {};
  bool ok = std::fread(magic, 1, 8, f) == 8 && std::memcmp(magic, "SWSKIN01", 8) == 0 &&
            std::fread(&in->vertices, 4, 1, f) == 1 && std::fread(&in->joints, 4, 1, f) == 1;
  ok = ok && read_array(f, &in->positions, in->vertices) &&
       read_array(f, &in->normals, in->vertices) &&
       read_array(f, &in->joint_indices, in->vertices) &&
       read_array(f, &in->weights, in->vertices) && read_array(f, &in->matrices, in->joints);
  std::fclose(f);
  return ok;
}

// One ozz job over vertices [first, first + count) of arrays laid out like ours.
ozz::geometry::SkinningJob ozz_job(const Inputs& in, const std::vector<glm::vec4>& weights,
                                   const std::vector<ozz::math::Float4x4>& matrices, int first,
                                   int count, int influences, std::vector<float>* out_p,
                                   std::vector<float>* out_n) {
  ozz::geometry::SkinningJob job;
  job.vertex_count = count;
  job.influences_count = influences;
  job.joint_matrices = ozz::make_span(matrices);
  const auto* joints = reinterpret_cast<const std::uint16_t*>(in.joint_indices.data() + first);
  job.joint_indices = {joints, joints + 4 * std::size_t(count)};
  job.joint_indices_stride = sizeof(in.joint_indices[0]);
  const float* w = &weights[std::size_t(first)].x;
  job.joint_weights = {w, w + 4 * std::size_t(count)};
  job.joint_weights_stride = sizeof(glm::vec4);
  const float* p = &in.positions[std::size_t(first)].x;
  job.in_positions = {p, p + 3 * std::size_t(count)};
  job.in_positions_stride = sizeof(glm::vec3);
  const float* n = &in.normals[std::size_t(first)].x;
  job.in_normals = {n, n + 3 * std::size_t(count)};
  job.in_normals_stride = sizeof(glm::vec3);
  float* op = out_p->data() + 3 * std::size_t(first);
  float* on = out_n->data() + 3 * std::size_t(first);
  job.out_positions = {op, op + 3 * std::size_t(count)};
  job.out_positions_stride = 3 * sizeof(float);
  job.out_normals = {on, on + 3 * std::size_t(count)};
  job.out_normals_stride = 3 * sizeof(float);
  return job;
}

int influence_count(const glm::vec4& w) {
  return w.w > 0.f ? 4 : w.z > 0.f ? 3 : w.y > 0.f ? 2 : 1;
}

// The mesh reordered by influence count (ozz's parts), with the part boundaries.
Inputs partition_by_influences(const Inputs& in, std::array<int, 5>* part_start) {
  Inputs out = in;
  out.positions.clear();
  out.normals.clear();
  out.joint_indices.clear();
  out.weights.clear();
  for (int k = 1; k <= 4; ++k) {
    (*part_start)[std::size_t(k - 1)] = static_cast<int>(out.positions.size());
    for (int v = 0; v < in.vertices; ++v) {
      if (influence_count(in.weights[std::size_t(v)]) != k) continue;
      out.positions.push_back(in.positions[std::size_t(v)]);
      out.normals.push_back(in.normals[std::size_t(v)]);
      out.joint_indices.push_back(in.joint_indices[std::size_t(v)]);
      out.weights.push_back(in.weights[std::size_t(v)]);
    }
  }
  (*part_start)[4] = in.vertices;
  return out;
}

// Process CPU seconds: clock() natively; in WebAssembly node's process.cpuUsage(), since
// Emscripten's clock() is wall time, which on a shared machine also counts the other processes.
double cpu_seconds() {
#if defined(__EMSCRIPTEN__)
  return EM_ASM_DOUBLE({
    const u = process.cpuUsage();
    return (u.user + u.system) / 1e6;
  });
#else
  return double(std::clock()) / CLOCKS_PER_SEC;
#endif
}

// Best ns per vertex of each body over 7 alternating rounds of 0.3 s.
std::vector<double> best_ns_per_vertex(const std::vector<std::function<void()>>& bodies,
                                       int vertices) {
  std::vector<double> best(bodies.size(), 1e30);
  for (const auto& body : bodies) {
    for (int i = 0; i < 20; ++i) body();
  }
  for (int round = 0; round < 7; ++round) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const double start = cpu_seconds();
      long passes = 0;
      while (cpu_seconds() - start < 0.3) {
        bodies[b]();
        ++passes;
      }
      const double ns = (cpu_seconds() - start) * 1e9 / double(passes) / vertices;
      if (ns < best[b]) best[b] = ns;
    }
  }
  return best;
}

double max_difference(const std::vector<float>& a, const std::vector<float>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, double(std::abs(a[i] - b[i])));
  return d;
}

void print(const std::string& name, double value, const char* unit) {
  std::printf("{\"name\": \"%s\", \"value\": %.6g, \"unit\": \"%s\"}\n", name.c_str(), value, unit);
}

}  // namespace

int main(int argc, char** argv) {
  Inputs in;
  if (argc < 3 || !read_inputs(argv[1], &in)) {
    std::fprintf(
        stderr,
        "usage: skinning_vs_ozz INPUTS.bin LABEL (inputs from signweave-bench skinning_inputs)\n");
    return 2;
  }
  const std::string label = argv[2];
  const std::size_t n3 = 3 * std::size_t(in.vertices);
  std::vector<ozz::math::Float4x4> ozz_matrices(std::size_t(in.joints));
  for (int j = 0; j < in.joints; ++j) {
    const float* m = &in.matrices[std::size_t(j)][0][0];
    for (int c = 0; c < 4; ++c)
      ozz_matrices[std::size_t(j)].cols[c] = ozz::math::simd_float4::LoadPtrU(m + 4 * c);
  }
  const std::vector<glm::vec4> four(std::size_t(in.vertices), glm::vec4(0.4f, 0.3f, 0.2f, 0.1f));
  std::vector<float> ours_p(n3), ours_n(n3), ozz_p(n3), ozz_n(n3);

  sw::skinning::SkinningJob ours;
  ours.vertex_count = in.vertices;
  ours.skinning_matrices = in.matrices.data();
  ours.joint_count = in.joints;
  ours.in_positions = in.positions.data();
  ours.in_normals = in.normals.data();
  ours.joints = in.joint_indices.data();
  ours.out_positions = ours_p.data();
  ours.out_normals = ours_n.data();
  ours.path = sw::skinning::SkinningPath::Simd;

  // All four influences: one ozz job over the whole mesh, the same arrays as ours.
  ours.weights = four.data();
  const ozz::geometry::SkinningJob ozz_four =
      ozz_job(in, four, ozz_matrices, 0, in.vertices, 4, &ozz_p, &ozz_n);
  if (!ozz_four.Validate() || !ours.validate().empty()) {
    std::fprintf(stderr, "skinning_vs_ozz: invalid job\n");
    return 1;
  }
  if (argc > 3 && std::strcmp(argv[3], "--passes-only") == 0) {
    // For an instruction count (callgrind): 50 passes of each job and workload, no timing.
    std::array<int, 5> part{};
    const Inputs parted = partition_by_influences(in, &part);
    std::vector<ozz::geometry::SkinningJob> ozz_parts;
    for (int k = 1; k <= 4; ++k) {
      const int count = part[std::size_t(k)] - part[std::size_t(k - 1)];
      if (count > 0)
        ozz_parts.push_back(ozz_job(parted, parted.weights, ozz_matrices, part[std::size_t(k - 1)],
                                    count, k, &ozz_p, &ozz_n));
    }
    const bool four_only = argc > 4 && std::strcmp(argv[4], "four") == 0;
    const bool avatar_only = argc > 4 && std::strcmp(argv[4], "avatar") == 0;
    for (int i = 0; i < 50; ++i) {
      if (!avatar_only) {
        ours.weights = four.data();
        ours.run();
        ozz_four.Run();
      }
      if (!four_only) {
        ours.weights = in.weights.data();
        ours.run();
        for (const auto& job : ozz_parts) job.Run();
      }
    }
    return 0;
  }
  const std::vector<double> four_ns =
      best_ns_per_vertex({[&] { ours.run(); }, [&] { ozz_four.Run(); }}, in.vertices);
  const double four_diff = std::max(max_difference(ours_p, ozz_p), max_difference(ours_n, ozz_n));

  // The avatar's weights: ours as it is; ozz over the mesh split by influence count.
  std::array<int, 5> part{};
  const Inputs parted = partition_by_influences(in, &part);
  std::vector<ozz::geometry::SkinningJob> ozz_parts;
  for (int k = 1; k <= 4; ++k) {
    const int count = part[std::size_t(k)] - part[std::size_t(k - 1)];
    if (count > 0)
      ozz_parts.push_back(ozz_job(parted, parted.weights, ozz_matrices, part[std::size_t(k - 1)],
                                  count, k, &ozz_p, &ozz_n));
  }
  ours.weights = in.weights.data();
  const std::vector<double> avatar_ns = best_ns_per_vertex({[&] { ours.run(); },
                                                            [&] {
                                                              for (const auto& job : ozz_parts)
                                                                job.Run();
                                                            }},
                                                           in.vertices);

  const std::string base =
      "skinning_vs_ozz_" + label + "_" + std::to_string(in.vertices) + "_vertices";
  print(base + "_all_4_influences_ours", four_ns[0], "ns/vertex");
  print(base + "_all_4_influences_ozz", four_ns[1], "ns/vertex");
  print(base + "_all_4_influences_ozz_over_ours", four_ns[1] / four_ns[0], "x");
  print(base + "_all_4_influences_max_difference", four_diff, "m");
  print(base + "_avatar_weights_ours", avatar_ns[0], "ns/vertex");
  print(base + "_avatar_weights_ozz_parts_by_influences", avatar_ns[1], "ns/vertex");
  print(base + "_avatar_weights_ozz_over_ours", avatar_ns[1] / avatar_ns[0], "x");
  for (int k = 1; k <= 4; ++k) {
    print(base + "_avatar_vertices_with_" + std::to_string(k) + "_influences",
          part[std::size_t(k)] - part[std::size_t(k - 1)], "vertices");
  }
  return 0;
}

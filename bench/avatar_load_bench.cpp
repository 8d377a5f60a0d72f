// Avatar start-up cost natively: what the page pays between the avatar's bytes arriving and the
// first frame — glTF load (container, JSON, accessors, merge), body anchors (ray casts), and the
// skinning instance — on models/signweave-avatar.glb (or the synthetic avatar, named so).
// Each part is the median of several cold runs, in milliseconds; bench/avatar_load_bench.mjs is
// the WASM twin (the page's real cost).
#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "avatar/body_anchors.h"
#include "avatar/gltf_loader.h"
#include "avatar/synthetic_avatar.h"
#include "bench.h"
#include "skinning/avatar_instance.h"

namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> xs) {
  std::sort(xs.begin(), xs.end());
  return xs[xs.size() / 2];
}

}  // namespace

SW_BENCH("avatar_load") {
  using namespace sw;
  const std::string path = std::string(SIGNWEAVE_SOURCE_DIR) + "/models/signweave-avatar.glb";
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string label = "avatar";
  if (bytes.empty()) {
    bytes = avatar::make_synthetic_avatar_glb();
    label = "synthetic";
  }
  constexpr int kRuns = 7;  // odd: the median is one run's figure
  std::vector<double> load, anchors, instance, total;
  for (int run = 0; run < kRuns; ++run) {
    auto start = std::chrono::steady_clock::now();
    avatar::LoadResult r = avatar::load_avatar(bytes.data(), bytes.size());
    if (!r.ok()) return {};
    load.push_back(ms_since(start));
    auto t = std::chrono::steady_clock::now();
    r.avatar.anchors = avatar::compute_body_anchors(r.avatar);
    anchors.push_back(ms_since(t));
    t = std::chrono::steady_clock::now();
    skinning::AvatarInstance inst(r.avatar);
    inst.update();
    instance.push_back(ms_since(t));
    total.push_back(ms_since(start));
  }
  return {{"avatar_load_native_" + label + "_gltf_ms", median(load), "ms"},
          {"avatar_load_native_" + label + "_anchors_ms", median(anchors), "ms"},
          {"avatar_load_native_" + label + "_instance_ms", median(instance), "ms"},
          {"avatar_load_native_" + label + "_total_ms", median(total), "ms"}};
}

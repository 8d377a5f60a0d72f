// Synthesis time on real signs (issue 27): the sample of the dev corpora that bench/real_signs.mjs
// writes to build/bench/real-signs.jsonl (every k-th HamNoSys, H-SiGML and G-SiGML sign, about 120
// a file; `./signweave bench` writes it first). Each sign is compiled as the page's dictionary
// look-up compiles it (synthCompile): its text parsed, then synthesised from rest and back on the
// project's avatar. CPU ms per sign (mean of SIGNWEAVE_BENCH_CALLS calls, default 3, after one
// warm-up call): mean, median, p95 and worst per corpus and overall, and the same per clip frame.
// Per-sign figures also go to build/bench/real-signs-native.jsonl (or $SIGNWEAVE_REAL_SIGNS_OUT),
// for the comparison with the reference engine (bench/synthesis_real_bench.mjs). Skipped with a
// message when the sample is absent (no ../shared/corpus). bench/synthesis_real_bench.mjs is the
// WASM twin.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench.h"
#include "synthesis/phrase_text.h"
#include "synthesis/signing_avatar.h"
#include "synthesis/synthesize.h"

namespace {

struct RealSign {
  std::string corpus, gloss, text;
  int index = 0;
};

struct Timed {
  double ms = 0.0;  // CPU ms per compile
  int frames = 0;
};

std::string build_path(const char* name) {
  return std::string(SIGNWEAVE_SOURCE_DIR) + "/build/bench/" + name;
}

std::vector<RealSign> read_sample() {
  const char* env = std::getenv("SIGNWEAVE_REAL_SIGNS");
  std::ifstream in(env ? std::string(env) : build_path("real-signs.jsonl"));
  std::vector<RealSign> out;
  std::string line;
  while (std::getline(in, line)) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object()) continue;
    out.push_back(
        {j.value("corpus", ""), j.value("gloss", ""), j.value("text", ""), j.value("index", 0)});
  }
  return out;
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * v.size()))];
}

void add_stats(std::vector<sw::bench::Result>* out, const std::string& prefix,
               const std::vector<double>& v, const std::string& unit) {
  double total = 0.0;
  for (double x : v) total += x;
  out->push_back({prefix + "_mean", total / double(v.size()), unit});
  out->push_back({prefix + "_median", quantile(v, 0.5), unit});
  out->push_back({prefix + "_p95", quantile(v, 0.95), unit});
  out->push_back({prefix + "_max", quantile(v, 1.0), unit});
}

}  // namespace

SW_BENCH("synthesis_real") {
  using namespace sw::synthesis;
  const std::vector<RealSign> sample = read_sample();
  if (sample.empty()) {
    std::fprintf(stderr,
                 "synthesis_real: skipped, no sample at %s (run node bench/real_signs.mjs; needs "
                 "../shared/corpus)\n",
                 build_path("real-signs.jsonl").c_str());
    return {};
  }
  SigningAvatar avatar =
      load_signing_avatar_file(std::string(SIGNWEAVE_SOURCE_DIR) + "/models/signweave-avatar.glb");
  if (!avatar.ok()) {
    std::fprintf(stderr, "synthesis_real: skipped, models/signweave-avatar.glb did not load\n");
    return {};
  }
  const char* calls_env = std::getenv("SIGNWEAVE_BENCH_CALLS");
  const int calls = std::max(1, calls_env ? std::atoi(calls_env) : 3);
  Synthesizer synth(avatar.avatar);
  const SynthesisOptions options;
  // What synthCompile does for one sign: parse the text, synthesise the phrase it gives.
  const auto compile = [&](const std::string& text) {
    PhraseText t = phrase_from_text(text, {});
    if (!t.ok()) return -1;
    SynthesisResult r = synth.phrase(t.items, options);
    return r.ok() ? r.clip.frame_count : -1;
  };
  std::map<std::string, std::vector<Timed>> by_corpus;
  std::map<std::string, int> failed;
  const char* out_env = std::getenv("SIGNWEAVE_REAL_SIGNS_OUT");  // e.g. /dev/null under a profiler
  std::ofstream per_sign(out_env ? std::string(out_env) : build_path("real-signs-native.jsonl"));
  for (const RealSign& s : sample) {
    const int frames = compile(s.text);  // warm-up, and the sign's frame count
    if (frames <= 0) {
      ++failed[s.corpus];
      continue;
    }
    const std::clock_t start = std::clock();
    for (int i = 0; i < calls; ++i) compile(s.text);
    const double ms = 1000.0 * double(std::clock() - start) / CLOCKS_PER_SEC / calls;
    by_corpus[s.corpus].push_back({ms, frames});
    by_corpus["all"].push_back({ms, frames});
    per_sign << nlohmann::json{{"corpus", s.corpus},
                               {"index", s.index},
                               {"gloss", s.gloss},
                               {"ms", ms},
                               {"frames", frames}}
                    .dump()
             << "\n";
  }
  int all_failed = 0;
  for (const auto& [corpus, n] : failed) all_failed += n;
  std::vector<sw::bench::Result> out;
  for (const auto& [corpus, timed] : by_corpus) {
    std::vector<double> ms, us_per_frame;
    for (const Timed& t : timed) {
      ms.push_back(t.ms);
      us_per_frame.push_back(1000.0 * t.ms / t.frames);
    }
    const std::string name = "synthesis_real_" + corpus;
    out.push_back({name + "_signs", double(timed.size()), "signs"});
    out.push_back(
        {name + "_failed", double(corpus == "all" ? all_failed : failed[corpus]), "signs"});
    add_stats(&out, name + "_per_sign_native_cpu", ms, "ms/sign");
    add_stats(&out, name + "_per_frame_native_cpu", us_per_frame, "us/frame");
  }
  return out;
}

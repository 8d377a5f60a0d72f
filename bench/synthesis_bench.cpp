// Synthesis time: one sign (a fingerspelled letter: key pose, hold, transitions from and to rest)
// and a 20-sign phrase, on the project's avatar when models/signweave-avatar.glb is present, else
// on the procedural reference humanoid; and every sign of the ASL starter lexicon one at a time,
// as a dictionary look-up pays it (real signs: two hands, contacts on the other hand, the
// placement searches the twenty synthetic signs rarely reach). Same workloads as
// bench/synthesis_bench.mjs in WASM.
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench.h"
#include "synthesis/phrase_text.h"
#include "synthesis/reference_humanoid.h"
#include "synthesis/signing_avatar.h"
#include "synthesis/synthesize.h"

namespace {

// Twenty signs of the formula notation: handshapes, orientations, locations, movements.
const char* kSigns[] = {
    "R(H(fist), F_9^1, E(u), P(o), Loc(shoulders, right, none))",
    "R(H(flat, thumbacross), E(u), P(o), Loc(shoulders, right, none))",
    "R(H(ceeall), E(u), P(l), Loc(shoulders, right, none))",
    "R(H(finger2), E(u), P(o), Loc(chin, centre, touch))",
    "R(H(flat), E(u), P(i), Loc(forehead, right, close), M(straight o))",
    "R(H(pinch12), E(u), P(l), Loc(chest, right, none), M(circle axis=o cw small))",
    "R(H(finger23spread), E(u), P(o), Loc(shoulders, right, none))",
    "R(H(flat), E(l), P(d), Loc(neutral, centre, none), M(wavy r))",
    "R(H(fist), E(l), P(i), Loc(chest, left, touch))",
    "R(H(finger2), E(o), P(d), Loc(neutral, right, none), M(arc r bulge=u))",
    "R(H(flat), E(u), P(o), Loc(shoulders, right, none), M(nod))",
    "R(H(flat), E(u), P(l), Loc(chest, right, none), M(replace H(fist)))",
    "R(H(finger2345), E(u), P(o), Loc(neutral, centre, none), M(fingerplay))",
    "R(H(fist), E(u), P(o), Loc(cheeks, right, touch))",
    "R(H(flat), E(o), P(u), Loc(neutral, centre, none), M(straight u)) Sym(lr)",
    "R(H(finger2), E(u), P(o), Loc(mouth, centre, close), M(zigzag d))",
    "R(H(ceeall), E(o), P(l), Loc(neutral, right, none), M(spiral axis=o ccw))",
    "R(H(flat), E(u), P(o), Loc(shoulders, right, none), M(twist))",
    "R(H(pinchall), E(u), P(o), Loc(chin, centre, close), M(straight o fast))",
    "R(H(flat), E(u), P(o), Loc(eyebrows, right, close), M(ellipse axis=o cw))",
};

sw::avatar::Avatar bench_avatar(std::string* which) {
  sw::synthesis::SigningAvatar a =
      sw::synthesis::load_signing_avatar_file(std::string(SIGNWEAVE_SOURCE_DIR) + "/models/signweave-avatar.glb");
  if (a.ok()) {
    *which = "avatar";
    return std::move(a.avatar);
  }
  *which = "reference";
  return sw::synthesis::make_reference_humanoid();
}

// Process CPU time per call (ms): on a shared machine the wall-clock figure of bench.h also counts
// the time other processes hold the cores; both are reported.
double cpu_ms_per_call(const std::function<void()>& body, int calls) {
  std::clock_t start = std::clock();
  for (int i = 0; i < calls; ++i) body();
  return 1000.0 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC / calls;
}

}  // namespace

SW_BENCH("synthesis") {
  using namespace sw::synthesis;
  std::string which;
  const sw::avatar::Avatar avatar = bench_avatar(&which);
  std::vector<PhraseItem> items;
  for (const char* s : kSigns) {
    PhraseText t = phrase_from_text(s, {});
    if (t.ok()) items.insert(items.end(), t.items.begin(), t.items.end());
  }
  if (items.size() != 20) return {{"synthesis_parse_failed_signs", double(20 - items.size()), "signs"}};
  // The avatar is measured once (rig, capsules from the mesh, rest pose), as the page and the
  // server do; that one-off cost is reported separately.
  const double setup_ns = sw::bench::time_ns_per_call([&] { Synthesizer s(avatar); }, 0.5);
  Synthesizer synth(avatar);
  const SynthesisOptions options;
  // One sign from rest and back: the unit a dictionary look-up pays.
  size_t next = 0;
  const double sign_ns = sw::bench::time_ns_per_call([&] {
    SynthesisResult r = synth.phrase({items[next++ % items.size()]}, options);
    if (!r.ok()) next = 0;
  });
  const double phrase_ns = sw::bench::time_ns_per_call([&] { synth.phrase(items, options); }, 1.0);
  next = 0;
  const double sign_cpu_ms = cpu_ms_per_call([&] { synth.phrase({items[next++ % items.size()]}, options); }, 100);
  const double phrase_cpu_ms = cpu_ms_per_call([&] { synth.phrase(items, options); }, 5);
  return {{"synthesis_avatar_setup_native_" + which, setup_ns / 1e6, "ms"},
          {"synthesis_per_sign_native_" + which, sign_ns / 1e6, "ms/sign"},
          {"synthesis_20_sign_phrase_native_" + which, phrase_ns / 1e6, "ms/phrase"},
          {"synthesis_20_sign_phrase_per_sign_native_" + which, phrase_ns / 20e6, "ms/sign"},
          {"synthesis_per_sign_native_cpu_" + which, sign_cpu_ms, "ms/sign"},
          {"synthesis_20_sign_phrase_native_cpu_" + which, phrase_cpu_ms, "ms/phrase"}};
}

// Every lexicon sign from rest and back, one at a time: the mean, median, 90th percentile and
// slowest CPU time per sign (each sign timed over 5 calls, the same Synthesizer as the page's).
SW_BENCH("synthesis_lexicon") {
  using namespace sw::synthesis;
  std::string which;
  const sw::avatar::Avatar avatar = bench_avatar(&which);
  std::ifstream in(std::string(SIGNWEAVE_SOURCE_DIR) + "/data/ase/lexicon.jsonl");
  std::vector<std::vector<PhraseItem>> signs;
  std::vector<std::string> glosses;
  std::string line;
  while (std::getline(in, line)) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object() || !j.contains("notation")) continue;
    PhraseText t = phrase_from_text(j.value("notation", ""), {});
    if (!t.ok()) continue;
    signs.push_back(t.items);
    glosses.push_back(j.value("gloss", ""));
  }
  if (signs.empty()) return {{"synthesis_lexicon_signs", 0.0, "signs"}};
  Synthesizer synth(avatar);
  const SynthesisOptions options;
  std::vector<double> ms;
  std::vector<std::pair<double, std::string>> slowest;
  for (size_t i = 0; i < signs.size(); ++i) {
    ms.push_back(cpu_ms_per_call([&] { synth.phrase(signs[i], options); }, 5));
    slowest.push_back({ms.back(), glosses[i]});
  }
  double total = 0.0;
  for (double m : ms) total += m;
  std::sort(ms.begin(), ms.end());
  // The slowest signs on stderr (stdout stays JSON lines): where a search is worth a look.
  std::sort(slowest.rbegin(), slowest.rend());
  for (size_t i = 0; i < std::min<size_t>(5, slowest.size()); ++i)
    std::fprintf(stderr, "synthesis_lexicon: %s %.2f ms\n", slowest[i].second.c_str(), slowest[i].first);
  const auto at = [&](double q) { return ms[std::min(ms.size() - 1, static_cast<size_t>(q * ms.size()))]; };
  return {{"synthesis_lexicon_signs_" + which, double(ms.size()), "signs"},
          {"synthesis_lexicon_per_sign_mean_native_cpu_" + which, total / ms.size(), "ms/sign"},
          {"synthesis_lexicon_per_sign_median_native_cpu_" + which, at(0.5), "ms/sign"},
          {"synthesis_lexicon_per_sign_p90_native_cpu_" + which, at(0.9), "ms/sign"},
          {"synthesis_lexicon_per_sign_max_native_cpu_" + which, ms.back(), "ms/sign"}};
}

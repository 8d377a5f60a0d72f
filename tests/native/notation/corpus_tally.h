// Test support for the corpus tests (HamNoSys and SiGML): how many signs parsed, parsed clean and
// round-tripped, with the commonest diagnostic messages, printed in one format for every notation.
#pragma once

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace sw::notation {

struct CorpusTally {
  int signs = 0, parsed = 0, clean = 0, round_trips = 0;
  std::map<std::string, int> reasons;  // diagnostic message -> how many signs had it
};

// Prints the tally and its `top` commonest reasons.
inline void report_corpus_tally(const char* what, const CorpusTally& t, std::size_t top) {
  std::printf("[corpus] %s: %d signs, %d parsed (%.2f%%), %d clean (%.2f%%), %d round trips (%.2f%% of clean)\n",
              what, t.signs, t.parsed, 100.0 * t.parsed / std::max(1, t.signs), t.clean,
              100.0 * t.clean / std::max(1, t.signs), t.round_trips, 100.0 * t.round_trips / std::max(1, t.clean));
  std::vector<std::pair<int, std::string>> ranked;
  for (const auto& [message, n] : t.reasons) ranked.emplace_back(n, message);
  std::sort(ranked.rbegin(), ranked.rend());
  for (std::size_t i = 0; i < ranked.size() && i < top; ++i)
    std::printf("    %5d  %s\n", ranked[i].first, ranked[i].second.c_str());
}

}  // namespace sw::notation

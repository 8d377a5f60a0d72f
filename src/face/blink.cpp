#include "face/blink.h"

#include <algorithm>

#include "face/easing.h"

namespace sw::face {

std::vector<double> schedule_blinks(double duration_s, const std::vector<double>& boundaries_s,
                                    std::uint32_t seed, const BlinkTiming& timing) {
  std::vector<double> starts;
  if (duration_s <= 0.0) return starts;
  // A small LCG (Numerical Recipes constants) rather than <random>: its sequence is specified, so
  // native and WebAssembly builds schedule the same blinks.
  std::uint32_t state = seed * 1664525u + 1013904223u;
  auto next_unit = [&state]() {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
  };
  double t = timing.min_interval_s * 0.5 + next_unit() * timing.min_interval_s;
  while (t < duration_s) {
    starts.push_back(t);
    t += timing.min_interval_s + next_unit() * (timing.max_interval_s - timing.min_interval_s);
  }
  for (double b : boundaries_s)
    if (b >= 0.0 && b < duration_s) starts.push_back(b);
  std::sort(starts.begin(), starts.end());
  const double blink_length = timing.closing_s + timing.closed_s + timing.opening_s;
  std::vector<double> merged;
  for (double s : starts)
    if (merged.empty() || s - merged.back() > blink_length * 1.5) merged.push_back(s);
  return merged;
}

float blink_weight(const std::vector<double>& starts_s, double t_s, const BlinkTiming& timing) {
  float weight = 0.0f;
  for (double s : starts_s) {
    const double local = t_s - s;
    if (local < 0.0) break;
    if (local < timing.closing_s) {
      weight = std::max(weight, ease_cosine(float(local / timing.closing_s)));
    } else if (local < timing.closing_s + timing.closed_s) {
      weight = 1.0f;
    } else if (local < timing.closing_s + timing.closed_s + timing.opening_s) {
      const double u = (local - timing.closing_s - timing.closed_s) / timing.opening_s;
      weight = std::max(weight, 1.0f - ease_cosine(float(u)));
    }
  }
  return weight;
}

}  // namespace sw::face

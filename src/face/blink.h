// Blinks: a deterministic schedule of eye blinks for a clip. People blink every few seconds, and
// signers blink at prosodic boundaries (ends of phrases), so blinks fall both on a seeded
// irregular rhythm and at every pause the timeline asks for.
#pragma once

#include <cstdint>
#include <vector>

namespace sw::face {

struct BlinkTiming {
  double closing_s = 0.08;  // upper lid down (fast)
  double closed_s = 0.04;
  double opening_s = 0.14;  // lid up (slower than closing)
  double min_interval_s = 2.4;
  double max_interval_s = 4.8;
};

// Blink start times within [0, duration_s): seeded rhythm plus one at each boundary time; blinks
// closer than one blink apart are merged. Same seed, same schedule (clips must be deterministic).
std::vector<double> schedule_blinks(double duration_s, const std::vector<double>& boundaries_s,
                                    std::uint32_t seed, const BlinkTiming& timing = {});

// Lid closure in [0, 1] at time t for a schedule (cosine-shaped closing and opening).
float blink_weight(const std::vector<double>& starts_s, double t_s, const BlinkTiming& timing = {});

}  // namespace sw::face

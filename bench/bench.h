// A tiny benchmark registry: each bench/<topic>_bench.cpp registers functions with SW_BENCH; the
// signweave-bench binary runs them all and prints one JSON line per result:
//   {"name": "fk_65_joints_native", "value": 812.5, "unit": "ns/update"}
// Figures live here, never in timed tests.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace sw::bench {

struct Result {
  std::string name;
  double value = 0.0;
  std::string unit;
};

using BenchFn = std::function<std::vector<Result>()>;
int register_bench(const char* name, BenchFn fn);

// Runs `body` repeatedly for at least `min_seconds` and returns the mean nanoseconds per call.
double time_ns_per_call(const std::function<void()>& body, double min_seconds = 0.3);

}  // namespace sw::bench

#define SW_BENCH_CONCAT2(a, b) a##b
#define SW_BENCH_CONCAT(a, b) SW_BENCH_CONCAT2(a, b)
#define SW_BENCH(name)                                                            \
  static std::vector<sw::bench::Result> SW_BENCH_CONCAT(sw_bench_fn_, __LINE__)(); \
  static const int SW_BENCH_CONCAT(sw_bench_reg_, __LINE__) =                      \
      sw::bench::register_bench(name, SW_BENCH_CONCAT(sw_bench_fn_, __LINE__));   \
  static std::vector<sw::bench::Result> SW_BENCH_CONCAT(sw_bench_fn_, __LINE__)()

// signweave-bench: runs every registered benchmark and prints JSON lines (bench.h).
// Usage: signweave-bench [substring]   — only benchmarks whose name contains the substring.
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include "bench.h"

namespace sw::bench {
namespace {
std::vector<std::pair<std::string, BenchFn>>& registry() {
  static std::vector<std::pair<std::string, BenchFn>> benches;
  return benches;
}
std::string json_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}
}  // namespace

int register_bench(const char* name, BenchFn fn) {
  registry().emplace_back(name, std::move(fn));
  return static_cast<int>(registry().size());
}

double time_ns_per_call(const std::function<void()>& body, double min_seconds) {
  using clock = std::chrono::steady_clock;
  body();  // warm caches
  long iterations = 1;
  for (;;) {
    const auto start = clock::now();
    for (long i = 0; i < iterations; ++i) body();
    const double elapsed = std::chrono::duration<double>(clock::now() - start).count();
    if (elapsed >= min_seconds) return elapsed * 1e9 / double(iterations);
    iterations *= (elapsed < min_seconds / 10) ? 10 : 2;
  }
}

}  // namespace sw::bench

int main(int argc, char** argv) {
  const char* filter = argc > 1 ? argv[1] : nullptr;
  for (auto& [name, fn] : sw::bench::registry()) {
    if (filter && !std::strstr(name.c_str(), filter)) continue;
    for (const auto& r : fn()) {
      std::printf("{\"name\": \"%s\", \"value\": %.6g, \"unit\": \"%s\"}\n",
                  sw::bench::json_escape(r.name).c_str(), r.value,
                  sw::bench::json_escape(r.unit).c_str());
      std::fflush(stdout);
    }
  }
  return 0;
}

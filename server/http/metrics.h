// Metrics: request counts by route and status and a latency histogram, exposed at /metrics in the
// Prometheus text format (version 0.0.4), plus gauges the caller adds (database size).
// Routes are the templates ("/api/signs/{id}"), never raw paths, so the label set stays bounded
// however many ids or files are requested.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <utility>

namespace sw::http {

class Metrics {
 public:
  void record(const std::string& route, int status, double seconds);
  // The exposition text; `extra` is appended as-is (gauges computed at scrape time).
  std::string render(const std::string& extra) const;

 private:
  // Upper bounds in seconds. Why these: a sign fetch takes tens of microseconds, an import of a
  // whole lexicon seconds; the buckets span both with a factor of about 2.5 between them.
  static constexpr std::array<double, 13> kBuckets = {0.0001, 0.00025, 0.0005, 0.001, 0.0025, 0.005,
                                                      0.01,   0.025,   0.05,   0.1,   0.25,   1.0,  5.0};
  struct Histogram {
    std::array<std::uint64_t, kBuckets.size()> counts{};
    std::uint64_t count = 0;
    double sum = 0.0;
  };
  mutable std::mutex mutex_;
  std::map<std::pair<std::string, int>, std::uint64_t> requests_;
  std::map<std::string, Histogram> latency_;
};

}  // namespace sw::http

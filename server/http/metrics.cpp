// Prometheus text exposition (see metrics.h).
#include "http/metrics.h"

#include <cstdio>

namespace sw::http {

void Metrics::record(const std::string& route, int status, double seconds) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++requests_[{route, status}];
  Histogram& histogram = latency_[route];
  for (std::size_t i = 0; i < kBuckets.size(); ++i) {
    if (seconds <= kBuckets[i]) ++histogram.counts[i];
  }
  ++histogram.count;
  histogram.sum += seconds;
}

std::string Metrics::render(const std::string& extra) const {
  std::string out;
  char line[512];
  std::lock_guard<std::mutex> lock(mutex_);
  out += "# HELP signweave_http_requests_total HTTP requests answered, by route and status.\n";
  out += "# TYPE signweave_http_requests_total counter\n";
  for (const auto& [key, count] : requests_) {
    std::snprintf(line, sizeof line, "signweave_http_requests_total{route=\"%s\",status=\"%d\"} %llu\n",
                  key.first.c_str(), key.second, static_cast<unsigned long long>(count));
    out += line;
  }
  out += "# HELP signweave_http_request_duration_seconds Time from routing to the response body, by route.\n";
  out += "# TYPE signweave_http_request_duration_seconds histogram\n";
  for (const auto& [route, histogram] : latency_) {
    for (std::size_t i = 0; i < kBuckets.size(); ++i) {
      std::snprintf(line, sizeof line,
                    "signweave_http_request_duration_seconds_bucket{route=\"%s\",le=\"%g\"} %llu\n",
                    route.c_str(), kBuckets[i], static_cast<unsigned long long>(histogram.counts[i]));
      out += line;
    }
    std::snprintf(line, sizeof line,
                  "signweave_http_request_duration_seconds_bucket{route=\"%s\",le=\"+Inf\"} %llu\n"
                  "signweave_http_request_duration_seconds_sum{route=\"%s\"} %.9f\n"
                  "signweave_http_request_duration_seconds_count{route=\"%s\"} %llu\n",
                  route.c_str(), static_cast<unsigned long long>(histogram.count), route.c_str(),
                  histogram.sum, route.c_str(), static_cast<unsigned long long>(histogram.count));
    out += line;
  }
  out += extra;
  return out;
}

}  // namespace sw::http

// The HTTP API of the gesture database and the routing of every request: /api/* to the store,
// /healthz and /metrics, /models/* to the avatar directory, everything else to the page's static
// files. One dispatcher (no per-route regexes) so that every answer — success, refusal, crash —
// is timed and counted under a bounded route label, and every error is JSON.
//
// Routes (docs/API.md is the reference with examples):
//   GET    /api/languages
//   GET    /api/signs?q=&lang=&limit=&cursor=
//   POST   /api/signs                      Authorization: Bearer <token>
//   GET    /api/signs/{id}                 ETag "<revision>"; If-None-Match -> 304
//   PUT    /api/signs/{id}                 Bearer + If-Match "<revision>" (428 without, 409 stale)
//   DELETE /api/signs/{id}                 Bearer + If-Match
//   GET    /api/signs/{id}/history
//   GET    /api/lookup?text=&lang=
//   POST   /api/import?lang=               Bearer; JSON lines, all or nothing
//   GET    /healthz[?deep=1]               deep: PRAGMA integrity_check + content fingerprint
//   GET    /metrics                        Prometheus text
#pragma once

#include <httplib.h>

#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

#include "http/metrics.h"
#include "http/static_files.h"
#include "store/store.h"

namespace sw::http {

struct ApiLimits {
  // Why 256 KiB: one sign is at most 64 KiB of notation plus labels; anything bigger is not a sign.
  std::size_t max_sign_body_bytes = 256 * 1024;
  // Why 16 KiB: browsers send 1–2 KiB of headers; a bigger block is an attack or a broken client.
  std::size_t max_header_bytes = 16 * 1024;
};

class ApiRoutes {
 public:
  ApiRoutes(store::Store& store, Metrics& metrics, const std::string& web_dir,
            const std::string& models_dir, ApiLimits limits);
  // Answers any request. Never throws.
  void handle(const httplib::Request& req, httplib::Response& res);

 private:
  void route(const httplib::Request& req, httplib::Response& res, std::string* label);

  void get_languages(const httplib::Request& req, httplib::Response& res);
  void search_signs(const httplib::Request& req, httplib::Response& res);
  void get_sign(const httplib::Request& req, httplib::Response& res, std::int64_t id);
  void create_sign(const httplib::Request& req, httplib::Response& res);
  void update_sign(const httplib::Request& req, httplib::Response& res, std::int64_t id);
  void delete_sign(const httplib::Request& req, httplib::Response& res, std::int64_t id);
  void sign_history(const httplib::Request& req, httplib::Response& res, std::int64_t id);
  void lookup(const httplib::Request& req, httplib::Response& res);
  void import_signs(const httplib::Request& req, httplib::Response& res);
  void healthz(const httplib::Request& req, httplib::Response& res);
  void metrics(const httplib::Request& req, httplib::Response& res);

  // The author name of a valid bearer token; throws ApiError 401 (missing/malformed) or 403.
  std::string authenticate(const httplib::Request& req);

  // GET /api/signs/{id} bodies, valid while the store's content generation has not moved: a fetch
  // then costs one indexed read instead of a transaction, two queries and a JSON build.
  struct CachedSign {
    std::int64_t generation = 0;
    std::int64_t revision = 0;
    bool deleted = false;
    std::string body;
  };
  std::mutex sign_cache_mutex_;
  std::unordered_map<std::int64_t, CachedSign> sign_cache_;

  store::Store& store_;
  Metrics& metrics_;
  StaticFiles web_;
  StaticFiles models_;
  ApiLimits limits_;
};

}  // namespace sw::http

// HttpServer: cpp-httplib configured for the gesture database — limits (body, headers, timeouts,
// worker threads) with their reasons, every method routed to ApiRoutes, errors httplib raises
// itself (bad request line, 413, 414) turned into the same JSON shape, and a clean stop() that
// lets in-flight requests finish.
#pragma once

#include <memory>
#include <string>

#include "http/api_routes.h"
#include "http/metrics.h"
#include "store/store.h"

namespace httplib {
class Server;
}

namespace sw::http {

struct ServerConfig {
  std::string host = "127.0.0.1";
  int port = 8080;  // 0: any free port (printed at start; the tests use this)
  std::string web_dir = "web";
  std::string models_dir = "models";
  // Why 128: cpp-httplib gives each open connection a worker for as long as it is kept alive, so
  // the pool bounds concurrent clients. 128 serves the benchmark's 64 connections plus browsers,
  // at 8 MiB of reserved (not committed) stack each.
  int threads = 128;
  // Why 16 MiB: the largest request is a bulk import of a whole lexicon (one JSON line per sign,
  // a few hundred bytes each: 16 MiB is tens of thousands of signs). Sign bodies have their own,
  // smaller limit (ApiLimits).
  std::size_t max_body_bytes = 16 * 1024 * 1024;
  ApiLimits api_limits;
  // Why 5 s: long enough for a slow mobile upload of one request, short enough that a stalled
  // client cannot hold a worker; keep-alive idles also end after 5 s (and bound how long a
  // graceful shutdown waits for idle connections).
  int read_timeout_s = 5;
  int write_timeout_s = 10;
  int keep_alive_timeout_s = 5;
  std::size_t keep_alive_max_requests = 100000;
};

class HttpServer {
 public:
  HttpServer(store::Store& store, const ServerConfig& config);
  ~HttpServer();

  // Binds the listening socket. Returns the bound port, or -1 with `error` set.
  int bind(std::string* error);
  // Serves until stop(). Returns false if the server could not run.
  bool run();
  // Stops accepting; requests in progress finish, then run() returns. Safe from any thread.
  void stop();

 private:
  store::Store& store_;
  ServerConfig config_;
  Metrics metrics_;
  std::unique_ptr<ApiRoutes> routes_;
  std::unique_ptr<httplib::Server> server_;
};

}  // namespace sw::http

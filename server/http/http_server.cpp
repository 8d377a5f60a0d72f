// cpp-httplib set-up (see http_server.h).
#include "http/http_server.h"

#include <httplib.h>

#include <sys/socket.h>

#include <cstdio>

#include "http/json_reply.h"

namespace sw::http {

// Debian's libcpp-httplib was compiled with a listen backlog of 5: a burst of new connections
// (a page load opens several, a benchmark 64) overflows it and the kernel drops SYNs, which
// clients retry only after a second. The listening socket is reachable from a subclass, and
// calling listen() again on it raises the backlog.
class BacklogServer : public httplib::Server {
 public:
  void raise_backlog(int backlog) {
    socket_t socket = svr_sock_;
    if (socket != INVALID_SOCKET) ::listen(socket, backlog);
  }
};

HttpServer::HttpServer(store::Store& store, const ServerConfig& config)
    : store_(store), config_(config) {
  routes_ = std::make_unique<ApiRoutes>(store_, metrics_, config_.web_dir, config_.models_dir,
                                        config_.api_limits);
  server_ = std::make_unique<BacklogServer>();
  httplib::Server& server = *server_;
  int threads = config_.threads;
  server.new_task_queue = [threads] { return new httplib::ThreadPool(static_cast<size_t>(threads)); };
  server.set_keep_alive_max_count(config_.keep_alive_max_requests);
  server.set_keep_alive_timeout(config_.keep_alive_timeout_s);
  server.set_read_timeout(config_.read_timeout_s, 0);
  server.set_write_timeout(config_.write_timeout_s, 0);
  server.set_payload_max_length(config_.max_body_bytes);
  server.set_tcp_nodelay(true);

  ApiRoutes* routes = routes_.get();
  auto handler = [routes](const httplib::Request& req, httplib::Response& res) { routes->handle(req, res); };
  // One catch-all per method: ApiRoutes does the routing (and the 405s) itself.
  server.Get(".*", handler);
  server.Post(".*", handler);
  server.Put(".*", handler);
  server.Delete(".*", handler);
  server.Patch(".*", handler);
  server.Options(".*", handler);

  Metrics* metrics = &metrics_;
  std::size_t body_limit = config_.max_body_bytes;
  // Called for every answer >= 400. Ours already carry a JSON body; the ones httplib makes on its
  // own (malformed request line, 413 over max_body_bytes, 414 URI too long) get one here.
  httplib::Server::HandlerWithResponse on_error = [metrics, body_limit](const httplib::Request& req,
                                                                       httplib::Response& res) {
    if (!res.body.empty() || res.content_length_ > 0) return httplib::Server::HandlerResponse::Unhandled;
    std::string message;
    switch (res.status) {
      case 400: message = "malformed HTTP request"; break;
      case 413: message = "request body too large"; break;
      case 414: message = "request URI too long"; break;
      case 416: message = "requested range not satisfiable"; break;
      default: message = "request refused by the HTTP layer"; break;
    }
    nlohmann::json detail{{"status", res.status}};
    if (res.status == 413) detail["limit_bytes"] = body_limit;
    reply_error(res, res.status, message, detail);
    (void)req;
    metrics->record("http_layer", res.status, 0.0);
    return httplib::Server::HandlerResponse::Handled;
  };
  server.set_error_handler(on_error);
  server.set_exception_handler([](const httplib::Request& req, httplib::Response& res, std::exception_ptr) {
    std::fprintf(stderr, "signweave-server: unhandled exception on %s %s\n", req.method.c_str(), req.path.c_str());
    reply_error(res, 500, "internal error (logged on the server)");
  });
}

HttpServer::~HttpServer() = default;

int HttpServer::bind(std::string* error) {
  int port;
  if (config_.port == 0) {
    port = server_->bind_to_any_port(config_.host);
  } else {
    port = server_->bind_to_port(config_.host, config_.port) ? config_.port : -1;
  }
  // Why 1024: the kernel's default somaxconn on current Linux is 4096; 1024 absorbs any burst a
  // single self-hosted server sees without holding many half-open connections.
  if (port > 0) static_cast<BacklogServer*>(server_.get())->raise_backlog(1024);
  if (port <= 0) {
    if (error) *error = "cannot listen on " + config_.host + ":" + std::to_string(config_.port) + " (in use, or not an address of this machine)";
    return -1;
  }
  return port;
}

bool HttpServer::run() { return server_->listen_after_bind(); }

void HttpServer::stop() { server_->stop(); }

}  // namespace sw::http

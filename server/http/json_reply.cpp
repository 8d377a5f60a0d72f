// JSON replies (see json_reply.h).
#include "http/json_reply.h"

namespace sw::http {

void reply_json(httplib::Response& res, int status, const nlohmann::json& body) {
  res.status = status;
  // error_handler_t::replace: a stored string with bad UTF-8 (impossible through the API, which
  // validates input) would otherwise throw while answering.
  res.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                  "application/json");
}

void reply_error(httplib::Response& res, int status, const std::string& message,
                 const nlohmann::json& detail) {
  reply_json(res, status, nlohmann::json{{"error", message}, {"detail", detail}});
}

}  // namespace sw::http

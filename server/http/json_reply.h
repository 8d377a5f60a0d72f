// JSON replies: every API answer, success or error, goes through these so that errors always
// read {"error": "<one line>", "detail": {...}} with the status that fits.
#pragma once

#include <httplib.h>

#include <nlohmann/json.hpp>

#include <string>

namespace sw::http {

void reply_json(httplib::Response& res, int status, const nlohmann::json& body);
void reply_error(httplib::Response& res, int status, const std::string& message,
                 const nlohmann::json& detail = nlohmann::json::object());

}  // namespace sw::http

// ApiError: a refusal the client can act on — the HTTP status, a one-line message naming what was
// wrong, and a JSON detail object (field name, line/column, current revision ...). The store and
// the HTTP layer throw it; the HTTP layer turns it into {"error": message, "detail": detail}.
// Failures that are not the client's fault are DatabaseError (sqlite_db.h), answered with 500/503.
#pragma once

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

namespace sw::store {

class ApiError : public std::runtime_error {
 public:
  ApiError(int status, const std::string& message, nlohmann::json detail = nlohmann::json::object())
      : std::runtime_error(message), status_(status), detail_(std::move(detail)) {}
  int status() const { return status_; }
  const nlohmann::json& detail() const { return detail_; }

 private:
  int status_;
  nlohmann::json detail_;
};

}  // namespace sw::store

// JSON in and out for the gesture database: the strict reading of a request body (valid UTF-8,
// bounded nesting, every field known and of the right type — an unknown or mistyped field is
// named in the 400), and the JSON shape of signs, languages and revisions the API returns.
// Shared by the HTTP API, `POST /api/import` and `signweave import`, so all three accept exactly
// the same documents.
#pragma once

#include <nlohmann/json.hpp>

#include <string_view>

#include "store/sign_record.h"

namespace sw::store {

// Why 32: the deepest document the API accepts is an import line with keyword objects (depth 3);
// a limit far below the parser's own keeps hostile "[[[[..." bodies cheap to refuse.
constexpr int kMaxJsonDepth = 32;

// Parses a JSON document. Throws ApiError(400) naming the byte offset (and line/column) of the
// first invalid UTF-8 byte or syntax error, or the nesting depth exceeded.
nlohmann::json parse_json_document(std::string_view text);

// Reads a sign object. Throws ApiError(400) with detail {"field": name} for an unknown field, a
// wrong type, a missing required field or a value over its limit. `require_language` is true on
// create; an import line may take its language from the file instead.
SignInput parse_sign_input(const nlohmann::json& object, bool require_language);

// Reads a languages.json entry {"code", "name", "spoken", "alphabet_script"}.
Language parse_language(const nlohmann::json& object);

nlohmann::json sign_to_json(const SignRecord& sign);
// The sign's content without id/revision/timestamps: what a revision snapshot keeps.
nlohmann::json sign_content_json(const SignRecord& sign);
nlohmann::json language_to_json(const Language& language);
nlohmann::json revision_to_json(const RevisionRecord& revision);

}  // namespace sw::store

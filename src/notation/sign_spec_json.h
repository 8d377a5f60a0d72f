// SignSpec <-> JSON (nlohmann), both directions: the form the server stores and serves, the WASM
// API hands the editor, and the tests compare (two SignSpecs are equal when their JSON is).
// Enum values are written with the words of sign_spec_names.h; directions as [x, y, z].
//
// Reading never throws (the WASM build cannot catch): a malformed document gives false and a
// message naming the field.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "notation/diagnostic.h"
#include "notation/parse.h"
#include "notation/sign_spec.h"

namespace sw::notation {

nlohmann::json sign_to_json(const SignSpec& sign);
bool sign_from_json(const nlohmann::json& j, SignSpec* sign, std::string* error);
// Text forms (compact, one line).
std::string sign_to_json_text(const SignSpec& sign);
bool sign_from_json_text(std::string_view text, SignSpec* sign, std::string* error);

// {"severity":"error","line":..,"column":..,"offset":..,"length":..,"symbol":..,"message":..}
nlohmann::json diagnostic_to_json(const Diagnostic& d);
nlohmann::json diagnostics_to_json(const std::vector<Diagnostic>& diagnostics);

// The result of parsing a text, as the WASM API and the server hand it on:
// {"format": .., "ok": .., "signs": [{"gloss", "line", "ok", "spec": {...}|null,
//  "diagnostics": [...]}], "diagnostics": [every diagnostic, for the editor's underlines]}.
nlohmann::json parse_result_to_json(const std::vector<SignParse>& signs, NotationFormat format);

}  // namespace sw::notation

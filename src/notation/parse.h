// One entry point for every notation the core reads: the server, the CLI, the WASM API and the
// notation editor call this and never a format's parser directly.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "notation/diagnostic.h"
#include "notation/sign_spec.h"

namespace sw::notation {

struct ParseOutcome {
  std::vector<SignSpec> signs;            // every sign that parsed (a file may hold many)
  std::vector<Diagnostic> diagnostics;    // errors and warnings, each with position and symbol
  bool ok() const { return !has_error(diagnostics); }
};

// Parse `text` written in `format`. Never throws; malformed input gives diagnostics.
ParseOutcome parse_notation(std::string_view text, NotationFormat format);
// Guess the format from the text (XML root element, private-use code points, "R(" / "L(" ...).
NotationFormat detect_format(std::string_view text);
// Canonical names used in the API and the database: "formula", "hamnosys", "hsigml", "gsigml".
const char* format_name(NotationFormat format);
bool format_from_name(std::string_view name, NotationFormat* out);

}  // namespace sw::notation

// One entry point for every notation the core reads: the server, the CLI, the WASM API and the
// notation editor call this and never a format's parser directly.
#pragma once

#include <cstddef>
#include <optional>
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

// One sign of a text, parsed on its own (added for the CLI's per-sign report and the server's
// per-sign import): its gloss, the SignSpec when one could be built (the HamNoSys and SiGML
// readers recover from some errors and still build one), and its own diagnostics.
struct SignParse {
  std::string gloss;
  std::optional<SignSpec> spec;
  std::vector<Diagnostic> diagnostics;
  std::size_t offset = 0;  // byte offset where the sign starts in the text
  int line = 1;            // its line (1-based)
  bool ok() const { return spec.has_value() && !has_error(diagnostics); }
};
// Every sign of `text` (a formula/HamNoSys file holds one sign a line, `GLOSS = ...`, `#`
// comments; a SiGML document one per sign element). Diagnostics that belong to no sign (a broken
// XML document, an empty text) come back as a SignParse without spec.
std::vector<SignParse> parse_signs(std::string_view text, NotationFormat format);

// Writes signs in `format` (added with the printers): formula and HamNoSys as one line per sign
// (`GLOSS = ...`; HamNoSys as Unicode code points), SiGML as one <sigml> document.
std::string print_notation(const std::vector<SignSpec>& signs, NotationFormat format);
// Guess the format from the text (XML root element, private-use code points, "R(" / "L(" ...).
NotationFormat detect_format(std::string_view text);
// Canonical names used in the API and the database: "formula", "hamnosys", "hsigml", "gsigml".
const char* format_name(NotationFormat format);
bool format_from_name(std::string_view name, NotationFormat* out);

}  // namespace sw::notation

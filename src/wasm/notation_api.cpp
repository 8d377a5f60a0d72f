// Embind API of the notation module (thin: the logic is in src/notation). JSON strings cross the
// boundary: the editor parses a text for its SignSpec and diagnostics (underlines), detects the
// notation of pasted text, and prints a SignSpec back into any notation.
#include <emscripten/bind.h>

#include <string>

#include "notation/parse.h"
#include "notation/sign_spec_json.h"

namespace {

using sw::notation::NotationFormat;

// format: "formula" | "hamnosys" | "hsigml" | "gsigml" | "" (detect).
std::string notation_parse(const std::string& text, const std::string& format_name) {
  NotationFormat format = sw::notation::detect_format(text);
  if (!format_name.empty() && !sw::notation::format_from_name(format_name, &format)) {
    return nlohmann::json({{"ok", false}, {"error", "unknown notation '" + format_name + "' (formula, hamnosys, hsigml, gsigml)"}}).dump();
  }
  return sw::notation::parse_result_to_json(sw::notation::parse_signs(text, format), format).dump();
}

std::string notation_detect(const std::string& text) {
  return sw::notation::format_name(sw::notation::detect_format(text));
}

// spec_json: one SignSpec as JSON; returns {"ok", "text"} or {"ok": false, "error"}.
std::string notation_print(const std::string& spec_json, const std::string& format_name) {
  NotationFormat format;
  if (!sw::notation::format_from_name(format_name, &format)) {
    return nlohmann::json({{"ok", false}, {"error", "unknown notation '" + format_name + "'"}}).dump();
  }
  sw::notation::SignSpec sign;
  std::string error;
  if (!sw::notation::sign_from_json_text(spec_json, &sign, &error)) {
    return nlohmann::json({{"ok", false}, {"error", error}}).dump();
  }
  return nlohmann::json({{"ok", true}, {"text", sw::notation::print_notation({sign}, format)}}).dump();
}

}  // namespace

EMSCRIPTEN_BINDINGS(notation_api) {
  emscripten::function("notationParse", &notation_parse);
  emscripten::function("notationDetect", &notation_detect);
  emscripten::function("notationPrint", &notation_print);
}

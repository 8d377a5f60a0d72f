// Notation validation through the core (see sign_validation.h).
#include "store/sign_validation.h"

#include <nlohmann/json.hpp>

#include "notation/parse.h"
#include "store/api_error.h"

// The notation parsers land with the formula reader (src/notation/formula.h); before that this
// build has the parse.h contract but no parser. The SignSpec -> JSON converter (cached as the
// sign's compiled form) comes separately.
#if __has_include("notation/formula.h")
#define SIGNWEAVE_STORE_HAS_PARSER 1
#else
#define SIGNWEAVE_STORE_HAS_PARSER 0
#endif
#if __has_include("notation/sign_spec_json.h")
#define SIGNWEAVE_STORE_HAS_SPEC_JSON 1
#include "notation/sign_spec_json.h"
#else
#define SIGNWEAVE_STORE_HAS_SPEC_JSON 0
#endif

namespace sw::store {
namespace {

using nlohmann::json;

const char* const kFormatNames[] = {"formula", "hamnosys", "hsigml", "gsigml"};

bool known_format(const std::string& name) {
  for (const char* known : kFormatNames) {
    if (name == known) return true;
  }
  return false;
}

}  // namespace

bool notation_parser_available() { return SIGNWEAVE_STORE_HAS_PARSER != 0; }

ValidatedNotation validate_notation(const std::string& notation,
                                    const std::optional<std::string>& format) {
  if (format && !known_format(*format)) {
    throw ApiError(400, "unknown notation format '" + *format + "'",
                   json{{"field", "format"}, {"allowed", kFormatNames}});
  }
#if SIGNWEAVE_STORE_HAS_PARSER
  using namespace sw::notation;
  NotationFormat parsed_format;
  if (format) {
    format_from_name(*format, &parsed_format);
  } else {
    parsed_format = detect_format(notation);
  }
  ParseOutcome outcome = parse_notation(notation, parsed_format);
  json diagnostics = json::array();
  for (const Diagnostic& d : outcome.diagnostics) {
    diagnostics.push_back(json{{"severity", d.severity == Severity::Error ? "error" : "warning"},
                               {"message", d.message},
                               {"line", d.line},
                               {"column", d.column},
                               {"offset", d.offset},
                               {"length", d.length},
                               {"symbol", d.symbol}});
  }
  if (!outcome.ok()) {
    const Diagnostic* first = nullptr;
    for (const Diagnostic& d : outcome.diagnostics) {
      if (d.severity == Severity::Error) {
        first = &d;
        break;
      }
    }
    std::string message = first ? "notation does not parse: " + format_diagnostic(*first)
                                : std::string("notation does not parse");
    throw ApiError(422, message,
                   json{{"field", "notation"},
                        {"format", format_name(parsed_format)},
                        {"diagnostics", diagnostics}});
  }
  if (outcome.signs.size() != 1) {
    throw ApiError(422,
                   "notation holds " + std::to_string(outcome.signs.size()) +
                       " signs; a database entry is exactly one sign",
                   json{{"field", "notation"}, {"signs", outcome.signs.size()}});
  }
  ValidatedNotation result;
  result.format = format_name(parsed_format);
#if SIGNWEAVE_STORE_HAS_SPEC_JSON
  result.compiled = json{{"spec", sw::notation::sign_to_json(outcome.signs.front())}}.dump();
#endif
  return result;
#else
  (void)notation;
  throw ApiError(503, "this server was built without the notation parser; signs cannot be checked",
                 json{{"field", "notation"}});
#endif
}

}  // namespace sw::store

// Notation validation through the core (see sign_validation.h).
#include "store/sign_validation.h"

#include <nlohmann/json.hpp>

#include <memory>

#include "notation/parse.h"
#include "notation/sign_spec_json.h"
#include "store/api_error.h"
#include "synthesis/signing_avatar.h"
#include "synthesis/synthesize.h"

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

// Set once before the server's threads start; read-only afterwards, so no lock is needed. The
// Synthesizer keeps a pointer to the avatar, so both live on the heap and never move.
struct ValidationAvatar {
  synthesis::SigningAvatar avatar;
  std::unique_ptr<synthesis::Synthesizer> synthesizer;
};
std::unique_ptr<ValidationAvatar>& validation_avatar() {
  static std::unique_ptr<ValidationAvatar> instance;
  return instance;
}

}  // namespace

bool load_validation_avatar(const std::string& glb_path, std::string* error) {
  auto loaded = std::make_unique<ValidationAvatar>();
  loaded->avatar = synthesis::load_signing_avatar_file(glb_path);
  if (!loaded->avatar.ok()) {
    *error = glb_path + ": " + loaded->avatar.error;
    return false;
  }
  loaded->synthesizer = std::make_unique<synthesis::Synthesizer>(loaded->avatar.avatar);
  if (!loaded->synthesizer->ok()) {
    *error = glb_path + ": " + loaded->synthesizer->error();
    return false;
  }
  validation_avatar() = std::move(loaded);
  return true;
}

bool synthesis_check_enabled() { return validation_avatar() != nullptr; }

ValidatedNotation validate_notation(const std::string& notation,
                                    const std::optional<std::string>& format) {
  if (format && !known_format(*format)) {
    throw ApiError(400, "unknown notation format '" + *format + "'",
                   json{{"field", "format"}, {"allowed", kFormatNames}});
  }
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
  if (const auto& checker = validation_avatar()) {
    const synthesis::SynthesisResult synthesised =
        checker->synthesizer->sign(outcome.signs.front(), synthesis::SynthesisOptions{});
    if (!synthesised.ok()) {
      const synthesis::SynthesisError& first = synthesised.errors.front();
      throw ApiError(422, "notation parses but cannot be signed: " + first.where + ": " + first.message,
                     json{{"field", "notation"},
                          {"format", format_name(parsed_format)},
                          {"stage", "synthesis"},
                          {"where", first.where}});
    }
  }
  ValidatedNotation result;
  result.format = format_name(parsed_format);
  result.compiled = json{{"spec", sw::notation::sign_to_json(outcome.signs.front())}}.dump();
  return result;
}

}  // namespace sw::store

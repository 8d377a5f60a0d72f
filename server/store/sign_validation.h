// The check every sign passes before it is written (API, bulk import and `signweave import`
// alike): the notation must parse with the core's own parser (sw::notation::parse_notation) into
// exactly one sign, and — when the synthesis stage is built in — compile onto the avatar.
// A refusal is ApiError(422) carrying the parser's diagnostics: message, line, column, byte
// offset, length and the offending symbol, ready for the notation editor to underline.
#pragma once

#include <optional>
#include <string>

namespace sw::store {

struct ValidatedNotation {
  std::string format;                  // canonical name: formula | hamnosys | hsigml | gsigml
  std::optional<std::string> compiled; // JSON the core derived (the SignSpec), cached in the row
};

// Throws ApiError(400) for an unknown format name, ApiError(422) when the notation is refused.
ValidatedNotation validate_notation(const std::string& notation,
                                    const std::optional<std::string>& format);

// The second stage of the check: the avatar every written sign must also synthesise on (a place
// the avatar lacks, two hands each placed on the other, ...). Loaded once at start-up by the
// server and by `signweave import`; false with `error` set when the file cannot be used, and the
// caller refuses to start rather than store signs it cannot play. Until it is called, only the
// parse stage runs (the store's own unit tests).
bool load_validation_avatar(const std::string& glb_path, std::string* error);
// True once load_validation_avatar succeeded (reported by /healthz).
bool synthesis_check_enabled();

}  // namespace sw::store

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

// True when this build links a notation parser (false only in a build without src/notation's
// parsers, where every write is refused with 503 rather than stored unchecked).
bool notation_parser_available();

}  // namespace sw::store

// Phrase text: what a user types -> the items of a phrase. Text that parses as notation (any
// format, notation/parse.h) gives its signs; otherwise, with a fingerspelling alphabet
// (data/<lang>/alphabet.jsonl: {"letter", "notation", "format"} per line), each letter of each
// word is fingerspelled and punctuation becomes a pause.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "synthesis/synthesize.h"

namespace sw::synthesis {

struct AlphabetEntry {
  std::string letter;    // upper case, UTF-8 ("A", "Б", "10")
  std::string notation;
  std::string format = "formula";
};

// Reads alphabet JSON lines; false with `error` ("line 3: ...") on a malformed line.
bool parse_alphabet_jsonl(std::string_view text, std::vector<AlphabetEntry>* out, std::string* error);

struct PhraseText {
  std::vector<PhraseItem> items;
  std::vector<SynthesisError> errors;
  bool fingerspelled = false;
  bool ok() const { return errors.empty() && !items.empty(); }
};

// `alphabet` may be empty (then only notation is accepted).
PhraseText phrase_from_text(std::string_view text, const std::vector<AlphabetEntry>& alphabet);

// Upper case of one UTF-8 letter (ASCII and Cyrillic, Ukrainian letters included).
std::string upper_letter(std::string_view utf8_letter);

}  // namespace sw::synthesis

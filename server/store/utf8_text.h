// UTF-8 text handling for the gesture database: validation (every string the server accepts is
// valid UTF-8), decoding to code points, lower-casing for case-insensitive search and lookup, and
// the character classes the phrase tokeniser needs.
//
// Limits, with their reason: lower-casing covers ASCII, Latin-1, Latin Extended-A, Greek and
// Cyrillic (every alphabet of the sign languages in data/); other scripts compare as written. No
// Unicode normalisation (NFC) is applied — the data files and the page both send NFC, and an ICU
// dependency for the rare decomposed input is not worth its size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sw::store {

// Byte offset of the first invalid UTF-8 sequence (overlongs, surrogates and code points above
// U+10FFFF are invalid), or npos when `text` is valid.
std::size_t find_invalid_utf8(std::string_view text);
inline bool is_valid_utf8(std::string_view text) {
  return find_invalid_utf8(text) == std::string_view::npos;
}

// Decodes valid UTF-8 (call is_valid_utf8 first; invalid bytes decode as U+FFFD).
std::vector<char32_t> decode_utf8(std::string_view text);
void append_utf8(std::string& out, char32_t code_point);
std::string encode_utf8(const std::vector<char32_t>& code_points);

char32_t to_lower(char32_t code_point);
// Lower-cased, surrounding white space removed, inner runs of white space collapsed to one space:
// the form glosses, keywords and queries are compared in.
std::string normalize_for_match(std::string_view text);

// Letters and digits of any script (what words are made of). Private-use code points (HamNoSys
// symbols) and punctuation/symbol blocks are not.
bool is_word_char(char32_t code_point);
bool is_space(char32_t code_point);
// Apostrophes that belong inside a word (don't, п'ять, Ukrainian modifier letter apostrophe).
bool is_word_joiner(char32_t code_point);
// Punctuation that ends a clause or a sentence in signing: returns the pause in seconds, 0 if the
// code point is not such punctuation.
double pause_after_punctuation_s(char32_t code_point);

}  // namespace sw::store

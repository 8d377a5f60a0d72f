// UTF-8 encoding, the one encoder every layer uses (notation's readers and printers, the phrase
// text of synthesis, the server's store). Decoders stay with their callers: each has its own rule
// for bad bytes (notation: U+FFFD a byte; the store validates first).
#pragma once

#include <string>

namespace sw::text {

// Appends the UTF-8 bytes of `code_point` as given: 1 byte below U+0080, 2 below U+0800, 3 below
// U+10000 (surrogates included: the caller decides whether they are allowed), else 4. Values
// above U+10FFFF are not code points; callers that may meet them replace them first (notation's
// append_utf8 writes U+FFFD).
void append_utf8(std::string* out, char32_t code_point);

}  // namespace sw::text

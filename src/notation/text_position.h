// Text positions for diagnostics: UTF-8 decoding and byte offset -> (line, column in code points),
// shared by every notation reader so that an error points at the same place in the editor, the CLI
// and the server's JSON.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "notation/diagnostic.h"

namespace sw::notation {

// Decodes one code point at `*offset` and advances it. Malformed UTF-8 (a stray continuation
// byte, a truncated sequence, an overlong form) yields U+FFFD and advances by one byte, so a
// reader never stops or loops on bad bytes.
char32_t decode_utf8(std::string_view text, std::size_t* offset);
// Appends the UTF-8 form of `code_point` (U+FFFD for values that are not scalar values).
void append_utf8(std::string* out, char32_t code_point);
// "U+E0FF" for printing unknown symbols.
std::string code_point_label(char32_t code_point);

// One line of a text: bytes [start, end), the '\n' excluded, and its 1-based number.
struct TextLine {
  std::size_t start = 0, end = 0;
  int number = 1;
};
// The '\n'-separated lines of a text, the last one included even without a '\n' (an empty text is
// one empty line): how the one-sign-per-line notation readers walk their input.
std::vector<TextLine> split_lines(std::string_view text);

// Maps byte offsets of one text to 1-based line and column (columns count code points, as the
// web editor does). Built once per text: O(lines) memory, O(log lines + line length) per query.
class LineIndex {
 public:
  explicit LineIndex(std::string_view text);
  void locate(std::size_t offset, int* line, int* column) const;
  // A diagnostic at [offset, offset + length) with its line and column filled in.
  Diagnostic make(std::size_t offset, std::size_t length, std::string symbol, std::string message,
                  Severity severity = Severity::Error) const;

 private:
  std::string_view text_;
  std::vector<std::size_t> line_starts_;
};

}  // namespace sw::notation

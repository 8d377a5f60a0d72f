// UTF-8 decoding and offset -> line/column mapping for diagnostics (see text_position.h).
#include "notation/text_position.h"

#include <algorithm>
#include <cstdio>

#include "text/utf8.h"

namespace sw::notation {

char32_t decode_utf8(std::string_view text, std::size_t* offset) {
  const std::size_t i = *offset;
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) {
    *offset = i + 1;
    return lead;
  }
  int extra = 0;
  char32_t cp = 0;
  char32_t min_value = 0;
  if ((lead & 0xE0) == 0xC0) {
    extra = 1, cp = lead & 0x1F, min_value = 0x80;
  } else if ((lead & 0xF0) == 0xE0) {
    extra = 2, cp = lead & 0x0F, min_value = 0x800;
  } else if ((lead & 0xF8) == 0xF0) {
    extra = 3, cp = lead & 0x07, min_value = 0x10000;
  } else {
    *offset = i + 1;
    return 0xFFFD;
  }
  if (i + extra >= text.size()) {  // truncated sequence
    *offset = i + 1;
    return 0xFFFD;
  }
  for (int k = 1; k <= extra; ++k) {
    const unsigned char c = byte(i + k);
    if ((c & 0xC0) != 0x80) {
      *offset = i + 1;
      return 0xFFFD;
    }
    cp = (cp << 6) | (c & 0x3F);
  }
  if (cp < min_value || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) {
    *offset = i + 1;
    return 0xFFFD;
  }
  *offset = i + 1 + extra;
  return cp;
}

void append_utf8(std::string* out, char32_t cp) {
  if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) cp = 0xFFFD;
  sw::text::append_utf8(out, cp);
}

std::string code_point_label(char32_t cp) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "U+%04X", static_cast<unsigned>(cp));
  return buffer;
}

LineIndex::LineIndex(std::string_view text) : text_(text) {
  line_starts_.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') line_starts_.push_back(i + 1);
  }
}

void LineIndex::locate(std::size_t offset, int* line, int* column) const {
  offset = std::min(offset, text_.size());
  const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const std::size_t line_index = static_cast<std::size_t>(it - line_starts_.begin()) - 1;
  std::size_t i = line_starts_[line_index];
  int col = 1;
  while (i < offset) {
    decode_utf8(text_, &i);
    ++col;
  }
  *line = static_cast<int>(line_index) + 1;
  *column = col;
}

Diagnostic LineIndex::make(std::size_t offset, std::size_t length, std::string symbol,
                           std::string message, Severity severity) const {
  Diagnostic d;
  d.severity = severity;
  d.offset = std::min(offset, text_.size());
  d.length = std::min(length, text_.size() - d.offset);
  locate(d.offset, &d.line, &d.column);
  d.symbol = std::move(symbol);
  d.message = std::move(message);
  return d;
}

std::vector<TextLine> split_lines(std::string_view text) {
  std::vector<TextLine> lines;
  std::size_t start = 0;
  for (int number = 1;; ++number) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    lines.push_back({start, end, number});
    if (end == text.size()) break;
    start = end + 1;
  }
  return lines;
}

}  // namespace sw::notation

// Tests of UTF-8 decoding and offset -> line/column (src/notation/text_position.h).
#include "notation/text_position.h"

#include <gtest/gtest.h>

namespace sw::notation {
namespace {

TEST(TextPosition, ColumnsCountCodePointsAndLinesStartAfterNewlines) {
  const std::string text = "ab\n\xD0\x92\xEE\x80\x81x\n";  // "ab", "В U+E001 x"
  const LineIndex index(text);
  int line = 0, column = 0;
  index.locate(1, &line, &column);
  EXPECT_EQ(line, 1);
  EXPECT_EQ(column, 2);
  index.locate(8, &line, &column);  // 'x': after a 2-byte and a 3-byte code point
  EXPECT_EQ(line, 2);
  EXPECT_EQ(column, 3);
  index.locate(1000, &line, &column);  // clamped to the end
  EXPECT_EQ(line, 3);
  const Diagnostic d = index.make(3, 99, "В", "message");
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 1);
  EXPECT_EQ(d.length, text.size() - 3);  // clamped to the text
}

TEST(TextPosition, MalformedUtf8AdvancesOneByteAsReplacement) {
  const std::string bad[] = {"\x80", "\xC3", "\xE2\x82", "\xC0\xAF", "\xED\xA0\x80", "\xF4\x90\x80\x80", "\xFF"};
  for (const std::string& s : bad) {
    std::size_t offset = 0;
    EXPECT_EQ(decode_utf8(s, &offset), 0xFFFDu) << s.size();
    EXPECT_EQ(offset, 1u);
  }
  for (char32_t cp : {char32_t{0x41}, char32_t{0x412}, char32_t{0xE0F1}, char32_t{0x1F600}}) {
    std::string s;
    append_utf8(&s, cp);
    std::size_t offset = 0;
    EXPECT_EQ(decode_utf8(s, &offset), cp);
    EXPECT_EQ(offset, s.size());
  }
  EXPECT_EQ(code_point_label(0xE0FF), "U+E0FF");
}

TEST(TextPosition, SplitLinesKeepsEveryLineAndItsNumber) {
  const std::string_view text = "a = 1\n\n  b = 2\nlast";
  const std::vector<TextLine> lines = split_lines(text);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(text.substr(lines[0].start, lines[0].end - lines[0].start), "a = 1");
  EXPECT_EQ(lines[1].start, lines[1].end);  // the empty line
  EXPECT_EQ(text.substr(lines[3].start, lines[3].end - lines[3].start), "last");
  for (std::size_t i = 0; i < lines.size(); ++i) EXPECT_EQ(lines[i].number, static_cast<int>(i) + 1);
  // A final '\n' opens an empty last line; an empty text is one empty line.
  EXPECT_EQ(split_lines("x\n").size(), 2u);
  ASSERT_EQ(split_lines("").size(), 1u);
  EXPECT_EQ(split_lines("")[0].end, 0u);
}

}  // namespace
}  // namespace sw::notation

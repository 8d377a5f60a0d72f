// Phrase text: notation or fingerspelling -> phrase items (phrase_text.h).
#include "synthesis/phrase_text.h"

#include <nlohmann/json.hpp>

#include "notation/parse.h"
#include "text/utf8.h"

namespace sw::synthesis {
namespace {

// Decodes one UTF-8 code point at text[i]; returns its byte length (1 for invalid bytes).
int utf8_next(std::string_view text, size_t i, char32_t* cp) {
  unsigned char c = static_cast<unsigned char>(text[i]);
  int len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 1;
  if (i + len > text.size()) len = 1;
  if (len == 1) {
    *cp = c;
    return 1;
  }
  char32_t v = c & (0x7F >> len);
  for (int k = 1; k < len; ++k) v = (v << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
  *cp = v;
  return len;
}

std::string utf8_encode(char32_t cp) {
  std::string s;
  sw::text::append_utf8(&s, cp);
  return s;
}

char32_t upper(char32_t c) {
  if (c >= 'a' && c <= 'z') return c - 32;
  if (c >= 0x0430 && c <= 0x044F) return c - 0x20;  // а..я
  if (c >= 0x0450 && c <= 0x045F) return c - 0x50;  // ѐ..џ: і ї є ...
  if (c == 0x0491) return 0x0490;                   // ґ
  return c;
}

bool is_punctuation(char32_t c) {
  return c == '.' || c == ',' || c == '!' || c == '?' || c == ';' || c == ':' || c == 0x2026;
}
bool is_space(char32_t c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

std::string upper_letter(std::string_view s) {
  std::string out;
  for (size_t i = 0; i < s.size();) {
    char32_t cp;
    i += utf8_next(s, i, &cp);
    out += utf8_encode(upper(cp));
  }
  return out;
}

bool parse_alphabet_jsonl(std::string_view text, std::vector<AlphabetEntry>* out, std::string* error) {
  size_t pos = 0;
  int line_no = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("letter") || !j.contains("notation") ||
        !j["letter"].is_string() || !j["notation"].is_string()) {
      *error = "line " + std::to_string(line_no) + ": expected {\"letter\": ..., \"notation\": ...}";
      return false;
    }
    AlphabetEntry e;
    e.letter = upper_letter(j["letter"].get<std::string>());
    e.notation = j["notation"].get<std::string>();
    if (j.contains("format") && j["format"].is_string()) e.format = j["format"].get<std::string>();
    out->push_back(std::move(e));
  }
  return true;
}

PhraseText phrase_from_text(std::string_view text, const std::vector<AlphabetEntry>& alphabet) {
  PhraseText out;
  notation::ParseOutcome parsed = notation::parse_notation(text, notation::detect_format(text));
  if (parsed.ok() && !parsed.signs.empty()) {
    for (size_t i = 0; i < parsed.signs.size(); ++i) {
      PhraseItem it;
      it.kind = PhraseItem::Kind::Sign;
      it.sign = parsed.signs[i];
      it.label = parsed.signs[i].gloss;
      it.word_index = static_cast<int>(i);
      out.items.push_back(std::move(it));
    }
    return out;
  }
  if (alphabet.empty()) {
    std::string why = parsed.diagnostics.empty() ? "no sign in the text" : notation::format_diagnostic(parsed.diagnostics[0]);
    out.errors.push_back({"text", "not notation (" + why + ") and no fingerspelling alphabet is available"});
    return out;
  }
  // Fingerspell: the longest alphabet entry matching at each position (digits like "10").
  out.fingerspelled = true;
  int word = -1;
  bool in_word = false;
  for (size_t i = 0; i < text.size();) {
    char32_t cp;
    int len = utf8_next(text, i, &cp);
    if (is_space(cp)) {
      in_word = false;
      i += len;
      continue;
    }
    if (is_punctuation(cp)) {
      PhraseItem p;
      p.kind = PhraseItem::Kind::Pause;
      p.label = std::string(text.substr(i, len));
      p.word_index = word;
      out.items.push_back(p);
      in_word = false;
      i += len;
      continue;
    }
    if (!in_word) {
      ++word;
      in_word = true;
    }
    const AlphabetEntry* best = nullptr;
    size_t best_len = 0;
    for (const auto& e : alphabet) {
      // Compare upper-cased text of the same byte length as the entry's letter.
      size_t probe = 0, j = i;
      std::string up;
      while (j < text.size() && up.size() < e.letter.size()) {
        char32_t c2;
        int l2 = utf8_next(text, j, &c2);
        up += utf8_encode(upper(c2));
        j += l2;
        probe = j - i;
      }
      if (up == e.letter && probe > best_len) {
        best = &e;
        best_len = probe;
      }
    }
    if (!best) {
      out.errors.push_back({"text, byte " + std::to_string(i),
                            "no fingerspelling for '" + std::string(text.substr(i, len)) + "' in the alphabet"});
      i += len;
      continue;
    }
    notation::NotationFormat fmt = notation::NotationFormat::Formula;
    notation::format_from_name(best->format, &fmt);
    notation::ParseOutcome letter = notation::parse_notation(best->notation, fmt);
    if (!letter.ok() || letter.signs.empty()) {
      out.errors.push_back({"alphabet letter '" + best->letter + "'",
                            letter.diagnostics.empty() ? "no sign" : notation::format_diagnostic(letter.diagnostics[0])});
    } else {
      PhraseItem it;
      it.kind = PhraseItem::Kind::Letter;
      it.sign = letter.signs[0];
      it.label = best->letter;
      it.word_index = word;
      out.items.push_back(std::move(it));
    }
    i += best_len;
  }
  return out;
}

}  // namespace sw::synthesis

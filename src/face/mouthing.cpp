#include "face/mouthing.h"

#include <algorithm>
#include <cctype>
#include <cstdint>

namespace sw::face {
namespace {

int viseme(const char* name) { return channel_index(name); }

// Decodes one UTF-8 code point; advances i. Invalid bytes decode as U+FFFD and advance by one.
std::uint32_t next_code_point(std::string_view s, std::size_t& i) {
  const auto c = static_cast<unsigned char>(s[i]);
  int extra = 0;
  std::uint32_t cp = c;
  if (c >= 0xF0) {
    extra = 3;
    cp = c & 0x07;
  } else if (c >= 0xE0) {
    extra = 2;
    cp = c & 0x0F;
  } else if (c >= 0xC0) {
    extra = 1;
    cp = c & 0x1F;
  } else if (c >= 0x80) {
    ++i;
    return 0xFFFD;
  }
  if (extra > 0 && i + std::size_t(extra) >= s.size()) {
    ++i;
    return 0xFFFD;
  }
  for (int k = 1; k <= extra; ++k) {
    const auto cc = static_cast<unsigned char>(s[i + std::size_t(k)]);
    if ((cc & 0xC0) != 0x80) {
      ++i;
      return 0xFFFD;
    }
    cp = (cp << 6) | (cc & 0x3F);
  }
  i += std::size_t(extra) + 1;
  return cp;
}

// Cyrillic letters (Ukrainian and Russian) -> viseme names.
const char* cyrillic_viseme(std::uint32_t cp) {
  if (cp >= 0x0410 && cp <= 0x042F) cp += 0x20;  // upper -> lower (basic block)
  switch (cp) {
    case 0x0430:
    case 0x044F:
      return "viseme_aa";  // а я
    case 0x0435:
    case 0x0454:
    case 0x044D:
    case 0x0451:
      return "viseme_E";  // е є э ё
    case 0x0438:
    case 0x0456:
    case 0x0457:
    case 0x0439:
    case 0x044B:
      return "viseme_I";
    case 0x043E:
      return "viseme_O";  // о
    case 0x0443:
    case 0x044E:
      return "viseme_U";  // у ю
    case 0x043F:
    case 0x0431:
    case 0x043C:
      return "viseme_PP";  // п б м
    case 0x0444:
    case 0x0432:
      return "viseme_FF";  // ф в
    case 0x0442:
    case 0x0434:
      return "viseme_DD";  // т д
    case 0x043A:
    case 0x0433:
    case 0x0491:
    case 0x0445:
      return "viseme_kk";  // к г ґ х
    case 0x0447:
    case 0x0448:
    case 0x0449:
    case 0x0436:
      return "viseme_CH";  // ч ш щ ж
    case 0x0441:
    case 0x0437:
    case 0x0446:
      return "viseme_SS";  // с з ц
    case 0x043D:
    case 0x043B:
      return "viseme_nn";  // н л
    case 0x0440:
      return "viseme_RR";  // р
    default:
      return nullptr;
  }
}

// Latin spelling and SAMPA share most letters; SAMPA's vowel symbols (@ { V E I O U Q 3) are
// read as the vowel they write.
const char* latin_viseme(char c) {
  switch (c) {
    case 'a':
    case 'A':
    case '{':
    case 'V':
      return "viseme_aa";
    case 'e':
    case 'E':
    case '@':
    case '3':
      return "viseme_E";
    case 'i':
    case 'I':
    case 'y':
    case 'Y':
    case 'j':
      return "viseme_I";
    case 'o':
    case 'O':
    case 'Q':
      return "viseme_O";
    case 'u':
    case 'U':
    case 'w':
    case 'W':
      return "viseme_U";
    case 'p':
    case 'P':
    case 'b':
    case 'B':
    case 'm':
    case 'M':
      return "viseme_PP";
    case 'f':
    case 'F':
    case 'v':
      return "viseme_FF";
    case 'T':
    case 'D':
      return "viseme_TH";
    case 't':
    case 'd':
      return "viseme_DD";
    case 'k':
    case 'K':
    case 'g':
    case 'G':
    case 'c':
    case 'C':
    case 'q':
    case 'x':
    case 'N':
      return "viseme_kk";
    case 'S':
    case 'Z':
    case 'J':
      return "viseme_CH";
    case 's':
    case 'z':
      return "viseme_SS";
    case 'n':
    case 'l':
    case 'L':
      return "viseme_nn";
    case 'r':
    case 'R':
      return "viseme_RR";
    default:
      return nullptr;  // h, apostrophes, digits, punctuation: no distinct mouth shape
  }
}

bool is_vowel_viseme(int channel) {
  return channel == viseme("viseme_aa") || channel == viseme("viseme_E") ||
         channel == viseme("viseme_I") || channel == viseme("viseme_O") ||
         channel == viseme("viseme_U");
}

}  // namespace

std::vector<int> visemes_of_word(std::string_view text) {
  std::vector<int> out;
  auto push = [&](const char* name) {
    const int v = viseme(name);
    // A doubled letter is one phoneme ("hello", "ee"): keep one key.
    if (v >= 0 && (out.empty() || out.back() != v)) out.push_back(v);
  };
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      const std::uint32_t cp = next_code_point(text, i);
      if (const char* name = cyrillic_viseme(cp)) push(name);
      continue;
    }
    const char lower = static_cast<char>(std::tolower(c));
    const char next = i + 1 < text.size()
                          ? static_cast<char>(std::tolower(static_cast<unsigned char>(text[i + 1])))
                          : '\0';
    // Digraphs: English spelling th/sh/ch/ph/ng and SAMPA tS/dZ.
    if (lower == 't' && next == 'h') {
      push("viseme_TH");
      i += 2;
      continue;
    }
    if ((lower == 's' || lower == 'c') && next == 'h') {
      push("viseme_CH");
      i += 2;
      continue;
    }
    if (lower == 'p' && next == 'h') {
      push("viseme_FF");
      i += 2;
      continue;
    }
    if (lower == 'n' && next == 'g') {
      push("viseme_kk");
      i += 2;
      continue;
    }
    if ((text[i] == 't' || text[i] == 'd') && i + 1 < text.size() &&
        (text[i + 1] == 'S' || text[i + 1] == 'Z')) {
      push("viseme_CH");
      i += 2;
      continue;
    }
    if (const char* name = latin_viseme(text[i])) push(name);
    ++i;
  }
  return out;
}

std::vector<VisemeKey> schedule_mouthing(std::string_view text, double start_s, double end_s) {
  std::vector<VisemeKey> keys;
  const std::vector<int> sequence = visemes_of_word(text);
  if (sequence.empty() || end_s <= start_s) return keys;
  const int silence = viseme("viseme_sil");
  // Rest, one key per phoneme evenly spread, rest (seed 000: before motion ... back at rest).
  const double step = (end_s - start_s) / double(sequence.size() + 1);
  keys.push_back(VisemeKey{silence, start_s, 1.0f});
  for (std::size_t k = 0; k < sequence.size(); ++k) {
    const float peak = is_vowel_viseme(sequence[k]) ? 1.0f : 0.8f;
    keys.push_back(VisemeKey{sequence[k], start_s + step * double(k + 1), peak});
  }
  keys.push_back(VisemeKey{silence, end_s, 1.0f});
  return keys;
}

ChannelWeights sample_mouthing(const std::vector<VisemeKey>& keys, double t_s) {
  ChannelWeights out;
  if (keys.empty() || t_s <= keys.front().time_s || t_s >= keys.back().time_s) return out;
  // Find the bracketing keys; the two visemes cross-fade linearly between their peaks.
  for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
    const VisemeKey& a = keys[k];
    const VisemeKey& b = keys[k + 1];
    if (t_s < a.time_s || t_s > b.time_s) continue;
    const double span = b.time_s - a.time_s;
    const float mu = span > 0.0 ? static_cast<float>((t_s - a.time_s) / span) : 1.0f;
    out[a.channel] = std::max(out[a.channel], (1.0f - mu) * a.weight);
    out[b.channel] = std::max(out[b.channel], mu * b.weight);
    break;
  }
  return out;
}

}  // namespace sw::face

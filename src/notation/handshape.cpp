// HamNoSys-style handshape descriptions -> per-finger configurations (see handshape.h).
//
// The base shapes follow the HamNoSys 4 handshape chart: which fingers are "selected" (extended
// or forming the shape) and where the thumb is by default; modifiers then change the thumb, the
// bending of the selected fingers, or of the fingers named after a finger symbol.
#include "notation/handshape.h"

#include <array>
#include <cmath>
#include <cstring>

#include "notation/hamnosys_symbols.h"

namespace sw::notation {
namespace {

struct Alias {
  char32_t word;
  const char* alias;
};
// The formula's friendly names (docs/NOTATION.md, H(...)).
constexpr Alias kAliases[] = {
    {hamfist, "fist"},
    {hamflathand, "flat"},
    {hamfinger2, "finger2"},
    {hamfinger23, "finger23"},
    {hamfinger23spread, "finger23spread"},
    {hamfinger2345, "finger2345"},
    {hampinch12, "pinch12"},
    {hampinchall, "pinchall"},
    {hampinch12open, "pinch12open"},
    {hamcee12, "cee12"},
    {hamceeall, "ceeall"},
    {hamceeopen, "ceeopen"},
    {hamthumboutmod, "thumbout"},
    {hamthumbacrossmod, "thumbacross"},
    {hamthumbopenmod, "thumbopen"},
    {hamfingerstraightmod, "straight"},
    {hamfingerbendmod, "bent"},
    {hamfingerhookmod, "hooked"},
    {hamdoublebent, "doublebent"},
    {hamdoublehooked, "doublehooked"},
    {hambetween, "between"},
    {hamthumb, "thumb"},
    {hamindexfinger, "index"},
    {hammiddlefinger, "middle"},
    {hamringfinger, "ring"},
    {hampinky, "little"},
    {hamfingertip, "tip"},
    {hamfingernail, "nail"},
    {hamfingerpad, "pad"},
    {hamfingermidjoint, "middle_joint"},
    {hamfingerbase, "base"},
    {hamfingerside, "side"},
    {kShapeRound, "round"},
    {kShapeSpread, "spread"},
    {kShapeCrossed, "crossed"},
    {kShapeThumbOn2, "thumbon2"},
    {kShapeThumbOn3, "thumbon3"},
    {kShapeThumbOn4, "thumbon4"},
    {kShapeThumbOn5, "thumbon5"},
};

bool is_extra(char32_t w) {
  return w == kShapeRound || w == kShapeSpread || w == kShapeCrossed ||
         (w >= kShapeThumbOn2 && w <= kShapeThumbOn5);
}
bool is_digit_symbol(char32_t w) { return w >= hamthumb && w <= hampinky; }
bool is_finger_part(char32_t w) { return w >= hamfingertip && w <= hamfingerside; }
bool is_bending(char32_t w) {
  return (w >= hamfingerstraightmod && w <= hamdoublehooked) || w == kShapeRound;
}
bool is_thumb_mod(char32_t w) { return w >= hamthumboutmod && w <= hamthumbopenmod; }

FingerConfig seed_state(float t) {  // F_0^k(t): pressed (0) -> straight (1)
  FingerConfig c;
  c.id = 0;
  c.has_t = true;
  c.t = t;
  return c;
}
FingerConfig fixed_state(int id) {
  FingerConfig c;
  c.id = id;
  return c;
}

using Fingers = std::array<FingerConfig, kFingerCount>;
using FingerMask = std::array<bool, kFingerCount>;

// Fingers named after a base handshape and its modifiers with no bending after them take the
// place of the base's selected fingers (HamNoSys 4 / G-SiGML specialfingers: "hamfinger2
// hammiddlefinger" is the middle finger extended in the index's place, not both): a selected
// finger that is not named closes. `named` null: no such trailing digits. Only for the bases
// that select some of the four fingers (finger2, finger23, pinch12, cee12, ...): after a flat
// hand or a fist the digits name the fingers the hand is read with, as before.
void take_the_selected_fingers_place(const FingerMask& selected, const FingerMask* named, Fingers* f) {
  if (!named) return;
  int count = 0;
  for (int k = 1; k < kFingerCount; ++k) count += selected[k] ? 1 : 0;
  if (count == 0 || count >= 4) return;
  for (int k = 1; k < kFingerCount; ++k) {
    if (selected[k] && !(*named)[k]) (*f)[k] = seed_state(0.0f);
  }
}

// Base shape: fingers and the selected set the bending modifiers apply to.
void base_shape(char32_t base, Fingers* f, FingerMask* selected) {
  const FingerConfig pressed = seed_state(0.0f), straight = seed_state(1.0f);
  const FingerConfig round = fixed_state(kFingerRound), spread = fixed_state(kFingerSpread);
  selected->fill(false);
  for (int k = 1; k < kFingerCount; ++k) (*f)[k] = pressed;
  auto select = [&](std::initializer_list<int> ks, const FingerConfig& c) {
    for (int k : ks) (*f)[k] = c, (*selected)[k] = true;
  };
  switch (base) {
    case hamfist:  // A: fingers closed, thumb alongside the index (hamthumbacrossmod gives S)
      (*f)[0] = fixed_state(kThumbAlongside);
      break;
    case hamflathand:  // B: fingers straight together, thumb alongside
      (*f)[0] = fixed_state(kThumbAlongside);
      select({1, 2, 3, 4}, straight);
      break;
    case hamfinger2:
      (*f)[0] = fixed_state(kThumbAgainstPalm);
      select({1}, straight);
      break;
    case hamfinger23:
      (*f)[0] = fixed_state(kThumbAgainstPalm);
      select({1, 2}, straight);
      break;
    case hamfinger23spread:  // V: seed F_2^3, middle spread from the index
      (*f)[0] = fixed_state(kThumbAgainstPalm);
      select({1}, straight);
      select({2}, spread);
      break;
    case hamfinger2345:  // 4: all four straight and spread
      (*f)[0] = fixed_state(kThumbAgainstPalm);
      select({1}, straight);
      select({2, 3, 4}, spread);
      break;
    case hampinch12:  // thumb pad on the index tip (seed F_1^1), others closed
      (*f)[0] = fixed_state(kThumbPadOnIndex);
      select({1}, round);
      break;
    case hampinchall:  // all fingertips on the thumb (flat O)
      (*f)[0] = fixed_state(kThumbPadOnIndex);
      select({1, 2, 3, 4}, round);
      break;
    case hampinch12open:  // F / 9: thumb-index pinch, the others extended
      (*f)[0] = fixed_state(kThumbPadOnIndex);
      select({1}, round);
      for (int k : {2, 3, 4}) (*f)[k] = straight;
      break;
    case hamcee12:  // thumb and index form a C, others closed
      (*f)[0] = fixed_state(kThumbOpposed);
      select({1}, round);
      break;
    case hamceeall:  // C
      (*f)[0] = fixed_state(kThumbOpposed);
      select({1, 2, 3, 4}, round);
      break;
    default:  // hamceeopen: C of thumb and index, the others extended
      (*f)[0] = fixed_state(kThumbOpposed);
      select({1}, round);
      for (int k : {2, 3, 4}) (*f)[k] = straight;
      break;
  }
}

FingerConfig bending_config(char32_t w, const FingerConfig& old) {
  FingerConfig c;
  switch (w) {
    case hamfingerstraightmod: c = seed_state(1.0f); break;
    case hamfingerbendmod: c = fixed_state(kFingerHorizontal); break;
    case hamfingerhookmod: c = fixed_state(kFingerHooked); break;
    case hamdoublebent: c = fixed_state(kFingerDoubleBent); break;
    case hamdoublehooked: c = fixed_state(kFingerDoubleHooked); break;
    default: c = fixed_state(kFingerRound); break;
  }
  c.spread = old.id == kFingerSpread ? 1.0f : old.spread;  // bending keeps the fingers apart
  return c;
}

std::string describe_word(const std::vector<char32_t>& words, std::size_t i) {
  if (i >= words.size()) return "the end of the handshape";
  const std::string name = shape_word_name(words[i]);
  return name.empty() ? "an unknown symbol" : "'" + name + "'";
}

// Parses one shape (base and modifiers) starting at *i; stops before hambetween or at the end.
bool build_one(const std::vector<char32_t>& words, std::size_t* i, Fingers* f, ShapeError* error) {
  if (*i >= words.size() || !is_shape_base(words[*i])) {
    error->word_index = *i;
    error->message = "expected a handshape base (hamfist, hamflathand, hamfinger2, hamfinger23, "
                     "hamfinger23spread, hamfinger2345, hampinch12, hampinchall, hampinch12open, "
                     "hamcee12, hamceeall, hamceeopen), found " + describe_word(words, *i);
    return false;
  }
  FingerMask selected{};
  base_shape(words[*i], f, &selected);
  ++*i;
  FingerMask named{};  // fingers named by digit symbols since the last modifier
  bool any_named = false;
  auto scope = [&]() {
    FingerMask m = any_named ? named : selected;
    bool any = false;
    for (int k = 1; k < kFingerCount; ++k) any = any || m[k];
    if (!any) m = {false, true, true, true, true};  // a fist with a bending: all four fingers
    return m;
  };
  while (*i < words.size() && words[*i] != hambetween) {
    const char32_t w = words[*i];
    if (is_thumb_mod(w)) {
      (*f)[0] = fixed_state(w == hamthumboutmod    ? kThumbOut
                            : w == hamthumbacrossmod ? kThumbAcross
                                                     : kThumbOpposed);
    } else if (is_bending(w)) {
      const FingerMask m = scope();
      for (int k = 1; k < kFingerCount; ++k) {
        if (m[k]) (*f)[k] = bending_config(w, (*f)[k]);
      }
      named.fill(false), any_named = false;
    } else if (w == kShapeSpread) {
      const FingerMask m = scope();
      for (int k = 1; k < kFingerCount; ++k) {
        if (!m[k]) continue;
        FingerConfig& c = (*f)[k];
        if ((c.id == kFingerPressedToStraight && c.t >= 1.0f) || c.id == kFingerSpread) {
          c = fixed_state(kFingerSpread);  // seed F_2^k: straight and spread
        } else {
          c.spread = 1.0f;
        }
      }
      named.fill(false), any_named = false;
    } else if (w == kShapeCrossed) {
      (*f)[static_cast<int>(Finger::Middle)] = fixed_state(kFingerCrossed);  // seed F_3^3
    } else if (w >= kShapeThumbOn2 && w <= kShapeThumbOn5) {
      const int k = static_cast<int>(w - kShapeThumbOn2) + 2;
      (*f)[0] = fixed_state(k == 2 ? kThumbPadOnIndex : kThumbOnMiddle + (k - 3));
    } else if (is_digit_symbol(w)) {
      const int k = static_cast<int>(w - hamthumb);
      // A digit followed by a finger part says which finger the thumb touches (hamindexfinger
      // hamfingerpad: thumb on the index); otherwise it names the fingers the next bending is for.
      if (*i + 1 < words.size() && is_finger_part(words[*i + 1])) {
        if (k >= 1) (*f)[0] = fixed_state(k == 1 ? kThumbPadOnIndex : kThumbOnMiddle + (k - 2));
        ++*i;
      } else if (k >= 1) {
        named[k] = true, any_named = true;
        if ((*f)[k].id == kFingerPressedToStraight && (*f)[k].t <= 0.0f) {
          (*f)[k] = seed_state(1.0f);  // a named closed finger is extended as well
        }
      }
    } else if (is_finger_part(w)) {
      // A part without a digit refines the previous contact; it carries no finger state.
    } else {
      error->word_index = *i;
      error->message = "expected a handshape modifier (thumb, bending, finger) or hambetween, "
                       "found " + describe_word(words, *i);
      return false;
    }
    ++*i;
  }
  take_the_selected_fingers_place(selected, any_named ? &named : nullptr, f);
  return true;
}

}  // namespace

std::string shape_word_name(char32_t word) {
  if (is_extra(word)) {
    for (const Alias& a : kAliases) {
      if (a.word == word) return a.alias;
    }
  }
  return ham_symbol_name(word);
}

bool shape_word_from_name(std::string_view name, char32_t* word) {
  if (const HamSymbolInfo* s = ham_symbol_by_name(name); s && is_shape_word(s->code)) {
    *word = s->code;
    return true;
  }
  for (const Alias& a : kAliases) {
    if (name == a.alias) {
      *word = a.word;
      return true;
    }
  }
  return false;
}

const char* shape_word_alias(char32_t word) {
  for (const Alias& a : kAliases) {
    if (a.word == word) return a.alias;
  }
  return "";
}

bool is_shape_base(char32_t w) { return w >= hamfist && w <= hamceeopen; }

bool is_shape_word(char32_t w) {
  return is_shape_base(w) || is_thumb_mod(w) || is_bending(w) || is_extra(w) ||
         is_digit_symbol(w) || is_finger_part(w) || w == hambetween;
}

bool build_handshape(const std::vector<char32_t>& words, HandShape* shape, ShapeError* error) {
  std::size_t i = 0;
  Fingers first{};
  if (!build_one(words, &i, &first, error)) return false;
  if (i < words.size()) {  // hambetween: a shape between two shapes
    ++i;
    Fingers second{};
    if (!build_one(words, &i, &second, error)) return false;
    // Between two seed states F_0^k(t1), F_0^k(t2) the finger is half-way (seed eq. (4)
    // interpolation); where the states differ in kind the first shape's state is kept.
    for (int k = 0; k < kFingerCount; ++k) {
      if (first[k].has_t && second[k].has_t && first[k].id == second[k].id) {
        first[k].t = 0.5f * (first[k].t + second[k].t);
      }
    }
  }
  shape->fingers = first;
  shape->hamnosys_base = join_shape_words(words);
  return true;
}

namespace {
bool same_finger(const FingerConfig& a, const FingerConfig& b) {
  return a.id == b.id && a.has_t == b.has_t && a.t == b.t && a.spread == b.spread;
}
bool same_fingers(const HandShape& a, const HandShape& b) {
  for (int k = 0; k < kFingerCount; ++k) {
    if (!same_finger(a.fingers[k], b.fingers[k])) return false;
  }
  return true;
}
}  // namespace

// The handshape's words: its own (when they still build these fingers) or the closest base +
// thumb + bending combination.
std::vector<char32_t> handshape_words(const HandShape& shape) {
  std::vector<char32_t> words;
  if (!shape.hamnosys_base.empty() && split_shape_words(shape.hamnosys_base, &words)) {
    HandShape built;
    ShapeError error;
    bool only_ham = true;
    for (char32_t w : words) only_ham = only_ham && ham_symbol_by_code(w) != nullptr;
    if (only_ham && build_handshape(words, &built, &error) && same_fingers(built, shape)) return words;
  }
  std::vector<char32_t> best;
  int best_score = -1;
  const char32_t thumbs[] = {0, hamthumboutmod, hamthumbacrossmod, hamthumbopenmod};
  const char32_t bends[] = {0, hamfingerstraightmod, hamfingerbendmod, hamfingerhookmod,
                            hamdoublebent, hamdoublehooked};
  for (char32_t base = hamfist; base <= hamceeopen; ++base) {
    for (char32_t thumb : thumbs) {
      for (char32_t bend : bends) {
        std::vector<char32_t> candidate{base};
        if (thumb) candidate.push_back(thumb);
        if (bend) candidate.push_back(bend);
        HandShape built;
        ShapeError error;
        if (!build_handshape(candidate, &built, &error)) continue;
        int score = 0;
        for (int k = 0; k < kFingerCount; ++k) {
          const FingerConfig& a = built.fingers[k];
          const FingerConfig& b = shape.fingers[k];
          score += (a.id == b.id ? 2 : 0) + (std::abs(a.t - b.t) < 0.26f ? 1 : 0);
        }
        if (score > best_score) best_score = score, best = candidate;
      }
    }
  }
  return best;
}


std::string join_shape_words(const std::vector<char32_t>& words) {
  std::string out;
  for (char32_t w : words) {
    if (!out.empty()) out += ',';
    out += shape_word_name(w);
  }
  return out;
}

bool split_shape_words(std::string_view text, std::vector<char32_t>* words) {
  words->clear();
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view name = text.substr(start, end - start);
    if (!name.empty()) {
      char32_t w = 0;
      if (!shape_word_from_name(name, &w)) return false;
      words->push_back(w);
    }
    start = end + 1;
  }
  return true;
}

}  // namespace sw::notation

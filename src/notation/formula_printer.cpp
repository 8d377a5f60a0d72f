// Printer of the formula notation (docs/NOTATION.md): writes exactly what formula_parser.cpp
// reads, omitting what equals the reader's default, so parse(print(x)) == x.
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <string>
#include <vector>

#include "notation/formula.h"
#include "notation/seed_places.h"
#include "notation/handshape.h"
#include "notation/sign_spec_names.h"

namespace sw::notation {
namespace {


bool same_finger(const FingerConfig& a, const FingerConfig& b) {
  return a.id == b.id && a.has_t == b.has_t && a.t == b.t && a.spread == b.spread;
}

std::string finger_item(int k, const FingerConfig& c) {
  std::string s = "F_" + std::to_string(c.id) + "^" + std::to_string(k + 1);
  if (c.has_t) {
    s += "(" + format_float(c.t);
    if (c.spread != 0.0f) s += ", " + format_float(c.spread);
    s += ")";
  } else if (c.spread != 0.0f) {
    s += "(s=" + format_float(c.spread) + ")";
  }
  return s;
}

// H(words) for the base (when the shape has one that still builds), then the fingers that
// differ from it; without a base, all five fingers as the seed writes them.
void shape_items(const HandShape& shape, std::vector<std::string>* items) {
  HandShape from_base;
  bool have_base = false;
  std::vector<char32_t> words;
  if (!shape.hamnosys_base.empty() && split_shape_words(shape.hamnosys_base, &words)) {
    ShapeError error;
    have_base = build_handshape(words, &from_base, &error);
  }
  if (have_base) {
    std::string h = "H(";
    for (std::size_t i = 0; i < words.size(); ++i) {
      const char* alias = shape_word_alias(words[i]);
      h += (i ? ", " : "") + (alias[0] ? std::string(alias) : shape_word_name(words[i]));
    }
    items->push_back(h + ")");
  }
  for (int k = 0; k < kFingerCount; ++k) {
    if (!have_base || !same_finger(shape.fingers[k], from_base.fingers[k])) {
      items->push_back(finger_item(k, shape.fingers[k]));
    }
  }
}

std::string direction_arg(const Direction& d) { return d.is_zero() ? "0" : direction_word(d); }

bool is_default_location(const Location& l) {
  const Location d;
  return l.kind == d.kind && l.level == d.level && l.side == d.side && l.contact == d.contact &&
         l.seed_id == 0;
}

std::string location_item(const Location& l) {
  if (l.seed_id >= 1 && l.seed_id <= static_cast<int>(std::size(kSeedPlaces)) &&
      l.kind != Location::Kind::OtherHand && kSeedPlaces[l.seed_id - 1].level == l.level &&
      kSeedPlaces[l.seed_id - 1].side == l.side &&
      (l.contact == Contact::None || l.contact == Contact::Touch)) {
    return "L" + std::to_string(l.seed_id) + "(" + (l.contact == Contact::Touch ? "1" : "0") + ")";
  }
  std::string s = "Loc(";
  if (l.kind == Location::Kind::OtherHand) {
    s += std::string("hand, ") + name_of(l.hand_place);
    if (l.finger >= 0) s += ", " + std::to_string(l.finger + 1);
    if (l.side != Side::Centre) s += std::string(", ") + name_of(l.side);
  } else {
    const BodyLevel level = l.kind == Location::Kind::NeutralSpace ? BodyLevel::NeutralSpace : l.level;
    s += std::string(name_of(level)) + ", " + name_of(l.side);
  }
  if (l.contact != Contact::None) s += std::string(", ") + name_of(l.contact);
  return s + ")";
}

void orientation_items(const Orientation& o, bool always_both, std::vector<std::string>* items) {
  const Orientation d;
  if (o.seed_palm != SeedPalm::None) items->push_back(name_of(o.seed_palm));
  if (always_both || o.extended_finger != d.extended_finger) {
    items->push_back("E(" + direction_arg(o.extended_finger) + ")");
  }
  if (always_both || o.palm != d.palm) items->push_back("P(" + direction_arg(o.palm) + ")");
}

std::string movement_item(const Movement& m) {
  std::vector<std::string> args{name_of(m.kind)};
  if (!m.direction.is_zero()) args.push_back(direction_word(m.direction));
  if (!m.arc_bulge.is_zero()) args.push_back("bulge=" + direction_word(m.arc_bulge));
  if (!m.circle_axis.is_zero()) args.push_back("axis=" + direction_word(m.circle_axis));
  if (!m.ellipse_axis.is_zero()) args.push_back("ellipse=" + direction_word(m.ellipse_axis));
  if (m.clockwise) args.push_back("cw");
  if (m.size != Size::Normal) args.push_back(name_of(m.size));
  if (m.manner != Manner::Normal) args.push_back(name_of(m.manner));
  if (m.alternating) args.push_back("alt");
  if (m.to_shape) {
    std::vector<std::string> shape;
    shape_items(*m.to_shape, &shape);
    args.insert(args.end(), shape.begin(), shape.end());
  }
  if (m.to_orientation) orientation_items(*m.to_orientation, true, &args);
  if (m.to_location) args.push_back(location_item(*m.to_location));
  std::string s = "M(";
  for (std::size_t i = 0; i < args.size(); ++i) s += (i ? ", " : "") + args[i];
  return s + ")";
}

std::string step_item(const std::vector<Movement>& ms) {
  if (ms.size() == 1) return movement_item(ms[0]);
  std::string s = "Par(";
  for (std::size_t i = 0; i < ms.size(); ++i) s += (i ? ", " : "") + movement_item(ms[i]);
  return s + ")";
}

std::string quoted_if_needed(const std::string& v) {
  bool plain = !v.empty() && ((v[0] >= 'A' && v[0] <= 'Z') || (v[0] >= 'a' && v[0] <= 'z') || v[0] == '_');
  for (char c : v) {
    plain = plain && ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_');
  }
  if (plain) return v;
  std::string s = "\"";
  for (char c : v) {
    if (c == '"' || c == '\\') s += '\\';
    s += (c == '\n' || c == '\r') ? ' ' : c;  // a sign is one line
  }
  return s + "\"";
}

std::string hand_term(const char* letter, const HandSpec* hand, const SignSpec& sign, bool left) {
  std::vector<std::string> items;
  if (hand) {
    shape_items(hand->shape, &items);
    orientation_items(hand->orientation, false, &items);
    if (!is_default_location(hand->location)) items.push_back(location_item(hand->location));
    if (hand->location.contact_part) {
      std::string c = std::string("C(") + name_of(*hand->location.contact_part);
      if (hand->location.contact_finger >= 0) c += ", " + std::to_string(hand->location.contact_finger + 1);
      items.push_back(c + ")");
    }
  }
  if (left && sign.nondominant_is_place) items.push_back("place");
  for (const MovementStep& step : sign.movements) {
    items.push_back(step_item(left ? step.nondominant : step.dominant));
  }
  // Trailing empty steps of this hand say nothing: drop them.
  while (!items.empty() && items.back() == "Par()") items.pop_back();
  std::string s = std::string(letter) + "(";
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + items[i];
  return s + ")";
}

}  // namespace

std::string direction_word(const Direction& d) {
  std::string s;
  if (d.y > 0) s += 'u';
  if (d.y < 0) s += 'd';
  if (d.z > 0) s += 'o';
  if (d.z < 0) s += 'i';
  if (d.x > 0) s += 'l';
  if (d.x < 0) s += 'r';
  return s;
}

std::string format_float(float value) {
  char buffer[32];
  for (int precision = 1; precision <= 9; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, static_cast<double>(value));
    if (std::strtof(buffer, nullptr) == value) break;
  }
  return buffer;
}

std::string print_formula(const SignSpec& sign) {
  std::string s = hand_term("R", &sign.dominant, sign, false);
  bool left_moves = false;
  for (const MovementStep& step : sign.movements) left_moves = left_moves || !step.nondominant.empty();
  if (sign.nondominant || left_moves || sign.nondominant_is_place) {
    s += " " + hand_term("L", sign.nondominant ? &*sign.nondominant : nullptr, sign, true);
  }
  if (sign.symmetry != Symmetry::None) s += std::string(" Sym(") + name_of(sign.symmetry) + ")";
  if (sign.repetition.kind != RepeatKind::None) {
    s += std::string(" Rep(") + name_of(sign.repetition.kind);
    if (sign.repetition.count != 1) s += ", " + std::to_string(sign.repetition.count);
    s += ")";
  }
  const NonManual& n = sign.nonmanual;
  std::vector<std::string> nm;
  if (!n.mouthing.empty()) nm.push_back("mouth=" + quoted_if_needed(n.mouthing));
  if (!n.mouth_gesture.empty()) nm.push_back("mouthgesture=" + quoted_if_needed(n.mouth_gesture));
  if (!n.eyebrows.empty()) nm.push_back("brows=" + quoted_if_needed(n.eyebrows));
  if (!n.expression.empty()) {
    std::string e = "expression=" + quoted_if_needed(n.expression);
    if (n.expression_intensity != 0.0f) e += ":" + format_float(n.expression_intensity);
    nm.push_back(e);
  } else if (n.expression_intensity != 0.0f) {
    nm.push_back("intensity=" + format_float(n.expression_intensity));
  }
  if (!n.head.empty()) nm.push_back("head=" + quoted_if_needed(n.head));
  if (!n.gaze.empty()) nm.push_back("gaze=" + quoted_if_needed(n.gaze));
  if (!nm.empty()) {
    s += " N(";
    for (std::size_t i = 0; i < nm.size(); ++i) s += (i ? ", " : "") + nm[i];
    s += ")";
  }
  return s;
}

std::string print_formula_line(const SignSpec& sign) {
  if (sign.gloss.empty()) return print_formula(sign);
  std::string gloss;
  for (char c : sign.gloss) {
    // '=' '(' '"' would end the gloss early when read back, '#' would start a comment.
    const bool special = c == '=' || c == '#' || c == '(' || c == '"' || c == '\n' || c == '\r';
    gloss += special ? '_' : c;
  }
  return gloss + " = " + print_formula(sign);
}

}  // namespace sw::notation

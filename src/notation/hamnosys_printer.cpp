// Printer of HamNoSys 4 (code points or names): writes a SignSpec in the grammar hamnosys_parser
// reads, so that parse(print(x)) gives x back for what the readers produce. What HamNoSys cannot
// say (a palm direction with a finger-axis component, 3-letter movement directions, circle sense,
// formula-only handshape overrides) is written as the nearest HamNoSys symbol.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "notation/formula.h"
#include "notation/hamnosys.h"
#include "notation/hamnosys_places.h"
#include "notation/hamnosys_symbols.h"
#include "notation/handshape.h"
#include "notation/text_position.h"

namespace sw::notation {
namespace {

using Symbols = std::vector<char32_t>;

// The symbol "<prefix><direction word>", or for a direction the group lacks, the nearest one
// the group has (dropping the left/right, then the in/out component).
char32_t direction_symbol(std::string_view prefix, Direction d) {
  for (int attempt = 0; attempt < 3; ++attempt) {
    const std::string name = std::string(prefix) + direction_word(d);
    if (const HamSymbolInfo* s = ham_symbol_by_name(name)) return s->code;
    if (attempt == 0 && d.x != 0 && (d.y != 0 || d.z != 0)) {
      d.x = 0;
    } else if (d.z != 0 && d.y != 0) {
      d.z = 0;
    } else if (d.z != 0) {  // palm straight out/in: HamNoSys palm symbols have no o/i
      d = Direction{0, static_cast<std::int8_t>(d.z > 0 ? 1 : -1), 0};
    }
  }
  return 0;
}

// Symbols for a direction: one symbol, or for a three-component direction two symbols the reader
// takes "between" (u+i+l = ui then il), or the nearest one symbol the group has.
Symbols direction_symbols(std::string_view prefix, const Direction& d, bool with_between) {
  if (d.x != 0 && d.y != 0 && d.z != 0) {
    const std::string yz = std::string(prefix) + direction_word(Direction{0, d.y, d.z});
    const std::string zx = std::string(prefix) + direction_word(Direction{d.x, 0, d.z});
    const HamSymbolInfo* a = ham_symbol_by_name(yz);
    const HamSymbolInfo* b = ham_symbol_by_name(zx);
    if (a && b) {
      if (with_between) return {a->code, hambetween, b->code};
      return {a->code, b->code};
    }
  }
  if (const char32_t c = direction_symbol(prefix, d)) return {c};
  return {};
}

void append(Symbols* out, const Symbols& more) { out->insert(out->end(), more.begin(), more.end()); }

// handshape [extfidir] [palm]; orientation parts equal to `reference` are left out (the reader
// starts from the same reference).
Symbols hand_symbols(const HandSpec& hand, const Orientation& reference, bool with_shape) {
  Symbols out;
  if (with_shape) append(&out, handshape_words(hand.shape));
  if (hand.orientation.extended_finger != reference.extended_finger) {
    append(&out, direction_symbols("hamextfinger", hand.orientation.extended_finger, false));
  }
  if (hand.orientation.palm != reference.palm) {
    if (char32_t c = direction_symbol("hampalm", hand.orientation.palm)) out.push_back(c);
  }
  return out;
}




// A place on a hand: [digit] part (a fingertip of a named finger is written as the digit alone
// when that reads back the same).
Symbols place_symbols(HandPlace place, int finger) {
  Symbols out;
  const bool finger_place = place >= HandPlace::Fingertip && place <= HandPlace::FingerSide;
  if (finger >= 0 && finger < kFingerCount) out.push_back(hamthumb + static_cast<char32_t>(finger));
  if (!(finger >= 0 && place == HandPlace::Fingertip) || !finger_place) out.push_back(place_symbol(place));
  return out;
}

// [lr] level [lr] for a body location, without contact.
Symbols level_symbols(const Location& l) {
  Symbols out;
  const BodyLevel level = l.kind == Location::Kind::NeutralSpace ? BodyLevel::NeutralSpace : l.level;
  if (l.side == Side::Left) out.push_back(hamlrat);
  if (l.side == Side::LeftBeside) out.push_back(hamlrbeside);
  out.push_back(level_symbol(level));
  if (l.side == Side::Right) out.push_back(hamlrat);
  if (l.side == Side::RightBeside) out.push_back(hamlrbeside);
  return out;
}

bool is_default_location(const Location& l) {
  const Location d;
  return l.kind == d.kind && l.level == d.level && l.side == d.side && l.contact == d.contact &&
         !l.contact_part;
}

// The dominant hand's location (and the non-dominant's when it has its own body location).
Symbols location_symbols(const Location& l, const Location* nondominant) {
  Symbols out;
  const char32_t contact = contact_symbol(l.contact);
  if (l.kind == Location::Kind::OtherHand) {
    if (l.contact_part) {
      out.push_back(hamparbegin);
      append(&out, place_symbols(*l.contact_part, l.contact_finger));
      out.push_back(hamplus);
      append(&out, place_symbols(l.hand_place, l.finger));
      out.push_back(hamparend);
    } else {
      append(&out, place_symbols(l.hand_place, l.finger));
    }
    if (nondominant) {
      // The constellation made at a body location, which the non-dominant hand (the place)
      // holds: "(part + place) contact level [contact]" (hamnosys_parser.cpp,
      // read_constellation_place).
      if (contact) out.push_back(contact);
      append(&out, level_symbols(*nondominant));
      if (char32_t c = contact_symbol(nondominant->contact)) out.push_back(c);
      return out;
    }
  } else if (nondominant) {
    out.push_back(hamparbegin);
    if (l.contact_part) append(&out, place_symbols(*l.contact_part, l.contact_finger));
    Location at_default = l;
    at_default.contact = Contact::None;
    at_default.contact_part.reset();
    if (!l.contact_part || !is_default_location(at_default)) append(&out, level_symbols(l));
    out.push_back(hamplus);
    append(&out, level_symbols(*nondominant));
    if (char32_t c = contact_symbol(nondominant->contact)) out.push_back(c);
    out.push_back(hamparend);
  } else {
    if (l.contact_part) append(&out, place_symbols(*l.contact_part, l.contact_finger));
    append(&out, level_symbols(l));
  }
  if (contact) out.push_back(contact);
  return out;
}

Symbols movement_symbols(const Movement& m, const HandSpec& initial) {
  Symbols out;
  switch (m.kind) {
    case MovementKind::Straight:
    case MovementKind::Wavy:
    case MovementKind::Zigzag:
    case MovementKind::Arc:
      if (!m.direction.is_zero()) append(&out, direction_symbols("hammove", m.direction, true));
      if (m.kind == MovementKind::Straight && m.direction.is_zero()) out.push_back(hammoveX);
      if (m.kind == MovementKind::Arc) {
        if (char32_t c = direction_symbol("hamarc", m.arc_bulge)) {
          out.push_back(c);
        } else if (m.direction.is_zero()) {
          out.push_back(hamarcu);
        }
      }
      if (m.kind == MovementKind::Wavy) out.push_back(hamwavy);
      if (m.kind == MovementKind::Zigzag) out.push_back(hamzigzag);
      break;
    case MovementKind::Circle:
    case MovementKind::Ellipse:
    case MovementKind::Spiral: {
      const Symbols c = direction_symbols("hamcircle", m.circle_axis, true);
      if (c.empty()) {
        out.push_back(hamcircleo);
      } else {
        append(&out, c);
      }
      if (m.kind == MovementKind::Ellipse && m.ellipse_axis.is_zero()) out.push_back(hamellipseh);
      break;
    }
    case MovementKind::FingerPlay: out.push_back(hamfingerplay); break;
    case MovementKind::WristNod: out.push_back(hamnodding); break;
    case MovementKind::WristSwing: out.push_back(hamswinging); break;
    case MovementKind::WristTwist: out.push_back(hamtwisting); break;
    case MovementKind::WristCircle: out.push_back(m.clockwise ? hamstircw : hamstirccw); break;
    case MovementKind::Replace: {
      out.push_back(hamreplace);
      HandSpec to = initial;
      if (m.to_orientation) to.orientation = *m.to_orientation;
      if (m.to_shape) to.shape = *m.to_shape;
      append(&out, hand_symbols(to, initial.orientation, m.to_shape.has_value()));
      break;
    }
    case MovementKind::Target:
      break;
  }
  if (m.kind != MovementKind::Arc && !m.arc_bulge.is_zero()) {
    if (char32_t c = direction_symbol("hamarc", m.arc_bulge)) out.push_back(c);
  }
  if (!m.ellipse_axis.is_zero()) {
    const Direction& e = m.ellipse_axis;
    out.push_back(e == Direction{0, 1, 0} ? hamellipsev
                  : e == Direction{-1, 1, 0} ? hamellipseur
                  : e == Direction{1, 1, 0}  ? hamellipseul
                                             : hamellipseh);
  }
  // A target on its own is fenced in hamseqbegin...hamseqend: written bare, the reader would
  // take it as the target of the movement before it.
  if (m.kind == MovementKind::Target) out.push_back(hamseqbegin);
  if (m.kind != MovementKind::Target) {
    if (m.size == Size::Small) out.push_back(hamsmallmod);
    if (m.size == Size::Large) out.push_back(hamlargemod);
    switch (m.manner) {
      case Manner::Fast: out.push_back(hamfast); break;
      case Manner::Slow: out.push_back(hamslow); break;
      case Manner::Tense: out.push_back(hamtense); break;
      case Manner::Halt: out.push_back(hamhalt); break;
      case Manner::Rest: out.push_back(hamrest); break;
      case Manner::Normal: break;
    }
  }
  if (m.to_location) {
    Symbols loc = location_symbols(*m.to_location, nullptr);
    // A target equal to the start but for its contact is written as the contact alone.
    Location start = initial.location;
    start.contact = m.to_location->contact;
    const Location& t = *m.to_location;
    if (t.kind == start.kind && t.level == start.level && t.side == start.side &&
        t.hand_place == start.hand_place && t.finger == start.finger &&
        t.contact_part == start.contact_part && t.contact != Contact::None) {
      loc = {contact_symbol(t.contact)};
    }
    append(&out, loc);
  }
  if (m.alternating) out.push_back(hamalternatingmotion);
  if (m.kind == MovementKind::Target) out.push_back(hamseqend);
  return out;
}

char32_t repeat_symbol(RepeatKind k) {
  switch (k) {
    case RepeatKind::FromStart: return hamrepeatfromstart;
    case RepeatKind::Continuing: return hamrepeatcontinue;
    case RepeatKind::Reverse: return hamrepeatreverse;
    case RepeatKind::FromStartSeveral: return hamrepeatfromstartseveral;
    case RepeatKind::ContinuingSeveral: return hamrepeatcontinueseveral;
    case RepeatKind::None: return 0;
  }
  return 0;
}

}  // namespace

std::vector<char32_t> hamnosys_symbols(const SignSpec& sign) {
  Symbols out;
  switch (sign.symmetry) {
    case Symmetry::None: break;
    case Symmetry::MirrorLR: out.push_back(hamsymmlr); break;
    case Symmetry::MirrorLRUD: append(&out, {hamsymmlr, hamfingerstraightmod}); break;
    case Symmetry::MirrorLRIO: append(&out, {hamsymmlr, hamlargemod}); break;
    case Symmetry::Parallel: out.push_back(hamsymmpar); break;
    case Symmetry::ParallelUD: append(&out, {hamsymmpar, hamfingerstraightmod}); break;
    case Symmetry::ParallelIO: append(&out, {hamsymmpar, hamlargemod}); break;
  }
  // HamNoSys 4: hamnondominant before a one-handed sign's configuration: the other hand signs.
  if (sign.one_hand_is_nondominant && !sign.nondominant) out.push_back(hamnondominant);
  const Orientation default_orientation;
  if (sign.nondominant) {
    out.push_back(hamparbegin);
    append(&out, hand_symbols(sign.dominant, default_orientation, true));
    out.push_back(hamplus);
    append(&out, hand_symbols(*sign.nondominant, sign.dominant.orientation, true));
    out.push_back(hamparend);
  } else {
    append(&out, hand_symbols(sign.dominant, default_orientation, true));
  }
  const Location* nd_location = nullptr;
  if (sign.nondominant && !is_default_location(sign.nondominant->location) &&
      sign.nondominant->location.kind != Location::Kind::OtherHand) {
    nd_location = &sign.nondominant->location;
  }
  if (!is_default_location(sign.dominant.location) || nd_location) {
    append(&out, location_symbols(sign.dominant.location, nd_location));
  }
  const HandSpec& nd_initial = sign.nondominant ? *sign.nondominant : sign.dominant;
  for (const MovementStep& step : sign.movements) {
    const bool other_stays = step.nondominant_stays && step.nondominant.empty();
    const bool group = step.dominant.size() != 1 || !step.nondominant.empty() || other_stays;
    if (group) out.push_back(hamparbegin);
    for (const Movement& m : step.dominant) append(&out, movement_symbols(m, sign.dominant));
    if (!step.nondominant.empty()) {
      out.push_back(hamplus);
      for (const Movement& m : step.nondominant) append(&out, movement_symbols(m, nd_initial));
    } else if (other_stays) {
      append(&out, {hamplus, hamnomotion});
    }
    if (group) out.push_back(hamparend);
  }
  if (const char32_t r = repeat_symbol(sign.repetition.kind)) {
    for (int n = 0; n < std::max(1, sign.repetition.count); ++n) out.push_back(r);
  }
  return out;
}

std::string print_hamnosys(const SignSpec& sign, HamNoSysSpelling spelling) {
  std::string out;
  for (char32_t c : hamnosys_symbols(sign)) {
    if (spelling == HamNoSysSpelling::Unicode) {
      append_utf8(&out, c);
    } else {
      if (!out.empty()) out += ',';
      out += ham_symbol_name(c);
    }
  }
  return out;
}

}  // namespace sw::notation

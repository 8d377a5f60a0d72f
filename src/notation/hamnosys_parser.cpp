// Reader of HamNoSys 4 (see hamnosys.h for the grammar). Symbols -> SignSpec, recovering from
// unknown symbols and unbalanced brackets with a diagnostic each.
#include <algorithm>
#include <optional>
#include <string>

#include "notation/formula.h"
#include "notation/hamnosys.h"
#include "notation/hamnosys_places.h"
#include "notation/hamnosys_symbols.h"
#include "notation/handshape.h"
#include "notation/parallel_steps.h"
#include "notation/text_position.h"

namespace sw::notation {
namespace {

bool in_group(char32_t c, HamGroup g) {
  const HamSymbolInfo* s = ham_symbol_by_code(c);
  return s && s->group == g;
}

// The direction in a symbol's name after its prefix: "hamextfingerul" -> u + l.
Direction direction_of(char32_t code, std::string_view prefix) {
  Direction d;
  const std::string_view name = ham_symbol_name(code);
  if (name.size() > prefix.size()) parse_direction_word(name.substr(prefix.size()), &d);
  return d;
}

// "Between" two directions: the sum of both, each component's sign (u + ul -> ul, uo + ol -> uol).
Direction between(const Direction& a, const Direction& b) {
  auto sign = [](int v) { return static_cast<std::int8_t>(v > 0 ? 1 : v < 0 ? -1 : 0); };
  return Direction{sign(a.x + b.x), sign(a.y + b.y), sign(a.z + b.z)};
}

bool is_body_level(char32_t c) { return in_group(c, HamGroup::LocationBody); }
bool is_hand_place(char32_t c) {
  return in_group(c, HamGroup::LocationArmHand) || in_group(c, HamGroup::LocationFinger) ||
         in_group(c, HamGroup::ObsoleteWrist);
}
bool is_location_start(char32_t c) {
  return is_body_level(c) || is_hand_place(c) || c == hamlrbeside || c == hamlrat ||
         c == hamneutralspace || in_group(c, HamGroup::Contact) || c == hamcoreftag ||
         c == hamcorefref;
}
bool is_movement(char32_t c) {
  return in_group(c, HamGroup::StraightMovement) || in_group(c, HamGroup::CircularMovement) ||
         in_group(c, HamGroup::WristFingerMovement) || c == hammovecross || c == hammoveX;
}
bool is_movement_modifier(char32_t c) {
  return in_group(c, HamGroup::Arc) || in_group(c, HamGroup::WavyZigzag) ||
         in_group(c, HamGroup::Ellipse) || in_group(c, HamGroup::Size) ||
         in_group(c, HamGroup::Manner) || in_group(c, HamGroup::ClockPosition) ||
         c == hamalternatingmotion;
}

bool operator!=(const Orientation& a, const Orientation& b) {
  return a.extended_finger != b.extended_finger || a.palm != b.palm || a.seed_palm != b.seed_palm;
}

// One location element: what it says about a hand.
struct LocationPart {
  bool has_level = false;  // a body level or neutral space
  bool has_place = false;  // a place on a hand / arm
  Location location;       // level/side or place (kind set accordingly)
  bool part_only = false;  // only a hand part (digit/part symbols) with no body level
  // The part of THIS hand that makes the contact, from a bracket after the place
  // (read_contact_bracket): "hamearlobe hamseqbegin hamtouch hamthumb hamfingernail hamseqend".
  std::optional<HandPlace> bracket_part;
  std::int8_t bracket_finger = -1;
};

class Reader {
 public:
  Reader(const std::vector<HamSymbolRef>& s, std::vector<Diagnostic>* d)
      : s_(first_alternatives(s)), diags_(d) {
    match_brackets();
  }

  bool read(SignSpec* sign) {
    if (too_deep_) return false;
    std::size_t i = 0;
    const std::size_t end = s_.size();
    bool nondominant_first = false;
    // Prefix: two-handed operators and a pending alternation.
    while (i < end) {
      const char32_t c = s_[i].code;
      if (c == hamsymmlr || c == hamsymmpar) {
        i = read_symmetry(i, end, &sign->symmetry);
        continue;
      } else if (c == hamalternatingmotion) {
        alternate_all_ = true;
      } else if (c == hamnondominant) {
        // HamNoSys 4: before a one-handed configuration, the non-dominant hand signs (kept when
        // no hamplus pair of two hands follows, below).
        nondominant_first = true;
      } else if (c == hamnonipsi || c == hammime || c == hamversion40) {
        // Read and not kept.
      } else if (skip_ignorable(&i)) {
        continue;
      } else {
        break;
      }
      ++i;
    }
    // Initial configuration.
    if (i < end && s_[i].code == hamparbegin && match_[i] > i + 1 &&
        is_shape_base(s_[i + 1].code)) {
      const std::size_t close = match_[i];
      std::size_t plus = find_plus(i + 1, close);
      std::size_t j = read_hand(i + 1, plus, &sign->dominant, nullptr);
      if (j < plus)
        error(j, "expected the dominant hand's orientation or hamplus, found '" + s_[j].text + "'");
      if (plus == close) {
        error(i,
              "expected hamplus between the two hands' configurations in hamparbegin...hamparend");
      } else {
        // What the non-dominant hand does not say is as the dominant hand has it.
        HandSpec nd = sign->dominant;
        j = read_hand(plus + 1, close, &nd, &sign->dominant.orientation);
        if (j < close)
          error(j, "expected the non-dominant hand's configuration or hamparend, found '" +
                       s_[j].text + "'");
        sign->nondominant = nd;
      }
      i = close < end ? close + 1 : end;
    } else if (i < end && is_shape_base(s_[i].code)) {
      i = read_hand(i, end, &sign->dominant, nullptr);
      i = read_orientation_pair(i, end, sign);
    } else {
      if (i < end) {
        error(i,
              "expected a handshape (hamfist, hamflathand, hamfinger2, ...) or "
              "hamparbegin with two hands' configurations, found '" +
                  s_[i].text + "'");
      } else {
        error_at_end(
            "expected a handshape (hamfist, hamflathand, hamfinger2, ...), found the end of the "
            "sign");
      }
      return false;
    }
    sign->one_hand_is_nondominant =
        nondominant_first && !sign->nondominant && sign->symmetry == Symmetry::None;
    // Initial location.
    if (i < end && starts_location(i)) i = read_initial_location(i, end, sign);
    initial_dominant_ = sign->dominant;
    initial_nondominant_ = sign->nondominant ? *sign->nondominant : sign->dominant;
    // Actions.
    read_actions(i, end, sign, &sign->movements);
    if (own_side_dominant_) {
      sign->dominant.location.side = mirror(sign->dominant.location.side);
      for (MovementStep& step : sign->movements)
        for (Movement& m : step.dominant)
          if (m.to_location && m.to_location->kind == Location::Kind::Body)
            m.to_location->side = mirror(m.to_location->side);
    }
    if (alternate_all_) {
      for (MovementStep& step : sign->movements) {
        for (Movement& m : step.dominant) m.alternating = true;
        for (Movement& m : step.nondominant) m.alternating = true;
      }
    }
    // The other hand is a still place only without a symmetry operator (HamNoSys 4: the
    // non-dominant hand given as the place, "hamnondominant" / a hand constellation). With one,
    // both hands make the movements, the non-dominant hand mirrored, and the contact is between
    // them (the real-sign corpus, TO-MIX3: both hands circle against each other; read as a
    // place, one hand circled on a still one: 157 of its signs).
    if (sign->dominant.location.kind == Location::Kind::OtherHand &&
        sign->symmetry == Symmetry::None)
      sign->nondominant_is_place = true;
    return true;
  }

 private:
  // ---- diagnostics
  void report(std::size_t i, const std::string& message, Severity severity) {
    const HamSymbolRef& r = s_[i];
    diags_->push_back(Diagnostic{severity, r.offset, r.length, r.line, r.column, r.text, message});
  }
  void error(std::size_t i, const std::string& message) { report(i, message, Severity::Error); }
  void warning(std::size_t i, const std::string& message) { report(i, message, Severity::Warning); }
  void error_at_end(const std::string& message) {
    Diagnostic d;
    if (!s_.empty()) {
      d.offset = s_.back().offset + s_.back().length;
      d.line = s_.back().line;
      d.column = s_.back().column + 1;
    }
    d.message = message;
    diags_->push_back(std::move(d));
  }

  // ---- brackets: match_[i] = index of the closer of the opener at i (s_.size() if unclosed)
  static char32_t closer_of(char32_t c) {
    switch (c) {
      case hamseqbegin:
        return hamseqend;
      case hamparbegin:
        return hamparend;
      case hamfusionbegin:
        return hamfusionend;
      case hamaltbegin:
        return hamaltend;
      default:
        return 0;
    }
  }
  static bool is_closer(char32_t c) {
    return c == hamseqend || c == hamparend || c == hamfusionend || c == hamaltend;
  }
  void match_brackets() {
    match_.assign(s_.size(), s_.size());
    skip_.assign(s_.size(), false);
    std::vector<std::size_t> open;
    for (std::size_t i = 0; i < s_.size(); ++i) {
      const char32_t c = s_[i].code;
      if (closer_of(c)) {
        if (open.size() >= kMaxGroupDepth) {
          error(i, "groups nest deeper than " + std::to_string(kMaxGroupDepth) +
                       " levels (the reader's limit; real signs nest fewer than 5)");
          too_deep_ = true;
          return;
        }
        open.push_back(i);
      } else if (is_closer(c)) {
        if (!open.empty() && closer_of(s_[open.back()].code) == c) {
          match_[open.back()] = i;
          open.pop_back();
        } else if (!open.empty() && open.size() >= 2 &&
                   closer_of(s_[open[open.size() - 2]].code) == c) {
          // The inner group was never closed: close it here as well.
          error(open.back(), "unbalanced brackets: '" + s_[open.back()].text +
                                 "' is not closed (expected '" +
                                 ham_symbol_name(closer_of(s_[open.back()].code)) + "' before '" +
                                 s_[i].text + "')");
          match_[open.back()] = i;
          open.pop_back();
          match_[open.back()] = i;
          open.pop_back();
        } else {
          error(i,
                "unbalanced brackets: '" + s_[i].text + "' closes nothing that is open" +
                    (open.empty() ? ""
                                  : std::string(" (expected '") +
                                        ham_symbol_name(closer_of(s_[open.back()].code)) + "')"));
          skip_[i] = true;
        }
      }
    }
    for (std::size_t i : open) {
      error(i, "unbalanced brackets: '" + s_[i].text + "' is never closed (expected '" +
                   ham_symbol_name(closer_of(s_[i].code)) + "')");
    }
  }
  std::size_t find_plus(std::size_t begin, std::size_t end) const {
    for (std::size_t i = begin; i < end; ++i) {
      if (s_[i].code == hamplus) return i;
      if (closer_of(s_[i].code) && match_[i] < end) i = match_[i];
    }
    return end;
  }

  // Symbols with no bearing on SignSpec: skipped wherever they appear. Returns true (and moves
  // *i past them) when s_[*i] is one.
  bool skip_ignorable(std::size_t* i) {
    const char32_t c = s_[*i].code;
    if (skip_[*i] || c == hamspace || c == hamexclaim || c == hamcomma || c == hamfullstop ||
        c == hamquery || c == hamcoreftag || c == hamcorefref || c == hametc ||
        c == hamorirelative || c == hamversion40 || c == hammime || c == hamincreasing ||
        c == hamdecreasing || c == hamnondominant) {
      ++*i;
      return true;
    }
    if (c == hamaltbegin) {  // {a | b}: the first alternative is read, the rest skipped
      return false;
    }
    return false;
  }

  // ---- hand configuration: handshape [extfidir...] [palm...]
  // Marks inside a hand configuration that SignSpec does not keep (hamorirelative: orientation
  // relative to the other hand; hametc; hamnondominant; hamincreasing/decreasing in a change).
  std::size_t skip_marks(std::size_t i, std::size_t end) const {
    while (i < end &&
           (s_[i].code == hamorirelative || s_[i].code == hametc || s_[i].code == hamnondominant ||
            s_[i].code == hamincreasing || s_[i].code == hamdecreasing)) {
      ++i;
    }
    return i;
  }

  // Finger and finger-part symbols after a handshape belong to it (which fingers, which part the
  // thumb touches) unless they end in a contact, a body or hand place: then they are a location
  // ("hamfist hamindexfinger hamtouch": the index touches).
  bool finger_run_is_shape(std::size_t i, std::size_t end) const {
    if (s_[i].code >= hamfingertip && s_[i].code <= hamfingerside)
      return false;  // a part, no digit
    while (i < end && in_group(s_[i].code, HamGroup::LocationFinger)) ++i;
    if (i >= end) return true;
    const char32_t c = s_[i].code;
    return !(in_group(c, HamGroup::Contact) || is_body_level(c) || c == hamlrat ||
             c == hamlrbeside || in_group(c, HamGroup::LocationArmHand) || c == hamneutralspace);
  }

  std::size_t read_hand(std::size_t i, std::size_t end, HandSpec* hand, Orientation* base) {
    i = skip_marks(i, end);
    if (i < end && is_shape_base(s_[i].code)) {
      const std::size_t start = i;
      std::vector<char32_t> words;
      while (i < end && is_shape_word(s_[i].code)) {
        const char32_t c = s_[i].code;
        if (c == hambetween && i + 1 < end && s_[i + 1].code >= hamthumb &&
            s_[i + 1].code <= hampinky) {
          i += 2;  // "between two fingers": the first is kept
          continue;
        }
        if (c == hambetween && !(i + 1 < end && is_shape_base(s_[i + 1].code))) break;
        const bool run_start = !(i > start && in_group(s_[i - 1].code, HamGroup::LocationFinger));
        if (in_group(c, HamGroup::LocationFinger) && run_start && !finger_run_is_shape(i, end))
          break;
        words.push_back(c);
        ++i;
      }
      ShapeError err;
      HandShape shape;
      if (build_handshape(words, &shape, &err)) {
        hand->shape = shape;
      } else {
        error(start + std::min(err.word_index, words.size() - 1), err.message);
      }
    }
    if (base) hand->orientation = *base;
    i = read_orientation(skip_marks(i, end), end, &hand->orientation);
    return skip_marks(i, end);
  }

  // One handshape for both hands and their orientations paired ("hamfinger2345 hamthumboutmod
  // hamparbegin hamextfingeru hampalmdl hamplus hamextfingeru hampalmd hamparend", 147 signs of
  // the real-sign corpus): the pair is the two hands' orientations, the non-dominant hand's
  // starting from the dominant one as a hamplus configuration does. Read as a change of the hand
  // after the start, it left the dominant orientation unwritten and the pair's body place after
  // it a target of that change (PJM Peugeot: both hands at the shoulders read as the right hand
  // moving there from neutral space, then "hammovei hamlargemod" through the shoulder).
  // Returns the index after the pair, or i when none is there.
  std::size_t read_orientation_pair(std::size_t i, std::size_t end, SignSpec* sign) {
    if (!(i < end && s_[i].code == hamparbegin && match_[i] < end)) return i;
    const std::size_t close = match_[i];
    const std::size_t plus = find_plus(i + 1, close);
    auto is_orientation = [&](std::size_t k) {
      return k < close && (in_group(s_[k].code, HamGroup::ExtendedFinger) ||
                           in_group(s_[k].code, HamGroup::Palm));
    };
    if (plus >= close || !is_orientation(i + 1) || !is_orientation(plus + 1)) return i;
    std::size_t j = skip_marks(read_orientation(i + 1, plus, &sign->dominant.orientation), plus);
    if (j < plus)
      error(j, "expected the dominant hand's orientation or hamplus, found '" + s_[j].text + "'");
    // What the pair does not say of the other hand (a palm written alone) is the dominant hand's,
    // mirrored under a mirror symmetry as for a hand given only a location.
    HandSpec nd = nondominant_copy(*sign);
    j = skip_marks(read_orientation(plus + 1, close, &nd.orientation), close);
    if (j < close)
      error(j, "expected the non-dominant hand's orientation or hamparend, found '" + s_[j].text +
                   "'");
    sign->nondominant = nd;
    return close + 1;
  }

  std::size_t read_orientation(std::size_t i, std::size_t end, Orientation* o) {
    auto read_dirs = [&](HamGroup group, std::string_view prefix, Direction* out) {
      if (!(i < end && in_group(s_[i].code, group))) return;
      Direction d = direction_of(s_[i].code, prefix);
      ++i;
      for (;;) {
        if (i < end && in_group(s_[i].code, group)) {
          d = between(d, direction_of(s_[i].code, prefix));
          ++i;
        } else if (i + 1 < end && s_[i].code == hambetween && in_group(s_[i + 1].code, group)) {
          d = between(d, direction_of(s_[i + 1].code, prefix));
          i += 2;
        } else {
          break;
        }
      }
      *out = d;
    };
    read_dirs(HamGroup::ExtendedFinger, "hamextfinger", &o->extended_finger);
    i = skip_marks(i, end);
    read_dirs(HamGroup::Palm, "hampalm", &o->palm);
    return i;
  }

  // ---- locations
  bool starts_location(std::size_t i) const {
    if (is_location_start(s_[i].code)) return true;
    return s_[i].code == hamparbegin && i + 1 < s_.size() && is_location_start(s_[i + 1].code) &&
           !in_group(s_[i + 1].code, HamGroup::Contact);
  }

  // [digits] [part] [lr] level [lr] [contact]; returns the index after it.
  std::size_t read_location_part(std::size_t i, std::size_t end, LocationPart* out,
                                 Contact* contact, bool* has_contact) {
    Location& loc = out->location;
    int finger = -1;
    bool lr_before = false, lr_beside = false;
    // Inside a sequence of places after hambelowstomach: the corpus writes places on the legs
    // there with the arm's symbols (rajstopy, pończochy: tights, stockings, "hambelowstomach
    // [hamupperarm hamlrat]", the thigh; KNEE1A^: "[hamelbowinside]", the hollow of the knee).
    bool in_sequence = false;
    char32_t level_code = 0;
    while (i < end) {
      const char32_t c = s_[i].code;
      if (in_sequence && level_code == hambelowstomach &&
          (c == hamupperarm || c == hamelbow || c == hamelbowinside || c == hamlowerarm)) {
        // A place on the leg, not a part of this hand (as a part, the hand put its own upper arm
        // at the belly: rajstopy's wrist leapt 466 mm about it, docs/SYNTHESIS.md leap). The body
        // model has no legs: the level below the stomach stands for it.
      } else if (c >= hamthumb && c <= hampinky) {
        if (finger < 0) finger = static_cast<int>(c - hamthumb);
        out->has_place = true;
        loc.hand_place = HandPlace::Fingertip;  // a finger alone: its tip
      } else if (is_hand_place(c)) {
        out->has_place = true;
        loc.hand_place = place_of(c);
      } else if (c == hamlrat || c == hamlrbeside) {
        // HamNoSys: the side symbol before the level is the non-dominant (left) side, after it
        // the dominant (right) side; hamlrbeside = beside the body, hamlrat = at that side.
        if (!out->has_level) {
          lr_before = true;
          lr_beside = c == hamlrbeside;
        } else {
          loc.side = c == hamlrbeside ? Side::RightBeside : Side::Right;
        }
      } else if (is_body_level(c) || c == hamneutralspace) {
        if (out->has_level) break;  // a second level starts a new location (a target)
        out->has_level = true;
        level_code = c;
        loc.level = c == hamneutralspace ? BodyLevel::NeutralSpace : level_of(c);
        if (lr_before) loc.side = lr_beside ? Side::LeftBeside : Side::Left;
      } else if (in_group(c, HamGroup::Contact)) {
        *contact = contact_of(c);
        *has_contact = true;
        ++i;
        // A contact written before the place (hambrushing hamshoulders hamtouch) qualifies the
        // way there; the place and its own contact follow.
        const bool nothing_yet = !out->has_level && !out->has_place && !lr_before;
        if (nothing_yet && i < end && is_location_start(s_[i].code) &&
            !in_group(s_[i].code, HamGroup::Contact)) {
          continue;
        }
        break;
      } else if (c == hamcoreftag || c == hamcorefref) {
        // coreference marks: read and skipped
      } else if (c == hambetween && (out->has_level || out->has_place) && i + 1 < end &&
                 is_location_start(s_[i + 1].code) &&
                 !in_group(s_[i + 1].code, HamGroup::Contact)) {
        // "Between two places": the first one is kept, the second read and dropped.
        LocationPart other;
        Contact other_contact = Contact::None;
        bool other_has_contact = false;
        i = read_location_part(i + 1, end, &other, &other_contact, &other_has_contact);
        if (other_has_contact) {
          *contact = other_contact;
          *has_contact = true;
          break;
        }
        continue;
      } else if (c == hamseqbegin && (out->has_level || out->has_place) &&
                 is_contact_bracket(i, end)) {
        i = read_contact_bracket(i, out, contact, has_contact);
        break;
      } else if ((c == hamseqbegin && i + 1 < end && is_location_start(s_[i + 1].code) &&
                  !holds_movement(i)) ||
                 c == hamseqend) {
        // A sequence of places inside a location (contact along the way): read through.
        in_sequence = c == hamseqbegin;
      } else {
        break;
      }
      ++i;
    }
    loc.finger = static_cast<std::int8_t>(finger);
    if (out->has_level) {
      loc.kind = loc.level == BodyLevel::NeutralSpace ? Location::Kind::NeutralSpace
                                                      : Location::Kind::Body;
    } else if (out->has_place) {
      loc.kind = Location::Kind::OtherHand;
    } else if (lr_before) {  // a side with no level: at that side of neutral space
      loc.side = lr_beside ? Side::RightBeside : Side::Right;
    }
    out->part_only = out->has_place && !out->has_level;
    return i;
  }

  // Whether the group opened at i holds a movement: then it is a sequence of actions (HamNoSys
  // 4: "hamlowerarm [hamtouch hammovedo hambetween hammoveor]", touching the forearm along a
  // path, the DGS corpus's CAST1), not a sequence of places inside a location.
  bool holds_movement(std::size_t i) const {
    const std::size_t close = std::min(match_[i], s_.size());
    for (std::size_t k = i + 1; k < close; ++k)
      if (is_movement(s_[k].code) || s_[k].code == hamreplace) return true;
    return false;
  }

  // HamNoSys 4 writes the part of the hand that makes a contact in brackets after the place:
  // place hamseqbegin contact [digits] part [side] hamseqend (an earring: "hamearlobe hamlrat
  // [hamtouch hamthumb hamindexfinger hamfingernail hampalm]", the thumb and index nails touch
  // the earlobe). SiGML writes the same as a location_bodyarm with a location_hand child (the
  // corpus's NGT file: location_bodyarm contact="touch" location="shoulders" with location_hand
  // digits="2" location="midjoint" side="dorsal"). Read as a movement to the hand part, it sent
  // one-handed signs to the resting hand (the real-sign corpus, 176 brackets after a side mark
  // alone). Only a contact followed by hand-part symbols is such a bracket; a bracket with a body
  // place or a movement inside ("[hambrushing hamchin hamtouch]") is a path and read as before.
  bool is_contact_bracket(std::size_t i, std::size_t end) const {
    const std::size_t close = match_[i];
    if (close >= end || close < i + 3 || !in_group(s_[i + 1].code, HamGroup::Contact)) return false;
    bool part = false;
    for (std::size_t k = i + 2; k < close; ++k) {
      // hamlrat / hamlrbeside: the side of the part ("[hamtouch hamlrbeside hamwristback]").
      if (s_[k].code == hamlrat || s_[k].code == hamlrbeside) continue;
      if (!is_hand_place(s_[k].code)) return false;
      part = true;
    }
    return part;
  }
  // Reads the bracket is_contact_bracket accepted; returns the index after its hamseqend. The
  // first digit names the finger (a second one, "hamthumb hamindexfinger", is read and dropped:
  // Location has one contact finger); a second part after a finger part is the side of it
  // (hampalm: palmar, hamhandback: dorsal, SiGML side="palmar"/"dorsal") and is not kept.
  std::size_t read_contact_bracket(std::size_t i, LocationPart* out, Contact* contact,
                                   bool* has_contact) {
    const std::size_t close = match_[i];
    *contact = contact_of(s_[i + 1].code);
    *has_contact = true;
    int finger = -1;
    std::optional<HandPlace> part;
    for (std::size_t k = i + 2; k < close; ++k) {
      const char32_t c = s_[k].code;
      if (c >= hamthumb && c <= hampinky) {
        if (finger < 0) finger = static_cast<int>(c - hamthumb);
      } else if (c == hamlrat || c == hamlrbeside) {
        // the side of the part: Location has no field for it
      } else if (!part) {
        part = place_of(c);
      }
    }
    if (!part) part = HandPlace::Fingertip;  // a finger alone: its tip (as read_location_part)
    out->bracket_part = part;
    out->bracket_finger = static_cast<std::int8_t>(finger);
    return close + 1;
  }

  // A whole location (single or hamparbegin a hamplus b hamparend) applied to the sign's hands.
  // `target` set: read as a movement's target location instead.
  std::size_t read_location(std::size_t i, std::size_t end, Location* dominant,
                            Location* nondominant, bool* nondominant_set) {
    Contact contact = dominant->contact;
    bool has_contact = false;
    if (s_[i].code == hamparbegin) {
      const std::size_t close = std::min(match_[i], end);
      const std::size_t plus = find_plus(i + 1, close);
      LocationPart a, b;
      Contact ca = Contact::None, cb = Contact::None;
      bool ha = false, hb = false;
      std::size_t j = read_location_part(i + 1, plus, &a, &ca, &ha);
      if (j < plus) error(j, "expected a location symbol, found '" + s_[j].text + "'");
      if (plus < close) {
        j = read_location_part(plus + 1, close, &b, &cb, &hb);
        if (j < close) error(j, "expected a location symbol, found '" + s_[j].text + "'");
      } else {
        error(i, "expected hamplus between the two hands' locations in hamparbegin...hamparend");
      }
      i = close < end ? close + 1 : end;
      // The dominant hand's part (a), at the other hand's place (b) or at a body location.
      if (b.part_only || (a.part_only && !b.has_level)) {
        Location loc = b.location;
        loc.kind = Location::Kind::OtherHand;
        if (a.part_only) {
          loc.contact_part = a.location.hand_place;
          loc.contact_finger = a.location.finger;
        } else if (a.has_level) {
          loc = a.location;  // both hands at body locations written oddly: keep the dominant's
        }
        *dominant = loc;
      } else {
        if (a.part_only) {
          dominant->contact_part = a.location.hand_place;
          dominant->contact_finger = a.location.finger;
        } else {
          const auto part = dominant->contact_part;
          const auto part_finger = dominant->contact_finger;
          *dominant = a.location;
          dominant->contact_part = part;
          dominant->contact_finger = part_finger;
        }
        if (nondominant && b.has_level) {
          *nondominant = b.location;
          if (hb) nondominant->contact = cb;
          *nondominant_set = true;
        }
      }
      if (a.bracket_part) {
        dominant->contact_part = a.bracket_part;
        dominant->contact_finger = a.bracket_finger;
      }
      if (ha) contact = ca;
      if (i < end && in_group(s_[i].code, HamGroup::Contact)) {
        contact = contact_of(s_[i].code);
        ++i;
      }
      dominant->contact = contact;
      return i;
    }
    LocationPart a;
    i = read_location_part(i, end, &a, &contact, &has_contact);
    if (a.has_level || a.has_place) {
      if (a.has_level && a.has_place) {
        // A part of this hand at a body location ("hamindexfinger hamfingertip hamchin").
        const Location loc = a.location;
        Location body = loc;
        body.contact_part = loc.hand_place;
        body.contact_finger = loc.finger;
        body.hand_place = HandPlace::Palm;
        body.finger = -1;
        *dominant = body;
      } else {
        *dominant = a.location;
      }
      if (a.bracket_part) {  // the bracket names this hand's part: it wins over a part before the
                             // place
        dominant->contact_part = a.bracket_part;
        dominant->contact_finger = a.bracket_finger;
      }
    }
    dominant->contact =
        has_contact ? contact : (a.has_level || a.has_place ? Contact::None : dominant->contact);
    return i;
  }

  std::size_t read_initial_location(std::size_t i, std::size_t end, SignSpec* sign) {
    Location nd;
    bool nd_set = false;
    i = read_location(i, end, &sign->dominant.location, &nd, &nd_set);
    if (!nd_set && sign->dominant.location.kind == Location::Kind::OtherHand)
      i = read_constellation_place(i, end, &nd, &nd_set);
    if (nd_set) {
      if (!sign->nondominant) sign->nondominant = nondominant_copy(*sign);
      if (same_side_pair(*sign, nd)) {
        if (nd.side == Side::Left || nd.side == Side::LeftBeside) {
          own_side_dominant_ = true;  // the dominant hand's sides, once its actions are read
        } else {
          nd.side = mirror(nd.side);
        }
      }
      sign->nondominant->location = nd;
    } else if (sign->nondominant && sign->symmetry != Symmetry::None &&
               sign->dominant.location.kind != Location::Kind::OtherHand) {
      sign->nondominant->location = mirrored_place(sign->dominant.location);
    }
    return i;
  }

  // The other hand's place when a symmetric sign writes the two hands' configurations and one
  // place ("hamsymmpar hamparbegin config hamplus config hamparend hamshoulders hamclose"): the
  // dominant hand's, at the mirror side, as the planner places a hand copied under a symmetry
  // (sign_motion.cpp make_plans: mirror_x). The non-dominant HandSpec made for the
  // configurations kept the place it had before the location was read, neutral space: the PJM
  // "n weeks ago" signs started the left hand there, away from its shoulder.
  static Location mirrored_place(const Location& dominant) {
    Location loc = dominant;
    loc.side = mirror(loc.side);
    return loc;
  }

  // A symmetric pair's hands are never at one place: mirrored they are at the two sides of the
  // body, and in parallel they keep apart. A pair that writes the same side of one place for
  // both hands writes each hand's own side: "hamparbegin hamlrat hamshoulders hamplus hamlrat
  // hamshoulders hamparend" (the PJM "n weeks ago" signs and Peugeot, whose dominant hand then
  // moves "hammoveil" to "hamlrat hamshouldertop") has each hand at its own shoulder, "hamshoulders
  // hamlrat" for both (siedem tygodni temu, hamsymmpar) too. The side is the hand's own for the
  // hand whose side it is (the non-dominant, left, hand for hamlrat before the place; the dominant,
  // right, hand after it); the other hand's is mirrored, and when that is the dominant hand, so
  // are the sides of the body places it moves to, written the same way (read_initial_location,
  // the actions). Read literally, both hands started at one shoulder and the non-dominant hand,
  // mirroring the movement, crossed the body (sześć tygodni temu 115 mm deep). A pair written
  // with the two sides (hamchest hamlrat + hamlrat hamchest) or at a centre place is read as
  // written.
  static Side mirror(Side s) { return static_cast<Side>(4 - static_cast<int>(s)); }
  static bool same_side_pair(const SignSpec& sign, const Location& nd) {
    if (sign.symmetry == Symmetry::None) return false;
    const Location& d = sign.dominant.location;
    if (d.kind != Location::Kind::Body || nd.kind != Location::Kind::Body) return false;
    return nd.side != Side::Centre && nd.side == d.side && nd.level == d.level;
  }

  // A hand constellation (the dominant hand's part at a place on the other hand) followed by a
  // body location: the pair is made there ("hamparbegin hampalm hamplus hamhandback hamparend
  // hamclose hamshoulders": the palm close to the other hand's back, at the shoulders). SiGML
  // writes it as a handconstellation with a location_bodyarm child, which gsigml_reader.cpp
  // gives the non-dominant hand (the place) as its location; so does this. It was read as a
  // first movement to that body location (the corpus's TO-TELL1, HEART2A, TO-READ1C, CURTAIN2).
  // Returns the index after the body location, or i when none follows.
  std::size_t read_constellation_place(std::size_t i, std::size_t end, Location* nd, bool* nd_set) {
    if (i >= end) return i;
    const char32_t c = s_[i].code;
    const bool body =
        is_body_level(c) || c == hamneutralspace ||
        ((c == hamlrat || c == hamlrbeside) && i + 1 < end && is_body_level(s_[i + 1].code));
    if (!body) return i;
    LocationPart where;
    Contact contact = Contact::None;
    bool has_contact = false;
    const std::size_t next = read_location_part(i, end, &where, &contact, &has_contact);
    if (!where.has_level || where.has_place) return i;
    *nd = where.location;
    nd->contact = has_contact ? contact : Contact::None;
    *nd_set = true;
    return next;
  }

  // The non-dominant hand as the dominant hand has it, for a sign that gives the non-dominant
  // hand only a location: under a mirror symmetry its orientation is the dominant one mirrored
  // (written for the left hand, as a hamplus configuration is), so the copy does not turn the
  // left palm the way the right one faces.
  static HandSpec nondominant_copy(const SignSpec& sign) {
    HandSpec nd = sign.dominant;
    const Symmetry m = sign.symmetry;
    const bool x =
        m == Symmetry::MirrorLR || m == Symmetry::MirrorLRUD || m == Symmetry::MirrorLRIO;
    const bool y = m == Symmetry::MirrorLRUD || m == Symmetry::ParallelUD;
    const bool z = m == Symmetry::MirrorLRIO || m == Symmetry::ParallelIO;
    for (Direction* d : {&nd.orientation.extended_finger, &nd.orientation.palm}) {
      if (x) d->x = static_cast<std::int8_t>(-d->x);
      if (y) d->y = static_cast<std::int8_t>(-d->y);
      if (z) d->z = static_cast<std::int8_t>(-d->z);
    }
    return nd;
  }

  // A symmetry operator, hamsymmlr or hamsymmpar. HamNoSys 4 refines it with a following
  // hamfingerstraightmod (also mirror/parallel up-down) or hamlargemod (also in-out), as SiGML's
  // ud_symm/oi_symm. Returns the index after it.
  std::size_t read_symmetry(std::size_t i, std::size_t end, Symmetry* out) {
    const bool mirror = s_[i].code == hamsymmlr;
    *out = mirror ? Symmetry::MirrorLR : Symmetry::Parallel;
    ++i;
    if (i < end && s_[i].code == hamfingerstraightmod) {
      *out = mirror ? Symmetry::MirrorLRUD : Symmetry::ParallelUD;
      ++i;
    } else if (i < end && s_[i].code == hamlargemod) {
      *out = mirror ? Symmetry::MirrorLRIO : Symmetry::ParallelIO;
      ++i;
    }
    while (i < end && (s_[i].code == hamfingerstraightmod || s_[i].code == hamlargemod)) {
      warning(i, "a second symmetry refinement is read and not kept");
      ++i;
    }
    return i;
  }

  // Whether a sequential part starts at i (after a hamplus outside any hand pair): a symmetry
  // operator, a handshape or a two hands' configuration.
  bool starts_part(std::size_t i, std::size_t end) const {
    if (i >= end) return false;
    const char32_t c = s_[i].code;
    if (c == hamsymmlr || c == hamsymmpar || is_shape_base(c)) return true;
    return c == hamparbegin && i + 1 < end && is_shape_base(s_[i + 1].code);
  }

  // HamNoSys 4 sequential parts: sign := part {hamplus part}, part := [symmetry
  // [hamalternatingmotion]] config [location] action* (compounds; the DGS corpus's END4,
  // KARLSRUHE2). A later part is a change to its configuration and place (hamreplace), then its
  // actions, read on by the caller. A part's symmetry that differs from the sign's is read and
  // reported: SignSpec has one symmetry per sign.
  std::size_t read_part(std::size_t i, std::size_t end, SignSpec* sign,
                        std::vector<MovementStep>* steps) {
    while (i < end) {
      const char32_t c = s_[i].code;
      if (c == hamsymmlr || c == hamsymmpar) {
        Symmetry part = Symmetry::None;
        const std::size_t at = i;
        i = read_symmetry(i, end, &part);
        if (part != sign->symmetry)
          warning(at,
                  "a sequential part's own symmetry differs from the sign's: read and not kept");
      } else if (c == hamalternatingmotion || c == hamnondominant || c == hamnonipsi) {
        ++i;
      } else {
        break;
      }
    }
    i = read_replace(i, end, sign, steps);
    return read_part_orientation_pair(i, end, steps);
  }

  // One handshape for both hands and then the two hands' orientations (as read_orientation_pair
  // at the sign's start), in a later part: the pair is the change's orientations.
  std::size_t read_part_orientation_pair(std::size_t i, std::size_t end,
                                         std::vector<MovementStep>* steps) {
    if (!(i < end && s_[i].code == hamparbegin && match_[i] < end) || steps->empty() ||
        steps->back().dominant.empty())
      return i;
    const std::size_t close = match_[i];
    const std::size_t plus = find_plus(i + 1, close);
    auto is_orientation = [&](std::size_t k) {
      return k < close && (in_group(s_[k].code, HamGroup::ExtendedFinger) ||
                           in_group(s_[k].code, HamGroup::Palm));
    };
    if (plus >= close || !is_orientation(i + 1) || !is_orientation(plus + 1)) return i;
    MovementStep& step = steps->back();
    Movement& dom = step.dominant.back();
    Orientation o = dom.to_orientation ? *dom.to_orientation : initial_dominant_.orientation;
    std::size_t j = skip_marks(read_orientation(i + 1, plus, &o), plus);
    if (j < plus)
      error(j, "expected the dominant hand's orientation or hamplus, found '" + s_[j].text + "'");
    dom.to_orientation = o;
    Movement nd;
    nd.kind = MovementKind::Replace;
    nd.to_shape = dom.to_shape;
    Orientation ond = initial_nondominant_.orientation;
    j = skip_marks(read_orientation(plus + 1, close, &ond), close);
    if (j < close)
      error(j, "expected the non-dominant hand's orientation or hamparend, found '" + s_[j].text +
                   "'");
    nd.to_orientation = ond;
    step.nondominant.assign(1, nd);
    step.nondominant_stays = false;
    i = close + 1;
    bool fresh = true;
    if (i < end && starts_location(i)) i = read_target(i, end, steps, &fresh);
    return i;
  }

  // ---- actions
  // Whether [i, end) holds a hamnomotion (the part of a group after hamplus that says the
  // non-dominant hand does not move).
  bool holds_nomotion(std::size_t i, std::size_t end) const {
    for (; i < end; ++i)
      if (s_[i].code == hamnomotion) return true;
    return false;
  }

  Movement* last_of(std::vector<MovementStep>* steps) {
    if (steps->empty() || steps->back().dominant.empty()) return nullptr;
    return &steps->back().dominant.back();
  }

  void read_actions(std::size_t i, std::size_t end, SignSpec* sign,
                    std::vector<MovementStep>* steps) {
    bool last_is_fresh = false;  // the last movement was read in this group, just before
    while (i < end) {
      if (skip_ignorable(&i)) continue;
      const char32_t c = s_[i].code;
      if (is_movement(c) ||
          ((in_group(c, HamGroup::Arc) || in_group(c, HamGroup::WavyZigzag)) && !last_is_fresh)) {
        MovementStep step;
        step.dominant.push_back(movement_of(i));
        ++i;
        steps->push_back(std::move(step));
        last_is_fresh = true;
      } else if (c == hamreplace) {
        i = read_replace(i + 1, end, sign, steps);
        last_is_fresh = true;
      } else if (is_movement_modifier(c) || c == hambetween) {
        Movement* m = last_is_fresh ? last_of(steps) : nullptr;
        if (c == hambetween && m && i + 1 < end && is_movement(s_[i + 1].code)) {
          const Movement other = movement_of(i + 1);
          m->direction = between(m->direction, other.direction);
          m->circle_axis = between(m->circle_axis, other.circle_axis);
          i += 2;
          continue;
        }
        if (!m) {
          if (c == hamalternatingmotion) {
            alternate_all_ = true;
          } else {
            warning(i, "a movement modifier with no movement before it is ignored");
          }
        } else {
          modify(m, c);
        }
        ++i;
      } else if (in_group(c, HamGroup::Repetition) && c != hamalternatingmotion) {
        const RepeatKind kind = c == hamrepeatfromstart          ? RepeatKind::FromStart
                                : c == hamrepeatfromstartseveral ? RepeatKind::FromStartSeveral
                                : c == hamrepeatcontinue         ? RepeatKind::Continuing
                                : c == hamrepeatcontinueseveral  ? RepeatKind::ContinuingSeveral
                                                                 : RepeatKind::Reverse;
        if (sign->repetition.kind == kind) {
          ++sign->repetition.count;
        } else {
          sign->repetition.kind = kind;
          sign->repetition.count = 1;
        }
        ++i;
        last_is_fresh = false;
      } else if (c == hamnomotion) {
        ++i;
      } else if (c == hamseqbegin || c == hamfusionbegin) {
        const std::size_t close = std::min(match_[i], end);
        read_actions(i + 1, close, sign, steps);
        i = close < end ? close + 1 : end;
        last_is_fresh = false;
      } else if (c == hamparbegin && starts_location(i)) {
        i = read_target(i, end, steps, &last_is_fresh);
      } else if (c == hamparbegin) {
        const std::size_t close = std::min(match_[i], end);
        const std::size_t plus = find_plus(i + 1, close);
        std::vector<MovementStep> a, b;
        read_actions(i + 1, plus, sign, &a);
        if (plus < close) {
          // After hamplus: the non-dominant hand's actions (its changes start from its own
          // configuration).
          const bool outer = reading_nondominant_;
          reading_nondominant_ = true;
          read_actions(plus + 1, close, sign, &b);
          reading_nondominant_ = outer;
        }
        MovementStep step = join_parallel_steps(a);
        for (MovementStep& s : b) {
          step.nondominant.insert(step.nondominant.end(), s.dominant.begin(), s.dominant.end());
        }
        // "hamplus hamnomotion": the other hand stays, it does not follow the symmetry.
        if (plus < close && b.empty() && holds_nomotion(plus + 1, close))
          step.nondominant_stays = true;
        if (!step.nondominant.empty()) step.nondominant_stays = false;
        if (!step.dominant.empty() || !step.nondominant.empty()) steps->push_back(std::move(step));
        i = close < end ? close + 1 : end;
        last_is_fresh = !steps->empty() && !steps->back().dominant.empty();
      } else if (c == hamaltbegin) {
        // {a | b}: read the first alternative, skip the others.
        const std::size_t close = std::min(match_[i], end);
        std::size_t bar = i + 1;
        while (bar < close && s_[bar].code != hammetaalt) {
          if (closer_of(s_[bar].code) && match_[bar] < close) bar = match_[bar];
          ++bar;
        }
        read_actions(i + 1, bar, sign, steps);
        i = close < end ? close + 1 : end;
        last_is_fresh = false;
      } else if (starts_location(i)) {
        i = read_target(i, end, steps, &last_is_fresh);
      } else if (c == hamplus && starts_part(i + 1, end)) {
        i = read_part(i + 1, end, sign, steps);
        last_is_fresh = true;
      } else if (c == hamplus) {
        warning(i,
                "hamplus outside hamparbegin...hamparend: what follows is read as a change of the "
                "hand");
        ++i;
        last_is_fresh = false;
      } else if (is_shape_base(c) || in_group(c, HamGroup::ExtendedFinger) ||
                 in_group(c, HamGroup::Palm)) {
        warning(
            i, "a hand configuration after the start is read as a change (hamreplace) of the hand");
        i = read_replace(i, end, sign, steps);
        last_is_fresh = true;
      } else {
        error(i,
              "expected a movement, hamreplace, a location, a repetition or a group "
              "(hamseqbegin, hamparbegin, hamfusionbegin), found '" +
                  s_[i].text + "'");
        ++i;
      }
    }
  }

  Movement movement_of(std::size_t i) const {
    const char32_t c = s_[i].code;
    Movement m;
    if (in_group(c, HamGroup::StraightMovement)) {
      m.kind = MovementKind::Straight;
      m.direction = direction_of(c, "hammove");
    } else if (in_group(c, HamGroup::CircularMovement)) {
      m.kind = MovementKind::Circle;
      m.circle_axis = direction_of(c, "hamcircle");
    } else if (c == hamfingerplay) {
      m.kind = MovementKind::FingerPlay;
    } else if (c == hamnodding) {
      m.kind = MovementKind::WristNod;
    } else if (c == hamswinging) {
      m.kind = MovementKind::WristSwing;
    } else if (c == hamtwisting) {
      m.kind = MovementKind::WristTwist;
    } else if (c == hamstircw || c == hamstirccw) {
      m.kind = MovementKind::WristCircle;
      m.clockwise = c == hamstircw;
    } else if (in_group(c, HamGroup::Arc)) {  // an arc with no straight movement before it
      m.kind = MovementKind::Arc;
      m.arc_bulge = direction_of(c, "hamarc");
    } else if (c == hamwavy || c == hamzigzag) {
      m.kind = c == hamwavy ? MovementKind::Wavy : MovementKind::Zigzag;
    } else {  // hammovecross, hammoveX: a short straight movement of unspecified direction
      m.kind = MovementKind::Straight;
    }
    return m;
  }

  void modify(Movement* m, char32_t c) {
    if (in_group(c, HamGroup::Arc)) {
      if (m->kind == MovementKind::Straight) m->kind = MovementKind::Arc;
      m->arc_bulge = direction_of(c, "hamarc");
    } else if (c == hamwavy || c == hamzigzag) {
      m->kind = c == hamwavy ? MovementKind::Wavy : MovementKind::Zigzag;
    } else if (in_group(c, HamGroup::Ellipse)) {
      if (m->kind == MovementKind::Circle) m->kind = MovementKind::Ellipse;
      m->ellipse_axis = c == hamellipseh    ? Direction{1, 0, 0}
                        : c == hamellipsev  ? Direction{0, 1, 0}
                        : c == hamellipseur ? Direction{-1, 1, 0}
                                            : Direction{1, 1, 0};
    } else if (c == hamsmallmod) {
      m->size = Size::Small;
    } else if (c == hamlargemod) {
      m->size = Size::Large;
    } else if (c == hamfast || c == hamslow || c == hamtense || c == hamrest || c == hamhalt) {
      m->manner = c == hamfast    ? Manner::Fast
                  : c == hamslow  ? Manner::Slow
                  : c == hamtense ? Manner::Tense
                  : c == hamrest  ? Manner::Rest
                                  : Manner::Halt;
    } else if (c == hamalternatingmotion) {
      m->alternating = true;
    }
    // Clock positions, hamincreasing/hamdecreasing: read and not kept (see hamnosys.h).
  }

  // A location in action position: the target of the movement just read, else a Target move.
  std::size_t read_target(std::size_t i, std::size_t end, std::vector<MovementStep>* steps,
                          bool* fresh) {
    Movement* m = *fresh ? last_of(steps) : nullptr;
    Location loc = initial_dominant_.location;
    loc.contact = Contact::None;
    if (m && m->to_location) loc = *m->to_location;
    Location unused;
    bool unused_set = false;
    const std::size_t next = read_location(i, end, &loc, &unused, &unused_set);
    if (m && !m->to_location) {
      m->to_location = loc;
    } else if (m && m->kind == MovementKind::Replace) {
      m->to_location = loc;
    } else {
      Movement target;
      target.kind = MovementKind::Target;
      target.to_location = loc;
      MovementStep step;
      step.dominant.push_back(target);
      steps->push_back(std::move(step));
    }
    *fresh = true;
    return next;
  }

  // hamreplace (config | hand) [location]: a change of handshape/orientation (and place).
  std::size_t read_replace(std::size_t i, std::size_t end, SignSpec* sign,
                           std::vector<MovementStep>* steps) {
    (void)sign;
    Movement dom;
    dom.kind = MovementKind::Replace;
    std::optional<Movement> nd;
    bool other_stays = false;
    auto fill = [&](std::size_t from, std::size_t to, const HandSpec& initial, Movement* m) {
      HandSpec h;
      h.shape.hamnosys_base.clear();
      Orientation o = initial.orientation;
      const bool has_shape = from < to && is_shape_base(s_[from].code);
      std::size_t j = read_hand(from, to, &h, &o);
      if (has_shape) m->to_shape = h.shape;
      if (h.orientation != initial.orientation) m->to_orientation = h.orientation;
      return j;
    };
    const bool grouped = i < end && (s_[i].code == hamparbegin || s_[i].code == hamseqbegin) &&
                         match_[i] > i + 1 && match_[i] <= end && !starts_location(i);
    if (grouped && (s_[i].code == hamparbegin || find_plus(i + 1, match_[i]) < match_[i])) {
      const std::size_t close = match_[i];
      const std::size_t plus = find_plus(i + 1, close);
      std::size_t j = fill(i + 1, plus, initial_dominant_, &dom);
      if (j < plus) error(j, "expected a hand configuration, found '" + s_[j].text + "'");
      if (plus < close && plus + 2 == close && s_[plus + 1].code == hamnomotion) {
        // "hamreplace hamparbegin hand hamplus hamnomotion hamparend" (WHY3B): only the dominant
        // hand changes; the other keeps its configuration instead of following the symmetry.
        other_stays = true;
      } else if (plus < close) {
        Movement m;
        m.kind = MovementKind::Replace;
        j = fill(plus + 1, close, initial_nondominant_, &m);
        if (j < close) error(j, "expected a hand configuration, found '" + s_[j].text + "'");
        nd = m;
      }
      i = close < end ? close + 1 : end;
    } else {
      const std::size_t j =
          fill(i, end, reading_nondominant_ ? initial_nondominant_ : initial_dominant_, &dom);
      if (j == i && !(i < end && starts_location(i))) {
        if (i < end) {
          error(i, "expected a hand configuration after hamreplace, found '" + s_[i].text + "'");
        } else {
          error_at_end("expected a hand configuration after hamreplace, found the end of the sign");
        }
      }
      i = j;
    }
    MovementStep step;
    step.dominant.push_back(dom);
    if (nd) step.nondominant.push_back(*nd);
    step.nondominant_stays = other_stays;
    steps->push_back(std::move(step));
    bool fresh = true;
    while (i < end && (is_movement_modifier(s_[i].code) && !in_group(s_[i].code, HamGroup::Arc))) {
      modify(&steps->back().dominant.back(), s_[i].code);
      ++i;
    }
    if (i < end && starts_location(i)) i = read_target(i, end, steps, &fresh);
    return i;
  }

  // {a | b | c} -> a: HamNoSys alternatives are resolved to the first one before reading (the
  // others are variants of the same sign). An alternative left open runs to the end.
  static std::vector<HamSymbolRef> first_alternatives(const std::vector<HamSymbolRef>& in) {
    std::vector<HamSymbolRef> out;
    int depth = 0;         // nesting of hamaltbegin
    int skipping_at = -1;  // depth at which we skip (after hammetaalt)
    for (const HamSymbolRef& r : in) {
      if (r.code == hamaltbegin) {
        ++depth;
        continue;
      }
      if (r.code == hamaltend && depth > 0) {
        if (skipping_at == depth) skipping_at = -1;
        --depth;
        continue;
      }
      if (r.code == hammetaalt && depth > 0) {
        if (skipping_at < 0) skipping_at = depth;
        continue;
      }
      if (skipping_at < 0) out.push_back(r);
    }
    return out;
  }

  const std::vector<HamSymbolRef> s_;
  std::vector<Diagnostic>* diags_;
  std::vector<std::size_t> match_;
  std::vector<bool> skip_;
  // The reader recurses once per group level: the limit keeps hostile input from exhausting the
  // stack (WASM's is small).
  static constexpr std::size_t kMaxGroupDepth = 32;
  bool too_deep_ = false;
  bool own_side_dominant_ = false;
  bool alternate_all_ = false;
  bool reading_nondominant_ = false;  // inside the part after hamplus of an action group
  HandSpec initial_dominant_, initial_nondominant_;
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ','; }

}  // namespace

std::vector<HamSymbolRef> tokenize_hamnosys(std::string_view text, std::size_t begin,
                                            std::size_t end, std::vector<Diagnostic>* diagnostics) {
  return tokenize_hamnosys(text, LineIndex(text), begin, end, diagnostics);
}

std::vector<HamSymbolRef> tokenize_hamnosys(std::string_view text, const LineIndex& index,
                                            std::size_t begin, std::size_t end,
                                            std::vector<Diagnostic>* diagnostics) {
  std::vector<HamSymbolRef> out;
  std::size_t i = begin;
  while (i < end) {
    const char ch = text[i];
    if (is_space(ch) || ch == ';') {
      ++i;
      continue;
    }
    HamSymbolRef r;
    r.offset = i;
    if ((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z')) {
      while (i < end && ((text[i] >= 'a' && text[i] <= 'z') || (text[i] >= 'A' && text[i] <= 'Z') ||
                         (text[i] >= '0' && text[i] <= '9') || text[i] == '_')) {
        ++i;
      }
      r.text = std::string(text.substr(r.offset, i - r.offset));
      const HamSymbolInfo* info = ham_symbol_by_name(r.text);
      if (!info) {
        diagnostics->push_back(
            index.make(r.offset, i - r.offset, r.text,
                       "unknown HamNoSys symbol name '" + r.text +
                           "': expected a name such as hamflathand (docs/hamnosys-symbols.tsv)"));
        continue;
      }
      r.code = info->code;
    } else {
      const char32_t cp = decode_utf8(text, &i);
      if (i > end) i = end;
      const HamSymbolInfo* info = ham_symbol_by_code(cp);
      r.text = info ? info->name : code_point_label(cp);
      if (!info) {
        diagnostics->push_back(
            index.make(r.offset, i - r.offset, r.text,
                       "unknown HamNoSys symbol " + r.text +
                           ": expected a HamNoSys 4 code point (U+E000..U+E0F1) or a symbol name"));
        continue;
      }
      r.code = cp;
    }
    r.length = i - r.offset;
    index.locate(r.offset, &r.line, &r.column);
    out.push_back(std::move(r));
  }
  return out;
}

bool parse_hamnosys_symbols(const std::vector<HamSymbolRef>& symbols, std::size_t sign_offset,
                            SignSpec* sign, std::vector<Diagnostic>* diagnostics) {
  (void)sign_offset;
  Reader reader(symbols, diagnostics);
  return reader.read(sign);
}

std::vector<SignParse> parse_hamnosys_text(std::string_view text) {
  std::vector<SignParse> out;
  const LineIndex index(text);
  for (const TextLine& line : split_lines(text)) {
    std::size_t end = text.find('#', line.start);  // a comment runs to the end of the line
    if (end == std::string_view::npos || end > line.end) end = line.end;
    std::size_t a = line.start;
    while (a < end && is_space(text[a])) ++a;
    std::size_t b = end;
    while (b > a && is_space(text[b - 1])) --b;
    if (a < b) {
      SignParse sign;
      sign.offset = a;
      sign.line = line.number;
      std::size_t symbols_start = a;
      const std::size_t eq = text.substr(a, b - a).find('=');
      if (eq != std::string_view::npos) {
        std::size_t g_end = a + eq;
        while (g_end > a && is_space(text[g_end - 1])) --g_end;
        sign.gloss = std::string(text.substr(a, g_end - a));
        symbols_start = a + eq + 1;
      }
      const std::vector<HamSymbolRef> symbols =
          tokenize_hamnosys(text, index, symbols_start, b, &sign.diagnostics);
      SignSpec spec;
      spec.gloss = sign.gloss;
      if (symbols.empty()) {
        sign.diagnostics.push_back(index.make(symbols_start, b - symbols_start, "",
                                              "expected HamNoSys symbols, found none"));
      } else if (parse_hamnosys_symbols(symbols, a, &spec, &sign.diagnostics)) {
        sign.spec = std::move(spec);
      }
      out.push_back(std::move(sign));
    }
  }
  return out;
}

}  // namespace sw::notation

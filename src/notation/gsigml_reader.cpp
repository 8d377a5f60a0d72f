// Reader of G-SiGML hamgestural_sign elements (the gestural SiGML of the eSIGN/JASigning tools):
// sign_nonmanual tiers and sign_manual's handconfig / split_handconfig, location_bodyarm,
// location_hand, split_location, handconstellation and the motions (directedmotion,
// circularmotion, wristmotion, fingerplay, nomotion, tgt_motion, rpt_motion, par_motion,
// seq_motion, split_motion). Handshapes are spelled as HamNoSys words and built by handshape.h;
// location names are HamNoSys names without "ham" (hamnosys_places.h).
//
// Does not keep: clock positions of circles (start/end), ceeopening, contactpair, speed factors,
// body/shoulder/eyelid tiers (SignSpec has no field for them); they are read and skipped.
#include <array>
#include <map>
#include <string>

#include "notation/formula.h"
#include "notation/hamnosys_places.h"
#include "notation/hamnosys_symbols.h"
#include "notation/handshape.h"
#include "notation/parallel_steps.h"
#include "notation/sigml.h"

namespace sw::notation {
namespace {

using Attributes = std::map<std::string, std::string>;

Direction between(const Direction& a, const Direction& b) {
  auto sign = [](int v) { return static_cast<std::int8_t>(v > 0 ? 1 : v < 0 ? -1 : 0); };
  return Direction{sign(a.x + b.x), sign(a.y + b.y), sign(a.z + b.z)};
}

// A G-SiGML direction value: letters u/d, l/r, o/i, a letter possibly written twice or thrice
// ("uuo": between u and uo, the doubled letter weighing more, as HamNoSys writes two direction
// symbols side by side). SignSpec's Direction has one step per axis, so the sum of the letters
// keeps each axis's sign ("uuo" -> uo). Opposite letters of one axis ("ud") are no direction.
bool sigml_direction(std::string_view word, Direction* d) {
  if (word.empty() || word.size() > 6) return false;
  int sum[3] = {0, 0, 0};
  bool up = false, down = false, left = false, right = false, out = false, in = false;
  for (char c : word) {
    switch (c) {
      case 'u':
        up = true;
        ++sum[1];
        break;
      case 'd':
        down = true;
        --sum[1];
        break;
      case 'l':
        left = true;
        ++sum[0];
        break;  // +X is the signer's left
      case 'r':
        right = true;
        --sum[0];
        break;
      case 'o':
        out = true;
        ++sum[2];
        break;  // away from the body
      case 'i':
        in = true;
        --sum[2];
        break;
      default:
        return false;
    }
  }
  if ((up && down) || (left && right) || (out && in)) return false;
  auto sign = [](int v) { return static_cast<std::int8_t>(v > 0 ? 1 : v < 0 ? -1 : 0); };
  *d = Direction{sign(sum[0]), sign(sum[1]), sign(sum[2])};
  return true;
}

// A numeric G-SiGML bend ("410"): one digit per joint from the knuckle to the tip, each the
// joint's flexion in quarters of a right angle (0 straight .. 4 fully bent), the explicit form
// beside the named bends. SignSpec keeps named bends only: the digits map to the nearest one
// (knuckle bent alone: bent; tip joints alone: hooked; knuckle and middle: double-bent; all:
// double-hooked; all partly: round; none: straight). Returns 0 when `value` is not numeric.
char32_t numeric_bend(std::string_view value) {
  if (value.empty() || value.size() > 3) return 0;
  int joint[3] = {0, 0, 0};
  for (std::size_t k = 0; k < value.size(); ++k) {
    if (value[k] < '0' || value[k] > '4') return 0;
    joint[k] = value[k] - '0';
  }
  const bool base = joint[0] >= 3, middle = joint[1] >= 3, tip = joint[2] >= 3;
  if (base && middle && tip) return hamdoublehooked;
  if (base && middle) return hamdoublebent;
  if (base) return hamfingerbendmod;
  if (middle || tip) return hamfingerhookmod;
  if (joint[0] + joint[1] + joint[2] >= 3) return kShapeRound;
  return hamfingerstraightmod;
}

bool same_orientation(const Orientation& a, const Orientation& b) {
  return a.extended_finger == b.extended_finger && a.palm == b.palm && a.seed_palm == b.seed_palm;
}

class GReader {
 public:
  explicit GReader(SignParse* out) : out_(out) {}

  void read(const XmlElement& sign) {
    if (const std::string* g = sign.attribute("gloss")) out_->gloss = *g;
    spec_.gloss = out_->gloss;
    const XmlElement* manual = nullptr;
    for (const XmlElement& c : sign.children) {
      if (c.name == "sign_manual") {
        manual = &c;
      } else if (c.name == "sign_nonmanual") {
        read_nonmanual(c);
      } else {
        warn(c,
             "expected sign_manual or sign_nonmanual in hamgestural_sign, found <" + c.name + ">");
      }
    }
    if (!manual) {
      error(sign, "hamgestural_sign", "expected a <sign_manual> element, found none");
      return;
    }
    read_manual(*manual);
    if (!failed_) out_->spec = std::move(spec_);
  }

 private:
  // ---- diagnostics
  void report(const XmlElement& e, std::string symbol, std::string message, Severity severity) {
    out_->diagnostics.push_back(diagnostic_at(e, std::move(symbol), std::move(message), severity));
  }
  void error(const XmlElement& e, std::string symbol, std::string message) {
    report(e, std::move(symbol), std::move(message), Severity::Error);
  }
  void warn(const XmlElement& e, std::string message) {
    report(e, e.name, std::move(message), Severity::Warning);
  }
  void bad_value(const XmlElement& e, const std::string& attr, const std::string& value,
                 const char* expected) {
    error(e, attr + "=\"" + value + "\"",
          "expected " + std::string(expected) + " for " + attr + " in <" + e.name + ">, found '" +
              value + "'");
  }

  bool direction(const XmlElement& e, const char* attr, Direction* out) {
    const std::string* v = e.attribute(attr);
    if (!v) return false;
    if (!sigml_direction(*v, out)) {
      bad_value(e, attr, *v, "a direction (letters u/d, l/r, o/i, never both of a pair)");
      return false;
    }
    return true;
  }
  bool flag(const XmlElement& e, const char* attr) {
    const std::string* v = e.attribute(attr);
    return v && *v == "true";
  }

  // ---- non-manual tiers
  void read_nonmanual(const XmlElement& e) {
    for (const XmlElement& tier : e.children) {
      for (const XmlElement& item : tier.children) read_nonmanual_item(item);
      read_nonmanual_item(tier);  // a tier written without its wrapper
    }
  }
  void read_nonmanual_item(const XmlElement& item) {
    NonManual& n = spec_.nonmanual;
    const std::string* movement = item.attribute("movement");
    if (item.name == "mouth_picture") {
      if (const std::string* p = item.attribute("picture"))
        n.mouthing += (n.mouthing.empty() ? "" : " ") + *p;
    } else if (item.name == "mouth_gesture" && movement) {
      n.mouth_gesture = *movement;
    } else if (item.name == "eye_brows" && movement) {
      // SiGML codes: RB raised brows, FU furrowed; others kept as written.
      n.eyebrows = *movement == "RB" ? "up" : *movement == "FU" ? "down" : *movement;
    } else if (item.name == "head_movement" && movement) {
      n.head = *movement == "NO"   ? "nod"
               : *movement == "SH" ? "shake"
               : *movement == "TL" ? "tilt_l"
               : *movement == "TR" ? "tilt_r"
                                   : *movement;
    } else if (item.name == "eye_gaze") {
      const std::string* d = item.attribute("direction");
      if (d)
        n.gaze = *d == "AD" ? "addressee" : *d == "HC" ? "hands" : *d;
      else if (movement)
        n.gaze = *movement == "UP" ? "up" : *movement;
    }
    // body_movement, shoulder_movement, eye_lids, extra_movement: no SignSpec field (see top).
  }

  // ---- hand configuration: attributes accumulate over consecutive handconfig elements
  void merge(const XmlElement& e, Attributes* into) {
    for (const XmlAttribute& a : e.attributes) (*into)[a.name] = a.value;
    attr_source_[into] = &e;
  }

  bool shape_word(const XmlElement& e, const std::string& attr, const std::string& value,
                  std::vector<char32_t>* words) {
    static const std::map<std::string, char32_t> kBases = {{"fist", hamfist},
                                                           {"flat", hamflathand},
                                                           {"finger2", hamfinger2},
                                                           {"finger23", hamfinger23},
                                                           {"finger23spread", hamfinger23spread},
                                                           {"finger2345", hamfinger2345},
                                                           {"pinch12", hampinch12},
                                                           {"pinchall", hampinchall},
                                                           {"pinch12open", hampinch12open},
                                                           {"cee12", hamcee12},
                                                           {"ceeall", hamceeall},
                                                           {"cee12open", hamceeopen}};
    static const std::map<std::string, char32_t> kThumbs = {
        {"out", hamthumboutmod}, {"across", hamthumbacrossmod}, {"opposed", hamthumbopenmod}};
    static const std::map<std::string, char32_t> kBends = {{"straight", hamfingerstraightmod},
                                                           {"bent", hamfingerbendmod},
                                                           {"round", kShapeRound},
                                                           {"hooked", hamfingerhookmod},
                                                           {"dblbent", hamdoublebent},
                                                           {"dblhooked", hamdoublehooked}};
    const bool is_shape = attr == "handshape" || attr == "second_handshape";
    const bool is_thumb = attr == "thumbpos" || attr == "second_thumbpos";
    const auto& table = is_shape ? kBases : is_thumb ? kThumbs : kBends;
    if (!is_shape && !is_thumb) {
      if (const char32_t bend = numeric_bend(value)) {
        words->push_back(bend);
        return true;
      }
    }
    const auto it = table.find(value);
    if (it == table.end()) {
      bad_value(e, attr, value,
                is_shape   ? "a handshape (fist, flat, finger2, finger23, finger23spread, "
                             "finger2345, pinch12, pinchall, pinch12open, cee12, ceeall, cee12open)"
                : is_thumb ? "a thumb position (out, across, opposed)"
                           : "a bending (straight, bent, round, hooked, dblbent, dblhooked, or "
                             "joint digits 0-4 such as 410)");
      return false;
    }
    words->push_back(it->second);
    return true;
  }

  // Applies accumulated handconfig attributes to `hand`; orientation starts from `base`.
  // Returns whether a handshape was given.
  bool apply(const Attributes& a, HandSpec* hand, const Orientation& base) {
    const auto source = attr_source_.find(&a);
    const XmlElement& e = source == attr_source_.end() ? no_element_ : *source->second;
    auto get = [&](const char* k) -> const std::string* {
      const auto it = a.find(k);
      return it == a.end() ? nullptr : &it->second;
    };
    bool has_shape = false;
    if (const std::string* shape = get("handshape")) {
      std::vector<char32_t> words;
      bool ok = shape_word(e, "handshape", *shape, &words);
      if (const std::string* t = get("thumbpos")) ok = shape_word(e, "thumbpos", *t, &words) && ok;
      if (const std::string* b = get("mainbend")) ok = shape_word(e, "mainbend", *b, &words) && ok;
      for (int k = 1; k <= 5; ++k) {
        const std::string key = "bend" + std::to_string(k);
        if (const std::string* b = get(key.c_str())) {
          words.push_back(hamthumb + static_cast<char32_t>(k - 1));
          ok = shape_word(e, key, *b, &words) && ok;
        }
      }
      if (const std::string* special = get("specialfingers")) {
        for (char c : *special) {
          if (c < '1' || c > '5') {
            bad_value(e, "specialfingers", *special, "finger digits 1..5");
            ok = false;
            break;
          }
          words.push_back(hamthumb + static_cast<char32_t>(c - '1'));
        }
      }
      if (const std::string* second = get("second_handshape")) {
        words.push_back(hambetween);
        ok = shape_word(e, "second_handshape", *second, &words) && ok;
        if (const std::string* t = get("second_thumbpos"))
          ok = shape_word(e, "second_thumbpos", *t, &words) && ok;
        if (const std::string* b = get("second_mainbend"))
          ok = shape_word(e, "second_mainbend", *b, &words) && ok;
      }
      if (ok) {
        ShapeError err;
        HandShape built;
        if (build_handshape(words, &built, &err)) {
          hand->shape = built;
          has_shape = true;
        } else {
          error(e, *shape, err.message);
        }
      }
    }
    hand->orientation = base;
    Direction d;
    auto dir = [&](const char* k, Direction* out) {
      const std::string* v = get(k);
      if (!v) return false;
      if (!sigml_direction(*v, out)) {
        bad_value(e, k, *v, "a direction (letters u/d, l/r, o/i, never both of a pair)");
        return false;
      }
      return true;
    };
    if (dir("extfidir", &d)) {
      Direction second;
      if (dir("second_extfidir", &second)) d = between(d, second);
      hand->orientation.extended_finger = d;
    }
    if (dir("palmor", &d)) {
      Direction second;
      if (dir("second_palmor", &second)) d = between(d, second);
      hand->orientation.palm = d;
    }
    return has_shape;
  }

  // ---- locations
  bool level_or_place(const XmlElement& e, const std::string& value, Location* loc) {
    if (value == "neutralspace") {
      loc->kind = Location::Kind::NeutralSpace;
      loc->level = BodyLevel::NeutralSpace;
      return true;
    }
    const HamSymbolInfo* s = ham_symbol_by_name("ham" + value);
    if (s && s->group == HamGroup::LocationBody) {
      loc->kind = Location::Kind::Body;
      loc->level = level_of(s->code);
      return true;
    }
    if (s && (s->group == HamGroup::LocationArmHand || s->group == HamGroup::LocationFinger)) {
      loc->kind = Location::Kind::OtherHand;
      loc->hand_place = place_of(s->code);
      return true;
    }
    static const std::map<std::string, HandPlace> kHandPlaces = {
        {"tip", HandPlace::Fingertip},   {"nail", HandPlace::FingerNail},
        {"pad", HandPlace::FingerPad},   {"midjoint", HandPlace::FingerMiddleJoint},
        {"base", HandPlace::FingerBase}, {"side", HandPlace::FingerSide}};
    const auto it = kHandPlaces.find(value);
    if (it != kHandPlaces.end()) {
      loc->kind = Location::Kind::OtherHand;
      loc->hand_place = it->second;
      return true;
    }
    bad_value(e, "location", value,
              "a body or hand location (shoulders, chest, chin, ..., tip, nail, palm, ...)");
    return false;
  }
  void side(const XmlElement& e, Location* loc) {
    const std::string* v = e.attribute("side");
    if (!v) return;
    if (*v == "right_at")
      loc->side = Side::Right;
    else if (*v == "left_at")
      loc->side = Side::Left;
    else if (*v == "right_beside")
      loc->side = Side::RightBeside;
    else if (*v == "left_beside")
      loc->side = Side::LeftBeside;
    // palmar / dorsal: the side of a hand or arm, no SignSpec field (see top).
  }
  bool contact(const XmlElement& e, Contact* c) {
    const std::string* v = e.attribute("contact");
    if (!v) return false;
    static const std::map<std::string, Contact> kContacts = {{"touch", Contact::Touch},
                                                             {"close", Contact::Close},
                                                             {"armextended", Contact::ArmExtended},
                                                             {"brush", Contact::Brush},
                                                             {"interlock", Contact::Interlock},
                                                             {"cross", Contact::Cross},
                                                             {"behind", Contact::Behind},
                                                             {"grasp", Contact::Grasp}};
    const auto it = kContacts.find(*v);
    if (it == kContacts.end()) {
      bad_value(e, "contact", *v,
                "a contact (touch, close, armextended, brush, interlock, cross, behind, grasp)");
      return false;
    }
    *c = it->second;
    return true;
  }
  void digits(const XmlElement& e, std::int8_t* finger) {
    const std::string* v = e.attribute("digits");
    if (!v || v->empty()) return;
    if ((*v)[0] < '1' || (*v)[0] > '5') {
      bad_value(e, "digits", *v, "finger digits 1..5");
      return;
    }
    *finger = static_cast<std::int8_t>((*v)[0] - '1');
  }
  // location_hand: a place on a hand (the other hand's, or this hand's part in a constellation).
  Location hand_location(const XmlElement& e) {
    Location loc;
    if (const std::string* v = e.attribute("location")) level_or_place(e, *v, &loc);
    loc.kind = Location::Kind::OtherHand;
    loc.level = BodyLevel::NeutralSpace;
    digits(e, &loc.finger);
    side(e, &loc);
    contact(e, &loc.contact);
    return loc;
  }
  Location bodyarm_location(const XmlElement& e) {
    Location loc;
    if (const std::string* v = e.attribute("location")) level_or_place(e, *v, &loc);
    side(e, &loc);
    contact(e, &loc.contact);
    for (const XmlElement& c : e.children) {
      if (c.name == "location_hand") {  // the part of this hand that is there
        const Location part = hand_location(c);
        loc.contact_part = part.hand_place;
        loc.contact_finger = part.finger;
      }
    }
    return loc;
  }
  bool is_location(const XmlElement& e) const {
    return e.name == "location_bodyarm" || e.name == "location_hand" ||
           e.name == "split_location" || e.name == "handconstellation";
  }
  // Reads a location element into the dominant (and non-dominant) locations.
  void location(const XmlElement& e, Location* dom, Location* nd, bool* nd_set) {
    if (e.name == "location_bodyarm") {
      *dom = bodyarm_location(e);
    } else if (e.name == "location_hand") {
      *dom = hand_location(e);
    } else if (e.name == "split_location") {
      if (e.children.size() == 1) {
        // One location: the dominant hand's; the other hand keeps its own (SiGML allows the
        // non-dominant part to be left out).
        location(e.children[0], dom, nullptr, nullptr);
        return;
      }
      if (e.children.size() != 2) {
        error(e, "split_location",
              "expected one or two locations (dominant, non-dominant) in split_location, found " +
                  std::to_string(e.children.size()));
        return;
      }
      location(e.children[0], dom, nullptr, nullptr);
      if (nd) {
        Location unused;
        location(e.children[1], nd, &unused, nullptr);
        if (nd_set) *nd_set = true;
      }
    } else {  // handconstellation
      std::vector<const XmlElement*> hands;
      const XmlElement* body = nullptr;
      for (const XmlElement& c : e.children) {
        if (c.name == "location_hand") hands.push_back(&c);
        if (c.name == "location_bodyarm") body = &c;
      }
      Contact c = dom->contact;
      const bool has_contact = contact(e, &c);
      if (hands.size() >= 2) {
        const Location part = hand_location(*hands[0]);
        Location place = hand_location(*hands[1]);
        place.contact_part = part.hand_place;
        place.contact_finger = part.finger;
        place.contact = Contact::None;
        *dom = place;
      } else if (hands.size() == 1) {
        *dom = hand_location(*hands[0]);
      }
      if (body) {
        const Location where = bodyarm_location(*body);
        if (hands.empty()) {
          *dom = where;
        } else if (nd && nd_set) {
          *nd = where;
          *nd_set = true;
        }
      }
      if (has_contact) dom->contact = c;
    }
  }

  // ---- manual part
  void read_manual(const XmlElement& m) {
    if (!m.children.empty() && m.children[0].name == "sign_manual") {
      // A compound: sign_manual parts one after the other. The first part is the sign's start;
      // each later part's configuration and place are a change (tgt_motion), then its motions.
      read_manual(m.children[0]);
      if (failed_) return;
      for (std::size_t p = 1; p < m.children.size(); ++p) {
        const XmlElement& part = m.children[p];
        if (part.name != "sign_manual") {
          motion(part, &spec_.movements, false);
          continue;
        }
        XmlElement change;
        change.name = "tgt_motion";
        change.offset = part.offset, change.length = part.length, change.line = part.line,
        change.column = part.column;
        std::size_t i = 0;
        while (i < part.children.size() &&
               (part.children[i].name == "handconfig" ||
                part.children[i].name == "split_handconfig" || is_location(part.children[i]))) {
          change.children.push_back(part.children[i++]);
        }
        if (!change.children.empty()) target(change, &spec_.movements, false);
        for (; i < part.children.size(); ++i) motion(part.children[i], &spec_.movements, false);
      }
      return;
    }
    const bool both = flag(m, "both_hands"), lr = flag(m, "lr_symm"), ud = flag(m, "ud_symm"),
               oi = flag(m, "oi_symm");
    if (lr)
      spec_.symmetry = ud ? Symmetry::MirrorLRUD : oi ? Symmetry::MirrorLRIO : Symmetry::MirrorLR;
    else if (both)
      spec_.symmetry = ud ? Symmetry::ParallelUD : oi ? Symmetry::ParallelIO : Symmetry::Parallel;
    const bool out_of_phase = flag(m, "outofphase");
    // A one-handed sign of the non-dominant hand (checked below, once the hands are known).
    const bool nondominant_signs = flag(m, "nondominant");

    // Initial configuration and location: everything before the first motion.
    Attributes dom_attrs, nd_attrs;
    bool split = false;
    std::size_t i = 0;
    for (; i < m.children.size(); ++i) {
      const XmlElement& c = m.children[i];
      if (c.name == "handconfig") {
        merge(c, &dom_attrs);
      } else if (c.name == "split_handconfig") {
        if (c.children.size() != 2) {
          error(c, "split_handconfig",
                "expected two handconfig elements (dominant, non-dominant) in split_handconfig, "
                "found " +
                    std::to_string(c.children.size()));
          continue;
        }
        merge(c.children[0], &dom_attrs);
        merge(c.children[1], &nd_attrs);
        split = true;
      } else {
        break;
      }
    }
    if (dom_attrs.empty() || dom_attrs.find("handshape") == dom_attrs.end()) {
      error(m, "sign_manual",
            "expected a handconfig with a handshape at the start of sign_manual, found " +
                (i < m.children.size() ? "<" + m.children[i].name + ">" : std::string("none")));
      failed_ = true;
      return;
    }
    const Orientation default_orientation;
    apply(dom_attrs, &spec_.dominant, default_orientation);
    if (split) {
      HandSpec nd = spec_.dominant;  // what it does not say is as the dominant hand has it
      apply(nd_attrs, &nd, spec_.dominant.orientation);
      spec_.nondominant = nd;
    }
    Location nd_location;
    bool nd_location_set = false;
    for (; i < m.children.size() && is_location(m.children[i]); ++i) {
      location(m.children[i], &spec_.dominant.location, &nd_location, &nd_location_set);
    }
    if (nd_location_set) {
      if (!spec_.nondominant) spec_.nondominant = spec_.dominant;
      spec_.nondominant->location = nd_location;
    }
    // The other hand is a still place only without a symmetry (lr_symm / both_hands), as the
    // HamNoSys reader has it (hamnosys_parser.cpp): with one, both hands make the motions, the
    // non-dominant one mirrored, and the contact is between them.
    if (spec_.dominant.location.kind == Location::Kind::OtherHand &&
        spec_.symmetry == Symmetry::None)
      spec_.nondominant_is_place = true;
    spec_.one_hand_is_nondominant =
        nondominant_signs && !spec_.nondominant && spec_.symmetry == Symmetry::None;
    initial_dom_ = spec_.dominant;
    initial_nd_ = spec_.nondominant ? *spec_.nondominant : spec_.dominant;
    posture_[0] = Posture{initial_dom_, false};
    posture_[1] = Posture{initial_nd_, false};
    // Motions.
    for (; i < m.children.size(); ++i) motion(m.children[i], &spec_.movements, false);
    if (out_of_phase) {
      for (MovementStep& s : spec_.movements) {
        for (Movement& mv : s.dominant) mv.alternating = true;
        for (Movement& mv : s.nondominant) mv.alternating = true;
      }
    }
  }

  void manner(const XmlElement& e, Movement* m) {
    if (flag(e, "fast")) m->manner = Manner::Fast;
    if (flag(e, "slow")) m->manner = Manner::Slow;
    if (flag(e, "tense")) m->manner = Manner::Tense;
    if (flag(e, "halt")) m->manner = Manner::Halt;
    if (flag(e, "rest")) m->manner = Manner::Rest;
    if (const std::string* s = e.attribute("size")) {
      if (*s == "small")
        m->size = Size::Small;
      else if (*s == "big" || *s == "large")
        m->size = Size::Large;
      else
        bad_value(e, "size", *s, "small or big");
    }
    if (flag(e, "alternating")) m->alternating = true;
  }

  static void push(std::vector<MovementStep>* steps, const Movement& m, bool nondominant) {
    MovementStep s;
    (nondominant ? s.nondominant : s.dominant).push_back(m);
    steps->push_back(std::move(s));
  }

  void motion(const XmlElement& e, std::vector<MovementStep>* steps, bool nondominant) {
    Movement m;
    if (e.name == "directedmotion") {
      m.kind = MovementKind::Straight;
      direction(e, "direction", &m.direction);
      Direction second;
      if (direction(e, "second_direction", &second)) m.direction = between(m.direction, second);
      if (direction(e, "curve", &m.arc_bulge)) m.kind = MovementKind::Arc;
      if (const std::string* z = e.attribute("zigzag_style")) {
        if (*z == "wavy")
          m.kind = MovementKind::Wavy;
        else if (*z == "zigzag")
          m.kind = MovementKind::Zigzag;
        else
          bad_value(e, "zigzag_style", *z, "wavy or zigzag");
      }
      if (const std::string* el = e.attribute("ellipse_direction")) ellipse(e, *el, &m);
      manner(e, &m);
      push(steps, m, nondominant);
    } else if (e.name == "circularmotion") {
      m.kind = MovementKind::Circle;
      direction(e, "axis", &m.circle_axis);
      if (const std::string* el = e.attribute("ellipse_direction")) {
        ellipse(e, *el, &m);
        m.kind = MovementKind::Ellipse;
      }
      manner(e, &m);
      push(steps, m, nondominant);
    } else if (e.name == "wristmotion") {
      const std::string* w = e.attribute("motion");
      const std::string v = w ? *w : "";
      if (v == "nodding")
        m.kind = MovementKind::WristNod;
      else if (v == "swinging")
        m.kind = MovementKind::WristSwing;
      else if (v == "twisting")
        m.kind = MovementKind::WristTwist;
      else if (v == "stircw" || v == "stirccw")
        m.kind = MovementKind::WristCircle, m.clockwise = v == "stircw";
      else {
        bad_value(e, "motion", v, "nodding, swinging, twisting, stircw or stirccw");
        return;
      }
      manner(e, &m);
      push(steps, m, nondominant);
    } else if (e.name == "fingerplay") {
      m.kind = MovementKind::FingerPlay;
      manner(e, &m);
      push(steps, m, nondominant);
    } else if (e.name == "nomotion") {
      // no movement
    } else if (e.name == "tgt_motion") {
      target(e, steps, nondominant);
    } else if (e.name == "rpt_motion") {
      repeat(e, steps, nondominant);
    } else if (e.name == "seq_motion") {
      for (const XmlElement& c : e.children) motion(c, steps, nondominant);
    } else if (e.name == "par_motion") {
      std::vector<MovementStep> inner;
      for (const XmlElement& c : e.children) motion(c, &inner, nondominant);
      if (!inner.empty()) steps->push_back(join_parallel_steps(inner));
    } else if (e.name == "split_motion") {
      if (e.children.size() != 2) {
        error(e, "split_motion",
              "expected two motions (dominant, non-dominant) in split_motion, found " +
                  std::to_string(e.children.size()));
        return;
      }
      std::vector<MovementStep> inner;
      motion(e.children[0], &inner, false);
      motion(e.children[1], &inner, true);
      if (inner.empty()) return;
      MovementStep step = join_parallel_steps(inner);
      // <nomotion/> for the other hand: it stays, it does not follow the symmetry.
      if (e.children[1].name == "nomotion" && step.nondominant.empty())
        step.nondominant_stays = true;
      steps->push_back(std::move(step));
    } else if (e.name == "handconfig" || e.name == "split_handconfig" || is_location(e)) {
      // A configuration or place after the motions began: a change to it, as tgt_motion says.
      XmlElement wrapper;
      wrapper.name = "tgt_motion";
      wrapper.offset = e.offset, wrapper.length = e.length, wrapper.line = e.line,
      wrapper.column = e.column;
      wrapper.children.push_back(e);
      target(wrapper, steps, nondominant);
    } else {
      warn(e,
           "expected a motion element (directedmotion, circularmotion, wristmotion, fingerplay, "
           "nomotion, tgt_motion, rpt_motion, par_motion, seq_motion, split_motion), found <" +
               e.name + ">: skipped");
    }
  }

  void ellipse(const XmlElement& e, const std::string& v, Movement* m) {
    if (v == "h")
      m->ellipse_axis = Direction{1, 0, 0};
    else if (v == "v")
      m->ellipse_axis = Direction{0, 1, 0};
    else if (v == "ur")
      m->ellipse_axis = Direction{-1, 1, 0};
    else if (v == "ul")
      m->ellipse_axis = Direction{1, 1, 0};
    else
      bad_value(e, "ellipse_direction", v, "h, v, ur or ul");
  }

  // tgt_motion: [motion...] [changeposture] [handconfig|split_handconfig] [location...]
  void target(const XmlElement& e, std::vector<MovementStep>* steps, bool nondominant) {
    std::vector<MovementStep> inner;
    Attributes dom_attrs, nd_attrs;
    bool has_config = false, split = false;
    const XmlElement* location_el = nullptr;
    for (const XmlElement& c : e.children) {
      if (c.name == "changeposture") {
      } else if (c.name == "handconfig") {
        merge(c, &dom_attrs);
        has_config = true;
      } else if (c.name == "split_handconfig" && c.children.size() == 2) {
        merge(c.children[0], &dom_attrs);
        merge(c.children[1], &nd_attrs);
        has_config = split = true;
      } else if (is_location(c)) {
        location_el = &c;
      } else {
        motion(c, &inner, nondominant);
      }
    }
    const HandSpec& initial = nondominant ? initial_nd_ : initial_dom_;
    Movement change;
    change.kind = MovementKind::Replace;
    if (has_config) change_posture(dom_attrs, nondominant ? 1 : 0, &change);
    std::optional<Location> to;
    if (location_el) {
      Location loc = initial.location;
      loc.contact = Contact::None;
      Location unused;
      bool unused_set = false;
      location(*location_el, &loc, &unused, &unused_set);
      to = loc;
    }
    Movement* carrier = nullptr;  // the movement the target belongs to
    if (!inner.empty()) {
      MovementStep& last = inner.back();
      std::vector<Movement>& list =
          nondominant || last.dominant.empty() ? last.nondominant : last.dominant;
      if (!list.empty()) carrier = &list.back();
    }
    if (carrier && !has_config) {
      if (to) carrier->to_location = to;
      manner(e, carrier);
    } else if (has_config || to) {
      if (!has_config) change.kind = MovementKind::Target;
      change.to_location = to;
      manner(e, &change);
      if (!inner.empty()) {
        (nondominant ? inner.back().nondominant : inner.back().dominant).push_back(change);
      } else {
        push(&inner, change, nondominant);
      }
      if (split) {
        Movement nd_change;
        nd_change.kind = MovementKind::Replace;
        change_posture(nd_attrs, 1, &nd_change);
        inner.back().nondominant.push_back(nd_change);
      }
    } else if (carrier) {
      manner(e, carrier);
    }
    steps->insert(steps->end(), inner.begin(), inner.end());
  }

  void repeat(const XmlElement& e, std::vector<MovementStep>* steps, bool nondominant) {
    const std::string* r = e.attribute("repetition");
    RepeatKind kind = RepeatKind::FromStart;
    if (r) {
      if (*r == "fromstart")
        kind = RepeatKind::FromStart;
      else if (*r == "fromstart_several")
        kind = RepeatKind::FromStartSeveral;
      else if (*r == "continue")
        kind = RepeatKind::Continuing;
      else if (*r == "continue_several")
        kind = RepeatKind::ContinuingSeveral;
      else if (*r == "reverse" || *r == "tofroto")
        kind = RepeatKind::Reverse;
      else
        bad_value(e, "repetition", *r,
                  "fromstart, fromstart_several, continue, continue_several, reverse or tofroto");
    }
    spec_.repetition.kind = kind;
    spec_.repetition.count = 1;
    if (const std::string* second = e.attribute("second_repetition")) {
      if (r && *second == *r) spec_.repetition.count = 2;
    }
    const std::size_t first = steps->size();
    for (const XmlElement& c : e.children) motion(c, steps, nondominant);
    if (flag(e, "alternating")) {
      for (std::size_t i = first; i < steps->size(); ++i) {
        for (Movement& m : (*steps)[i].dominant) m.alternating = true;
        for (Movement& m : (*steps)[i].nondominant) m.alternating = true;
      }
    }
  }

  SignParse* out_;
  SignSpec spec_;
  HandSpec initial_dom_, initial_nd_;
  // Each hand's posture after the changes read so far (0 dominant, 1 non-dominant): posture
  // changes are cumulative (SiGML changeposture: what a change does not say stays as the last
  // change left it), so a later change of orientation alone keeps the changed handshape, and the
  // reverse.
  struct Posture {
    HandSpec hand;
    bool shape_changed = false;        // a change so far gave a handshape
    bool orientation_changed = false;  // a change so far left the start's orientation
  };
  std::array<Posture, 2> posture_;

  // A change (tgt_motion handconfig) of hand `which` from its current posture: the handshape when
  // given or changed before, the orientation when it or an earlier change differs from the
  // sign's start (so a change back to the start's orientation is still written).
  void change_posture(const Attributes& attrs, int which, Movement* change) {
    Posture& p = posture_[static_cast<std::size_t>(which)];
    const HandSpec& initial = which == 0 ? initial_dom_ : initial_nd_;
    HandSpec h = p.hand;
    const bool shape = apply(attrs, &h, p.hand.orientation);
    p.shape_changed = p.shape_changed || shape;
    p.hand.shape = h.shape;
    p.hand.orientation = h.orientation;
    if (p.shape_changed) change->to_shape = h.shape;
    p.orientation_changed =
        p.orientation_changed || !same_orientation(h.orientation, initial.orientation);
    if (p.orientation_changed) change->to_orientation = h.orientation;
  }
  std::map<const Attributes*, const XmlElement*> attr_source_;  // for diagnostics' positions
  XmlElement no_element_;
  bool failed_ = false;
};

}  // namespace

SignParse read_hamgestural_sign(const XmlElement& sign) {
  SignParse out;
  GReader reader(&out);
  reader.read(sign);
  return out;
}

}  // namespace sw::notation

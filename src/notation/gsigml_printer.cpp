// Printer of G-SiGML hamgestural_sign elements: writes a SignSpec in the element structure
// gsigml_reader.cpp reads, so that read(print(x)) gives x back for signs read from G-SiGML.
// One extension: a per-movement `alternating="true"` attribute (SiGML puts out-of-phase on
// sign_manual or rpt_motion only; the reader accepts both).
#include <string>
#include <vector>

#include "notation/formula.h"
#include "notation/hamnosys_places.h"
#include "notation/hamnosys_symbols.h"
#include "notation/handshape.h"
#include "notation/sigml.h"

namespace sw::notation {
namespace {

struct Out {
  std::string text;
  int depth = 0;
  void line(const std::string& s) { text += std::string(static_cast<std::size_t>(depth) * 2, ' ') + s + "\n"; }
};

std::string attr(const char* name, const std::string& value) {
  return std::string(" ") + name + "=\"" + xml_escape(value) + "\"";
}

const char* base_name(char32_t w) {
  switch (w) {
    case hamfist: return "fist";
    case hamflathand: return "flat";
    case hamfinger2: return "finger2";
    case hamfinger23: return "finger23";
    case hamfinger23spread: return "finger23spread";
    case hamfinger2345: return "finger2345";
    case hampinch12: return "pinch12";
    case hampinchall: return "pinchall";
    case hampinch12open: return "pinch12open";
    case hamcee12: return "cee12";
    case hamceeall: return "ceeall";
    default: return "cee12open";
  }
}
const char* thumb_name(char32_t w) {
  return w == hamthumboutmod ? "out" : w == hamthumbacrossmod ? "across" : "opposed";
}
const char* bend_name(char32_t w) {
  switch (w) {
    case hamfingerstraightmod: return "straight";
    case hamfingerbendmod: return "bent";
    case hamfingerhookmod: return "hooked";
    case hamdoublebent: return "dblbent";
    case hamdoublehooked: return "dblhooked";
    default: return "round";
  }
}
bool is_bend(char32_t w) { return (w >= hamfingerstraightmod && w <= hamdoublehooked) || w == kShapeRound; }
bool is_digit(char32_t w) { return w >= hamthumb && w <= hampinky; }

// Handshape words -> handconfig attributes (handshape, thumbpos, mainbend, bendK,
// specialfingers, second_*). Words G-SiGML cannot say (finger parts) are left out.
std::string shape_attributes(const HandShape& shape) {
  std::vector<char32_t> words;
  if (shape.hamnosys_base.empty() || !split_shape_words(shape.hamnosys_base, &words)) {
    words = handshape_words(shape);
  } else {
    HandShape built;
    ShapeError error;
    if (!build_handshape(words, &built, &error)) words = handshape_words(shape);
  }
  std::string out, special;
  std::string prefix;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const char32_t w = words[i];
    if (w == hambetween) {
      prefix = "second_";
    } else if (w >= hamfist && w <= hamceeopen) {
      out += attr((prefix + "handshape").c_str(), base_name(w));
    } else if (w >= hamthumboutmod && w <= hamthumbopenmod) {
      out += attr((prefix + "thumbpos").c_str(), thumb_name(w));
    } else if (is_bend(w)) {
      out += attr((prefix + "mainbend").c_str(), bend_name(w));
    } else if (is_digit(w) && prefix.empty()) {
      if (i + 1 < words.size() && is_bend(words[i + 1])) {
        out += attr(("bend" + std::to_string(w - hamthumb + 1)).c_str(), bend_name(words[i + 1]));
        ++i;
      } else if (!(i + 1 < words.size() && words[i + 1] >= hamfingertip && words[i + 1] <= hamfingerside)) {
        special += static_cast<char>('1' + (w - hamthumb));
      } else {
        ++i;  // digit + part: a thumb contact, not expressible here
      }
    }
  }
  if (!special.empty()) out += attr("specialfingers", special);
  return out;
}

std::string orientation_attributes(const Orientation& o, const Orientation& reference) {
  std::string out;
  if (o.extended_finger != reference.extended_finger && !o.extended_finger.is_zero()) {
    out += attr("extfidir", direction_word(o.extended_finger));
  }
  if (o.palm != reference.palm && !o.palm.is_zero()) out += attr("palmor", direction_word(o.palm));
  return out;
}

std::string handconfig(const HandShape* shape, const Orientation& o, const Orientation& reference) {
  return "<handconfig" + (shape ? shape_attributes(*shape) : std::string()) + orientation_attributes(o, reference) + "/>";
}

const char* side_name(Side s) {
  switch (s) {
    case Side::Right: return "right_at";
    case Side::Left: return "left_at";
    case Side::RightBeside: return "right_beside";
    case Side::LeftBeside: return "left_beside";
    case Side::Centre: return "";
  }
  return "";
}
std::string place_name(HandPlace p) {
  switch (p) {
    case HandPlace::Fingertip: return "tip";
    case HandPlace::FingerNail: return "nail";
    case HandPlace::FingerPad: return "pad";
    case HandPlace::FingerMiddleJoint: return "midjoint";
    case HandPlace::FingerBase: return "base";
    case HandPlace::FingerSide: return "side";
    default: return std::string(ham_symbol_name(place_symbol(p))).substr(3);
  }
}
std::string contact_name(Contact c) {
  switch (c) {
    case Contact::Touch: return "touch";
    case Contact::Close: return "close";
    case Contact::ArmExtended: return "armextended";
    case Contact::Brush: return "brush";
    case Contact::Interlock: return "interlock";
    case Contact::Cross: return "cross";
    case Contact::Behind: return "behind";
    case Contact::Grasp: case Contact::Between: return "grasp";
    case Contact::None: return "";
  }
  return "";
}

std::string location_hand(HandPlace place, int finger, Side side, Contact contact) {
  std::string s = "<location_hand" + attr("location", place_name(place));
  if (finger >= 0) s += attr("digits", std::string(1, static_cast<char>('1' + finger)));
  if (side_name(side)[0]) s += attr("side", side_name(side));
  if (contact != Contact::None) s += attr("contact", contact_name(contact));
  return s + "/>";
}

void location_bodyarm(Out* out, const Location& l) {
  std::string s = "<location_bodyarm";
  const bool neutral = l.kind == Location::Kind::NeutralSpace || l.level == BodyLevel::NeutralSpace;
  s += attr("location", neutral ? "neutralspace" : std::string(ham_symbol_name(level_symbol(l.level))).substr(3));
  if (side_name(l.side)[0]) s += attr("side", side_name(l.side));
  if (l.contact != Contact::None) s += attr("contact", contact_name(l.contact));
  if (!l.contact_part) {
    out->line(s + "/>");
    return;
  }
  out->line(s + ">");
  ++out->depth;
  out->line(location_hand(*l.contact_part, l.contact_finger, Side::Centre, Contact::None));
  --out->depth;
  out->line("</location_bodyarm>");
}

// The dominant location (with the non-dominant's own body location when it has one).
void location(Out* out, const Location& l, const Location* nondominant) {
  if (l.kind == Location::Kind::OtherHand) {
    if (!l.contact_part && !nondominant) {
      out->line(location_hand(l.hand_place, l.finger, l.side, l.contact));
      return;
    }
    out->line("<handconstellation" + (l.contact != Contact::None ? attr("contact", contact_name(l.contact)) : "") + ">");
    ++out->depth;
    out->line(location_hand(l.contact_part ? *l.contact_part : HandPlace::Palm, l.contact_part ? l.contact_finger : -1,
                            Side::Centre, Contact::None));
    out->line(location_hand(l.hand_place, l.finger, l.side, Contact::None));
    if (nondominant) location_bodyarm(out, *nondominant);
    --out->depth;
    out->line("</handconstellation>");
    return;
  }
  if (nondominant) {
    out->line("<split_location>");
    ++out->depth;
    location_bodyarm(out, l);
    location_bodyarm(out, *nondominant);
    --out->depth;
    out->line("</split_location>");
    return;
  }
  location_bodyarm(out, l);
}

bool is_default_location(const Location& l) {
  const Location d;
  return l.kind == d.kind && l.level == d.level && l.side == d.side && l.contact == d.contact && !l.contact_part;
}

std::string manner_attributes(const Movement& m) {
  std::string s;
  if (m.size == Size::Small) s += attr("size", "small");
  if (m.size == Size::Large) s += attr("size", "big");
  switch (m.manner) {
    case Manner::Fast: s += attr("fast", "true"); break;
    case Manner::Slow: s += attr("slow", "true"); break;
    case Manner::Tense: s += attr("tense", "true"); break;
    case Manner::Halt: s += attr("halt", "true"); break;
    case Manner::Rest: s += attr("rest", "true"); break;
    case Manner::Normal: break;
  }
  if (m.alternating) s += attr("alternating", "true");
  return s;
}

std::string ellipse_attribute(const Direction& e) {
  if (e.is_zero()) return "";
  return attr("ellipse_direction", e == Direction{0, 1, 0} ? "v" : e == Direction{-1, 1, 0} ? "ur"
                                   : e == Direction{1, 1, 0} ? "ul" : "h");
}

void movement(Out* out, const Movement& m, const HandSpec& initial) {
  std::string base;  // the motion element, without manner when a tgt_motion carries it
  switch (m.kind) {
    case MovementKind::Straight: case MovementKind::Arc: case MovementKind::Wavy: case MovementKind::Zigzag:
      base = "<directedmotion";
      if (!m.direction.is_zero()) base += attr("direction", direction_word(m.direction));
      if (!m.arc_bulge.is_zero()) base += attr("curve", direction_word(m.arc_bulge));
      if (m.kind == MovementKind::Wavy) base += attr("zigzag_style", "wavy");
      if (m.kind == MovementKind::Zigzag) base += attr("zigzag_style", "zigzag");
      base += ellipse_attribute(m.ellipse_axis);
      break;
    case MovementKind::Circle: case MovementKind::Ellipse: case MovementKind::Spiral:
      base = "<circularmotion";
      if (!m.circle_axis.is_zero()) base += attr("axis", direction_word(m.circle_axis));
      base += ellipse_attribute(m.kind == MovementKind::Ellipse && m.ellipse_axis.is_zero() ? Direction{1, 0, 0} : m.ellipse_axis);
      break;
    case MovementKind::FingerPlay: base = "<fingerplay"; break;
    case MovementKind::WristNod: base = "<wristmotion" + attr("motion", "nodding"); break;
    case MovementKind::WristSwing: base = "<wristmotion" + attr("motion", "swinging"); break;
    case MovementKind::WristTwist: base = "<wristmotion" + attr("motion", "twisting"); break;
    case MovementKind::WristCircle: base = "<wristmotion" + attr("motion", m.clockwise ? "stircw" : "stirccw"); break;
    case MovementKind::Replace: case MovementKind::Target: break;
  }
  const bool change = m.kind == MovementKind::Replace || m.kind == MovementKind::Target;
  const bool has_target = m.to_shape || m.to_orientation || m.to_location;
  if (!change && !has_target) {
    out->line(base + manner_attributes(m) + "/>");
    return;
  }
  out->line("<tgt_motion" + manner_attributes(m) + ">");
  ++out->depth;
  if (!change) out->line(base + "/>");
  if (m.to_shape || m.to_orientation || m.kind == MovementKind::Replace) {
    out->line("<changeposture/>");
    // Posture changes are cumulative (gsigml_reader.cpp): a changed orientation is written in
    // full, since a direction left out reads as the last change's, not the start's.
    Orientation unwritten;
    unwritten.extended_finger = Direction{};
    unwritten.palm = Direction{};
    const Orientation o = m.to_orientation ? *m.to_orientation : initial.orientation;
    out->line(handconfig(m.to_shape ? &*m.to_shape : nullptr, o,
                         m.to_orientation ? unwritten : initial.orientation));
  }
  if (m.to_location) location(out, *m.to_location, nullptr);
  --out->depth;
  out->line("</tgt_motion>");
}

void step(Out* out, const MovementStep& s, const HandSpec& dom, const HandSpec& nd) {
  auto group = [&](const std::vector<Movement>& ms, const HandSpec& initial) {
    if (ms.size() == 1) {
      movement(out, ms[0], initial);
      return;
    }
    if (ms.empty()) {
      out->line("<nomotion/>");
      return;
    }
    out->line("<par_motion>");
    ++out->depth;
    for (const Movement& m : ms) movement(out, m, initial);
    --out->depth;
    out->line("</par_motion>");
  };
  if (s.nondominant.empty() && !s.nondominant_stays) {
    group(s.dominant, dom);
    return;
  }
  out->line("<split_motion>");
  ++out->depth;
  group(s.dominant, dom);
  group(s.nondominant, nd);
  --out->depth;
  out->line("</split_motion>");
}

const char* repetition_name(RepeatKind k) {
  switch (k) {
    case RepeatKind::FromStart: return "fromstart";
    case RepeatKind::FromStartSeveral: return "fromstart_several";
    case RepeatKind::Continuing: return "continue";
    case RepeatKind::ContinuingSeveral: return "continue_several";
    case RepeatKind::Reverse: return "reverse";
    case RepeatKind::None: return "";
  }
  return "";
}

}  // namespace

std::string print_hamgestural_sign(const SignSpec& sign, int indent) {
  Out out;
  out.depth = indent / 2;
  out.line("<hamgestural_sign" + attr("gloss", sign.gloss) + ">");
  ++out.depth;
  const NonManual& n = sign.nonmanual;
  if (!n.mouthing.empty() || !n.mouth_gesture.empty() || !n.eyebrows.empty() || !n.head.empty() || !n.gaze.empty()) {
    out.line("<sign_nonmanual>");
    ++out.depth;
    if (!n.mouthing.empty() || !n.mouth_gesture.empty()) {
      out.line("<mouthing_tier>");
      ++out.depth;
      if (!n.mouthing.empty()) out.line("<mouth_picture" + attr("picture", n.mouthing) + "/>");
      if (!n.mouth_gesture.empty()) out.line("<mouth_gesture" + attr("movement", n.mouth_gesture) + "/>");
      --out.depth;
      out.line("</mouthing_tier>");
    }
    if (!n.eyebrows.empty()) {
      const std::string code = n.eyebrows == "up" ? "RB" : n.eyebrows == "down" ? "FU" : n.eyebrows;
      out.line("<facialexpr_tier><eye_brows" + attr("movement", code) + "/></facialexpr_tier>");
    }
    if (!n.head.empty()) {
      const std::string code = n.head == "nod" ? "NO" : n.head == "shake" ? "SH" : n.head == "tilt_l" ? "TL"
                               : n.head == "tilt_r" ? "TR" : n.head;
      out.line("<head_tier><head_movement" + attr("movement", code) + "/></head_tier>");
    }
    if (!n.gaze.empty()) {
      const std::string code = n.gaze == "addressee" ? "AD" : n.gaze == "hands" ? "HC" : n.gaze;
      out.line("<eyegaze_tier><eye_gaze" + attr("direction", code) + "/></eyegaze_tier>");
    }
    --out.depth;
    out.line("</sign_nonmanual>");
  }
  std::string manual = "<sign_manual";
  switch (sign.symmetry) {
    case Symmetry::None: break;
    case Symmetry::MirrorLR: manual += attr("both_hands", "true") + attr("lr_symm", "true"); break;
    case Symmetry::MirrorLRUD: manual += attr("both_hands", "true") + attr("lr_symm", "true") + attr("ud_symm", "true"); break;
    case Symmetry::MirrorLRIO: manual += attr("both_hands", "true") + attr("lr_symm", "true") + attr("oi_symm", "true"); break;
    case Symmetry::Parallel: manual += attr("both_hands", "true"); break;
    case Symmetry::ParallelUD: manual += attr("both_hands", "true") + attr("ud_symm", "true"); break;
    case Symmetry::ParallelIO: manual += attr("both_hands", "true") + attr("oi_symm", "true"); break;
  }
  if (sign.one_hand_is_nondominant && !sign.nondominant) manual += attr("nondominant", "true");
  out.line(manual + ">");
  ++out.depth;
  const Orientation default_orientation;
  if (sign.nondominant) {
    out.line("<split_handconfig>");
    ++out.depth;
    out.line(handconfig(&sign.dominant.shape, sign.dominant.orientation, default_orientation));
    out.line(handconfig(&sign.nondominant->shape, sign.nondominant->orientation, sign.dominant.orientation));
    --out.depth;
    out.line("</split_handconfig>");
  } else {
    out.line(handconfig(&sign.dominant.shape, sign.dominant.orientation, default_orientation));
  }
  const Location* nd_location = nullptr;
  if (sign.nondominant && !is_default_location(sign.nondominant->location) &&
      sign.nondominant->location.kind != Location::Kind::OtherHand) {
    nd_location = &sign.nondominant->location;
  }
  if (!is_default_location(sign.dominant.location) || nd_location) location(&out, sign.dominant.location, nd_location);
  const HandSpec& nd = sign.nondominant ? *sign.nondominant : sign.dominant;
  const bool repeat = sign.repetition.kind != RepeatKind::None;
  if (repeat) {
    std::string r = "<rpt_motion" + attr("repetition", repetition_name(sign.repetition.kind));
    if (sign.repetition.count >= 2) r += attr("second_repetition", repetition_name(sign.repetition.kind));
    out.line(r + ">");
    ++out.depth;
  }
  for (const MovementStep& s : sign.movements) step(&out, s, sign.dominant, nd);
  if (repeat) {
    --out.depth;
    out.line("</rpt_motion>");
  }
  --out.depth;
  out.line("</sign_manual>");
  --out.depth;
  out.line("</hamgestural_sign>");
  return out.text;
}

std::string print_gsigml(const std::vector<SignSpec>& signs) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<sigml>\n";
  for (const SignSpec& s : signs) out += print_hamgestural_sign(s, 2);
  return out + "</sigml>\n";
}

}  // namespace sw::notation

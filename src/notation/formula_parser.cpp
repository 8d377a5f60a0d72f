// Reader of the formula notation (docs/NOTATION.md): a lexer with byte offsets and a
// recursive-descent parser, one sign a line. Every error says what was expected and what was
// found, at the token's line and column; the reader then goes on with the next line.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "notation/formula.h"
#include "notation/seed_places.h"
#include "notation/handshape.h"
#include "notation/sign_spec_names.h"
#include "notation/text_position.h"

namespace sw::notation {
namespace {

// ------------------------------------------------------------------------------------------
// Lexer

enum class Tok { Ident, Number, String, LParen, RParen, Comma, Equals, Colon, Caret, End, Bad };

struct Token {
  Tok kind = Tok::End;
  std::string_view text;  // as written (for strings: with the quotes)
  std::string value;      // strings: the unescaped content
  double number = 0.0;
  std::size_t offset = 0;
};

bool ident_start(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
}
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9'); }
bool digit(char c) { return c >= '0' && c <= '9'; }

class Lexer {
 public:
  Lexer(std::string_view text, std::size_t begin, std::size_t end)
      : text_(text), pos_(begin), end_(end) {}

  Token next() {
    while (pos_ < end_ && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r')) ++pos_;
    Token t;
    t.offset = pos_;
    if (pos_ >= end_) {
      t.kind = Tok::End;
      return t;
    }
    const char c = text_[pos_];
    const std::size_t start = pos_;
    auto single = [&](Tok k) {
      ++pos_;
      t.kind = k;
      t.text = text_.substr(start, 1);
      return t;
    };
    switch (c) {
      case '(': return single(Tok::LParen);
      case ')': return single(Tok::RParen);
      case ',': return single(Tok::Comma);
      case '=': return single(Tok::Equals);
      case ':': return single(Tok::Colon);
      case '^': return single(Tok::Caret);
      default: break;
    }
    if (ident_start(c)) {
      while (pos_ < end_ && ident_char(text_[pos_])) ++pos_;
      t.kind = Tok::Ident;
      t.text = text_.substr(start, pos_ - start);
      return t;
    }
    if (digit(c) || c == '.' || c == '-') {
      if (c == '-') ++pos_;
      while (pos_ < end_ && digit(text_[pos_])) ++pos_;
      if (pos_ < end_ && text_[pos_] == '.') {
        ++pos_;
        while (pos_ < end_ && digit(text_[pos_])) ++pos_;
      }
      t.text = text_.substr(start, pos_ - start);
      const std::string s(t.text);
      char* parsed_end = nullptr;
      t.number = std::strtod(s.c_str(), &parsed_end);
      t.kind = (parsed_end == s.c_str() + s.size() && s != "-" && s != "." && s != "-.")
                   ? Tok::Number
                   : Tok::Bad;
      return t;
    }
    if (c == '"') {
      ++pos_;
      while (pos_ < end_ && text_[pos_] != '"') {
        if (text_[pos_] == '\\' && pos_ + 1 < end_) ++pos_;
        t.value.push_back(text_[pos_]);
        ++pos_;
      }
      if (pos_ >= end_) {  // unterminated
        t.kind = Tok::Bad;
        t.text = text_.substr(start, pos_ - start);
        return t;
      }
      ++pos_;
      t.kind = Tok::String;
      t.text = text_.substr(start, pos_ - start);
      return t;
    }
    // Anything else is one (possibly multi-byte) character the syntax does not use.
    decode_utf8(text_, &pos_);
    if (pos_ > end_) pos_ = end_;
    t.kind = Tok::Bad;
    t.text = text_.substr(start, pos_ - start);
    return t;
  }

 private:
  std::string_view text_;
  std::size_t pos_;
  std::size_t end_;
};

std::string describe(const Token& t) {
  switch (t.kind) {
    case Tok::End: return "the end of the line";
    case Tok::Number: return "the number " + std::string(t.text);
    case Tok::String: return "the string " + std::string(t.text);
    case Tok::Bad:
      if (!t.text.empty() && t.text[0] == '"') return "an unterminated string";
      return "the character '" + std::string(t.text) + "'";
    default: return "'" + std::string(t.text) + "'";
  }
}


// Which parts of a movement's target orientation were written, so the unwritten ones can be taken
// from the hand's orientation before that movement (a movement that writes only P(...) turns the
// palm and keeps the fingers where they were).
struct OrientationWritten {
  bool e = false, p = false, d = false;
  Token at;  // the first orientation item, for diagnostics
};

// The parts of one hand term, before they are merged into the sign.
struct HandTerm {
  HandSpec hand;
  bool has_configuration = false;  // a shape, orientation or location item was written
  std::vector<MovementStep> steps; // movement items in order (dominant side filled)
  bool place = false;
};

class SignReader {
 public:
  SignReader(std::string_view text, const LineIndex& index, std::size_t begin, std::size_t end,
             std::vector<Diagnostic>* diagnostics)
      : lexer_(text, begin, end), index_(index), diagnostics_(diagnostics) {
    advance();
  }

  // sign := term+ ; term := R(...) | L(...) | Sym(...) | N(...) | Rep(...)
  // Errors are values (the WASM build has no exception catching): every read_* returns false
  // after recording one diagnostic, and callers return at once.
  bool read(SignSpec* sign) { return read_sign(sign); }

 private:
  // ---- token helpers
  void advance() { tok_ = lexer_.next(); }
  bool fail(const Token& at, const std::string& message) {
    diagnostics_->push_back(index_.make(at.offset, at.text.size(), std::string(at.text), message));
    return false;
  }
  bool expected(const std::string& what) {
    return fail(tok_, "expected " + what + ", found " + describe(tok_));
  }
  bool expect(Tok kind, const char* what) {
    if (tok_.kind != kind) return expected(what);
    advance();
    return true;
  }
  bool accept(Tok kind) {
    if (tok_.kind != kind) return false;
    advance();
    return true;
  }
  bool is_ident(std::string_view name) const { return tok_.kind == Tok::Ident && tok_.text == name; }
  bool number(const char* what, double lo, double hi, double* out) {
    if (tok_.kind != Tok::Number) return expected(what);
    const double v = tok_.number;
    if (!(v >= lo && v <= hi)) {
      return fail(tok_, std::string(what) + " must be in [" + trim(lo) + ", " + trim(hi) +
                            "], found " + std::string(tok_.text));
    }
    advance();
    *out = v;
    return true;
  }
  bool number(const char* what, double lo, double hi, float* out) {
    double v = 0;
    if (!number(what, lo, hi, &v)) return false;
    *out = static_cast<float>(v);
    return true;
  }
  static std::string trim(double v) {
    std::string s = std::to_string(v);
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  }
  bool integer(const char* what, int lo, int hi, int* out) {
    const Token at = tok_;
    double v = 0;
    if (!number(what, lo, hi, &v)) return false;
    if (v != std::floor(v)) {
      return fail(at, std::string(what) + " must be a whole number, found " + std::string(at.text));
    }
    *out = static_cast<int>(v);
    return true;
  }
  bool word(const std::string& what, std::string* out) {
    if (tok_.kind != Tok::Ident) return expected(what);
    *out = std::string(tok_.text);
    advance();
    return true;
  }

  // ---- sign
  bool read_sign(SignSpec* sign) {
    bool have_right = false, have_left = false, have_sym = false, have_n = false, have_rep = false;
    HandTerm right, left;
    if (tok_.kind == Tok::End) return expected("a hand term R(...)");
    while (tok_.kind != Tok::End) {
      const Token at = tok_;
      if (is_ident("R") || is_ident("L")) {
        const bool is_right = tok_.text == "R";
        if (is_right ? have_right : have_left) {
          return fail(at, std::string("the ") + (is_right ? "right" : "left") + " hand term " +
                              std::string(at.text) + "(...) is written twice");
        }
        if (!is_right && !have_right) {
          return fail(at, "expected the dominant hand term R(...) before L(...)");
        }
        advance();
        (is_right ? have_right : have_left) = true;
        if (!read_hand(is_right ? &right : &left, is_right, sign)) return false;
      } else if (is_ident("Sym")) {
        if (have_sym) return fail(at, "Sym(...) is written twice");
        have_sym = true;
        advance();
        if (!expect(Tok::LParen, "'(' after Sym")) return false;
        const Token w = tok_;
        std::string name;
        if (!word("a symmetry (lr, lrud, lrio, par, parud, pario)", &name)) return false;
        if (!from_name(name, &sign->symmetry) || sign->symmetry == Symmetry::None) {
          return fail(w, "expected a symmetry (lr, lrud, lrio, par, parud, pario), found '" + name + "'");
        }
        if (!expect(Tok::RParen, "')' after the symmetry")) return false;
      } else if (is_ident("N")) {
        if (have_n) return fail(at, "N(...) is written twice");
        have_n = true;
        advance();
        if (!read_nonmanual(&sign->nonmanual)) return false;
      } else if (is_ident("Rep")) {
        if (have_rep || sign->repetition.kind != RepeatKind::None) {
          return fail(at, "Rep(...) is written twice");
        }
        have_rep = true;
        advance();
        if (!read_repetition(&sign->repetition)) return false;
      } else {
        return expected(have_right ? "a term L(...), Sym(...), N(...) or Rep(...)"
                                   : "a hand term R(...)");
      }
      accept(Tok::Comma);  // terms may be separated by commas as well as spaces
    }
    if (!have_right) return expected("a hand term R(...)");
    sign->dominant = right.hand;
    if (have_left && left.has_configuration) sign->nondominant = left.hand;
    sign->nondominant_is_place = left.place;
    // Movement steps: the i-th movement item of R and the i-th of L happen together.
    const std::size_t n = std::max(right.steps.size(), left.steps.size());
    sign->movements.assign(n, MovementStep{});
    for (std::size_t i = 0; i < right.steps.size(); ++i) {
      sign->movements[i].dominant = right.steps[i].dominant;
    }
    for (std::size_t i = 0; i < left.steps.size(); ++i) {
      sign->movements[i].nondominant = left.steps[i].dominant;
    }
    return true;
  }

  // hand := '(' item {',' item} ')' ; items in any order
  bool read_hand(HandTerm* term, bool is_right, SignSpec* sign) {
    std::vector<std::vector<OrientationWritten>> written;  // parallel to term->steps
    static const char* kItems = "a hand item (F_i^k, H, D<i>, E, P, L<i>, Loc, C, M, Par, Rep)";
    if (!expect(Tok::LParen, is_right ? "'(' after R" : "'(' after L")) return false;
    bool have_shape_base = false, have_loc = false, have_e = false, have_p = false,
         have_d = false, have_c = false;
    bool finger_set[kFingerCount] = {false, false, false, false, false};
    for (;;) {
      const Token at = tok_;
      if (tok_.kind != Tok::Ident) return expected(kItems);
      const std::string_view w = tok_.text;
      if (w.size() > 2 && w[0] == 'F' && w[1] == '_') {
        int k = 0;
        FingerConfig c;
        if (!read_finger(&c, &k)) return false;
        if (finger_set[k]) return fail(at, "finger " + std::to_string(k + 1) + " is given twice");
        finger_set[k] = true;
        term->hand.shape.fingers[k] = c;
        term->has_configuration = true;
      } else if (w == "H") {
        if (have_shape_base) return fail(at, "H(...) is written twice");
        for (bool f : finger_set) {
          if (f) return fail(at, "H(...) must come before the F items that override it");
        }
        have_shape_base = true;
        advance();
        if (!read_shape(&term->hand.shape)) return false;
        term->has_configuration = true;
      } else if (w.size() == 2 && w[0] == 'D' && w[1] >= '1' && w[1] <= '5') {
        if (have_d) return fail(at, "a palm orientation D<i> is given twice");
        have_d = true;
        term->hand.orientation.seed_palm = static_cast<SeedPalm>(w[1] - '0');
        advance();
        term->has_configuration = true;
      } else if (w == "E" || w == "P") {
        const bool is_e = w == "E";
        bool& have = is_e ? have_e : have_p;
        if (have) return fail(at, std::string(w) + "(...) is given twice");
        have = true;
        advance();
        Direction& d = is_e ? term->hand.orientation.extended_finger : term->hand.orientation.palm;
        if (!read_direction_arg(is_e ? "the extended-finger direction" : "the palm direction", &d)) {
          return false;
        }
        term->has_configuration = true;
      } else if (is_seed_location(w) || w == "Loc") {
        if (have_loc) return fail(at, "the hand's location is given twice");
        have_loc = true;
        Location loc;
        if (!read_location(&loc)) return false;
        loc.contact_part = term->hand.location.contact_part;
        loc.contact_finger = term->hand.location.contact_finger;
        term->hand.location = loc;
        term->has_configuration = true;
      } else if (w == "C") {
        if (have_c) return fail(at, "C(...) is given twice");
        have_c = true;
        advance();
        if (!read_contact_part(&term->hand.location)) return false;
        term->has_configuration = true;
      } else if (w == "M") {
        MovementStep step;
        step.dominant.emplace_back();
        written.emplace_back(1);
        if (!read_movement(&step.dominant.back(), &written.back().back())) return false;
        term->steps.push_back(std::move(step));
      } else if (w == "Par") {
        advance();
        if (!expect(Tok::LParen, "'(' after Par")) return false;
        MovementStep step;
        written.emplace_back();
        while (tok_.kind != Tok::RParen) {
          if (!is_ident("M")) return expected("a movement M(...) inside Par(...)");
          step.dominant.emplace_back();
          written.back().emplace_back();
          if (!read_movement(&step.dominant.back(), &written.back().back())) return false;
          if (!accept(Tok::Comma) && tok_.kind != Tok::RParen) return expected("',' or ')' in Par(...)");
        }
        advance();
        term->steps.push_back(std::move(step));
      } else if (w == "Rep") {
        if (sign->repetition.kind != RepeatKind::None) return fail(at, "Rep(...) is written twice");
        advance();
        if (!read_repetition(&sign->repetition)) return false;
      } else if (w == "place") {
        if (is_right) return fail(at, "'place' (the other hand is the location) belongs in L(...)");
        term->place = true;
        advance();
      } else {
        return expected(kItems);
      }
      if (accept(Tok::RParen)) return inherit_unwritten_orientation(term, written);
      if (!accept(Tok::Comma)) return expected("',' or ')' after a hand item");
    }
  }

  // A movement's target orientation keeps what it does not write: its unwritten E or P is the
  // hand's at the start of that movement (the term's own, then each earlier movement's target),
  // not the default. A hand written with D<i> has no separate E and P to keep, so a movement
  // changing only one of them is ambiguous and reported.
  bool inherit_unwritten_orientation(HandTerm* term, const std::vector<std::vector<OrientationWritten>>& written) {
    Orientation running = term->hand.orientation;
    for (std::size_t s = 0; s < term->steps.size(); ++s) {
      std::vector<Movement>& moves = term->steps[s].dominant;
      std::optional<Orientation> after;
      for (std::size_t k = 0; k < moves.size(); ++k) {
        if (!moves[k].to_orientation) continue;
        const OrientationWritten& w = written[s][k];
        Orientation& o = *moves[k].to_orientation;
        if (!w.d) {
          if (w.e != w.p && running.seed_palm != SeedPalm::None) {
            return fail(w.at, std::string("this movement changes only ") + (w.e ? "E" : "P") +
                                  " of a hand written with " + name_of(running.seed_palm) +
                                  ": write both E(...) and P(...), or a D<i>");
          }
          if (!w.e) o.extended_finger = running.extended_finger;
          if (!w.p) o.palm = running.palm;
        }
        after = o;
      }
      if (after) running = *after;
    }
    return true;
  }

  static bool is_seed_location(std::string_view w) {
    if (w.size() < 2 || w.size() > 4 || w[0] != 'L') return false;
    for (std::size_t i = 1; i < w.size(); ++i) {
      if (!digit(w[i])) return false;
    }
    return true;
  }

  // F_i^k [ '(' [t] [',' s | ',' s=number] ')' ]  — seed 004 eq. (4)
  bool read_finger(FingerConfig* out, int* finger_index) {
    const Token at = tok_;
    const std::string_view id_text = tok_.text.substr(2);
    if (id_text.size() > 2) return fail(at, "configuration number too long in '" + std::string(at.text) + "'");
    for (char c : id_text) {
      if (!digit(c)) {
        return fail(at, "expected F_<i>^<k> with a configuration number i, found '" +
                            std::string(at.text) + "'");
      }
    }
    const int id = std::atoi(std::string(id_text).c_str());
    advance();
    if (!expect(Tok::Caret, "'^' between the configuration and the finger number (F_i^k)")) return false;
    int k = 0;
    if (!integer("the finger number k (1 thumb .. 5 little)", 1, 5, &k)) return false;
    const int max_id = k == 1 ? static_cast<int>(kThumbAlongside) : static_cast<int>(kFingerDoubleHooked);
    if (id > max_id) {
      return fail(at, "configuration " + std::to_string(id) + " does not exist for finger " +
                          std::to_string(k) + " (0.." + std::to_string(max_id) + ")");
    }
    FingerConfig c;
    c.id = id;
    if (accept(Tok::LParen)) {
      if (tok_.kind == Tok::Number) {
        c.has_t = true;
        if (!number("t", 0.0, 1.0, &c.t)) return false;
        if (accept(Tok::Comma)) {
          if (is_ident("s")) {
            advance();
            if (!expect(Tok::Equals, "'=' after s")) return false;
          }
          if (!number("the spread s", 0.0, 1.0, &c.spread)) return false;
        }
      } else if (is_ident("s")) {
        advance();
        if (!expect(Tok::Equals, "'=' after s")) return false;
        if (!number("the spread s", 0.0, 1.0, &c.spread)) return false;
      } else {
        return expected("t (a number in [0, 1]) or s=<spread>");
      }
      if (!expect(Tok::RParen, "')' after the finger's parameters")) return false;
    }
    *finger_index = k - 1;
    *out = c;
    return true;
  }

  // H '(' word {[','] word} ')': a HamNoSys handshape by names or aliases.
  bool read_shape(HandShape* shape) {
    if (!expect(Tok::LParen, "'(' after H")) return false;
    std::vector<char32_t> words;
    std::vector<Token> tokens;
    while (tok_.kind != Tok::RParen) {
      if (tok_.kind != Tok::Ident) return expected("a handshape word (a base such as flat or fist, or a modifier) or ')'");
      char32_t w = 0;
      if (!shape_word_from_name(tok_.text, &w)) {
        return fail(tok_, "expected a handshape word (bases: fist flat finger2 finger23 "
                          "finger23spread finger2345 pinch12 pinchall pinch12open cee12 ceeall "
                          "ceeopen; modifiers: thumbout thumbacross thumbopen straight bent round "
                          "hooked doublebent doublehooked spread crossed thumbon2..thumbon5; or a "
                          "HamNoSys name), found '" + std::string(tok_.text) + "'");
      }
      words.push_back(w);
      tokens.push_back(tok_);
      advance();
      accept(Tok::Comma);
    }
    const Token close = tok_;
    advance();
    ShapeError error;
    if (!build_handshape(words, shape, &error)) {
      return fail(error.word_index < tokens.size() ? tokens[error.word_index] : close, error.message);
    }
    return true;
  }

  bool read_direction_arg(const std::string& what, Direction* d) {
    if (!expect(Tok::LParen, "'('")) return false;
    if (!read_direction(what, d)) return false;
    return expect(Tok::RParen, "')' after the direction");
  }
  bool read_direction(const std::string& what, Direction* d) {
    if (tok_.kind == Tok::Number && tok_.number == 0.0) {  // "0": no direction
      *d = Direction{};
      advance();
      return true;
    }
    if (tok_.kind != Tok::Ident || !parse_direction_word(tok_.text, d)) {
      return expected(what + " (letters u/d, l/r, o/i, at most one of each pair)");
    }
    advance();
    return true;
  }

  // L<i> '(' mu ')' | Loc '(' args ')'
  bool read_location(Location* out) {
    Location loc;
    const Token at = tok_;
    if (tok_.text != "Loc") {
      const int i = std::atoi(std::string(tok_.text.substr(1)).c_str());
      if (i < 1 || i > kSeedPlaceCount) {
        return fail(at, "seed localisation L" + std::to_string(i) + " does not exist (L1..L" +
                            std::to_string(kSeedPlaceCount) + ")");
      }
      advance();
      if (!expect(Tok::LParen, "'(' after L<i> (its contact mu)")) return false;
      const Token mu_at = tok_;
      double mu = 0;
      if (!number("the contact mu (0 no touch, 1 touch)", 0, 1, &mu)) return false;
      if (mu != 0.0 && mu != 1.0) return fail(mu_at, "the contact mu must be 0 (no touch) or 1 (touch)");
      if (!expect(Tok::RParen, "')' after mu")) return false;
      const SeedPlace& p = kSeedPlaces[i - 1];
      loc.level = p.level;
      loc.side = p.side;
      loc.kind = p.level == BodyLevel::NeutralSpace ? Location::Kind::NeutralSpace : Location::Kind::Body;
      loc.contact = mu == 1.0 ? Contact::Touch : Contact::None;
      loc.seed_id = i;
      *out = loc;
      return true;
    }
    advance();
    if (!expect(Tok::LParen, "'(' after Loc")) return false;
    bool have_level = false, have_side = false, have_contact = false, have_place = false,
         have_finger = false, on_hand = false;
    for (;;) {
      const Token w = tok_;
      if (tok_.kind == Tok::Number) {
        int k = 0;
        if (!integer("a finger number (1 thumb .. 5 little)", 1, 5, &k)) return false;
        if (have_finger) return fail(w, "the finger is given twice");
        have_finger = true;
        loc.finger = static_cast<std::int8_t>(k - 1);
      } else {
        std::string name;
        if (!word("a level, side, contact, 'hand' or a place on the hand", &name)) return false;
        BodyLevel level;
        Side side;
        Contact contact;
        HandPlace place;
        if (name == "hand") {
          if (on_hand || have_level) return fail(w, "'hand' must come first in Loc(...), once");
          on_hand = true;
        } else if (!on_hand && from_name(name, &level)) {
          if (have_level) return fail(w, "the level is given twice");
          have_level = true;
          loc.level = level;
        } else if (from_name(name, &side)) {
          if (have_side) return fail(w, "the side is given twice");
          have_side = true;
          loc.side = side;
        } else if (from_name(name, &contact)) {
          if (have_contact) return fail(w, "the contact is given twice");
          have_contact = true;
          loc.contact = contact;
        } else if (on_hand && from_name(name, &place)) {
          if (have_place) return fail(w, "the place on the hand is given twice");
          have_place = true;
          loc.hand_place = place;
        } else {
          return fail(w, on_hand ? "expected a place on the other hand (" + names_list<HandPlace>() +
                                       "), a finger 1..5, a side or a contact, found '" + name + "'"
                                 : "expected a level (" + names_list<BodyLevel>() + "), a side (" +
                                       names_list<Side>() + "), a contact (" + names_list<Contact>() +
                                       ") or 'hand', found '" + name + "'");
        }
      }
      if (accept(Tok::RParen)) break;
      if (!accept(Tok::Comma)) return expected("',' or ')' in Loc(...)");
    }
    if (on_hand) {
      if (!have_place) {
        return fail(at, "Loc(hand, ...) needs a place on the other hand (" + names_list<HandPlace>() + ")");
      }
      loc.kind = Location::Kind::OtherHand;
    } else {
      if (!have_level) return fail(at, "Loc(...) needs a level (" + names_list<BodyLevel>() + ")");
      if (have_finger) return fail(at, "a finger number belongs to Loc(hand, ...)");
      loc.kind = loc.level == BodyLevel::NeutralSpace ? Location::Kind::NeutralSpace : Location::Kind::Body;
    }
    *out = loc;
    return true;
  }

  // C '(' place [',' finger] ')'
  bool read_contact_part(Location* loc) {
    if (!expect(Tok::LParen, "'(' after C")) return false;
    const Token w = tok_;
    std::string name;
    if (!word("a part of the hand (" + names_list<HandPlace>() + ")", &name)) return false;
    HandPlace place;
    if (!from_name(name, &place)) {
      return fail(w, "expected a part of the hand (" + names_list<HandPlace>() + "), found '" + name + "'");
    }
    loc->contact_part = place;
    loc->contact_finger = -1;
    if (accept(Tok::Comma)) {
      int k = 0;
      if (!integer("a finger number (1 thumb .. 5 little)", 1, 5, &k)) return false;
      loc->contact_finger = static_cast<std::int8_t>(k - 1);
    }
    return expect(Tok::RParen, "')' after C(...)");
  }

  // M '(' kind {[','] arg} ')'
  bool read_movement(Movement* out, OrientationWritten* written) {
    advance();  // M
    if (!expect(Tok::LParen, "'(' after M")) return false;
    Movement m;
    const Token kind_at = tok_;
    std::string kind;
    if (!word("a movement kind (" + names_list<MovementKind>() + ")", &kind)) return false;
    if (!from_name(kind, &m.kind)) {
      return fail(kind_at, "expected a movement kind (" + names_list<MovementKind>() + "), found '" + kind + "'");
    }
    bool have_dir = false, have_size = false, have_manner = false;
    HandShape shape;
    bool have_shape = false;
    Orientation orientation;
    bool have_orientation = false;
    for (;;) {
      accept(Tok::Comma);
      if (accept(Tok::RParen)) break;
      const Token at = tok_;
      if (tok_.kind != Tok::Ident) return expected("a movement argument or ')'");
      const std::string_view w = tok_.text;
      Size size;
      Manner manner;
      Direction d;
      if (w == "bulge" || w == "axis" || w == "ellipse" || w == "dir") {
        advance();
        if (!expect(Tok::Equals, "'=' after the key")) return false;
        Direction& target = w == "bulge" ? m.arc_bulge
                            : w == "axis" ? m.circle_axis
                            : w == "ellipse" ? m.ellipse_axis
                                             : m.direction;
        if (!read_direction(std::string("the ") + std::string(w) + " direction", &target)) return false;
        if (w == "dir") have_dir = true;
      } else if (w == "cw" || w == "ccw") {
        m.clockwise = w == "cw";
        advance();
      } else if (w == "alt") {
        m.alternating = true;
        advance();
      } else if (w != "normal" && from_name(w, &size)) {
        if (have_size) return fail(at, "the size is given twice");
        have_size = true;
        m.size = size;
        advance();
      } else if (w != "normal" && from_name(w, &manner)) {
        if (have_manner) return fail(at, "the manner is given twice");
        have_manner = true;
        m.manner = manner;
        advance();
      } else if (w == "H") {
        if (have_shape) return fail(at, "H(...) must come once, before the F items");
        advance();
        if (!read_shape(&shape)) return false;
        have_shape = true;
      } else if (w.size() > 2 && w[0] == 'F' && w[1] == '_') {
        int k = 0;
        FingerConfig c;
        if (!read_finger(&c, &k)) return false;
        shape.fingers[k] = c;
        have_shape = true;
      } else if (w == "E" || w == "P") {
        const bool is_e = w == "E";
        advance();
        if (!have_orientation) written->at = at;
        (is_e ? written->e : written->p) = true;
        Direction& target = is_e ? orientation.extended_finger : orientation.palm;
        if (!read_direction_arg(is_e ? "the extended-finger direction" : "the palm direction", &target)) {
          return false;
        }
        have_orientation = true;
      } else if (w.size() == 2 && w[0] == 'D' && w[1] >= '1' && w[1] <= '5') {
        if (!have_orientation) written->at = at;
        written->d = true;
        orientation.seed_palm = static_cast<SeedPalm>(w[1] - '0');
        have_orientation = true;
        advance();
      } else if (is_seed_location(w) || w == "Loc") {
        if (m.to_location) return fail(at, "the movement's target location is given twice");
        Location loc;
        if (!read_location(&loc)) return false;
        m.to_location = loc;
      } else if (!have_dir && parse_direction_word(w, &d)) {
        m.direction = d;
        have_dir = true;
        advance();
      } else {
        return expected("a movement argument (a direction, bulge=, axis=, ellipse=, cw, ccw, small, "
                        "large, fast, slow, tense, halt, rest, alt, H(...), F_i^k, E(...), P(...), "
                        "Loc(...)) or ')'");
      }
    }
    if (have_shape) m.to_shape = shape;
    if (have_orientation) m.to_orientation = orientation;
    *out = std::move(m);
    return true;
  }

  // Rep '(' kind [',' n] ')'
  bool read_repetition(Repetition* rep) {
    if (!expect(Tok::LParen, "'(' after Rep")) return false;
    const Token at = tok_;
    std::string kind;
    if (!word("a repetition (fromstart, continuing, reverse, fromstart_several, continuing_several)", &kind)) {
      return false;
    }
    if (!from_name(kind, &rep->kind) || rep->kind == RepeatKind::None) {
      rep->kind = RepeatKind::None;
      return fail(at, "expected a repetition (fromstart, continuing, reverse, fromstart_several, "
                      "continuing_several), found '" + kind + "'");
    }
    rep->count = 1;
    if (accept(Tok::Comma)) {
      if (!integer("the number of extra repetitions", 1, 100, &rep->count)) return false;
    }
    return expect(Tok::RParen, "')' after Rep(...)");
  }

  // N '(' key=value {',' key=value} ')'
  bool read_nonmanual(NonManual* n) {
    static const char* kKeys = "a non-manual key (mouth, mouthgesture, brows, expression, intensity, head, gaze)";
    if (!expect(Tok::LParen, "'(' after N")) return false;
    for (;;) {
      const Token key_at = tok_;
      std::string key;
      if (!word(kKeys, &key)) return false;
      if (!expect(Tok::Equals, "'=' after the key")) return false;
      if (key == "intensity") {
        if (!number("the intensity", 0.0, 1.0, &n->expression_intensity)) return false;
      } else {
        std::string value;
        if (tok_.kind == Tok::String) {
          value = tok_.value;
        } else if (tok_.kind == Tok::Ident) {
          value = std::string(tok_.text);
        } else {
          return expected("a value (a word or a \"string\")");
        }
        advance();
        if (key == "mouth") {
          n->mouthing = value;
        } else if (key == "mouthgesture") {
          n->mouth_gesture = value;
        } else if (key == "brows") {
          n->eyebrows = value;
        } else if (key == "expression") {
          n->expression = value;
          if (accept(Tok::Colon)) {
            if (!number("the intensity", 0.0, 1.0, &n->expression_intensity)) return false;
          }
        } else if (key == "head") {
          n->head = value;
        } else if (key == "gaze") {
          n->gaze = value;
        } else {
          return fail(key_at, std::string("expected ") + kKeys + ", found '" + key + "'");
        }
      }
      if (accept(Tok::RParen)) return true;
      if (!accept(Tok::Comma)) return expected("',' or ')' in N(...)");
    }
  }

  Lexer lexer_;
  const LineIndex& index_;
  std::vector<Diagnostic>* diagnostics_;
  Token tok_;
};

// The gloss of `GLOSS = formula`: text before an '=' that comes before any '(' or '"'.
std::size_t find_gloss_separator(std::string_view line) {
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '(' || c == '"') return std::string_view::npos;
    if (c == '=') return i;
  }
  return std::string_view::npos;
}

std::string_view trim_view(std::string_view s, std::size_t* lead) {
  std::size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r')) ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r')) --b;
  if (lead) *lead = a;
  return s.substr(a, b - a);
}

// The end of the line's content: a '#' outside a string starts a comment.
std::size_t content_end(std::string_view text, std::size_t begin, std::size_t end) {
  bool in_string = false;
  for (std::size_t i = begin; i < end; ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '#') {
      return i;
    }
  }
  return end;
}

}  // namespace

bool parse_direction_word(std::string_view word, Direction* d) {
  if (word.empty() || word.size() > 3) return false;
  Direction r;
  for (char c : word) {
    switch (c) {
      case 'u': if (r.y) return false; r.y = 1; break;
      case 'd': if (r.y) return false; r.y = -1; break;
      case 'l': if (r.x) return false; r.x = 1; break;   // +X is the signer's left
      case 'r': if (r.x) return false; r.x = -1; break;
      case 'o': if (r.z) return false; r.z = 1; break;   // away from the body
      case 'i': if (r.z) return false; r.z = -1; break;
      default: return false;
    }
  }
  *d = r;
  return true;
}

std::vector<SignParse> parse_formula_text(std::string_view text) {
  std::vector<SignParse> out;
  const LineIndex index(text);
  for (const TextLine& line : split_lines(text)) {
    const std::size_t line_start = line.start;
    const std::size_t end = content_end(text, line_start, line.end);
    std::size_t lead = 0;
    const std::string_view content = trim_view(text.substr(line_start, end - line_start), &lead);
    if (!content.empty()) {
      SignParse sign;
      const std::size_t content_start = line_start + lead;
      sign.offset = content_start;
      sign.line = line.number;
      std::size_t formula_start = content_start;
      const std::size_t eq = find_gloss_separator(content);
      if (eq != std::string_view::npos) {
        sign.gloss = std::string(trim_view(content.substr(0, eq), nullptr));
        formula_start = content_start + eq + 1;
        if (sign.gloss.empty()) {
          sign.diagnostics.push_back(index.make(content_start, 1, "=",
                                                "expected a gloss before '=', found nothing"));
        }
      }
      const std::size_t formula_end = content_start + content.size();
      SignSpec spec;
      spec.gloss = sign.gloss;
      if (!has_error(sign.diagnostics)) {
        SignReader reader(text, index, formula_start, formula_end, &sign.diagnostics);
        if (reader.read(&spec)) sign.spec = std::move(spec);
      }
      out.push_back(std::move(sign));
    }
  }
  return out;
}

}  // namespace sw::notation

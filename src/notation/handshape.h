// Handshapes from HamNoSys-style descriptions: a base shape (the twelve HamNoSys bases) plus thumb
// and bending modifiers, per-finger sub-specifications and "between" shapes, turned into the
// seed's per-finger configurations F_i^k (seed 004 eq. (4); ids in sign_spec.h).
//
// One description language serves three notations: HamNoSys symbols (hamfinger2,
// hamthumbacrossmod, hamfingerbendmod, hamindexfinger, ...), the formula's H(...) (friendly aliases
// of the same symbols plus four formula-only modifiers) and G-SiGML handconfig attributes (which
// the G-SiGML reader spells as the same symbols).
//
// Does not: decide joint angles (synthesis does that from the ids), or validate anatomical
// plausibility of overrides.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "notation/sign_spec.h"

namespace sw::notation {

// Formula-only modifiers, outside HamNoSys (whose symbols are Unicode private-use code points
// U+E000..U+E0FF): code points from a plane HamNoSys never uses, so one word list holds both.
enum ShapeExtra : char32_t {
  kShapeRound = 0xF0001,    // every selected finger round (G-SiGML bend "round")
  kShapeSpread = 0xF0002,   // selected fingers spread apart
  kShapeCrossed = 0xF0003,  // middle crossed over the index (seed F_3^3)
  kShapeThumbOn2 = 0xF0012, // thumb tip on the index .. little finger (kShapeThumbOn2 + k - 2)
  kShapeThumbOn3 = 0xF0013,
  kShapeThumbOn4 = 0xF0014,
  kShapeThumbOn5 = 0xF0015,
};

// The name a word is written with in HandShape::hamnosys_base: the HamNoSys name for symbols
// ("hamflathand"), the formula word for extras ("round"); "" for codes that are neither.
std::string shape_word_name(char32_t word);
// Inverse of shape_word_name; also accepts the formula's aliases ("flat", "thumbout", "bent").
bool shape_word_from_name(std::string_view name, char32_t* word);
// The formula alias of a word ("flat" for hamflathand) or "" when it has none.
const char* shape_word_alias(char32_t word);
// True for the words a handshape description may contain (bases, thumb and bending modifiers,
// finger and finger-part symbols, hambetween, the extras).
bool is_shape_word(char32_t word);
bool is_shape_base(char32_t word);

struct ShapeError {
  std::size_t word_index = 0;  // which word was wrong (== words.size() for "ended too early")
  std::string message;         // "expected ..., found ..."
};

// Builds the per-finger configuration of `words` (see the file comment). On success fills
// `shape` (fingers + hamnosys_base = the words' names joined by commas) and returns true;
// otherwise returns false and says which word was wrong.
bool build_handshape(const std::vector<char32_t>& words, HandShape* shape, ShapeError* error);

// The words of a handshape for printing: its own (HandShape::hamnosys_base, when they are all
// HamNoSys symbols and still build these fingers) or else the base + thumb + bending combination
// whose fingers come closest (formula shapes written with F items).
std::vector<char32_t> handshape_words(const HandShape& shape);

// Joins/splits the names stored in HandShape::hamnosys_base.
std::string join_shape_words(const std::vector<char32_t>& words);
bool split_shape_words(std::string_view text, std::vector<char32_t>* words);

}  // namespace sw::notation

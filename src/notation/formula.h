// The seed's formula notation as a text syntax (seed 004 Table 2, extended to two hands,
// movements and non-manuals): `R(L1(0), D1, F_0^1(0.5), F_0^2(1), ...)`. The syntax is defined in
// docs/NOTATION.md, which is kept true to this reader; the printer writes what the reader reads,
// so parse(print(x)) == x for every SignSpec the readers produce.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "notation/parse.h"
#include "notation/sign_spec.h"

namespace sw::notation {

// A text of signs, one a line: `GLOSS = formula` or a bare formula; `#` starts a comment.
std::vector<SignParse> parse_formula_text(std::string_view text);
// The formula of one sign (no gloss, one line).
std::string print_formula(const SignSpec& sign);
// `GLOSS = formula` (just the formula when the gloss is empty).
std::string print_formula_line(const SignSpec& sign);

// Shared with the other printers and readers: the formula's direction words ("u", "dol", ...).
std::string direction_word(const Direction& d);
bool parse_direction_word(std::string_view word, Direction* d);
// The shortest decimal text that reads back as the same float ("0.5", "1", "0.333333343").
std::string format_float(float value);

}  // namespace sw::notation

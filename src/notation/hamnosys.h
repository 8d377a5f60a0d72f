// HamNoSys 4: the reader (Unicode private-use strings such as U+E001 U+E020 ..., or symbol names
// "hamflathand,hamextfingeru,...") and the printer (both spellings). The symbol inventory is
// hamnosys_symbols.h; handshapes go through handshape.h.
//
// Grammar read (HamNoSys 4, as real corpora write it):
//   sign     := part {hamplus part}                                 (sequential parts)
//   part     := [hamnondominant] [symmetry [hamalternatingmotion]] config [location] action*
//   config   := hand | hamparbegin hand hamplus hand hamparend      (dominant, non-dominant)
//   hand     := handshape [extfidir {[hambetween] extfidir}] [palm {[hambetween] palm}]
//   location := [part] [lr] level [lr] [contact] [bracket] | place [contact] [bracket]
//             | hamparbegin location hamplus location hamparend [contact]
//             | (place | hamparbegin part hamplus place hamparend) [contact] body-location
//   bracket  := hamseqbegin contact {digit | part | lr} hamseqend   (this hand's contact part)
//   action   := movement modifier* | hamreplace (config|hand) [location] | location (target)
//             | hamseqbegin action* hamseqend | hamfusionbegin action* hamfusionend
//             | hamparbegin action* [hamplus action*] hamparend | repetition
//             | {alternative | alternative}  (the first alternative is taken)
//   A later part is read as a change (hamreplace) to its configuration and place, then its
//   actions; its symmetry is kept only where it is the sign's (SignSpec has one per sign).
//   hamnondominant before a one-handed configuration: the non-dominant hand signs.
// Unknown symbols and unbalanced brackets give a diagnostic with position and symbol; the reader
// skips them and goes on (it never stops early or crashes).
//
// Does not: keep HamNoSys detail SignSpec has no field for (clock positions, hamincreasing,
// coreference tags, hammime); those are read and skipped.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "notation/diagnostic.h"
#include "notation/parse.h"
#include "notation/sign_spec.h"

namespace sw::notation {

// One symbol of a sign with where it was written (for diagnostics).
struct HamSymbolRef {
  char32_t code = 0;
  std::size_t offset = 0, length = 0;
  int line = 1, column = 1;
  std::string text;  // as written: the name, or the code point label "U+E001"
};

// A text of HamNoSys signs, one a line (`GLOSS = symbols` or just symbols, `#` comments).
std::vector<SignParse> parse_hamnosys_text(std::string_view text);
// Splits one sign's text into symbols (code points or names); unknown ones are reported in
// `diagnostics` and left out.
std::vector<HamSymbolRef> tokenize_hamnosys(std::string_view text, std::size_t begin,
                                            std::size_t end, std::vector<Diagnostic>* diagnostics);
// The same with the text's line index built once by the caller (files of many signs).
class LineIndex;
std::vector<HamSymbolRef> tokenize_hamnosys(std::string_view text, const LineIndex& index,
                                            std::size_t begin, std::size_t end,
                                            std::vector<Diagnostic>* diagnostics);
// Reads one sign from its symbols (the H-SiGML reader calls this with one symbol per element).
// Returns false only when no SignSpec could be built (no handshape at all); errors it recovered
// from are in `diagnostics`.
bool parse_hamnosys_symbols(const std::vector<HamSymbolRef>& symbols, std::size_t sign_offset,
                            SignSpec* sign, std::vector<Diagnostic>* diagnostics);

enum class HamNoSysSpelling { Unicode, Names };
// The symbols of a sign, in writing order.
std::vector<char32_t> hamnosys_symbols(const SignSpec& sign);
// Unicode: the code points; Names: "hamflathand,hamextfingeru,...".
std::string print_hamnosys(const SignSpec& sign, HamNoSysSpelling spelling);

}  // namespace sw::notation

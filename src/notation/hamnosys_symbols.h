// The HamNoSys 4 symbol inventory: code point (Unicode private use, U+E000...), name
// ("hamflathand") and group, compiled in from docs/hamnosys-symbols.tsv (generated table: see
// tools/gen_hamnosys_symbols.py). Used by the HamNoSys and H-SiGML readers and printers and by the
// formula's H(...) handshapes.
#pragma once

#include <string_view>

namespace sw::notation {

enum class HamGroup : unsigned char {
  Punctuation, HandshapeBase, ThumbModifier, FingerBending, ExtendedFinger, Palm, LocationBody,
  LocationModifier, LocationNeutral, LocationArmHand, LocationFinger, ObsoleteWrist,
  StraightMovement, CircularMovement, WristFingerMovement, Replacement, MovementOther,
  ClockPosition, Arc, WavyZigzag, Ellipse, Size, Manner, Contact, Repetition, Grouping,
  TwoHanded, Other,
};

// Every symbol by its HamNoSys name, valued by its code point.
enum Ham : char32_t {
#include "notation/hamnosys_symbol_codes.inc"
};

struct HamSymbolInfo {
  char32_t code;
  const char* name;
  HamGroup group;
};

// nullptr when the code point / name is not a HamNoSys 4 symbol.
const HamSymbolInfo* ham_symbol_by_code(char32_t code);
const HamSymbolInfo* ham_symbol_by_name(std::string_view name);
// The name of a known code point, or "" when unknown.
const char* ham_symbol_name(char32_t code);
HamGroup ham_symbol_group(char32_t code);  // Punctuation for unknown codes (callers check first)

}  // namespace sw::notation

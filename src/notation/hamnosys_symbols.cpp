// Look-ups in the compiled-in HamNoSys symbol table (see hamnosys_symbols.h).
#include "notation/hamnosys_symbols.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <iterator>

namespace sw::notation {
namespace {

constexpr HamSymbolInfo kSymbols[] = {
#include "notation/hamnosys_symbols_table.inc"
};
constexpr std::size_t kSymbolCount = std::size(kSymbols);

// Indices into kSymbols sorted by name, built once (209 entries: a binary search beats hashing
// here and needs no allocation).
const std::array<unsigned short, kSymbolCount>& by_name() {
  static const std::array<unsigned short, kSymbolCount> order = [] {
    std::array<unsigned short, kSymbolCount> o{};
    for (std::size_t i = 0; i < kSymbolCount; ++i) o[i] = static_cast<unsigned short>(i);
    std::sort(o.begin(), o.end(), [](unsigned short a, unsigned short b) {
      return std::strcmp(kSymbols[a].name, kSymbols[b].name) < 0;
    });
    return o;
  }();
  return order;
}

}  // namespace

const HamSymbolInfo* ham_symbol_by_code(char32_t code) {
  const auto* end = kSymbols + kSymbolCount;
  const auto* it = std::lower_bound(kSymbols, end, code,
                                    [](const HamSymbolInfo& s, char32_t c) { return s.code < c; });
  return (it != end && it->code == code) ? it : nullptr;
}

const HamSymbolInfo* ham_symbol_by_name(std::string_view name) {
  const auto& order = by_name();
  const auto it = std::lower_bound(order.begin(), order.end(), name,
                                   [](unsigned short i, std::string_view n) {
                                     return std::string_view(kSymbols[i].name) < n;
                                   });
  if (it != order.end() && std::string_view(kSymbols[*it].name) == name) return &kSymbols[*it];
  // H-SiGML (the HamNoSys 4 element names of UEA's SiGML tools) spells U+E060 "hamUpperarm";
  // the symbol table's name is "hamupperarm". Both are read; printers write the table's.
  if (name == "hamUpperarm") return ham_symbol_by_name("hamupperarm");
  return nullptr;
}

const char* ham_symbol_name(char32_t code) {
  const HamSymbolInfo* s = ham_symbol_by_code(code);
  return s ? s->name : "";
}

HamGroup ham_symbol_group(char32_t code) {
  const HamSymbolInfo* s = ham_symbol_by_code(code);
  return s ? s->group : HamGroup::Punctuation;
}

}  // namespace sw::notation

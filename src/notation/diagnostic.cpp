// Diagnostic helpers: the error test every caller uses and the one-line form the CLI and logs
// print. (Written on the notation branch because its parsers need it first; the foundation
// branch owns the contract in diagnostic.h.)
#include "notation/diagnostic.h"

namespace sw::notation {

bool has_error(const std::vector<Diagnostic>& diagnostics) {
  for (const Diagnostic& d : diagnostics) {
    if (d.severity == Severity::Error) return true;
  }
  return false;
}

std::string format_diagnostic(const Diagnostic& d) {
  std::string out = "line " + std::to_string(d.line) + ", column " + std::to_string(d.column) + ": ";
  if (d.severity == Severity::Warning) out += "warning: ";
  out += d.message;
  if (!d.symbol.empty()) out += " (symbol '" + d.symbol + "')";
  return out;
}

}  // namespace sw::notation

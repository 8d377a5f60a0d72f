// Diagnostic helpers: whether a list fails a parse, and the one-line form the CLI and logs print.
#include "notation/diagnostic.h"

namespace sw::notation {

bool has_error(const std::vector<Diagnostic>& diagnostics) {
  for (const Diagnostic& d : diagnostics) {
    if (d.severity == Severity::Error) return true;
  }
  return false;
}

std::string format_diagnostic(const Diagnostic& d) {
  // "line 3, column 14: unknown symbol 'hamfoo'" — the symbol follows the message so that messages
  // read as sentences ("unknown symbol", "expected ')' here") whatever the symbol is.
  std::string out = "line " + std::to_string(d.line) + ", column " + std::to_string(d.column) + ": ";
  if (d.severity == Severity::Warning) out += "warning: ";
  out += d.message.empty() ? std::string("error") : d.message;
  if (!d.symbol.empty()) out += " '" + d.symbol + "'";
  return out;
}

}  // namespace sw::notation

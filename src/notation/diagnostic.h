// Diagnostic: what was wrong and where — the error value every parser and loader returns.
// Nothing in the core throws across the WASM boundary; callers print these or turn them into
// 4xx JSON (server) and underlines (notation editor).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sw::notation {

enum class Severity { Error, Warning };

struct Diagnostic {
  Severity severity = Severity::Error;
  std::size_t offset = 0;   // byte offset into the input (UTF-8)
  std::size_t length = 0;   // bytes covered (0: a point), for underlining in the editor
  int line = 1;             // 1-based
  int column = 1;           // 1-based, in Unicode code points
  std::string symbol;       // the offending symbol / token as written ("hamfoo", "U+E0FF", ")")
  std::string message;      // what was wrong, in plain English
};

// True if any diagnostic is an error (warnings alone do not fail a parse).
bool has_error(const std::vector<Diagnostic>& diagnostics);
// "line 3, column 14: unknown symbol 'hamfoo': ..." — one line, for the CLI and logs.
std::string format_diagnostic(const Diagnostic& d);

}  // namespace sw::notation

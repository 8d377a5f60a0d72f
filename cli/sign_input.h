// Reading signs for `check` and `coverage`: a file (or stdin) in any supported notation, detected
// by extension and content — .sigml/.xml (H- or G-SiGML), .jsonl (one JSON object a line with a
// `hamnosys`, `names`, or `notation` field and optionally `gloss`, `format`), anything else by
// content (formula or HamNoSys text, one sign a line).
#pragma once

#include <string>
#include <vector>

#include "notation/parse.h"

namespace sw::cli {

struct InputSign {
  notation::SignParse parse;            // gloss, spec, diagnostics
  notation::NotationFormat format = notation::NotationFormat::Formula;
  int line = 1;                         // line of the sign in the file
};

struct InputOptions {
  std::string jsonl_field;  // .jsonl: which field ("hamnosys", "names", "notation"); empty: first present
};

// Reads `path` ("-" for stdin). Returns false (with `error`) when the file cannot be read.
bool read_text(const std::string& path, std::string* text, std::string* error);
// Every sign of `text` from `path` (the path decides .jsonl / .sigml handling).
std::vector<InputSign> parse_input(const std::string& path, const std::string& text, const InputOptions& options);

}  // namespace sw::cli

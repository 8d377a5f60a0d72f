// `signweave convert IN --to sigml|hsigml|gsigml|hamnosys|formula [--out FILE] [--field F]`:
// reads every sign of a file in any notation the core reads (sign_input.h) and writes them in
// another, with the core's printers (src/notation/*_printer.cpp), so the dictionary can feed
// CWASA/JASigning users and take their files back. `sigml` is H-SiGML (hns_sign, what CWASA
// plays from HamNoSys); formula and HamNoSys are one `GLOSS = ...` line per sign.
//
// Signs that do not parse are not written: each is reported on stderr with its line and first
// error, and the exit code is 1 (0 when every sign converted, 2 on usage errors).
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "command.h"
#include "notation/diagnostic.h"
#include "notation/parse.h"
#include "sign_input.h"

namespace sw::cli {
namespace {

bool target_format(const std::string& name, notation::NotationFormat* format) {
  if (name == "sigml") {
    *format = notation::NotationFormat::HSiGML;
    return true;
  }
  return notation::format_from_name(name, format);
}

int convert_command(const std::vector<std::string>& args) {
  std::string path, to, out_path;
  InputOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--to" && i + 1 < args.size()) {
      to = args[++i];
    } else if (args[i] == "--out" && i + 1 < args.size()) {
      out_path = args[++i];
    } else if (args[i] == "--field" && i + 1 < args.size()) {
      options.jsonl_field = args[++i];
    } else if (path.empty() && (args[i] == "-" || args[i].rfind("--", 0) != 0)) {
      path = args[i];
    } else {
      std::fprintf(stderr, "convert: unexpected argument '%s'\n", args[i].c_str());
      return 2;
    }
  }
  notation::NotationFormat format = notation::NotationFormat::Formula;
  if (path.empty() || !target_format(to, &format)) {
    std::fprintf(
        stderr,
        "usage: signweave convert IN|- --to sigml|hsigml|gsigml|hamnosys|formula [--out FILE]\n");
    return 2;
  }
  std::string text, error;
  if (!read_text(path, &text, &error)) {
    std::fprintf(stderr, "convert: %s\n", error.c_str());
    return 2;
  }
  std::vector<notation::SignSpec> signs;
  int rejected = 0;
  for (const InputSign& s : parse_input(path, text, options)) {
    if (s.parse.ok()) {
      signs.push_back(*s.parse.spec);
      continue;
    }
    ++rejected;
    std::string reason = "no sign";
    for (const notation::Diagnostic& d : s.parse.diagnostics) {
      if (d.severity == notation::Severity::Error) {
        reason = notation::format_diagnostic(d);
        break;
      }
    }
    std::fprintf(stderr, "convert: %s line %d '%s' not converted: %s\n", path.c_str(), s.line,
                 s.parse.gloss.c_str(), reason.c_str());
  }
  const std::string printed = notation::print_notation(signs, format);
  if (out_path.empty()) {
    std::fwrite(printed.data(), 1, printed.size(), stdout);
  } else {
    std::ofstream out(out_path, std::ios::binary);
    out << printed;
    if (!out) {
      std::fprintf(stderr, "convert: cannot write %s\n", out_path.c_str());
      return 2;
    }
  }
  std::fprintf(stderr, "convert: %zu signs written as %s, %d not converted\n", signs.size(),
               notation::format_name(format), rejected);
  return rejected == 0 && !signs.empty() ? 0 : 1;
}

}  // namespace

SW_CLI_COMMAND("convert",
               "convert IN|- --to sigml|hsigml|gsigml|hamnosys|formula [--out FILE]   write signs "
               "in another notation",
               convert_command);

}  // namespace sw::cli

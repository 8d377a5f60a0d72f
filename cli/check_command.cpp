// `signweave check FILE|-`: parses every sign of a file in any supported notation (and runs the
// registered per-sign steps, e.g. synthesis) and prints one JSON object per sign, then a summary
// line. Exit code 0 when every sign is clean, 1 when any has an error, 2 on usage errors.
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "command.h"
#include "notation/sign_spec_json.h"
#include "sign_input.h"
#include "sign_steps.h"

namespace sw::cli {
namespace {

int check_command(const std::vector<std::string>& args) {
  std::string path;
  InputOptions options;
  bool with_spec = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--field" && i + 1 < args.size()) {
      options.jsonl_field = args[++i];
    } else if (args[i] == "--spec") {
      with_spec = true;
    } else if (path.empty()) {
      path = args[i];
    } else {
      std::fprintf(stderr, "check: unexpected argument '%s'\n", args[i].c_str());
      return 2;
    }
  }
  if (path.empty()) {
    std::fprintf(stderr, "usage: signweave check FILE|- [--field hamnosys|names|notation] [--spec]\n");
    return 2;
  }
  std::string text, error;
  if (!read_text(path, &text, &error)) {
    std::fprintf(stderr, "check: %s\n", error.c_str());
    return 2;
  }
  int signs = 0, ok = 0, with_errors = 0, warnings = 0;
  std::vector<int> step_ok(sign_steps().size(), 0);
  for (const InputSign& s : parse_input(path, text, options)) {
    nlohmann::json out;
    out["gloss"] = s.parse.gloss;
    out["format"] = notation::format_name(s.format);
    out["line"] = s.line;
    bool sign_ok = s.parse.ok();
    nlohmann::json diagnostics = nlohmann::json::array();
    for (const notation::Diagnostic& d : s.parse.diagnostics) {
      diagnostics.push_back({{"line", d.line}, {"column", d.column}, {"symbol", d.symbol},
                             {"message", d.message},
                             {"severity", d.severity == notation::Severity::Error ? "error" : "warning"}});
      if (d.severity == notation::Severity::Warning) ++warnings;
    }
    if (s.parse.spec) {
      nlohmann::json steps = nlohmann::json::object();
      for (std::size_t k = 0; k < sign_steps().size(); ++k) {
        const SignStepResult r = sign_steps()[k].fn(*s.parse.spec);
        steps[sign_steps()[k].name] = {{"ok", r.ok}, {"error", r.error}, {"detail", r.detail}};
        if (r.ok) ++step_ok[k];
        sign_ok = sign_ok && r.ok;
      }
      if (!steps.empty()) out["steps"] = steps;
      if (with_spec) out["spec"] = notation::sign_to_json(*s.parse.spec);
    }
    out["parsed"] = s.parse.ok();  // the notation alone, whatever the steps say
    out["ok"] = sign_ok;           // parsed, and every step (synthesis) succeeded
    out["diagnostics"] = diagnostics;
    std::printf("%s\n", out.dump().c_str());
    ++signs;
    if (sign_ok) ++ok;
    else ++with_errors;
  }
  nlohmann::json summary = {{"signs", signs}, {"ok", ok}, {"failed", with_errors}, {"warnings", warnings}};
  for (std::size_t k = 0; k < sign_steps().size(); ++k) summary[sign_steps()[k].name] = step_ok[k];
  std::printf("%s\n", nlohmann::json({{"summary", summary}}).dump().c_str());
  return with_errors == 0 && signs > 0 ? 0 : 1;
}

}  // namespace

SW_CLI_COMMAND("check", "check FILE|- [--field hamnosys|names|notation] [--spec]   parse every sign, one JSON line each",
               check_command);

}  // namespace sw::cli

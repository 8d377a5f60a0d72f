// `signweave coverage FILE...`: the same parsing as `check` over whole corpora, quietly: one JSON
// summary per file (signs, parsed, clean, each registered step's successes, top failure reasons,
// parse time per sign).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "command.h"
#include "sign_input.h"
#include "sign_steps.h"

namespace sw::cli {
namespace {

// A failure reason without its particulars, so that equal causes count together:
// "expected a handshape (...), found 'hamextfingeru'" -> "expected a handshape (...)".
std::string reason_of(const std::string& message) {
  const std::size_t found = message.find(", found");
  return found == std::string::npos ? message : message.substr(0, found);
}

int coverage_command(const std::vector<std::string>& args) {
  InputOptions options;
  std::vector<std::string> paths;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--field" && i + 1 < args.size()) {
      options.jsonl_field = args[++i];
    } else {
      paths.push_back(args[i]);
    }
  }
  if (paths.empty()) {
    std::fprintf(stderr, "usage: signweave coverage FILE... [--field hamnosys|names|notation]\n");
    return 2;
  }
  int status = 0;
  for (const std::string& path : paths) {
    std::string text, error;
    if (!read_text(path, &text, &error)) {
      std::printf("%s\n", nlohmann::json({{"file", path}, {"error", error}}).dump().c_str());
      status = 2;
      continue;
    }
    const auto start = std::chrono::steady_clock::now();
    const std::vector<InputSign> signs = parse_input(path, text, options);
    const double parse_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int parsed = 0, clean = 0;
    std::vector<int> step_ok(sign_steps().size(), 0);
    std::map<std::string, int> reasons;
    std::map<std::string, int> formats;
    for (const InputSign& s : signs) {
      ++formats[notation::format_name(s.format)];
      if (s.parse.spec) ++parsed;
      if (s.parse.ok()) ++clean;
      for (const notation::Diagnostic& d : s.parse.diagnostics) {
        if (d.severity == notation::Severity::Error) ++reasons[reason_of(d.message)];
      }
      if (s.parse.spec) {
        for (std::size_t k = 0; k < sign_steps().size(); ++k) {
          const SignStepResult r = sign_steps()[k].fn(*s.parse.spec);
          if (r.ok) ++step_ok[k];
          else ++reasons[std::string(sign_steps()[k].name) + ": " + reason_of(r.error)];
        }
      }
    }
    std::vector<std::pair<int, std::string>> top;
    for (const auto& [reason, n] : reasons) top.emplace_back(n, reason);
    std::sort(top.begin(), top.end(), [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
    nlohmann::json top_json = nlohmann::json::array();
    for (std::size_t i = 0; i < top.size() && i < 5; ++i) top_json.push_back({{"reason", top[i].second}, {"count", top[i].first}});
    nlohmann::json out = {{"file", path},          {"formats", formats},
                          {"signs", signs.size()}, {"parsed", parsed},
                          {"clean", clean},        {"top_failure_reasons", top_json},
                          {"parse_us_per_sign", signs.empty() ? 0.0 : 1e6 * parse_s / static_cast<double>(signs.size())}};
    for (std::size_t k = 0; k < sign_steps().size(); ++k) {
      out[std::string(sign_steps()[k].name) == "synthesise" ? "synthesised" : sign_steps()[k].name] = step_ok[k];
    }
    std::printf("%s\n", out.dump().c_str());
  }
  return status;
}

}  // namespace

SW_CLI_COMMAND("coverage", "coverage FILE... [--field hamnosys|names|notation]   per-file summary JSON", coverage_command);

}  // namespace sw::cli

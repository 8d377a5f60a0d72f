// `signweave-cli parity [NAME]`: prints a parity case's JSON, or the list of cases (cli/parity.h).
// Hidden from users (./signweave has no parity subcommand); tests/node/wasm_loader.mjs runs it.
#include <cstdio>
#include <map>
#include <string>

#include "command.h"
#include "parity.h"

namespace sw::cli {
namespace {

struct ParityCase {
  const char* description;
  ParityCaseFn fn;
};

std::map<std::string, ParityCase>& cases() {
  static std::map<std::string, ParityCase> table;
  return table;
}

int parity_command(const std::vector<std::string>& args) {
  if (args.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& [name, entry] : cases()) list.push_back({{"name", name}, {"description", entry.description}});
    std::printf("%s\n", list.dump().c_str());
    return 0;
  }
  if (args.size() != 1) {
    std::fprintf(stderr, "usage: signweave-cli parity [CASE]\n");
    return 2;
  }
  const auto it = cases().find(args[0]);
  if (it == cases().end()) {
    std::fprintf(stderr, "parity: unknown case '%s' (run 'signweave-cli parity' for the list)\n", args[0].c_str());
    return 2;
  }
  const nlohmann::json result = it->second.fn();
  std::printf("%s\n", result.dump().c_str());
  return 0;
}

}  // namespace

int register_parity_case(const char* name, const char* description, ParityCaseFn fn) {
  cases()[name] = ParityCase{description, fn};
  return 0;
}

SW_CLI_COMMAND("parity", "parity [CASE]   (internal) print a native/WASM parity case as JSON", parity_command);

}  // namespace sw::cli

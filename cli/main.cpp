// signweave-cli: the native command line behind ./signweave check|coverage|synth|import.
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "command.h"

namespace sw::cli {
namespace {
struct Entry {
  const char* usage;
  CommandFn fn;
};
std::map<std::string, Entry>& commands() {
  static std::map<std::string, Entry> table;
  return table;
}
}  // namespace

int register_command(const char* name, const char* usage, CommandFn fn) {
  commands()[name] = Entry{usage, fn};
  return 0;
}

}  // namespace sw::cli

int main(int argc, char** argv) {
  auto& table = sw::cli::commands();
  if (argc < 2 || table.find(argv[1]) == table.end()) {
    std::fprintf(stderr, "usage: signweave <command> ...\ncommands:\n");
    for (const auto& [name, entry] : table) std::fprintf(stderr, "  %s\n", entry.usage);
    return 2;
  }
  std::vector<std::string> args(argv + 2, argv + argc);
  return table[argv[1]].fn(args);
}

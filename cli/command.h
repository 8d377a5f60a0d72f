// CLI subcommands register themselves here (one file per command: check_command.cpp,
// coverage_command.cpp, synth_command.cpp, import_command.cpp) so cli/main.cpp stays a dispatcher.
#pragma once

#include <string>
#include <vector>

namespace sw::cli {

// Returns the process exit code: 0 success, 1 the input had errors, 2 usage error.
using CommandFn = int (*)(const std::vector<std::string>& args);
int register_command(const char* name, const char* usage, CommandFn fn);

}  // namespace sw::cli

#define SW_CLI_COMMAND(name, usage, fn) \
  static const int sw_cli_registered_##fn = sw::cli::register_command(name, usage, fn)

// Per-sign steps after parsing, plugged into `check` and `coverage`: the synthesis branch
// registers "synthesise" here (SW_CLI_SIGN_STEP in its own cli/*.cpp) and both commands run every
// registered step on each sign that parsed, reporting its result per sign and counting successes.
// Steps are looked up at run time, so check/coverage build and work without any.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "notation/sign_spec.h"

namespace sw::cli {

struct SignStepResult {
  bool ok = false;
  std::string error;      // why not, in plain English (empty when ok)
  nlohmann::json detail;  // anything worth printing per sign (e.g. duration_s, frames)
};
using SignStepFn = SignStepResult (*)(const notation::SignSpec& sign);

struct SignStep {
  const char* name;
  SignStepFn fn;
};

int register_sign_step(const char* name, SignStepFn fn);
// In registration order (static initialisation order across files is unspecified: steps must
// not depend on each other).
const std::vector<SignStep>& sign_steps();

}  // namespace sw::cli

#define SW_CLI_SIGN_STEP(name, fn) \
  static const int sw_cli_step_registered_##fn = sw::cli::register_sign_step(name, fn)

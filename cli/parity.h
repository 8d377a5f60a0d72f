// Native/WASM parity cases: named, deterministic computations whose results the node tests compare
// with the same computation run in the WebAssembly module (ARCHITECTURE.md: "the same input gives the
// same clip natively and in WASM, to 1e-5").
//
// Each module registers its cases in cli/parity_<module>.cpp:
//
//   static nlohmann::json euler_case() { return {{"inputs", ...}, {"outputs", ...}}; }
//   SW_PARITY_CASE("euler", "six orders: angles -> quat -> angles", euler_case);
//
// `signweave-cli parity` lists the cases (JSON array); `signweave-cli parity NAME` prints the case's
// JSON on one line (doubles at full precision). A case should print its inputs as well as its
// outputs, so the node test feeds exactly those inputs to the WASM side and no generator is written
// twice. Cases must not read files or the clock: the same binary prints the same bytes every run.
#pragma once

#include <nlohmann/json.hpp>

namespace sw::cli {

using ParityCaseFn = nlohmann::json (*)();
int register_parity_case(const char* name, const char* description, ParityCaseFn fn);

}  // namespace sw::cli

#define SW_PARITY_CASE(name, description, fn) \
  static const int sw_parity_registered_##fn = sw::cli::register_parity_case(name, description, fn)

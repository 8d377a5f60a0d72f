// The registry of per-sign steps (see sign_steps.h).
#include "sign_steps.h"

namespace sw::cli {
namespace {
std::vector<SignStep>& table() {
  static std::vector<SignStep> steps;
  return steps;
}
}  // namespace

int register_sign_step(const char* name, SignStepFn fn) {
  table().push_back(SignStep{name, fn});
  return 0;
}

const std::vector<SignStep>& sign_steps() { return table(); }

}  // namespace sw::cli

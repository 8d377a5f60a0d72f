// The "synthesise" step of `check` and `coverage` (cli/sign_steps.h): every sign that parsed is
// also synthesised on the project's avatar, so a file is checked the way the server and the page
// will use it — a location the avatar cannot reach or an option out of range fails here too.
#include <memory>

#include "project_root.h"
#include "sign_steps.h"
#include "synthesis/clip_steps.h"
#include "synthesis/rig.h"
#include "synthesis/signing_avatar.h"
#include "synthesis/synthesize.h"

namespace sw::cli {
namespace {

// Loaded once per process: the avatar and its measurements (rig, body capsules) cost a few
// milliseconds, a sign about half a millisecond.
struct LoadedSynthesizer {
  synthesis::SigningAvatar avatar;
  std::unique_ptr<synthesis::Synthesizer> synthesizer;
  synthesis::Rig rig;  // for the arms' per-frame steps
  std::string rig_error;
};

const LoadedSynthesizer& loaded() {
  // Built in place and never moved: the Synthesizer keeps a pointer to the avatar.
  static const LoadedSynthesizer* instance = [] {
    auto* l = new LoadedSynthesizer;
    l->avatar = synthesis::load_signing_avatar_file(project_root() + "/models/signweave-avatar.glb");
    if (l->avatar.ok()) {
      l->synthesizer = std::make_unique<synthesis::Synthesizer>(l->avatar.avatar);
      if (!synthesis::build_rig(l->avatar.avatar, &l->rig, &l->rig_error) && l->rig_error.empty())
        l->rig_error = "the avatar's rig could not be built";
    }
    return l;
  }();
  return *instance;
}

SignStepResult synthesise(const notation::SignSpec& sign) {
  SignStepResult out;
  const LoadedSynthesizer& l = loaded();
  if (!l.avatar.ok()) {
    out.error = "avatar: " + l.avatar.error;
    return out;
  }
  const synthesis::SynthesisResult r = l.synthesizer->sign(sign, synthesis::SynthesisOptions{});
  if (!r.ok()) {
    out.error = r.errors.front().where + ": " + r.errors.front().message;
    return out;
  }
  out.ok = true;
  out.detail = {{"duration_s", r.clip.duration_s()},
                {"frames", r.clip.frame_count},
                {"max_reach_error_m", r.report.max_reach_error_m},
                {"max_penetration_m", r.report.max_penetration_m},
                {"warnings", r.report.warnings.size()}};
  // How far a wrist or elbow moves in one frame, and the largest change of that step (the whole
  // clip, rest transitions included): a pose that flips shows here though no depth does. The
  // smoothness tests hold the lexicon to 0.10 m and 0.056 m (human signing speed and
  // acceleration at 30 fps).
  if (l.rig_error.empty()) {
    const synthesis::FrameSteps steps = synthesis::measure_frame_steps(l.rig, r.clip);
    out.detail["max_arm_step_m"] = steps.step_m;
    out.detail["max_arm_step_at"] = steps.step_what;
    out.detail["max_arm_step_change_m"] = steps.change_m;
    out.detail["max_arm_step_change_at"] = steps.change_what;
  }
  return out;
}

}  // namespace

SW_CLI_SIGN_STEP("synthesise", synthesise);

}  // namespace sw::cli

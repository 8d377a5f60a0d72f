// How deep the arms of a synthesised clip go where they must not: an upper arm or forearm in the
// trunk, a forearm through the other, with the intended-contact exemptions synthesis applies.
// Shared by the lexicon tests that walk the data at one setting (alphabet_test.cpp) and at all
// nine (motion_smoothness_test.cpp, which measures depth and smoothness on the same clips).
#pragma once

#include <string>

#include "synthesis/collision.h"
#include "synthesis/sign_motion.h"
#include "synthesis/synthesize.h"

namespace sw::synthesis::testing {

// Deepest arm penetration over a clip (exemptions as synthesis applies them), split into arm in
// the trunk and forearm through forearm.
struct ArmDepths {
  float trunk_m = 0.0f, forearms_m = 0.0f;
  std::string trunk_what, forearms_what;
};
inline ArmDepths arm_depths(const SynthContext& ctx, const SynthesisResult& r) {
  ArmDepths out;
  PoseBuilder pb(ctx.rig);
  const auto& ex = r.report.intended_contact;
  for (int f = 0; f < r.clip.frame_count; ++f) {
    pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * ctx.rig.joint_count]);
    for (Side s : {kLeft, kRight}) {
      bool contact = ex[f] & exempt_bit(s, false);
      bool hands = !(ex[f] & exempt_bit(s, true)) && !(ex[f] & exempt_bit(other(s), true));
      Penetration t = arm_penetration(ctx.body, pb, s, true, contact, false);
      if (t.depth_m > out.trunk_m) {
        out.trunk_m = t.depth_m;
        out.trunk_what = t.what + " at frame " + std::to_string(f);
      }
      Penetration p = arm_penetration(ctx.body, pb, s, false, contact, hands);
      if (p.depth_m > out.forearms_m) {
        out.forearms_m = p.depth_m;
        out.forearms_what = p.what + " at frame " + std::to_string(f);
      }
    }
  }
  return out;
}

}  // namespace sw::synthesis::testing

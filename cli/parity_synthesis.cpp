// Parity case for src/synthesis: a short phrase (formula notation, two signs with movement,
// symmetry and a thumb-contact handshape) synthesised on the procedural reference humanoid; the
// WASM API's synthCompile on the same text and avatar must give the same clip to 1e-5.
#include "parity.h"
#include "synthesis/clip_sampler.h"
#include "synthesis/phrase_text.h"
#include "synthesis/reference_humanoid.h"
#include "synthesis/synthesize.h"

namespace sw::cli {
namespace {

// Shared with tests/node/synthesis.test.mjs through the case's "inputs".
const char* kParityText =
    "HELLO = R(H(flat), E(u), P(o), Loc(forehead, right, close), M(straight r))\n"
    "OK = R(H(pinch12), E(u), P(l), Loc(chest, right, none), M(circle axis=o cw small))";

nlohmann::json synthesis_case() {
  avatar::Avatar av = synthesis::make_reference_humanoid();
  synthesis::PhraseText phrase = synthesis::phrase_from_text(kParityText, {});
  nlohmann::json out = {{"inputs", {{"text", kParityText}, {"avatar", "reference"}}}};
  if (!phrase.ok()) {
    out["error"] = phrase.errors.empty() ? "no signs" : phrase.errors[0].message;
    return out;
  }
  synthesis::SynthesisResult r = synthesis::synthesize_phrase(phrase.items, av);
  if (!r.ok()) {
    out["error"] = r.errors[0].message;
    return out;
  }
  const synthesis::Clip& c = r.clip;
  nlohmann::json samples = nlohmann::json::array();
  std::vector<glm::quat> q(c.joint_count());
  // Ten times spread over the clip, between frames too (exercises the sampler's slerp).
  for (int i = 0; i < 10; ++i) {
    double t = c.duration_s() * (i + 0.37) / 10.0;
    synthesis::sample_clip(c, t, q.data(), nullptr, nullptr);
    nlohmann::json flat = nlohmann::json::array();
    for (const auto& r4 : q) flat.insert(flat.end(), {r4.x, r4.y, r4.z, r4.w});
    samples.push_back({{"t", t}, {"rotations", flat}});
  }
  out["outputs"] = {{"frame_count", c.frame_count},
                    {"joint_count", c.joint_count()},
                    {"segments", c.segments.size()},
                    {"samples", samples}};
  return out;
}

}  // namespace

SW_PARITY_CASE("synthesis", "formula phrase on the reference humanoid: sampled clip rotations", synthesis_case);

}  // namespace sw::cli

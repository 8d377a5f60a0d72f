// Embind API of synthesis: notation or a typed phrase -> clip handle; its segments (captions) as
// JSON; the clip sampled at t into local joint transforms (a Float32Array VIEW into WASM memory,
// 10 floats per joint: tx ty tz qx qy qz qw sx sy sz, the avatar API's layout); BVH / GLB bytes.
// Thin by rule: handle bookkeeping and argument conversion; the logic is in src/synthesis.
//
// JS:
//   const a = core.synthAvatarLoad(glbBytes);      // {id} or {error}; anchors computed
//   const ref = core.synthAvatarReference();        // {id}: the procedural reference humanoid
//   core.synthSetAlphabet(a.id, jsonlText);         // optional: fingerspelling for typed text
//   const c = core.synthCompile(a.id, text, {speed: 1, leftHanded: false, fps: 30});
//                                                   // {id, frames, duration, fingerspelled} or {error}
//   JSON.parse(core.synthSegments(c.id));           // [{kind, label, word, start, end}, ...]
//   const locals = core.synthSample(c.id, t);       // Float32Array view, valid until next call
//   core.synthExportBvh(c.id); core.synthExportGlb(c.id);   // string / Uint8Array (copied out)
//   core.synthClipFree(c.id); core.synthAvatarFree(a.id);
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "math/transform.h"
#include "synthesis/clip_export.h"
#include "synthesis/clip_sampler.h"
#include "synthesis/phrase_text.h"
#include "synthesis/reference_humanoid.h"
#include "synthesis/signing_avatar.h"
#include "synthesis/synthesize.h"

namespace {

using emscripten::typed_memory_view;
using emscripten::val;

struct SynthAvatar {
  sw::avatar::Avatar avatar;
  std::unique_ptr<sw::synthesis::Synthesizer> synth;  // measures `avatar` once; points into it
  std::vector<sw::synthesis::AlphabetEntry> alphabet;
};
struct SynthClip {
  int avatar = 0;
  sw::synthesis::Clip clip;
  std::vector<sw::math::Transform> locals;  // the sample view's memory
};

std::map<int, std::unique_ptr<SynthAvatar>>& avatars() {
  static std::map<int, std::unique_ptr<SynthAvatar>> m;
  return m;
}
std::map<int, std::unique_ptr<SynthClip>>& clips() {
  static std::map<int, std::unique_ptr<SynthClip>> m;
  return m;
}
int next_id() {
  static int id = 1;
  return id++;
}
val error(const std::string& message) {
  val out = val::object();
  out.set("error", message);
  return out;
}
val registered(sw::synthesis::SigningAvatar&& a) {
  if (!a.ok()) return error(a.error);
  auto entry = std::make_unique<SynthAvatar>();
  entry->avatar = std::move(a.avatar);
  entry->synth = std::make_unique<sw::synthesis::Synthesizer>(entry->avatar);
  if (!entry->synth->ok()) return error(entry->synth->error());
  int id = next_id();
  avatars()[id] = std::move(entry);
  val out = val::object();
  out.set("id", id);
  return out;
}

val synth_avatar_load(const std::string& bytes) {
  return registered(sw::synthesis::load_signing_avatar(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
}

val synth_avatar_reference() {
  sw::synthesis::SigningAvatar a;
  a.avatar = sw::synthesis::make_reference_humanoid();
  sw::synthesis::prepare_signing_avatar(&a);
  return registered(std::move(a));
}

bool synth_avatar_free(int id) { return avatars().erase(id) > 0; }

std::string synth_set_alphabet(int avatar, const std::string& jsonl) {
  auto it = avatars().find(avatar);
  if (it == avatars().end()) return "no avatar " + std::to_string(avatar);
  std::vector<sw::synthesis::AlphabetEntry> entries;
  std::string err;
  if (!sw::synthesis::parse_alphabet_jsonl(jsonl, &entries, &err)) return err;
  it->second->alphabet = std::move(entries);
  return "";
}

val synth_compile(int avatar, const std::string& text, val options) {
  auto it = avatars().find(avatar);
  if (it == avatars().end()) return error("no avatar " + std::to_string(avatar));
  sw::synthesis::SynthesisOptions opt;
  // Each option read once and kept where it is given (not undefined). Not typeOf() and
  // hasOwnProperty(): each of those is several calls into JS (hasOwnProperty looks up
  // Object.prototype.hasOwnProperty and calls it), and together they were 2-3 % of a lexicon
  // sign's CPU time in WASM (node --cpu-prof). A primitive has none of these properties.
  if (!options.isUndefined() && !options.isNull()) {
    const val speed = options["speed"], fps = options["fps"], left_handed = options["leftHanded"];
    if (!speed.isUndefined()) opt.speed = speed.as<float>();
    if (!fps.isUndefined()) opt.fps = fps.as<float>();
    if (!left_handed.isUndefined()) opt.left_handed = left_handed.as<bool>();
  }
  sw::synthesis::PhraseText phrase = sw::synthesis::phrase_from_text(text, it->second->alphabet);
  if (!phrase.ok()) return error(phrase.errors.empty() ? "no signs in the text" : phrase.errors[0].where + ": " + phrase.errors[0].message);
  sw::synthesis::SynthesisResult r = it->second->synth->phrase(phrase.items, opt);
  if (!r.ok()) return error(r.errors[0].where + ": " + r.errors[0].message);
  auto c = std::make_unique<SynthClip>();
  c->avatar = avatar;
  c->clip = std::move(r.clip);
  c->locals.resize(c->clip.joint_names.size());
  val out = val::object();
  out.set("frames", c->clip.frame_count);
  out.set("duration", c->clip.duration_s());
  out.set("joints", c->clip.joint_count());
  out.set("fingerspelled", phrase.fingerspelled);
  out.set("maxPenetrationM", r.report.max_penetration_m);
  int id = next_id();
  clips()[id] = std::move(c);
  out.set("id", id);
  return out;
}

std::string synth_segments(int clip) {
  auto it = clips().find(clip);
  if (it == clips().end()) return "[]";
  static const char* kinds[] = {"sign", "letter", "transition", "hold", "pause"};
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : it->second->clip.segments)
    out.push_back({{"kind", kinds[static_cast<int>(s.kind)]}, {"label", s.label},
                   {"word", s.word_index}, {"start", s.start_s}, {"end", s.end_s}});
  return out.dump();
}

val synth_joint_names(int clip) {
  auto it = clips().find(clip);
  val out = val::array();
  if (it == clips().end()) return out;
  const auto& names = it->second->clip.joint_names;
  for (size_t i = 0; i < names.size(); ++i) out.set(static_cast<unsigned>(i), names[i]);
  return out;
}

val synth_sample(int clip, double t_s) {
  auto it = clips().find(clip);
  if (it == clips().end()) return val::null();
  SynthClip& c = *it->second;
  auto av = avatars().find(c.avatar);
  if (av == avatars().end()) return val::null();
  if (!sw::synthesis::sample_clip_local(c.clip, av->second->avatar.skeleton, t_s, c.locals.data()))
    return val::null();
  return val(typed_memory_view(c.locals.size() * 10, reinterpret_cast<const float*>(c.locals.data())));
}

val synth_export(int clip, bool glb) {
  auto it = clips().find(clip);
  if (it == clips().end()) return val::null();
  auto av = avatars().find(it->second->avatar);
  if (av == avatars().end()) return val::null();
  sw::synthesis::ExportResult e = glb ? sw::synthesis::export_glb(it->second->clip, av->second->avatar)
                                      : sw::synthesis::export_bvh(it->second->clip, av->second->avatar);
  if (!e.ok()) return error(e.error);
  if (!glb) return val(std::string(e.bytes.begin(), e.bytes.end()));
  // Copied out: export bytes outlive this call (a view would dangle once `e` is gone).
  val view(typed_memory_view(e.bytes.size(), e.bytes.data()));
  val copy = val::global("Uint8Array").new_(e.bytes.size());
  copy.call<void>("set", view);
  return copy;
}
val synth_export_bvh(int clip) { return synth_export(clip, false); }
val synth_export_glb(int clip) { return synth_export(clip, true); }
bool synth_clip_free(int clip) { return clips().erase(clip) > 0; }

}  // namespace

EMSCRIPTEN_BINDINGS(synthesis_api) {
  emscripten::function("synthAvatarLoad", &synth_avatar_load);
  emscripten::function("synthAvatarReference", &synth_avatar_reference);
  emscripten::function("synthAvatarFree", &synth_avatar_free);
  emscripten::function("synthSetAlphabet", &synth_set_alphabet);
  emscripten::function("synthCompile", &synth_compile);
  emscripten::function("synthSegments", &synth_segments);
  emscripten::function("synthJointNames", &synth_joint_names);
  emscripten::function("synthSample", &synth_sample);
  emscripten::function("synthExportBvh", &synth_export_bvh);
  emscripten::function("synthExportGlb", &synth_export_glb);
  emscripten::function("synthClipFree", &synth_clip_free);
}

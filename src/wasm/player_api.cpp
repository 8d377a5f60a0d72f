// player_api.cpp — the page's player, bound with embind: one avatar, one current clip, and per
// frame the chain  sample the clip at t -> local transforms -> FK -> skinning matrices -> morphs +
// LBS  into buffers the page reads as typed-array views (no per-frame copy; the views stay valid
// until the next loadAvatar, because AvatarInstance never reallocates its buffers).
//
// Thin glue only: loading is synthesis/signing_avatar.h (loader + body anchors + rig check),
// parsing notation/parse.h, synthesis synthesis/synthesize.h (a Synthesizer measures the avatar
// once, so live preview per keystroke stays cheap), sampling synthesis/clip_sampler.h, posing and
// skinning skinning/avatar_instance.h, export synthesis/clip_export.h. This file sequences those
// calls and turns their results into JSON for the page (web/js/signing_core.js).
//
//   const p = new Module.Player();
//   p.loadAvatar(uint8Array)              -> "" or the loader's message
//   JSON.parse(p.avatarInfoJson())        -> { vertex_count, joints[{name, parent}], named{canonical:
//                                            index}, primitives, materials, anchors[], morphs[], height_m }
//   p.indices() p.positions() p.normals() p.jointPositions() p.anchorPositions()   (views)
//   JSON.parse(p.setNotation(text, format, optionsJson))
//   JSON.parse(p.setPhrase(itemsJson, optionsJson))
//        -> { ok, diagnostics[{severity, offset, length, line, column, symbol, message}], errors[],
//             duration_s, frame_count, segments[{kind, label, word_index, start_s, end_s}] }
//   p.update(t_s)                         pose + skin at t (the rest pose when there is no clip)
//   p.hamSymbolName(codePoint)            "hamflathand", or "" for a code point that is no symbol
//   p.exportBvh() -> text;  p.exportGlb() -> Uint8Array view (copy it before the next call)
//
// Errors are values: a bad notation, phrase JSON or option never aborts the module (exceptions
// abort under -sDISABLE_EXCEPTION_CATCHING), so JSON is parsed with allow_exceptions = false.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "notation/hamnosys_symbols.h"
#include "notation/parse.h"
#include "skeleton/humanoid_names.h"
#include "skinning/avatar_instance.h"
#include "skinning/skinning_job.h"
#include "face/channel_set.h"
#include "face/emotion.h"
#include "synthesis/clip_export.h"
#include "synthesis/clip_sampler.h"
#include "synthesis/signing_avatar.h"
#include "synthesis/synthesize.h"

namespace {

using emscripten::typed_memory_view;
using emscripten::val;
using nlohmann::json;

template <typename T>
val view_of(const std::vector<T>& v) {
  return val(typed_memory_view(v.size(), v.data()));
}

json diagnostics_json(const std::vector<sw::notation::Diagnostic>& diagnostics) {
  json out = json::array();
  for (const auto& d : diagnostics) {
    out.push_back({{"severity", d.severity == sw::notation::Severity::Error ? "error" : "warning"},
                   {"offset", d.offset},
                   {"length", d.length},
                   {"line", d.line},
                   {"column", d.column},
                   {"symbol", d.symbol},
                   {"message", d.message}});
  }
  return out;
}

const char* segment_kind_name(sw::synthesis::ClipSegment::Kind kind) {
  using Kind = sw::synthesis::ClipSegment::Kind;
  switch (kind) {
    case Kind::Sign: return "sign";
    case Kind::Letter: return "letter";
    case Kind::Transition: return "transition";
    case Kind::Hold: return "hold";
    case Kind::Pause: return "pause";
  }
  return "sign";
}

// Text from users (labels, notation symbols) may hold invalid UTF-8: replace it rather than let
// dump() throw, which would abort the module.
std::string text_of(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

json error_json(const std::string& where, const std::string& message) {
  return {{"where", where}, {"message", message}};
}

// Options the page may set; anything absent keeps SynthesisOptions' default. A malformed options
// document is reported, not ignored. `label` (optional) names a sign whose notation has no gloss,
// for its caption segment.
bool read_options(const std::string& text, sw::synthesis::SynthesisOptions* options, std::string* error,
                  std::string* label = nullptr) {
  if (text.empty()) return true;
  json doc = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded() || !doc.is_object()) {
    *error = "synthesis options must be a JSON object";
    return false;
  }
  if (auto it = doc.find("left_handed"); it != doc.end()) {
    if (!it->is_boolean()) { *error = "option left_handed must be true or false"; return false; }
    options->left_handed = it->get<bool>();
  }
  // The face channel; the core validates the values (synthesis::validate_options).
  if (auto it = doc.find("emotion"); it != doc.end()) {
    if (!it->is_string()) { *error = "option emotion must be a string"; return false; }
    options->emotion = it->get<std::string>();
  }
  if (auto it = doc.find("intensity"); it != doc.end()) {
    if (!it->is_number()) { *error = "option intensity must be a number from 0 to 1"; return false; }
    options->emotion_intensity = it->get<float>();
  }
  if (auto it = doc.find("mouthing"); it != doc.end()) {
    if (!it->is_boolean()) { *error = "option mouthing must be true or false"; return false; }
    options->mouthing = it->get<bool>();
  }
  if (auto it = doc.find("label"); it != doc.end() && label) {
    if (!it->is_string()) { *error = "option label must be a string"; return false; }
    *label = it->get<std::string>();
  }
  return true;
}

// Format by canonical name ("formula", "hamnosys", "hsigml", "gsigml"), or detected for "auto"/"".
bool read_format(const std::string& name, const std::string& text, sw::notation::NotationFormat* format) {
  if (name.empty() || name == "auto") {
    *format = sw::notation::detect_format(text);
    return true;
  }
  return sw::notation::format_from_name(name, format);
}

class Player {
 public:
  // Takes the bytes as a JS value, not std::string: embind fills a std::string from a Uint8Array
  // one byte at a time in JS (~50-80 ms for the 1.7 MB avatar on the page's main thread), while
  // TypedArray.set copies them into WASM memory at once. An ArrayBuffer is viewed as bytes; anything
  // else arrives empty, which the loader rejects with its message.
  std::string loadAvatar(const emscripten::val& bytes) {
    const emscripten::val u8 = emscripten::val::global("Uint8Array");
    const emscripten::val view = bytes.instanceof(u8) ? bytes
                                 : bytes.instanceof(emscripten::val::global("ArrayBuffer")) ? u8.new_(bytes)
                                                                                             : u8.new_(0);
    std::vector<std::uint8_t> data(view["length"].as<std::size_t>());
    emscripten::val(emscripten::typed_memory_view(data.size(), data.data())).call<void>("set", view);
    sw::synthesis::SigningAvatar loaded = sw::synthesis::load_signing_avatar(data.data(), data.size());
    if (!loaded.ok()) return loaded.error;
    // Release in dependency order: the instance and synthesizer point into the avatar.
    instance_.reset();
    synthesizer_.reset();
    clip_.reset();
    avatar_ = std::make_unique<sw::avatar::Avatar>(std::move(loaded.avatar));
    synthesizer_ = std::make_unique<sw::synthesis::Synthesizer>(*avatar_);
    if (!synthesizer_->ok()) {
      const std::string error = synthesizer_->error();
      synthesizer_.reset();
      avatar_.reset();
      return error;
    }
    instance_ = std::make_unique<sw::skinning::AvatarInstance>(*avatar_);
    joint_positions_.assign(3 * std::size_t(avatar_->skeleton.joint_count()), 0.0f);
    path_ = sw::skinning::simd_available() ? sw::skinning::SkinningPath::Simd : sw::skinning::SkinningPath::Scalar;
    // Idle in synthesis' rest pose (arms down): an empty phrase is one frame of it. The file's
    // bind pose is a T-pose, which nobody stands in.
    json rest{{"errors", json::array()}};
    adopt(synthesizer_->phrase({}, sw::synthesis::SynthesisOptions{}), rest);
    update(0.0);
    return "";
  }

  std::string avatarInfoJson() const {
    if (!avatar_) return "null";
    const sw::avatar::Avatar& a = *avatar_;
    json joints = json::array();
    for (const auto& j : a.skeleton.joints) joints.push_back({{"name", j.name}, {"parent", j.parent}});
    json named = json::object();
    for (int id = 0; id < int(a.canonical_to_joint.size()); ++id) {
      named[std::string(sw::skeleton::humanoid_joint_name(id))] = a.canonical_to_joint[std::size_t(id)];
    }
    json primitives = json::array();
    for (const auto& p : a.mesh.primitives) {
      primitives.push_back({{"first_index", p.first_index}, {"index_count", p.index_count}, {"material", p.material}});
    }
    json materials = json::array();
    for (const auto& m : a.mesh.materials) {
      materials.push_back({{"name", m.name},
                           {"base_color", {m.base_color.r, m.base_color.g, m.base_color.b, m.base_color.a}},
                           {"roughness", m.roughness},
                           {"metallic", m.metallic}});
    }
    json anchors = json::array();
    for (const auto& an : a.anchors) anchors.push_back(an.name);
    json morphs = json::array();
    bool has_face_channels = false;
    for (const auto& m : a.morphs) {
      morphs.push_back(m.name);
      has_face_channels = has_face_channels || sw::face::channel_index(m.name) >= 0;
    }
    // The page shows the face controls only for an avatar whose morph targets the face layer drives.
    json face = nullptr;
    if (has_face_channels) face = json{{"emotions", sw::face::emotion_names()}};
    // Stature from the bind-pose mesh: the camera frames the figure with it.
    float min_y = std::numeric_limits<float>::max(), max_y = std::numeric_limits<float>::lowest();
    for (const auto& p : a.mesh.positions) {
      min_y = std::min(min_y, p.y);
      max_y = std::max(max_y, p.y);
    }
    return json{{"vertex_count", a.mesh.positions.size()},
                {"triangle_count", a.mesh.indices.size() / 3},
                {"joints", joints},
                {"named", named},
                {"primitives", primitives},
                {"materials", materials},
                {"anchors", anchors},
                {"morphs", morphs},
                {"face", face},
                {"height_m", a.mesh.positions.empty() ? 0.0f : max_y - min_y}}
        .dump(-1, ' ', false, json::error_handler_t::replace);
  }

  val indices() const { return avatar_ ? view_of(avatar_->mesh.indices) : val::null(); }
  val positions() const { return instance_ ? view_of(instance_->positions()) : val::null(); }
  val normals() const { return instance_ ? view_of(instance_->normals()) : val::null(); }
  val jointPositions() const { return view_of(joint_positions_); }
  val anchorPositions() const { return instance_ ? view_of(instance_->anchor_positions()) : val::null(); }

  // Parse only (the editor's underline without a preview): { ok, format, diagnostics }.
  std::string parse(const std::string& text, const std::string& format_name) const {
    sw::notation::NotationFormat format{};
    if (!read_format(format_name, text, &format)) {
      return text_of(json{{"ok", false}, {"diagnostics", json::array()}, {"errors", json::array({error_json("format", "unknown notation format '" + format_name + "'")})}});
    }
    sw::notation::ParseOutcome parsed = sw::notation::parse_notation(text, format);
    return text_of(json{{"ok", parsed.ok() && !parsed.signs.empty()},
                {"format", sw::notation::format_name(format)},
                {"signs", parsed.signs.size()},
                {"diagnostics", diagnostics_json(parsed.diagnostics)}});
  }

  // One sign in any notation -> the current clip (from rest back to rest).
  std::string setNotation(const std::string& text, const std::string& format_name, const std::string& options_json) {
    json out{{"ok", false}, {"diagnostics", json::array()}, {"errors", json::array()}};
    sw::synthesis::SynthesisOptions options;
    std::string error;
    if (!avatar_) return fail(out, "avatar", "no avatar is loaded");
    std::string label;
    if (!read_options(options_json, &options, &error, &label)) return fail(out, "options", error);
    sw::notation::NotationFormat format{};
    if (!read_format(format_name, text, &format)) return fail(out, "format", "unknown notation format '" + format_name + "'");
    sw::notation::ParseOutcome parsed = sw::notation::parse_notation(text, format);
    out["diagnostics"] = diagnostics_json(parsed.diagnostics);
    out["format"] = sw::notation::format_name(format);
    if (!parsed.ok()) return text_of(out);
    if (parsed.signs.empty()) return fail(out, "notation", "the text holds no sign");
    sw::notation::SignSpec& sign = parsed.signs.front();
    if (sign.gloss.empty()) sign.gloss = label;
    return adopt(synthesizer_->sign(sign, options), out);
  }

  // A phrase: {"items": [{"kind": "sign"|"letter"|"pause", "notation", "format", "label",
  // "word_index"}]} -> one clip with transitions, pauses and a caption segment per item.
  std::string setPhrase(const std::string& items_json, const std::string& options_json) {
    json out{{"ok", false}, {"diagnostics", json::array()}, {"errors", json::array()}};
    sw::synthesis::SynthesisOptions options;
    std::string error;
    if (!avatar_) return fail(out, "avatar", "no avatar is loaded");
    if (!read_options(options_json, &options, &error)) return fail(out, "options", error);
    json doc = json::parse(items_json, nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded() || !doc.is_object() || !doc.contains("items") || !doc["items"].is_array()) {
      return fail(out, "phrase", "the phrase must be a JSON object with an array 'items'");
    }
    std::vector<sw::synthesis::PhraseItem> items;
    const json& list = doc["items"];
    for (std::size_t i = 0; i < list.size(); ++i) {
      const json& entry = list[i];
      const std::string where = "item " + std::to_string(i + 1);
      if (!entry.is_object()) return fail(out, where, "each item must be an object");
      sw::synthesis::PhraseItem item;
      if (entry.contains("kind") && !entry["kind"].is_string()) return fail(out, where, "kind must be a string");
      const std::string kind = entry.contains("kind") ? entry["kind"].get<std::string>() : "sign";
      item.label = entry.contains("label") && entry["label"].is_string() ? entry["label"].get<std::string>() : "";
      item.word_index = entry.contains("word_index") && entry["word_index"].is_number_integer() ? entry["word_index"].get<int>() : -1;
      if (kind == "pause") {
        item.kind = sw::synthesis::PhraseItem::Kind::Pause;
        items.push_back(std::move(item));
        continue;
      }
      if (kind != "sign" && kind != "letter") return fail(out, where, "kind must be sign, letter or pause, not '" + kind + "'");
      item.kind = kind == "letter" ? sw::synthesis::PhraseItem::Kind::Letter : sw::synthesis::PhraseItem::Kind::Sign;
      if (!entry.contains("notation") || !entry["notation"].is_string()) return fail(out, where, "a sign item needs its notation text");
      const std::string text = entry["notation"].get<std::string>();
      const std::string format_name = entry.contains("format") && entry["format"].is_string() ? entry["format"].get<std::string>() : "";
      sw::notation::NotationFormat format{};
      if (!read_format(format_name, text, &format)) return fail(out, where, "unknown notation format '" + format_name + "'");
      sw::notation::ParseOutcome parsed = sw::notation::parse_notation(text, format);
      if (!parsed.ok() || parsed.signs.empty()) {
        const std::string why = parsed.diagnostics.empty() ? std::string("no sign in its notation")
                                                           : sw::notation::format_diagnostic(parsed.diagnostics.front());
        return fail(out, where + (item.label.empty() ? "" : " '" + item.label + "'"), why);
      }
      item.sign = std::move(parsed.signs.front());
      items.push_back(std::move(item));
    }
    return adopt(synthesizer_->phrase(items, options), out);
  }

  // The HamNoSys name of one code point ("hamflathand"), "" when it is none: the sign page shows
  // symbol names beside the glyphs, which need a HamNoSys font to be readable.
  std::string hamSymbolName(unsigned code) const { return sw::notation::ham_symbol_name(char32_t(code)); }

  // The current clip as BVH text ("" when there is no clip or it cannot be written).
  std::string exportBvh() const {
    if (!clip_) return "";
    const sw::synthesis::ExportResult bvh = sw::synthesis::export_bvh(*clip_, *avatar_);
    return bvh.ok() ? std::string(bvh.bytes.begin(), bvh.bytes.end()) : "";
  }

  // The current clip as glTF binary: a view into module memory, valid until the next export.
  val exportGlb() {
    glb_.clear();
    if (clip_) {
      sw::synthesis::ExportResult glb = sw::synthesis::export_glb(*clip_, *avatar_);
      if (glb.ok()) glb_ = std::move(glb.bytes);
    }
    return view_of(glb_);
  }

  // Pose at t (the rest pose without a clip), FK, skinning; joint positions for the debug overlay.
  void update(double time_s) {
    if (!instance_) return;
    bool posed = false;
    if (clip_) {
      posed = sw::synthesis::sample_clip_local(*clip_, avatar_->skeleton, time_s, instance_->locals().data());
      if (posed && !clip_morphs_.empty()) {
        sw::synthesis::sample_clip(*clip_, time_s, nullptr, nullptr, clip_morphs_.data());
        for (std::size_t m = 0; m < clip_morphs_.size(); ++m) {
          if (clip_to_morph_[m] >= 0) instance_->morph_weights()[std::size_t(clip_to_morph_[m])] = clip_morphs_[m];
        }
      }
    }
    if (!posed) instance_->reset_pose();
    instance_->update(path_);
    const auto& models = instance_->model_matrices();
    for (std::size_t j = 0; j < models.size(); ++j) {
      for (int k = 0; k < 3; ++k) joint_positions_[3 * j + std::size_t(k)] = models[j][3][k];
    }
  }

 private:
  static std::string fail(json& out, const std::string& where, const std::string& message) {
    out["ok"] = false;
    out["errors"].push_back(error_json(where, message));
    return text_of(out);
  }

  // A synthesised clip becomes the current one; on failure the previous clip keeps playing.
  std::string adopt(sw::synthesis::SynthesisResult result, json& out) {
    for (const auto& e : result.errors) out["errors"].push_back(error_json(e.where, e.message));
    if (!result.ok()) {
      out["ok"] = false;
      return text_of(out);
    }
    clip_ = std::make_unique<sw::synthesis::Clip>(std::move(result.clip));
    clip_to_morph_.assign(std::size_t(clip_->morph_count()), -1);
    clip_morphs_.assign(std::size_t(clip_->morph_count()), 0.0f);
    for (std::size_t m = 0; m < clip_to_morph_.size(); ++m) {
      for (std::size_t a = 0; a < avatar_->morphs.size(); ++a) {
        if (avatar_->morphs[a].name == clip_->morph_names[m]) clip_to_morph_[m] = int(a);
      }
    }
    instance_->reset_pose();
    std::fill(instance_->morph_weights().begin(), instance_->morph_weights().end(), 0.0f);
    json segments = json::array();
    for (const auto& s : clip_->segments) {
      segments.push_back({{"kind", segment_kind_name(s.kind)}, {"label", s.label}, {"word_index", s.word_index},
                          {"start_s", s.start_s}, {"end_s", s.end_s}});
    }
    out["ok"] = true;
    out["duration_s"] = clip_->duration_s();
    out["frame_count"] = clip_->frame_count;
    out["fps"] = clip_->fps;
    out["segments"] = segments;
    out["warnings"] = result.report.warnings;
    return text_of(out);
  }

  std::unique_ptr<sw::avatar::Avatar> avatar_;
  std::unique_ptr<sw::skinning::AvatarInstance> instance_;
  std::vector<float> joint_positions_;
  std::unique_ptr<sw::synthesis::Clip> clip_;
  std::vector<int> clip_to_morph_;   // clip morph channel -> avatar morph index, -1 if none
  std::vector<float> clip_morphs_;   // one sample of the clip's morph channels
  std::unique_ptr<sw::synthesis::Synthesizer> synthesizer_;
  std::vector<std::uint8_t> glb_;
  sw::skinning::SkinningPath path_ = sw::skinning::SkinningPath::Scalar;
};

}  // namespace

EMSCRIPTEN_BINDINGS(player_api) {
  emscripten::class_<Player>("Player")
      .constructor<>()
      .function("loadAvatar", &Player::loadAvatar)
      .function("avatarInfoJson", &Player::avatarInfoJson)
      .function("indices", &Player::indices)
      .function("positions", &Player::positions)
      .function("normals", &Player::normals)
      .function("jointPositions", &Player::jointPositions)
      .function("anchorPositions", &Player::anchorPositions)
      .function("parse", &Player::parse)
      .function("setNotation", &Player::setNotation)
      .function("setPhrase", &Player::setPhrase)
      .function("hamSymbolName", &Player::hamSymbolName)
      .function("exportBvh", &Player::exportBvh)
      .function("exportGlb", &Player::exportGlb)
      .function("update", &Player::update);
}

// Shared helpers for the synthesis tests: the reference humanoid, a variant with different joint
// axes and size (synthesis must work on ANY humanoid), sign builders and pose measurements.
#pragma once

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "notation/diagnostic.h"
#include "notation/hamnosys.h"

#include "notation/sign_spec.h"
#include "synthesis/handshape.h"
#include "synthesis/phrase_text.h"
#include "synthesis/reference_humanoid.h"
#include "synthesis/rig.h"
#include "synthesis/signing_avatar.h"
#include "synthesis/synthesize.h"

namespace sw::synthesis::testing {

// Reads a whole file (the data/ files the lexicon and alphabet tests walk); false if unreadable.
inline bool read_text_file(const std::string& path, std::string* out) {
  std::ifstream in(path);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  *out = ss.str();
  return true;
}

// One sign of a data/<language>/lexicon.jsonl file, its notation read into phrase items.
struct LexiconSign {
  std::string gloss;
  PhraseText text;
};
// The signs of a lexicon file's text, one JSON object per non-empty line.
inline std::vector<LexiconSign> lexicon_signs(const std::string& jsonl) {
  std::vector<LexiconSign> signs;
  std::istringstream lines(jsonl);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    const nlohmann::json entry = nlohmann::json::parse(line);
    signs.push_back({entry.at("gloss").get<std::string>(),
                     phrase_from_text(entry.at("notation").get<std::string>(), {})});
  }
  return signs;
}

// The reference avatar re-rigged: same bind positions scaled by `scale`, but every joint gets a
// different, non-identity rest rotation (as arbitrary glTF rigs have).
inline avatar::Avatar make_rotated_variant(float scale) {
  avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  build_rig(av, &rig, &error);
  const int n = rig.joint_count;
  std::vector<glm::quat> model(n);
  for (int j = 0; j < n; ++j) {
    float a = 0.37f * static_cast<float>(j % 7) - 1.1f;
    glm::vec3 axis = glm::normalize(glm::vec3(std::sin(1.3f * j), std::cos(0.7f * j), 0.5f));
    model[j] = axis_angle(axis, a);
  }
  for (int j = 0; j < n; ++j) {
    auto& joint = av.skeleton.joints[j];
    int p = joint.parent;
    glm::vec3 pos = rig.bind_pos[j] * scale;
    if (p < 0) {
      joint.rest.translation = pos;
      joint.rest.rotation = model[j];
    } else {
      glm::vec3 ppos = rig.bind_pos[p] * scale;
      joint.rest.translation = glm::conjugate(model[p]) * (pos - ppos);
      joint.rest.rotation = glm::conjugate(model[p]) * model[j];
    }
  }
  // Anchors: same model-space points, scaled; offsets are in the joint's bind space.
  for (auto& a : av.anchors) {
    a.offset = glm::conjugate(model[a.joint]) * (a.offset * scale);
    a.normal = glm::conjugate(model[a.joint]) * a.normal;
  }
  return av;
}

inline notation::HandShape shape_all(int finger_id, int thumb_id, bool has_t = false, float t = 1.0f,
                                     float spread = 0.0f) {
  notation::HandShape s;
  s.fingers[0] = notation::FingerConfig{thumb_id, has_t, t, 0.0f};
  for (int k = 1; k < 5; ++k) s.fingers[k] = notation::FingerConfig{finger_id, has_t, t, spread};
  return s;
}

inline notation::HandShape fist() { return shape_all(0, 0, true, 0.0f); }
inline notation::HandShape flat() { return shape_all(0, notation::kThumbAlongside, true, 1.0f); }
inline notation::HandShape index_point() {
  notation::HandShape s = fist();
  s.fingers[1] = notation::FingerConfig{0, true, 1.0f, 0.0f};
  return s;
}

inline notation::SignSpec sign_at(const notation::HandShape& shape, notation::BodyLevel level,
                                  notation::Side side, notation::Contact contact) {
  notation::SignSpec s;
  s.gloss = "test";
  s.dominant.shape = shape;
  s.dominant.location.kind = level == notation::BodyLevel::NeutralSpace
                                 ? notation::Location::Kind::NeutralSpace
                                 : notation::Location::Kind::Body;
  s.dominant.location.level = level;
  s.dominant.location.side = side;
  s.dominant.location.contact = contact;
  return s;
}

// Pose of a frame of a clip.
inline PoseBuilder frame_pose(const Rig& rig, const Clip& clip, int frame) {
  PoseBuilder pb(rig);
  pb.set_from_local(&clip.rotations[static_cast<size_t>(frame) * clip.joint_count()]);
  return pb;
}

// First frame of the first Sign/Letter segment.
inline int first_sign_frame(const Clip& clip) {
  for (const auto& s : clip.segments)
    if (s.kind == ClipSegment::Kind::Sign || s.kind == ClipSegment::Kind::Letter)
      return static_cast<int>(std::lround(s.start_s * clip.fps));
  return 0;
}

// Last frame of the last Sign/Letter segment (within the clip), or 0 with none.
inline int last_sign_frame(const Clip& clip) {
  int last = 0;
  for (const auto& s : clip.segments)
    if (s.kind == ClipSegment::Kind::Sign || s.kind == ClipSegment::Kind::Letter)
      last = static_cast<int>(std::lround(s.end_s * clip.fps));
  return std::min(last, clip.frame_count - 1);
}

inline float deg(float rad) { return rad * 57.2957795f; }
// The angle between two unit directions (a requested and a posed palm normal or finger
// direction), in degrees.
inline float angle_deg(const glm::vec3& a, const glm::vec3& b) {
  return deg(std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f)));
}

// The project's avatar (models/signweave-avatar.glb) for tests that run on it beside the
// procedural rigs. A checkout without the model: not present, no error; a model the loader
// refuses: present, with its message (the test should fail on it).
struct ProjectAvatar {
  bool present = false;
  avatar::Avatar avatar;
  std::string error;
};
inline ProjectAvatar load_project_avatar() {
  ProjectAvatar p;
  const std::string path = std::string(SIGNWEAVE_SOURCE_DIR) + "/models/signweave-avatar.glb";
  if (!std::ifstream(path).good()) return p;
  p.present = true;
  SigningAvatar sa = load_signing_avatar_file(path);
  if (sa.ok()) p.avatar = std::move(sa.avatar);
  else p.error = sa.error;
  return p;
}

// The rigs the lexicon-wide tests run on, by name: the reference humanoid and, where the checkout
// has it, the project avatar. `error` is load_project_avatar's (a model the loader refuses).
using NamedRigs = std::vector<std::pair<std::string, avatar::Avatar>>;
inline NamedRigs reference_and_project_avatar(std::string* error) {
  NamedRigs rigs;
  rigs.push_back({"reference", make_reference_humanoid()});
  ProjectAvatar project = load_project_avatar();
  *error = project.error;
  if (project.present && project.error.empty()) rigs.push_back({"avatar", std::move(project.avatar)});
  return rigs;
}

// The one sign of a HamNoSys text (comma-separated symbol names, as the corpus writes them) into
// `*out`. Fails, with the reader's diagnostics (line, column, symbol), when the text is not
// exactly one sign read without error: `ASSERT_TRUE(read_one_hamnosys("hamfist,...", &s));`.
inline ::testing::AssertionResult read_one_hamnosys(std::string_view names,
                                                    notation::SignSpec* out) {
  const std::vector<notation::SignParse> read = notation::parse_hamnosys_text(names);
  if (read.size() != 1u)
    return ::testing::AssertionFailure()
           << read.size() << " signs read, not one, from \"" << names << '"';
  if (!read[0].ok()) {
    ::testing::AssertionResult failure = ::testing::AssertionFailure();
    failure << "\"" << names << "\" is not read:";
    for (const notation::Diagnostic& d : read[0].diagnostics)
      failure << ' ' << notation::format_diagnostic(d) << ';';
    return failure;
  }
  *out = *read[0].spec;
  return ::testing::AssertionSuccess();
}

}  // namespace sw::synthesis::testing

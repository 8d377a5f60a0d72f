// synthesis_probe: the developer's yardstick for synthesis changes, kept in the tree so that every
// "exact" and every instruction count in docs/SYNTHESIS.md can be reproduced by the next reader.
//
//   signweave-probe prof [--passes N] [--left] [--reference] [--only GLOSS]
//       synthesise every ASL starter-lexicon sign once from rest and back (one Synthesizer, the
//       default options: what a dictionary look-up pays), N times over. Run it under
//       `valgrind --tool=callgrind` and read `Synthesizer::phrase`'s inclusive count: instructions
//       are repeatable on a shared machine, wall times are not.
//   signweave-probe hash
//       one line per clip, "<rig> <hand> <timing> <gloss> <64-bit FNV-1a>", over the lexicon on
//       both rigs (project avatar, reference humanoid), both handednesses and three timings
//       (default; 60 fps at speed 1.25; 25 fps at speed 0.8): 1,692 clips. The hash covers every
//       bit of the clip (frame count, rotations, root translation, morph weights, segment times),
//       so two builds whose outputs `cmp` equal produce the same clips bit for bit.
//
// It reads data/ase/lexicon.jsonl and models/signweave-avatar.glb from the source tree it was
// built from. Not a test (it asserts nothing) and not a benchmark (it times nothing).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "synthesis/phrase_text.h"
#include "synthesis/reference_humanoid.h"
#include "synthesis/signing_avatar.h"
#include "synthesis/synthesize.h"

namespace {

using namespace sw::synthesis;

struct LexiconSign {
  std::string gloss;
  std::vector<PhraseItem> items;
};

std::vector<LexiconSign> read_lexicon() {
  std::vector<LexiconSign> signs;
  std::ifstream in(std::string(SIGNWEAVE_SOURCE_DIR) + "/data/ase/lexicon.jsonl");
  std::string line;
  while (std::getline(in, line)) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object() || !j.contains("notation")) continue;
    PhraseText t = phrase_from_text(j.value("notation", ""), {});
    if (!t.ok()) {
      std::fprintf(stderr, "signweave-probe: %s does not parse\n", j.value("gloss", "").c_str());
      continue;
    }
    signs.push_back({j.value("gloss", ""), t.items});
  }
  return signs;
}

// FNV-1a over raw bytes: the clip's bits, not its values (a -0.0 against 0.0 counts).
struct Fnv1a {
  std::uint64_t h = 1469598103934665603ull;
  void add(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
  template <typename T>
  void add_vector(const std::vector<T>& v) {
    const std::uint64_t n = v.size();
    add(&n, sizeof n);
    if (!v.empty()) add(v.data(), v.size() * sizeof(T));
  }
};

std::uint64_t clip_hash(const SynthesisResult& r) {
  Fnv1a f;
  const std::uint8_t ok = r.ok() ? 1 : 0;
  f.add(&ok, 1);
  f.add(&r.clip.fps, sizeof r.clip.fps);
  f.add(&r.clip.frame_count, sizeof r.clip.frame_count);
  f.add_vector(r.clip.rotations);
  f.add_vector(r.clip.root_translation);
  f.add_vector(r.clip.morph_weights);
  for (const ClipSegment& s : r.clip.segments) {
    f.add(&s.start_s, sizeof s.start_s);
    f.add(&s.end_s, sizeof s.end_s);
  }
  return f.h;
}

sw::avatar::Avatar project_avatar() {
  SigningAvatar a =
      load_signing_avatar_file(std::string(SIGNWEAVE_SOURCE_DIR) + "/models/signweave-avatar.glb");
  if (!a.ok()) {
    std::fprintf(stderr, "signweave-probe: the project avatar does not load: %s\n",
                 a.error.c_str());
    std::exit(1);
  }
  return std::move(a.avatar);
}

int prof(int argc, char** argv) {
  int passes = 1;
  bool left = false, reference = false;
  std::string only;
  for (int i = 2; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--passes") && i + 1 < argc)
      passes = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--left"))
      left = true;
    else if (!std::strcmp(argv[i], "--reference"))
      reference = true;
    else if (!std::strcmp(argv[i], "--only") && i + 1 < argc)
      only = argv[++i];
    else {
      std::fprintf(stderr, "signweave-probe prof: unknown argument '%s'\n", argv[i]);
      return 2;
    }
  }
  const std::vector<LexiconSign> signs = read_lexicon();
  const sw::avatar::Avatar avatar = reference ? make_reference_humanoid() : project_avatar();
  Synthesizer synth(avatar);
  if (!synth.ok()) {
    std::fprintf(stderr, "signweave-probe: %s\n", synth.error().c_str());
    return 1;
  }
  SynthesisOptions options;
  options.left_handed = left;
  int frames = 0, failed = 0;
  for (int p = 0; p < passes; ++p) {
    for (const LexiconSign& s : signs) {
      if (!only.empty() && s.gloss != only) continue;
      const SynthesisResult r = synth.phrase(s.items, options);
      frames += r.clip.frame_count;
      failed += r.ok() ? 0 : 1;
    }
  }
  std::printf("%zu signs, %d passes, %d frames, %d failed\n", signs.size(), passes, frames, failed);
  return failed ? 1 : 0;
}

int hash() {
  const std::vector<LexiconSign> signs = read_lexicon();
  struct Rig {
    const char* name;
    sw::avatar::Avatar avatar;
  };
  std::vector<Rig> rigs;
  rigs.push_back({"avatar", project_avatar()});
  rigs.push_back({"reference", make_reference_humanoid()});
  struct Timing {
    const char* name;
    float fps, speed;
  };
  const Timing timings[] = {
      {"default", 30.0f, 1.0f}, {"60fps-x1.25", 60.0f, 1.25f}, {"25fps-x0.8", 25.0f, 0.8f}};
  for (const Rig& rig : rigs) {
    Synthesizer synth(rig.avatar);
    if (!synth.ok()) {
      std::fprintf(stderr, "signweave-probe: %s: %s\n", rig.name, synth.error().c_str());
      return 1;
    }
    for (int left = 0; left < 2; ++left) {
      for (const Timing& t : timings) {
        SynthesisOptions options;
        options.left_handed = left != 0;
        options.fps = t.fps;
        options.speed = t.speed;
        for (const LexiconSign& s : signs) {
          const SynthesisResult r = synth.phrase(s.items, options);
          std::printf("%s %s %s %s %016llx\n", rig.name, left ? "left" : "right", t.name,
                      s.gloss.c_str(), static_cast<unsigned long long>(clip_hash(r)));
        }
      }
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "prof") return prof(argc, argv);
  if (mode == "hash") return hash();
  std::fprintf(stderr,
               "usage: signweave-probe prof [--passes N] [--left] [--reference] [--only GLOSS]\n"
               "       signweave-probe hash\n");
  return 2;
}

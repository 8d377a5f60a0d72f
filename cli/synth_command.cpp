// `signweave synth TEXT --out F.bvh|F.glb`: notation (any format) or a typed phrase (fingerspelled
// with data/<lang>/alphabet.jsonl) -> a clip on the project's avatar -> a BVH or GLB file.
//
//   synth TEXT --out F.bvh|F.glb [--lang ase|ukl] [--avatar F.glb] [--speed X] [--left-handed]
//
// Prints where it wrote and what synthesis measured; exit 0 on success, 1 bad input, 2 usage.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "command.h"
#include "synthesis/clip_export.h"
#include "synthesis/phrase_text.h"
#include "synthesis/signing_avatar.h"
#include "synthesis/synthesize.h"

namespace sw::cli {
namespace {

// The project root: $SIGNWEAVE_ROOT, else two levels above the binary (build/native/), else cwd.
std::string project_root() {
  if (const char* env = std::getenv("SIGNWEAVE_ROOT")) return env;
  char buf[4096];
  ssize_t n = readlink("/proc/self/exe", buf, sizeof(buf) - 1);
  if (n > 0) {
    std::string exe(buf, static_cast<size_t>(n));
    for (int up = 0; up < 3; ++up) {
      size_t slash = exe.rfind('/');
      if (slash == std::string::npos) break;
      exe = exe.substr(0, slash);
      if (std::ifstream(exe + "/models/signweave-avatar.glb").good()) return exe;
    }
  }
  return ".";
}

bool read_file(const std::string& path, std::string* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  *out = ss.str();
  return true;
}

bool has_cyrillic(const std::string& s) {
  for (unsigned char c : s)
    if (c == 0xD0 || c == 0xD1 || c == 0xD2) return true;  // UTF-8 lead bytes of U+0400..U+04FF
  return false;
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

int synth(const std::vector<std::string>& args) {
  std::string text, out, lang, avatar_path;
  synthesis::SynthesisOptions options;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string* v) {
      if (i + 1 >= args.size()) return false;
      *v = args[++i];
      return true;
    };
    std::string v;
    if (a == "--out") {
      if (!value(&out)) return 2;
    } else if (a == "--lang") {
      if (!value(&lang)) return 2;
    } else if (a == "--avatar") {
      if (!value(&avatar_path)) return 2;
    } else if (a == "--speed") {
      if (!value(&v)) return 2;
      options.speed = std::strtof(v.c_str(), nullptr);
    } else if (a == "--left-handed") {
      options.left_handed = true;
    } else if (text.empty()) {
      text = a;
    } else {
      text += " " + a;
    }
  }
  if (text.empty() || out.empty() || !(ends_with(out, ".bvh") || ends_with(out, ".glb"))) {
    std::fprintf(stderr, "usage: synth TEXT --out F.bvh|F.glb [--lang ase|ukl] [--avatar F.glb] [--speed X] [--left-handed]\n");
    return 2;
  }
  const std::string root = project_root();
  if (avatar_path.empty()) avatar_path = root + "/models/signweave-avatar.glb";
  synthesis::SigningAvatar avatar = synthesis::load_signing_avatar_file(avatar_path);
  if (!avatar.ok()) {
    std::fprintf(stderr, "error: %s: %s\n", avatar_path.c_str(), avatar.error.c_str());
    return 1;
  }
  if (lang.empty()) lang = has_cyrillic(text) ? "ukl" : "ase";
  std::vector<synthesis::AlphabetEntry> alphabet;
  for (const char* file : {"alphabet.jsonl", "digits.jsonl"}) {
    std::string jsonl, error;
    std::string path = root + "/data/" + lang + "/" + file;
    if (!read_file(path, &jsonl)) continue;
    if (!synthesis::parse_alphabet_jsonl(jsonl, &alphabet, &error))
      std::fprintf(stderr, "warning: %s: %s\n", path.c_str(), error.c_str());
  }
  synthesis::PhraseText phrase = synthesis::phrase_from_text(text, alphabet);
  for (const auto& e : phrase.errors) std::fprintf(stderr, "error: %s: %s\n", e.where.c_str(), e.message.c_str());
  if (!phrase.ok()) return 1;
  synthesis::SynthesisResult result = synthesis::synthesize_phrase(phrase.items, avatar.avatar, options);
  for (const auto& e : result.errors) std::fprintf(stderr, "error: %s: %s\n", e.where.c_str(), e.message.c_str());
  if (!result.ok()) return 1;
  synthesis::ExportResult file = ends_with(out, ".bvh") ? synthesis::export_bvh(result.clip, avatar.avatar)
                                                        : synthesis::export_glb(result.clip, avatar.avatar);
  if (!file.ok()) {
    std::fprintf(stderr, "error: export: %s\n", file.error.c_str());
    return 1;
  }
  std::ofstream f(out, std::ios::binary);
  f.write(reinterpret_cast<const char*>(file.bytes.data()), static_cast<std::streamsize>(file.bytes.size()));
  if (!f) {
    std::fprintf(stderr, "error: cannot write %s\n", out.c_str());
    return 1;
  }
  for (const auto& w : result.report.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  std::printf("wrote %s: %d frames, %.2f s, %zu items (%s), max penetration %.1f mm, %d via-points\n",
              out.c_str(), result.clip.frame_count, result.clip.duration_s(), phrase.items.size(),
              phrase.fingerspelled ? ("fingerspelled, " + lang).c_str() : "notation",
              result.report.max_penetration_m * 1000.0, result.report.via_points_inserted);
  return 0;
}

}  // namespace

SW_CLI_COMMAND("synth", "synth TEXT --out F.bvh|F.glb [--lang ase|ukl] [--avatar F.glb] [--speed X] [--left-handed]", synth);

}  // namespace sw::cli

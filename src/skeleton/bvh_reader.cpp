// BVH reader: text -> Bvh, or the first problem with its line number (bvh.h for the format and the
// limits). A hand-written recursive-descent parser over whitespace-separated tokens for HIERARCHY,
// then strictly one frame per line for MOTION, so that a short or long frame is reported on its
// own line.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

#include "skeleton/bvh.h"

namespace sw::skeleton {
namespace {

struct Token {
  std::string_view text;
  int line = 0;
};

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  // Skips whitespace and returns the next token without consuming it; nullopt at the end.
  std::optional<Token> peek() {
    skip_space();
    if (pos_ >= text_.size()) return std::nullopt;
    std::size_t end = pos_;
    while (end < text_.size() && !is_space(text_[end])) ++end;
    return Token{text_.substr(pos_, end - pos_), line_};
  }
  std::optional<Token> next() {
    std::optional<Token> t = peek();
    if (t) pos_ += t->text.size();
    return t;
  }
  // Moves past the end of the current line; false (and stays) if it holds more than whitespace.
  bool finish_line(Token& stray) {
    while (pos_ < text_.size() && text_[pos_] != '\n') {
      if (!is_space(text_[pos_])) {
        std::size_t end = pos_;
        while (end < text_.size() && !is_space(text_[end])) ++end;
        stray = Token{text_.substr(pos_, end - pos_), line_};
        return false;
      }
      ++pos_;
    }
    if (pos_ < text_.size()) {
      ++pos_;
      ++line_;
    }
    return true;
  }
  // The next raw line (without its newline) and its number; false at the end of the text.
  bool next_line(std::string_view& out, int& line) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    out = text_.substr(pos_, end - pos_);
    line = line_;
    pos_ = end < text_.size() ? end + 1 : end;
    if (end < text_.size()) ++line_;
    return true;
  }
  int line() const { return line_; }

 private:
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

std::string quoted(std::string_view s) {
  // Long garbage tokens would make unreadable messages; 40 bytes identify any real keyword.
  // Control and non-ASCII bytes are shown as \xNN so that a message is always printable text.
  constexpr std::size_t kShown = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < s.size() && i < kShown; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static const char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (s.size() > kShown) out += "...";
  return out + "'";
}

std::optional<BvhChannel> parse_channel(std::string_view s) {
  static constexpr BvhChannel kAll[] = {BvhChannel::Xposition, BvhChannel::Yposition,
                                        BvhChannel::Zposition, BvhChannel::Xrotation,
                                        BvhChannel::Yrotation, BvhChannel::Zrotation};
  for (BvhChannel c : kAll) {
    const std::string_view name = bvh_channel_name(c);
    if (name.size() != s.size()) continue;
    bool same = true;
    for (std::size_t i = 0; i < s.size() && same; ++i) {
      same = std::tolower(static_cast<unsigned char>(s[i])) ==
             std::tolower(static_cast<unsigned char>(name[i]));
    }
    if (same) return c;
  }
  return std::nullopt;
}

class Parser {
 public:
  explicit Parser(std::string_view text) : lex_(text) {}

  BvhReadResult parse() {
    BvhReadResult result;
    if (!parse_hierarchy() || !parse_motion()) {
      result.error = error_;
      return result;
    }
    result.bvh = std::move(bvh_);
    result.ok = true;
    return result;
  }

 private:
  bool fail(int line, std::string message) {
    error_ = BvhError{line, std::move(message)};
    return false;
  }
  bool fail_at_end(const std::string& expected) {
    return fail(lex_.line(), "unexpected end of file: expected " + expected);
  }

  // A finite number within the magnitude limit, or a failure naming what it was for.
  bool number(const Token& t, const char* what, double& out) {
    const std::string s(t.text);
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0') {
      return fail(t.line,
                  std::string("expected a number for ") + what + ", found " + quoted(t.text));
    }
    if (!std::isfinite(v) || (errno == ERANGE && std::fabs(v) > 1.0)) {
      return fail(t.line,
                  std::string("the ") + what + " " + quoted(t.text) + " is not a finite number");
    }
    if (std::fabs(v) > Bvh::kMaxMagnitude) {
      return fail(t.line, std::string("the ") + what + " " + quoted(t.text) +
                              " is too large (limit 1e6: no capture produces such values)");
    }
    out = v;
    return true;
  }

  bool expect(const char* keyword, const std::string& context, Token* where = nullptr) {
    const std::optional<Token> t = lex_.next();
    if (!t) return fail_at_end(std::string("'") + keyword + "' " + context);
    if (t->text != keyword) {
      return fail(t->line, std::string("expected '") + keyword + "' " + context + ", found " +
                               quoted(t->text));
    }
    if (where) *where = *t;
    return true;
  }

  bool parse_hierarchy() {
    const std::optional<Token> first = lex_.next();
    if (!first) return fail(1, "empty file: a BVH file starts with HIERARCHY");
    if (first->text != "HIERARCHY") {
      return fail(first->line,
                  "expected 'HIERARCHY' at the start of the file, found " + quoted(first->text));
    }
    for (;;) {
      const std::optional<Token> t = lex_.peek();
      if (!t) return fail_at_end("'ROOT' or 'MOTION'");
      if (t->text == "MOTION") break;
      if (t->text != "ROOT") {
        return fail(t->line, "unknown keyword " + quoted(t->text) +
                                 " in HIERARCHY (expected 'ROOT' or 'MOTION')");
      }
      lex_.next();
      if (!parse_joint(-1, *t)) return false;
    }
    if (bvh_.joints.empty()) return fail(lex_.peek()->line, "HIERARCHY has no ROOT joint");
    return true;
  }

  // After ROOT/JOINT: name { OFFSET x y z CHANNELS n ... (JOINT ... | End Site {...})* }
  bool parse_joint(int parent, const Token& keyword) {
    const std::optional<Token> name = lex_.next();
    if (!name) return fail_at_end("a joint name after " + quoted(keyword.text));
    if (name->text == "{")
      return fail(name->line, "missing joint name after " + quoted(keyword.text));
    if (static_cast<int>(bvh_.joints.size()) >= Bvh::kMaxJoints) {
      return fail(name->line, "more than 1024 joints (the limit: real rigs have a few hundred)");
    }
    if (bvh_.find(name->text) >= 0)
      return fail(name->line, "duplicate joint name " + quoted(name->text));
    const int index = static_cast<int>(bvh_.joints.size());
    BvhJoint joint;
    joint.name = std::string(name->text);
    joint.parent = parent;
    bvh_.joints.push_back(joint);
    const std::string in_joint = "in joint " + quoted(name->text);

    Token open;
    if (!expect("{", "after joint name " + quoted(name->text), &open)) return false;
    bool has_offset = false, has_channels = false;
    for (;;) {
      const std::optional<Token> t = lex_.next();
      if (!t) {
        return fail(lex_.line(), "unexpected end of file: missing '}' closing joint " +
                                     quoted(name->text) + " (opened on line " +
                                     std::to_string(open.line) + ")");
      }
      if (t->text == "}") break;
      if (t->text == "OFFSET") {
        if (has_offset) return fail(t->line, "second OFFSET " + in_joint);
        glm::dvec3 offset;
        if (!parse_vec3(offset)) return false;
        bvh_.joints[static_cast<std::size_t>(index)].offset = offset;
        has_offset = true;
      } else if (t->text == "CHANNELS") {
        if (has_channels) return fail(t->line, "second CHANNELS " + in_joint);
        if (!parse_channels(index, *t)) return false;
        has_channels = true;
      } else if (t->text == "JOINT") {
        if (!has_offset || !has_channels) {
          return fail(t->line,
                      "JOINT before the OFFSET and CHANNELS of its parent " + quoted(name->text));
        }
        if (!parse_joint(index, *t)) return false;
      } else if (t->text == "End") {
        if (!parse_end_site(index)) return false;
      } else if (t->text == "ROOT" || t->text == "MOTION") {
        return fail(t->line, "missing '}' closing joint " + quoted(name->text) +
                                 " (opened on line " + std::to_string(open.line) + ") before " +
                                 quoted(t->text));
      } else {
        return fail(t->line, "unknown keyword " + quoted(t->text) + " " + in_joint +
                                 " (expected OFFSET, CHANNELS, JOINT, End Site or '}')");
      }
    }
    if (!has_offset) return fail(lex_.line(), "joint " + quoted(name->text) + " has no OFFSET");
    if (!has_channels) return fail(lex_.line(), "joint " + quoted(name->text) + " has no CHANNELS");
    return true;
  }

  bool parse_vec3(glm::dvec3& out) {
    static const char* kWhat[] = {"OFFSET x", "OFFSET y", "OFFSET z"};
    for (int i = 0; i < 3; ++i) {
      const std::optional<Token> t = lex_.next();
      if (!t) return fail_at_end("three OFFSET values");
      if (!number(*t, kWhat[i], out[i])) return false;
    }
    return true;
  }

  bool parse_channels(int index, const Token& keyword) {
    BvhJoint& joint = bvh_.joints[static_cast<std::size_t>(index)];
    const std::optional<Token> count_token = lex_.next();
    if (!count_token) return fail_at_end("a channel count after CHANNELS");
    const std::string count_text(count_token->text);
    char* end = nullptr;
    const long count = std::strtol(count_text.c_str(), &end, 10);
    if (end == count_text.c_str() || *end != '\0') {
      return fail(count_token->line,
                  "expected a channel count after CHANNELS, found " + quoted(count_token->text));
    }
    if (count != 3 && count != 6) {
      return fail(count_token->line,
                  "joint " + quoted(joint.name) + " declares " + count_text +
                      " channels; a BVH joint has 3 (rotations) or 6 (positions and rotations)");
    }
    int rotations = 0;
    bool seen[6] = {false, false, false, false, false, false};
    for (long i = 0; i < count; ++i) {
      const std::optional<Token> t = lex_.peek();
      if (!t) return fail_at_end(std::to_string(count) + " channel names after CHANNELS");
      const std::optional<BvhChannel> channel = parse_channel(t->text);
      if (!channel) {
        return fail(t->line, "CHANNELS " + count_text + " of joint " + quoted(joint.name) +
                                 " lists " + std::to_string(i) + " channel names, then " +
                                 quoted(t->text) + " (channel names are Xposition ... Zrotation)");
      }
      lex_.next();
      const int c = static_cast<int>(*channel);
      if (seen[c])
        return fail(t->line,
                    "channel " + quoted(t->text) + " listed twice in joint " + quoted(joint.name));
      seen[c] = true;
      if (c >= 3) ++rotations;
      joint.channels.push_back(*channel);
    }
    if (rotations != 3) {
      return fail(keyword.line,
                  "joint " + quoted(joint.name) + " must list all three rotation channels");
    }
    if (const std::optional<Token> extra = lex_.peek();
        extra && extra->line == keyword.line && parse_channel(extra->text)) {
      return fail(extra->line, "joint " + quoted(joint.name) +
                                   " lists more channel names than CHANNELS " + count_text +
                                   " declares");
    }
    return true;
  }

  bool parse_end_site(int parent) {
    BvhJoint& joint = bvh_.joints[static_cast<std::size_t>(parent)];
    const std::string context = "in the End Site of joint " + quoted(joint.name);
    if (!expect("Site", "after 'End'")) return false;
    if (joint.has_end_site)
      return fail(lex_.line(), "second End Site in joint " + quoted(joint.name));
    if (!expect("{", "after 'End Site'")) return false;
    if (!expect("OFFSET", context)) return false;
    glm::dvec3 offset;
    if (!parse_vec3(offset)) return false;
    if (!expect("}", "closing the End Site of joint " + quoted(joint.name))) return false;
    BvhJoint& j = bvh_.joints[static_cast<std::size_t>(parent)];
    j.has_end_site = true;
    j.end_site_offset = offset;
    return true;
  }

  bool parse_motion() {
    if (!expect("MOTION", "after the hierarchy")) return false;
    Token t;
    if (!expect("Frames:", "after MOTION", &t)) return false;
    const std::optional<Token> frames = lex_.next();
    if (!frames) return fail_at_end("the frame count after 'Frames:'");
    const std::string frames_text(frames->text);
    char* end = nullptr;
    errno = 0;
    const long long frame_count = std::strtoll(frames_text.c_str(), &end, 10);
    if (end == frames_text.c_str() || *end != '\0' || errno == ERANGE || frame_count < 0) {
      return fail(frames->line,
                  "expected a non-negative whole number of frames, found " + quoted(frames->text));
    }
    const std::size_t channels = static_cast<std::size_t>(bvh_.channel_count());
    if (static_cast<unsigned long long>(frame_count) > Bvh::kMaxValues / channels) {
      return fail(frames->line, "Frames: " + frames_text + " with " + std::to_string(channels) +
                                    " channels exceeds the limit of 64Mi values (512 MiB)");
    }
    if (!expect("Frame", "after the frame count")) return false;
    if (!expect("Time:", "after 'Frame'")) return false;
    const std::optional<Token> time = lex_.next();
    if (!time) return fail_at_end("the frame time after 'Frame Time:'");
    if (!number(*time, "frame time", bvh_.frame_time_s)) return false;
    if (!(bvh_.frame_time_s > 0.0))
      return fail(time->line, "the frame time must be positive, found " + quoted(time->text));
    Token stray;
    if (!lex_.finish_line(stray)) {
      return fail(stray.line, "unexpected " + quoted(stray.text) + " after the frame time");
    }

    bvh_.frame_count = static_cast<int>(frame_count);
    // Values are appended as frames are read rather than allocated from the declared count, so a
    // forged "Frames:" in a short file costs nothing.
    bvh_.values.reserve(std::min<std::size_t>(static_cast<std::size_t>(frame_count) * channels,
                                              std::size_t{1} << 20));
    std::vector<double> row(channels);
    std::string_view line_text;
    int line = 0;
    long long frame = 0;
    while (lex_.next_line(line_text, line)) {
      std::size_t pos = 0;
      std::size_t found = 0;
      for (;;) {
        while (pos < line_text.size() && is_space(line_text[pos])) ++pos;
        if (pos >= line_text.size()) break;
        std::size_t end_pos = pos;
        while (end_pos < line_text.size() && !is_space(line_text[end_pos])) ++end_pos;
        const Token value{line_text.substr(pos, end_pos - pos), line};
        pos = end_pos;
        if (frame >= frame_count) {
          return fail(line, "more frame lines than 'Frames: " + frames_text + "' declares");
        }
        if (found >= channels) {
          return fail(line, "frame " + std::to_string(frame + 1) + " has more than the " +
                                std::to_string(channels) + " values the CHANNELS declare");
        }
        if (!number(value, "channel value", row[found])) return false;
        ++found;
      }
      if (found == 0) continue;  // blank lines (e.g. a trailing newline) are not frames
      if (found != channels) {
        return fail(line, "frame " + std::to_string(frame + 1) + " has " + std::to_string(found) +
                              " values; the CHANNELS declare " + std::to_string(channels));
      }
      bvh_.values.insert(bvh_.values.end(), row.begin(), row.end());
      ++frame;
    }
    if (frame < frame_count) {
      return fail(line > 0 ? line : lex_.line(), "truncated: 'Frames: " + frames_text +
                                                     "' but the file ends after " +
                                                     std::to_string(frame) + " frames");
    }
    return true;
  }

  Lexer lex_;
  Bvh bvh_;
  BvhError error_;
};

}  // namespace

BvhReadResult read_bvh(std::string_view text) { return Parser(text).parse(); }

}  // namespace sw::skeleton

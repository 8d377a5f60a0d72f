// Synthesis: the public entry point that turns the formal model (SignSpec, seed 004) into motion
// (Clip) on a loaded avatar. The server validates signs with it, the CLI writes files with it, the
// WASM API plays it. Errors are values: nothing here throws or aborts on bad input.
//
// Pipeline (docs/SYNTHESIS.md): handshape by finger FK (+ thumb contact IK) -> target hand frame
// from the orientation -> hand target from the body anchor -> arm IK (two-bone + swivel + clavicle,
// wrist within limits) per frame along minimum-jerk movement paths -> transitions between signs by
// seed eqs (8)-(10) in quaternion space -> collision routing through via-poses -> one Clip.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "avatar/avatar.h"
#include "notation/sign_spec.h"
#include "synthesis/clip.h"

namespace sw::synthesis {

struct SynthesisOptions {
  float fps = 30.0f;              // seed 004 samples every 1/30 s
  float speed = 1.0f;             // global speed factor: 2 = twice as fast (durations / speed)
  bool left_handed = false;       // mirror everything: the dominant hand is the left one
  bool start_from_rest = true;    // a phrase begins and ends in the rest pose (arms down)
  float hold_s = 0.25f;           // hold of a static sign's key pose (a letter)
  float pause_s = 0.45f;          // pause inserted at punctuation
  bool avoid_collisions = true;   // route transitions/movements through via-poses when needed
  // Carry an elbow that the solved frames swing round its circle in one frame (a swivel read in
  // its turned zero) round at a signer's speed instead (elbow_path.h). false: the frames as
  // solved (the tests compare the two).
  bool carry_elbows = true;
  // The face channel (face/face_track.h): an emotion over the whole phrase, the signs' own
  // non-manuals (brows, head, expression), mouthing, and blinks at pauses.
  bool face = true;               // false: no morph tracks, head and eyes as the body leaves them
  std::string emotion = "neutral";  // face/emotion.h names
  float emotion_intensity = 0.0f;   // 0..1
  bool mouthing = true;           // mouth the sign's mouth picture, else the word it stands for
};

struct SynthesisError {
  std::string where;    // "sign 2 'HELLO' dominant location", "avatar", ...
  std::string message;  // what was wrong, in plain English
};

// Measurements the tests, `check` and the server report (what synthesis achieved).
struct SynthesisReport {
  float max_reach_error_m = 0.0f;     // contact key poses: distance contact part -> target
  float max_penetration_m = 0.0f;     // deepest unintended penetration over all frames
  int via_points_inserted = 0;        // collision routing (seed: intermediate states)
  int transition_states = 0;          // sum of k over transitions, seed eq. (10)
  int elbow_frames_carried = 0;       // arm-frames whose elbow elbow_path.h carried round
  std::vector<float> contact_distances_m;  // per hand placed on a body/hand place: part -> anchor
  std::vector<std::uint8_t> intended_contact;  // per frame: sign_motion.h exempt bits
  std::vector<std::string> warnings;  // unreachable targets, clamped joints, ...
};

struct SynthesisResult {
  Clip clip;
  std::vector<SynthesisError> errors;  // empty on success; the clip is then valid
  SynthesisReport report;
  bool ok() const { return errors.empty(); }
};

// One item of a phrase: a sign or a fingerspelled letter, or a pause (punctuation).
struct PhraseItem {
  enum class Kind { Sign, Letter, Pause } kind = Kind::Sign;
  notation::SignSpec sign;   // unused for Pause
  std::string label;         // caption: gloss, letter or word
  int word_index = -1;       // which word of the typed phrase it belongs to
};

struct SynthContext;

// A synthesizer bound to one avatar: measures the rig, the capsule body and the rest pose once
// (the expensive part: a pass over the mesh), then synthesises any number of signs and phrases.
// The avatar must outlive it. Check ok() / error() after construction.
class Synthesizer {
 public:
  Synthesizer(const avatar::Avatar& avatar, const SynthesisOptions& options = {});
  ~Synthesizer();
  Synthesizer(const Synthesizer&) = delete;
  Synthesizer& operator=(const Synthesizer&) = delete;
  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  // Per-call options (speed, handedness, fps...) on the cached avatar measurements.
  SynthesisResult phrase(const std::vector<PhraseItem>& items, const SynthesisOptions& options) const;
  SynthesisResult sign(const notation::SignSpec& sign, const SynthesisOptions& options) const;

 private:
  SynthContext* ctx_ = nullptr;
  std::string error_;
};

// One sign, from the rest pose (when options.start_from_rest) back to rest.
SynthesisResult synthesize_sign(const notation::SignSpec& sign, const avatar::Avatar& avatar,
                                const SynthesisOptions& options = {});

// A sequence of signs, letters and pauses -> one clip with transitions (seed eqs 8-10), holds,
// pauses and one ClipSegment per item (captions).
SynthesisResult synthesize_phrase(const std::vector<PhraseItem>& items, const avatar::Avatar& avatar,
                                  const SynthesisOptions& options = {});

}  // namespace sw::synthesis

// Face tracks: the non-manual channel of a clip — emotion, grammatical brows, mouthing, blinks,
// head gestures and gaze — written into a synthesised Clip (morph weights + head/eye rotations).
//
// Layers, in the order seed 002 applies them: the emotion (sustained, relaxed towards its target by
// seed 003's spring iteration so the intermediate states show), then the performance (brows,
// mouthing from the signs' NonManual, damped where the emotion already pushes), blinks on top, then
// head gestures on the head joint and eyes counter-rotated to keep eye contact.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "notation/sign_spec.h"
#include "skeleton/skeleton.h"
#include "synthesis/clip.h"

namespace sw::face {

struct FaceCue {  // one per sign (or pause) of the timeline
  double start_s = 0.0;
  double end_s = 0.0;
  notation::NonManual nonmanual;
  bool is_pause = false;  // a prosodic boundary: signers blink here
};

struct FaceOptions {
  std::string emotion = "neutral";  // face/emotion.h names
  float intensity = 0.0f;           // 0..1
  bool mouthing = true;
  bool blinks = true;
  std::uint32_t seed = 1;         // blink rhythm
  float response_time_s = 0.25f;  // how fast the emotion layer follows a change
};

// The joints the face layer moves; -1 where the avatar has none (then that part is skipped).
struct FaceRig {
  int head = -1;
  int left_eye = -1;
  int right_eye = -1;
};
// Finds head / leftEye / rightEye by their canonical names.
FaceRig face_rig_by_names(const skeleton::Skeleton& skeleton);

// Fills clip.morph_names with every face channel (channels.h order) and clip.morph_weights per
// frame; layers head gestures and gaze onto the clip's head and eye rotations. The clip's
// joint channels must be the skeleton's joints in order. Returns false (clip untouched) when the
// clip and skeleton disagree.
bool add_face_tracks(synthesis::Clip& clip, const skeleton::Skeleton& skeleton, const FaceRig& rig,
                     const std::vector<FaceCue>& cues, const FaceOptions& options);

}  // namespace sw::face

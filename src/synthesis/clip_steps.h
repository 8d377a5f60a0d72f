// How far the arms move between two frames of a clip: the largest per-frame step of a wrist or
// elbow (and optionally the fingertips) and the largest change of that step from one frame to the
// next. Issue 4 asks for motion that looks human, with continuous velocity at the joins; a pose
// that flips (an elbow swung behind the neck in one frame) stays within every depth bound but
// shows here. The smoothness tests hold the lexicon and the alphabets to human bounds with it, and
// `signweave-cli check` reports it for every sign it synthesises.
#pragma once

#include <string>

#include "synthesis/clip.h"
#include "synthesis/rig.h"

namespace sw::synthesis {

// What the measure follows: the wrists and elbows of both arms, their fingertips too, or only
// the fingertips.
enum class StepTrack { Arms, ArmsAndFingertips, Fingertips };

struct FrameSteps {
  float step_m = 0.0f;    // the largest distance a tracked point moves between two frames
  float change_m = 0.0f;  // the largest change of a point's per-frame displacement (a * dt^2)
  std::string step_what;  // "right elbow at frame 42": the point and the frame it arrives at
  std::string change_what;
};

// Frames first..last of `clip` (last < 0: to its end), posed on `rig` (the clip's root
// translation is left out: it moves the whole body, not an arm against it).
FrameSteps measure_frame_steps(const Rig& rig, const Clip& clip, int first = 0, int last = -1,
                               StepTrack track = StepTrack::Arms);

}  // namespace sw::synthesis

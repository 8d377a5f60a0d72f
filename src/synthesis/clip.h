// Clip: what synthesis produces and what the page plays — per frame, the local rotation of every
// joint of one avatar, the root translation and the face's morph-target weights, plus the timing
// of each sign for captions. Runtime data in the ozz sense: built once, sampled many times.
//
// Frames are sampled at `fps` (seed 004 samples generalised coordinates every 1/30 s). Sampling
// between frames slerps rotations and lerps the rest (see clip_sampler.h).
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace sw::synthesis {

struct ClipSegment {
  enum class Kind { Sign, Letter, Transition, Hold, Pause } kind = Kind::Sign;
  std::string label;      // gloss, letter or word the caption shows
  int word_index = -1;    // index of the word of the typed phrase it belongs to, -1 if none
  double start_s = 0.0;
  double end_s = 0.0;
};

struct Clip {
  float fps = 30.0f;
  int frame_count = 0;
  // One channel per joint of the avatar's skeleton, in skeleton order (names for export).
  std::vector<std::string> joint_names;
  std::vector<std::string> morph_names;
  // Frame-major: rotations[frame * joint_names.size() + joint] is the joint's LOCAL rotation.
  std::vector<glm::quat> rotations;
  std::vector<glm::vec3> root_translation;  // per frame, local translation of joint 0
  std::vector<float> morph_weights;         // frame-major, morph_names.size() per frame
  std::vector<ClipSegment> segments;

  double duration_s() const { return frame_count > 1 ? (frame_count - 1) / double(fps) : 0.0; }
  int joint_count() const { return static_cast<int>(joint_names.size()); }
  int morph_count() const { return static_cast<int>(morph_names.size()); }
};

}  // namespace sw::synthesis

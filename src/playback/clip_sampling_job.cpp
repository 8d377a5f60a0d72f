// ClipSamplingJob: see clip_sampling_job.h.
#include "playback/clip_sampling_job.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace sw::playback {

std::string ClipSamplingJob::validate() const {
  if (!clip) return "no clip";
  if (!skeleton) return "no skeleton";
  const std::size_t joints = std::size_t(skeleton->joint_count());
  if (std::size_t(clip->joint_count()) != joints) {
    return "the clip animates " + std::to_string(clip->joint_count()) + " joints, the skeleton has " +
           std::to_string(joints);
  }
  if (clip->frame_count < 1) return "the clip has no frames";
  if (!(clip->fps > 0.0f) || !std::isfinite(clip->fps)) return "the clip's fps must be positive";
  if (clip->rotations.size() != std::size_t(clip->frame_count) * joints) return "clip rotations do not match frames x joints";
  if (!clip->root_translation.empty() && clip->root_translation.size() != std::size_t(clip->frame_count)) {
    return "clip root translations do not match its frames";
  }
  const std::size_t morphs = std::size_t(clip->morph_count());
  if (morphs && !clip->morph_weights.empty() && clip->morph_weights.size() != std::size_t(clip->frame_count) * morphs) {
    return "clip morph weights do not match frames x morph channels";
  }
  if (!clip_to_morph.empty() && clip_to_morph.size != morphs) return "clip_to_morph needs one entry per clip morph channel";
  for (int target : clip_to_morph) {
    if (target >= 0 && std::size_t(target) >= output_morph_weights.size) return "clip_to_morph points past the morph weights";
  }
  if (output_locals.size < joints) return "output_locals is smaller than the skeleton";
  if (!std::isfinite(time_s)) return "time is not finite";
  return "";
}

bool ClipSamplingJob::run() const {
  if (!validate().empty()) return false;
  const synthesis::Clip& c = *clip;
  const std::size_t joints = std::size_t(skeleton->joint_count());
  const double last = double(c.frame_count - 1);
  const double position = std::clamp(time_s * double(c.fps), 0.0, last);
  const std::size_t f0 = std::size_t(std::floor(position));
  const std::size_t f1 = std::min(f0 + 1, std::size_t(c.frame_count - 1));
  const float alpha = float(position - double(f0));

  for (std::size_t j = 0; j < joints; ++j) {
    const glm::quat& a = c.rotations[f0 * joints + j];
    const glm::quat& b = c.rotations[f1 * joints + j];
    math::Transform& out = output_locals[j];
    out.translation = skeleton->joints[j].rest.translation;
    out.scale = skeleton->joints[j].rest.scale;
    // glm::slerp takes the short arc, so neighbouring frames never spin through the long way.
    out.rotation = glm::normalize(glm::slerp(a, b, alpha));
  }
  if (!c.root_translation.empty() && joints > 0) {
    output_locals[0].translation = glm::mix(c.root_translation[f0], c.root_translation[f1], alpha);
  }
  const std::size_t morphs = std::size_t(c.morph_count());
  if (morphs && !c.morph_weights.empty()) {
    for (std::size_t m = 0; m < clip_to_morph.size; ++m) {
      const int target = clip_to_morph[m];
      if (target < 0) continue;
      const float w0 = c.morph_weights[f0 * morphs + m], w1 = c.morph_weights[f1 * morphs + m];
      output_morph_weights[std::size_t(target)] = w0 + (w1 - w0) * alpha;
    }
  }
  return true;
}

}  // namespace sw::playback

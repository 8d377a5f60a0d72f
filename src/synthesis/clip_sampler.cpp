// Clip sampler: slerp/lerp between the two frames around t (clip_sampler.h).
#include "synthesis/clip_sampler.h"

#include <algorithm>
#include <cmath>

#include "synthesis/rig.h"

namespace sw::synthesis {

void sample_clip(const Clip& clip, double t_s, glm::quat* rotations, glm::vec3* root, float* morphs) {
  const int J = clip.joint_count(), M = clip.morph_count();
  if (clip.frame_count <= 0) return;
  double frame = std::min(std::max(0.0, t_s * clip.fps), static_cast<double>(clip.frame_count - 1));
  int f0 = static_cast<int>(std::floor(frame));
  int f1 = std::min(f0 + 1, clip.frame_count - 1);
  float u = static_cast<float>(frame - f0);
  if (rotations && clip.rotations.size() >= static_cast<size_t>(clip.frame_count) * J)
    for (int j = 0; j < J; ++j)
      rotations[j] = slerp_shortest(clip.rotations[static_cast<size_t>(f0) * J + j],
                                    clip.rotations[static_cast<size_t>(f1) * J + j], u);
  if (root && clip.root_translation.size() >= static_cast<size_t>(clip.frame_count))
    *root = glm::mix(clip.root_translation[f0], clip.root_translation[f1], u);
  if (morphs && clip.morph_weights.size() >= static_cast<size_t>(clip.frame_count) * M)
    for (int m = 0; m < M; ++m)
      morphs[m] = clip.morph_weights[static_cast<size_t>(f0) * M + m] * (1.0f - u) +
                  clip.morph_weights[static_cast<size_t>(f1) * M + m] * u;
}

bool sample_clip_local(const Clip& clip, const skeleton::Skeleton& skeleton, double t_s,
                       math::Transform* out) {
  const int J = clip.joint_count();
  if (J != skeleton.joint_count() || J == 0) return false;
  for (int j = 0; j < J; ++j) out[j] = skeleton.joints[j].rest;
  if (clip.frame_count <= 0) return true;
  // Rotations straight into the output (no temporary: the sampler allocates nothing).
  const double frame = std::min(std::max(0.0, t_s * clip.fps), static_cast<double>(clip.frame_count - 1));
  const int f0 = static_cast<int>(std::floor(frame));
  const int f1 = std::min(f0 + 1, clip.frame_count - 1);
  const float u = static_cast<float>(frame - f0);
  for (int j = 0; j < J; ++j)
    out[j].rotation = slerp_shortest(clip.rotations[static_cast<size_t>(f0) * J + j],
                                     clip.rotations[static_cast<size_t>(f1) * J + j], u);
  if (clip.root_translation.size() >= static_cast<size_t>(clip.frame_count))
    out[0].translation = glm::mix(clip.root_translation[f0], clip.root_translation[f1], u);
  return true;
}

}  // namespace sw::synthesis

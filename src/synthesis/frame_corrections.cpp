// Frame corrections: ramps over neighbouring frames and the nearest clear swivel
// (frame_corrections.h).
#include "synthesis/frame_corrections.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace sw::synthesis {

float ramp_weight(int distance, int radius) {
  const float x = static_cast<float>(std::abs(distance)) / static_cast<float>(radius + 1);
  if (x >= 1.0f) return 0.0f;
  return 1.0f - x * x * (3.0f - 2.0f * x);
}

std::vector<float> ramp_scalars(const std::vector<float>& fix, int radius) {
  const int n = static_cast<int>(fix.size());
  std::vector<float> out(fix.size(), 0.0f);
  for (int f = 0; f < n; ++f) {
    float best = 0.0f;
    for (int g = std::max(0, f - radius); g <= std::min(n - 1, f + radius); ++g) {
      const float o = ramp_weight(f - g, radius) * fix[g];
      if (std::abs(o) > std::abs(best)) best = o;
    }
    out[f] = best;
  }
  return out;
}

std::vector<glm::vec3> ramp_offsets(const std::vector<glm::vec3>& fix, int radius) {
  const int n = static_cast<int>(fix.size());
  std::vector<glm::vec3> out(fix.size(), glm::vec3(0.0f));
  for (int f = 0; f < n; ++f) {
    glm::vec3 best(0.0f), sum(0.0f);
    float most = 0.0f;
    for (int g = std::max(0, f - radius); g <= std::min(n - 1, f + radius); ++g) {
      const glm::vec3 o = ramp_weight(f - g, radius) * fix[g];
      sum += o;
      const float len = glm::length(o);
      if (len > most) most = len, best = o;
    }
    // The length of the largest, the direction of the weighted sum: neighbours that push
    // different ways (LOOK's hand out of the head: 91 mm at the key pose, 110 mm two frames on,
    // 50 degrees apart) hand the lead to each other without a jump in direction (the largest
    // alone switched from one to the other between two frames: the target 58 mm in one frame).
    // Pushes that nearly cancel have no direction to blend: the largest, as before.
    const float sum_len = glm::length(sum);
    out[f] = sum_len > 0.5f * most ? (most / sum_len) * sum : best;
  }
  return out;
}

std::vector<glm::quat> ramp_turns(const std::vector<glm::quat>& fix, int radius) {
  const int n = static_cast<int>(fix.size());
  std::vector<glm::quat> out(fix.size());
  for (int f = 0; f < n; ++f) {
    glm::quat r = fix[f];
    float best = rotation_angle(r);
    for (int g = std::max(0, f - radius); g <= std::min(n - 1, f + radius); ++g) {
      const float w = ramp_weight(f - g, radius);
      const float a = w * rotation_angle(fix[g]);
      if (a > best + 1e-4f) {
        best = a;
        r = slerp_shortest(glm::quat(1, 0, 0, 0), fix[g], w);
      }
    }
    out[f] = r;
  }
  return out;
}

SwivelChoice nearest_clear_swivel(float base_depth_m, float clear_m, float prefer, float min_gain_m,
                                  const std::function<float(float offset_rad, bool* usable)>& depth_at,
                                  bool only_prefer) {
  SwivelChoice best{0.0f, base_depth_m};
  const float first_sign = prefer < 0.0f ? -1.0f : 1.0f;
  int other_clear_k = 0;  // the step at which the other side cleared (0: not yet)
  for (int k = 1; k <= 12; ++k) {
    if (other_clear_k > 0 && k > other_clear_k + kPreferSlackSteps) break;
    for (float sign : {first_sign, -first_sign}) {
      if ((other_clear_k > 0 || (only_prefer && prefer != 0.0f)) && sign != first_sign) continue;
      const float offset = sign * 0.1f * static_cast<float>(k);
      bool usable = true;
      const float d = depth_at(offset, &usable);
      if (!usable) continue;
      const bool clears = d <= clear_m;
      // A clear offset on the preferred side replaces the other side's clear one.
      if (d < best.depth_m - 1e-4f || (clears && other_clear_k > 0)) best = {offset, d};
      if (prefer == 0.0f) {
        if (best.depth_m <= clear_m) return best;
      } else if (clears) {
        if (sign == first_sign) return best;
        other_clear_k = k;
      }
    }
  }
  if (best.depth_m > clear_m && base_depth_m - best.depth_m < min_gain_m) return {0.0f, base_depth_m};
  return best;
}

}  // namespace sw::synthesis

#include "synthesis/clip_steps.h"

#include <vector>

namespace sw::synthesis {

FrameSteps measure_frame_steps(const Rig& rig, const Clip& clip, int first, int last,
                               StepTrack track) {
  const bool arms = track != StepTrack::Fingertips, tips = track != StepTrack::Arms;
  FrameSteps w;
  PoseBuilder pb(rig);
  const int J = rig.joint_count;
  const char* side_names[2] = {"left", "right"};
  const char* finger_names[5] = {"thumb", "index", "middle", "ring", "little"};
  std::vector<std::string> names;
  for (Side s : {kLeft, kRight}) {
    if (arms) {
      names.push_back(std::string(side_names[s]) + " wrist");
      names.push_back(std::string(side_names[s]) + " elbow");
    }
    for (int k = 0; tips && k < 5; ++k)
      names.push_back(std::string(side_names[s]) + " " + finger_names[k] + " tip");
  }
  if (last < 0 || last >= clip.frame_count) last = clip.frame_count - 1;
  std::vector<glm::vec3> prev, cur, step(names.size()), prev_step(names.size());
  for (int f = first; f <= last; ++f) {
    pb.set_from_local(&clip.rotations[static_cast<size_t>(f) * J]);
    cur.clear();
    for (Side s : {kLeft, kRight}) {
      if (arms) {
        cur.push_back(pb.position(rig.arms[s].hand));
        cur.push_back(pb.position(rig.arms[s].lower));
      }
      for (int k = 0; tips && k < 5; ++k) cur.push_back(pb.tip(s, k));
    }
    if (f > first) {
      for (size_t k = 0; k < cur.size(); ++k) {
        step[k] = cur[k] - prev[k];
        const float d = glm::length(step[k]);
        if (d > w.step_m) {
          w.step_m = d;
          w.step_what = names[k] + " at frame " + std::to_string(f);
        }
        // The second difference: a joint held and then let go changes its displacement by the
        // whole jump in one frame even when the jump is under the speed bound.
        if (f > first + 1) {
          const float c = glm::length(step[k] - prev_step[k]);
          if (c > w.change_m) {
            w.change_m = c;
            w.change_what = names[k] + " at frame " + std::to_string(f);
          }
        }
      }
      prev_step.swap(step);
    }
    prev.swap(cur);
  }
  return w;
}

}  // namespace sw::synthesis

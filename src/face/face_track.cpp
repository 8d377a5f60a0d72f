#include "face/face_track.h"

#include <algorithm>
#include <cmath>

#include "face/blink.h"
#include "face/channel_set.h"
#include "face/easing.h"
#include "face/emotion.h"
#include "face/head_gesture.h"
#include "face/mouthing.h"
#include "face/spring_frame.h"

namespace sw::face {
namespace {

// seed 003: a channel that varies a lot across expressions gets a soft spring (1/k = variance), so
// it moves with visible intermediate states; a channel no expression touches stays stiff. The
// constants are normalised to a mean of 1 so `response_time_s` sets the overall pace.
std::vector<float> compute_channel_spring_constants() {
  const Emotion emotions[] = {Emotion::Happy, Emotion::Sad,     Emotion::Angry, Emotion::Surprised,
                              Emotion::Fear,  Emotion::Disgust, Emotion::Sleepy};
  std::vector<float> k(kChannelCount, 1.0f);
  double sum = 0.0;
  int counted = 0;
  for (int c = 0; c < kChannelCount; ++c) {
    std::vector<float> lengths;
    for (Emotion e : emotions) lengths.push_back(emotion_weights(e, 1.0f)[c]);
    // Natural length 0 = neutral; k_max 4 keeps untouched channels at most 4x stiffer than the
    // softest, so a brow raise from the performance still eases rather than snaps.
    k[std::size_t(c)] = spring_constant_from_lengths(lengths, 0.0f, 4.0f);
    sum += k[std::size_t(c)];
    ++counted;
  }
  const float mean = static_cast<float>(sum / counted);
  for (float& v : k) v /= mean;
  return k;
}

// The constants depend on nothing but the emotion tables: worked out once, not for every clip
// (7 x 67 emotion tables each time, 4% of a sign's synthesis time).
const std::vector<float>& channel_spring_constants() {
  static const std::vector<float> constants = compute_channel_spring_constants();
  return constants;
}

const FaceCue* cue_at(const std::vector<FaceCue>& cues, double t) {
  for (const FaceCue& c : cues)
    if (t >= c.start_s && t < c.end_s) return &c;
  return nullptr;
}

// Grammatical brows over a sign: ease in and out over 0.15 s at either end (seed 001 cosine).
float envelope(const FaceCue& cue, double t) {
  const double ramp = std::min(0.15, 0.5 * (cue.end_s - cue.start_s));
  if (ramp <= 0.0) return 0.0f;
  const float in = ease_cosine(float((t - cue.start_s) / ramp));
  const float out = ease_cosine(float((cue.end_s - t) / ramp));
  return std::min(in, out);
}

glm::quat world_rotation(const skeleton::Skeleton& skeleton, const glm::quat* locals, int joint) {
  glm::quat r(1, 0, 0, 0);
  for (int j = joint; j >= 0; j = skeleton.joints[std::size_t(j)].parent) r = locals[j] * r;
  return r;
}

glm::quat rest_world_rotation(const skeleton::Skeleton& skeleton, int joint) {
  glm::quat r(1, 0, 0, 0);
  for (int j = joint; j >= 0; j = skeleton.joints[std::size_t(j)].parent)
    r = skeleton.joints[std::size_t(j)].rest.rotation * r;
  return r;
}

}  // namespace

FaceRig face_rig_by_names(const skeleton::Skeleton& skeleton) {
  FaceRig rig;
  rig.head = skeleton.find("head");
  rig.left_eye = skeleton.find("leftEye");
  rig.right_eye = skeleton.find("rightEye");
  return rig;
}

bool add_face_tracks(synthesis::Clip& clip, const skeleton::Skeleton& skeleton, const FaceRig& rig,
                     const std::vector<FaceCue>& cues, const FaceOptions& options) {
  const int joints = clip.joint_count();
  if (joints != skeleton.joint_count() || clip.frame_count < 0 ||
      clip.rotations.size() != std::size_t(clip.frame_count) * std::size_t(joints) ||
      clip.fps <= 0.0f)
    return false;
  for (int j : {rig.head, rig.left_eye, rig.right_eye})
    if (j >= joints) return false;

  clip.morph_names.clear();
  for (int c = 0; c < kChannelCount; ++c) clip.morph_names.emplace_back(channel_name(c));
  clip.morph_weights.assign(std::size_t(clip.frame_count) * kChannelCount, 0.0f);

  Emotion global_emotion = Emotion::Neutral;
  emotion_from_name(options.emotion, &global_emotion);

  // Emotion dynamics (seed 003): per channel, a moving point tied by a zero-length spring to a
  // fixed point at the target weight; one relaxation step per frame shows the intermediate states.
  const std::vector<float>& k = channel_spring_constants();
  SpringFrame springs;
  std::vector<int> moving(kChannelCount), target(kChannelCount);
  const ChannelWeights start = emotion_weights(global_emotion, options.intensity);
  for (int c = 0; c < kChannelCount; ++c) {
    moving[std::size_t(c)] = springs.add_point({float(c), start[c]}, false);
    target[std::size_t(c)] = springs.add_point({float(c), start[c]}, true);
    springs.add_spring(moving[std::size_t(c)], target[std::size_t(c)], k[std::size_t(c)], 0.0f);
  }
  const float dt = 1.0f / clip.fps;
  const float alpha = 1.0f - std::exp(-dt / std::max(1e-3f, options.response_time_s));

  std::vector<std::vector<VisemeKey>> mouthing(cues.size());
  std::vector<double> boundaries;
  for (std::size_t i = 0; i < cues.size(); ++i) {
    const FaceCue& cue = cues[i];
    if (cue.is_pause) boundaries.push_back(cue.start_s);
    if (options.mouthing && !cue.nonmanual.mouthing.empty()) {
      // The spoken word takes the first ~80% of the sign; the mouth is at rest for the hold.
      const double end = cue.start_s + 0.8 * (cue.end_s - cue.start_s);
      mouthing[i] = schedule_mouthing(cue.nonmanual.mouthing, cue.start_s, end);
    }
  }
  const double duration = clip.duration_s();
  const std::vector<double> blinks = options.blinks
                                         ? schedule_blinks(duration + dt, boundaries, options.seed)
                                         : std::vector<double>{};

  const glm::quat head_rest_world =
      rig.head >= 0 ? rest_world_rotation(skeleton, rig.head) : glm::quat(1, 0, 0, 0);
  const int blink_l = channel_index("eyeBlinkLeft"), blink_r = channel_index("eyeBlinkRight");
  // The eyes' rest rotations in the world depend on the skeleton alone: once per clip.
  const int eyes[2] = {rig.left_eye, rig.right_eye};
  glm::quat eye_rest_worlds[2] = {glm::quat(1, 0, 0, 0), glm::quat(1, 0, 0, 0)};
  for (int e = 0; e < 2; ++e)
    if (eyes[e] >= 0) eye_rest_worlds[e] = rest_world_rotation(skeleton, eyes[e]);

  for (int f = 0; f < clip.frame_count; ++f) {
    const double t = f / double(clip.fps);
    const FaceCue* cue = cue_at(cues, t);

    Emotion emotion = global_emotion;
    float intensity = options.intensity;
    if (cue && !cue->nonmanual.expression.empty() &&
        emotion_from_name(cue->nonmanual.expression, &emotion)) {
      intensity =
          cue->nonmanual.expression_intensity > 0.0f ? cue->nonmanual.expression_intensity : 0.7f;
    }
    const ChannelWeights emotion_target = emotion_weights(emotion, intensity);
    for (int c = 0; c < kChannelCount; ++c)
      springs.points()[std::size_t(target[std::size_t(c)])].position.y = emotion_target[c];
    if (f > 0) springs.step(alpha);
    ChannelWeights emotion_now;
    for (int c = 0; c < kChannelCount; ++c)
      emotion_now[c] = springs.points()[std::size_t(moving[std::size_t(c)])].position.y;

    ChannelWeights performance;
    if (cue) {
      const float e = envelope(*cue, t);
      if (cue->nonmanual.eyebrows == "up") {  // yes/no questions, topics
        performance[channel_index("browInnerUp")] = 0.8f * e;
        performance[channel_index("browOuterUpLeft")] = 0.8f * e;
        performance[channel_index("browOuterUpRight")] = 0.8f * e;
      } else if (cue->nonmanual.eyebrows == "down") {  // wh-questions
        performance[channel_index("browDownLeft")] = 0.8f * e;
        performance[channel_index("browDownRight")] = 0.8f * e;
      }
      const std::size_t cue_index = std::size_t(cue - cues.data());
      const ChannelWeights mouth = sample_mouthing(mouthing[cue_index], t);
      for (int c = 0; c < kChannelCount; ++c) performance[c] = std::max(performance[c], mouth[c]);
    }
    ChannelWeights combined = combine_damped(emotion_now, performance);
    const float lid = blink_weight(blinks, t);
    combined[blink_l] = std::max(combined[blink_l], lid);
    combined[blink_r] = std::max(combined[blink_r], lid);
    std::copy(combined.w.begin(), combined.w.end(),
              clip.morph_weights.begin() + std::ptrdiff_t(f) * kChannelCount);

    glm::quat* locals = clip.rotations.data() + std::size_t(f) * std::size_t(joints);
    if (rig.head >= 0) {
      if (cue && !cue->nonmanual.head.empty()) {
        const HeadGesture g = head_gesture_from_name(cue->nonmanual.head);
        const float u = float((t - cue->start_s) / std::max(1e-6, cue->end_s - cue->start_s));
        // A model-space rotation about the head's pivot: local' = inv(P) * R * P * local.
        const int parent = skeleton.joints[std::size_t(rig.head)].parent;
        const glm::quat parent_world =
            parent >= 0 ? world_rotation(skeleton, locals, parent) : glm::quat(1, 0, 0, 0);
        locals[rig.head] = glm::normalize(glm::inverse(parent_world) * head_gesture_rotation(g, u) *
                                          parent_world * locals[rig.head]);
      }
      // seed 002: eyes inherit the head, then counter-rotate to keep the gaze on the target.
      const glm::quat head_world = world_rotation(skeleton, locals, rig.head);
      const glm::quat head_relative = head_world * glm::inverse(head_rest_world);
      const glm::vec3 look = gaze_direction(cue ? cue->nonmanual.gaze : std::string());
      const glm::quat in_head = gaze_rotation(head_relative, look);
      for (int e = 0; e < 2; ++e) {
        const int eye = eyes[e];
        if (eye < 0) continue;
        const glm::quat eye_world = head_relative * in_head * eye_rest_worlds[e];
        const int parent = skeleton.joints[std::size_t(eye)].parent;
        // An eye's parent is the head on a humanoid: its world rotation is head_world, the same
        // product of the same rotations (the eyes written here are not among them).
        const glm::quat parent_world = parent == rig.head ? head_world
                                       : parent >= 0      ? world_rotation(skeleton, locals, parent)
                                                          : glm::quat(1, 0, 0, 0);
        locals[eye] = glm::normalize(glm::inverse(parent_world) * eye_world);
      }
    }
  }
  return true;
}

}  // namespace sw::face

#include "face/emotion.h"

#include <algorithm>
#include <cctype>
#include <utility>

namespace sw::face {
namespace {

struct Offset {
  const char* channel;
  float weight;
};

// FACS composition (seed 001 lists the AUs; seed 002 gives the control-point directions):
//   happy     AU6 + AU12                 (seed 002: mouth corners up)
//   sad       AU1 + AU4 + AU15 + AU23    (seed 001 verbatim; AU23 lip tightener ~ mouthPress)
//   angry     AU4 + AU5 + AU7 + AU23     (seed 002: inner brows down and in)
//   surprised AU1 + AU2 + AU5 + AU26     (seed 002: brows up)
//   fear      AU1 + AU2 + AU4 + AU5 + AU20 + AU26
//   disgust   AU9 + AU10 + AU15 + AU16
//   sleepy    brows slightly up, lids narrowed (seed 002)
std::vector<Offset> offsets_of(Emotion e) {
  switch (e) {
    case Emotion::Happy:
      return {{"cheekSquintLeft", 0.6f}, {"cheekSquintRight", 0.6f}, {"mouthSmileLeft", 0.9f},
              {"mouthSmileRight", 0.9f}, {"eyeSquintLeft", 0.25f},   {"eyeSquintRight", 0.25f}};
    case Emotion::Sad:
      return {{"browInnerUp", 0.85f},   {"browDownLeft", 0.3f},    {"browDownRight", 0.3f},
              {"mouthFrownLeft", 0.7f}, {"mouthFrownRight", 0.7f}, {"mouthPress", 0.3f}};
    case Emotion::Angry:
      return {{"browDownLeft", 0.9f}, {"browDownRight", 0.9f}, {"eyeWideLeft", 0.3f},
              {"eyeWideRight", 0.3f}, {"eyeSquintLeft", 0.5f}, {"eyeSquintRight", 0.5f},
              {"mouthPress", 0.6f},   {"noseSneerLeft", 0.2f}, {"noseSneerRight", 0.2f}};
    case Emotion::Surprised:
      return {{"browInnerUp", 0.9f}, {"browOuterUpLeft", 0.9f}, {"browOuterUpRight", 0.9f},
              {"eyeWideLeft", 0.8f}, {"eyeWideRight", 0.8f},    {"jawOpen", 0.45f}};
    case Emotion::Fear:
      return {{"browInnerUp", 0.8f},  {"browOuterUpLeft", 0.5f}, {"browOuterUpRight", 0.5f},
              {"browDownLeft", 0.3f}, {"browDownRight", 0.3f},   {"eyeWideLeft", 0.8f},
              {"eyeWideRight", 0.8f}, {"mouthStretch", 0.6f},    {"jawOpen", 0.2f}};
    case Emotion::Disgust:
      return {{"noseSneerLeft", 0.8f},  {"noseSneerRight", 0.8f},  {"mouthUpperUp", 0.6f},
              {"mouthFrownLeft", 0.4f}, {"mouthFrownRight", 0.4f}, {"mouthLowerDown", 0.2f},
              {"browDownLeft", 0.4f},   {"browDownRight", 0.4f}};
    case Emotion::Sleepy:
      return {{"browOuterUpLeft", 0.2f},
              {"browOuterUpRight", 0.2f},
              {"eyeBlinkLeft", 0.45f},
              {"eyeBlinkRight", 0.45f}};
    case Emotion::Neutral:
      break;
  }
  return {};
}

constexpr std::pair<Emotion, const char*> kNames[] = {
    {Emotion::Neutral, "neutral"}, {Emotion::Happy, "happy"},         {Emotion::Sad, "sad"},
    {Emotion::Angry, "angry"},     {Emotion::Surprised, "surprised"}, {Emotion::Fear, "fear"},
    {Emotion::Disgust, "disgust"}, {Emotion::Sleepy, "sleepy"},
};

}  // namespace

bool emotion_from_name(std::string_view name, Emotion* out) {
  std::string lower(name);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "surprise") lower = "surprised";
  if (lower == "anger") lower = "angry";
  if (lower == "happiness" || lower == "joy") lower = "happy";
  if (lower == "sadness") lower = "sad";
  for (const auto& [e, n] : kNames) {
    if (lower == n) {
      *out = e;
      return true;
    }
  }
  return false;
}

const char* emotion_name(Emotion e) {
  for (const auto& [em, n] : kNames)
    if (em == e) return n;
  return "neutral";
}

std::vector<std::string> emotion_names() {
  std::vector<std::string> names;
  for (const auto& entry : kNames) names.emplace_back(entry.second);
  return names;
}

ChannelWeights emotion_weights(Emotion e, float intensity) {
  ChannelWeights out;
  const float k = std::clamp(intensity, 0.0f, 1.0f);
  for (const auto& o : offsets_of(e)) {
    const int i = channel_index(o.channel);
    if (i >= 0) out[i] = o.weight * k;
  }
  return out;
}

ChannelWeights combine_damped(const ChannelWeights& emotion, const ChannelWeights& performance) {
  ChannelWeights out;
  for (int i = 0; i < kChannelCount; ++i) {
    const float e = std::clamp(emotion[i], 0.0f, 1.0f);
    const float p = std::clamp(performance[i], 0.0f, 1.0f);
    out[i] = std::clamp(e + p * (1.0f - e), 0.0f, 1.0f);
  }
  return out;
}

}  // namespace sw::face

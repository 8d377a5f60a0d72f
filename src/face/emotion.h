// Emotion layer (seed 002 §"emotional modification"; FACS units from seed 001): an emotion with an
// intensity is a set of channel offsets applied on top of the neutral face BEFORE the performance
// (brows, mouthing), and the performance is damped on the channels the emotion already pushes.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "face/channel_set.h"

namespace sw::face {

enum class Emotion { Neutral, Happy, Sad, Angry, Surprised, Fear, Disgust, Sleepy };

// Parses "happy", "sad", ... (case-insensitive); false for an unknown name.
bool emotion_from_name(std::string_view name, Emotion* out);
const char* emotion_name(Emotion e);
std::vector<std::string> emotion_names();

// The channel weights of an emotion at intensity in [0, 1] (seed 002 uses 0..100; we use 0..1).
// Intensity scales every offset linearly; 0 gives the neutral face.
ChannelWeights emotion_weights(Emotion e, float intensity);

// seed 002: "channels already pushed by the emotion are damped in the performance" — the
// performance adds only into the headroom the emotion left: w = e + p (1 - e), clamped to [0, 1].
ChannelWeights combine_damped(const ChannelWeights& emotion, const ChannelWeights& performance);

}  // namespace sw::face

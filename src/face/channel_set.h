// ChannelWeights: one weight per face channel (channels.h: expression channels then visemes), the
// unit every face layer produces and combines. Indexing by name keeps layers independent of the
// avatar; the clip maps names onto the avatar's morph targets at the end.
#pragma once

#include <array>
#include <string_view>

#include "face/channels.h"

namespace sw::face {

constexpr int kChannelCount = static_cast<int>(kExpressionChannels.size() + kVisemeChannels.size());

struct ChannelWeights {
  std::array<float, kChannelCount> w{};

  float& operator[](int i) { return w[static_cast<std::size_t>(i)]; }
  float operator[](int i) const { return w[static_cast<std::size_t>(i)]; }
};

// Index of a channel name in the combined list, -1 if unknown.
int channel_index(std::string_view name);
std::string_view channel_name(int index);
// True for the 15 viseme channels.
bool is_viseme_channel(int index);

}  // namespace sw::face

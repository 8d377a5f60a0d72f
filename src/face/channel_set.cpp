#include "face/channel_set.h"

namespace sw::face {

int channel_index(std::string_view name) {
  for (std::size_t i = 0; i < kExpressionChannels.size(); ++i)
    if (kExpressionChannels[i] == name) return static_cast<int>(i);
  for (std::size_t i = 0; i < kVisemeChannels.size(); ++i)
    if (kVisemeChannels[i] == name) return static_cast<int>(kExpressionChannels.size() + i);
  return -1;
}

std::string_view channel_name(int index) {
  if (index < 0 || index >= kChannelCount) return {};
  const auto i = static_cast<std::size_t>(index);
  if (i < kExpressionChannels.size()) return kExpressionChannels[i];
  return kVisemeChannels[i - kExpressionChannels.size()];
}

bool is_viseme_channel(int index) {
  return index >= static_cast<int>(kExpressionChannels.size()) && index < kChannelCount;
}

}  // namespace sw::face

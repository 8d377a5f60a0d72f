#include "face/expression_blender.h"

#include "face/easing.h"

namespace sw::face {

ChannelWeights bilinear_blend(const ChannelWeights& q11, const ChannelWeights& q12,
                              const ChannelWeights& q21, const ChannelWeights& q22, float s2,
                              float t2) {
  const float s1 = 1.0f - s2;
  const float t1 = 1.0f - t2;
  ChannelWeights out;
  for (int i = 0; i < kChannelCount; ++i)
    out[i] = s1 * (t1 * q11[i] + t2 * q12[i]) + s2 * (t1 * q21[i] + t2 * q22[i]);
  return out;
}

ExpressionBlender::ExpressionBlender(const ChannelWeights& initial)
    : source_(initial), target_(initial) {}

void ExpressionBlender::retarget(const ChannelWeights& target, double now_s, double duration_s) {
  source_ = value(now_s);  // seed 001: snapshot the current blend as the new source
  target_ = target;
  start_s_ = now_s;
  duration_s_ = duration_s;
}

ChannelWeights ExpressionBlender::value(double now_s) const {
  if (duration_s_ <= 0.0 || now_s >= start_s_ + duration_s_) return target_;
  if (now_s <= start_s_) return source_;
  const float mu = ease_cosine(static_cast<float>((now_s - start_s_) / duration_s_));
  ChannelWeights out;
  for (int i = 0; i < kChannelCount; ++i) out[i] = lerp(source_[i], target_[i], mu);
  return out;
}

}  // namespace sw::face

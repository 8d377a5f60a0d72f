// ExpressionBlender: moves the face from one expression to the next with cosine easing, and lets a
// new expression interrupt a transition without a jump — seed 001's bilinear method (Arai et al.):
// switching mid-way snapshots the current blend as the new source (Q13 = t1 Q11 + t2 Q12).
#pragma once

#include "face/channel_set.h"

namespace sw::face {

// seed 001: P = s1 (t1 Q11 + t2 Q12) + s2 (t1 Q21 + t2 Q22), s1 + s2 = t1 + t2 = 1, per channel.
ChannelWeights bilinear_blend(const ChannelWeights& q11, const ChannelWeights& q12,
                              const ChannelWeights& q21, const ChannelWeights& q22, float s2,
                              float t2);

class ExpressionBlender {
 public:
  explicit ExpressionBlender(const ChannelWeights& initial = {});

  // Start moving towards `target`, reaching it `duration_s` after `now_s`. If a transition is
  // under way, its current blend becomes the new source (seed 001), so the face never jumps.
  void retarget(const ChannelWeights& target, double now_s, double duration_s);
  ChannelWeights value(double now_s) const;

 private:
  ChannelWeights source_;
  ChannelWeights target_;
  double start_s_ = 0.0;
  double duration_s_ = 0.0;
};

}  // namespace sw::face

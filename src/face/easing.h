// Easing curves for face channels. Seed 001 (§2, after Parke 1972): the face accelerates and
// decelerates, so a cosine interpolation mu = (1 - cos(pi t)) / 2 replaces the linear one, whose
// velocity jumps at every key.
#pragma once

namespace sw::face {

// t clamped to [0, 1].
float ease_linear(float t);
// seed 001: cosine interpolation, zero velocity at both ends.
float ease_cosine(float t);
// Linear interpolation between a and b by mu (seed 001 eq. (2.5): P = (1 - t) P_prev + t P_next).
float lerp(float a, float b, float mu);

}  // namespace sw::face

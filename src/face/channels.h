// Face channels: the canonical names of the avatar's morph targets, shared by the avatar generator
// (models/), the loader, the face synthesis (expression, emotion, mouthing, blink) and the page.
//
// The expression channels follow the ARKit blend-shape names (the de-facto convention of face rigs,
// so third-party avatars map without tables); the visemes follow the Oculus/OVR 15-viseme set used
// for lip sync. Seed 001 motivates independent channels: whole-face keys cannot combine independent
// motions (AU1 + AU4 + AU15 + AU23 for sad).
#pragma once

#include <array>
#include <string_view>

namespace sw::face {

constexpr std::array<std::string_view, 26> kExpressionChannels = {
    "browInnerUp",                          // AU1
    "browDownLeft",    "browDownRight",     // AU4
    "browOuterUpLeft", "browOuterUpRight",  // AU2
    "eyeBlinkLeft",    "eyeBlinkRight",     // AU45 (upper lid closes)
    "eyeSquintLeft",   "eyeSquintRight",    // AU7 (lower lid up)
    "eyeWideLeft",     "eyeWideRight",      // AU5
    "cheekSquintLeft", "cheekSquintRight",  // AU6 cheek raise
    "noseSneerLeft",   "noseSneerRight",    // AU9 nose wrinkle
    "mouthUpperUp",                         // AU10 upper-lip raise
    "mouthSmileLeft",  "mouthSmileRight",   // AU12 lip-corner puller
    "mouthFrownLeft",  "mouthFrownRight",   // AU15 lip-corner depressor
    "mouthStretch",                         // AU20 lip stretch
    "mouthPucker",                          // AU18 lip pucker / rounding
    "mouthPress",                           // AU24 lip press
    "mouthLowerDown",                       // AU16 lower-lip depressor
    "jawOpen",                              // AU26/27 mouth open
    "tongueOut",
};

constexpr std::array<std::string_view, 15> kVisemeChannels = {
    "viseme_sil", "viseme_PP", "viseme_FF", "viseme_TH", "viseme_DD",
    "viseme_kk",  "viseme_CH", "viseme_SS", "viseme_nn", "viseme_RR",
    "viseme_aa",  "viseme_E",  "viseme_I",  "viseme_O",  "viseme_U",
};

}  // namespace sw::face

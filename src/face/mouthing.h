// Mouthing: a spoken-word picture (SiGML mouth_picture SAMPA such as "tIn", plain Latin spelling
// such as "hello", or Cyrillic) turned into timed viseme keys.
//
// Seed 000 (Thai mouth shapes) animates each vowel with three key frames — before motion, maximum,
// back at rest — and linear in-betweens of the displacement (3.3). We generalise that to every
// phoneme: each viseme peaks at its own key and falls linearly to zero at the neighbouring keys,
// which gives coarticulation for free; the word opens from and closes to rest (viseme_sil).
// Seed 000 covers vowels only; consonant classes (bilabial closure, labiodental, ...) follow the
// 15-viseme set of face/channels.h.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "face/channel_set.h"

namespace sw::face {

struct VisemeKey {
  int channel = -1;     // channel_index() of a viseme_* channel
  double time_s = 0.0;  // peak time
  float weight = 1.0f;  // peak weight (vowels open fully, consonants slightly less)
};

// The viseme sequence of a word (no timing yet). Unknown characters are skipped; digraphs (th,
// sh, ch, ng, SAMPA tS/dZ) are read as one phoneme.
std::vector<int> visemes_of_word(std::string_view text);

// Spreads the word's visemes over [start_s, end_s] with rest keys at both ends (seed 000's three
// phases per vowel become one rise/peak/fall per phoneme).
std::vector<VisemeKey> schedule_mouthing(std::string_view text, double start_s, double end_s);

// The viseme weights at time t from a key list (linear in-betweens, seed 000 eq. (3.3)).
ChannelWeights sample_mouthing(const std::vector<VisemeKey>& keys, double t_s);

}  // namespace sw::face

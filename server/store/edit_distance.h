// Bounded optimal-string-alignment distance (Damerau–Levenshtein with adjacent transpositions,
// each substring edited once), over code points: the typo tolerance of sign search. "helo",
// "hlelo" and "hellp" are each one edit from "hello".
#pragma once

#include <vector>

namespace sw::store {

// Returns the distance, or bound + 1 as soon as the distance is known to exceed `bound` (a row of
// the dynamic programme whose minimum is over the bound), so most candidates cost a few rows.
int bounded_osa_distance(const std::vector<char32_t>& a, const std::vector<char32_t>& b, int bound);

}  // namespace sw::store

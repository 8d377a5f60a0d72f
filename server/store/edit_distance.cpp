// Bounded OSA distance (see edit_distance.h).
#include "store/edit_distance.h"

#include <algorithm>
#include <cstdlib>

namespace sw::store {

int bounded_osa_distance(const std::vector<char32_t>& a, const std::vector<char32_t>& b, int bound) {
  const int n = static_cast<int>(a.size());
  const int m = static_cast<int>(b.size());
  if (std::abs(n - m) > bound) return bound + 1;
  // Three rows: i-2 (for transpositions), i-1, i.
  std::vector<int> before_previous(m + 1), previous(m + 1), current(m + 1);
  for (int j = 0; j <= m; ++j) previous[j] = j;
  for (int i = 1; i <= n; ++i) {
    current[0] = i;
    int row_minimum = current[0];
    for (int j = 1; j <= m; ++j) {
      int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      int best = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        best = std::min(best, before_previous[j - 2] + 1);
      }
      current[j] = best;
      row_minimum = std::min(row_minimum, best);
    }
    if (row_minimum > bound) return bound + 1;
    std::swap(before_previous, previous);
    std::swap(previous, current);
  }
  return std::min(previous[m], bound + 1);
}

}  // namespace sw::store

// Joining a parallel group's steps (see parallel_steps.h).
#include "notation/parallel_steps.h"

namespace sw::notation {

MovementStep join_parallel_steps(const std::vector<MovementStep>& parts) {
  MovementStep joined;
  bool any_stays = false, every_follower_stays = true;
  for (const MovementStep& p : parts) {
    joined.dominant.insert(joined.dominant.end(), p.dominant.begin(), p.dominant.end());
    joined.nondominant.insert(joined.nondominant.end(), p.nondominant.begin(), p.nondominant.end());
    any_stays = any_stays || p.nondominant_stays;
    // A part whose dominant movements the other hand follows by the symmetry.
    if (!p.dominant.empty() && p.nondominant.empty() && !p.nondominant_stays)
      every_follower_stays = false;
  }
  joined.nondominant_stays = any_stays && every_follower_stays && joined.nondominant.empty();
  return joined;
}

}  // namespace sw::notation

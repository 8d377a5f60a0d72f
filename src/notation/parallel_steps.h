// The movement steps of a parallel group (HamNoSys hamparbegin...hamparend, G-SiGML par_motion /
// split_motion) joined into the one step they make, shared by the HamNoSys and G-SiGML readers so
// both read "this hand stays" (MovementStep::nondominant_stays) the same way.
#pragma once

#include <vector>

#include "notation/sign_spec.h"

namespace sw::notation {

// The parts' movements, each hand's in the parts' order. The non-dominant hand stays in the
// joined step only where every part that moves the dominant hand and leaves the other to the
// symmetry says it stays (TO-OPPRESS1A: `hamparbegin hammoved hamparbegin hamreplace
// hamextfingero hamplus hamnomotion hamparend hamparend`, the move down is both hands', only the
// turn is the dominant's own; SignSpec has no mark for a part of a step, so the other hand keeps
// following the symmetry there, as it did before the mark). A step that writes movements for the
// non-dominant hand has no "stays": the list says what that hand does.
MovementStep join_parallel_steps(const std::vector<MovementStep>& parts);

}  // namespace sw::notation

// Reference humanoid: the project's procedural skeleton (skeleton/synthetic_humanoid.h, with
// finger metacarpals) as an Avatar, with body anchors on its capsule body. Synthesis tests,
// benchmarks and the native/WASM parity case use it so they do not depend on a model file; the
// product uses models/signweave-avatar.glb.
#pragma once

#include "avatar/avatar.h"

namespace sw::synthesis {

avatar::Avatar make_reference_humanoid();

}  // namespace sw::synthesis

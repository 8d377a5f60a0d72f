// Reference humanoid: a procedural 1.70 m skeleton with the canonical VRM joint names, the
// project's bind convention (identity rest rotations, T-pose, arms along +-X, palms down, facing
// +Z) and body anchors on its capsule body. Synthesis tests, benchmarks and the native/WASM parity
// case use it so they do not depend on a model file; the product uses models/signweave-avatar.glb.
#pragma once

#include "avatar/avatar.h"

namespace sw::synthesis {

avatar::Avatar make_reference_humanoid();

}  // namespace sw::synthesis

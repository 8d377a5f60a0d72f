// Skin weights: up to four joint influences per vertex, normalised, for linear blend skinning
// (glTF 2.0 §3.7.3.3 JOINTS_0 / WEIGHTS_0).
//
// Method: every deforming joint owns a bone segment (joint -> its chain child). A vertex gets
// candidate joints from the body part it lies on (a finger vertex only sees its own finger's
// phalanges and metacarpal, never the neighbour finger), weights inversely proportional to the
// 4th power of its distance to each candidate segment — which blends over about one limb radius
// around each joint, narrow at the knuckles and wide at the shoulder — then a few rounds of
// smoothing along the mesh edges remove the steps where two parts meet. Finally the four largest
// are kept and renormalised.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "implicit_body.h"

namespace sw::avatar_generator {

struct SkinWeights {
  std::vector<std::array<std::uint16_t, 4>> joints;
  std::vector<glm::vec4> weights;
};

// `jaw_mask(p)` in [0,1] says how much of the lower face at p is carried by the jaw.
SkinWeights compute_skin_weights(const HumanoidLayout& layout, const ImplicitBody& body,
                                 const std::vector<glm::vec3>& positions,
                                 const std::vector<int>& nearest_primitive,
                                 const std::vector<std::uint32_t>& triangles,
                                 float (*jaw_mask)(glm::vec3));

}  // namespace sw::avatar_generator

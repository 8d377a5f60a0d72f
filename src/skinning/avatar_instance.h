// AvatarInstance: one posed copy of a loaded Avatar and the buffers the skinning pipeline writes —
//   pose (local TRS per joint) -> model matrices -> skinning matrices -> morphs -> LBS
// -> skinned positions/normals (packed xyz floats) and anchor world positions.
// The WASM API hands typed-array views of these buffers to the page; they are allocated once in
// the constructor and never reallocated, so views stay valid (until the instance is destroyed).
//
// Does NOT: own the Avatar (it must outlive the instance), sample clips (synthesis does), or
// check joint indices again (the loader validated them).
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "avatar/avatar.h"
#include "math/transform.h"
#include "skinning/morph_job.h"
#include "skinning/skinning_job.h"

namespace sw::skinning {

class AvatarInstance {
 public:
  explicit AvatarInstance(const avatar::Avatar& avatar);

  const avatar::Avatar& avatar() const { return *avatar_; }

  // The pose: one local transform per skeleton joint; starts at (and reset_pose() restores) the
  // skeleton's rest transforms.
  std::vector<math::Transform>& locals() { return locals_; }
  void reset_pose();
  // One weight per avatar morph target, 0 at start.
  std::vector<float>& morph_weights() { return morph_weights_; }

  // Runs the whole pipeline. False (with error()) only if a job rejected its configuration,
  // e.g. a non-finite morph weight.
  bool update(SkinningPath path = SkinningPath::Simd);
  const std::string& error() const { return error_; }

  const std::vector<glm::mat4>& model_matrices() const { return models_; }
  const std::vector<glm::mat4>& skinning_matrices() const { return skinning_; }
  const std::vector<float>& positions() const { return out_positions_; }            // 3 per vertex
  const std::vector<float>& normals() const { return out_normals_; }                // 3 per vertex
  const std::vector<float>& anchor_positions() const { return anchor_positions_; }  // 3 per anchor
  const std::vector<float>& anchor_normals() const { return anchor_normals_; }      // 3 per anchor

 private:
  const avatar::Avatar* avatar_;
  std::vector<math::Transform> locals_;
  std::vector<float> morph_weights_;
  std::vector<VertexRange> morph_ranges_;
  std::vector<glm::mat4> models_;
  std::vector<glm::mat4> skinning_;
  std::vector<glm::vec3> morphed_positions_;
  std::vector<glm::vec3> morphed_normals_;
  std::vector<float> out_positions_;
  std::vector<float> out_normals_;
  std::vector<float> anchor_positions_;
  std::vector<float> anchor_normals_;
  std::string error_;
};

}  // namespace sw::skinning

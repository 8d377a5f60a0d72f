// AvatarInstance: runs the pose -> skinned mesh pipeline. See avatar_instance.h.
#include "skinning/avatar_instance.h"

#include "skeleton/local_to_model.h"
#include "skinning/skinning_matrix_job.h"

namespace sw::skinning {

AvatarInstance::AvatarInstance(const avatar::Avatar& avatar) : avatar_(&avatar) {
  const std::size_t joints = avatar.skeleton.joints.size();
  const std::size_t vertices = avatar.mesh.positions.size();
  locals_.resize(joints);
  reset_pose();
  morph_weights_.assign(avatar.morphs.size(), 0.0f);
  morph_ranges_ = morph_vertex_ranges(avatar.morphs);
  models_.assign(joints, glm::mat4(1.0f));
  skinning_.assign(joints, glm::mat4(1.0f));
  morphed_positions_.resize(vertices);
  morphed_normals_.resize(avatar.mesh.normals.size() == vertices ? vertices : 0);
  out_positions_.assign(3 * vertices, 0.0f);
  out_normals_.assign(3 * morphed_normals_.size(), 0.0f);
  anchor_positions_.assign(3 * avatar.anchors.size(), 0.0f);
  anchor_normals_.assign(3 * avatar.anchors.size(), 0.0f);
}

void AvatarInstance::reset_pose() {
  for (std::size_t i = 0; i < locals_.size(); ++i) locals_[i] = avatar_->skeleton.joints[i].rest;
}

bool AvatarInstance::update(SkinningPath path) {
  const avatar::Avatar& a = *avatar_;
  const int joint_count = a.skeleton.joint_count();
  error_.clear();

  skeleton::LocalToModelJob fk;
  fk.skeleton = &a.skeleton;
  fk.input = locals_;
  fk.output = models_;
  if (!fk.run()) {
    error_ = "forward kinematics rejected the pose";
    return false;
  }

  SkinningMatrixJob palette;
  palette.models = models_.data();
  palette.inverse_binds = a.inverse_bind.data();
  palette.joint_count = static_cast<int>(a.inverse_bind.size()) < joint_count
                            ? static_cast<int>(a.inverse_bind.size())
                            : joint_count;
  palette.skinning_matrices = skinning_.data();
  if (!palette.run()) {
    error_ = palette.validate();
    return false;
  }

  const bool has_normals = !morphed_normals_.empty();
  MorphJob morph;
  morph.vertex_count = static_cast<int>(morphed_positions_.size());
  morph.rest_positions = a.mesh.positions.data();
  morph.rest_normals = has_normals ? a.mesh.normals.data() : nullptr;
  morph.targets = a.morphs.data();
  morph.target_count = static_cast<int>(a.morphs.size());
  morph.ranges = morph_ranges_.data();
  morph.weights = morph_weights_.data();
  morph.out_positions = morphed_positions_.data();
  morph.out_normals = has_normals ? morphed_normals_.data() : nullptr;
  if (!morph.run()) {
    error_ = morph.validate();
    return false;
  }

  SkinningJob skin;
  skin.vertex_count = static_cast<int>(morphed_positions_.size());
  skin.skinning_matrices = skinning_.data();
  skin.joint_count = joint_count;
  skin.in_positions = morphed_positions_.data();
  skin.in_normals = has_normals ? morphed_normals_.data() : nullptr;
  skin.joints = a.mesh.joints.data();
  skin.weights = a.mesh.weights.data();
  skin.out_positions = out_positions_.data();
  skin.out_normals = has_normals ? out_normals_.data() : nullptr;
  skin.path = path;
  if (!skin.run()) {
    error_ = skin.validate();
    return false;
  }

  // Anchors ride their joint: the offset is in the joint's bind space (avatar.h), so the point
  // moves exactly like a vertex weighted fully to that joint.
  for (std::size_t i = 0; i < a.anchors.size(); ++i) {
    const avatar::Anchor& anchor = a.anchors[i];
    glm::vec3 p = anchor.offset, n = anchor.normal;
    if (anchor.joint >= 0 && anchor.joint < joint_count) {
      const glm::mat4& m = models_[static_cast<std::size_t>(anchor.joint)];
      p = glm::vec3(m * glm::vec4(anchor.offset, 1.0f));
      n = glm::vec3(m * glm::vec4(anchor.normal, 0.0f));
      const float len = glm::length(n);
      if (len > 0.0f) n /= len;
    }
    for (int k = 0; k < 3; ++k) {
      anchor_positions_[3 * i + static_cast<std::size_t>(k)] = p[k];
      anchor_normals_[3 * i + static_cast<std::size_t>(k)] = n[k];
    }
  }
  return true;
}

}  // namespace sw::skinning

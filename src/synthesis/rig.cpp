// Rig: bind-pose measurements of a humanoid and the delta-rotation pose builder (see rig.h).
#include "synthesis/rig.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "math/quat_lanes.h"
#include "skeleton/humanoid_names.h"

namespace sw::synthesis {

glm::quat axis_angle(const glm::vec3& unit_axis, float angle_rad) {
  float h = 0.5f * angle_rad;
  float s = std::sin(h);
  return glm::quat(std::cos(h), unit_axis.x * s, unit_axis.y * s, unit_axis.z * s);
}

glm::mat3 orthonormal_frame(const glm::vec3& a, const glm::vec3& b) {
  glm::vec3 x = safe_normalize(a, glm::vec3(1, 0, 0));
  glm::vec3 y = reject(b, x);
  float len = glm::length(y);
  if (len > 1e-6f) {
    y /= len;
  } else {
    // b along a: any perpendicular will do (worked out only then: the solvers call this per
    // swivel candidate and per iteration).
    glm::vec3 helper = std::fabs(x.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    y = safe_normalize(reject(helper, x), glm::vec3(0, 0, 1));
  }
  return glm::mat3(x, y, glm::cross(x, y));
}

glm::quat frame_to_frame(const glm::mat3& frame0, const glm::vec3& a1, const glm::vec3& b1) {
  return glm::normalize(glm::quat_cast(orthonormal_frame(a1, b1) * glm::transpose(frame0)));
}

glm::quat frame_to_frame(const glm::vec3& a0, const glm::vec3& b0, const glm::vec3& a1,
                         const glm::vec3& b1) {
  return frame_to_frame(orthonormal_frame(a0, b0), a1, b1);
}

glm::quat slerp_shortest(const glm::quat& a, const glm::quat& b_in, float t) {
  glm::quat b = b_in;
  float d = glm::dot(a, b);
  if (d < 0.0f) {
    b = -b;
    d = -d;
  }
  if (d > 0.9995f) return glm::normalize(a + t * (b - a));  // nearly equal: nlerp is exact enough
  float theta = std::acos(std::min(d, 1.0f));
  float s = std::sin(theta);
  float wa = std::sin((1.0f - t) * theta) / s, wb = std::sin(t * theta) / s;
  return glm::normalize(wa * a + wb * b);
}

float rotation_angle(const glm::quat& q) {
  // atan2 keeps full precision near zero, where 2 acos(w) has a 7e-4 rad floor in float.
  return 2.0f * std::atan2(glm::length(glm::vec3(q.x, q.y, q.z)), std::fabs(q.w));
}

int find_canonical_joint(const avatar::Avatar& avatar, const std::string& canonical_name) {
  // The loader maps the rig's own names (Mixamo, VRM 0.x, ...) onto canonical ids in
  // canonical_to_joint; an avatar built in code without that map is read through the same alias
  // tables (skeleton/humanoid_names.h).
  int id = skeleton::canonical_joint_id(canonical_name);
  if (id < 0) return -1;
  if (avatar.canonical_to_joint.size() == static_cast<size_t>(skeleton::kHumanoidJointCount)) {
    int j = avatar.canonical_to_joint[static_cast<size_t>(id)];
    return j >= 0 && j < avatar.skeleton.joint_count() ? j : -1;
  }
  const auto& joints = avatar.skeleton.joints;
  for (int i = 0; i < static_cast<int>(joints.size()); ++i)
    if (skeleton::canonical_joint_id(joints[i].name) == id) return i;
  return -1;
}

glm::vec3 Rig::bind_tip(Side side, int finger) const {
  const FingerChain& c = arms[side].fingers[finger];
  if (c.tip >= 0) return bind_pos[c.tip];
  glm::vec3 d = bind_pos[c.bones[2]] - bind_pos[c.bones[1]];
  return bind_pos[c.bones[2]] + 0.8f * d;  // a distal phalanx is ~80% of the middle one
}

namespace {
const char* kFingerNames[5] = {"Thumb", "Index", "Middle", "Ring", "Little"};
}

bool build_rig(const avatar::Avatar& avatar, Rig* rig, std::string* error) {
  const auto& joints = avatar.skeleton.joints;
  const int n = static_cast<int>(joints.size());
  if (n == 0) {
    *error = "the avatar has no skeleton";
    return false;
  }
  Rig r;
  r.joint_count = n;
  r.parent.resize(n);
  r.bind_pos.resize(n);
  r.bind_rot.resize(n);
  r.bind_local_rot.resize(n);
  r.names.resize(n);
  std::vector<glm::mat4> model(n);
  for (int i = 0; i < n; ++i) {
    const auto& j = joints[i];
    if (j.parent >= i) {
      *error = "joint '" + j.name + "' comes before its parent (skeleton order)";
      return false;
    }
    r.parent[i] = j.parent;
    r.names[i] = j.name;
    r.bind_local_rot[i] = j.rest.rotation;
    glm::mat4 local = glm::translate(glm::mat4(1.0f), j.rest.translation) *
                      glm::mat4_cast(j.rest.rotation) * glm::scale(glm::mat4(1.0f), j.rest.scale);
    model[i] = j.parent < 0 ? local : model[j.parent] * local;
    r.bind_pos[i] = glm::vec3(model[i][3]);
    glm::mat3 m(model[i]);
    m[0] = glm::normalize(m[0]);
    m[1] = glm::normalize(m[1]);
    m[2] = glm::normalize(m[2]);
    r.bind_rot[i] = glm::normalize(glm::quat_cast(m));
  }
  r.root_translation = joints[0].rest.translation;

  auto need = [&](const std::string& name, int* out) {
    *out = find_canonical_joint(avatar, name);
    if (*out < 0) {
      *error = "the avatar has no '" + name + "' joint (canonical humanoid name)";
      return false;
    }
    return true;
  };
  if (!need("hips", &r.hips) || !need("spine", &r.spine) || !need("neck", &r.neck) ||
      !need("head", &r.head))
    return false;
  r.chest = find_canonical_joint(avatar, "chest");
  r.upper_chest = find_canonical_joint(avatar, "upperChest");

  for (int s = 0; s < 2; ++s) {
    std::string p = s == kLeft ? "left" : "right";
    ArmRig& a = r.arms[s];
    if (!need(p + "UpperArm", &a.upper) || !need(p + "LowerArm", &a.lower) ||
        !need(p + "Hand", &a.hand))
      return false;
    a.shoulder = find_canonical_joint(avatar, p + "Shoulder");
    for (int f = 0; f < 5; ++f) {
      std::string fn = p + kFingerNames[f];
      const char* parts[3] = {"Proximal", "Intermediate", "Distal"};
      const char* thumb_parts[3] = {"Metacarpal", "Proximal", "Distal"};
      for (int b = 0; b < 3; ++b)
        if (!need(fn + (f == 0 ? thumb_parts[b] : parts[b]), &a.fingers[f].bones[b])) return false;
      a.fingers[f].tip = find_canonical_joint(avatar, fn + "Tip");
    }
    a.upper_len_m = glm::length(r.bind_pos[a.lower] - r.bind_pos[a.upper]);
    a.lower_len_m = glm::length(r.bind_pos[a.hand] - r.bind_pos[a.lower]);
  }

  // Body frame measured on the skeleton: up from hips to head, left from the right shoulder to the
  // left one (+X on the project's avatar), forward = left x up (glTF: faces +Z).
  r.up = safe_normalize(r.bind_pos[r.head] - r.bind_pos[r.hips], glm::vec3(0, 1, 0));
  glm::vec3 across = r.bind_pos[r.arms[kLeft].upper] - r.bind_pos[r.arms[kRight].upper];
  r.shoulder_width_m = glm::length(across);
  r.left = safe_normalize(reject(across, r.up), glm::vec3(1, 0, 0));
  r.forward = glm::cross(r.left, r.up);

  for (int s = 0; s < 2; ++s) {
    ArmRig& a = r.arms[s];
    glm::vec3 wrist = r.bind_pos[a.hand];
    glm::vec3 idx = r.bind_pos[a.fingers[1].bones[0]], mid = r.bind_pos[a.fingers[2].bones[0]];
    glm::vec3 rng = r.bind_pos[a.fingers[3].bones[0]], lit = r.bind_pos[a.fingers[4].bones[0]];
    glm::vec3 knuckles = 0.25f * (idx + mid + rng + lit);
    a.finger_dir = safe_normalize(knuckles - wrist, glm::vec3(s == kLeft ? 1.0f : -1.0f, 0, 0));
    a.radial = safe_normalize(reject(idx - lit, a.finger_dir), r.forward);
    // Chirality of the hand: for a left hand palm = finger x radial, for a right hand the
    // opposite (a right hand is the mirror image of a left one).
    glm::vec3 c = glm::cross(a.finger_dir, a.radial);
    a.palm_normal = glm::normalize(s == kLeft ? c : -c);
    a.palm_length_m = glm::length(mid - wrist);
    a.palm_width_m = glm::length(idx - lit);
    a.finger_radius_m = std::max(0.004f, 0.15f * a.palm_width_m);
  }
  r.refresh_bind_cache();
  *rig = std::move(r);
  return true;
}

void Rig::refresh_bind_cache() {
  using namespace math::lanes;
  const size_t n = static_cast<size_t>(joint_count);
  bind_offset.assign(n, glm::vec4(0.0f));
  bind_rot_conj.resize(n);
  for (size_t j = 0; j < n; ++j) {
    const int p = parent[j];
    if (p >= 0) {
      // load3's lanes: x, y, z of the difference, w 0.
      const glm::vec3 d = bind_pos[j] - bind_pos[static_cast<size_t>(p)];
      bind_offset[j] = glm::vec4(d, 0.0f);
    }
    store4(&bind_rot_conj[j], quat_conjugate(load4(bind_rot[j])));
  }
}

PoseBuilder::PoseBuilder(const Rig& r)
    : rig(&r), delta_(r.joint_count, glm::quat(1, 0, 0, 0)), is_set_(r.joint_count, 0),
      pos_(r.joint_count) {}

void PoseBuilder::set(int joint, const glm::quat& d) {
  if (joint < 0) return;
  delta_[joint] = d;
  is_set_[joint] = 1;
  last_local_valid_ = false;
}

void PoseBuilder::finalize() {
  const Rig& r = *rig;
  last_local_valid_ = false;
  for (int j = 0; j < r.joint_count; ++j) {
    int p = r.parent[j];
    if (p < 0) {
      pos_[j] = r.bind_pos[j];
      continue;
    }
    if (!is_set_[j]) delta_[j] = delta_[p];
    // pos[p] + delta[p] * (bind offset), glm's arithmetic in lanes (set_from_local's).
    using namespace math::lanes;
    const Float4 moved = load3(pos_[p]) + quat_rotate(load4(delta_[p]), load4(r.bind_offset[j]));
    pos_[j] = glm::vec3(moved[0], moved[1], moved[2]);
  }
}

void PoseBuilder::set_from_local(const glm::quat* local) {
  const Rig& r = *rig;
  const int n = r.joint_count;
  std::vector<glm::quat>& model = scratch_;
  model.resize(n);
  last_local_.resize(n);
  recomputed_.resize(n);
  const bool incremental = last_local_valid_;
  for (int j = 0; j < n; ++j) {
    int p = r.parent[j];
    // Same local rotation (bitwise: -0 vs +0 or NaNs count as changed) under an unchanged parent:
    // model rotation, delta and position are what the previous call left.
    if (incremental && (p < 0 || !recomputed_[p]) &&
        math::lanes::same_bits(local[j], last_local_[j])) {
      recomputed_[j] = 0;
      continue;
    }
    recomputed_[j] = 1;
    last_local_[j] = local[j];
    // model = model[p] * local; delta = normalize(model * conjugate(bind)); pos = pos[p] +
    // delta[p] * (bind offset): glm's arithmetic, four lanes at a time (quat_mul above).
    using namespace math::lanes;
    const Float4 m = p < 0 ? load4(local[j]) : quat_mul(load4(model[p]), load4(local[j]));
    store4(&model[j], m);
    const Float4 d = quat_normalize(quat_mul(m, load4(r.bind_rot_conj[j])));
    store4(&delta_[j], d);
    is_set_[j] = 1;
    if (p < 0) {
      pos_[j] = r.bind_pos[j];
    } else {
      const Float4 moved = load3(pos_[p]) + quat_rotate(load4(delta_[p]), load4(r.bind_offset[j]));
      pos_[j] = glm::vec3(moved[0], moved[1], moved[2]);
    }
  }
  last_local_valid_ = true;
}

glm::vec3 PoseBuilder::tip(Side side, int finger) const {
  const FingerChain& c = rig->arms[side].fingers[finger];
  if (c.tip >= 0) return pos_[c.tip];
  return attached(c.bones[2], rig->bind_tip(side, finger));
}

glm::quat PoseBuilder::local_rotation(int j) const {
  const Rig& r = *rig;
  int p = r.parent[j];
  glm::quat dp = p < 0 ? glm::quat(1, 0, 0, 0) : delta_[p];
  // local_rotations' formula for one joint
  glm::quat rel = glm::conjugate(r.bind_rot[j]) * glm::conjugate(dp) * delta_[j] * r.bind_rot[j];
  return glm::normalize(r.bind_local_rot[j] * rel);
}

void PoseBuilder::local_rotations(glm::quat* out) const {
  const Rig& r = *rig;
  using namespace math::lanes;
  for (int j = 0; j < r.joint_count; ++j) {
    int p = r.parent[j];
    glm::quat dp = p < 0 ? glm::quat(1, 0, 0, 0) : delta_[p];
    // local = L_j * R_j^-1 * D_p^-1 * D_j * R_j  (rig.h: posed model rotation = D_j * R_j), the
    // products in glm's order and arithmetic, four lanes at a time (math/quat_lanes.h): the sign
    // motion converts every solved frame, and glm's scalar products were a tenth of its time.
    const Float4 bind = load4(r.bind_rot[j]);
    const Float4 rel =
        quat_mul(quat_mul(quat_mul(load4(r.bind_rot_conj[j]), quat_conjugate(load4(dp))), load4(delta_[j])), bind);
    store4(&out[j], quat_normalize(quat_mul(load4(r.bind_local_rot[j]), rel)));
  }
}

}  // namespace sw::synthesis

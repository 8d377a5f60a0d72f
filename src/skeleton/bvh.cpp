// Bvh data helpers and the conversions between BVH channel values and local Transforms (bvh.h).
#include "skeleton/bvh.h"

#include <cmath>

namespace sw::skeleton {
namespace {

constexpr double kDegreesPerRadian = 57.29577951308232;

bool is_rotation(BvhChannel c) { return static_cast<int>(c) >= 3; }
int axis_of(BvhChannel c) { return static_cast<int>(c) % 3; }

}  // namespace

const char* bvh_channel_name(BvhChannel channel) {
  switch (channel) {
    case BvhChannel::Xposition:
      return "Xposition";
    case BvhChannel::Yposition:
      return "Yposition";
    case BvhChannel::Zposition:
      return "Zposition";
    case BvhChannel::Xrotation:
      return "Xrotation";
    case BvhChannel::Yrotation:
      return "Yrotation";
    case BvhChannel::Zrotation:
      return "Zrotation";
  }
  return "Xrotation";
}

math::EulerOrder BvhJoint::rotation_order() const {
  int axes[3] = {0, 1, 2};
  int n = 0;
  for (BvhChannel c : channels) {
    if (is_rotation(c) && n < 3) axes[n++] = axis_of(c);
  }
  if (n != 3) return math::EulerOrder::XYZ;
  return math::euler_order_from_axes(axes[0], axes[1], axes[2]).value_or(math::EulerOrder::XYZ);
}

bool BvhJoint::has_position() const {
  for (BvhChannel c : channels) {
    if (!is_rotation(c)) return true;
  }
  return false;
}

int Bvh::channel_count() const {
  int n = 0;
  for (const BvhJoint& j : joints) n += static_cast<int>(j.channels.size());
  return n;
}

int Bvh::channel_offset(int joint) const {
  int n = 0;
  for (int i = 0; i < joint && i < static_cast<int>(joints.size()); ++i) {
    n += static_cast<int>(joints[static_cast<std::size_t>(i)].channels.size());
  }
  return n;
}

int Bvh::find(std::string_view name) const {
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::string BvhError::format() const { return "line " + std::to_string(line) + ": " + message; }

Skeleton to_skeleton(const Bvh& bvh, double scale_to_m, bool include_end_sites) {
  Skeleton s;
  s.joints.reserve(bvh.joints.size());
  for (const BvhJoint& j : bvh.joints) {
    Joint joint;
    joint.name = j.name;
    joint.parent = j.parent;
    joint.rest.translation = glm::vec3(j.offset * scale_to_m);
    s.joints.push_back(joint);
  }
  if (include_end_sites) {
    for (std::size_t i = 0; i < bvh.joints.size(); ++i) {
      const BvhJoint& j = bvh.joints[i];
      if (!j.has_end_site) continue;
      Joint tip;
      tip.name = j.name + "_end";
      tip.parent = static_cast<int>(i);
      tip.rest.translation = glm::vec3(j.end_site_offset * scale_to_m);
      s.joints.push_back(tip);
    }
  }
  return s;
}

bool frame_to_local(const Bvh& bvh, int frame, double scale_to_m, math::Span<math::Transform> out) {
  if (frame < 0 || frame >= bvh.frame_count || out.size < bvh.joints.size()) return false;
  const double* values = bvh.frame(frame);
  int channel = 0;
  for (std::size_t i = 0; i < bvh.joints.size(); ++i) {
    const BvhJoint& j = bvh.joints[i];
    glm::dvec3 position = j.offset;
    glm::dvec3 angles_rad(0.0);
    for (BvhChannel c : j.channels) {
      const double v = values[channel++];
      if (is_rotation(c)) {
        angles_rad[axis_of(c)] = v / kDegreesPerRadian;
      } else {
        position[axis_of(c)] = v;
      }
    }
    math::Transform& t = out[i];
    t.translation = glm::vec3(position * scale_to_m);
    t.rotation = glm::quat(math::quat_from_euler(angles_rad, j.rotation_order()));
    t.scale = glm::vec3(1.0f);
  }
  return true;
}

bool local_to_frame(math::Span<const math::Transform> local, double scale_to_m, Bvh& bvh,
                    int frame) {
  if (frame < 0 || frame >= bvh.frame_count || local.size < bvh.joints.size() ||
      !(scale_to_m != 0.0))
    return false;
  if (bvh.values.size() < std::size_t(bvh.frame_count) * std::size_t(bvh.channel_count()))
    return false;
  double* values = bvh.frame(frame);
  int channel = 0;
  for (std::size_t i = 0; i < bvh.joints.size(); ++i) {
    const BvhJoint& j = bvh.joints[i];
    const glm::dvec3 position = glm::dvec3(local[i].translation) / scale_to_m;
    // Continuity with the previous frame: BVH players interpolate angles, so a joint turning past
    // 180° (or through the middle axis' 90°) must not jump to the other equivalent angle set.
    glm::dvec3 previous_rad(0.0);
    if (frame > 0) {
      const double* before = bvh.frame(frame - 1) + (channel);
      for (std::size_t c = 0; c < j.channels.size(); ++c) {
        if (is_rotation(j.channels[c]))
          previous_rad[axis_of(j.channels[c])] = before[c] / kDegreesPerRadian;
      }
    }
    const glm::dvec3 angles_rad =
        math::euler_from_quat_near(glm::dquat(local[i].rotation), j.rotation_order(), previous_rad);
    for (BvhChannel c : j.channels) {
      values[channel++] =
          is_rotation(c) ? angles_rad[axis_of(c)] * kDegreesPerRadian : position[axis_of(c)];
    }
  }
  return true;
}

}  // namespace sw::skeleton

// Hand parts: posed points of hand and arm places, and posed avatar anchors.
#include "synthesis/hand_parts.h"

#include "synthesis/handshape.h"

namespace sw::synthesis {

using notation::HandPlace;

PartPoint hand_part(const PoseBuilder& pose, Side side, HandPlace place, int finger) {
  const Rig& rig = *pose.rig;
  const ArmRig& a = rig.arms[side];
  if (finger < 0 || finger > 4) finger = 1;
  const glm::quat& hd = pose.delta(a.hand);
  glm::vec3 n = hd * a.palm_normal, radial = hd * a.radial;
  const float r = a.finger_radius_m;
  const float half_thick = 0.17f * a.palm_width_m;
  glm::vec3 palm = pose.attached(a.hand, bind_palm_centre(rig, side));
  const FingerChain& c = a.fingers[finger];
  glm::vec3 distal = pose.position(c.bones[2]), tip = pose.tip(side, finger);
  const glm::quat& dd = pose.delta(c.bones[2]);
  glm::vec3 pad_n = dd * a.palm_normal;
  glm::vec3 mid_distal = 0.5f * (distal + tip);
  glm::vec3 forearm_axis = pose.position(a.hand) - pose.position(a.lower);
  glm::vec3 fn = pose.delta(a.lower) * a.palm_normal;  // palm side of the forearm
  float forearm_r = 0.10f * rig.shoulder_width_m;
  switch (place) {
    case HandPlace::Palm: return {palm, n};
    case HandPlace::BackOfHand: return {palm - 2.0f * half_thick * n, -n};
    case HandPlace::ThumbSide: return {palm - half_thick * n + 0.5f * a.palm_width_m * radial, radial};
    case HandPlace::LittleSide: return {palm - half_thick * n - 0.5f * a.palm_width_m * radial, -radial};
    case HandPlace::Fingertip: return {tip, safe_normalize(tip - distal, n)};
    case HandPlace::FingerPad: return {mid_distal + r * pad_n, pad_n};
    case HandPlace::FingerNail: return {mid_distal - r * pad_n, -pad_n};
    case HandPlace::FingerBase: return {pose.position(c.bones[0]) + r * (pose.delta(c.bones[0]) * a.palm_normal), n};
    case HandPlace::FingerMiddleJoint: return {pose.position(c.bones[1]) - r * (pose.delta(c.bones[1]) * a.palm_normal), -n};
    case HandPlace::FingerSide: {
      glm::vec3 s = finger <= 2 ? radial : -radial;
      return {mid_distal + r * s, s};
    }
    case HandPlace::Wrist: return {pose.position(a.hand) + forearm_r * fn, fn};
    case HandPlace::WristBack: return {pose.position(a.hand) - forearm_r * fn, -fn};
    case HandPlace::Forearm: return {pose.position(a.lower) + 0.5f * forearm_axis + forearm_r * fn, fn};
    case HandPlace::ForearmBack: return {pose.position(a.lower) + 0.5f * forearm_axis - forearm_r * fn, -fn};
    case HandPlace::Elbow: {
      glm::vec3 back = safe_normalize(reject(pose.position(a.upper) - pose.position(a.lower),
                                             safe_normalize(forearm_axis, rig.up)), -rig.forward);
      glm::vec3 outward = -safe_normalize(back + safe_normalize(forearm_axis, rig.up), rig.up);
      return {pose.position(a.lower) + forearm_r * outward, outward};
    }
    case HandPlace::ThumbBall: {  // the thenar eminence: palm side of the thumb's metacarpal
      glm::vec3 base = pose.position(a.fingers[0].bones[0]);
      glm::vec3 mid = 0.5f * (base + pose.position(a.fingers[0].bones[1]));
      return {mid + half_thick * n, n};
    }
    case HandPlace::ElbowInside: {  // the crook of the elbow, on the flexion side
      glm::vec3 inside = safe_normalize(reject(fn, safe_normalize(forearm_axis, rig.up)), rig.forward);
      return {pose.position(a.lower) + forearm_r * inside, inside};
    }
    case HandPlace::UpperArm: {
      glm::vec3 out = side == kLeft ? rig.left : -rig.left;
      glm::vec3 mid = 0.5f * (pose.position(a.upper) + pose.position(a.lower));
      return {mid + 1.3f * forearm_r * out, out};
    }
  }
  return {palm, n};
}

std::string hand_part_anchor_name(Side side, HandPlace place, int finger) {
  static const char* kFinger[5] = {"thumb", "index", "middle", "ring", "little"};
  std::string s = side == kLeft ? "left" : "right";
  const char* f = kFinger[finger < 0 || finger > 4 ? 1 : finger];
  switch (place) {
    case HandPlace::Palm: return "hand/" + s + "/palm";
    case HandPlace::BackOfHand: return "hand/" + s + "/back";
    case HandPlace::ThumbSide: return "hand/" + s + "/thumb_side";
    case HandPlace::LittleSide: return "hand/" + s + "/little_side";
    case HandPlace::Wrist: return "hand/" + s + "/wrist";
    case HandPlace::WristBack: return "hand/" + s + "/wrist_back";
    case HandPlace::Fingertip: return "hand/" + s + "/tip/" + f;
    case HandPlace::FingerPad: return "hand/" + s + "/pad/" + f;
    case HandPlace::FingerNail: return "hand/" + s + "/nail/" + f;
    case HandPlace::FingerBase: return "hand/" + s + "/base/" + f;
    case HandPlace::FingerMiddleJoint: return "hand/" + s + "/middle_joint/" + f;
    case HandPlace::FingerSide: return "hand/" + s + "/side/" + f;
    case HandPlace::Forearm: return "arm/" + s + "/forearm";
    case HandPlace::ForearmBack: return "arm/" + s + "/forearm_back";
    case HandPlace::Elbow: return "arm/" + s + "/elbow";
    case HandPlace::UpperArm: return "arm/" + s + "/upper_arm";
    case HandPlace::ThumbBall: return "hand/" + s + "/thumb_ball";
    case HandPlace::ElbowInside: return "arm/" + s + "/elbow_inside";
  }
  return "hand/" + s + "/palm";
}

bool anchor_point(const avatar::Avatar& avatar, const PoseBuilder& pose, const std::string& name,
                  PartPoint* out) {
  for (const auto& a : avatar.anchors) {
    if (a.name != name || a.joint < 0 || a.joint >= pose.rig->joint_count) continue;
    // Anchor offsets are in the joint's bind space (avatar/body_anchors.h): rotate them by the
    // joint's bind rotation into model space, then by the pose's delta.
    const glm::quat& bind_rot = pose.rig->bind_rot[a.joint];
    glm::vec3 bind = pose.rig->bind_pos[a.joint] + bind_rot * a.offset;
    out->point = pose.attached(a.joint, bind);
    out->normal = pose.delta(a.joint) * (bind_rot * a.normal);
    return true;
  }
  return false;
}

}  // namespace sw::synthesis

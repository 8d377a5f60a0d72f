#include "synthesis/elbow_path.h"

#include <algorithm>
#include <cmath>

#include "synthesis/subset_pose.h"

namespace sw::synthesis {

namespace {

constexpr float kPi = 3.14159265358979f;
// A swing of the elbow about the shoulder-wrist line (the part of its step the wrist's and the
// shoulder's motion do not explain) faster than this starts the continued path. The lexicon's
// largest step of an elbow, swing and carry together, is 68 mm at 30 fps (2.0 m/s).
constexpr float kSwingTriggerMPerS = 2.4f;
// The continued swing's speed and acceleration along the elbow's circle: within the smoothness
// tests' bounds (100 mm a frame, a change of step of 56 mm at 30 fps) with room for the wrist's
// own motion in the same frames.
constexpr float kSwingMaxMPerS = 1.8f;
constexpr float kSwingMaxAccelMPerS2 = 22.5f;
// An arm this close to straight has no circle to swing the elbow round.
constexpr float kMinRadiusM = 0.02f;
// The smoothness tests' bounds (100 mm a frame, a change of step of 56 mm, at 30 fps).
constexpr float kStepBoundMPerS = 3.0f;
constexpr float kChangeBoundMPerS2 = 50.4f;
// The way round is judged at this many points, and the longer taken only when it is this much
// shallower.
constexpr int kRouteSamples = 8;
constexpr float kRouteMarginM = 0.01f;
// A continued path is kept only when the arm stays within this of the clip's own deepest, or
// within the 5 mm rule's 4 mm where the clip was shallower.
constexpr float kFreeDepthM = 0.004f;
constexpr float kDeeperToleranceM = 0.001f;
// ... and bends the wrist at most this much further than the clip's own largest bend.
constexpr float kWristBendToleranceRad = 0.05f;
// Bisection steps for the hand's weight towards its own rotation (2^-12 of the slerp).
constexpr int kBendSearchSteps = 12;

float wrap_angle(float a) {  // to [-pi, pi)
  return a - 2.0f * kPi * std::floor((a + kPi) / (2.0f * kPi));
}

// The angle about `axis` (right-handed, in (-pi, pi]) that turns `from` onto `to`, both square to
// the axis: how far an elbow swung round the shoulder-wrist line between two frames.
float turn_about(const glm::vec3& from, const glm::vec3& to, const glm::vec3& axis) {
  return std::atan2(glm::dot(glm::cross(from, to), axis), glm::dot(from, to));
}

// One arm's continued path: the elbow held from the previous frame and the swing still to go.
struct ArmPath {
  bool has_previous = false;
  glm::vec3 previous_elbow{0.0f};
  bool active = false;
  // The rotation about the shoulder-wrist line still to go to the frame's own elbow, and the last
  // frame's swing.
  float remaining_rad = 0.0f;
  float rate_rad = 0.0f;
};

// How far a hand's local rotation is bent from its bind (rig.h local_rotations: the same angle as
// the hand's turn against the forearm), radians.
float wrist_bend(const Rig& rig, int hand, const glm::quat& local) {
  const glm::quat rel = glm::conjugate(rig.bind_local_rot[hand]) * local;
  return 2.0f * std::acos(std::min(1.0f, std::fabs(rel.w)));
}

// The largest bend of `side`'s wrist over the clip: the angle of the hand's local rotation from
// its bind (rig.h local_rotations: the same angle as the hand's turn against the forearm). The
// swing keeps the hand's orientation in space, so the wrist takes the forearm's turn back; an
// elbow carried half round its circle that way bent the wrist 2.8-3.1 rad (HEARING-AID1^, gołąb,
// kelner; the clips' own wrists at most 1.43 rad), far past the wrist's limits (arm_ik.h).
float largest_wrist_bend(const Rig& rig, Side side, int frame_count,
                         const std::vector<glm::quat>& rotations) {
  const int hand = rig.arms[side].hand;
  float largest = 0.0f;
  for (int f = 0; f < frame_count; ++f) {
    largest = std::max(
        largest, wrist_bend(rig, hand, rotations[static_cast<size_t>(f) * rig.joint_count + hand]));
  }
  return largest;
}

// The upper arm and forearm turned by `turn` (model space) about the line through the shoulder
// joint and the wrist, `posed` the frame as it was: the wrist on the line stays. The hand keeps
// its rotation in space (its local rotation takes the turn back; rig.h local_rotations' formula,
// local = L_j * R_j^-1 * D_parent^-1 * D_j * R_j, with the upper arm's and the forearm's deltas
// turned) as far as the wrist can follow: where that would bend the wrist past `max_bend_rad`,
// the hand's local rotation is slerped towards the frame's own (legal) one by the least that
// keeps the bend within it, and the hand turns with the forearm for the rest. The joints between
// them keep their local rotations.
void turn_arm(const Rig& rig, const ArmRig& arm, const glm::quat& turn, const PoseBuilder& posed,
              float max_bend_rad, glm::quat* local) {
  const int up = arm.upper, hand = arm.hand, forearm = rig.parent[hand];
  const glm::quat du = posed.delta(up), dpu = posed.delta(rig.parent[up]);
  local[up] = glm::normalize(rig.bind_local_rot[up] * glm::conjugate(rig.bind_rot[up]) *
                             glm::conjugate(dpu) * turn * du * rig.bind_rot[up]);
  const glm::quat dh = posed.delta(hand), dpf = turn * posed.delta(forearm);
  const glm::quat own = local[hand];
  const glm::quat kept =
      glm::normalize(rig.bind_local_rot[hand] * glm::conjugate(rig.bind_rot[hand]) *
                     glm::conjugate(dpf) * dh * rig.bind_rot[hand]);
  if (wrist_bend(rig, hand, kept) <= max_bend_rad) {
    local[hand] = kept;
    return;
  }
  // The least weight towards the frame's own rotation that keeps the bend within the bound
  // (the own rotation is within it: weight 1 always does).
  float lo = 0.0f, hi = 1.0f;
  for (int i = 0; i < kBendSearchSteps; ++i) {
    const float mid = 0.5f * (lo + hi);
    if (wrist_bend(rig, hand, slerp_shortest(kept, own, mid)) <= max_bend_rad)
      hi = mid;
    else
      lo = mid;
  }
  local[hand] = glm::normalize(slerp_shortest(kept, own, hi));
}

// How far `side`'s elbow is from the smoothness bounds over the clip: the larger of its largest
// per-frame step against 3 m/s and its largest change of step against 50 m/s^2 (the smoothness
// tests' 100 mm and 56 mm at 30 fps), 1 on a bound.
float elbow_roughness(const Rig& rig, Side side, float fps, int frame_count,
                      const std::vector<glm::quat>& rotations, float* largest_step_m = nullptr) {
  SubsetPose pb(rig, {rig.arms[side].lower});  // the elbow's position only
  float step = 0.0f, change = 0.0f;
  glm::vec3 previous{0.0f}, previous_step{0.0f};
  for (int f = 0; f < frame_count; ++f) {
    pb.set_from_local(&rotations[static_cast<size_t>(f) * rig.joint_count]);
    const glm::vec3 elbow = pb.position(rig.arms[side].lower);
    if (f > 0) {
      const glm::vec3 d = elbow - previous;
      step = std::max(step, glm::length(d));
      if (f > 1) change = std::max(change, glm::length(d - previous_step));
      previous_step = d;
    }
    previous = elbow;
  }
  if (largest_step_m) *largest_step_m = step;
  return std::max(step * fps / kStepBoundMPerS, change * fps * fps / kChangeBoundMPerS2);
}

// The deepest the arm goes into the trunk (its bind pose) on the elbow's way from `from` round
// the shoulder-wrist line by `angle`, the wrist held.
float route_depth(const BodyModel& body, Side s, const glm::vec3& shoulder, const glm::vec3& from,
                  const glm::vec3& wrist, const glm::vec3& axis, float angle) {
  float deepest = 0.0f;
  for (int k = 1; k <= kRouteSamples; ++k) {
    const glm::quat turn = glm::angleAxis(angle * static_cast<float>(k) / kRouteSamples, axis);
    ArmSegments arm;
    arm.shoulder = shoulder;
    arm.elbow = shoulder + turn * (from - shoulder);
    arm.wrist = wrist;
    deepest = std::max(deepest, arm_trunk_depth(body, s, arm, true));
  }
  return deepest;
}

// One arm's pass over the frames, forward (after a swing the elbow catches up with the frames)
// or backward (before it, the elbow sets off early). False when the clip ends before the elbow
// has caught up (the frames are then left as they were).
bool continue_arm_path(const Rig& rig, const BodyModel* body, Side s, float fps, int frame_count,
                       bool backward, float max_bend_rad, std::vector<glm::quat>* rotations,
                       int* changed) {
  const int J = rig.joint_count;
  const float trigger_m = kSwingTriggerMPerS / fps;
  const float max_step_m = kSwingMaxMPerS / fps;
  const float max_change_m = kSwingMaxAccelMPerS2 / (fps * fps);
  const ArmRig& arm = rig.arms[s];
  std::vector<glm::quat> out(*rotations);
  PoseBuilder pb(rig);
  ArmPath p;
  int count = 0;
  for (int k = 0; k < frame_count; ++k) {
    const int f = backward ? frame_count - 1 - k : k;
    glm::quat* local = &out[static_cast<size_t>(f) * J];
    pb.set_from_local(&(*rotations)[static_cast<size_t>(f) * J]);
    const glm::vec3 shoulder = pb.position(arm.upper), elbow = pb.position(arm.lower);
    const glm::vec3 wrist = pb.position(arm.hand);
    const glm::vec3 line = wrist - shoulder;
    const float length = glm::length(line);
    const glm::vec3 from_line =
        length > 1e-4f ? reject(elbow - shoulder, line / length) : glm::vec3(0.0f);
    const float radius = glm::length(from_line);
    if (!p.has_previous || radius < kMinRadiusM) {
      if (p.active) return false;
      p = ArmPath{};
      p.has_previous = true;
      p.previous_elbow = elbow;
      continue;
    }
    const glm::vec3 axis = line / length;
    // The swing from where the previous frame left the elbow to the frame's own, about the line.
    const glm::vec3 held = reject(p.previous_elbow - shoulder, axis);
    const glm::vec3 own = from_line / radius;
    float to_own = glm::length(held) > 1e-6f ? turn_about(held, own, axis) : 0.0f;
    if (!p.active) {
      if (radius * std::fabs(to_own) <= trigger_m) {
        p.previous_elbow = elbow;
        continue;
      }
      p.active = true;
      p.rate_rad = 0.0f;
      to_own = wrap_angle(to_own);
      // The way round the circle that keeps the arm shallower in the trunk; the shorter one
      // unless the longer is clearly shallower (the elbow swung over the shoulder rather than
      // through the chest).
      if (body) {
        const float other_way = to_own - (to_own < 0.0f ? -2.0f : 2.0f) * kPi;
        const float short_depth =
            route_depth(*body, s, shoulder, p.previous_elbow, wrist, axis, to_own);
        const float long_depth =
            route_depth(*body, s, shoulder, p.previous_elbow, wrist, axis, other_way);
        if (long_depth + kRouteMarginM < short_depth) to_own = other_way;
      }
    } else {
      // The same way round as the frames before (the remainder carried on, not re-wrapped).
      to_own = p.remaining_rad + wrap_angle(to_own - p.remaining_rad);
    }
    const float max_rate = max_step_m / radius, max_change = max_change_m / radius;
    const float sign = to_own < 0.0f ? -1.0f : 1.0f;
    // As fast as the bounds allow, slowing down in time to arrive with no swing left.
    const float wanted =
        sign * std::min(max_rate, std::sqrt(2.0f * max_change * std::fabs(to_own)));
    const float swing = std::clamp(wanted, p.rate_rad - max_change, p.rate_rad + max_change);
    if (swing * sign >= std::fabs(to_own)) {
      // Arrived: the frame's own elbow from here on.
      p.active = false;
      p.rate_rad = 0.0f;
      p.previous_elbow = elbow;
      continue;
    }
    p.remaining_rad = to_own - swing;
    p.rate_rad = swing;
    // The upper arm and forearm turned by -remaining about the line through the shoulder joint
    // (the wrist on the line stays); the hand keeps its rotation in space.
    const glm::quat turn = glm::angleAxis(-p.remaining_rad, axis);
    p.previous_elbow = shoulder + turn * (elbow - shoulder);
    turn_arm(rig, arm, turn, pb, max_bend_rad, local);
    ++count;
  }
  if (p.active) return false;
  rotations->swap(out);
  *changed += count;
  return true;
}

// The same swings centred on the frame of each jump: the elbow sets off before it and arrives
// after it, its angle about the shoulder-wrist line offset by a smoothstep (3t^2 - 2t^3) that
// rises by the jump over a window long enough for the speed and acceleration bounds, less the
// jump itself from its frame on. The offsets of overlapping windows add. False when a window does
// not fit in the clip.
bool centred_arm_path(const Rig& rig, const BodyModel* body, Side s, float fps, int frame_count,
                      float max_bend_rad, std::vector<glm::quat>* rotations, int* changed) {
  const int J = rig.joint_count;
  const float trigger_m = kSwingTriggerMPerS / fps;
  const float max_step_m = kSwingMaxMPerS / fps;
  const float max_change_m = kSwingMaxAccelMPerS2 / (fps * fps);
  const ArmRig& arm = rig.arms[s];
  std::vector<glm::vec3> shoulder(frame_count), elbow(frame_count), wrist(frame_count);
  {
    SubsetPose arm_joints(rig, {arm.upper, arm.lower, arm.hand});  // positions only
    for (int f = 0; f < frame_count; ++f) {
      arm_joints.set_from_local(&(*rotations)[static_cast<size_t>(f) * J]);
      shoulder[f] = arm_joints.position(arm.upper);
      elbow[f] = arm_joints.position(arm.lower);
      wrist[f] = arm_joints.position(arm.hand);
    }
  }
  PoseBuilder pb(rig);
  std::vector<float> offset(frame_count, 0.0f);
  bool any = false;
  for (int k = 1; k < frame_count; ++k) {
    const glm::vec3 line = wrist[k] - shoulder[k];
    const float length = glm::length(line);
    if (length < 1e-4f) continue;
    const glm::vec3 axis = line / length;
    const glm::vec3 own = reject(elbow[k] - shoulder[k], axis),
                    held = reject(elbow[k - 1] - shoulder[k], axis);
    const float radius = glm::length(own);
    if (radius < kMinRadiusM || glm::length(held) < kMinRadiusM) continue;
    // The jump: the angle about the line from where the previous frame's elbow is held to the
    // frame's own.
    float jump = turn_about(held, own, axis);
    if (radius * std::fabs(jump) <= trigger_m) continue;
    if (body) {
      const float other_way = jump - (jump < 0.0f ? -2.0f : 2.0f) * kPi;
      const float short_depth =
          route_depth(*body, s, shoulder[k], elbow[k - 1], wrist[k], axis, jump);
      const float long_depth =
          route_depth(*body, s, shoulder[k], elbow[k - 1], wrist[k], axis, other_way);
      if (long_depth + kRouteMarginM < short_depth) jump = other_way;
    }
    const float arc = radius * std::fabs(jump);
    const int window = static_cast<int>(
        std::ceil(std::max(1.5f * arc / max_step_m, std::sqrt(6.0f * arc / max_change_m))));
    if (window >= frame_count) return false;
    const int start = std::clamp(k - window / 2, 0, frame_count - 1 - window);
    for (int f = start; f < frame_count; ++f) {
      const float t = std::min(1.0f, static_cast<float>(f - start) / static_cast<float>(window));
      offset[f] += jump * t * t * (3.0f - 2.0f * t) - (f >= k ? jump : 0.0f);
    }
    any = true;
  }
  if (!any) return true;
  for (int f = 0; f < frame_count; ++f) {
    const glm::vec3 line = wrist[f] - shoulder[f];
    if (std::fabs(offset[f]) < 1e-6f || glm::length(line) < 1e-4f) continue;
    glm::quat* local = &(*rotations)[static_cast<size_t>(f) * J];
    pb.set_from_local(local);
    turn_arm(rig, arm, glm::angleAxis(offset[f], line / glm::length(line)), pb, max_bend_rad,
             local);
    ++*changed;
  }
  return true;
}

// How deep `side`'s arm goes over the clip, each part on its own, so that a variant deeper in one
// is not excused by another's depth: the upper arm and forearm into the trunk or the other forearm
// (the forearm's wrist end allowed to touch, as for a hand in contact: the same leniency for every
// variant), the hand into the trunk (the hand turns with the forearm where the wrist cannot take
// the swing back), and each hand into the other hand and forearm.
struct ArmDepths {
  float arm_m = 0.0f, hand_m = 0.0f, hands_m = 0.0f;
};
ArmDepths deepest_arm(const Rig& rig, const BodyModel& body, Side side, int frame_count,
                      const std::vector<glm::quat>& rotations) {
  PoseBuilder pb(rig);
  ArmDepths d;
  for (int f = 0; f < frame_count; ++f) {
    pb.set_from_local(&rotations[static_cast<size_t>(f) * rig.joint_count]);
    d.arm_m = std::max(d.arm_m, arm_penetration(body, pb, side, true, true, true).depth_m);
    d.hand_m = std::max(d.hand_m, hand_penetration(body, pb, side, true, false).depth_m);
    d.hands_m = std::max({d.hands_m, hand_penetration(body, pb, side, false, true).depth_m,
                          hand_penetration(body, pb, other(side), false, true).depth_m});
  }
  return d;
}

// Each part within the 5 mm rule's 4 mm or no deeper than the clip had it (1 mm of slack).
bool within_depths(const ArmDepths& trial, const ArmDepths& written) {
  auto allowed = [](float w) { return std::max(w, kFreeDepthM) + kDeeperToleranceM; };
  return trial.arm_m <= allowed(written.arm_m) && trial.hand_m <= allowed(written.hand_m) &&
         trial.hands_m <= allowed(written.hands_m);
}

}  // namespace

int continue_elbow_paths(const Rig& rig, const BodyModel* body, float fps, int frame_count,
                         std::vector<glm::quat>* rotations, float* largest_arm_step_m) {
  if (largest_arm_step_m) *largest_arm_step_m = 0.0f;
  if (frame_count < 2 || fps <= 0.0f) return 0;
  // One pass to find the arms whose elbow swings faster than the trigger at all (most clips have
  // none, and are left as they are at the cost of posing the arms' joints once per frame). It
  // reads only the shoulder joints', elbows' and wrists' positions: those and their ancestors are
  // posed (SubsetPose, the full pose's positions to the bit), not the fingers, legs and head (the
  // lexicon, each sign from rest and back: the pass 88.8 -> 18.8 M instructions, of 1.66 G).
  bool swings[2] = {false, false};
  // Each arm's largest wrist and elbow step, squared (largest_arm_step_m). A carried swing turns the arm
  // about the line through the shoulder joint and the wrist, so the wrists' steps stay these; a
  // carried elbow's are its kept variant's (elbow_roughness measures them).
  float wrist_step[2] = {0.0f, 0.0f}, elbow_step[2] = {0.0f, 0.0f};
  {
    SubsetPose pb(rig, {rig.arms[kLeft].upper, rig.arms[kLeft].lower, rig.arms[kLeft].hand,
                        rig.arms[kRight].upper, rig.arms[kRight].lower, rig.arms[kRight].hand});
    glm::vec3 previous[2], previous_wrist[2];
    const float trigger_m = kSwingTriggerMPerS / fps;
    for (int f = 0; f < frame_count; ++f) {
      pb.set_from_local(&(*rotations)[static_cast<size_t>(f) * rig.joint_count]);
      for (Side s : {kLeft, kRight}) {
        const ArmRig& arm = rig.arms[s];
        const glm::vec3 shoulder = pb.position(arm.upper), elbow = pb.position(arm.lower);
        const glm::vec3 wrist = pb.position(arm.hand);
        const glm::vec3 line = wrist - shoulder;
        if (largest_arm_step_m && f > 0) {  // squared here, the root taken once at the end
          const glm::vec3 de = elbow - previous[s], dw = wrist - previous_wrist[s];
          elbow_step[s] = std::max(elbow_step[s], glm::dot(de, de));
          wrist_step[s] = std::max(wrist_step[s], glm::dot(dw, dw));
        }
        previous_wrist[s] = wrist;
        if (f > 0 && glm::length(line) > 1e-4f) {
          const glm::vec3 axis = glm::normalize(line);
          const glm::vec3 own = reject(elbow - shoulder, axis),
                          held = reject(previous[s] - shoulder, axis);
          if (glm::length(own) >= kMinRadiusM && glm::length(held) >= kMinRadiusM &&
              glm::length(own) * std::fabs(turn_about(held, own, axis)) > trigger_m)
            swings[s] = true;
        }
        previous[s] = elbow;
      }
    }
  }
  int changed = 0;
  for (Side s : {kLeft, kRight}) {
    if (!swings[s]) continue;
    // The variants: the swing centred on the jump, the elbow catching up after it or setting off
    // before it; the way round chosen by the body or the shorter. The one whose elbow is nearest
    // the smoothness bounds in step and change of step wins, if nearer than the clip's own, and
    // only where it keeps the arm as far out of the body as the clip had it (or within the 5 mm
    // rule): the corpus check counts depth, and an elbow swung through the chest or the head is no
    // better than a jump.
    const ArmDepths written_depths =
        body ? deepest_arm(rig, *body, s, frame_count, *rotations) : ArmDepths{};
    // Nor may it bend the wrist further than the clip already does anywhere (a wrist past its
    // limits is no better than a jump either).
    const float own_wrist_bend = largest_wrist_bend(rig, s, frame_count, *rotations);
    const float allowed_wrist_bend = own_wrist_bend + kWristBendToleranceRad;
    std::vector<glm::quat> best;
    int best_changed = 0;
    float best_roughness = elbow_roughness(rig, s, fps, frame_count, *rotations);
    float best_step = elbow_step[s];  // squared
    for (int variant = 0; variant < 6; ++variant) {
      const bool by_body = variant % 2 == 0;
      if (!body && by_body) continue;
      std::vector<glm::quat> trial(*rotations);
      int count = 0;
      const BodyModel* route = by_body ? body : nullptr;
      const bool arrived = variant < 2   ? centred_arm_path(rig, route, s, fps, frame_count,
                                                            own_wrist_bend, &trial, &count)
                           : variant < 4 ? continue_arm_path(rig, route, s, fps, frame_count, false,
                                                             own_wrist_bend, &trial, &count)
                                         : continue_arm_path(rig, route, s, fps, frame_count, true,
                                                             own_wrist_bend, &trial, &count);
      if (!arrived || count == 0) continue;
      float trial_step = 0.0f;
      const float roughness = elbow_roughness(rig, s, fps, frame_count, trial, &trial_step);
      if (roughness >= best_roughness - 1e-3f) continue;
      if (largest_wrist_bend(rig, s, frame_count, trial) > allowed_wrist_bend) continue;
      if (body && !within_depths(deepest_arm(rig, *body, s, frame_count, trial), written_depths))
        continue;
      best_roughness = roughness;
      best_step = trial_step * trial_step;
      best.swap(trial);
      best_changed = count;
    }
    if (best_changed == 0) continue;
    rotations->swap(best);
    changed += best_changed;
    elbow_step[s] = best_step;
  }
  if (largest_arm_step_m)
    *largest_arm_step_m = std::sqrt(std::max({wrist_step[0], wrist_step[1], elbow_step[0], elbow_step[1]}));
  return changed;
}

}  // namespace sw::synthesis

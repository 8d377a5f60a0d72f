// Transitions: eqs (8)-(10) with slerp + minimum-jerk timing and via-pose routing (transition.h).
#include "synthesis/transition.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "synthesis/arm_ik.h"
#include "synthesis/movement.h"

namespace sw::synthesis {

float transition_lmax(const Rig& rig, const glm::quat* a, const glm::quat* b) {
  PoseBuilder pa(rig), pb(rig);
  pa.set_from_local(a);
  pb.set_from_local(b);
  float lmax = 0.0f;
  for (int j = 0; j < rig.joint_count; ++j)
    lmax = std::max(lmax, glm::length(pa.position(j) - pb.position(j)));
  return lmax;
}

int transition_states(float lmax_m, float fps, float speed) {
  float k = kTransitionStatesPerMetre * (fps / 30.0f) * lmax_m / speed;
  return std::max(kMinTransitionStates, static_cast<int>(std::ceil(k - 1e-4f)));
}

float max_penetration(const SynthContext& ctx, const glm::quat* frames, int frame_count,
                      const std::uint8_t* exempt, std::string* what, int* worst_frame) {
  const Rig& rig = ctx.rig;
  float worst = 0.0f;
  PoseBuilder pb(rig);
  for (int f = 0; f < frame_count; ++f) {
    // A held frame repeats the one before (the holds of a sign, a pause): same pose, same
    // depths, and the first occurrence already counted. Posing a frame is most of the check.
    const glm::quat* frame = frames + static_cast<size_t>(f) * rig.joint_count;
    if (f > 0 && exempt[f] == exempt[f - 1] &&
        std::memcmp(frame, frame - rig.joint_count, sizeof(glm::quat) * rig.joint_count) == 0)
      continue;
    pb.set_from_local(frame);
    for (int s = 0; s < 2; ++s) {
      Side side = static_cast<Side>(s);
      bool trunk = !(exempt[f] & exempt_bit(side, false));
      bool hands = !(exempt[f] & exempt_bit(side, true)) && !(exempt[f] & exempt_bit(other(side), true));
      Penetration p = hand_penetration(ctx.body, pb, side, trunk, hands);
      if (p.depth_m > worst) {
        worst = p.depth_m;
        if (what) *what = (side == kLeft ? "left hand in " : "right hand in ") + p.what;
        if (worst_frame) *worst_frame = f;
      }
      // The arm: always against the trunk (a hand's intended touch lets only the forearm's wrist
      // end rest on the body), its forearm against the other one unless the hands touch.
      Penetration arm = arm_penetration(ctx.body, pb, side, true, !trunk, hands && s == 0);
      if (arm.depth_m > worst) {
        worst = arm.depth_m;
        if (what) *what = arm.what;
        if (worst_frame) *worst_frame = f;
      }
    }
  }
  return worst;
}

namespace {

void interpolate(const glm::quat* a, const glm::quat* b, const std::vector<glm::quat>* delta,
                 float via_tau, int joints, int k, std::vector<glm::quat>* out) {
  out->resize(static_cast<size_t>(std::max(0, k - 1)) * joints);
  for (int i = 1; i < k; ++i) {
    float tau = static_cast<float>(i) / k;
    float e = minimum_jerk(tau);
    // The via displacement fades in and out with zero slope at both ends (sin^2 of a phase that
    // reaches 1/2 at the via time), peaking — zero slope again — where the direct path was
    // worst, so the path passes exactly through the via-pose there.
    float phase = tau <= via_tau ? 0.5f * tau / via_tau : 0.5f + 0.5f * (tau - via_tau) / (1.0f - via_tau);
    float w = std::sin(3.14159265f * phase);
    w *= w;
    for (int j = 0; j < joints; ++j) {
      glm::quat q = slerp_shortest(a[j], b[j], e);
      if (delta) q = q * slerp_shortest(glm::quat(1, 0, 0, 0), (*delta)[j], w);
      (*out)[static_cast<size_t>(i - 1) * joints + j] = glm::normalize(q);
    }
  }
}

// Samples of a path for its length (a sum of chords, so never longer than the path): at 24 the
// longest rest transition's joint path (1.5 m) is measured in steps of about 6 cm.
constexpr int kPathSamples = 24;

// The longest distance any joint travels along an interpolation (interpolate's arguments).
float path_length(const Rig& rig, const glm::quat* a, const glm::quat* b, const std::vector<glm::quat>* delta,
                  float via_tau) {
  const int J = rig.joint_count;
  std::vector<glm::quat> samples;
  interpolate(a, b, delta, via_tau, J, kPathSamples, &samples);
  PoseBuilder pb(rig);
  std::vector<glm::vec3> prev(J), cur(J);
  std::vector<float> length(J, 0.0f);
  for (int i = 0; i <= kPathSamples; ++i) {
    const glm::quat* frame = i == 0 ? a : i == kPathSamples ? b : &samples[static_cast<size_t>(i - 1) * J];
    pb.set_from_local(frame);
    for (int j = 0; j < J; ++j) {
      cur[j] = pb.position(j);
      if (i > 0) length[j] += glm::length(cur[j] - prev[j]);
    }
    std::swap(prev, cur);
  }
  return J > 0 ? *std::max_element(length.begin(), length.end()) : 0.0f;
}

}  // namespace

float transition_path_m(const Rig& rig, const glm::quat* from_locals, const glm::quat* to_locals) {
  return path_length(rig, from_locals, to_locals, nullptr, 0.5f);
}

TransitionPlan plan_transition(const SynthContext& ctx, const glm::quat* from, const glm::quat* to,
                               std::uint8_t exempt_from, std::uint8_t exempt_to) {
  const Rig& rig = ctx.rig;
  const int J = rig.joint_count;
  const float fps = ctx.options.fps, speed = ctx.options.speed;
  TransitionPlan plan;
  plan.lmax_m = transition_path_m(rig, from, to);
  plan.k = transition_states(plan.lmax_m, fps, speed);
  interpolate(from, to, nullptr, 0.5f, J, plan.k, &plan.frames);
  auto exempt_for = [&](int k) {
    std::vector<std::uint8_t> ex(std::max(0, k - 1), 0);
    for (int i = 1; i < k; ++i) {
      float tau = static_cast<float>(i) / k;
      if (tau < 0.35f) ex[i - 1] |= exempt_from;
      if (tau > 0.65f) ex[i - 1] |= exempt_to;
    }
    return ex;
  };
  plan.exempt = exempt_for(plan.k);
  if (plan.k < 2) return plan;
  std::string what;
  int worst = 0;
  plan.max_penetration_m = max_penetration(ctx, plan.frames.data(), plan.k - 1, plan.exempt.data(), &what, &worst);
  if (!ctx.options.avoid_collisions || plan.max_penetration_m <= 0.005f) return plan;

  // Route through a via-pose: the middle state with the offending hand(s) pulled out of the body
  // (along the escape direction and forward), re-solved by arm IK; orientation and fingers kept.
  // The via-pose replaces the worst state of the direct path (its time kept for the re-timed path).
  const float via_tau = std::min(0.8f, std::max(0.2f, static_cast<float>(worst + 1) / plan.k));
  std::vector<glm::quat> mid(J);
  for (int j = 0; j < J; ++j) mid[j] = slerp_shortest(from[j], to[j], minimum_jerk(via_tau));
  PoseBuilder worst_pose(rig);
  worst_pose.set_from_local(&plan.frames[static_cast<size_t>(worst) * J]);
  std::array<glm::vec3, 2> push{};
  for (int s = 0; s < 2; ++s) {
    Side side = static_cast<Side>(s);
    Penetration p = hand_penetration(ctx.body, worst_pose, side, true, true);
    if (p.depth_m > 0.0f) push[s] = glm::normalize(p.push_dir + rig.forward) * (p.depth_m + 0.03f);
    // An arm in the trunk or through the other forearm: the hand moves forward, away from the
    // body, and the via-pose's IK (with the body model) picks a swivel that keeps the arm out.
    Penetration arm = arm_penetration(ctx.body, worst_pose, side, true, false, true);
    if (arm.depth_m > 0.0f && glm::length(push[s]) == 0.0f)
      push[s] = glm::normalize(arm.push_dir + rig.forward) * (arm.depth_m + 0.03f);
  }
  TransitionPlan best = plan;
  // The push, then two, three and four times it; failing those, less than it: a via-pose pushed
  // further can take another swivel that is worse (a hand across the waist: 5.2 mm at 1x, 15 mm
  // at 2x, 1.2 mm at 0.75x).
  const float scales[] = {1.0f, 2.0f, 3.0f, 4.0f, 0.75f, 0.5f};
  for (int attempt = 1; attempt <= 6; ++attempt) {
    PoseBuilder pm(rig);
    pm.set_from_local(mid.data());
    std::vector<glm::quat> via = mid, arm_locals(J);
    for (int s = 0; s < 2; ++s) {
      if (glm::length(push[s]) == 0.0f) continue;
      Side side = static_cast<Side>(s);
      const ArmRig& a = rig.arms[s];
      ArmTarget t;
      t.point = pm.position(a.hand) + scales[attempt - 1] * push[s];
      t.contact_offset = glm::vec3(0.0f);
      t.hand_delta = pm.delta(a.hand);
      t.body = &ctx.body;
      PoseBuilder solved(rig);
      solved.set_from_local(mid.data());
      apply_arm(rig, side, solve_arm(rig, side, t), &solved);
      solved.local_rotations(arm_locals.data());
      for (int j : {a.shoulder, a.upper, a.lower, a.hand})
        if (j >= 0) via[j] = arm_locals[j];
    }
    std::vector<glm::quat> delta(J);
    for (int j = 0; j < J; ++j) delta[j] = glm::conjugate(mid[j]) * via[j];
    TransitionPlan p;
    p.lmax_m = path_length(rig, from, to, &delta, via_tau);  // eq. (10) along the routed path
    p.k = transition_states(p.lmax_m, fps, speed);
    p.via_points = 1;
    interpolate(from, to, &delta, via_tau, J, p.k, &p.frames);
    p.exempt = exempt_for(p.k);
    p.max_penetration_m = max_penetration(ctx, p.frames.data(), p.k - 1, p.exempt.data(), nullptr, nullptr);
    if (p.max_penetration_m < best.max_penetration_m) best = std::move(p);
    if (best.max_penetration_m <= 0.005f) break;
  }
  return best;
}

}  // namespace sw::synthesis

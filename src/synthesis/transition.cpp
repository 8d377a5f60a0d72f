// Transitions: eqs (8)-(10) with slerp + minimum-jerk timing and via-pose routing (transition.h).
#include "synthesis/transition.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

#include "math/quat_lanes.h"
#include "synthesis/arm_ik.h"
#include "synthesis/movement.h"
#include "synthesis/subset_pose.h"

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
  PenetrationMemo* memo = ctx.penetration_memo;
  for (int f = 0; f < frame_count; ++f) {
    // A held frame repeats the one before (the holds of a sign, a pause): same pose, same
    // depths, and the first occurrence already counted. Posing a frame is most of the check.
    const glm::quat* frame = frames + static_cast<size_t>(f) * rig.joint_count;
    if (f > 0 && exempt[f] == exempt[f - 1] &&
        std::memcmp(frame, frame - rig.joint_count, sizeof(glm::quat) * rig.joint_count) == 0)
      continue;
    // The frame's deepest check, first in the order below on a tie: over the frames, the first
    // frame's deepest is then the first of all checks that reaches the maximum, as when every
    // check is compared with the running worst.
    const PenetrationMemo::Result* known = memo ? memo->find(frame, exempt[f]) : nullptr;
    PenetrationMemo::Result here;
    if (!known) {
      pb.set_from_local(frame);
      for (int s = 0; s < 2; ++s) {
        Side side = static_cast<Side>(s);
        bool trunk = !(exempt[f] & exempt_bit(side, false));
        bool hands = !(exempt[f] & exempt_bit(side, true)) && !(exempt[f] & exempt_bit(other(side), true));
        Penetration p = hand_penetration(ctx.body, pb, side, trunk, hands);
        if (p.depth_m > here.depth_m) {
          here.depth_m = p.depth_m;
          here.what = (side == kLeft ? "left hand in " : "right hand in ") + p.what;
        }
        // The arm: always against the trunk (a hand's intended touch lets only the forearm's wrist
        // end rest on the body), its forearm against the other one unless the hands touch.
        Penetration arm = arm_penetration(ctx.body, pb, side, true, !trunk, hands && s == 0);
        if (arm.depth_m > here.depth_m) {
          here.depth_m = arm.depth_m;
          here.what = std::move(arm.what);
        }
      }
      known = &here;
    }
    if (known->depth_m > worst) {
      worst = known->depth_m;
      if (what) *what = known->what;
      if (worst_frame) *worst_frame = f;
    }
    if (memo && known == &here) memo->add(frame, exempt[f], std::move(here));
  }
  return worst;
}

PenetrationMemo::PenetrationMemo(const SynthContext& ctx) : table_(1024, -1) {
  const Rig& rig = ctx.rig;
  std::vector<char> mark(static_cast<size_t>(rig.joint_count), 0);
  auto reads = [&](int j) {
    for (; j >= 0 && j < rig.joint_count && !mark[j]; j = rig.parent[j]) mark[j] = 1;
  };
  for (const ArmRig& a : rig.arms) {
    for (int j : {a.shoulder, a.upper, a.lower, a.hand}) reads(j);
    for (const FingerChain& c : a.fingers) {
      for (int j : c.bones) reads(j);
      reads(c.tip);
    }
  }
  for (const Capsule& c : ctx.body.trunk) reads(c.joint);
  for (int s = 0; s < 2; ++s) {
    reads(ctx.body.upper_arm[s].joint);
    reads(ctx.body.forearm[s].joint);
  }
  for (int j = 0; j < rig.joint_count; ++j)
    if (mark[j]) joints_.push_back(j);
  for (const ArmRig& a : rig.arms)
    for (int j : {a.upper, a.lower, a.hand})
      if (j >= 0 && j < rig.joint_count) hash_joints_.push_back(j);
  // Room for a one-sign phrase's frames from rest and back (the lexicon's: 72 on average, 8,813
  // adds for 141 signs), so the keys are not copied as they grow: the keys' regrowth was 12 M
  // instructions of the lexicon's 1.47 G (speed-wasm). A longer phrase grows as before.
  constexpr size_t kReservedFrames = 128;
  keys_.reserve(kReservedFrames * 4 * joints_.size());
  exempt_.reserve(kReservedFrames);
  results_.reserve(kReservedFrames);
  hashes_.reserve(kReservedFrames);
}

std::uint32_t PenetrationMemo::key_hash(const glm::quat* frame, std::uint8_t exempt) const {
  // FNV-1a over the arm joints' bits only: they move on every frame of a transition, so they tell
  // frames apart; same() compares the whole key.
  std::uint32_t h = 2166136261u ^ exempt;
  for (int j : hash_joints_) {
    std::uint32_t w[4];
    std::memcpy(w, &frame[j], sizeof w);
    for (std::uint32_t x : w) h = (h ^ x) * 16777619u;
  }
  return h;
}

bool PenetrationMemo::same(size_t entry, const glm::quat* frame, std::uint8_t exempt) const {
  if (exempt_[entry] != exempt) return false;
  const std::uint32_t* key = &keys_[entry * 4 * joints_.size()];
  std::uint32_t differ = 0;
  for (size_t i = 0; i < joints_.size(); ++i, key += 4) {
    std::uint32_t w[4];
    std::memcpy(w, &frame[joints_[i]], sizeof w);
    differ |= (w[0] ^ key[0]) | (w[1] ^ key[1]) | (w[2] ^ key[2]) | (w[3] ^ key[3]);
  }
  return differ == 0;
}

const PenetrationMemo::Result* PenetrationMemo::find(const glm::quat* frame, std::uint8_t exempt) const {
  const std::uint32_t h = key_hash(frame, exempt);
  const size_t mask = table_.size() - 1;
  for (size_t i = h & mask;; i = (i + 1) & mask) {
    const std::int32_t e = table_[i];
    if (e < 0) return nullptr;
    if (hashes_[static_cast<size_t>(e)] == h && same(static_cast<size_t>(e), frame, exempt))
      return &results_[static_cast<size_t>(e)];
  }
}

void PenetrationMemo::add(const glm::quat* frame, std::uint8_t exempt, Result result) {
  if (2 * (results_.size() + 1) > table_.size()) {  // keep the table at most half full
    std::vector<std::int32_t> bigger(2 * table_.size(), -1);
    const size_t mask = bigger.size() - 1;
    for (size_t e = 0; e < hashes_.size(); ++e) {
      size_t i = hashes_[e] & mask;
      while (bigger[i] >= 0) i = (i + 1) & mask;
      bigger[i] = static_cast<std::int32_t>(e);
    }
    table_.swap(bigger);
  }
  const std::uint32_t h = key_hash(frame, exempt);
  const size_t mask = table_.size() - 1;
  size_t i = h & mask;
  while (table_[i] >= 0) i = (i + 1) & mask;
  table_[i] = static_cast<std::int32_t>(results_.size());
  const size_t at = keys_.size();
  keys_.resize(at + 4 * joints_.size());
  for (size_t k = 0; k < joints_.size(); ++k) std::memcpy(&keys_[at + 4 * k], &frame[joints_[k]], sizeof(glm::quat));
  exempt_.push_back(exempt);
  hashes_.push_back(h);
  results_.push_back(std::move(result));
}

namespace {

// A via-pose: the joints' rotation offsets from the direct path (local, right-multiplied) and the
// time (0..1 of the transition) at which the path passes through it.
struct Via {
  std::vector<glm::quat> delta;
  float tau = 0.5f;
};

// The weight of via `v` at time tau: sin^2 rising from the previous via's time (or the start) to
// its own and falling to the next via's time (or the end), zero slope at every via and at both
// ends, so consecutive vias' weights sum to 1 between them and the path passes exactly through
// each via-pose at its time.
float via_weight(const std::vector<Via>& vias, size_t v, float tau) {
  const float t0 = v == 0 ? 0.0f : vias[v - 1].tau, t1 = vias[v].tau;
  const float t2 = v + 1 == vias.size() ? 1.0f : vias[v + 1].tau;
  if (tau <= t0 || tau >= t2) return 0.0f;
  float phase = tau <= t1 ? 0.5f * (tau - t0) / (t1 - t0) : 0.5f + 0.5f * (tau - t1) / (t2 - t1);
  float w = std::sin(3.14159265f * phase);
  return w * w;
}

// One joint's shortest-path slerp from a to b (slerp_shortest, rig.cpp) worked out once for every
// sample of a path: the hemisphere flip, the angle and its sine do not depend on t, so they are
// computed once instead of per sample (an acos and a sin per joint per frame). Each sample is the
// same arithmetic on the same values as slerp_shortest(a, b, t), glm's quaternion sums and
// normalisation done four lanes at a time (math/quat_lanes.h): bit-identical.
struct JointSlerp {
  math::lanes::Float4 a, b, diff;  // b flipped into a's hemisphere; diff = b - a for the nlerp branch
  float theta = 0.0f, sin_theta = 0.0f;
  bool nlerp = true;
  // a and b the same bits (and finite): diff is +0, so a + t * diff is the same for every t >= 0
  // (minimum_jerk never goes below 0) and one sample serves the whole path.
  bool constant = false;
  JointSlerp(const glm::quat& a_in, const glm::quat& b_in) {
    glm::quat bq = b_in;
    float d = glm::dot(a_in, bq);
    if (d < 0.0f) {
      bq = -bq;
      d = -d;
    }
    a = math::lanes::load4(a_in);
    b = math::lanes::load4(bq);
    nlerp = d > 0.9995f;
    if (nlerp) {
      diff = math::lanes::load4(bq - a_in);
      constant = std::memcmp(&a_in, &b_in, sizeof(glm::quat)) == 0 && std::isfinite(a_in.w) &&
                 std::isfinite(a_in.x) && std::isfinite(a_in.y) && std::isfinite(a_in.z);
    } else {
      theta = std::acos(std::min(d, 1.0f));
      sin_theta = std::sin(theta);
    }
  }
  // slerp_shortest's normalize(a + t * (b - a)) or normalize(wa * a + wb * b).
  math::lanes::Float4 at(float t) const {
    if (nlerp) return math::lanes::quat_normalize(a + diff * t);
    float wa = std::sin((1.0f - t) * theta) / sin_theta, wb = std::sin(t * theta) / sin_theta;
    return math::lanes::quat_normalize(a * wa + b * wb);
  }
};

// interpolate() without via-poses (the direct transition and its path measurement): the same
// frames, each joint's slerp set up once for all of them (JointSlerp).
void interpolate_direct(const glm::quat* a, const glm::quat* b, int joints, int k, std::vector<glm::quat>* out) {
  out->resize(static_cast<size_t>(std::max(0, k - 1)) * joints);
  std::vector<JointSlerp> path;
  path.reserve(static_cast<size_t>(joints));
  for (int j = 0; j < joints; ++j) path.emplace_back(a[j], b[j]);
  for (int i = 1; i < k; ++i) {
    float e = minimum_jerk(static_cast<float>(i) / k);
    glm::quat* row = &(*out)[static_cast<size_t>(i - 1) * joints];
    const glm::quat* first = out->data();
    for (int j = 0; j < joints; ++j) {
      if (i > 1 && path[j].constant) row[j] = first[j];
      else math::lanes::store4(&row[j], math::lanes::quat_normalize(path[j].at(e)));
    }
  }
}

// The direct slerp's samples (JointSlerp::at, before the offsets) of one transition at the state
// counts already sampled: every via candidate of plan_transition's search shares the direct path
// from `from` to `to`, samples it at kPathSamples for its length and often at the same k as
// another candidate, and each sample is the same arithmetic on the same values (bit-identical).
class DirectSamples {
 public:
  // The k-1 states' samples, joint-major per state; computed with `path` on first use of k.
  const glm::quat* at(const std::vector<JointSlerp>& path, int k) {
    for (const Entry& e : entries_)
      if (e.k == k) return e.samples.data();
    Entry e;
    e.k = k;
    const size_t joints = path.size();
    e.samples.resize(static_cast<size_t>(std::max(0, k - 1)) * joints);
    for (int i = 1; i < k; ++i) {
      const float m = minimum_jerk(static_cast<float>(i) / k);
      for (size_t j = 0; j < joints; ++j) math::lanes::store4(&e.samples[(i - 1) * joints + j], path[j].at(m));
    }
    entries_.push_back(std::move(e));
    return entries_.back().samples.data();
  }

 private:
  struct Entry {
    int k = 0;
    std::vector<glm::quat> samples;
  };
  std::vector<Entry> entries_;
};

// With via-poses: each joint's direct slerp and each via's offset slerp from the identity set up
// once for all the states (JointSlerp), the offsets right-multiplied and the sum normalised four
// lanes at a time (math/quat_lanes.h): the same arithmetic on the same values as
// normalize(slerp_shortest(a, b, e) * slerp_shortest(1, delta, w) * ...), bit-identical. The path
// searches of plan_transition sample every via candidate several times (its length, its states,
// their re-timing), so the acos and sines per joint per state were most of a routed sign's time.
// `direct` (optional): the samples of the direct slerp from a to b kept across calls.
void interpolate(const glm::quat* a, const glm::quat* b, const std::vector<Via>& vias, int joints, int k,
                 std::vector<glm::quat>* out, DirectSamples* direct = nullptr) {
  if (vias.empty()) return interpolate_direct(a, b, joints, k, out);
  out->resize(static_cast<size_t>(std::max(0, k - 1)) * joints);
  std::vector<JointSlerp> path, offsets;
  path.reserve(static_cast<size_t>(joints));
  for (int j = 0; j < joints; ++j) path.emplace_back(a[j], b[j]);
  offsets.reserve(vias.size() * static_cast<size_t>(joints));
  for (const Via& via : vias)
    for (int j = 0; j < joints; ++j) offsets.emplace_back(glm::quat(1, 0, 0, 0), via.delta[static_cast<size_t>(j)]);
  // A joint whose direct slerp and every via offset are constant (JointSlerp::constant: the same
  // sample at every fraction > 0) has the same inputs, so the same result, at every state whose
  // weights are > 0 for the same vias as the first state's: copied from it (interpolate_direct's
  // rule, the offsets included).
  std::vector<char> fixed(static_cast<size_t>(joints), 0);
  for (int j = 0; j < joints; ++j) {
    bool all = path[static_cast<size_t>(j)].constant;
    for (size_t v = 0; all && v < vias.size(); ++v) all = offsets[v * static_cast<size_t>(joints) + j].constant;
    fixed[static_cast<size_t>(j)] = all;
  }
  const glm::quat* direct_at = direct ? direct->at(path, k) : nullptr;
  std::vector<float> w(vias.size());
  std::vector<char> first_weighted(vias.size(), 0);
  float first_e = 0.0f;
  for (int i = 1; i < k; ++i) {
    float tau = static_cast<float>(i) / k;
    float e = minimum_jerk(tau);
    for (size_t v = 0; v < vias.size(); ++v) w[v] = via_weight(vias, v, tau);
    bool as_first = i > 1 && e > 0.0f && first_e > 0.0f;
    for (size_t v = 0; v < vias.size(); ++v) {
      if (i == 1) first_weighted[v] = w[v] > 0.0f;
      else as_first = as_first && (w[v] > 0.0f) == static_cast<bool>(first_weighted[v]);
    }
    if (i == 1) first_e = e;
    for (int j = 0; j < joints; ++j) {
      if (as_first && fixed[static_cast<size_t>(j)]) {
        (*out)[static_cast<size_t>(i - 1) * joints + j] = (*out)[static_cast<size_t>(j)];
        continue;
      }
      math::lanes::Float4 q = direct_at ? math::lanes::load4(direct_at[static_cast<size_t>(i - 1) * joints + j])
                                        : path[j].at(e);
      for (size_t v = 0; v < vias.size(); ++v)
        if (w[v] > 0.0f) q = math::lanes::quat_mul(q, offsets[v * static_cast<size_t>(joints) + j].at(w[v]));
      math::lanes::store4(&(*out)[static_cast<size_t>(i - 1) * joints + j], math::lanes::quat_normalize(q));
    }
  }
}

// A path through whole waypoint poses: from a through each waypoint to b, joint rotations slerped
// piece by piece, one minimum-jerk profile over the whole (pieces by the share of the joint path
// each takes, so the speed carries through every waypoint). Unlike blended via offsets, each
// piece is a slerp between two poses clear of the body, so an arm that must first come forward
// and only then across (a far-side place from the rest) does so in order. At a waypoint the
// direction turns: over a window either side of it (45% of the shorter neighbouring piece) the
// two pieces, each extended past the waypoint, are cross-faded by a smoothstep, so the velocity
// is continuous and the path still passes exactly through the waypoint (both pieces are there).
void interpolate_chain(const Rig& rig, const glm::quat* a, const glm::quat* b,
                       const std::vector<std::vector<glm::quat>>& waypoints, int k, std::vector<glm::quat>* out) {
  const int J = rig.joint_count;
  std::vector<const glm::quat*> knots{a};
  for (const auto& w : waypoints) knots.push_back(w.data());
  knots.push_back(b);
  const size_t pieces = knots.size() - 1;
  std::vector<float> u{0.0f};
  for (size_t i = 1; i < knots.size(); ++i) u.push_back(u.back() + transition_lmax(rig, knots[i - 1], knots[i]) + 1e-6f);
  for (float& x : u) x /= u.back();
  std::vector<float> half(knots.size(), 0.0f);  // blend half-window at each interior knot
  for (size_t i = 1; i < pieces; ++i) half[i] = 0.45f * std::min(u[i] - u[i - 1], u[i + 1] - u[i]);
  auto piece = [&](size_t p, int j, float e) {
    return slerp_shortest(knots[p][j], knots[p + 1][j], (e - u[p]) / (u[p + 1] - u[p]));
  };
  out->resize(static_cast<size_t>(std::max(0, k - 1)) * J);
  for (int i = 1; i < k; ++i) {
    float e = minimum_jerk(static_cast<float>(i) / k);
    size_t seg = 0;
    while (seg + 1 < pieces && e > u[seg + 1]) ++seg;
    // The nearest interior knot whose window holds e, if any.
    size_t knot = 0;
    for (size_t n = 1; n < pieces; ++n)
      if (std::fabs(e - u[n]) < half[n]) knot = n;
    float x = knot ? (e - (u[knot] - half[knot])) / (2.0f * half[knot]) : 0.0f;
    float fade = x * x * (3.0f - 2.0f * x);
    for (int j = 0; j < J; ++j) {
      glm::quat q = knot ? slerp_shortest(piece(knot - 1, j, e), piece(knot, j, e), fade) : piece(seg, j, e);
      (*out)[static_cast<size_t>(i - 1) * J + j] = glm::normalize(q);
    }
  }
}

// Samples of a path for its length (a sum of chords, so never longer than the path): at 24 the
// longest rest transition's joint path (1.5 m) is measured in steps of about 6 cm.
constexpr int kPathSamples = 24;

// path_length's measure of only the `counted` joints' paths, along `samples` (kPathSamples - 1
// states) from a to b: those joints and their ancestors posed (SubsetPose), not the skeleton.
// Per counted joint the same chords summed in the same order as path_length's full pose, so the
// same length to the bit; the full pose skipped a joint it left alone (an exact 0 chord), which
// added here leaves the sum as it is.
float counted_path_length(const Rig& rig, const glm::quat* a, const glm::quat* b, const std::vector<glm::quat>& samples,
                          const std::vector<bool>& counted) {
  const int J = rig.joint_count;
  std::vector<int> wanted;
  for (int j = 0; j < J; ++j)
    if (counted[static_cast<size_t>(j)]) wanted.push_back(j);
  SubsetPose pose(rig, wanted);
  std::vector<glm::vec3> prev(wanted.size());
  std::vector<float> length(wanted.size(), 0.0f);
  for (int i = 0; i <= kPathSamples; ++i) {
    pose.set_from_local(i == 0 ? a : i == kPathSamples ? b : &samples[static_cast<size_t>(i - 1) * J]);
    for (size_t n = 0; n < wanted.size(); ++n) {
      const glm::vec3& cur = pose.position(wanted[n]);
      if (i > 0) length[n] += glm::length(cur - prev[n]);
      prev[n] = cur;
    }
  }
  float longest = 0.0f;
  for (float l : length) longest = std::max(longest, l);
  return longest;
}

// counted_path_length's measure of a rest transition's arm joints, and in the same walk the
// longest step its fingertips take between two of the kPathSamples states. `arm_m` is
// counted_path_length's value to the bit (each arm joint's chords are the same positions summed in
// the same order; the fingertips' ancestors posed with them change no arm joint's arithmetic).
struct ArmPathAndTipStep {
  float arm_m = 0.0f;       // eq. (10)'s L_max of the hand's path
  float arm_step_m = 0.0f;  // the longest arm-joint chord between neighbouring samples
  float tip_step_m = 0.0f;  // the longest fingertip chord between neighbouring samples
};
ArmPathAndTipStep arm_path_and_tip_step(const Rig& rig, const glm::quat* a, const glm::quat* b,
                                        const std::vector<glm::quat>& samples, const std::vector<bool>& arm,
                                        const std::vector<int>& tips) {
  const int J = rig.joint_count;
  std::vector<int> wanted;
  for (int j = 0; j < J; ++j)
    if (arm[static_cast<size_t>(j)]) wanted.push_back(j);
  const size_t first_tip = wanted.size();
  wanted.insert(wanted.end(), tips.begin(), tips.end());
  SubsetPose pose(rig, wanted);
  std::vector<glm::vec3> prev(wanted.size());
  std::vector<float> length(first_tip, 0.0f);
  float arm_step_sq = 0.0f, tip_step_sq = 0.0f;
  for (int i = 0; i <= kPathSamples; ++i) {
    pose.set_from_local(i == 0 ? a : i == kPathSamples ? b : &samples[static_cast<size_t>(i - 1) * J]);
    for (size_t n = 0; n < wanted.size(); ++n) {
      const glm::vec3& cur = pose.position(wanted[n]);
      if (i > 0) {
        const glm::vec3 chord = cur - prev[n];
        const float chord_sq = glm::dot(chord, chord);
        if (n < first_tip) {
          length[n] += glm::length(chord);
          arm_step_sq = std::max(arm_step_sq, chord_sq);
        } else {
          tip_step_sq = std::max(tip_step_sq, chord_sq);
        }
      }
      prev[n] = cur;
    }
  }
  ArmPathAndTipStep out;
  for (float l : length) out.arm_m = std::max(out.arm_m, l);
  out.arm_step_m = std::sqrt(arm_step_sq);
  out.tip_step_m = std::sqrt(tip_step_sq);
  return out;
}

// The longest distance any joint travels along an interpolation (interpolate's arguments).
// `sample(k, out)` writes the k-1 intermediate states of the path from a to b (interpolate's form).
// `counted` (optional, per joint): only those joints' paths enter the maximum.
template <typename Sampler>
float path_length(const Rig& rig, const glm::quat* a, const glm::quat* b, Sampler sample,
                  const std::vector<bool>* counted = nullptr) {
  const int J = rig.joint_count;
  std::vector<glm::quat> samples;
  sample(kPathSamples, &samples);
  if (counted) return counted_path_length(rig, a, b, samples, *counted);
  PoseBuilder pb(rig);
  std::vector<glm::vec3> prev(J);
  std::vector<float> length(J, 0.0f);
  for (int i = 0; i <= kPathSamples; ++i) {
    const glm::quat* frame = i == 0 ? a : i == kPathSamples ? b : &samples[static_cast<size_t>(i - 1) * J];
    pb.set_from_local(frame);
    for (int j = 0; j < J; ++j) {
      // A joint the incremental pose left alone has not moved: its chord is exactly 0 and adding
      // it would leave the sum as it is.
      if (i > 0 && !pb.recomputed(j)) continue;
      const glm::vec3& cur = pb.position(j);
      if (i > 0) length[j] += glm::length(cur - prev[j]);
      prev[j] = cur;
    }
  }
  return J > 0 ? *std::max_element(length.begin(), length.end()) : 0.0f;
}

// The deepest unintended penetration over frames as max_penetration measures it, split into the
// hands (in the trunk, in the other hand or forearm) and the arms (in the trunk, through the
// other forearm): a routed path is judged by what it adds to each beyond its end poses, and one
// kind's depth at an end (a hand held in the other, hanging forearm at a far-side place) must
// not hide what the path does with the other kind.
struct KindDepths {
  float hand_m = 0.0f, arm_m = 0.0f;
};
// How much deeper than the floors (each kind's depth at the end poses) `d` goes: the kinds'
// excesses added (plan_transition judges a routed path by it).
float excess_over(const KindDepths& d, float hand_floor_m, float arm_floor_m) {
  return std::max(0.0f, d.hand_m - hand_floor_m) + std::max(0.0f, d.arm_m - arm_floor_m);
}

// A bound past which the caller has no use for the depths: once the excess over the floors
// exceeds `above_m` (the depths only grow frame by frame, and so does the excess), the rest of
// the frames are not checked and the depths returned are the part measured, already past it.
struct ExcessBound {
  float hand_floor_m = 0.0f, arm_floor_m = 0.0f, above_m = 0.0f;
};

// With a bound, the frames are checked outward from the one nearest `deep_tau` (0..1 of the
// transition; `*deep_tau` is then set to where this call found its deepest frame): a routing
// search's candidates are deep at about the same time of the path, so a losing candidate passes
// the bound at its first few frames instead of after the shallow start. The order cannot change
// a result the caller uses: a full scan takes the maximum of every frame, and a scan cut short
// returns depths already past the bound whatever frames it measured (the candidate loses).
KindDepths depths_by_kind(const SynthContext& ctx, const glm::quat* frames, int frame_count, const std::uint8_t* exempt,
                          const ExcessBound* bound = nullptr, float* deep_tau = nullptr) {
  const Rig& rig = ctx.rig;
  KindDepths d;
  PoseBuilder pb(rig);
  const int k = frame_count + 1;  // the transition's states: frame f is at tau (f + 1) / k
  const int start =
      deep_tau ? std::min(std::max(static_cast<int>(std::lround(*deep_tau * k)) - 1, 0), std::max(frame_count - 1, 0))
               : 0;
  float deepest = -1.0f;
  int deepest_frame = start;
  for (int n = 0; n < frame_count; ++n) {
    if (bound && excess_over(d, bound->hand_floor_m, bound->arm_floor_m) > bound->above_m) break;
    // start, start + 1, start - 1, start + 2, ...; past one end, the rest of the other side.
    int f = n;
    if (start > 0) {
      const int below = start, above = frame_count - 1 - start;  // frames either side of start
      const int pair = (n + 1) / 2;
      if (n == 0) f = start;
      else if (pair <= std::min(below, above)) f = n % 2 ? start + pair : start - pair;
      else if (above > below) f = start + (n - below);
      else f = start - (n - above);
    }
    const glm::quat* frame = frames + static_cast<size_t>(f) * rig.joint_count;
    if (f > 0 && exempt[f] == exempt[f - 1] &&
        std::memcmp(frame, frame - rig.joint_count, sizeof(glm::quat) * rig.joint_count) == 0)
      continue;
    pb.set_from_local(frame);
    float here = 0.0f;
    for (int s = 0; s < 2; ++s) {
      const Side side = static_cast<Side>(s);
      const bool trunk = !(exempt[f] & exempt_bit(side, false));
      const bool hands = !(exempt[f] & exempt_bit(side, true)) && !(exempt[f] & exempt_bit(other(side), true));
      const float hand_m = hand_penetration(ctx.body, pb, side, trunk, hands).depth_m;
      const float arm_m = arm_penetration(ctx.body, pb, side, true, !trunk, hands && s == 0).depth_m;
      d.hand_m = std::max(d.hand_m, hand_m);
      d.arm_m = std::max(d.arm_m, arm_m);
      here = std::max(here, std::max(hand_m, arm_m));
    }
    if (here > deepest) {
      deepest = here;
      deepest_frame = f;
    }
  }
  if (deep_tau && frame_count > 0) *deep_tau = static_cast<float>(deepest_frame + 1) / k;
  return d;
}

// The largest acceleration an arm joint (shoulder girdle, upper arm, elbow, wrist) may reach in a
// transition, in m/s^2, measured as MotionSmoothness measures it: the second difference over a
// 1/30 s window (kArmAccelWindowS), the transition's ends held before and after it as the clip
// holds them. Hand accelerations in signing peak at a few tens of m/s^2; the smoothness tests
// hold wrists and elbows to 50.4 m/s^2 (5.6 cm change of a 30 fps step), and 40 leaves a fifth
// of that for the sign's own frames (swivel fixes ramped in). Eq. (10) sets a mean SPEED, and
// the global speed factor divides every duration, so along the same path every acceleration
// grows with its square: UNDERSTAND's raise to the forehead, whose elbow swings from behind the
// arm to in front of it between two waypoints of the hand's path (31-35 m/s^2 at speed 1),
// reached 50.4 / 53.0 m/s^2 (project avatar / reference) at 30 fps x 1.25. A faster signer still
// has a human arm: where the states would accelerate an arm joint beyond this, k grows by the
// square root of the excess (accelerations go as 1/duration^2 along the same path).
constexpr float kArmPeakAccelMPerS2 = 40.0f;
constexpr float kArmAccelWindowS = 1.0f / 30.0f;
// A corner of an arm's path (where a chain's pieces meet: UNDERSTAND's and TEACH's elbows swing
// 24 cm in one piece and 4 cm in the next, the cross-fade between them 0.09 s at speed 1.5) is
// as narrow as a few states, and the window's second difference over the states sees it by
// their phase: TEACH's lowering on the reference humanoid at 30 fps x 1.5 measured 56.5 m/s^2
// at 15 states, 46.6 at 19, 43.0 at 21, 59.5 at 22. So a chain's states are measured again at
// twice the density (the same 1/30 s window, the phases between the states too), and k
// stretched again on the new states, up to kAccelRounds times.
constexpr int kAccelRounds = 3;
// The states alone measured below this share of kArmPeakAccelMPerS2 are not measured between them
// (the phases the states missed raised TEACH's figure by at most 40%: 43.0 -> 59.5 m/s^2); each
// such check poses twice the states, and every rest transition's hand path had it.
constexpr float kAccelBetweenFrom = 0.7f;

// The arm joints (shoulder, upper arm, forearm, hand of both arms) of a rig.
std::vector<int> arm_joint_list(const Rig& rig) {
  std::vector<int> out;
  for (const ArmRig& a : rig.arms)
    for (int j : {a.shoulder, a.upper, a.lower, a.hand})
      if (j >= 0) out.push_back(j);
  return out;
}

// The fingertips accelerate at most this much in a transition's states. The arm joints' rule
// left them out, and the hand turning on the way from the rest swung them beyond the hand's
// 50.4 m/s^2 at speed 1.25 (TEACH and TEACHER's middle fingertip on the project avatar, 51.6
// at 60 fps). 50, not the arm's 40: at speed 1 the lexicon's rest transitions keep their tips
// within the bound (LOOK's 48.7 at 30 fps on the avatar, the highest) and keep their timing.
constexpr float kFingertipPeakAccelMPerS2 = 50.0f;

// The points kArmPeakAccelMPerS2's measure follows: the arm joints, then the fingertips (the
// tip joints, or the distal bones where a rig has none). `scale`: each point's position scale,
// so one bound reads both (the fingertips at kArmPeakAccelMPerS2 / kFingertipPeakAccelMPerS2:
// a second difference scales with the positions).
struct AccelPoints {
  std::vector<int> joints;
  std::vector<float> scale;
};
AccelPoints accel_point_list(const Rig& rig) {
  AccelPoints out;
  out.joints = arm_joint_list(rig);
  out.scale.assign(out.joints.size(), 1.0f);
  for (const ArmRig& a : rig.arms)
    for (const FingerChain& finger : a.fingers) {
      const int j = finger.tip >= 0 ? finger.tip : finger.bones[2];
      if (j < 0) continue;
      out.joints.push_back(j);
      out.scale.push_back(kArmPeakAccelMPerS2 / kFingertipPeakAccelMPerS2);
    }
  return out;
}

// kArmPeakAccelMPerS2's measure over positions pos[i * n + joint] of states 0..k (the two ends
// included) sampled at fps.
float arm_accel_of(const std::vector<glm::vec3>& pos, size_t n, int k, float fps) {
  const int window = std::max(1, static_cast<int>(std::lround(kArmAccelWindowS * fps)));
  const float window_s = static_cast<float>(window) / fps;
  auto at = [&](int i, size_t j) { return pos[static_cast<size_t>(std::min(std::max(i, 0), k)) * n + j]; };
  float worst = 0.0f;
  for (int i = 1 - window; i < k + window; ++i)
    for (size_t j = 0; j < n; ++j)
      worst = std::max(worst, glm::length(at(i + window, j) - 2.0f * at(i, j) + at(i - window, j)));
  return worst / (window_s * window_s);
}

// The same measure for k-1 states `frames` between `from` and `to` (each posed), at fps.
float arm_accel(const Rig& rig, const glm::quat* from, const glm::quat* to, const std::vector<glm::quat>& frames, int k,
                float fps) {
  const int J = rig.joint_count;
  const AccelPoints points = accel_point_list(rig);
  const size_t n_points = points.joints.size();
  std::vector<glm::vec3> pos(static_cast<size_t>(k + 1) * n_points);
  SubsetPose pb(rig, points.joints);  // the arms and fingertips only: legs, head and eyes left out
  for (int i = 0; i <= k; ++i) {
    pb.set_from_local(i == 0 ? from : i == k ? to : &frames[static_cast<size_t>(i - 1) * J]);
    for (size_t n = 0; n < n_points; ++n)
      pos[static_cast<size_t>(i) * n_points + n] = points.scale[n] * pb.position(points.joints[n]);
  }
  return arm_accel_of(pos, n_points, k, fps);
}

// kArmPeakAccelMPerS2's measure of a path at k states, the phases between them included: the
// states sampled at 2k, the window twice as many of them (see kAccelRounds).
template <typename Sampler>
float arm_accel_between_states(const Rig& rig, const glm::quat* from, const glm::quat* to, Sampler sample, int k,
                               float fps) {
  std::vector<glm::quat> dense;
  sample(2 * k, &dense);
  return arm_accel(rig, from, to, dense, 2 * k, 2.0f * fps);
}

// Stretches k (re-sampling the states with `sample`) until no arm joint accelerates beyond
// kArmPeakAccelMPerS2, up to kAccelRounds times; `chain`: a path with corners (waypoints), also
// measured between the states.
// `posed` (optional): the accel points' scaled positions of the states as they are on entry
// (arm_accel's pos, from a walk over them the caller made anyway), used for the first round.
template <typename Sampler>
void stretch_for_arm_accel(const Rig& rig, const glm::quat* from, const glm::quat* to, float fps, Sampler sample,
                           bool chain, int* k, std::vector<glm::quat>* frames,
                           const std::vector<glm::vec3>* posed = nullptr) {
  for (int round = 0; round < kAccelRounds; ++round) {
    float a = round == 0 && posed ? arm_accel_of(*posed, posed->size() / static_cast<size_t>(*k + 1), *k, fps)
                                  : arm_accel(rig, from, to, *frames, *k, fps);
    if (chain && a > kAccelBetweenFrom * kArmPeakAccelMPerS2)
      a = std::max(a, arm_accel_between_states(rig, from, to, sample, *k, fps));
    if (a <= kArmPeakAccelMPerS2) return;
    *k = static_cast<int>(std::ceil(*k * std::sqrt(a / kArmPeakAccelMPerS2)));
    sample(*k, frames);
  }
}

// The longest distance any joint moves in one frame along from, frames (k-1 states), to.
float max_joint_step(const Rig& rig, const glm::quat* from, const glm::quat* to, const std::vector<glm::quat>& frames,
                     int k) {
  const int J = rig.joint_count;
  PoseBuilder pb(rig);
  std::vector<glm::vec3> prev(J), cur(J);
  float worst = 0.0f;
  for (int i = 0; i <= k; ++i) {
    pb.set_from_local(i == 0 ? from : i == k ? to : &frames[static_cast<size_t>(i - 1) * J]);
    for (int j = 0; j < J; ++j) {
      cur[j] = pb.position(j);
      if (i > 0) worst = std::max(worst, glm::length(cur[j] - prev[j]));
    }
    std::swap(prev, cur);
  }
  return worst;
}

// Poses each of a plan's k-1 in-between states and hands it to `visit` (which keeps the depths it
// measures). With skip_contact, states where either hand may touch (the first and last third of a
// transition leaving or arriving at a contact) are left out: the routing asks what the path does
// away from the contacts.
template <typename Visit>
void for_each_state(const Rig& rig, const TransitionPlan& plan, bool skip_contact, Visit visit) {
  PoseBuilder pb(rig);
  for (int f = 0; f + 1 < plan.k; ++f) {
    const std::uint8_t ex = plan.exempt[static_cast<size_t>(f)];
    if (skip_contact && ((ex & exempt_bit(kLeft, true)) || (ex & exempt_bit(kRight, true)))) continue;
    pb.set_from_local(&plan.frames[static_cast<size_t>(f) * rig.joint_count]);
    visit(pb);
  }
}

// The intended-contact bits of a transition's k-1 states: a hand leaving (arriving at) a contact
// may touch during the first (last) third (plan_transition's rule).
std::vector<std::uint8_t> transition_exempt(int k, std::uint8_t exempt_from, std::uint8_t exempt_to) {
  std::vector<std::uint8_t> ex(std::max(0, k - 1), 0);
  for (int i = 1; i < k; ++i) {
    const float tau = static_cast<float>(i) / k;
    if (tau < 0.35f) ex[i - 1] |= exempt_from;
    if (tau > 0.65f) ex[i - 1] |= exempt_to;
  }
  return ex;
}

// The hand's path leaves the hanging rest forward, off the thigh: the wrist's straight line bowed
// forward by this much at its middle (a sine over the way). Straight, the forearm grazed the
// trunk on the way up to the shoulder and the chin (4-7 mm on the project avatar), and those
// rest transitions fell back to the direct path.
constexpr float kHandPathForwardBow_m = 0.05f;
// Where that path is not clear (a wrist line from the thigh to the far ear or hip crosses the
// face or the belly; the interpolated swivel swings the elbow through the chest), it is tried
// again, the swivel searched with the body model round the interpolated one (arm_ik.h
// near_swivel_rad), at the same bow and then bowed 12, 20 and 28 cm forward: a signer brings the
// hand across in front of the body. Measured on the far side's rest transitions (5 hands x 12
// levels x 3 contacts, both rigs): 12 cm clears the flat hand at the far ear on the project
// avatar (5 cm: forearm 12 mm in the head); 28 cm the avatar's fist touching the far shoulder
// top (20 cm: the hand 14 mm in the torso; routed, it took 2.17 s, now 1.30 s). (The fist at the
// far hip needs no retry: solved in the turning trunk's frame, the first form is clear.) The
// wider bows apply to an arm whose wrist travels more than 20 cm: the other arm, moved a few
// centimetres by a turning trunk, keeps its 5 cm.
struct HandPathTry {
  float bow_m;
  bool search_swivel;
  float apart_m;  // hands_apart_dirs: each wrist held off the other hand by this much on the way
  // With apart_m: how far ahead of the way the hand turns to its orientation at the sign
  // (hand_path_waypoint: the share of the way to the sign's times this, at most all of it).
  float turn_ahead;
  // With apart_m: the way's last stretch a straight approach of each hand to its place at the
  // sign, along the line the hands stay clear along (approach_dirs; held apart before it along
  // the line between the palm centres, as the hands-apart tries are), the sign's orientation,
  // elbow and handshape already held: two more waypoints, the wrist kApproachOffsets_m off its
  // place at the sign (plan_hand_path_bowed).
  bool approach = false;
};
constexpr HandPathTry kHandPathTries[] = {{kHandPathForwardBow_m, false, 0.0f, 0.0f},
                                          {kHandPathForwardBow_m, true, 0.0f, 0.0f},
                                          {0.12f, true, 0.0f, 0.0f},
                                          {0.20f, true, 0.0f, 0.0f},
                                          {0.28f, true, 0.0f, 0.0f},
                                          // hands_meet_at_sign's tries, last (hand_path_try_count).
                                          // Measured on the corpus sample (over 5 mm): the first
                                          // two 140 -> 127, the 12 cm ones 124, the two turning
                                          // ahead 1.5 times (the last waypoint at the sign's
                                          // orientation) 120; turning ahead alone, the C pair of
                                          // SynthesisTransition.HandsThatTouchAtTheSign... was deep.
                                          {kHandPathForwardBow_m, true, 0.05f, 1.0f},
                                          {0.12f, true, 0.08f, 1.0f},
                                          {kHandPathForwardBow_m, true, 0.12f, 1.0f},
                                          {0.20f, true, 0.12f, 1.0f},
                                          {kHandPathForwardBow_m, true, 0.05f, 1.5f},
                                          {0.12f, true, 0.08f, 1.5f},
                                          // The same with an approach, after them, so a sign one
                                          // of those clears keeps its clip (the lexicon's all do).
                                          // Measured on the whole corpus (rest-meet, over 5 mm):
                                          // 136 -> 121; put in their place, 132, but 23 signs
                                          // deeper by more than 2 mm (pistolet 0 -> 18.7 mm).
                                          {kHandPathForwardBow_m, true, 0.05f, 1.0f, true},
                                          {0.12f, true, 0.08f, 1.0f, true},
                                          {kHandPathForwardBow_m, true, 0.12f, 1.0f, true},
                                          {0.20f, true, 0.12f, 1.0f, true},
                                          {kHandPathForwardBow_m, true, 0.05f, 1.5f, true},
                                          {0.12f, true, 0.08f, 1.5f, true}};
// The tries above without the hands-apart ones: a rest transition whose sign's hands do not touch
// each other has no use for them.
constexpr int kHandPathPlainTries = 5;
constexpr int kHandPathTryCount = static_cast<int>(sizeof kHandPathTries / sizeof kHandPathTries[0]);
constexpr float kHandPathWideBowFrom_m = 0.20f;

// What one transition's hand-path tries have measured, for its later tries and calls
// (plan_transition asks plan_hand_path twice and plan_hand_path_least_deep once, each from the
// tries in order). All of it is the same arithmetic on the same inputs as measuring again, so
// what is kept is exact:
// - the end poses' depths (the ceilings of every try, and plan_transition's floors);
// - each try's waypoints (arm IK solves), which depend only on the ends and the try;
// - each try's last outcome where it was deeper than its ceilings: its states (k) and the depths
//   of its last pass, measured only until they passed those ceilings. A try whose waypoints are
//   the same bits as such a try's (the swivel search returned the interpolated swivel: 20 of the
//   lexicon's 61 deeper tries) or that try again (plan_hand_path_least_deep) samples the same
//   states, so its depths are at least those: past this call's ceilings, it is deeper without
//   measuring (and with the same states a call that stops at "not shorter" stops: see
//   plan_hand_path_bowed).
struct WaypointBase;
struct HandPathTrials {
  // The same for every try (speed-rest): the ends posed, and each waypoint's direct slerp posed
  // with the trunk's frame there (WaypointBase); the arm solves at the waypoints are the tries'
  // own. Made at the first try that needs them.
  std::unique_ptr<PoseBuilder> from_posed, to_posed;
  // By fraction of the way (the tries with an approach have more waypoints than the others).
  std::vector<std::pair<float, std::unique_ptr<WaypointBase>>> waypoint_bases;
  struct Try {
    std::vector<std::vector<glm::quat>> waypoints;  // empty until solved
    bool deeper = false;
    int k = 0;
    KindDepths depths;
  };
  std::array<Try, kHandPathTryCount> tries;
  bool has_ends = false;
  KindDepths ends_from, ends_to;
  // The approach's line (approach_dirs), found at the first try with an approach (zero before).
  bool has_approach = false;
  std::array<glm::vec3, 2> approach_dir{};
  void measure_ends(const SynthContext& ctx, const glm::quat* from, const glm::quat* to, std::uint8_t exempt_from,
                    std::uint8_t exempt_to) {
    if (has_ends) return;
    ends_from = depths_by_kind(ctx, from, 1, &exempt_from);
    ends_to = depths_by_kind(ctx, to, 1, &exempt_to);
    has_ends = true;
  }
};

bool same_waypoints(const std::vector<std::vector<glm::quat>>& a, const std::vector<std::vector<glm::quat>>& b) {
  if (a.size() != b.size()) return false;
  for (size_t w = 0; w < a.size(); ++w)
    if (a[w].size() != b[w].size() || std::memcmp(a[w].data(), b[w].data(), sizeof(glm::quat) * a[w].size()) != 0)
      return false;
  return true;
}

// The frame of the trunk the arms hang from (the upper chest), in one pose of a transition whose
// ends turn the trunk differently (thorax_turn.h), relative to the rest pose's trunk, in which the
// arm IK and its body model work: `rotation` turns the rest trunk's directions into this pose's,
// to_flat maps a model-space point of this pose into the rest trunk's frame, and `locals` is the
// pose with its trunk chain (the carrier and its ancestors) put back to the rest pose's. Not
// `turned` (both ends' trunks the same bits, as in every transition without a turn): identity.
struct ThoraxFrame {
  bool turned = false;
  glm::quat rotation{1, 0, 0, 0};
  glm::vec3 pivot_posed{0.0f}, pivot_flat{0.0f};
  std::vector<glm::quat> locals;
  glm::vec3 to_flat(const glm::vec3& p) const {
    return turned ? glm::conjugate(rotation) * (p - pivot_posed) + pivot_flat : p;
  }
};
ThoraxFrame thorax_frame(const SynthContext& ctx, const PoseBuilder& posed, const glm::quat* from,
                         const glm::quat* to, const glm::quat* locals) {
  const Rig& rig = ctx.rig;
  const int J = rig.joint_count;
  ThoraxFrame f;
  const ArmRig& a = rig.arms[kRight];
  const int first_arm_joint = a.shoulder >= 0 ? a.shoulder : a.upper;
  if (static_cast<int>(ctx.rest_locals.size()) != J || first_arm_joint < 0) return f;
  const int carrier = rig.parent[first_arm_joint];
  for (int j = carrier; j >= 0; j = rig.parent[j])
    if (std::memcmp(&from[j], &to[j], sizeof(glm::quat)) != 0) f.turned = true;
  if (!f.turned) return f;
  f.locals.assign(locals, locals + J);
  for (int j = carrier; j >= 0; j = rig.parent[j]) f.locals[static_cast<size_t>(j)] = ctx.rest_locals[static_cast<size_t>(j)];
  PoseBuilder flat(rig);
  flat.set_from_local(f.locals.data());
  f.rotation = posed.delta(carrier) * glm::conjugate(flat.delta(carrier));
  f.pivot_posed = posed.position(carrier);
  f.pivot_flat = flat.position(carrier);
  return f;
}

// The elbow's swivel in a posed arm, in solve_arm's convention: the angle of the elbow about the
// shoulder-wrist axis, 0 with the elbow down, positive out to the arm's side; in the rig's zero
// (Rig::fixed_handed_swivel_zero: the usual one, or arm_ik.h swivel_zero's of one handedness on
// both sides of the shoulder joint's coronal plane). A phrase's transitions read every sign's arm
// in the phrase's zero (the usual one), also a sign solved in the other: the reading is of elbow
// positions, so the turn it plans is the same elbow motion whichever zero solved the sign.
// `frame`: the turn of the trunk the arm hangs from (the body's directions turn with it; see
// ThoraxFrame below).
float pose_swivel(const Rig& rig, Side side, const PoseBuilder& pose, const glm::quat& frame = glm::quat(1, 0, 0, 0)) {
  const ArmRig& a = rig.arms[side];
  const glm::vec3 up = frame * rig.up, left = frame * rig.left, forward = frame * rig.forward;
  const glm::vec3 shoulder = pose.position(a.upper);
  const glm::vec3 axis = safe_normalize(pose.position(a.hand) - shoulder, forward);
  const glm::vec3 out_dir = side == kLeft ? left : -left;
  if (rig.fixed_handed_swivel_zero)
    return swivel_of(swivel_zero(axis, up, forward, out_dir, true), pose.position(a.lower) - shoulder);
  // The usual zero as the transitions have always read it (the way down without solve_chain's
  // lean near the upward vertical): main's clips to the bit (docs/SYNTHESIS.md swivel-choice).
  glm::vec3 down = reject(-up, axis);
  if (glm::length(down) < 1e-3f) down = reject(-forward, axis);
  down = glm::normalize(down);
  const glm::vec3 outp = safe_normalize(reject(reject(out_dir, axis), down), glm::cross(axis, down));
  const glm::vec3 elbow = reject(pose.position(a.lower) - shoulder, axis);
  return std::atan2(glm::dot(elbow, outp), glm::dot(elbow, down));
}

// Hands that come together: a rest transition into (or out of) a sign whose hands touch or nearly
// touch each other (kHandsMeetWithin_m) with both wrists moving. On the
// hand's path the two wrists run straight to their places at the sign and the hands meet part
// way, or turn into each other as they close: on the corpus sample 44 of the 56 rest transitions
// over 5 mm were a hand 7-16 mm in the other hand, in frames with no hand-contact exemption (the
// ones read had none on any frame, the key pose itself clear). Seed 004's
// remedy (SOURCES.md section 1, eqs. (8)-(10)) is intermediate states; a signer brings the hands
// together at the end, each approaching the other along the line between them (the contact's
// normal): hands_apart_dirs gives each wrist that direction, away from the other hand, and the
// hands-apart tries of kHandPathTries hold the wrists off by apart_m on the way.
std::array<glm::vec3, 2> hand_centres(const Rig& rig, const PoseBuilder& pose);
// Palm centres closer than this at the sign: hands that touch (the reader does not always mark
// the contact: the corpus's HOUSE1B, symmetric flat hands touching as a roof, has no hand-contact
// exemption at its key pose) or nearly so; a palm is about 10 cm long.
constexpr float kHandsMeetWithin_m = 0.15f;
bool hands_meet_at_sign(const Rig& rig, const PoseBuilder& pf, const PoseBuilder& pt, bool rest_at_start) {
  for (const ArmRig& a : rig.arms)
    if (glm::length(pt.position(a.hand) - pf.position(a.hand)) < 0.01f) return false;  // hand_path_waypoint's "stays"
  const PoseBuilder& sign = rest_at_start ? pt : pf;
  const std::array<glm::vec3, 2> centre = hand_centres(rig, sign);
  return glm::length(centre[0] - centre[1]) < kHandsMeetWithin_m;
}

// The middle of each palm (wrist + half the palm along the fingers) in a pose.
std::array<glm::vec3, 2> hand_centres(const Rig& rig, const PoseBuilder& pose) {
  std::array<glm::vec3, 2> centre;
  for (int s = 0; s < 2; ++s) {
    const ArmRig& a = rig.arms[s];
    centre[s] = pose.position(a.hand) + pose.delta(a.hand) * a.finger_dir * (0.5f * a.palm_length_m);
  }
  return centre;
}

// Per side, the direction from the other hand's centre (the middle of its palm) to this one's at
// the sign's end of the transition: the way this hand keeps off the other on the way. Hands whose
// centres coincide: each to its own side.
std::array<glm::vec3, 2> hands_apart_dirs(const Rig& rig, const PoseBuilder& sign_pose) {
  const std::array<glm::vec3, 2> centre = hand_centres(rig, sign_pose);
  std::array<glm::vec3, 2> dir;
  for (int s = 0; s < 2; ++s)
    dir[s] = safe_normalize(centre[s] - centre[1 - s], s == kLeft ? rig.left : -rig.left);
  return dir;
}

// The line a straight approach of the two hands to the sign takes (HandPathTry::approach): per
// side, the direction this hand comes from. The line between the palm centres (hands_apart_dirs)
// where the hands stay as clear of each other along it as they are at the sign; otherwise the
// candidate line along which they stay clearest (hands_swept_gap, over kApproachSweep_m of the
// hands' relative travel): hands whose parts pass each other at the sign (the corpus's symmetric
// C hands, TO-TOUCH1A: the open thumbs crossed under the palms) go through each other when they
// close along the centre line, whatever the path before. Only the last stretch takes it: the hands
// held apart along it on the way as well (by 5-12 cm, that line often forward and back) put a hand
// into the body, whole corpus over 5 mm 124 against 121 (choinka 3.0 -> 7.9 mm).
constexpr float kApproachSweep_m = 0.24f;
std::array<glm::vec3, 2> approach_dirs(const SynthContext& ctx, const PoseBuilder& sign_pose) {
  const Rig& rig = ctx.rig;
  const std::array<glm::vec3, 2> centre_line = hands_apart_dirs(rig, sign_pose);
  const glm::vec3 c = centre_line[kLeft];
  const float at_sign = hands_swept_gap(ctx.body, sign_pose, c, 0.0f);
  const float floor_m = std::min(at_sign, 0.0f) - 0.001f;
  float best_gap = hands_swept_gap(ctx.body, sign_pose, c, kApproachSweep_m);
  if (best_gap >= floor_m) return centre_line;
  glm::vec3 best = c;
  const glm::vec3 axes[] = {rig.up, -rig.up, rig.forward, -rig.forward, rig.left, -rig.left};
  for (const glm::vec3& axis : axes)
    for (float w : {0.5f, 1.0f, 2.0f, -1.0f}) {
      if (std::fabs(glm::dot(axis, c)) > 0.9f && w > 0.0f) continue;  // about the centre line
      const glm::vec3 dir = w < 0.0f ? axis : safe_normalize(c + w * axis, c);
      const float gap = hands_swept_gap(ctx.body, sign_pose, dir, kApproachSweep_m);
      if (gap > best_gap + 1e-4f) {
        best_gap = gap;
        best = dir;
      }
    }
  return {best, -best};
}

// How much of apart_m a wrist is held off at fraction s of the hand's path: none at either end,
// all of it from s = 0.23 to 0.77 (1.5 sin(pi s) capped at 1), so at every waypoint (0.25, 0.5,
// 0.75), and the hands close only in the last quarter.
float hands_apart_share(float s) { return std::min(1.0f, 1.5f * std::sin(3.14159265f * s)); }

// What a waypoint at the fraction s starts from, the same for every try (HandPathTrials): the
// direct slerp there, posed, and the trunk's frame in it.
struct WaypointBase {
  WaypointBase(const SynthContext& ctx, const glm::quat* from, const glm::quat* to, float s)
      : at(static_cast<size_t>(ctx.rig.joint_count)), pa(ctx.rig), pflat(ctx.rig) {
    for (int j = 0; j < ctx.rig.joint_count; ++j) at[j] = slerp_shortest(from[j], to[j], s);
    pa.set_from_local(at.data());
    // A trunk that turns on the way (thorax_turn.h: a key pose low on the far side) carries the
    // arms with it; the arm IK works with the trunk in its rest pose, so each arm is solved in the
    // trunk's frame at this waypoint (the thorax frame) and its local rotations, relative to the
    // turned trunk, are the same there. Solved in model space instead, the shoulder's own turn was
    // missing from the wrist: the waypoints' wrists 4-6 cm off the path.
    frame_at = thorax_frame(ctx, pa, from, to, at.data());
    if (frame_at.turned) pflat.set_from_local(frame_at.locals.data());
  }
  std::vector<glm::quat> at;
  PoseBuilder pa;
  ThoraxFrame frame_at;
  PoseBuilder pflat;  // posed only where the trunk turns
};

// A waypoint on the hand's own path between two poses (pf, pt: them posed; base: the direct slerp
// there), a fraction `s` of the way: each arm whose wrist moves is re-solved by the arm IK with
// its wrist on the straight line between its end
// positions, its elbow swivel interpolated between the ends' and the hand turned as the direct
// slerp turns it there (an orientation the arm reaches on that path; the model-space slerp of the
// two ends asked for turns beyond the forearm's and wrist's limits on the way up from the rest and
// the IK's clamped hand flipped 2-3 rad between waypoints); every other joint (fingers, an arm
// that stays) on the direct slerp. The swivel is given, not searched: the search (12 or more arm
// solves a waypoint) made a dictionary look-up 65% slower, and the path is checked against the
// body afterwards anyway (plan_hand_path). `previous`: the same arms at the neighbouring waypoint
// already solved, whose wrist angles this one continues (arm_ik.h), or none yet.
std::vector<glm::quat> hand_path_waypoint(const SynthContext& ctx, const WaypointBase& base, const PoseBuilder& pf,
                                          const PoseBuilder& pt, float s, std::array<ArmPose, 2>* previous,
                                          bool has_previous, float bow_m, bool search_swivel,
                                          const ThoraxFrame& frame_from, const ThoraxFrame& frame_to, float apart_m,
                                          const std::array<glm::vec3, 2>& apart_dir, float turn_ahead,
                                          bool sign_at_end, float approach_m,
                                          const std::array<glm::vec3, 2>& approach_dir) {
  // approach_m > 0: a waypoint of an approach (HandPathTry::approach), the wrist that far off its
  // place at the sign along approach_dir, the hand turned and the elbow swivelled as at the sign.
  const Rig& rig = ctx.rig;
  const PoseBuilder& pa = base.pa;
  const ThoraxFrame& frame_at = base.frame_at;
  std::vector<glm::quat> waypoint = base.at;
  const PoseBuilder& solve_pose = frame_at.turned ? base.pflat : pa;
  for (int side_index = 0; side_index < 2; ++side_index) {
    const Side side = static_cast<Side>(side_index);
    const ArmRig& a = rig.arms[side_index];
    const glm::vec3 wrist_from = pf.position(a.hand), wrist_to = pt.position(a.hand);
    // An arm that stays (the other arm at rest) keeps its slerp: 1 cm is below what a frame shows.
    if (glm::length(wrist_to - wrist_from) < 0.01f) continue;
    ArmTarget t;
    const float arm_bow_m = glm::length(wrist_to - wrist_from) > kHandPathWideBowFrom_m ? bow_m : kHandPathForwardBow_m;
    const PoseBuilder& sign_pose = sign_at_end ? pt : pf;
    t.point = frame_at.to_flat(approach_m > 0.0f
                                   ? sign_pose.position(a.hand) + approach_m * approach_dir[side_index]
                                   : wrist_from + s * (wrist_to - wrist_from) +
                                         arm_bow_m * std::sin(3.14159265f * s) * rig.forward +
                                         apart_m * hands_apart_share(s) * apart_dir[side_index]);
    t.contact_offset = glm::vec3(0.0f);
    t.hand_delta = glm::conjugate(frame_at.rotation) * pa.delta(a.hand);
    if (approach_m > 0.0f) {
      t.hand_delta = glm::conjugate(frame_at.rotation) * sign_pose.delta(a.hand);
    } else if (apart_m > 0.0f) {
      // Hands kept apart close in along the line between them; turned towards their orientation
      // at the sign ahead of the way (turn_ahead), so the last quarter mostly closes the gap:
      // turning while closing, the hand-written C pair of SynthesisTransition.HandsThatTouch...
      // stayed 5.5 mm deep with the wrists apart (6.8 before).
      const PoseBuilder& sign = sign_at_end ? pt : pf;
      const float w = std::min(1.0f, turn_ahead * (sign_at_end ? s : 1.0f - s));
      t.hand_delta = glm::conjugate(frame_at.rotation) * slerp_shortest(pa.delta(a.hand), sign.delta(a.hand), w);
    }
    t.auto_swivel = false;
    const float swivel_from = pose_swivel(rig, side, pf, frame_from.rotation);
    float turn = pose_swivel(rig, side, pt, frame_to.rotation) - swivel_from;  // the shorter way round
    if (turn > 3.14159265f) turn -= 6.28318531f;
    if (turn < -3.14159265f) turn += 6.28318531f;
    t.swivel_rad = swivel_from + s * turn;
    if (approach_m > 0.0f) t.swivel_rad = sign_at_end ? swivel_from + turn : swivel_from;
    if (search_swivel) {
      // A retry's arm: the swivel searched round the interpolated one, with the body model,
      // so the elbow keeps out of the trunk where the interpolated swivel does not.
      t.auto_swivel = true;
      t.body = &ctx.body;
      t.has_near_swivel = true;
      t.near_swivel_rad = t.swivel_rad;
    }
    ArmPose& arm = (*previous)[side_index];
    if (has_previous) {
      // Wrist angles move at most 0.8 rad from the neighbouring waypoint (a quarter of the way
      // between them; the wrist's whole flexion range is 2.4 rad).
      t.previous = &arm;
      t.max_wrist_step_rad = 0.8f;
    }
    arm = solve_arm(rig, side, t);
    // `at` posed is pa as it stands (this loop changes no joint of it): a copy, not a second FK.
    PoseBuilder solved = solve_pose;
    apply_arm(rig, side, arm, &solved);
    for (int j : {a.shoulder, a.upper, a.lower, a.hand})
      if (j >= 0) waypoint[j] = solved.local_rotation(j);  // only the arm's joints are taken
  }
  return waypoint;
}

// Waypoints on the hand's path per rest transition: 3 (at a quarter, half, three quarters). ME's
// raise on the project avatar takes 29 states with 2, 28 with 3, 4 or 5 (46 direct), the
// lexicon's median no lower with more; each costs an arm solve.
constexpr int kHandPathWaypoints = 3;
// The approach's waypoints (HandPathTry::approach): at these fractions of the way from the sign's
// end, the wrist this far off its place at the sign. Between them and the key pose the arm's
// joints change so little that their slerp is about the straight approach; from the last
// hands-apart waypoint (a quarter of the way out, 5-12 cm apart) it was not, and the hands closed
// into each other there (docs/SYNTHESIS.md, rest-meet). Not tuned.
constexpr std::array<float, 2> kApproachFractions = {0.03f, 0.10f};
constexpr std::array<float, 2> kApproachOffsets_m = {0.01f, 0.03f};
// With an approach, every joint but the arms' (the fingers' shape) reaches the sign's this share
// of the way from the sign's end (plan_hand_path_bowed): a signer forms the hand before the hands
// meet. Without it the corpus had as many signs over 5 mm, but SKY-OR-HEAVEN2A 4.6 mm (0.3 with).
constexpr float kApproachLead = 0.25f;

// The fastest a finger or fingertip moves on a rest transition's hand path (its peak, not its
// mean; the arm keeps eq. (10)'s minimum-jerk profile). Peak hand speeds in fluent signing are
// about 2-3 m/s (motion-capture studies of ASL/DGS signers; MotionSmoothness holds every tracked
// point to 3 m/s, 10 cm a frame at 30 fps): 2.5 m/s leaves a sixth of that for the frames'
// rounding. Measured over the lexicon's rest transitions: 2.2 m/s made ME's raise 0.83 s on the
// project avatar, 2.5 m/s 0.73 s, 2.8 m/s 0.63 s with a fingertip at 98.6 mm a frame (WOMAN).
constexpr float kHandPathFingerPeakMPerS = 2.5f;

// The first measure pass of a rest transition's hand path takes this much over the states its
// sampled peaks ask for (plan_hand_path_bowed). The fingers' need the states then measure, over the
// estimate (the lexicon's 696 passes, project avatar): median 0.993, 90th percentile 1.03, 95th
// 1.055, worst 1.10. At 1, 107 of the lexicon's 686 first passes are stretched and taken again
// (675 of 708 before) and its clips have 0.66 % more frames; at 1.03, 45, but 2.1 % more frames.
constexpr float kFirstPassStatesMargin = 1.0f;

// A finger's or fingertip's longest step a frame on a rest transition: kHandPathFingerPeakMPerS,
// scaled as eq. (10)'s k is (the global speed divides every duration) below speed 1, and not
// above it: a faster signer's hand is no faster than a human hand. Scaled by 1.25, the peak was
// 3.1 m/s and 605 of the lexicon's 846 sign-settings at speed 1.25 (both rigs, 25/30/60 fps) had
// a fingertip over the 3 m/s bound in a rest transition (up to 3.48 m/s, MAN's middle tip).
float finger_peak_step_m(float fps, float speed) { return kHandPathFingerPeakMPerS * std::min(speed, 1.0f) / fps; }

// The longest step a frame any joint may take on a path of eq. (10)'s L_max in k states: a single
// minimum-jerk profile peaks at 1.875 times the mean speed, +10 % (plan_chain's rule).
float profile_peak_step_m(float lmax_m, int k) { return 1.875f * lmax_m / k * 1.1f; }

// Which joints are arm joints (arm_joint_list), by joint index: the joints eq. (10)'s L_max is
// measured on for a rest transition, whose coef is a hand speed.
std::vector<bool> arm_joint_mask(const Rig& rig) {
  std::vector<bool> mask(static_cast<size_t>(rig.joint_count), false);
  for (int j : arm_joint_list(rig)) mask[static_cast<size_t>(j)] = true;
  return mask;
}

// A rest transition that does not take the hand's path (plan_hand_path: not shorter, or not clear
// of the body at any try) is timed as the hand's path is: eq. (10)'s L_max the arm joints' path
// (coef's 1 m/s is a hand speed), states added where an arm joint outruns the minimum-jerk peak
// (1.875 times the mean, plan_chain's rule) or a finger or fingertip kHandPathFingerPeakMPerS,
// then stretched until no arm joint accelerates beyond kArmPeakAccelMPerS2. Timed by its
// fingertips' path instead (the longest joint path, the index tip swinging up from hanging), the
// direct path and the via-poses took 1.2-1.4 s where the hand's path takes 0.7-0.9 (DAY's hands
// leaving each other for the rest: 1.43 s on the reference humanoid), and the far side's routed
// pointing touches 3.6-3.8 s. `chain`: a path with corners (stretch_for_arm_accel).
// `scratch`: the walk's buffers and the rig's joint lists, kept by plan_transition for its many
// candidates (each of LOVE's 26 via candidates is timed so; allocated per call, they were most of
// the walk's cost beyond the poses). Filled at the first use.
struct RestPathScratch {
  void prepare(const Rig& rig) {
    if (!prev.empty() || rig.joint_count == 0) return;
    arm_joints = arm_joint_mask(rig);
    points = accel_point_list(rig);
    prev.resize(static_cast<size_t>(rig.joint_count));
  }
  std::vector<bool> arm_joints;
  AccelPoints points;
  std::vector<glm::vec3> prev, accel_pos;
};
template <typename Sampler>
void time_rest_path_by_arm(const Rig& rig, const glm::quat* from, const glm::quat* to, float fps, float speed,
                           Sampler sample, bool chain, RestPathScratch* scratch, TransitionPlan* p) {
  const int J = rig.joint_count;
  scratch->prepare(rig);
  const std::vector<bool>& arm_joints = scratch->arm_joints;
  p->lmax_m = path_length(rig, from, to, sample, &arm_joints);
  p->k = transition_states(p->lmax_m, fps, speed);
  sample(p->k, &p->frames);
  // The longest step a frame of an arm joint and of any other joint (fingers, fingertips). The
  // same walk keeps the acceleration measure's points (arm_accel's positions, the same bits as
  // its own pose of them: SubsetPose), so where the states stay, its first round poses nothing.
  float arm_step_m = 0.0f, finger_step_m = 0.0f;
  const AccelPoints& points = scratch->points;
  const size_t n_points = points.joints.size();
  std::vector<glm::vec3>& accel_pos = scratch->accel_pos;
  accel_pos.resize(static_cast<size_t>(p->k + 1) * n_points);
  {
    PoseBuilder pb(rig);
    std::vector<glm::vec3>& prev = scratch->prev;
    for (int i = 0; i <= p->k; ++i) {
      pb.set_from_local(i == 0 ? from : i == p->k ? to : &p->frames[static_cast<size_t>(i - 1) * J]);
      for (size_t n = 0; n < n_points; ++n)
        accel_pos[static_cast<size_t>(i) * n_points + n] = points.scale[n] * pb.position(points.joints[n]);
      for (int j = 0; j < J; ++j) {
        const glm::vec3& cur = pb.position(j);
        if (i > 0) {
          float& longest = arm_joints[static_cast<size_t>(j)] ? arm_step_m : finger_step_m;
          longest = std::max(longest, glm::length(cur - prev[static_cast<size_t>(j)]));
        }
        prev[static_cast<size_t>(j)] = cur;
      }
    }
  }
  const float peak_step_m = profile_peak_step_m(p->lmax_m, p->k);
  const float finger_peak_m = finger_peak_step_m(fps, speed);
  const float stretch = std::max(arm_step_m / peak_step_m, finger_step_m / finger_peak_m);
  const bool resampled = stretch > 1.0f;
  if (resampled) {
    p->k = static_cast<int>(std::ceil(p->k * stretch));
    sample(p->k, &p->frames);
  }
  stretch_for_arm_accel(rig, from, to, fps, sample, chain, &p->k, &p->frames, resampled ? nullptr : &accel_pos);
}

// interpolate_chain's path through the hand-path waypoints, computed for what differs: the
// waypoints differ from the direct slerp only in the arm joints (shoulder, upper arm, forearm,
// hand), so every other joint's pieces lie on its one slerp arc from `from` to `to`, and a piece
// or the cross-fade of two is that arc at a mixed fraction: one slerp a joint, as on the direct
// path, instead of two or three (sampling the chain whole made a dictionary look-up 40% slower).
// The knots' shares of the path are measured once.
class HandChain {
 public:
  // pf, pt: `from` and `to` posed (the caller has them already).
  HandChain(const Rig& rig, const glm::quat* from, const glm::quat* to, const PoseBuilder& pf, const PoseBuilder& pt,
            const std::vector<std::vector<glm::quat>>& waypoints, const std::vector<float>& fractions)
      : rig_(rig), s_{0.0f} {
    knots_.push_back(from);
    for (const auto& w : waypoints) knots_.push_back(w.data());
    knots_.push_back(to);
    s_.insert(s_.end(), fractions.begin(), fractions.end());
    s_.push_back(1.0f);
    u_.push_back(0.0f);
    // transition_lmax between neighbouring knots, each knot posed once (transition_lmax poses
    // both of its ends, so every waypoint twice and the ends again): the same positions, the
    // same arithmetic.
    const int J = rig.joint_count;
    std::vector<glm::vec3> prev(J), cur(J);
    for (int j = 0; j < J; ++j) prev[j] = pf.position(j);
    PoseBuilder pw(rig);
    for (size_t i = 1; i < knots_.size(); ++i) {
      const PoseBuilder* posed = &pt;
      if (i + 1 < knots_.size()) {
        pw.set_from_local(knots_[i]);
        posed = &pw;
      }
      float lmax = 0.0f;
      for (int j = 0; j < J; ++j) {
        cur[j] = posed->position(j);
        lmax = std::max(lmax, glm::length(prev[j] - cur[j]));
      }
      u_.push_back(u_.back() + lmax + 1e-6f);
      std::swap(prev, cur);
    }
    for (float& x : u_) x /= u_.back();
    half_.assign(knots_.size(), 0.0f);
    for (size_t i = 1; i + 1 < knots_.size(); ++i) half_[i] = 0.45f * std::min(u_[i] - u_[i - 1], u_[i + 1] - u_[i]);
    arm_joint_.assign(static_cast<size_t>(rig.joint_count), false);
    for (const ArmRig& a : rig.arms)
      for (int j : {a.shoulder, a.upper, a.lower, a.hand})
        if (j >= 0) arm_joint_[static_cast<size_t>(j)] = true;
    direct_.reserve(static_cast<size_t>(rig.joint_count));
    for (int j = 0; j < rig.joint_count; ++j) direct_.emplace_back(from[j], to[j]);
    // Each arm joint's slerp along each piece, set up once: the chain is sampled several times
    // (its length, its states, their re-timing and the phases between them).
    for (int j = 0; j < rig.joint_count; ++j) {
      if (!arm_joint_[static_cast<size_t>(j)]) continue;
      piece_joint_.push_back(j);
      for (size_t p = 0; p + 1 < knots_.size(); ++p) pieces_.emplace_back(knots_[p][j], knots_[p + 1][j]);
    }
    piece_of_joint_.assign(static_cast<size_t>(rig.joint_count), -1);
    for (size_t n = 0; n < piece_joint_.size(); ++n) piece_of_joint_[static_cast<size_t>(piece_joint_[n])] = static_cast<int>(n);
  }
  // The k-1 intermediate states (interpolate_chain's form).
  void sample(int k, std::vector<glm::quat>* out) const {
    const int J = rig_.joint_count;
    const size_t pieces = knots_.size() - 1;
    // slerp_shortest(knots_[p][j], knots_[p + 1][j], ...) set up once (JointSlerp): bit-identical.
    auto piece = [&](size_t p, int j, float e) {
      const JointSlerp& path = pieces_[static_cast<size_t>(piece_of_joint_[static_cast<size_t>(j)]) * pieces + p];
      glm::quat q;
      math::lanes::store4(&q, path.at((e - u_[p]) / (u_[p + 1] - u_[p])));
      return q;
    };
    auto fraction = [&](size_t p, float e) { return s_[p] + (e - u_[p]) / (u_[p + 1] - u_[p]) * (s_[p + 1] - s_[p]); };
    out->resize(static_cast<size_t>(std::max(0, k - 1)) * J);
    float first_s = -1.0f;
    for (int i = 1; i < k; ++i) {
      const float e = minimum_jerk(static_cast<float>(i) / k);
      size_t seg = 0;
      while (seg + 1 < pieces && e > u_[seg + 1]) ++seg;
      size_t knot = 0;
      for (size_t n = 1; n < pieces; ++n)
        if (std::fabs(e - u_[n]) < half_[n]) knot = n;
      const float x = knot ? (e - (u_[knot] - half_[knot])) / (2.0f * half_[knot]) : 0.0f;
      const float fade = x * x * (3.0f - 2.0f * x);
      const float s = knot ? fraction(knot - 1, e) + fade * (fraction(knot, e) - fraction(knot - 1, e)) : fraction(seg, e);
      if (i == 1) first_s = s;
      glm::quat* state = &(*out)[static_cast<size_t>(i - 1) * J];
      for (int j = 0; j < J; ++j) {
        if (!arm_joint_[static_cast<size_t>(j)]) {
          // A joint that does not move (JointSlerp::constant) has the same sample at every s > 0
          // (interpolate_direct's rule): copied from the first state.
          if (i > 1 && s > 0.0f && first_s > 0.0f && direct_[static_cast<size_t>(j)].constant)
            state[j] = (*out)[static_cast<size_t>(j)];
          else
            math::lanes::store4(&state[j], direct_[static_cast<size_t>(j)].at(s));
          continue;
        }
        const glm::quat q = knot ? slerp_shortest(piece(knot - 1, j, e), piece(knot, j, e), fade) : piece(seg, j, e);
        state[j] = glm::normalize(q);
      }
    }
  }

 private:
  const Rig& rig_;
  std::vector<const glm::quat*> knots_;
  std::vector<float> s_, u_, half_;
  std::vector<bool> arm_joint_;
  std::vector<JointSlerp> direct_;  // each joint's direct slerp, set up once
  // The arm joints' slerps along the pieces: pieces_[n * pieces + p] for arm joint
  // piece_joint_[n] (piece_of_joint_[j] = n), piece p.
  std::vector<int> piece_joint_, piece_of_joint_;
  std::vector<JointSlerp> pieces_;
};

// transition_path_m's measurement of the direct path, walked only as far as a question needs:
// whether the direct path takes more states than some k. A joint's length only grows along the
// walk, so once the longest so far asks for more than k states the whole path does, and the
// rest of the walk (an FK pass a sample) is skipped when the hand's path is taken. Walked to its
// end it gives transition_path_m's value bit for bit (same samples, same sums, in the same order).
class DirectPathLength {
 public:
  DirectPathLength(const Rig& rig, const glm::quat* from, const glm::quat* to, float fps, float speed)
      : rig_(rig), from_(from), to_(to), fps_(fps), speed_(speed), pb_(rig),
        row_(static_cast<size_t>(rig.joint_count)), prev_(static_cast<size_t>(rig.joint_count)),
        length_(static_cast<size_t>(rig.joint_count), 0.0f) {
    path_.reserve(static_cast<size_t>(rig.joint_count));
    for (int j = 0; j < rig.joint_count; ++j) path_.emplace_back(from[j], to[j]);
  }
  // Whether the direct path needs more than k states (transition_states of its length).
  bool states_exceed(int k) {
    while (transition_states(longest_, fps_, speed_) <= k && next_ <= kPathSamples) step();
    return transition_states(longest_, fps_, speed_) > k;
  }
  // The whole path's length (transition_path_m).
  float length_m() {
    while (next_ <= kPathSamples) step();
    return longest_;
  }

 private:
  void step() {
    const int J = rig_.joint_count;
    const int i = next_++;
    if (i > 0 && i < kPathSamples) {
      // interpolate_direct's sample i, made when it is walked to: a joint that does not move
      // keeps its first sample, as interpolate_direct copies it.
      const float e = minimum_jerk(static_cast<float>(i) / kPathSamples);
      for (int j = 0; j < J; ++j)
        if (i == 1 || !path_[static_cast<size_t>(j)].constant)
          math::lanes::store4(&row_[static_cast<size_t>(j)], math::lanes::quat_normalize(path_[static_cast<size_t>(j)].at(e)));
    }
    pb_.set_from_local(i == 0 ? from_ : i == kPathSamples ? to_ : row_.data());
    for (int j = 0; j < J; ++j) {
      if (i > 0 && !pb_.recomputed(j)) continue;  // path_length's rule: an exact 0 chord
      const glm::vec3& cur = pb_.position(j);
      if (i > 0) {
        length_[static_cast<size_t>(j)] += glm::length(cur - prev_[static_cast<size_t>(j)]);
        longest_ = std::max(longest_, length_[static_cast<size_t>(j)]);
      }
      prev_[static_cast<size_t>(j)] = cur;
    }
  }
  const Rig& rig_;
  const glm::quat *from_, *to_;
  float fps_, speed_;
  PoseBuilder pb_;
  std::vector<JointSlerp> path_;  // each joint's direct slerp (interpolate_direct's)
  std::vector<glm::quat> row_;    // the sample being walked
  std::vector<glm::vec3> prev_;
  std::vector<float> length_;
  float longest_ = 0.0f;
  int next_ = 0;
};

// A rest transition along the hand's path: the direct slerp's joints replaced by a chain through
// waypoints on the hand's own path (hand_path_waypoint), eq. (10)'s k along the joints' path of
// that chain, states added where a joint would outrun the minimum-jerk peak (as for the routed
// chains). The waypoints are solved from the sign's end towards the rest, each continuing from
// the one before: the key pose's arm is the one to match (the rest's hanging arm is reached from
// any swivel), and solved from the rest the IK's wrist flipped on the way up (ME's raise then
// needed more states than the direct path and was not taken; its lowering, solved from the key
// pose, 28). Taken (true) only when it needs fewer states than the direct path and adds no depth, of
// either kind, beyond the end poses' own (0.5 mm): otherwise the direct path and its routing
// stand, so the collision remedies are unchanged wherever the hand's path is not clear.
bool plan_hand_path_bowed(const SynthContext& ctx, const glm::quat* from, const glm::quat* to, bool rest_at_start,
                          std::uint8_t exempt_from, std::uint8_t exempt_to, DirectPathLength* direct, int try_index,
                          HandPathTrials* trials, bool allow_longer, TransitionPlan* out, bool* deeper,
                          float added_m = 0.0005f) {
  *deeper = false;
  const Rig& rig = ctx.rig;
  const int J = rig.joint_count;
  const float fps = ctx.options.fps, speed = ctx.options.speed;
  const HandPathTry& attempt = kHandPathTries[try_index];
  HandPathTrials::Try& record = trials->tries[static_cast<size_t>(try_index)];
  std::vector<float> fractions(kHandPathWaypoints), approach_m(kHandPathWaypoints, 0.0f);
  for (int w = 0; w < kHandPathWaypoints; ++w) fractions[w] = static_cast<float>(w + 1) / (kHandPathWaypoints + 1);
  const bool approach = attempt.approach;
  if (approach) {
    // The approach's waypoints beside the sign's end, in the path's order.
    for (size_t n = 0; n < kApproachFractions.size(); ++n) {
      const size_t i = rest_at_start ? kApproachFractions.size() - 1 - n : n;
      const float f = rest_at_start ? 1.0f - kApproachFractions[i] : kApproachFractions[i];
      if (rest_at_start) {
        fractions.push_back(f);
        approach_m.push_back(kApproachOffsets_m[i]);
      } else {
        fractions.insert(fractions.begin() + static_cast<long>(n), f);
        approach_m.insert(approach_m.begin() + static_cast<long>(n), kApproachOffsets_m[i]);
      }
    }
  }
  const int waypoint_count = static_cast<int>(fractions.size());
  // The fingers' (and every joint's but the arms') share of the way at each waypoint: with an
  // approach, the hand has its sign's shape before the last stretch (a signer forms the hand
  // before the hands meet, and parts them before it relaxes).
  std::vector<float> finger_s = fractions;
  if (approach)
    for (float& f : finger_s)
      f = rest_at_start ? std::min(1.0f, f / (1.0f - kApproachLead)) : std::max(0.0f, (f - kApproachLead) / (1.0f - kApproachLead));
  if (!trials->from_posed) {
    trials->from_posed = std::make_unique<PoseBuilder>(rig);
    trials->to_posed = std::make_unique<PoseBuilder>(rig);
    trials->from_posed->set_from_local(from);
    trials->to_posed->set_from_local(to);
  }
  const PoseBuilder& pf = *trials->from_posed;
  const PoseBuilder& pt = *trials->to_posed;
  if (approach && !trials->has_approach) {
    trials->approach_dir = approach_dirs(ctx, rest_at_start ? pt : pf);
    trials->has_approach = true;
  }
  if (record.waypoints.empty()) {
    record.waypoints.resize(static_cast<size_t>(waypoint_count));
    std::array<ArmPose, 2> solved_arms;
    const ThoraxFrame frame_from = thorax_frame(ctx, pf, from, to, from);
    const ThoraxFrame frame_to = thorax_frame(ctx, pt, from, to, to);
    const std::array<glm::vec3, 2> apart_dir =
        attempt.apart_m > 0.0f ? hands_apart_dirs(rig, rest_at_start ? pt : pf) : std::array<glm::vec3, 2>{};
    for (int i = 0; i < waypoint_count; ++i) {
      const int w = rest_at_start ? waypoint_count - 1 - i : i;
      WaypointBase* base = nullptr;
      for (auto& b : trials->waypoint_bases)
        if (b.first == finger_s[w]) base = b.second.get();
      if (!base) {
        trials->waypoint_bases.emplace_back(finger_s[w], std::make_unique<WaypointBase>(ctx, from, to, finger_s[w]));
        base = trials->waypoint_bases.back().second.get();
      }
      record.waypoints[w] = hand_path_waypoint(ctx, *base, pf, pt, fractions[w], &solved_arms, i > 0, attempt.bow_m,
                                               attempt.search_swivel, frame_from, frame_to, attempt.apart_m, apart_dir,
                                               attempt.turn_ahead, rest_at_start, approach_m[w], trials->approach_dir);
    }
  }
  const std::vector<std::vector<glm::quat>>& waypoints = record.waypoints;
  // What the end poses themselves have: a pass deeper than this, of either kind, is not taken
  // (`deeper`), so once a pass's depth of one kind exceeds it the rest of its states' checks
  // cannot change the outcome (depths only grow along the pass) and are skipped.
  // added_m: 0.5 mm (plan_transition's kNothingAdded_m: sampling), or what the caller still
  // accepts (plan_hand_path_least_deep).
  trials->measure_ends(ctx, from, to, exempt_from, exempt_to);
  const float hand_ceiling_m = std::max(trials->ends_from.hand_m, trials->ends_to.hand_m) + added_m;
  const float arm_ceiling_m = std::max(trials->ends_from.arm_m, trials->ends_to.arm_m) + added_m;
  auto is_deeper = [&](const KindDepths& d) { return d.hand_m > hand_ceiling_m || d.arm_m > arm_ceiling_m; };
  // A try already measured deeper with these waypoints (HandPathTrials): the same states, whose
  // depths are at least what that measure found. Without allow_longer, this call would stop at
  // "not shorter" as soon as a k of its passes (they only grow, to the one kept) is not fewer
  // than the direct path's states; where even the last is fewer, it reaches the same end.
  for (const HandPathTrials::Try& earlier : trials->tries)
    if (earlier.deeper && (&earlier == &record || same_waypoints(earlier.waypoints, waypoints)) &&
        is_deeper(earlier.depths) && (allow_longer || direct->states_exceed(earlier.k))) {
      *deeper = true;
      return false;
    }
  record.deeper = false;
  // A retry (every try after the first) whose waypoints themselves are deeper than the ceilings is
  // taken as deeper without sampling its chain (speed-rest). The chain runs through each waypoint
  // (the cross-fade at a knot passes next to it), so its states there are about as deep; a retry
  // is asked where the tries before it were deep, and there the waypoints of the wider bows are
  // often in the body themselves. Each waypoint is checked with both ends' exemptions (the most
  // any state of the path has), so no state there is checked more leniently. Not exact: a chain's
  // states can miss a deep waypoint's neighbourhood; measured against sampling every try
  // (docs/SYNTHESIS.md, speed-rest): no corpus sign over 1 mm deeper, the lexicon's clips
  // unchanged. The first try is not checked: the lexicon's 282 rest transitions make 343 tries,
  // most take their first, and there the three poses cost more than they save.
  if (try_index > 0) {
    const std::uint8_t either_end = exempt_from | exempt_to;
    for (const std::vector<glm::quat>& waypoint : waypoints) {
      const KindDepths at_waypoint = depths_by_kind(ctx, waypoint.data(), 1, &either_end);
      if (is_deeper(at_waypoint)) {
        // Recorded as a try found deeper at no states (k = 0): HandPathTrials's shortcut then
        // answers it as this check would, whatever the direct path's length.
        record.deeper = true;
        record.k = 0;
        record.depths = at_waypoint;
        *deeper = true;
        return false;
      }
    }
  }
  const HandChain chain(rig, from, to, pf, pt, waypoints, finger_s);
  auto sample = [&](int k, std::vector<glm::quat>* frames) { chain.sample(k, frames); };
  // Eq. (10)'s L_max on the hand's path is the arm's: the longest path of the shoulder girdle,
  // upper arm, forearm and wrist joints (the hand joint is the wrist). coef's 1 m/s is a mean
  // HAND speed (the wrist marker of the motion-capture literature), and on the way up from the
  // rest the fingertips travel 2.2 times the wrist's path as the hand turns from hanging to its
  // sign (ME on the project avatar: index tip 0.97 m, wrist 0.44 m): counted, that turn set k and
  // ME's raise took 1.0 s where a signer takes 0.6-0.8 s. The fingers are held to a human speed
  // by the peak rule below instead (kHandPathFingerPeakMPerS).
  const std::vector<bool> arm_joints = arm_joint_mask(rig);
  const float finger_peak_m = finger_peak_step_m(fps, speed);
  TransitionPlan p;
  // The fingertips' steps between the path-length samples: those samples are states of the same
  // minimum-jerk timing (sample i at e = minimum_jerk(i / kPathSamples), as state i of k at
  // minimum_jerk(i / k)), so the longest chord times kPathSamples is the fingertips' peak travel
  // in the transition's time, and k states step about that over k a frame.
  std::vector<int> tips;
  for (const ArmRig& a : rig.arms)
    for (const FingerChain& finger : a.fingers) {
      const int j = finger.tip >= 0 ? finger.tip : finger.bones[2];
      if (j >= 0) tips.push_back(j);
    }
  ArmPathAndTipStep measured;
  {
    std::vector<glm::quat> samples;
    sample(kPathSamples, &samples);
    measured = arm_path_and_tip_step(rig, from, to, samples, arm_joints, tips);
  }
  p.lmax_m = measured.arm_m;
  p.k = transition_states(p.lmax_m, fps, speed);
  // The arm's own rule (eq. (10)) and the steps the arm may take at that k (plan_chain's peak
  // rule: the minimum-jerk peak of L_max in eq. (10)'s k states, +10 %).
  const float peak_step_m = profile_peak_step_m(p.lmax_m, p.k);
  // The first measure pass at the states the fingers and the arm's steps ask for, where they ask
  // for more than eq. (10): before, it was taken at eq. (10)'s k and thrown away in 334 of the
  // lexicon's 350 passes (307 for the finger peak, 17 for the arm's), its states sampled, posed and
  // partly checked again. The estimates (kFirstPassStatesMargin over the sampled peaks) are
  // measured on the states like any others, and stretched further where they fall short.
  const float sampled_states = kFirstPassStatesMargin * kPathSamples;
  p.k = std::max({p.k, static_cast<int>(std::ceil(sampled_states * measured.tip_step_m / finger_peak_m)),
                  static_cast<int>(std::ceil(sampled_states * measured.arm_step_m / peak_step_m))});
  if (!allow_longer && !direct->states_exceed(p.k)) return false;
  // One pass over the states: the longest joint step of a frame (plan_chain's peak rule) and
  // the depths of each kind (depths_by_kind's measure).
  // Each state's deepest check in max_penetration's terms, for the memo of the phrase's final
  // check (PenetrationMemo), which would otherwise pose and check these states again.
  std::vector<PenetrationMemo::Result> deepest;
  // `abandon_step_m`: a step longer than this means the states are sampled again (more of
  // them) and this pass's depths are thrown away, so past it only the steps are measured.
  // `step_m`: the longest step of an arm joint; `finger_step_m`: of any other joint.
  // `accel_mps2`: the arm joints' largest acceleration (kArmPeakAccelMPerS2's measure),
  // the transition's ends held before and after it as the clip holds them.
  float finger_step_m = 0.0f, accel_mps2 = 0.0f;
  const AccelPoints accel_points = accel_point_list(rig);
  const size_t arms_n = accel_points.joints.size();
  std::vector<glm::vec3> arm_pos;
  // The arm-joint mask as bytes (a std::vector<bool> costs a shift and a mask per read) for the
  // step loop below, which reads it for every joint of every state.
  const std::vector<char> arm_joint_bytes(arm_joints.begin(), arm_joints.end());
  auto measure = [&](float* step_m, KindDepths* d, float abandon_step_m, float abandon_finger_step_m) {
    PoseBuilder pb(rig);
    std::vector<glm::vec3> prev(J);
    *step_m = 0.0f;
    finger_step_m = 0.0f;
    *d = KindDepths{};
    deepest.assign(static_cast<size_t>(std::max(0, p.k - 1)), PenetrationMemo::Result{});
    arm_pos.resize(static_cast<size_t>(p.k + 1) * arms_n);
    for (int i = 0; i <= p.k; ++i) {
      pb.set_from_local(i == 0 ? from : i == p.k ? to : &p.frames[static_cast<size_t>(i - 1) * J]);
      for (size_t n = 0; n < arms_n; ++n)
        arm_pos[static_cast<size_t>(i) * arms_n + n] =
            accel_points.scale[n] * pb.position(accel_points.joints[n]);
      // The longest steps as squares, one square root per kind and state: glm::length is the
      // square root of glm::dot, and the square root keeps the order (IEEE, correctly rounded),
      // so the root of the largest square is the largest length to the bit.
      float arm_step_sq = 0.0f, finger_step_sq = 0.0f;
      for (int j = 0; j < J; ++j) {
        const glm::vec3& cur = pb.position(j);
        if (i > 0) {
          const glm::vec3 step = cur - prev[static_cast<size_t>(j)];
          float& longest_sq = arm_joint_bytes[static_cast<size_t>(j)] ? arm_step_sq : finger_step_sq;
          longest_sq = std::max(longest_sq, glm::dot(step, step));
        }
        prev[static_cast<size_t>(j)] = cur;
      }
      if (i > 0) {
        *step_m = std::max(*step_m, std::sqrt(arm_step_sq));
        finger_step_m = std::max(finger_step_m, std::sqrt(finger_step_sq));
      }
      if (i == 0 || i == p.k || *step_m > abandon_step_m || finger_step_m > abandon_finger_step_m) continue;
      if (is_deeper(*d)) continue;
      const std::uint8_t ex = p.exempt[static_cast<size_t>(i - 1)];
      for (int side_index = 0; side_index < 2; ++side_index) {
        const Side side = static_cast<Side>(side_index);
        const bool trunk = !(ex & exempt_bit(side, false));
        const bool hands = !(ex & exempt_bit(side, true)) && !(ex & exempt_bit(other(side), true));
        Penetration hand = hand_penetration(ctx.body, pb, side, trunk, hands);
        Penetration arm = arm_penetration(ctx.body, pb, side, true, !trunk, hands && side_index == 0);
        d->hand_m = std::max(d->hand_m, hand.depth_m);
        d->arm_m = std::max(d->arm_m, arm.depth_m);
        PenetrationMemo::Result& r = deepest[static_cast<size_t>(i - 1)];
        if (hand.depth_m > r.depth_m) {
          r.depth_m = hand.depth_m;
          r.what = (side == kLeft ? "left hand in " : "right hand in ") + hand.what;
        }
        if (arm.depth_m > r.depth_m) {
          r.depth_m = arm.depth_m;
          r.what = std::move(arm.what);
        }
      }
    }
    accel_mps2 = arm_accel_of(arm_pos, arms_n, p.k, fps);
  };
  sample(p.k, &p.frames);
  p.exempt = transition_exempt(p.k, exempt_from, exempt_to);
  float step_m = 0.0f;
  KindDepths d;
  measure(&step_m, &d, peak_step_m, finger_peak_m);
  float stretch = std::max({step_m / peak_step_m, finger_step_m / finger_peak_m,
                            std::sqrt(accel_mps2 / kArmPeakAccelMPerS2)});
  // The step rules and the acceleration, on the states and between them, together; then the
  // acceleration alone, measured again on the new states (kAccelRounds).
  for (int round = 0; round < kAccelRounds; ++round) {
    // The first round's states are stretched by the step rules anyway where they ask for more.
    if ((round > 0 || stretch <= 1.0f) && accel_mps2 > kAccelBetweenFrom * kArmPeakAccelMPerS2) {
      const float between = arm_accel_between_states(rig, from, to, sample, p.k, fps);
      stretch = std::max(stretch, std::sqrt(between / kArmPeakAccelMPerS2));
    }
    if (stretch <= 1.0f) break;
    p.k = static_cast<int>(std::ceil(p.k * stretch));
    if (!allow_longer && !direct->states_exceed(p.k)) return false;
    sample(p.k, &p.frames);
    p.exempt = transition_exempt(p.k, exempt_from, exempt_to);
    measure(&step_m, &d, std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity());
    stretch = std::sqrt(accel_mps2 / kArmPeakAccelMPerS2);
  }
  p.via_points = waypoint_count;
  if (is_deeper(d)) {
    record.deeper = true;
    record.k = p.k;
    record.depths = d;
    *deeper = true;
    return false;
  }
  p.max_penetration_m = std::max(d.hand_m, d.arm_m);
  if (PenetrationMemo* memo = ctx.penetration_memo)
    for (int i = 0; i + 1 < p.k; ++i) {
      const glm::quat* frame = &p.frames[static_cast<size_t>(i) * J];
      const std::uint8_t ex = p.exempt[static_cast<size_t>(i)];
      if (!memo->find(frame, ex)) memo->add(frame, ex, std::move(deepest[static_cast<size_t>(i)]));
    }
  *out = std::move(p);
  return true;
}

// How many of kHandPathTries a rest transition tries: the hands-apart ones only where the hands
// meet at the sign (hands_meet_at_sign). Asked only once the plain tries are used up (two poses).
int hand_path_try_count(const SynthContext& ctx, const glm::quat* from, const glm::quat* to, bool rest_at_start) {
  PoseBuilder pf(ctx.rig), pt(ctx.rig);
  pf.set_from_local(from);
  pt.set_from_local(to);
  return hands_meet_at_sign(ctx.rig, pf, pt, rest_at_start) ? kHandPathTryCount : kHandPathPlainTries;
}

// The hand's path of a rest transition (plan_hand_path_bowed) through kHandPathTries in order,
// from `*next_try`: the first that adds no depth beyond the end poses is taken when it takes fewer
// states than the direct path, or, with `retry` (the direct path is not clear of the body and
// plan_transition would route it round with via-poses, which is not a path a signer's arm takes),
// whatever its states. A try that is clear of the body but not shorter (without `retry`) ends the
// search and `*next_try` stays on it, so the retry starts there and does not repeat the tries
// found deeper. Before the retries, the far side's rest transitions were routed through
// via-poses whose IK lifted the elbow out to the side: the project avatar's right fist to the
// left hip swung out 21 cm to the right at chest height (upper arm abducted 54 deg), 1.90 s.
bool plan_hand_path(const SynthContext& ctx, const glm::quat* from, const glm::quat* to, bool rest_at_start,
                    std::uint8_t exempt_from, std::uint8_t exempt_to, DirectPathLength* direct, bool retry,
                    int* next_try, HandPathTrials* trials, TransitionPlan* out) {
  int tries = kHandPathPlainTries;
  bool counted = false;
  for (;; ++*next_try) {
    if (*next_try >= tries) {
      if (counted) break;
      counted = true;
      tries = hand_path_try_count(ctx, from, to, rest_at_start);
      if (*next_try >= tries) break;
    }
    bool deeper = false;
    if (plan_hand_path_bowed(ctx, from, to, rest_at_start, exempt_from, exempt_to, direct, *next_try, trials, retry,
                             out, &deeper))
      return true;
    // Not shorter than the direct path: the later tries, bowed further, are longer still.
    if (!deeper) return false;
  }
  return false;
}

// The last resort of a rest transition that nothing above cleared: the hand's path at whichever
// of kHandPathTries adds least beyond the end poses, if that is less than `within_m` (the best
// routed path's excess over them, excess_over's measure). plan_hand_path takes a try only when it
// adds nothing (0.5 mm), and the routing below it (via-poses on the direct slerp) cannot repair an
// arm that the slerp of joint rotations swings through the trunk: seed 004's remedy, intermediate
// states, must be states of a path the arm can take. The tries plan_hand_path rejected were
// never measured against the routes (each stops at its first state past the ends + 0.5 mm).
// Measured on the corpus (every 2nd clean sign; best route -> least-deep hand path): GROUP1D's
// rest-in 5.3 -> 2.7 mm, TONSILS1A's 8.5 -> 5.0, anioł's 70.9 -> 28.3, odpoczynek's 78.1 -> 63.0,
// INTEREST1B's lowering 119.7 -> 93.5 (before sign_motion.cpp stopped its hand at the body). Each
// try is measured only as far as it stays within the best found so far (plan_hand_path_bowed's
// ceiling), so a try that cannot win stops early. Returns the winner's excess in *excess_m.
bool plan_hand_path_least_deep(const SynthContext& ctx, const glm::quat* from, const glm::quat* to, bool rest_at_start,
                               std::uint8_t exempt_from, std::uint8_t exempt_to, DirectPathLength* direct,
                               float within_m, HandPathTrials* trials, TransitionPlan* out, float* excess_m) {
  trials->measure_ends(ctx, from, to, exempt_from, exempt_to);
  const float hand_floor_m = std::max(trials->ends_from.hand_m, trials->ends_to.hand_m);
  const float arm_floor_m = std::max(trials->ends_from.arm_m, trials->ends_to.arm_m);
  bool found = false;
  const int tries = hand_path_try_count(ctx, from, to, rest_at_start);
  for (int n = 0; n < tries; ++n) {
    if (within_m <= 0.0f) break;
    TransitionPlan p;
    bool deeper = false;
    if (!plan_hand_path_bowed(ctx, from, to, rest_at_start, exempt_from, exempt_to, direct, n, trials, true, &p,
                              &deeper, within_m))
      continue;
    const KindDepths d = depths_by_kind(ctx, p.frames.data(), p.k - 1, p.exempt.data());
    const float excess = excess_over(d, hand_floor_m, arm_floor_m);
    if (excess >= within_m) continue;  // each kind within it, both together not
    *out = std::move(p);
    *excess_m = excess;
    within_m = excess - 1e-4f;
    found = true;
  }
  return found;
}

}  // namespace

float transition_path_m(const Rig& rig, const glm::quat* from_locals, const glm::quat* to_locals) {
  return path_length(rig, from_locals, to_locals, [&](int k, std::vector<glm::quat>* out) {
    interpolate(from_locals, to_locals, {}, rig.joint_count, k, out);
  });
}

TransitionPlan plan_transition(const SynthContext& ctx, const glm::quat* from, const glm::quat* to,
                               std::uint8_t exempt_from, std::uint8_t exempt_to) {
  const Rig& rig = ctx.rig;
  const int J = rig.joint_count;
  const float fps = ctx.options.fps, speed = ctx.options.speed;
  TransitionPlan plan;
  DirectPathLength direct(rig, from, to, fps, speed);
  // From and back to the rest pose (every dictionary lookup starts and ends with them), the hand
  // takes its own, shorter path when that is clear of the body (plan_hand_path). It is judged
  // against the body model, so only with collision avoidance on.
  const size_t pose_bytes = sizeof(glm::quat) * static_cast<size_t>(J);
  const bool has_rest = static_cast<int>(ctx.rest_locals.size()) == J;
  const bool rest_at_start = has_rest && std::memcmp(from, ctx.rest_locals.data(), pose_bytes) == 0;
  const bool rest_at_end = has_rest && std::memcmp(to, ctx.rest_locals.data(), pose_bytes) == 0;
  // The hand path's tries already known to be deeper than the ends are not tried again below.
  int hand_try = 0;
  HandPathTrials trials;
  RestPathScratch rest_scratch;
  const bool hand_path_tried = ctx.options.avoid_collisions && rest_at_start != rest_at_end &&
                               direct.states_exceed(kMinTransitionStates);
  if (hand_path_tried) {
    TransitionPlan hand_path;
    if (plan_hand_path(ctx, from, to, rest_at_start, exempt_from, exempt_to, &direct, false, &hand_try, &trials,
                       &hand_path))
      return hand_path;
  }
  auto sample_direct = [&](int k, std::vector<glm::quat>* out) { interpolate(from, to, {}, J, k, out); };
  // A rest transition's direct path and via-poses (below) are timed by the arm, as its hand's
  // path is (time_rest_path_by_arm); every other transition by eq. (10) over all joints.
  if (hand_path_tried) {
    time_rest_path_by_arm(rig, from, to, fps, speed, sample_direct, false, &rest_scratch, &plan);
  } else {
    plan.lmax_m = direct.length_m();  // transition_path_m
    plan.k = transition_states(plan.lmax_m, fps, speed);
    interpolate(from, to, {}, J, plan.k, &plan.frames);
    stretch_for_arm_accel(rig, from, to, fps, sample_direct, false, &plan.k, &plan.frames);
  }
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
  // What the end poses themselves have (a sign's key pose at a known gap): a path is judged by
  // what it adds beyond that, per kind, and one that adds nothing (0.5 mm: sampling) is taken.
  // The kinds' excesses add up: judged by the larger one, a candidate that took the hands 0.3 mm
  // less deep into each other while putting the forearms 14.6 mm through each other won (SAD's
  // and HAVE's hands rising from the rest, thumbs meeting in front of the face: the forearms at
  // some state counts only, 7-10 mm on the reference humanoid, 5.5 mm on the project avatar).
  trials.measure_ends(ctx, from, to, exempt_from, exempt_to);
  const float hand_floor_m = std::max(trials.ends_from.hand_m, trials.ends_to.hand_m);
  const float arm_floor_m = std::max(trials.ends_from.arm_m, trials.ends_to.arm_m);
  auto excess_of = [&](const KindDepths& d) { return excess_over(d, hand_floor_m, arm_floor_m); };
  constexpr float kNothingAdded_m = 0.0005f;
  const KindDepths direct_depths = depths_by_kind(ctx, plan.frames.data(), plan.k - 1, plan.exempt.data());
  const float direct_excess = excess_of(direct_depths);
  if (direct_excess <= kNothingAdded_m) return plan;
  // A rest transition whose direct path cuts through the body: the hand's own path, in front of
  // the body, where one is clear (plan_hand_path's retry), before any via-pose.
  if (hand_path_tried) {
    TransitionPlan hand_path;
    if (plan_hand_path(ctx, from, to, rest_at_start, exempt_from, exempt_to, &direct, true, &hand_try, &trials,
                       &hand_path))
      return hand_path;
  }

  // Route through a via-pose: the middle state with the offending hand(s) pulled out of the body
  // (along the escape direction and forward), re-solved by arm IK; orientation and fingers kept.
  // The via-pose replaces the worst state of the direct path (its time kept for the re-timed path).
  const float via_tau = std::min(0.8f, std::max(0.2f, static_cast<float>(worst + 1) / plan.k));
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
  // The candidate that adds least beyond the end poses wins (then the shallowest); the first
  // within 5 mm, or adding nothing, is taken (consider, below).
  float best_excess = direct_excess;
  // A candidate whose excess is already past best_excess + 1e-4 part way along its states cannot
  // win (consider's both tests fail, and the excess only grows): its remaining states are not
  // checked (depths_by_kind's bound).
  auto losing_bound = [&] { return ExcessBound{hand_floor_m, arm_floor_m, best_excess + 1e-4f}; };
  // Where along the path the last candidate measured was deepest (at first the direct path's
  // worst state): the next candidate's depths are checked outward from there (depths_by_kind).
  float deep_tau = static_cast<float>(worst + 1) / plan.k;
  // The direct slerp's samples every candidate's via-poses ride on (interpolate).
  DirectSamples direct_samples;
  // A via-pose at time `tau` of the direct path: each pushed hand's wrist target moved by its
  // push, the arm re-solved by the arm IK with the body model (shoulder girdle included, so the
  // clavicle's protraction travels with the arm instead of being slerped apart from it);
  // orientation and fingers kept.
  auto make_via = [&](const std::array<glm::vec3, 2>& pushes, float tau) {
    std::vector<glm::quat> at(J);
    for (int j = 0; j < J; ++j) at[j] = slerp_shortest(from[j], to[j], minimum_jerk(tau));
    PoseBuilder pm(rig);
    pm.set_from_local(at.data());
    std::vector<glm::quat> via = at, arm_locals(J);
    for (int s = 0; s < 2; ++s) {
      if (glm::length(pushes[s]) == 0.0f) continue;
      Side side = static_cast<Side>(s);
      const ArmRig& a = rig.arms[s];
      ArmTarget t;
      t.point = pm.position(a.hand) + pushes[s];
      t.contact_offset = glm::vec3(0.0f);
      t.hand_delta = pm.delta(a.hand);
      t.body = &ctx.body;
      PoseBuilder solved(rig);
      solved.set_from_local(at.data());
      apply_arm(rig, side, solve_arm(rig, side, t), &solved);
      solved.local_rotations(arm_locals.data());
      for (int j : {a.shoulder, a.upper, a.lower, a.hand})
        if (j >= 0) via[j] = arm_locals[j];
    }
    Via v;
    v.tau = tau;
    v.delta.resize(J);
    for (int j = 0; j < J; ++j) v.delta[j] = glm::conjugate(at[j]) * via[j];
    return v;
  };
  auto plan_with = [&](const std::vector<Via>& vias) {
    std::pair<TransitionPlan, float> out;
    TransitionPlan& p = out.first;
    auto sample_vias = [&](int k, std::vector<glm::quat>* out) { interpolate(from, to, vias, J, k, out, &direct_samples); };
    p.via_points = static_cast<int>(vias.size());
    if (hand_path_tried) {
      time_rest_path_by_arm(rig, from, to, fps, speed, sample_vias, false, &rest_scratch, &p);
    } else {
      p.lmax_m = path_length(rig, from, to, sample_vias);  // eq. (10) along the routed path
      p.k = transition_states(p.lmax_m, fps, speed);
      sample_vias(p.k, &p.frames);
      stretch_for_arm_accel(rig, from, to, fps, sample_vias, false, &p.k, &p.frames);
    }
    p.exempt = exempt_for(p.k);
    const ExcessBound bound = losing_bound();
    const KindDepths d = depths_by_kind(ctx, p.frames.data(), p.k - 1, p.exempt.data(), &bound, &deep_tau);
    p.max_penetration_m = std::max(d.hand_m, d.arm_m);
    out.second = excess_of(d);
    return out;
  };
  auto plan_chain = [&](const std::vector<Via>& vias) {
    std::vector<std::vector<glm::quat>> waypoints;
    for (const Via& v : vias) {
      std::vector<glm::quat> w(J);
      for (int j = 0; j < J; ++j)
        w[j] = glm::normalize(slerp_shortest(from[j], to[j], minimum_jerk(v.tau)) * v.delta[j]);
      waypoints.push_back(std::move(w));
    }
    std::pair<TransitionPlan, float> result;
    TransitionPlan& p = result.first;
    auto sample = [&](int k, std::vector<glm::quat>* out) { interpolate_chain(rig, from, to, waypoints, k, out); };
    p.via_points = static_cast<int>(vias.size());
    if (hand_path_tried) {
      time_rest_path_by_arm(rig, from, to, fps, speed, sample, true, &rest_scratch, &p);
      p.exempt = exempt_for(p.k);
      const ExcessBound bound = losing_bound();
      const KindDepths d = depths_by_kind(ctx, p.frames.data(), p.k - 1, p.exempt.data(), &bound, &deep_tau);
      p.max_penetration_m = std::max(d.hand_m, d.arm_m);
      result.second = excess_of(d);
      return result;
    }
    p.lmax_m = path_length(rig, from, to, sample);  // eq. (10) along the routed path
    p.k = transition_states(p.lmax_m, fps, speed);
    sample(p.k, &p.frames);
    // Eq. (10) sets the mean speed; a single minimum-jerk profile peaks at 1.875 times it. The
    // pieces share that profile by the path of the joint that travels furthest overall, so a
    // joint that travels most in one piece (a hand's fingertips swinging round the waypoint)
    // can outrun it there: then the states are increased until no joint steps further per frame
    // than the profile's peak over the whole path (the human speed of the direct transitions).
    const float peak_step_m = profile_peak_step_m(p.lmax_m, p.k);
    const float step_m = max_joint_step(rig, from, to, p.frames, p.k);
    if (step_m > peak_step_m) {
      p.k = static_cast<int>(std::ceil(p.k * step_m / peak_step_m));
      sample(p.k, &p.frames);
    }
    stretch_for_arm_accel(rig, from, to, fps, sample, true, &p.k, &p.frames);
    p.exempt = exempt_for(p.k);
    const ExcessBound bound = losing_bound();
    const KindDepths d = depths_by_kind(ctx, p.frames.data(), p.k - 1, p.exempt.data(), &bound, &deep_tau);
    p.max_penetration_m = std::max(d.hand_m, d.arm_m);
    result.second = excess_of(d);
    return result;
  };
  auto consider = [&](std::pair<TransitionPlan, float> c) {
    if (c.second < best_excess - 1e-4f ||
        (c.second <= best_excess + 1e-4f && c.first.max_penetration_m < best.max_penetration_m)) {
      best = std::move(c.first);
      best_excess = c.second;
    }
    return best.max_penetration_m <= 0.005f || best_excess <= kNothingAdded_m;
  };
  // Forearms through each other (arms that cross on the way: LOVE's fists rising from the rest
  // to cross at the chest): both arms pushed along their own escapes (one forward, the other
  // back into the chest) made the outcome a lottery of the state count k (LOVE on the project
  // avatar: 2-41 mm over speeds 0.7-1.5 and 25-60 fps). Signers bring the arm that ends in front
  // in front all the way: one arm's wrist alone is held forward of the other by the depth plus
  // a margin, the arm in front at the crossed end of the transition first (the end where the
  // forearms are nearer each other), then the other.
  {
    float pair_depth = 0.0f;
    for_each_state(rig, plan, true, [&](const PoseBuilder& pb) {
      pair_depth = std::max(pair_depth, arm_penetration(ctx.body, pb, kLeft, false, false, true).depth_m);
    });
    if (pair_depth > 0.005f) {
      auto forearms = [&](const glm::quat* locals, float* gap_m) {
        PoseBuilder p(rig);
        p.set_from_local(locals);
        const ArmRig &l = rig.arms[kLeft], &r = rig.arms[kRight];
        *gap_m = segment_segment_distance(p.position(l.lower), p.position(l.hand), p.position(r.lower),
                                          p.position(r.hand), nullptr, nullptr);
        // Forward depth of each forearm's middle: which one is in front.
        return glm::dot(p.position(l.lower) + p.position(l.hand) - p.position(r.lower) - p.position(r.hand),
                        rig.forward);
      };
      float gap_from = 0.0f, gap_to = 0.0f;
      const float left_ahead_from = forearms(from, &gap_from), left_ahead_to = forearms(to, &gap_to);
      const Side front = (gap_to <= gap_from ? left_ahead_to : left_ahead_from) > 0.0f ? kLeft : kRight;
      // Margins up to 20 cm: the depth measured is the forearms', and a hand can be deeper in
      // the other forearm than they are in each other (LOVE on the project avatar at 25-60 fps x
      // 0.8-1.25: forearms 14 mm, the left hand 45 mm in the right forearm on the direct path;
      // the best route up to 12 cm left 7.6-8.4 mm, 16 cm takes it to 1.0-4.0).
      for (Side s : {front, other(front)})
        for (float margin : {0.04f, 0.08f, 0.12f, 0.16f, 0.20f})
          for (float tau : {via_tau, 0.5f, 0.35f, 0.65f}) {
            std::array<glm::vec3, 2> fwd{};
            fwd[s] = rig.forward * (pair_depth + margin);
            if (consider(plan_with({make_via(fwd, tau)}))) return best;
          }
    }
  }
  // Hands into each other on the way (HAVE's and FAMILY's hands leaving their contact for the
  // rest, SAD's spread thumbs meeting in front of the face): each hand's own push is along the
  // other hand, so the two pushes cancel or swap which hand is inside. Signers part the hands:
  // each wrist is held out to its own side and forward for the middle of the path, by half the
  // depth plus a margin (sideways alone was a wash: the fingers still crossed in front). Where
  // the hands meet early on the way (SAD's spread hands just leaving the face), a waypoint at
  // 0.15 (alone, or paired with one at 0.5) parts them from the start: one at the worst state or
  // two at 0.35/0.65 left SAD 14-16 mm on the reference humanoid. What clears SAD is the single
  // waypoint at 0.15 with the 10 cm margin (0.0 mm, the 13th candidate); the 0.15/0.5 pair at
  // 10 cm leaves 15.9 mm. So without the single 0.15 SAD ends at 14.7 mm (the pair at 6 cm, the
  // best of the rest): not the candidates' order, the one candidate that works removed.
  // (Only when a hand goes deeper than 5 mm at all: the hands' own scan poses every state again.)
  if (direct_depths.hand_m > 0.005f) {
    float hands_depth = 0.0f;
    for_each_state(rig, plan, true, [&](const PoseBuilder& pb) {
      for (Side side : {kLeft, kRight})
        hands_depth = std::max(hands_depth, hand_penetration(ctx.body, pb, side, false, true).depth_m);
    });
    if (hands_depth > 0.005f) {
      auto apart = [&](float margin_m) {
        std::array<glm::vec3, 2> out{};
        for (int s = 0; s < 2; ++s) {
          const glm::vec3 own_side = s == kLeft ? rig.left : -rig.left;
          out[s] = glm::normalize(own_side + rig.forward) * (0.5f * hands_depth + margin_m);
        }
        return out;
      };
      for (float margin : {0.03f, 0.06f, 0.10f}) {
        for (float tau : {via_tau, 0.5f, 0.15f})
          if (consider(plan_with({make_via(apart(margin), tau)}))) return best;
        if (consider(plan_chain({make_via(apart(margin), 0.35f), make_via(apart(margin), 0.65f)}))) return best;
        if (consider(plan_chain({make_via(apart(margin), 0.15f), make_via(apart(margin), 0.5f)}))) return best;
      }
    }
  }
  // The push, then two, three and four times it; failing those, less than it: a via-pose pushed
  // further can take another swivel that is worse (a hand across the waist: 5.2 mm at 1x, 15 mm
  // at 2x, 1.2 mm at 0.75x).
  const float scales[] = {1.0f, 2.0f, 3.0f, 4.0f, 0.75f, 0.5f};
  for (float scale : scales)
    if (consider(plan_with({make_via({scale * push[0], scale * push[1]}, via_tau)}))) return best;

  // Round the front: an arm that sweeps through the trunk between a far-side place and the rest
  // (the clavicle protracted at one end, hanging at the other) is routed with its wrist held in
  // front of the trunk, pulled straight forward along the body's forward axis by the depth the
  // direct path reached plus a margin. One such via-pose only moves the cut to the path's other
  // half (the project avatar's fist at shoulder_top: upper arm 117 mm in the torso before the via
  // at mid-transition, 138 mm after one at 0.2), so two: forward early, then forward late.
  float depth[2] = {0.0f, 0.0f};
  for_each_state(rig, plan, false, [&](const PoseBuilder& pb) {
    for (Side side : {kLeft, kRight}) {
      depth[side] = std::max(depth[side], arm_penetration(ctx.body, pb, side, true, false, false).depth_m);
      depth[side] = std::max(depth[side], hand_penetration(ctx.body, pb, side, true, false).depth_m);
    }
  });
  auto forward_push = [&](float margin_m) {
    std::array<glm::vec3, 2> fwd{};
    for (int s = 0; s < 2; ++s)
      if (depth[s] > 0.005f) fwd[s] = rig.forward * (depth[s] + margin_m);
    return fwd;
  };
  // Nothing cleared it: the hand's path that adds least, if it adds less than the best route.
  auto least_deep = [&] {
    if (!hand_path_tried || best.max_penetration_m <= 0.005f || best_excess <= kNothingAdded_m) return best;
    TransitionPlan hand_path;
    float excess = 0.0f;
    if (plan_hand_path_least_deep(ctx, from, to, rest_at_start, exempt_from, exempt_to, &direct, best_excess - 1e-4f,
                                  &trials, &hand_path, &excess))
      return hand_path;
    return best;
  };
  if (depth[0] <= 0.005f && depth[1] <= 0.005f) return least_deep();
  const float margins_m[] = {0.05f, 0.10f, 0.15f, 0.22f};
  for (float tau : {via_tau, 0.5f})
    for (float margin : margins_m)
      if (consider(plan_with({make_via(forward_push(margin), tau)}))) return best;
  for (float tau : {via_tau, 0.5f, 0.3f, 0.7f})
    for (float margin : margins_m)
      if (consider(plan_chain({make_via(forward_push(margin), tau)}))) return best;
  const std::pair<float, float> pairs[] = {{0.3f, 0.7f}, {0.2f, 0.6f}, {0.4f, 0.8f}};
  for (const auto& tt : pairs)
    for (float margin : margins_m)
      if (consider(plan_chain({make_via(forward_push(margin), tt.first), make_via(forward_push(margin), tt.second)})))
        return best;
  return least_deep();
}

}  // namespace sw::synthesis

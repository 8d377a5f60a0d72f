// Sign motion: key states, movement steps, repetitions and two hands -> frames (sign_motion.h).
#include "synthesis/sign_motion.h"

#include "face/emotion.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <type_traits>

#include "synthesis/arm_ik.h"
#include "synthesis/clip_steps.h"
#include "synthesis/elbow_path.h"
#include "synthesis/frame_corrections.h"
#include "synthesis/hand_parts.h"
#include "synthesis/movement.h"
#include "synthesis/orientation.h"
#include "synthesis/thorax_turn.h"
#include "synthesis/transition.h"

namespace sw::synthesis {

using notation::BodyLevel;
using notation::Contact;
using notation::HandPlace;
using notation::Location;
using notation::Movement;
using notation::MovementKind;

namespace {

const char* level_name(BodyLevel l) {
  static const char* names[] = {"above_head", "head_top", "head", "forehead", "eyebrows", "eyes",
                                "nose", "ears", "cheeks", "mouth", "lips", "teeth", "tongue", "chin",
                                "under_chin", "neck", "shoulders", "shoulder_top", "chest", "stomach",
                                "belly", "waist", "below_waist", "neutral"};
  return names[static_cast<int>(l)];
}

notation::Side mirror_side(notation::Side s) {
  return static_cast<notation::Side>(4 - static_cast<int>(s));
}

const char* side_name(notation::Side s) {
  static const char* names[] = {"right_beside", "right", "centre", "left", "left_beside"};
  return names[static_cast<int>(s)];
}

bool is_touch(Contact c) {
  return c == Contact::Touch || c == Contact::Brush || c == Contact::Grasp ||
         c == Contact::Between || c == Contact::Interlock;
}

// How far the contact part stays from the place (m): touch 0, close 5 cm, none 7 cm — the
// acceptance band for "no contact" is 3-10 cm.
// The furthest a hand held off the far side's beside places is searched from the place (m):
// inside the 3-10 cm band with a centimetre to spare for the contact part's reach error.
constexpr float kFarBesideHeldOff_m = 0.09f;
// A hand held off a body place whose orientation misses by more than this (10 degrees, the
// acceptance's palm bound) searches the no-contact band for a better place (key_state).
constexpr float kBandSearchAboveRad = 0.17f;

float contact_distance(Contact c, bool on_hand) {
  if (is_touch(c)) return 0.0f;
  if (c == Contact::Close) return on_hand ? 0.04f : 0.05f;
  return on_hand ? 0.06f : 0.07f;
}

bool finger_extended(const notation::FingerConfig& f) {
  return (f.id == notation::kFingerPressedToStraight && (!f.has_t || f.t >= 0.5f)) ||
         f.id == notation::kFingerSpread || f.id == notation::kFingerCrossed;
}

// The part of this hand that makes contact: as written (C(...)), else the index fingertip for a
// pointing hand, the fingertips of a flat hand, the palm otherwise.
void contact_part(const notation::HandSpec& spec, HandPlace* place, int* finger) {
  if (spec.location.contact_part) {
    *place = *spec.location.contact_part;
    *finger = spec.location.contact_finger >= 0 ? spec.location.contact_finger : 1;
    return;
  }
  const auto& f = spec.shape.fingers;
  bool idx = finger_extended(f[1]), mid = finger_extended(f[2]), rng = finger_extended(f[3]),
       lit = finger_extended(f[4]);
  if (spec.location.kind == Location::Kind::NeutralSpace || !is_touch(spec.location.contact)) {
    *place = HandPlace::Palm;
    *finger = 1;
  } else if (idx && !mid) {
    *place = HandPlace::Fingertip;
    *finger = 1;
  } else if (idx && mid && rng && lit) {
    *place = HandPlace::Fingertip;
    *finger = 2;
  } else {
    *place = HandPlace::Palm;
    *finger = 1;
  }
}

struct HandState {
  glm::vec3 target{0.0f};       // absolute; for a hand placed on the other hand: offset from it
  glm::quat delta{1, 0, 0, 0};
  HandAngles angles;
  glm::vec3 offset{0.0f};
  float swivel = 0.4f;
  // The wrist movement's part of delta, right-multiplied onto the held orientation
  // (ArmTarget::wrist_motion; identity: none).
  glm::quat wrist_turn{1, 0, 0, 0};
  // How far the hand is on its way to a place on the other ARM (0: not, 1: there). That place
  // moves with the other arm's swivel, which the frames may still clear out of the body: the
  // hand follows the place's move by this share (sign_motion's frames, `arm_place`).
  float on_arm_place = 0.0f;
};

// The arm target that holds a hand state as it is: its contact offset, orientation and swivel
// (no swivel search), at `point`.
ArmTarget held_state_target(const HandState& h, const glm::vec3& point) {
  ArmTarget t;
  t.point = point;
  t.contact_offset = h.offset;
  t.hand_delta = h.delta;
  t.auto_swivel = false;
  t.swivel_rad = h.swivel;
  return t;
}

// A movement's hand turn, seed 004's orientation change within a gesture (eq. (7)'s S_beg ->
// S_end): a turn larger than kAmbiguousTurnRad (150 degrees) may go either way round
// (choose_turn_direction), and no step turns the hand faster on average than
// kMeanHandTurnRadPerS, so its minimum-jerk peak stays at 1.875 times that. 5 rad/s peaks at
// 9.4 rad/s, under the 15 rad/s at which the per-frame solve takes a wrist change for a flip
// (kWristFlipRadPerS) and within the 10-15 rad/s of a fast forearm rotation. The written
// replace (0.35 s) turned 180 degrees at 9 rad/s on average, 17 at the peak. Measured on
// STUDENT with the way round chosen: 6 rad/s, wrist or elbow steps up to 42 mm (avatar) / 48 mm
// (reference); 5 rad/s, 40 / 41 mm (with the rounding's way round, 6 rad/s left the avatar's
// elbow jumping 128 mm).
constexpr float kAmbiguousTurnRad = 2.618f;
constexpr float kMeanHandTurnRadPerS = 5.0f;

// Above speed 1 a step's wrists, elbows and fingertips accelerate at most this much in the solved
// clip (over kStepHandAccelWindowS, as the smoothness tests measure; synthesize_sign_motion
// stretches the step). The tests' bound is 50.4 m/s^2 (5.6 cm change of a 30 fps step); this is
// measured on the solved frames themselves (the transitions' 40, kArmPeakAccelMPerS2, plans
// states before the clip is blended), so a tenth is left, for the joins with the transitions.
// The signs' steps took the speed factor as a divisor of every duration: at 1.25 every
// acceleration was 1.56 times its speed-1 figure (PLEASE's circle on the chest, reference:
// 46.4 m/s^2 at 30 fps x 1, 65.0 at 60 fps x 1.25; LOOK's V hand on the avatar 53.1).
constexpr float kStepHandPeakAccelMPerS2 = 45.0f;
constexpr float kStepHandAccelWindowS = 1.0f / 30.0f;
// And their speed (the tests' bound 3 m/s; a tenth left as above). TEACHER's move from the
// temples down to the shoulders (reference humanoid, 60 fps x 1.25) took its left elbow to 3.15.
constexpr float kStepHandPeakSpeedMPerS = 2.7f;
// A step's acceleration is not exactly 1/duration^2 in the solved clip (the window's phase over
// the frames, the clamped wrist's corners, the wrist-rate rules that still scale with the speed
// factor): up to this many stretches, each taken only when it measures better (PLEASE on the
// reference at 60 fps x 1.25: 65.0, 45.5, then 50.2 m/s^2 at one more state).
constexpr int kStepAccelRounds = 3;

HandState mix_state(const HandState& a, const HandState& b, float s) {
  HandState o;
  o.target = a.target + s * (b.target - a.target);
  o.delta = slerp_shortest(a.delta, b.delta, s);
  o.angles = mix(a.angles, b.angles, s);
  o.offset = a.offset + s * (b.offset - a.offset);
  o.swivel = a.swivel + s * (b.swivel - a.swivel);
  o.on_arm_place = a.on_arm_place + s * (b.on_arm_place - a.on_arm_place);
  return o;
}

// The hand's turn from a to b, the other way round the same axis than slerp_shortest takes (the
// angle 2*pi minus the short one). For a turn of about 180 degrees (a hand written fingers in,
// palm down, turning to fingers out, palm to the side: STUDENT) the two ways are about as long,
// and which one slerp_shortest takes is decided by the rounding of a dot product near 0, not by
// what the arm can follow (choose_turn_direction).
glm::quat slerp_other_way(const glm::quat& a, const glm::quat& b, float t) {
  glm::quat bq = glm::dot(a, b) < 0.0f ? b : -b;  // the hemisphere slerp_shortest does not take
  const float d = std::max(-1.0f, std::min(1.0f, glm::dot(a, bq)));
  const float theta = std::acos(d), sin_theta = std::sin(theta);
  if (sin_theta < 1e-6f) return slerp_shortest(a, b, t);
  return glm::normalize(a * (std::sin((1.0f - t) * theta) / sin_theta) + bq * (std::sin(t * theta) / sin_theta));
}

struct HandPlan {
  Side side = kRight;
  bool active = false;
  notation::HandSpec spec;
  bool mirror_x = false;          // orientation and location mirrored (the other side's hand)
  MirrorAxes move_mirror;         // movements mirrored
  bool alternating = false;
  bool on_other_hand = false;     // location is a place on the other hand/arm
  HandPlace place = HandPlace::Palm;
  int place_finger = 1;
  float place_distance_m = 0.0f;
  bool exempt_trunk = false, exempt_hand = false;
  // The notation says this hand stays (hamplus hamnomotion, <nomotion/>) and it has no movement
  // in any step: the frames keep it where it is (holds_still_while_the_other_moves).
  bool written_still = false;
  // The non-dominant hand is the dominant one's copy under a symmetry (hamsymmlr, hamsymmpar and
  // their combinations): its place is the mirror of the dominant hand's (lay_mirror_pair_apart).
  bool copy_of_dominant = false;
  std::vector<std::vector<Movement>> steps;
};

// Poses `side`'s arm (the shoulder girdle down, fingers included) at rest in `pb`, as the frames
// of a sign pose an inactive hand, with its arm from the upper arm down swung by `swing` (model
// space, about the shoulder joint; resting_arm_gives_way). The joints left unset follow their
// parents when finalized, as in the frames: a pose started from the whole rest pose instead
// keeps rest rotations for the joints an arm solve does not set (the finger metacarpals and tips)
// and puts the solved hand's fingers where they are not.
void pose_arm_at_rest(const Rig& rig, const PoseBuilder& rest, Side side, const glm::quat& swing, PoseBuilder* pb) {
  const ArmRig& a = rig.arms[side];
  for (int j = 0; j < rig.joint_count; ++j) {
    int p = j;
    while (p >= 0 && p != a.shoulder && p != a.upper) p = rig.parent[p];
    if (p >= 0) pb->set(j, p == a.upper ? swing * rest.delta(j) : rest.delta(j));
  }
}

// A hand in neutral space whose first step twists the wrist (PLAY's Y hands, fingers up and palm
// in): the placement search scored the key pose alone, and picked one with the wrist flexed 73
// degrees and the forearm across the fingers, where a twist about the fingers asks the wrist's
// radial deviation (at its limit) instead of the forearm's rotation: 0.415 rad off at the twist's
// peak (project avatar; SignMotion::orientation_error_rad). A signer holds the hand where the
// forearm can turn it. The cost of a placement (at its swivel) then also counts the hand's
// orientation at the twist's two peaks (phases 3/8 and 5/8 of wrist_motion, the envelope full),
// solved as the frames solve them (the wrist kept where it is, the motion right-multiplied):
// 3 per radian of the worse, as the key pose's own error. Zero cost and no solve for any other
// hand.
struct WristTwistCost {
  const Rig& rig;
  const HandPlan& plan;
  const HandState& st;
  const Movement* twist = nullptr;
  WristTwistCost(const Rig& r, const HandPlan& p, const HandState& s) : rig(r), plan(p), st(s) {
    if (!plan.steps.empty())
      for (const Movement& m : plan.steps[0])
        if (m.kind == MovementKind::WristTwist) twist = &m;
  }
  float operator()(const ArmTarget& at, const ArmPose& p) const {
    if (!twist) return 0.0f;
    ArmTarget mt = at;
    mt.auto_swivel = false;
    mt.swivel_rad = p.swivel_rad;
    float worst = 0.0f;
    for (float phase : {0.375f, 0.625f}) {
      const glm::quat motion = wrist_motion(rig, plan.side, *twist, phase);
      mt.hand_delta = st.delta * motion;
      mt.wrist_motion = motion;
      mt.point = at.point + mt.hand_delta * st.offset - st.delta * st.offset;
      worst = std::max(worst, solve_arm(rig, plan.side, mt).orientation_error_rad);
    }
    return 3.0f * worst;
  }
};

struct Solver {
  const SynthContext& ctx;
  const Rig& rig;
  std::vector<SynthesisError>* errors;
  std::string where;
  PoseBuilder bind_pose;
  std::array<ArmPose, 2> rest_arm;
  HandAngles rest_angles;
  // The sign's thorax turn (none unless set_thorax_turn) and the turned body its anchors are on.
  ThoraxTurn turn;
  PoseBuilder turned_pose;

  Solver(const SynthContext& c, std::vector<SynthesisError>* e, std::string w)
      : ctx(c), rig(c.rig), errors(e), where(std::move(w)), bind_pose(c.rig), turned_pose(c.rig) {
    bind_pose.finalize();
  }

  void set_thorax_turn(const ThoraxTurn& t) {
    turn = t;
    turned_pose = PoseBuilder(rig);
    pose_thorax_turn(rig, turn, &turned_pose);
    turned_pose.finalize();
  }

  // A body anchor as the sign is solved: on the bind pose, or with a thorax turn on the turned
  // body, seen in the thorax frame (thorax_turn.h).
  bool body_anchor(const std::string& name, PartPoint* p) const {
    if (!turn.active()) return anchor_point(*ctx.avatar, bind_pose, name, p);
    if (!anchor_point(*ctx.avatar, turned_pose, name, p)) return false;
    p->point = turn.to_thorax_point(p->point);
    p->normal = turn.to_thorax_dir(p->normal);
    return true;
  }

  glm::vec3 part_offset(Side side, const HandAngles& angles, HandPlace place, int finger) const {
    PoseBuilder pb(rig);
    pose_fingers(rig, side, angles, glm::quat(1, 0, 0, 0), &pb);
    pb.finalize();
    return hand_part(pb, side, place, finger).point - rig.bind_pos[rig.arms[side].hand];
  }

  // A hand beside the FAR side of the body: the right hand at `left_beside`, the left at
  // `right_beside` (as seen after a left-handed mirror).
  static bool far_side_beside(const HandPlan& plan, const Location& loc) {
    if (loc.kind != Location::Kind::Body) return false;
    const notation::Side seen = plan.mirror_x ? mirror_side(loc.side) : loc.side;
    return seen == (plan.side == kRight ? notation::Side::LeftBeside : notation::Side::RightBeside);
  }

  // A hand at the FAR side's own places (the right hand at `left`).
  static bool far_side_place(const HandPlan& plan, const Location& loc) {
    if (loc.kind != Location::Kind::Body) return false;
    const notation::Side seen = plan.mirror_x ? mirror_side(loc.side) : loc.side;
    return seen == (plan.side == kRight ? notation::Side::Left : notation::Side::Right);
  }

  // Absolute target for a body / neutral-space location; false (with an error) if the avatar
  // lacks the anchor.
  bool body_target(const HandPlan& plan, const Location& loc, glm::vec3* target, PartPoint* anchor) {
    std::string name = body_anchor_name(loc, plan.mirror_x);
    PartPoint p;
    if (!body_anchor(name, &p)) {
      errors->push_back({where + (plan.side == kRight ? " right" : " left") + " hand location",
                         "the avatar has no body anchor '" + name + "'"});
      return false;
    }
    *anchor = p;
    if (loc.kind == Location::Kind::NeutralSpace || loc.level == BodyLevel::NeutralSpace) {
      *target = p.point + (loc.contact == Contact::ArmExtended ? 0.15f : 0.0f) * rig.forward;
      return true;
    }
    if (loc.contact == Contact::ArmExtended) {
      *target = p.point + 0.3f * rig.forward;
      return true;
    }
    glm::vec3 away = glm::normalize(p.normal);
    // A hand beside the FAR side of the body (the right hand at `left_beside`) is held off it in
    // front: the other arm hangs at that side, and the crossing arm reaches the place round the
    // front of the chest. Held off sideways (the anchor's normal on a rig whose `*_beside` normal
    // points out) the hand is level with the body's mid-plane and the upper arm goes through the
    // torso (40-83 mm at the chest and belly on the reference humanoid, 8-24 mm at the face).
    // From the shoulders down it is slanted back in towards the middle (half as much inwards as
    // forwards; measured: straight forward, or as much inwards as forwards, leaves the chest key
    // poses 2-3 mm deeper), at the neck a quarter (a half pushes the hand off the jaw, 10 cm from
    // the place; none lets the rest transitions cut through the chest, 126 mm), at the face not
    // at all (the forearm passes below the chin and a slant brings it into the head).
    if (far_side_beside(plan, loc)) {
      const glm::vec3 across = plan.side == kRight ? rig.left : -rig.left;  // to the far side
      const float slant = static_cast<int>(loc.level) >= static_cast<int>(BodyLevel::Shoulders) ? 0.5f
                          : loc.level == BodyLevel::Neck                                       ? 0.25f
                                                                                               : 0.0f;
      away = glm::normalize(rig.forward - slant * across);
    }
    // A hand held off the FAR side's own place at the ears, neck or shoulders (the right hand
    // off the left ear) is held off between the place's normal and forward, at the ears also a
    // little up: along the normal alone (out to the far side of the head, forward from the side
    // of the neck) the hand sat beside the head or under the jaw and the forearm crossed the face
    // into the head (the project avatar's fist across the body off the ear: 30.9 mm; off the neck
    // 5.7 mm; the pointing hand off the shoulders 7.5 mm). In front, the forearm passes in front
    // of the face and chest. Measured on the project avatar over the 3 hands x close and none
    // (HandsAcrossTheBody's hands): ears 30.9 -> 1.6 mm (0.5 up; without it 9.9, with 1.0 up
    // 17.5, 0.5 forward 31.6, 1.5 forward 2.0), neck 5.7 -> 1.3 mm, shoulders 7.5 -> 1.8 mm; the
    // reference humanoid stays within 2 mm. (The shoulder top has its own search, below.)
    if (far_side_place(plan, loc) && !is_touch(loc.contact) &&
        (loc.level == BodyLevel::Ears || loc.level == BodyLevel::Neck || loc.level == BodyLevel::Shoulders))
      away = glm::normalize(away + rig.forward + (loc.level == BodyLevel::Ears ? 0.5f : 0.0f) * rig.up);
    *target = p.point + contact_distance(loc.contact, false) * away;
    return true;
  }

  PartPoint other_hand_place(const PoseBuilder& pose, const HandPlan& plan) const {
    return other_hand_place(pose, plan.side, plan.place, plan.place_finger);
  }
  // The place `place` (finger `finger`) on the hand or arm other than `side`'s, as posed.
  PartPoint other_hand_place(const PoseBuilder& pose, Side side, HandPlace place,
                             int finger) const {
    Side o = other(side);
    PartPoint p;
    if (!anchor_point(*ctx.avatar, pose, hand_part_anchor_name(o, place, finger), &p))
      p = hand_part(pose, o, place, finger);
    return p;
  }

  // A hand held off a place on the body (no contact: 3-10 cm, issue 4) whose arm is in the trunk
  // or whose elbow is behind the body turns out of it (turn_hand_out_of_body, arm_ik.h) by 15
  // degrees or more. A signer holding the hand off the place need not turn it: the hand may be
  // anywhere in the band, and a few centimetres higher, lower, out or forward free the arm with
  // the hand's orientation intact (PERSON's and HAVE's flat hands before the chest: the forearm
  // 7-8 mm in the trunk; TEACH's flat-O hands beside the temples: the elbow behind the body).
  // The band round the anchor (5, 7, 9 cm, a centimetre inside it for the contact part's reach
  // error) is searched, each placement with its own swivel; a placement wins only where the arm
  // is clear (as turn_hand_out_of_body judges it) and the palm within 10 degrees, the nearest to
  // the written place and orientation best. Without one the turn decides, as before. Bounded
  // (81 placements, each solved at one swivel, then at most each with a swivel search) and run
  // only where the turn would be.
  void hold_off_clear(const HandPlan& plan, const Location& loc, const PartPoint& anchor, ArmTarget* t,
                      ArmPose* best, HandState* st) const {
    if (!t->body || loc.kind != Location::Kind::Body || is_touch(loc.contact) ||
        loc.contact == Contact::ArmExtended || loc.level == BodyLevel::NeutralSpace ||
        far_side_place(plan, loc) || far_side_beside(plan, loc))
      return;
    const auto in_conflict = arm_in_body_conflict;  // what turn_hand_out_of_body acts on
    if (!in_conflict(*best)) return;
    const glm::vec3 written = st->target;
    const glm::vec3 n = glm::normalize(anchor.normal);
    const glm::vec3 outward = plan.side == kLeft ? rig.left : -rig.left;
    auto cost = [&](const ArmPose& p, glm::vec3 target) {
      return 3.0f * p.orientation_error_rad + 20.0f * p.reach_error_m + 1.5f * glm::length(target - written) +
             p.body_cost;
    };
    // The band's placements, nearest the written place first: a placement costs at least 1.5 per
    // metre of shift, so once a clear one costs less than that the farther ones cannot win.
    struct Placement {
      glm::vec3 point;
      float shift_m;
    };
    std::array<Placement, 81> placements;
    size_t count = 0;
    for (float distance : {0.05f, 0.07f, 0.09f})
      for (float fwd : {0.0f, 0.5f, 1.0f})
        for (float up : {-0.5f, 0.0f, 0.5f})
          for (float out : {-0.4f, 0.0f, 0.4f}) {
            const glm::vec3 away = n + fwd * rig.forward + up * rig.up + out * outward;
            if (glm::length(away) < 0.3f) continue;
            const glm::vec3 point = anchor.point + distance * glm::normalize(away);
            placements[count++] = {point, glm::length(point - written)};
          }
    std::stable_sort(placements.begin(), placements.begin() + static_cast<std::ptrdiff_t>(count),
                     [](const Placement& a, const Placement& b) { return a.shift_m < b.shift_m; });
    ArmTarget c = *t;
    float best_cost = std::numeric_limits<float>::max();
    ArmPose found;
    glm::vec3 found_point = written;
    // First at the written place's swivel (one arm solve each, as the band search compares its
    // placements): the best clear one, given its own swivel, wins if it is still clear and within
    // 10 degrees; only otherwise is every placement given its own swivel search (12 solves each).
    // Over the two lexicon tests (both rigs), 19 of 26 searches end in the first pass: 1,651
    // single solves and 412 swivel searches, where every placement's swivel search took 1,117
    // (TEACH on the reference humanoid 2.9 -> 1.5 ms per sign, natively).
    {
      ArmTarget fixed = c;
      fixed.auto_swivel = false;
      fixed.has_near_swivel = false;
      fixed.swivel_rad = best->swivel_rad;
      glm::vec3 pick = written;
      for (size_t i = 0; i < count && 1.5f * placements[i].shift_m < best_cost; ++i) {
        fixed.point = placements[i].point;
        const ArmPose p = solve_arm(rig, plan.side, fixed);
        if (in_conflict(p) || p.orientation_error_rad > kBandSearchAboveRad) continue;
        const float pc = cost(p, fixed.point);
        if (pc < best_cost) {
          best_cost = pc;
          pick = fixed.point;
        }
      }
      if (pick != written) {
        c.point = pick;
        const ArmPose p = solve_arm(rig, plan.side, c);
        if (!in_conflict(p) && p.orientation_error_rad <= kBandSearchAboveRad) {
          *best = p;
          st->target = pick;
          t->point = pick;
          return;
        }
      }
      best_cost = std::numeric_limits<float>::max();
    }
    for (size_t i = 0; i < count && 1.5f * placements[i].shift_m < best_cost; ++i) {
      c.point = placements[i].point;
      const ArmPose p = solve_arm(rig, plan.side, c);
      if (in_conflict(p) || p.orientation_error_rad > kBandSearchAboveRad) continue;
      const float pc = cost(p, c.point);
      if (pc < best_cost) {
        best_cost = pc;
        found = p;
        found_point = c.point;
      }
    }
    if (found_point == written) return;
    *best = found;
    st->target = found_point;
    t->point = found_point;
  }

  // near_swivel: the swivel the hand has where this state is reached from (a movement's goal:
  // the state before it), so the sign's key poses choose neighbouring swivels (arm_ik.h
  // ArmTarget::near_swivel_rad); null for the sign's first key pose.
  // solve_handshape of a side and shape, solved once per sign: its thumb contact is a
  // Levenberg-Marquardt solve (about 0.27 M instructions), and a sign's key states ask for the
  // same shape again (the state turned with the trunk, each movement's goal, both hands of a
  // symmetric sign). solve_handshape reads only the side and the five finger configurations, so a
  // remembered result is the one it would return.
  struct SolvedShape {
    Side side;
    std::array<notation::FingerConfig, notation::kFingerCount> fingers;
    HandAngles angles;
  };
  std::vector<SolvedShape> solved_shapes;
  static bool same_fingers(const std::array<notation::FingerConfig, notation::kFingerCount>& a,
                           const std::array<notation::FingerConfig, notation::kFingerCount>& b) {
    for (size_t k = 0; k < a.size(); ++k)
      if (a[k].id != b[k].id || a[k].has_t != b[k].has_t || std::memcmp(&a[k].t, &b[k].t, sizeof(float)) != 0 ||
          std::memcmp(&a[k].spread, &b[k].spread, sizeof(float)) != 0)
        return false;
    return true;
  }
  HandAngles handshape(Side side, const notation::HandShape& shape) {
    for (const SolvedShape& s : solved_shapes)
      if (s.side == side && same_fingers(s.fingers, shape.fingers)) return s.angles;
    solved_shapes.push_back({side, shape.fingers, solve_handshape(rig, side, shape)});
    return solved_shapes.back().angles;
  }

  HandState key_state(const HandPlan& plan, const notation::HandSpec& spec, bool* ok,
                      PartPoint* anchor_out, const float* near_swivel = nullptr) {
    HandState st;
    st.angles = handshape(plan.side, spec.shape);
    st.delta = hand_delta_for(rig, plan.side, orientation_frame(rig, spec.orientation, plan.side, plan.mirror_x));
    HandPlace place;
    int finger;
    contact_part(spec, &place, &finger);
    st.offset = part_offset(plan.side, st.angles, place, finger);
    if (spec.location.kind == Location::Kind::OtherHand) {
      st.target = glm::vec3(0.0f);  // relative to the other hand's place, added per frame
      *ok = true;
      return st;
    }
    PartPoint anchor;
    *ok = body_target(plan, spec.location, &st.target, &anchor);
    if (anchor_out) *anchor_out = anchor;
    if (*ok) {
      ArmTarget t;
      t.point = st.target;
      t.contact_offset = st.offset;
      t.hand_delta = st.delta;
      // The swivel keeps the arm out of the body (unless collision handling is off).
      t.body = ctx.options.avoid_collisions ? &ctx.body : nullptr;
      t.hand_contact = spec.location.kind == Location::Kind::Body && is_touch(spec.location.contact);
      if (near_swivel) {
        t.has_near_swivel = true;
        t.near_swivel_rad = *near_swivel;
      }
      // A touch's written pose: its own solve seeks the orientation acceptance (arm_ik.h). Not a
      // hand held off or in neutral space, whose placement searches below re-solve it anyway.
      t.seek_orientation_acceptance = t.hand_contact;
      ArmPose best = solve_arm(rig, plan.side, t);
      t.seek_orientation_acceptance = false;
      if (spec.location.kind == Location::Kind::NeutralSpace ||
          spec.location.level == BodyLevel::NeutralSpace) {
        // Neutral space is a region, not a point: signers hold an upright hand higher and closer,
        // a hand pointing away lower and further. Search a few places around the anchor for the
        // one where the wrist realises the orientation best (a small penalty keeps it central).
        const float up_steps[4] = {-0.06f, 0.0f, 0.06f, 0.12f};
        const float in_steps[4] = {-0.12f, -0.06f, 0.0f, 0.05f};
        // Placements are compared at the chosen swivel (cheap), then the winner gets its own
        // swivel search.
        glm::vec3 base = st.target;
        t.auto_swivel = false;
        t.swivel_rad = best.swivel_rad;
        const WristTwistCost twist_cost{rig, plan, st};
        // (The body cost — arm in the trunk, elbow behind the body — counts as in solve_arm.)
        float best_cost = 3.0f * best.orientation_error_rad + 20.0f * best.reach_error_m + best.body_cost +
                          twist_cost(t, best);
        bool moved = false;
        glm::vec3 outward = plan.side == kLeft ? rig.left : -rig.left;
        auto try_ring = [&](float dx, float lift, float nearer = 0.0f) {
          for (float du : up_steps)
            for (float dz : in_steps) {
              glm::vec3 shift = (du + lift) * rig.up + (dz - nearer) * rig.forward + dx * outward;
              t.point = base + shift;
              ArmPose p = solve_arm(rig, plan.side, t);
              float cost = 3.0f * p.orientation_error_rad + 20.0f * p.reach_error_m +
                           1.5f * glm::length(shift) + p.body_cost + twist_cost(t, p);
              if (cost < best_cost) {
                best_cost = cost;
                best = p;
                st.target = t.point;
                moved = true;
              }
            }
        };
        try_ring(0.0f, 0.0f);
        // The second ring (8 cm out) only while the first ring's best pose still misses its
        // orientation by more than 3 degrees or has a body cost: where it already realises the
        // hand and keeps the arm clear, a place 8 cm further out (1.5 per metre of shift more)
        // rarely wins (speed-wasm, docs/SYNTHESIS.md: 3 corpus signs change; its 16 solves were
        // 2 % of the lexicon's instructions).
        if (best.orientation_error_rad > 0.05f || best.body_cost > 0.0f) try_ring(0.08f, 0.0f);
        // Further out to the hand's own side only while the orientation still misses by more
        // than 10 degrees (so most signs pay nothing for it). Fingers pointing out to that side
        // with the palm down need the forearm to point that way: from a hand in front of the
        // chest the forearm points inwards and the wrist would need 45+ degrees of ulnar
        // deviation (limit 35), and the elbow cannot come in front of the body to turn it (the
        // trunk is there, see solve_arm); with the hand in front of the shoulder the elbow stays
        // at the side and the forearm points out.
        for (float dx : {0.16f, 0.24f})
          if (best.orientation_error_rad > 0.17f) try_ring(dx, 0.0f);
        for (float lift : {0.12f})
          for (float dx : {0.0f, 0.08f})
            if (best.orientation_error_rad > 0.17f) try_ring(dx, lift);
        // Nearer the body and lower, still only while over 10 degrees: a hand pointing across
        // the body to the other side with the palm up (NUMBER's, FRIEND's and SCHOOL's left
        // hand, seed 004's place hand: 16-17 degrees off at the rings' nearest, 12 cm in) needs
        // the forearm across the body below the chest, the elbow at the side (within 3 degrees
        // 14-28 cm in and 0-12 cm lower; 8 cm nearer at the same height left 12-15).
        for (float dx : {0.0f, 0.08f})
          for (float nearer : {0.08f, 0.16f})
            if (best.orientation_error_rad > 0.17f) try_ring(dx, -0.06f, nearer);
        if (moved) {
          t.point = st.target;
          t.auto_swivel = true;
          const ArmPose fixed = best;
          best = solve_arm(rig, plan.side, t);
          // A twisting hand keeps the compared swivel if its own swivel search (which sees the
          // key pose alone) would leave less room for the twist.
          if (twist_cost.twist && 3.0f * fixed.orientation_error_rad + twist_cost(t, fixed) <
                                      3.0f * best.orientation_error_rad + twist_cost(t, best))
            best = fixed;
        }
      }
      // A hand held off the FAR side's beside place low down (the right hand beside the left
      // hip): the arm reaches across the belly, and where the slanted place body_target holds
      // it at still puts the arm in the trunk (the reference humanoid's upper arm 7-27 mm at the
      // belly to below the waist, the project avatar's 57 mm below the waist, with the arm
      // stretched), the place is searched round the anchor within the contact band: higher
      // and further in front lets the elbow come forward and bend. The arm's depth decides
      // (1 per mm), then the hand's orientation and reach, then staying near the written place.
      else if (t.body && far_side_beside(plan, spec.location) && !is_touch(spec.location.contact) &&
               best.trunk_depth_m > 0.005f) {
        const glm::vec3 across = plan.side == kRight ? rig.left : -rig.left;
        const glm::vec3 written = st.target;
        // The hand too: a hand in the hip is pushed out per frame, and the arm follows it in.
        PoseBuilder rest(rig);
        rest.set_from_local(ctx.rest_locals.data());
        auto cost = [&](const ArmPose& p, glm::vec3 target) {
          PoseBuilder posed(rig);
          pose_arm_at_rest(rig, rest, other(plan.side), glm::quat(1, 0, 0, 0), &posed);
          apply_arm(rig, plan.side, p, &posed);
          pose_fingers(rig, plan.side, st.angles, p.hand, &posed);
          posed.finalize();
          const float depth = std::max(p.trunk_depth_m, hand_penetration(ctx.body, posed, plan.side, true, false).depth_m);
          return 1000.0f * std::max(0.0f, depth - 0.002f) + 3.0f * p.orientation_error_rad +
                 20.0f * p.reach_error_m + 1.5f * glm::length(target - written);
        };
        float best_cost = cost(best, written);
        for (float distance : {contact_distance(spec.location.contact, false), 0.08f, kFarBesideHeldOff_m})
          for (float in : {0.0f, 0.5f, 1.0f, 1.5f, 2.0f, 3.0f})
            for (float up : {-0.5f, 0.0f, 0.5f, 1.0f, 1.5f, 2.0f, 3.0f}) {
              t.point = anchor.point + distance * glm::normalize(rig.forward - in * across + up * rig.up);
              ArmPose p = solve_arm(rig, plan.side, t);
              const float c = cost(p, t.point);
              if (c < best_cost) {
                best_cost = c;
                best = p;
                st.target = t.point;
              }
            }
      }
      // The same for a hand held off the far side's shoulder top (the right hand over the left
      // shoulder): held straight up off the place the arm solved with the elbow up behind the
      // head, and the transitions from the rest swung it there through the trunk (the project
      // avatar: 102-116 mm). The direction the hand is held off in is searched at the written
      // distance, scored by the posed arm's and hand's depth and by an elbow behind the
      // shoulder. (Not at the ears: there it found 18 mm for 23 on the project avatar but took
      // the reference humanoid's pointing hand from 2.5 to 21 mm.)
      else if (t.body && far_side_place(plan, spec.location) && !is_touch(spec.location.contact) &&
               spec.location.level == BodyLevel::ShoulderTop) {
        const glm::vec3 written = st.target;
        const ArmRig& arm = rig.arms[plan.side];
        // Scored on the whole rest pose with the arm solved into it, where the joints an arm
        // solve leaves (the finger metacarpals) keep the hanging hand's rotations, so the hand's
        // depth scored here is not the sign's (the project avatar's fist held off, fingers
        // across: 52-83 mm, the fingers hanging below the wrist; posed as the frames pose it,
        // 0-25 mm). Why no better score is used: the key pose does not decide the clip. As
        // solved, every candidate's forearm is 49-61 mm in the far torso half; turned out of the
        // body (turn_hand_out_of_body, below) the pointing hand's still 17-120 mm; the clip's
        // figure (13.0 mm) is what the per-frame corrections (pushes, swivel fixes, turns) make
        // of the pick. Scored after the turn and posed as the frames pose it, the fist went
        // 13.0 -> 17.0 mm and the pointing hand 10.7 -> 29.5 mm; posed right without the turn,
        // 13 -> 38 mm. The pick is kept (held by HandsAcrossTheBody) until a score of the
        // corrected frames replaces it.
        PoseBuilder posed(rig);
        auto cost = [&](const ArmPose& p, glm::vec3 target) {
          posed.set_from_local(ctx.rest_locals.data());
          apply_arm(rig, plan.side, p, &posed);
          pose_fingers(rig, plan.side, st.angles, p.hand, &posed);
          posed.finalize();
          const float depth = std::max(arm_penetration(ctx.body, posed, plan.side, true, false, false).depth_m,
                                       hand_penetration(ctx.body, posed, plan.side, true, false).depth_m);
          const float behind = std::max(0.0f, -glm::dot(posed.position(arm.lower) - posed.position(arm.upper), rig.forward));
          return 1000.0f * std::max(0.0f, depth - 0.002f) + 100.0f * behind + 3.0f * p.orientation_error_rad +
                 20.0f * p.reach_error_m + 1.5f * glm::length(target - written);
        };
        float best_cost = cost(best, written);
        const glm::vec3 n = glm::normalize(anchor.normal);
        // (Held further off, up to 8 cm, cleared more, but the per-frame pushes then left some
        // hands beyond the 10 cm band.)
        const float distance = contact_distance(spec.location.contact, false);
        for (float fwd : {0.0f, 0.5f, 1.0f, 2.0f, 4.0f})
          for (float up : {-1.0f, -0.5f, 0.0f, 0.5f, 1.0f}) {
            const glm::vec3 away = n + fwd * rig.forward + up * rig.up;
            if (glm::length(away) < 0.3f) continue;  // back into the place (the shoulder top's normal is up)
            t.point = anchor.point + distance * glm::normalize(away);
            ArmPose p = solve_arm(rig, plan.side, t);
            const float c = cost(p, t.point);
            if (c < best_cost) {
              best_cost = c;
              best = p;
              st.target = t.point;
            }
          }
      }
      // A hand held off a place on the body (no contact, or close) may be anywhere within the
      // no-contact band round it (3-10 cm, issue 4), not only straight out along the place's
      // normal. Where the written distance leaves the orientation more than 10 degrees off, the
      // band is searched for the place the wrist realises it best, as neutral space is: a few
      // centimetres higher, lower, out or further off change the forearm's direction, and with
      // it what the twist and the wrist's deviation must supply (the Ukrainian letters at the
      // chest, seed 004's L1: 9-19 degrees off held 7 cm straight out). Placements are compared
      // at the chosen swivel, the winner gets its own swivel search and is kept only if it
      // still scores better; the distances stay a centimetre inside the band for the contact
      // part's reach error. Not beside the body (`*_beside`, a place already off the skin):
      // searched there, TEACH and TEACHER (flat-O hands beside the temples, close) moved their
      // fingertips at 65-67 m/s^2 at 30-60 fps x 1.25 (bounds 52 and 63) and the reference
      // humanoid's elbow at 78 m/s^2 (59).
      else if (spec.location.kind == Location::Kind::Body && !is_touch(spec.location.contact) &&
               spec.location.contact != Contact::ArmExtended &&
               !far_side_place(plan, spec.location) &&
               spec.location.side != notation::Side::RightBeside &&
               spec.location.side != notation::Side::LeftBeside &&
               best.orientation_error_rad > kBandSearchAboveRad) {
        const glm::vec3 written = st.target;
        const glm::vec3 n = glm::normalize(anchor.normal);
        const glm::vec3 outward = plan.side == kLeft ? rig.left : -rig.left;
        ArmTarget fixed = t;
        fixed.auto_swivel = false;
        fixed.swivel_rad = best.swivel_rad;
        auto cost = [&](const ArmPose& p, glm::vec3 target) {
          return 3.0f * p.orientation_error_rad + 20.0f * p.reach_error_m +
                 1.5f * glm::length(target - written) + p.body_cost;
        };
        const float original_cost = cost(best, written);
        float best_cost = original_cost;
        glm::vec3 best_point = written;
        for (float distance : {0.05f, 0.07f, 0.09f})
          for (float up : {-0.8f, -0.4f, 0.0f, 0.4f, 0.8f})
            for (float out : {-0.4f, 0.0f, 0.4f, 0.8f}) {
              fixed.point =
                  anchor.point + distance * glm::normalize(n + up * rig.up + out * outward);
              const ArmPose p = solve_arm(rig, plan.side, fixed);
              const float c = cost(p, fixed.point);
              if (c < best_cost) {
                best_cost = c;
                best_point = fixed.point;
              }
            }
        if (best_point != written) {
          t.point = best_point;
          const ArmPose p = solve_arm(rig, plan.side, t);
          if (cost(p, best_point) < original_cost) {
            best = p;
            st.target = best_point;
          }
        }
      }
      // A hand held off its place moves within the band before it turns (hold_off_clear).
      hold_off_clear(plan, spec.location, anchor, &t, &best, &st);
      // An orientation that puts the arm in the body gives way (arm_ik.h).
      t.point = st.target;
      if (turn_hand_out_of_body(rig, plan.side, &t, &best)) st.delta = t.hand_delta;
      // A touch the folded arm cannot reach with the written orientation tilts the hand (arm_ik.h).
      if (turn_hand_to_reach(rig, plan.side, &t, &best)) st.delta = t.hand_delta;
      st.swivel = best.swivel_rad;
    }
    return st;
  }
};

// A one-handed sign whose hand comes to rest in the other arm, which hangs at rest (the right
// hand beside the far side of the belly, waist or hip, where the left arm hangs: up to 43 mm in
// its forearm): the resting arm gives way, as a signer's does. It swings rigidly about its
// shoulder joint — out to its side, forward or back — by the smallest of 0.1-0.5 rad that takes
// the hand and forearm out of it (2 mm) without putting the resting arm into the trunk; the
// model-space rotation, identity when nothing is in the way, is applied to that arm's joints
// from the upper arm down in every frame of the sign (the transitions blend it in from the rest).
glm::quat resting_arm_gives_way(Solver& solver, const std::array<HandPlan, 2>& plans,
                                const std::array<HandState, 2>& key, int resting) {
  const SynthContext& ctx = solver.ctx;
  const Rig& rig = ctx.rig;
  const glm::quat none(1, 0, 0, 0);
  const int active = 1 - resting;
  if (!ctx.options.avoid_collisions || plans[resting].active || !plans[active].active ||
      plans[active].on_other_hand)
    return none;
  const Side act = plans[active].side, rest_side = plans[resting].side;
  const ArmRig& ra = rig.arms[rest_side];
  // Only a hand well over on the resting arm's side can be in it (most signs: no check at all).
  const glm::vec3 outward = rest_side == kLeft ? rig.left : -rig.left;
  const glm::vec3 mid = rig.bind_pos[rig.chest];
  if (glm::dot(key[active].target - mid, outward) < 0.5f * glm::dot(rig.bind_pos[ra.upper] - mid, outward))
    return none;
  PoseBuilder rest(rig);
  rest.set_from_local(ctx.rest_locals.data());
  ArmTarget t;
  t.point = key[active].target;
  t.contact_offset = key[active].offset;
  t.hand_delta = key[active].delta;
  t.auto_swivel = false;
  t.swivel_rad = key[active].swivel;
  t.body = &ctx.body;
  const ArmPose ap = solve_arm(rig, act, t);
  auto depths = [&](const glm::quat& swing, float* in_other, float* rest_in_trunk) {
    PoseBuilder pb(rig);
    pose_arm_at_rest(rig, rest, rest_side, swing, &pb);
    apply_arm(rig, act, ap, &pb);
    pose_fingers(rig, act, key[active].angles, ap.hand, &pb);
    pb.finalize();
    *in_other = std::max(hand_penetration(ctx.body, pb, act, false, true).depth_m,
                         arm_penetration(ctx.body, pb, act, false, false, true).depth_m);
    *rest_in_trunk = std::max(arm_penetration(ctx.body, pb, rest_side, true, false, false).depth_m,
                              hand_penetration(ctx.body, pb, rest_side, true, false).depth_m);
  };
  float in_other = 0.0f, rest_trunk = 0.0f;
  depths(none, &in_other, &rest_trunk);
  if (in_other <= 0.005f) return none;
  // Out to its side (about the forward axis), forward and back (about the sideways axis).
  const glm::vec3 out_axis = rig.forward * (rest_side == kLeft ? 1.0f : -1.0f);
  const glm::vec3 axes[5] = {out_axis, rig.left, -rig.left, glm::normalize(out_axis + rig.left),
                             glm::normalize(out_axis - rig.left)};
  for (float angle : {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.8f})
    for (const glm::vec3& axis : axes) {
      const glm::quat swing = axis_angle(axis, angle);
      float d = 0.0f, trunk = 0.0f;
      depths(swing, &d, &trunk);
      if (d <= 0.002f && trunk <= std::max(rest_trunk, 0.002f)) return swing;
    }
  return none;
}

// Hands that cross at their key pose (LOVE's fists on the chest, DIFFERENT's index fingers,
// BOOK's palms together) are written at the same place, so the two arms were solved through each
// other (forearm through forearm by up to 74 mm). Signers lay one in front of the other: the
// dominant hand comes forward along the body's forward axis by the measured overlap of forearms
// or hands plus 4 mm (so they touch, 5 mm rule), with a fresh swivel, until clear (4 rounds, the
// shallowest kept: the forearm's angle changes as the hand moves, so one step can fall short).
//
// `near`: the swivels this pose is reached from (a movement's goal: its start). The fresh swivel
// is then chosen near them (arm_ik.h ArmTarget::near_swivel_rad), so the separation does not
// swing the elbow to another branch on the way to the goal.
// Returns the depth of the state kept (at most 3 mm when the rounds cleared it).
float separate_along_escape(Solver& solver, const std::array<HandPlan, 2>& plans,
                            std::array<HandState, 2>* key, const std::array<HandState, 2>* near) {
  const SynthContext& ctx = solver.ctx;
  const Rig& rig = ctx.rig;
  auto target_of = [&](int i) {
    ArmTarget t;
    t.point = (*key)[i].target;
    t.contact_offset = (*key)[i].offset;
    t.hand_delta = (*key)[i].delta;
    t.auto_swivel = false;
    t.swivel_rad = (*key)[i].swivel;
    t.body = &ctx.body;
    t.hand_contact = plans[i].exempt_trunk;
    return t;
  };
  // Up to kRounds moves; the shallowest state seen is kept, the one after the last move checked
  // too: that one was kept unmeasured, and on the reference humanoid DIFFERENT's forearms went
  // 37 -> 14 -> 15 -> 11 mm over the rounds (lexicon at 25-60 fps: 15.5 -> 13.4 mm). More rounds
  // (5-8) gained nothing more or swung the elbow to another branch (124 mm in a frame).
  constexpr int kRounds = 4;
  HandState best = (*key)[0];
  float best_depth_m = std::numeric_limits<float>::max();
  float written_trunk_m = 0.0f;  // the dominant arm's depth in the trunk at the written pose
  for (int round = 0; round <= kRounds; ++round) {
    PoseBuilder pb(rig);
    float trunk_m = 0.0f;
    for (int i = 0; i < 2; ++i) {
      ArmPose ap = solve_arm(rig, plans[i].side, target_of(i));
      if (i == 0) trunk_m = ap.trunk_depth_m;
      apply_arm(rig, plans[i].side, ap, &pb);
      pose_fingers(rig, plans[i].side, (*key)[i].angles, ap.hand, &pb);
      pb.finalize();
    }
    if (round == 0) written_trunk_m = trunk_m;
    const Side d = plans[0].side;
    Penetration pen = arm_penetration(ctx.body, pb, d, false, plans[0].exempt_trunk, true);
    Penetration hands = hand_penetration(ctx.body, pb, d, false, true);
    if (hands.depth_m > pen.depth_m) pen = hands;
    // A state is judged by the pair and, where its fresh swivel takes the dominant arm deeper
    // into the trunk than the written pose by more than the 5 mm rule (a real conflict, as
    // arm_in_body_conflict has it: a graze is the frames' swivel fix's), by that depth too, as
    // hands_pair_depth counts the trunk: the swivel that parts the hands can be one through the
    // body. FREE8's flat hands before the shoulders, the fingers in towards each other (project
    // avatar, the hands 5.3 mm in each other): moved 9 mm up, the freshly chosen elbow swung in
    // front of the chest, the hands clear and the arm 77 mm in the trunk (the clip's 87 mm). The
    // written place is beyond the folded arm's reach there, and the steep reach cost of a hand
    // that touches in the sign (target_of's hand_contact, arm_ik.cpp solve_arm) ranked a 30 mm
    // miss through the body above a 75 mm one beside it.
    const float into_trunk_m = trunk_m - written_trunk_m;
    const float depth_m = std::max(pen.depth_m, into_trunk_m > 0.005f ? into_trunk_m : 0.0f);
    if (depth_m <= 0.003f) return depth_m;
    if (depth_m < best_depth_m) {
      best_depth_m = depth_m;
      best = (*key)[0];
    }
    if (round == kRounds) break;
    // Out along the escape direction (palms together part sideways), but never back into the
    // body: crossed forearms escape forwards or backwards, and the front is where there is room.
    glm::vec3 dir = pen.push_dir;
    const float back = glm::dot(dir, rig.forward);
    if (back < 0.0f) dir -= back * rig.forward;
    dir = glm::length(dir) < 0.3f ? rig.forward : glm::normalize(dir);
    (*key)[0].target += (pen.depth_m + 0.004f) * dir;
    ArmTarget t = target_of(0);
    t.auto_swivel = true;
    if (near) {
      t.has_near_swivel = true;
      t.near_swivel_rad = (*near)[0].swivel;
    }
    (*key)[0].swivel = solve_arm(rig, d, t).swivel_rad;
  }
  (*key)[0] = best;
  return best_depth_m;
}

// How deep the two hands of a key pair are in each other: the dominant forearm through the other,
// either hand in the other hand or its forearm, and the dominant arm in the trunk.
float hands_pair_depth(const SynthContext& ctx, const std::array<HandPlan, 2>& plans,
                       const std::array<HandState, 2>& key, std::array<float, 2>* swivels) {
  const Rig& rig = ctx.rig;
  PoseBuilder pb(rig);
  float trunk = 0.0f;
  for (int i = 0; i < 2; ++i) {
    ArmTarget t;
    t.point = key[i].target;
    t.contact_offset = key[i].offset;
    t.hand_delta = key[i].delta;
    t.auto_swivel = false;
    t.swivel_rad = swivels ? (*swivels)[i] : key[i].swivel;
    t.body = &ctx.body;
    t.hand_contact = plans[i].exempt_trunk;
    const ArmPose ap = solve_arm(rig, plans[i].side, t);
    if (i == 0) trunk = ap.trunk_depth_m;
    apply_arm(rig, plans[i].side, ap, &pb);
    pose_fingers(rig, plans[i].side, key[i].angles, ap.hand, &pb);
    pb.finalize();
  }
  const Side d = plans[0].side;
  return std::max({trunk, arm_penetration(ctx.body, pb, d, false, plans[0].exempt_trunk, true).depth_m,
                   hand_penetration(ctx.body, pb, d, false, true).depth_m,
                   hand_penetration(ctx.body, pb, other(d), false, true).depth_m});
}

// A symmetric pair written at one place whose fingers both point across the body at the other
// hand (within 60 degrees of the lateral axis: E(lo) mirrored is 45, E(o), E(u) 90): the fingers
// cross there, and a signer lays one on the other (ASL DIFFERENT: the index fingers an X), which
// is the escape's way below (the dominant hand on top), not side by side, where they would only
// meet tip to tip. Hands at mirror places apart (HOUSE's roof: the fingertips meet) do not count.
// The escape is then kept wherever it is clean and passes the step rule against the laid-apart
// clip (sign_motion.h mirror_apart_is_kept's SignMotion overload: synthesize_sign_motion,
// choose_mirror_apart).
bool mirror_fingers_cross(const SynthContext& ctx, const std::array<HandPlan, 2>& plans,
                          const std::array<HandState, 2>& key) {
  constexpr float kAcrossCos = 0.5f, kOnePlaceM = 0.02f;
  const Rig& rig = ctx.rig;
  if (!plans[1].copy_of_dominant) return false;
  if (glm::length(key[0].target - key[1].target) > kOnePlaceM) return false;
  const glm::vec3 lateral = glm::normalize(rig.left);
  for (int i = 0; i < 2; ++i) {
    const glm::vec3 fingers = key[i].delta * rig.arms[plans[i].side].finger_dir;
    const glm::vec3 to_other = plans[i].side == kLeft ? -lateral : lateral;
    if (!(glm::dot(fingers, to_other) > kAcrossCos)) return false;
  }
  return true;
}

// A symmetric pair (the other hand the dominant one's copy, its place mirrored: hamsymmlr,
// hamsymmpar) written at one place, or at mirror places whose hands still meet, is laid apart as a
// signer holds it: both hands out to their own sides by the same amount, the places still
// mirrored. The escape below moves the dominant hand alone, along the deepest overlap's way out,
// often forward or up (the corpus's uwaga: the right hand 8 cm in front of the left at the chin,
// the left one left 15 mm in the chin; EQUAL9^'s 6 cm to the right, BUSH2^'s 12 cm): the places
// are no longer mirrored, the mirrored movements that follow take the hands through each other,
// and the frames' push of the second hand (only that one gives way) flips from frame to frame.
// Searched in steps of the pair's depth (half of it each way, and 2 mm), from the written places,
// each hand with a fresh swivel near its written one; kept only where the pair comes clear (the
// escape's 3 mm) within kMaxOutM each way, neither arm more than 5 mm deeper in the trunk than
// written. Returns whether it did (the caller keeps the clip only where it measures better:
// synthesize_sign_motion, mirror_apart_is_kept).
bool lay_mirror_pair_apart(Solver& solver, const std::array<HandPlan, 2>& plans, std::array<HandState, 2>* key) {
  const SynthContext& ctx = solver.ctx;
  const Rig& rig = ctx.rig;
  if (!plans[1].copy_of_dominant) return false;
  const glm::vec3 lateral = glm::normalize(rig.left);
  const glm::vec3 apart = (*key)[0].target - (*key)[1].target;
  // Mirror places: the targets differ along the body's left axis only, each hand on its own side,
  // at the middle, or crossed by less than 5 cm (a contact point's offset at a place in the middle:
  // myć twarz's flat hands at the head, 3.1 cm). Not hands written crossed: LOVE's fists, each at
  // the other side of the chest, 15.2 cm.
  if (glm::length(apart - glm::dot(apart, lateral) * lateral) > 0.01f) return false;
  const glm::vec3 dominant_side = plans[0].side == kLeft ? lateral : -lateral;
  if (glm::dot(apart, dominant_side) < -0.05f) return false;
  // The pair's depth (either hand in the other hand or forearm, the forearms through each other)
  // and each arm's in the trunk, posed at `k`'s swivels.
  auto measure = [&](const std::array<HandState, 2>& k, std::array<float, 2>* trunk) {
    PoseBuilder pb(rig);
    for (int i = 0; i < 2; ++i) {
      ArmTarget t;
      t.point = k[i].target;
      t.contact_offset = k[i].offset;
      t.hand_delta = k[i].delta;
      t.auto_swivel = false;
      t.swivel_rad = k[i].swivel;
      t.body = &ctx.body;
      t.hand_contact = plans[i].exempt_trunk;
      const ArmPose ap = solve_arm(rig, plans[i].side, t);
      (*trunk)[i] = ap.trunk_depth_m;
      apply_arm(rig, plans[i].side, ap, &pb);
      pose_fingers(rig, plans[i].side, k[i].angles, ap.hand, &pb);
      pb.finalize();
    }
    const Side d = plans[0].side;
    return std::max({arm_penetration(ctx.body, pb, d, false, plans[0].exempt_trunk, true).depth_m,
                     hand_penetration(ctx.body, pb, d, false, true).depth_m,
                     hand_penetration(ctx.body, pb, other(d), false, true).depth_m});
  };
  std::array<float, 2> written_trunk{};
  const float written_depth = measure(*key, &written_trunk);
  if (written_depth <= 0.003f) return false;
  constexpr float kMaxOutM = 0.15f;
  constexpr int kRounds = 12;
  std::array<HandState, 2> k = *key;
  float out_m = 0.0f, depth = written_depth;
  for (int round = 0; round < kRounds; ++round) {
    out_m += 0.5f * depth + 0.002f;
    if (out_m > kMaxOutM) return false;
    for (int i = 0; i < 2; ++i) {
      const glm::vec3 own_side = plans[i].side == kLeft ? lateral : -lateral;
      k[i].target = (*key)[i].target + out_m * own_side;
      ArmTarget t;
      t.point = k[i].target;
      t.contact_offset = k[i].offset;
      t.hand_delta = k[i].delta;
      t.body = &ctx.body;
      t.hand_contact = plans[i].exempt_trunk;
      t.has_near_swivel = true;
      t.near_swivel_rad = (*key)[i].swivel;
      k[i].swivel = solve_arm(rig, plans[i].side, t).swivel_rad;
    }
    // An arm taken deeper into the trunk than at the written places by more than the 5 mm rule
    // stops the search (the escape judges its fresh swivels so too, separate_along_escape): the
    // way out to the sides is then through the body.
    std::array<float, 2> trunk{};
    depth = measure(k, &trunk);
    if (trunk[0] > written_trunk[0] + 0.005f || trunk[1] > written_trunk[1] + 0.005f) return false;
    if (depth <= 0.003f) {
      *key = k;
      return true;
    }
  }
  return false;
}

// Returns whether the pair was laid apart to both sides (lay_mirror_pair_apart).
bool separate_crossed_hands(Solver& solver, const std::array<HandPlan, 2>& plans,
                            std::array<HandState, 2>* key, const std::array<HandState, 2>* near = nullptr) {
  const SynthContext& ctx = solver.ctx;
  const Rig& rig = ctx.rig;
  if (!ctx.options.avoid_collisions || !plans[0].active || !plans[1].active) return false;
  if (plans[0].on_other_hand || plans[1].on_other_hand || plans[0].exempt_hand) return false;
  const std::array<HandState, 2> written = *key;
  // At the key pose only: a movement's goal keeps the way its start was laid apart.
  if (!near && ctx.mirror_pairs_apart && lay_mirror_pair_apart(solver, plans, key)) return true;
  const float escape_depth = separate_along_escape(solver, plans, key, near);
  // The escape rounds measure the dominant hand and the forearms (and a trunk conflict their
  // fresh swivel makes) only: the other hand can still
  // lie in the dominant forearm. DIFFERENT on the reference humanoid: both palms written at the
  // centre, the whole hands overlap, the escape pushes alternate up and down (18 -> 11 -> 5 -> 10
  // mm) and the left hand stays 15-24 mm in the right forearm; the frames then push it out one
  // by one (37-84 mm) and its forearm sweeps through the right hand (34.4 mm). Where the pair is
  // still deeper than the 5 mm rule and the escape rounds did not clear even what they measure
  // (their pushes alternating), the dominant hand is laid clear from the written pose by the
  // smallest move that clears both hands and both forearms: up (on top), forward, out to its own
  // side and their combinations, 2-12 cm, each with a fresh swivel near the written one. Where
  // the rounds cleared it (BABY: the left hand left 41 mm in the right forearm), the frames'
  // push of the other hand does the rest (BABY 0-3.7 mm over 25-60 fps x 0.8-1.25); laid
  // clear by the search instead it reached 7.3 mm on the reference humanoid at 60 fps x 0.8.
  if (escape_depth <= 0.003f) return false;
  const float escaped = hands_pair_depth(ctx, plans, *key, nullptr);
  if (escaped <= 0.005f) return false;
  const glm::vec3 out = plans[0].side == kRight ? -rig.left : rig.left;
  const glm::vec3 dirs[7] = {rig.up, rig.forward, out, glm::normalize(rig.up + rig.forward),
                             glm::normalize(rig.up + out), glm::normalize(rig.forward + out),
                             glm::normalize(rig.up + rig.forward + out)};
  std::array<HandState, 2> best = *key;
  float best_depth = escaped;
  for (float move_m : {0.02f, 0.04f, 0.06f, 0.08f, 0.10f, 0.12f}) {
    for (const glm::vec3& dir : dirs) {
      std::array<HandState, 2> k = written;
      k[0].target += move_m * dir;
      ArmTarget t;
      t.point = k[0].target;
      t.contact_offset = k[0].offset;
      t.hand_delta = k[0].delta;
      t.body = &ctx.body;
      t.hand_contact = plans[0].exempt_trunk;
      t.has_near_swivel = true;
      t.near_swivel_rad = near ? (*near)[0].swivel : written[0].swivel;
      k[0].swivel = solve_arm(rig, plans[0].side, t).swivel_rad;
      const float d = hands_pair_depth(ctx, plans, k, nullptr);
      if (d < best_depth - 1e-4f) {
        best_depth = d;
        best = k;
      }
    }
    if (best_depth <= 0.003f) break;  // the smallest move that clears (the escape's criterion)
  }
  *key = best;
  return false;
}

// Where a place on the other hand is (plus `distance_m` along its normal) while that hand holds
// its key pose. Movements between the other hand and the body use it: the signs that do
// (GOOD, LEARN, STUDENT) hold the other hand still, as a place, so its key pose stands for the
// whole movement.
glm::vec3 other_hand_point(Solver& solver, const HandPlan& plan, const HandPlan& other_plan,
                           const HandState& other_key, HandPlace place, int finger, float distance_m) {
  const Rig& rig = solver.rig;
  PoseBuilder pb(rig);
  const ArmTarget ot = held_state_target(other_key, other_key.target);
  ArmPose op = solve_arm(rig, other_plan.side, ot);
  apply_arm(rig, other_plan.side, op, &pb);
  pose_fingers(rig, other_plan.side, other_key.angles, op.hand, &pb);
  pb.finalize();
  HandPlan at = plan;
  at.place = place;
  at.place_finger = finger;
  PartPoint p = solver.other_hand_place(pb, at);
  return p.point + distance_m * glm::normalize(p.normal);
}

// Where a hand placed on the other hand and that hand meet (seed 004 / HamNoSys: one hand as the
// place of the other). The place hand is solved first and this hand put on the named part of it,
// so this hand's orientation was whatever its arm could reach there (LATER 17 degrees off, BUY
// 19-22, LEARN 23). A signer brings both hands to where both arms hold their orientations: the
// place hand, held in neutral space (a region, not a point), moves, and this hand's elbow
// swivels. Where either hand misses by more than kBandSearchAboveRad (the band search's trigger
// for a body place), the place hand's key target is searched over a bounded grid round it, as
// the band search does round a body place: each candidate solves the place arm and this arm on
// the moved place, both at their key swivels (one solve each), scored over both hands by the
// palm's error (3 per radian; the acceptance's measure), the whole rotation's (1 per radian), the
// reach (20 per metre), the body cost and 1.5 per metre moved; the kMeetFinalists best get their
// swivels searched near their key swivels. A finalist must keep the place hand's palm within
// 10 degrees (or no worse than it was), both contacts within 1 cm, both arms out of the trunk
// (2 mm, or no deeper than they were), and bring the worse palm nearer; the best-scoring one
// wins. Only the place hand's target moves: this hand's target stays relative to its place, so
// the contact (touch, or held off 4-6 cm along the place's normal) is kept.
struct MeetingPoint {
  ArmPose place_arm, hand_arm;
  glm::vec3 place_target{0.0f}, hand_point{0.0f};
  float hand_palm_rad = 0.0f, place_palm_rad = 0.0f;
  float cost = 0.0f;
};
bool meet_where_both_hands_hold(Solver& solver, const HandPlan& plan, const HandPlan& place_plan,
                                HandState* key, HandState* place_key, ArmTarget* t, ArmPose* ap) {
  const Rig& rig = solver.rig;
  const BodyModel* body = t->body;
  // The place hand's key target: shifts (m) up, across towards the placed hand's side and
  // forward, inside the neutral space the neutral search roams (up to 24 cm out, 12 up): a
  // coarse grid (18), then the neighbours of its best (26) at half its steps; 3 finalists get
  // their swivels searched. The winners in the lexicon lie 6-12 cm forward (away from the
  // body), -12 to +18 cm up, within 8 cm across; the full grid at the fine steps (209 places)
  // finds the same within 0.5 degrees but for BUY and MONEY on the avatar (5.4 for 9.2), at 4
  // times the cost. Only for the lexicon's dozen signs over the bound, about 0.3 ms each
  // natively (docs/SYNTHESIS.md).
  static constexpr float kMeetUp[3] = {-0.12f, 0.0f, 0.12f};
  static constexpr float kMeetAcross[3] = {-0.08f, 0.0f, 0.08f};
  static constexpr float kMeetForward[2] = {-0.06f, 0.06f};
  static constexpr float kFineUpM = 0.06f, kFineAcrossM = 0.04f, kFineForwardM = 0.06f;
  constexpr float kPlaceHoldsRad = 0.17f;   // the place hand's own orientation bound (10 degrees)
  constexpr float kContactReachM = 0.01f;   // the contact's acceptance (1 cm)
  constexpr float kClearM = 0.002f;         // an arm deeper in the trunk is cleared per frame
  const glm::vec3 across = plan.side == kRight ? -rig.left : rig.left;  // to the placed hand's side
  // The palm normal's error (the acceptance's measure), which the search scores first; the
  // whole rotation's error (ArmPose::orientation_error_rad, the finger direction too) weighs a
  // third as much. Scored on the whole rotation alone, the reference humanoid's HOSPITAL found
  // 51 -> 35 degrees of rotation with the palm 24 -> 35 degrees off.
  auto palm_error = [&](Side side, const ArmPose& p, const glm::quat& requested) {
    const float c = glm::dot(posed_hand_frame(rig, side, p.hand).palm, posed_hand_frame(rig, side, requested).palm);
    return std::acos(std::clamp(c, -1.0f, 1.0f));
  };
  // held: both arms at their key swivels, as the frames pose the written meeting point;
  // otherwise each swivel is searched near its key swivel.
  auto solve_pair = [&](const glm::vec3& place_target, bool held, MeetingPoint* m) {
    ArmTarget pt;
    pt.point = place_target;
    pt.contact_offset = place_key->offset;
    pt.hand_delta = place_key->delta;
    pt.body = body;
    pt.auto_swivel = !held;
    pt.swivel_rad = place_key->swivel;
    pt.has_near_swivel = true;
    pt.near_swivel_rad = place_key->swivel;
    m->place_arm = solve_arm(rig, place_plan.side, pt);
    m->place_target = place_target;
    PoseBuilder pb(rig);
    apply_arm(rig, place_plan.side, m->place_arm, &pb);
    pose_fingers(rig, place_plan.side, place_key->angles, m->place_arm.hand, &pb);
    pb.finalize();
    const PartPoint p = solver.other_hand_place(pb, plan);
    ArmTarget ht = *t;
    ht.point = key->target + p.point + plan.place_distance_m * glm::normalize(p.normal);
    ht.auto_swivel = !held;
    ht.swivel_rad = key->swivel;
    ht.has_near_swivel = true;
    ht.near_swivel_rad = key->swivel;
    m->hand_arm = solve_arm(rig, plan.side, ht);
    m->hand_point = ht.point;
    m->hand_palm_rad = palm_error(plan.side, m->hand_arm, key->delta);
    m->place_palm_rad = palm_error(place_plan.side, m->place_arm, place_key->delta);
    m->cost = 3.0f * (m->hand_palm_rad + m->place_palm_rad) +
              (m->hand_arm.orientation_error_rad + m->place_arm.orientation_error_rad) +
              20.0f * (m->hand_arm.reach_error_m + m->place_arm.reach_error_m) + m->hand_arm.body_cost +
              m->place_arm.body_cost + 1.5f * glm::length(place_target - place_key->target);
  };
  MeetingPoint written;
  solve_pair(place_key->target, true, &written);
  // A hand misses where its palm or its whole rotation (the finger direction with it) is more
  // than 10 degrees off: the frames that follow the key pose (the per-frame pushes and turns, a
  // brush's or tap's path) take a rotation miss into the palm (the reference humanoid's NICE:
  // 5.9 degrees of palm and 13.1 of rotation at the key pose, 12.3 of palm in the clip).
  auto worst_rotation = [](const MeetingPoint& p) {
    return std::max(p.hand_arm.orientation_error_rad, p.place_arm.orientation_error_rad);
  };
  if (written.hand_palm_rad <= kBandSearchAboveRad && written.place_palm_rad <= kBandSearchAboveRad &&
      worst_rotation(written) <= kBandSearchAboveRad)
    return false;
  const float place_bound = std::max(kPlaceHoldsRad, written.place_palm_rad);
  // A candidate must bring the worse of the two palms nearer its direction (a better score that
  // trades this hand's palm for the place hand's does not count), or with both palms within
  // 10 degrees, the worse of the two rotations.
  const float worse_palm = std::max(written.hand_palm_rad, written.place_palm_rad);
  auto better = [&](const MeetingPoint& c) {
    const float palm = std::max(c.hand_palm_rad, c.place_palm_rad);
    if (palm < worse_palm) return true;
    return worse_palm <= kBandSearchAboveRad && palm <= kBandSearchAboveRad &&
           worst_rotation(c) < worst_rotation(written);
  };
  const float reach_bound = std::max(kContactReachM, written.hand_arm.reach_error_m);
  // Nor an arm deeper in the trunk than the frames leave it (their clearing turns the swivel
  // where an arm is over kClearM deep, and the palm with it: NEW on the reference humanoid,
  // 7.8 degrees at the searched key pose, 19.8 in the clip with a 0.2 rad fix; held out of the
  // trunk, 15.1).
  const float trunk_bound = std::max(kClearM, written.hand_arm.trunk_depth_m);
  const float place_trunk_bound = std::max(kClearM, written.place_arm.trunk_depth_m);
  // Candidates are compared with both arms at their key swivels (one solve each, cheap); the
  // kMeetFinalists best get their swivels searched and are held to the bounds above.
  constexpr int kMeetFinalists = 3;
  std::array<MeetingPoint, kMeetFinalists> finalists;
  int count = 0;
  MeetingPoint m;
  auto consider = [&](const glm::vec3& shift) {
    if (shift == glm::vec3(0.0f)) return;
    solve_pair(place_key->target + shift, true, &m);
    int at = std::min(count, kMeetFinalists);
    while (at > 0 && m.cost < finalists[at - 1].cost) {
      if (at < kMeetFinalists) finalists[at] = finalists[at - 1];
      --at;
    }
    if (at < kMeetFinalists) finalists[at] = m;
    count = std::min(count + 1, kMeetFinalists);
  };
  for (float up : kMeetUp)
    for (float ac : kMeetAcross)
      for (float fw : kMeetForward) consider(up * rig.up + ac * across + fw * rig.forward);
  const glm::vec3 centre = finalists[0].place_target - place_key->target;
  for (int du = -1; du <= 1; ++du)
    for (int da = -1; da <= 1; ++da)
      for (int df = -1; df <= 1; ++df)
        if (du || da || df)
          consider(centre + float(du) * kFineUpM * rig.up + float(da) * kFineAcrossM * across +
                   float(df) * kFineForwardM * rig.forward);
  MeetingPoint best = written;
  for (int k = 0; k < count; ++k) {
    solve_pair(finalists[k].place_target, false, &m);
    if (m.place_palm_rad > place_bound || m.place_arm.reach_error_m > kContactReachM ||
        m.hand_arm.reach_error_m > reach_bound || !better(m) ||
        m.hand_arm.trunk_depth_m > trunk_bound || m.place_arm.trunk_depth_m > place_trunk_bound)
      continue;
    if (m.cost < best.cost) best = m;
  }
  if (best.place_target == written.place_target) return false;
  place_key->target = best.place_target;
  place_key->swivel = best.place_arm.swivel_rad;
  key->swivel = best.hand_arm.swivel_rad;
  t->point = best.hand_point;
  *ap = best.hand_arm;
  return true;
}

// Whether a step's movements, or any of a hand's, take it to a place on the other hand or arm.
bool moves_to_the_other_hand_in(const std::vector<Movement>& step) {
  for (const Movement& m : step)
    if (m.to_location && m.to_location->kind == Location::Kind::OtherHand) return true;
  return false;
}

// Whether a movement ends on the other hand (its target place is there).
bool ends_on_the_other_hand(const Movement& m) {
  return m.to_location && m.to_location->kind == Location::Kind::OtherHand;
}

bool moves_to_the_other_hand(const HandPlan& plan) {
  for (const auto& step : plan.steps)
    if (moves_to_the_other_hand_in(step)) return true;
  return false;
}

// A symmetric pair whose dominant hand is on the other (HamNoSys: a symmetry operator and a
// hand contact, hamnosys_parser.cpp; ROUND-BALL2: flat hands palm on palm, both moving) moves
// both hands, the other hand with the dominant hand's movements mirrored. A target on "the other
// hand" among those (the touch at the end of the movement) is the dominant hand's contact with
// the other: the dominant hand keeps it, being placed on the other hand. Copied to the other hand
// it asked each hand to go to the other, each placed relative to the other (the corpus: 19 signs
// deeper, up to 117 mm). The copy keeps the movement and drops that target.
void keep_pair_contact_on_the_dominant_hand(std::vector<Movement>* copied) {
  for (Movement& m : *copied)
    if (m.to_location && m.to_location->kind == Location::Kind::OtherHand) m.to_location.reset();
}

// A symmetric pair with the dominant hand on the other (keep_pair_contact_on_the_dominant_hand)
// whose step goes to a place on the body or in space (SHOCK2A: the flat hands side by side,
// thumb side to little side, move up and in to touch the chest; TO-DIG1A: the fists, one on the
// other, to the chest and beside the shoulder) moves as one: the other hand, its copy, takes the
// pair there, the dominant hand stays on it. Both went there: the dominant hand's target is kept
// relative to the other hand's place, taken where the other hand starts (other_hand_point at its
// key pose), and the other hand's own travel was added to it per frame, so the dominant hand went
// the way twice, through the chest (SHOCK2A 15 mm, TO-DIG1A 48 mm; the upper arm in the torso).
// The dominant hand keeps its changes of shape and orientation; its path movements become
// changes in place (the other hand's copy carries the path).
void ride_on_the_carrying_hand(std::vector<Movement>* dominant_step) {
  bool to_place = false;
  for (const Movement& m : *dominant_step)
    to_place = to_place || (m.to_location && m.to_location->kind != Location::Kind::OtherHand);
  if (!to_place) return;
  for (Movement& m : *dominant_step) {
    if (m.to_location && m.to_location->kind != Location::Kind::OtherHand) m.to_location.reset();
    switch (m.kind) {
      case MovementKind::Straight: case MovementKind::Arc: case MovementKind::Circle: case MovementKind::Ellipse:
      case MovementKind::Wavy: case MovementKind::Zigzag: case MovementKind::Spiral: case MovementKind::Target:
        m.kind = MovementKind::Replace;
        break;
      default: break;
    }
  }
}

// Whether a step moves the hand along a path of its own (movement_offset's kinds), not only to
// a place or in place.
bool has_path_movement(const std::vector<Movement>& step) {
  for (const Movement& m : step) {
    switch (m.kind) {
      case MovementKind::Straight: case MovementKind::Arc: case MovementKind::Circle:
      case MovementKind::Ellipse: case MovementKind::Wavy: case MovementKind::Zigzag:
      case MovementKind::Spiral:
        return true;
      default: break;
    }
  }
  return false;
}

// A symmetric sign that writes the non-dominant hand's place (HamNoSys 4: a symmetry operator
// and a "hamparbegin place hamplus place hamparend" location; the reader gives that hand its own
// HandSpec with the dominant orientation already mirrored, hamnosys_parser.cpp nondominant_copy)
// still copies the dominant hand's movements to the other hand, and the symmetry operator mirrors
// them (HamNoSys 4 manual, symmetry operators: the non-dominant hand's handshape, orientation,
// location AND movements are the mirror image). make_plans gave that hand the signer's
// handedness only (its plan is written for it, mirror_x), so the copies went the dominant way:
// a move to the right took both hands right, a turn to palm down turned the left palm the right
// palm's way, a target beside the right of the chest took the left hand across the body there
// (the corpus's TO-BE-BROKEN1 42 mm deep, pomylić 60 mm). The copy is mirrored here, in signer
// space, by the symmetry's axes: directions, arcs, circle axes and senses (a mirror image turns
// the other way, as movement_offset's parity rule), the orientation it turns to, the side of the
// body place it moves to. A target on "the other hand" is the dominant hand's contact with the
// other: the copy drops it, as keep_pair_contact_on_the_dominant_hand (each hand sent to the
// other: Oświęcim's wrists, 49 mm).
void mirror_copy_for_the_written_other_hand(std::vector<Movement>* copied, const MirrorAxes& sym) {
  auto flip = [&sym](notation::Direction* d) {
    if (sym.x) d->x = static_cast<std::int8_t>(-d->x);
    if (sym.y) d->y = static_cast<std::int8_t>(-d->y);
    if (sym.z) d->z = static_cast<std::int8_t>(-d->z);
  };
  const bool odd = ((sym.x ? 1 : 0) + (sym.y ? 1 : 0) + (sym.z ? 1 : 0)) % 2 == 1;
  if (moves_to_the_other_hand_in(*copied)) {
    copied->clear();
    return;
  }
  for (Movement& m : *copied) {
    flip(&m.direction);
    flip(&m.arc_bulge);
    flip(&m.circle_axis);
    flip(&m.ellipse_axis);
    if (odd) m.clockwise = !m.clockwise;
    if (m.to_orientation) {
      flip(&m.to_orientation->extended_finger);
      flip(&m.to_orientation->palm);
    }
    if (m.to_location && sym.x) m.to_location->side = mirror_side(m.to_location->side);
  }
}

std::array<HandPlan, 2> make_plans(const SynthContext& ctx, const notation::SignSpec& sign) {
  const bool lh = ctx.options.left_handed;
  const Side dom = lh ? kLeft : kRight;
  std::array<HandPlan, 2> plans;
  HandPlan& d = plans[0];
  // A one-handed sign of the non-dominant hand (hamnondominant, nondominant="true") is made by
  // that hand; its HandSpec is written as a non-dominant hand is, so only the side changes.
  d.side = sign.one_hand_is_nondominant && !sign.nondominant ? other(dom) : dom;
  d.active = true;
  d.spec = sign.dominant;
  d.mirror_x = lh;
  d.move_mirror.x = lh;
  HandPlan& n = plans[1];
  n.side = other(dom);
  using notation::Symmetry;
  const Symmetry sym = sign.symmetry;
  MirrorAxes sym_axes;
  sym_axes.x = sym == Symmetry::MirrorLR || sym == Symmetry::MirrorLRUD || sym == Symmetry::MirrorLRIO;
  sym_axes.y = sym == Symmetry::MirrorLRUD || sym == Symmetry::ParallelUD;
  sym_axes.z = sym == Symmetry::MirrorLRIO || sym == Symmetry::ParallelIO;
  if (sign.nondominant) {
    n.active = true;
    n.spec = *sign.nondominant;
    n.mirror_x = lh;  // written for the left hand; a left-handed signer mirrors it too
    n.move_mirror.x = lh;
  } else if (sym != Symmetry::None) {
    n.active = true;
    n.spec = sign.dominant;
    n.mirror_x = !lh;
    n.move_mirror = sym_axes;
    n.move_mirror.x = sym_axes.x != lh;
    n.copy_of_dominant = true;
  }
  for (const auto& step : sign.movements) {
    d.steps.push_back(step.dominant);
    std::vector<Movement> nd = step.nondominant;
    // A step that says the other hand stays (hamplus hamnomotion, <nomotion/>) holds it where it
    // is: the symmetry's copy would move the hand the notation keeps still (HANDENARBEID).
    if (nd.empty() && sym != Symmetry::None && !sign.nondominant_is_place && !step.nondominant_stays) {
      nd = step.dominant;
      if (sign.dominant.location.kind == Location::Kind::OtherHand) {
        keep_pair_contact_on_the_dominant_hand(&nd);
        ride_on_the_carrying_hand(&d.steps.back());
      }
      // The symmetry alone: the plan's move_mirror adds the signer's handedness.
      if (sign.nondominant) mirror_copy_for_the_written_other_hand(&nd, sym_axes);
    }
    if (!step.nondominant.empty()) {
      // Written for the non-dominant hand itself: only the signer's handedness mirrors it.
      n.move_mirror = MirrorAxes{lh, false, false};
    }
    n.steps.push_back(sign.nondominant_is_place ? std::vector<Movement>{} : nd);
    for (const auto& m : step.dominant) n.alternating = n.alternating || m.alternating;
  }
  bool stays_said = false, moves = false;
  for (const auto& step : sign.movements) stays_said = stays_said || step.nondominant_stays;
  for (const auto& step : n.steps) moves = moves || !step.empty();
  n.written_still = n.active && stays_said && !moves;
  for (auto& p : plans) {
    const Location& loc = p.spec.location;
    if (loc.kind == Location::Kind::OtherHand) {
      p.on_other_hand = true;
      p.place = loc.hand_place;
      p.place_finger = loc.finger >= 0 ? loc.finger : 1;
      p.place_distance_m = contact_distance(loc.contact, true);
      p.exempt_hand = true;
    }
    if (loc.kind == Location::Kind::Body && is_touch(loc.contact)) p.exempt_trunk = true;
    // A hand that moves to touch the body (LEARN: from the left palm to the forehead) touches
    // it as much as one placed there: the per-frame push must not hold it off the forehead.
    for (const auto& step : p.steps)
      for (const auto& m : step)
        if (m.to_location && m.to_location->kind == Location::Kind::Body && is_touch(m.to_location->contact))
          p.exempt_trunk = true;
  }
  // Hands in contact with each other (placed on, or moving to, the other): neither counts as
  // penetrating the other.
  if (plans[0].on_other_hand || plans[1].on_other_hand || moves_to_the_other_hand(plans[0]) ||
      moves_to_the_other_hand(plans[1]))
    plans[0].exempt_hand = plans[1].exempt_hand = true;
  return plans;
}

// The hand solved second gives way to the first (the per-frame pushes out of the other hand and
// forearm, then clear_arm's swivel fix), and its corrections are ramped in over the frames
// around. A hand the notation keeps still (HamNoSys `hamplus hamnomotion`, G-SiGML <nomotion/>,
// and no movement of its own in any step) was the one that gave way to the dominant hand moving
// past it: the flat hands palm down at the chest, the right one moving up beside the left, moved
// the left wrist 105 mm and its elbow 219 mm on the reference humanoid for a 14 mm overlap of the
// hands. The moving hand goes round it instead. Only where the notation says so: for every
// non-dominant hand without a movement of its own the corpus's procent (the left hand held in
// neutral space, the right forearm sweeping down across it) went 1.5 -> 41.4 mm, the moving
// forearm cannot clear the hand its pushes leave in it (docs/SYNTHESIS.md, ref-drift).
bool holds_still_while_the_other_moves(const HandPlan& still, const HandPlan& moving) {
  if (!still.written_still || !moving.active || still.on_other_hand) return false;
  for (const auto& step : moving.steps)
    if (!step.empty()) return true;
  return false;
}

// Whether a place on a hand or arm moves with the hand alone: the arm's places (forearm,
// elbow, upper arm) are where the arm's solve puts them, not at an offset from the hand joint
// (Solver::part_offset poses the fingers only).
bool hand_borne_place(HandPlace p) {
  return p != HandPlace::Forearm && p != HandPlace::ForearmBack && p != HandPlace::Elbow &&
         p != HandPlace::ElbowInside && p != HandPlace::UpperArm;
}

// Whether a hand is placed on, or moves to, a place on the other ARM (not borne by the hand).
bool presents_the_arm(const HandPlan& plan) {
  if (plan.on_other_hand && !hand_borne_place(plan.place)) return true;
  for (const auto& step : plan.steps)
    for (const Movement& m : step)
      if (m.to_location && m.to_location->kind == Location::Kind::OtherHand &&
          !hand_borne_place(m.to_location->hand_place))
        return true;
  return false;
}

// A two-handed sign whose hands are each written on the other (a symmetric sign with a hand
// contact and no location symbol: RUBBING-ONES-HANDS-TOGETHER, the palm on the palm; FRESH, the
// thumb tips together; SHIP, the fingertips together; 120 of the real-sign corpus's clean signs).
// In HamNoSys a sign without a location symbol is made in neutral space, and a hand contact in a
// two-handed sign says the hands touch each other there (HamNoSys 4 manual, "hand constellation";
// docs SOURCES.md). Neither hand has a place of its own, so the non-dominant hand becomes the
// place of the dominant one: it is held at the neutral-space place of its written side (the
// centre unless written otherwise) with the part the dominant hand touches at the anchor, so the
// pair meets there; the dominant hand stays on it at the named part. From there the existing
// placement takes over (the neutral-space search, the place rounds, meet_where_both_hands_hold),
// as for a place hand written in neutral space. The place hand keeps its orientation, shape and
// movements (none when the notation makes it the place: SignSpec::nondominant_is_place).
void place_pair_in_neutral_space(HandPlan* place_plan, const HandPlan& placed) {
  Location& loc = place_plan->spec.location;
  loc.kind = Location::Kind::NeutralSpace;
  loc.level = BodyLevel::NeutralSpace;
  loc.contact = Contact::None;  // its contact is the placed hand's, which touches it
  if (hand_borne_place(placed.place)) {
    loc.contact_part = placed.place;
    loc.contact_finger = static_cast<std::int8_t>(placed.place_finger);
  } else {
    loc.contact_part.reset();  // an arm place: the hand is held at the anchor, the rounds bring the arm
    loc.contact_finger = -1;
  }
  place_plan->on_other_hand = false;
  place_plan->place_distance_m = 0.0f;
  place_plan->exempt_hand = true;  // the hands touch on purpose
}

// The body's turns a one-handed sign may take for a hand on or beside the FAR side of the body
// (far_side_turns; each is taken only where its key pose measures shallower, below).
//
// From the stomach down (the right hand at the left hip) the arm reaches across the belly and,
// with the trunk unturned, lay in it however the place was held off and the elbow swung (a fist
// touching beside the far side below the waist: upper arm 61-79 mm in the torso). A signer
// turns the upper body towards that side, which brings the place forward of the reaching
// shoulder. kFarSideThoraxTurnRad: 20 degrees, about half the thoracolumbar axial rotation a
// standing adult has each way (about 35-45 degrees, most of it thoracic), so a reach, not a
// twist to the limit.
constexpr float kFarSideThoraxTurnRad = 0.35f;
// With the turn, the trunk may also lean forward 0.2 rad (11 degrees; trunk flexion goes to
// 60-90), which lowers the shoulder towards a place below the waist (measured: the reference
// humanoid's fists touching beside the far side below the waist 37.8 / 36.5 -> 7.6 / 3.3 mm;
// 0.1 rad 21.5 / 14.8, 0.3 and 0.4 no better on the project avatar). Only below the waist: at
// the waist and belly the place is within the arm's reach and leaning put the clips deeper
// (the reference humanoid's fist touching beside the waist 14.1 -> 17.2 mm, the belly 4.6 ->
// 8.3), though their key poses as scored measured shallower. A side bend towards the far side
// instead raised the reaching shoulder (0.1 rad: 37.8 -> 40.3 mm below the waist).
constexpr float kFarSideLeanRad = 0.2f;
// At the far ear (the right hand at the left ear) the forearm crossed the face into the head
// (the project avatar 14-41 mm, the reference humanoid's fist touching 13.7 mm): the head turns
// towards the reaching hand and presents the ear, 0.4 rad (23 degrees; the neck turns 70-80 each
// way). Measured over the ears' 15 cases a rig (5 hands x touch, close, none): 0.2 rad left the
// avatar at 38 mm, 0.4 rad at 17.5, 0.6 rad at 10.7 with a third of the turn more; the thorax
// turn does not help there (the head's anchors turn with the chest, less the neck's give-back).
// The eyes keep their gaze (the face layer counter-rotates them).
// The same turn is offered at the far side of the neck (at or beside it): the neck's anchors turn
// with the neck, which brings its far side forward, and the jaw turns away from the forearm.
// Measured on the project avatar (taken only where the key pose measures shallower, as every
// turn): the fist across the body touching beside the neck 12.7 -> 2.0 mm (forearm in the head),
// with the fingers up 2.8 -> 1.9; held off the neck's `left` place the flat hand ends 10.8 cm
// from it instead of 11.3 (no contact 9.2 instead of 11.9); the fist across the body touching
// that place 1.8 -> 4.0 mm (its turned key pose scored shallower; the clip's head is turned,
// the IK's is not). The reference humanoid takes it nowhere in these sweeps.
constexpr float kFarEarHeadTurnRad = 0.4f;

std::vector<ThoraxTurn> far_side_turns(const SynthContext& ctx, const std::array<HandPlan, 2>& plans) {
  std::vector<ThoraxTurn> turns;
  if (!ctx.options.avoid_collisions) return turns;
  const HandPlan& d = plans[0];
  if (!d.active || plans[1].active || d.on_other_hand) return turns;
  const Location& loc = d.spec.location;
  if (loc.kind != Location::Kind::Body) return turns;
  // Towards the far side: the right hand's shoulder forward is a positive turn about up; the
  // head towards the right hand a negative one.
  const float towards_far = d.side == kRight ? 1.0f : -1.0f;
  const bool far = Solver::far_side_beside(d, loc) || Solver::far_side_place(d, loc);
  if (far && static_cast<int>(loc.level) >= static_cast<int>(BodyLevel::Stomach) &&
      static_cast<int>(loc.level) <= static_cast<int>(BodyLevel::BelowWaist)) {
    turns.push_back(make_thorax_turn(ctx.rig, towards_far * kFarSideThoraxTurnRad));
    if (loc.level == BodyLevel::BelowWaist)
      turns.push_back(make_thorax_turn(ctx.rig, towards_far * kFarSideThoraxTurnRad, kFarSideLeanRad));
  }
  if ((Solver::far_side_place(d, loc) && loc.level == BodyLevel::Ears) || (far && loc.level == BodyLevel::Neck))
    turns.push_back(make_thorax_turn(ctx.rig, 0.0f, 0.0f, -towards_far * kFarEarHeadTurnRad));
  return turns;
}

// How far a one-handed sign's key pose (plans[0]'s hand at `st`, the other arm at rest) is
// in the body, as the sign's frames pose it: the arm and the hand in the trunk (the hand not when
// it touches on purpose), plus, for a touch, how far it stops short of its place beyond 5 mm.
float key_pose_depth(Solver& solver, const std::array<HandPlan, 2>& plans, const HandState& st) {
  const SynthContext& ctx = solver.ctx;
  const Rig& rig = ctx.rig;
  const HandPlan& plan = plans[0];
  const bool touch = is_touch(plan.spec.location.contact);
  ArmTarget t = held_state_target(st, st.target);
  t.body = &ctx.body;
  t.hand_contact = touch;
  const ArmPose ap = solve_arm(rig, plan.side, t);
  PoseBuilder rest(rig);
  rest.set_from_local(ctx.rest_locals.data());
  PoseBuilder pb(rig);
  pose_arm_at_rest(rig, rest, plans[1].side, glm::quat(1, 0, 0, 0), &pb);
  apply_arm(rig, plan.side, ap, &pb);
  pose_fingers(rig, plan.side, st.angles, ap.hand, &pb);
  pb.finalize();
  float depth = arm_penetration(ctx.body, pb, plan.side, true, touch, false).depth_m;
  if (!touch) depth = std::max(depth, hand_penetration(ctx.body, pb, plan.side, true, false).depth_m);
  return depth + (touch ? std::max(0.0f, ap.reach_error_m - 0.005f) : 0.0f);
}

}  // namespace

std::string body_anchor_name(const Location& loc, bool mirror_x) {
  notation::Side side = mirror_x ? mirror_side(loc.side) : loc.side;
  if (loc.kind == Location::Kind::NeutralSpace || loc.level == BodyLevel::NeutralSpace)
    return std::string("space/") + side_name(side);
  if (loc.kind == Location::Kind::OtherHand) return "";
  return std::string("body/") + level_name(loc.level) + "/" + side_name(side);
}

bool validate_options(const SynthesisOptions& options, std::string* error) {
  if (!(options.fps >= 5.0f && options.fps <= 240.0f)) {
    *error = "fps must be between 5 and 240 (got " + std::to_string(options.fps) + ")";
    return false;
  }
  if (!(options.speed >= 0.1f && options.speed <= 10.0f)) {
    *error = "speed must be between 0.1 and 10 (got " + std::to_string(options.speed) + ")";
    return false;
  }
  face::Emotion emotion{};
  if (!face::emotion_from_name(options.emotion, &emotion)) {
    *error = "unknown emotion '" + options.emotion + "' (one of: neutral, happy, sad, angry, "
             "surprised, fear, disgust, sleepy)";
    return false;
  }
  if (!(options.emotion_intensity >= 0.0f && options.emotion_intensity <= 1.0f)) {
    *error = "emotion intensity must be between 0 and 1 (got " +
             std::to_string(options.emotion_intensity) + ")";
    return false;
  }
  return true;
}

bool make_context(const avatar::Avatar& avatar, const SynthesisOptions& options, SynthContext* ctx,
                  std::string* error) {
  ctx->avatar = &avatar;
  ctx->options = options;
  if (!validate_options(options, error)) return false;
  if (!build_rig(avatar, &ctx->rig, error)) return false;
  ctx->body = build_body_model(avatar, ctx->rig);
  const Rig& rig = ctx->rig;
  // Rest pose: arms hanging a little out and forward, hands relaxed, palms to the thighs.
  PoseBuilder pb(rig);
  notation::HandShape relaxed;
  for (int k = 1; k < 5; ++k) relaxed.fingers[k] = notation::FingerConfig{0, true, 0.82f, 0.0f};
  relaxed.fingers[0] = notation::FingerConfig{notation::kThumbAlongside, false, 1.0f, 0.0f};
  HandAngles rest = handshape_angles(relaxed);
  for (int s = 0; s < 2; ++s) {
    const ArmRig& a = rig.arms[s];
    glm::vec3 out = s == kLeft ? rig.left : -rig.left;
    float reach = 0.95f * (a.upper_len_m + a.lower_len_m);
    ArmTarget t;
    t.point = rig.bind_pos[a.upper] + reach * glm::normalize(-rig.up + 0.22f * out + 0.12f * rig.forward);
    t.contact_offset = glm::vec3(0.0f);
    t.hand_delta = hand_delta_for(rig, static_cast<Side>(s), HandFrame{-rig.up, -out});
    ArmPose p = solve_arm(rig, static_cast<Side>(s), t);
    apply_arm(rig, static_cast<Side>(s), p, &pb);
    pose_fingers(rig, static_cast<Side>(s), rest, p.hand, &pb);
  }
  pb.finalize();
  ctx->rest_locals.resize(rig.joint_count);
  pb.local_rotations(ctx->rest_locals.data());
  return true;
}

namespace {

// A played step's frames in the sign's clip: [begin, end), its states n and its states at speed 1.
struct StepSpan {
  size_t begin = 0, end = 0;
  int states = 0, states_at_speed_1 = 0;
};

// The sign's frames with step i (in the order played) at step_states[i] states where that is
// more than the speed factor gives it (0 or missing: as the speed factor gives); each played
// step's span into `spans`. choose_branch: a frame continuing a wrist flip is solved from the
// previous wrist too, and that kept where it is no deeper and nearer (solve_frames);
// `continued_frames` (optional) receives how many hand-frames continue a flip.
// `usual_alternative` (optional): where the jam rule's clip was kept, the clip without the rule
// (finished alike); otherwise an empty SignMotion. extra_ramp_rounds: more last ramp rounds where
// the last one's corrections leap (ramp_rounds; synthesize_sign_motion_ramped_again asks).
bool synthesize_sign_motion_timed(const SynthContext& ctx, const notation::SignSpec& sign,
                                  const std::string& where, const std::vector<int>& step_states,
                                  bool choose_branch, SignMotion* result, std::vector<SynthesisError>* errors,
                                  std::vector<StepSpan>* spans, int* continued_frames,
                                  SignMotion* usual_alternative, bool extra_ramp_rounds = false) {
  const Rig& rig = ctx.rig;
  const float fps = ctx.options.fps, speed = ctx.options.speed;
  Solver solver(ctx, errors, where);
  std::array<HandPlan, 2> plans = make_plans(ctx, sign);
  if (plans[0].on_other_hand && plans[1].on_other_hand) place_pair_in_neutral_space(&plans[1], plans[0]);
  if ((plans[0].on_other_hand || moves_to_the_other_hand(plans[0])) && !plans[1].active) {
    // A place on the other hand needs that hand: hold it in neutral space, palm up. So does a
    // one-handed sign that moves to it (the corpus's INJECTION1A: into the crook of the other
    // elbow; NGT BLOED_AFNEMEN), which make_plans no longer drops (the reader's brackets).
    plans[1].active = true;
    plans[1].spec = notation::HandSpec{};
    plans[1].spec.orientation.extended_finger = {1, 0, 1};
    plans[1].spec.orientation.palm = {0, 1, 0};
    plans[1].spec.location.kind = Location::Kind::NeutralSpace;
    plans[1].spec.location.side = notation::Side::Left;
    // A place on the arm (the crook of the elbow, the upper arm): held with the hand in front of
    // the chest, that arm's elbow and upper arm hang beside the torso, and the reaching arm went
    // through the chest to them (the corpus's INJECTION1A 64 mm, T-SHIRT1 127 mm). A signer
    // presents the arm, held out in front (HamNoSys's hamarmextended).
    if (presents_the_arm(plans[0])) plans[1].spec.location.contact = notation::Contact::ArmExtended;
    plans[1].mirror_x = ctx.options.left_handed;
    plans[1].steps.assign(plans[0].steps.size(), {});
  }
  // A touch on the other hand missing its place by more than kPlaceMissM moves the place
  // (below), for up to kPlaceRounds rounds or until the miss is under kPlaceReachM. The first
  // move also takes the place kPlaceForwardM forward: the point of the elbow's sphere nearest
  // DAY's written place pulls the upper arm across the chest, into the torso in the arc down
  // (measured, 3 rounds: no forward move 10.4 mm deep on the reference humanoid and 7.5 on the
  // avatar, 3 cm 8.7/3.9, 5 cm 7.8/2.3 with the touch still within 7-8 mm; more rounds creep
  // the place back in). An arm still in the trunk at a round also moves the place out by its
  // depth plus kPlaceClearM.
  constexpr float kPlaceMissM = 0.01f, kPlaceReachM = 0.002f, kPlaceClearM = 0.02f;
  constexpr float kPlaceForwardM = 0.05f;
  constexpr int kPlaceRounds = 3;
  // A one-handed sign's hand on the far side: the body turns it may take (far_side_turns).
  const std::vector<ThoraxTurn> body_turns = far_side_turns(ctx, plans);
  // Solve order: a hand that is the place of the other goes first.
  std::array<int, 2> order = {0, 1};
  // So does the other arm of a hand that moves to a place on it (arm_place, below), and a hand
  // the notation keeps still while the other moves.
  if (plans[0].on_other_hand ||
      (presents_the_arm(plans[0]) && plans[1].active && !plans[1].on_other_hand) ||
      holds_still_while_the_other_moves(plans[1], plans[0]))
    order = {1, 0};

  // Key states.
  std::array<HandState, 2> key;
  // A hand on the other hand whose contact part is on its arm and whose place was moved (below):
  // its per-frame target is its wrist, this far from the contact target of the key pose, so a
  // movement moves the hand and not the elbow.
  std::array<bool, 2> wrist_led = {false, false};
  // A hand that moves to a place on the other ARM (INJECTION1A: into the crook of the elbow): its
  // goal is that place where the other arm holds its key pose (other_hand_point), but the frames
  // still clear that arm out of the trunk by turning its swivel (the presented arm 0.1 rad on both
  // test rigs), which carries the elbow and the upper arm 14-20 mm away from where the goal was
  // taken. The place, its distance and where it was at the key pose, per hand; the frames move
  // the hand with the place by HandState::on_arm_place.
  struct ArmPlace {
    HandPlace place = HandPlace::Palm;
    int finger = 1;
    float distance_m = 0.0f;
    glm::vec3 at_key{0.0f};
  };
  std::array<ArmPlace, 2> arm_place;
  std::array<glm::vec3, 2> wrist_from_contact = {glm::vec3(0.0f), glm::vec3(0.0f)};
  size_t before = errors->size();
  for (int i = 0; i < 2; ++i) {
    if (!plans[i].active) continue;
    bool ok = true;
    key[i] = solver.key_state(plans[i], plans[i].spec, &ok, nullptr);
  }
  if (errors->size() > before) return false;
  // A turn is taken where it takes the key pose less deep into the body (or a touch nearer its
  // place): the key state is solved again in each turned body's frame; the shallowest wins, the
  // unturned pose unless a turn gains half a millimetre (docs/SYNTHESIS.md, the figures).
  if (!body_turns.empty()) {
    float best = key_pose_depth(solver, plans, key[0]) - 0.0005f;
    ThoraxTurn chosen;
    for (const ThoraxTurn& turn : body_turns) {
      solver.set_thorax_turn(turn);
      bool ok = true;
      const HandState turned = solver.key_state(plans[0], plans[0].spec, &ok, nullptr);
      const float depth = ok ? key_pose_depth(solver, plans, turned) : best;
      if (depth < best) {
        best = depth;
        key[0] = turned;
        chosen = turn;
      }
    }
    solver.set_thorax_turn(chosen);
  }
  // A hand placed on the other hand had the default swivel (key_state cannot know where that
  // place is): MORNING's left hand in the crook of the right elbow was held with its elbow down
  // into the body and the per-frame clearing flipped it between two swivels (45 cm in a frame).
  // Its key swivel is chosen, with the body model, where the place is at the other hand's key pose.
  for (int i = 0; i < 2; ++i) {
    const HandPlan& op = plans[1 - i];
    if (!plans[i].active || !plans[i].on_other_hand || !op.active || op.on_other_hand) continue;
    ArmTarget t;
    t.point = key[i].target + other_hand_point(solver, plans[i], op, key[1 - i], plans[i].place,
                                               plans[i].place_finger, plans[i].place_distance_m);
    t.contact_offset = key[i].offset;
    t.hand_delta = key[i].delta;
    t.body = ctx.options.avoid_collisions ? &ctx.body : nullptr;
    ArmPose ap = solve_arm(rig, plans[i].side, t);
    key[i].swivel = ap.swivel_rad;
    // A place the hand cannot reach comes to it (DAY: the right elbow on the back of the left
    // hand, written in neutral space, beyond the reach of the upper arm from the shoulder: the
    // elbow missed it by 78 mm on the avatar, 116 mm on the reference humanoid). The place
    // hand's key target moves by the residual, towards where the contact part actually is
    // (ArmPose::contact_point; hand_parts' elbow anchor is not the point the solver aims), and
    // both are solved again; the place hand keeps its own swivel choice (body model, limits)
    // and its per-frame clearing. Its later goals start from this target (a goal without a new
    // location keeps it), so it stays there for the whole sign.
    //
    // For a hand that holds still on its place, or whose contact part is on its arm. A movement
    // of the hand on the place moves its contact part's target; DAY's arc down-left moved the
    // elbow's 5 cm, off its reachable sphere at the moved place: the right wrist's twist ran to
    // its limit and the wrist jumped 13-19 cm in a frame (MotionSmoothness). An arm contact is
    // therefore led by its wrist through its movement (wrist_led): the arc moves the hand, the
    // elbow stays. A hand contact with a movement keeps the written place (not measured yet).
    bool holds_still = true;
    for (const auto& step : plans[i].steps) holds_still = holds_still && step.empty();
    HandPlace cpart;
    int cfinger;
    contact_part(plans[i].spec, &cpart, &cfinger);
    const bool arm_part = cpart == HandPlace::Elbow || cpart == HandPlace::Forearm ||
                          cpart == HandPlace::ForearmBack || cpart == HandPlace::UpperArm ||
                          cpart == HandPlace::ElbowInside;
    // So does a place whose hand reaches it only through the trunk (MORNING: the left hand in the
    // crook of the right elbow, which hangs at the side of the body; the left arm reached across
    // the whole torso, 96 mm in it at the key pose on the reference humanoid, cleared frame by
    // frame to 4.9-7.0 mm over the frame rates and speeds): the place moves out by that arm's
    // depth + kPlaceClearM and kPlaceForwardM forward, as for a miss (one round brings it to 0).
    const bool moves_place = (holds_still || arm_part) && (ap.reach_error_m > kPlaceMissM || ap.trunk_depth_m > 0.005f);
    for (int round = 0; moves_place && round < kPlaceRounds && (ap.reach_error_m > kPlaceReachM || ap.trunk_depth_m > 0.005f); ++round) {
      glm::vec3 residual = ap.contact_point - t.point;
      if (ap.trunk_depth_m > 0.0f) residual += (ap.trunk_depth_m + kPlaceClearM) * ap.trunk_push_dir;
      if (round == 0) residual += kPlaceForwardM * rig.forward;
      HandState& place_key = key[1 - i];
      place_key.target += residual;
      ArmTarget pt;
      pt.point = place_key.target;
      pt.contact_offset = place_key.offset;
      pt.hand_delta = place_key.delta;
      pt.body = t.body;
      pt.has_near_swivel = true;
      pt.near_swivel_rad = place_key.swivel;
      ArmPose pap = solve_arm(rig, op.side, pt);
      place_key.swivel = pap.swivel_rad;
      t.point = key[i].target + other_hand_point(solver, plans[i], op, place_key, plans[i].place,
                                                 plans[i].place_finger, plans[i].place_distance_m);
      t.has_near_swivel = true;
      t.near_swivel_rad = key[i].swivel;
      ap = solve_arm(rig, plans[i].side, t);
      key[i].swivel = ap.swivel_rad;
    }
    // Both hands meet where both hold their orientations (meet_where_both_hands_hold): only a
    // place hand held still in neutral space moves (its key target holds for the whole sign).
    // Not for a contact part on the arm led by its wrist through a movement (DAY's elbow on the
    // back of the left hand): searched after the place rounds, the reference humanoid's palm came
    // to 0 degrees, but the frames' arm clearing turns the swivel there (0.4 -> 0.6 rad), which
    // the key pose's body cost does not see, and the wrist-led elbow misses its place by 39 mm
    // (the first grid: 27 mm on the avatar, the elbow sliding 6.6 cm along the other hand);
    // searched before them, the rounds undid most of it (15-20 degrees) and the elbow slid 27 cm.
    bool place_still = true;
    for (const auto& step : op.steps) place_still = place_still && step.empty();
    const Location& ploc = op.spec.location;
    if (place_still && !arm_part &&
        (ploc.kind == Location::Kind::NeutralSpace || ploc.level == BodyLevel::NeutralSpace))
      meet_where_both_hands_hold(solver, plans[i], op, &key[i], &key[1 - i], &t, &ap);
    if (moves_place && !holds_still) {
      wrist_led[i] = true;
      wrist_from_contact[i] = arm_segments(rig, plans[i].side, ap).wrist - t.point;
    }
  }
  const bool fingers_cross = mirror_fingers_cross(ctx, plans, key);
  const bool mirror_laid_apart = separate_crossed_hands(solver, plans, &key);
  std::array<glm::quat, 2> give_way = {resting_arm_gives_way(solver, plans, key, 0),
                                       resting_arm_gives_way(solver, plans, key, 1)};

  // Segments: (step, reversed, return-to-start). Repetitions per seed/HamNoSys.
  struct Segment { int step; bool reversed; bool back_to_start; };
  std::vector<Segment> segments;
  const int steps = static_cast<int>(sign.movements.size());
  for (int s = 0; s < steps; ++s) segments.push_back({s, false, false});
  using notation::RepeatKind;
  const auto& rep = sign.repetition;
  int extra = std::max(1, rep.count);
  if (rep.kind == RepeatKind::FromStartSeveral || rep.kind == RepeatKind::ContinuingSeveral) extra = std::max(2, rep.count);
  if (steps > 0 && rep.kind != RepeatKind::None) {
    for (int r = 0; r < std::min(extra, 8); ++r) {
      if (rep.kind == RepeatKind::FromStart || rep.kind == RepeatKind::FromStartSeveral) {
        segments.push_back({-1, false, true});
        for (int s = 0; s < steps; ++s) segments.push_back({s, false, false});
      } else if (rep.kind == RepeatKind::Reverse) {
        bool back = r % 2 == 0;
        for (int s = 0; s < steps; ++s) {
          int idx = back ? steps - 1 - s : s;
          segments.push_back({idx, back, false});
        }
      } else {
        for (int s = 0; s < steps; ++s) segments.push_back({s, false, false});
      }
    }
  }

  // Per-frame targets: for each hand, a function of the frame giving its HandState.
  struct FrameTarget { std::array<HandState, 2> hand; };
  // Bitwise: equal states give equal solutions (a +0/-0 or NaN mismatch only costs a solve).
  static_assert(std::is_trivially_copyable<HandState>::value &&
                    sizeof(HandState) % sizeof(float) == 0 && alignof(HandState) == alignof(float),
                "HandState is compared bitwise: floats only, no padding");
  auto same_states = [](const FrameTarget& a, const FrameTarget& b) {
    return std::memcmp(a.hand.data(), b.hand.data(), sizeof(a.hand)) == 0;
  };
  // A sign's solve state, per frame (and hand) and the clip solved from it: what a second try of
  // the solve (another swivel side for a run of fixes, another rule) starts from and what it is
  // compared against. One struct, so a try is one copy and a restore one assignment: restored by
  // hand field by field, a field could be forgotten (stop 19's merge added final_wrist to one).
  struct ClipSolveState {
    std::vector<FrameTarget> frames;
    // The hand turns and swivel offsets clear_arm applied, per frame and hand (identity / 0: none).
    std::vector<std::array<glm::quat, 2>> turns;
    std::vector<std::array<float, 2>> swivel_fixes;
    // The swivel offsets the ramp rounds added to each frame so far (clear_arm's preferred side).
    std::vector<std::array<float, 2>> swivel_ramped;
    // The per-frame push out of the body / the other hand, per frame and hand (zero: none).
    std::vector<std::array<glm::vec3, 2>> push_offsets;
    // The arm pose each frame ended its first solve with, per hand, and whether it was continued.
    std::vector<std::array<ArmPose, 2>> solved;
    std::vector<std::array<char, 2>> continued;
    // Each frame's finished wrist per hand (after its pushes and arm clearing).
    std::vector<std::array<glm::vec3, 2>> final_wrist;
    SignMotion out;
  };
  ClipSolveState st;
  std::vector<FrameTarget>& frames = st.frames;
  auto add_hold = [&](float seconds) {
    int n = std::max(1, static_cast<int>(std::lround(seconds * fps / speed)));
    for (int i = 0; i < n; ++i) frames.push_back(frames.back());
  };
  frames.push_back(FrameTarget{key});
  if (steps == 0) {
    add_hold(ctx.options.hold_s);
  } else {
    add_hold(0.08f);
    std::array<HandState, 2> state = key;
    std::array<HandState, 2> start_state = key;
    // Remember each played segment's start and goal (before path offsets) so a reversed one can
    // retrace it.
    std::vector<std::array<HandState, 2>> seg_start(steps), seg_goal(steps);
    // Per hand: whether an earlier step moved it away from its written location.
    std::array<bool, 2> relocated = {false, false};
    // Per hand touching the body at its written place: the place's outward normal, which a
    // circle there starts against (movement.h movement_offset; zero: none).
    std::array<glm::vec3, 2> touch_outward = {glm::vec3(0.0f), glm::vec3(0.0f)};
    for (int i = 0; i < 2; ++i) {
      const Location& loc = plans[i].spec.location;
      PartPoint place;
      if (plans[i].active && loc.kind == Location::Kind::Body && loc.level != BodyLevel::NeutralSpace &&
          is_touch(loc.contact) &&
          solver.body_anchor(body_anchor_name(loc, plans[i].mirror_x), &place) &&
          glm::length(place.normal) > 1e-6f)
        touch_outward[i] = glm::normalize(place.normal);
    }
    // Which way round a hand turns from `from` to `goal` (true: the other way than
    // slerp_shortest). A turn of more than kAmbiguousTurnRad can go either way at nearly the same
    // length; the way the arm follows is the one the IK reaches best at a quarter, half and three
    // quarters of the way (3 * orientation error + 20 * reach error + the body cost, the swivel
    // choice's units, arm_ik.h). STUDENT's two 180-degree turns (the pinched hand from the left
    // palm, fingers down, to the forehead, fingers in; then to fingers out, palm left) went the
    // way the rounding chose: on the project avatar through orientations 90+ degrees out of the
    // wrist's reach, so the wrist held and then swung round the fingertip (98 mm in a frame).
    auto choose_turn_direction = [&](int i, const std::array<HandState, 2>& from,
                                     const std::array<HandState, 2>& goal) {
      const float short_turn = rotation_angle(glm::conjugate(from[i].delta) * goal[i].delta);
      if (short_turn < kAmbiguousTurnRad) return false;
      const HandPlan& op = plans[1 - i];
      glm::vec3 place(0.0f);
      if (plans[i].on_other_hand && op.active)
        place = other_hand_point(solver, plans[i], op, key[1 - i], plans[i].place, plans[i].place_finger,
                                 plans[i].place_distance_m);
      float cost[2] = {0.0f, 0.0f};
      for (int way = 0; way < 2; ++way)
        for (float s : {0.25f, 0.5f, 0.75f}) {
          const HandState h = mix_state(from[i], goal[i], s);
          ArmTarget t = held_state_target(h, h.target + place);
          if (way) t.hand_delta = slerp_other_way(from[i].delta, goal[i].delta, s);
          t.body = ctx.options.avoid_collisions ? &ctx.body : nullptr;
          t.hand_contact = plans[i].exempt_trunk;
          const ArmPose ap = solve_arm(rig, plans[i].side, t);
          cost[way] += 3.0f * ap.orientation_error_rad + 20.0f * ap.reach_error_m + ap.body_cost;
        }
      // The other way only when it is clearly better: near a tie the choice would follow the
      // rounding of the solves (native and WebAssembly must make the same clip).
      return cost[1] < cost[0] - 0.01f;
    };
    for (const Segment& seg : segments) {
      std::array<HandState, 2> from = state, goal = state;
      std::array<bool, 2> other_way = {false, false};  // the hand turns the other way round
      std::array<bool, 2> wrist_path = {false, false};  // the wrist, not the contact part, travels
      std::array<std::vector<Movement>, 2> ms;
      float duration = 0.3f, hold = 0.0f;
      if (seg.back_to_start) {
        goal = start_state;
      } else if (seg.reversed) {
        // Retrace: from the forward segment's goal back to its start, offsets played backwards
        // (at s = 0 this is exactly where the forward segment ended).
        from = seg_goal[seg.step];
        goal = seg_start[seg.step];
        for (int i = 0; i < 2; ++i)
          if (seg.step < static_cast<int>(plans[i].steps.size())) ms[i] = plans[i].steps[seg.step];
        for (int i = 0; i < 2; ++i)
          for (const auto& m : ms[i]) duration = std::max(duration, movement_duration_s(m));
      } else {
        bool goal_changed = false;
        for (int i = 0; i < 2; ++i) {
          if (!plans[i].active || seg.step >= static_cast<int>(plans[i].steps.size())) continue;
          ms[i] = plans[i].steps[seg.step];
          // A path in the same step (THANK-YOU: Par(M(straight, do), M(replace, E(o), P(u))))
          // takes the hand away from its place while it changes orientation or shape: like a
          // hand an earlier step relocated (below), it turns about its wrist, not about the
          // written contact part. Turned about the fingertips at the chin, fingers forward put
          // the goal's wrist 18 cm behind the chin, in the neck (the reference humanoid's
          // forearm 86 mm in the torso along the path, cleared frame by frame by swivel fixes
          // of up to 1.5 rad that never settled: 3.1 m/s, 93 m/s^2 at 60 fps).
          // (Not a contact part on the arm: DAY's elbow stays on the other hand while the
          // forearm turns about it, wrist_led above.)
          const bool leaves_place = !wrist_led[i] && std::any_of(ms[i].begin(), ms[i].end(), [](const notation::Movement& mv) {
            return mv.kind == MovementKind::Straight || mv.kind == MovementKind::Arc;
          });
          const bool to_place = std::any_of(ms[i].begin(), ms[i].end(), [](const notation::Movement& mv) {
            return mv.kind == MovementKind::Target && mv.to_location.has_value();
          });
          const bool turns = std::any_of(ms[i].begin(), ms[i].end(), [](const notation::Movement& mv) {
            return mv.to_orientation.has_value();
          });
          // A hand that travels to a new place while it turns (GOOD: the fingertips from the
          // chin to the left palm, turning from fingers up, palm in, to fingers forward, palm
          // up) moves its wrist along the path and turns about it. Its contact point's path
          // with the turn about the fingertips swung the wrist back into the neck near the chin
          // (the reference humanoid's elbow 3.25 m/s, 123 m/s^2 at 30 fps x 1.25, as the frames'
          // swivel fixes chased the forearm out of the torso). Both ends are as before.
          wrist_path[i] = !wrist_led[i] && to_place && turns;
          for (const auto& m : ms[i]) {
            duration = std::max(duration, movement_duration_s(m));
            hold = std::max(hold, movement_hold_s(m));
            // Changes of handshape / orientation / location during the movement.
            notation::HandSpec spec = plans[i].spec;
            bool changed = false;
            if (m.to_shape) { spec.shape = *m.to_shape; changed = true; }
            if (m.to_orientation) { spec.orientation = *m.to_orientation; changed = true; }
            const bool to_other_hand = m.to_location && m.to_location->kind == Location::Kind::OtherHand;
            if (m.to_location) {
              spec.location = *m.to_location;
              changed = true;
            }
            if (changed) {
              goal_changed = true;
              bool ok = true;
              HandState g = solver.key_state(plans[i], spec, &ok, nullptr, &goal[i].swivel);
              if (!ok) return false;
              // A movement to a place on the other hand (GOOD: chin -> left palm) was not
              // followed: the hand stayed at the chin and only turned, about its fingertips,
              // which swung the wrist behind the chin in one frame (51 cm). Its goal is that
              // place where the other hand holds its key pose, so the hand travels the path
              // from its start to there (minimum-jerk, orientation slerped with it) and the arm
              // is solved per frame along it.
              //
              // The reverse (LEARN: from the left palm to the forehead) had the opposite defect:
              // a hand placed on the other hand has its target relative to that place, and the
              // absolute forehead goal was added to the palm's position per frame (the hand
              // aimed far past the head). The goal is made relative to the same place.
              const HandPlan& op = plans[1 - i];
              if (to_other_hand && !plans[i].on_other_hand && op.active && !op.on_other_hand) {
                const Location& to = *m.to_location;
                g.target = other_hand_point(solver, plans[i], op, key[1 - i], to.hand_place,
                                            to.finger >= 0 ? to.finger : 1, contact_distance(to.contact, true));
                if (!hand_borne_place(to.hand_place)) {
                  arm_place[i] = {to.hand_place, to.finger >= 0 ? to.finger : 1,
                                  contact_distance(to.contact, true), g.target};
                  g.on_arm_place = 1.0f;
                }
                ArmTarget t;
                t.point = g.target;
                t.contact_offset = g.offset;
                t.hand_delta = g.delta;
                t.body = ctx.options.avoid_collisions ? &ctx.body : nullptr;
                t.has_near_swivel = true;
                t.near_swivel_rad = goal[i].swivel;
                g.swivel = solve_arm(rig, plans[i].side, t).swivel_rad;
              } else if (m.to_location && !to_other_hand && plans[i].on_other_hand && op.active) {
                g.target -= other_hand_point(solver, plans[i], op, key[1 - i], plans[i].place,
                                             plans[i].place_finger, plans[i].place_distance_m);
              }
              if (!m.to_location) g.target = goal[i].target;
              if (!m.to_location && (relocated[i] || leaves_place)) {
                // A hand that an earlier step moved away from its written place keeps its
                // wrist where it is while it changes shape or orientation: the written contact
                // part belongs to the written place. Turning about that fingertip at the
                // forehead (STUDENT: fingers turned out, palm in) put the wrist inside the
                // head and the arm behind it (57 cm in a frame).
                g.target = goal[i].target - goal[i].delta * goal[i].offset + g.delta * g.offset;
              }
              if (plans[i].on_other_hand && op.active) {
                // key_state leaves a hand on the other hand at the default swivel (its place is
                // known only per frame); a goal away from that place (STUDENT: at the forehead,
                // turning the palm in) then pulled the elbow into the body and the per-frame
                // clearing flipped it. The swivel is chosen where the goal is. So is that of a
                // goal still on the place: LEARN's change to the pinched hand on the left palm
                // swung the elbow from its key swivel (2.0 rad) to the default 0.4, with the
                // wrist at all its limits (orientation 71 degrees off) on the way.
                ArmTarget t;
                t.point = g.target + other_hand_point(solver, plans[i], op, key[1 - i], plans[i].place,
                                                      plans[i].place_finger, plans[i].place_distance_m);
                t.contact_offset = g.offset;
                t.hand_delta = g.delta;
                t.body = ctx.options.avoid_collisions ? &ctx.body : nullptr;
                t.has_near_swivel = true;
                t.near_swivel_rad = goal[i].swivel;
                g.swivel = solve_arm(rig, plans[i].side, t).swivel_rad;
              }
              goal[i].angles = g.angles;
              goal[i].delta = g.delta;
              goal[i].offset = g.offset;
              goal[i].target = g.target;
              goal[i].swivel = g.swivel;
              if (m.to_location) goal[i].on_arm_place = g.on_arm_place;
            }
          }
        }
        // Hands that meet at the goal are laid apart there, as at the key pose (BOOK: the
        // palms-together hands turn palms up where they met and overlap). Left to the per-frame
        // push (which moves the second hand solved, out of the first), the separation came on within a few frames at the
        // end of the movement and its residual rounds jumped (the left wrist 83 mm in a frame,
        // 86 mm change of step on the avatar). Decided at the goal, it is interpolated along the
        // movement like the rest of the state.
        if (goal_changed) separate_crossed_hands(solver, plans, &goal, &from);
        for (int i = 0; i < 2; ++i)
          for (const auto& m : ms[i]) relocated[i] = relocated[i] || m.to_location.has_value();
        seg_start[seg.step] = from;
        seg_goal[seg.step] = goal;
      }
      // Every segment (a step, its retrace, the return of a repetition from the start): the
      // hand's turn goes the way the arm reaches, and lasts at least its turn at
      // kMeanHandTurnRadPerS (the minimum-jerk peak is 1.875 times that). A retrace samples the
      // same states as its step, so it takes the same way back.
      for (int i = 0; i < 2; ++i) {
        if (!plans[i].active) continue;
        other_way[i] = choose_turn_direction(i, from, goal);
        float turn = rotation_angle(glm::conjugate(from[i].delta) * goal[i].delta);
        if (other_way[i]) turn = 6.28318531f - turn;
        duration = std::max(duration, turn / kMeanHandTurnRadPerS);
      }
      int n = std::max(2, static_cast<int>(std::lround(duration * fps / speed)));
      const size_t played = spans->size();
      if (played < step_states.size()) n = std::max(n, step_states[played]);
      spans->push_back(
          {frames.size(), 0, n, std::max(2, static_cast<int>(std::lround(duration * fps)))});
      std::array<HandState, 2> last = from;
      for (int f = 1; f <= n; ++f) {
        float s = minimum_jerk(static_cast<float>(f) / n);
        float path_s = seg.reversed ? 1.0f - s : s;
        FrameTarget ft;
        std::array<glm::vec3, 2> travel = {glm::vec3(0.0f), glm::vec3(0.0f)};  // the path's offsets
        for (int i = 0; i < 2; ++i) {
          HandState h = mix_state(from[i], goal[i], s);
          const glm::vec3 state_target = h.target;  // before the path's offsets
          if (other_way[i]) h.delta = slerp_other_way(from[i].delta, goal[i].delta, s);
          if (wrist_path[i]) {
            const glm::vec3 w0 = from[i].target - from[i].delta * from[i].offset;
            const glm::vec3 w1 = goal[i].target - goal[i].delta * goal[i].offset;
            h.target = w0 + s * (w1 - w0) + h.delta * h.offset;
          }
          glm::vec3 reference = h.delta * rig.arms[plans[i].side].palm_normal;
          bool alt = i == 1 && plans[1].alternating;
          const glm::vec3 outward = relocated[i] ? glm::vec3(0.0f) : touch_outward[i];
          for (const auto& m : ms[i]) {
            float ps = path_s;
            // A path that ends on the other hand (hammovel hampalm hamtouch: left, onto the
            // other palm) has its end in the goal state already (that place, other_hand_point):
            // the direction is the way there and its size the distance, not a further move. Its
            // whole offset on top of the goal took the index 11-12 cm past the palm (a straight
            // move's size, movement_size_m). The path keeps its shape (an arc's bulge, a wave)
            // less the chord, so it starts at the start and ends on the place.
            // (A hand already on the other hand keeps its path: its goal is its own place there.)
            const bool lands = ends_on_the_other_hand(m) && !plans[i].on_other_hand &&
                               plans[1 - i].active && !plans[1 - i].on_other_hand;
            auto offset = [&](float at) {
              glm::vec3 o = movement_offset(rig, m, plans[i].move_mirror, at, reference, outward);
              if (lands)
                o -= at * movement_offset(rig, m, plans[i].move_mirror, 1.0f, reference, outward);
              return o;
            };
            const glm::vec3 before_path = h.target;
            if (alt && movement_is_cyclic(m)) {
              float shifted = std::fmod(ps + 0.5f, 1.0f);
              h.target += offset(shifted) - offset(0.5f);
            } else if (alt) {
              h.target -= offset(ps);
            } else {
              h.target += offset(ps);
            }
            travel[i] += h.target - before_path;
            // A wrist movement (nod, swing, twist, circle) turns the hand at the wrist: the
            // wrist stays where it is. Turning it about the contact part instead (the target is
            // where that part goes) swung the wrist around the palm (Й's twist: the wrist's
            // per-frame step changed by 73 mm from one frame to the next).
            //
            // Wrist motions cycle at a constant rate (wrist_motion's phase is the step's time):
            // on the minimum-jerk path parameter the middle cycle ran 1.9 times faster than the
            // others and WALK's flapping fingertips changed their step by 72 mm. Twists too: one
            // drives the forearm's rotation into its limit (Й: E(u), P(o), the hand already at
            // the forearm's, the ulnar and the extension limit), where the clamped wrist angles
            // jumped; timed at a constant rate that passed under the flip threshold
            // (kWristFlipRadPerS: Й's ring tip 46 -> 81 mm change of step), so twists had kept
            // the warped timing whose fast middle the flip rule caught. The frames of a wrist
            // motion now turn the hand as the key pose's wrist realises it and refit the
            // clamped angles beyond a limit (ArmTarget::wrist_motion).
            const float time_s = static_cast<float>(f) / n;
            const float phase = seg.reversed ? 1.0f - time_s : time_s;
            const glm::quat motion = wrist_motion(rig, plans[i].side, m, phase);
            const glm::quat turned = h.delta * motion;
            h.wrist_turn = h.wrist_turn * motion;
            h.target += turned * h.offset - h.delta * h.offset;
            h.delta = turned;
            if (m.kind == MovementKind::FingerPlay) h.angles = finger_play(h.angles, ps);
          }
          if (wrist_led[i]) {
            // The contact part on the arm (DAY's elbow) stays on its place and the wrist goes
            // round it at the distance the key pose has: the movement turns the forearm about
            // the elbow. The path's offset moves the wrist's direction from the elbow, not the
            // elbow. Moved by the offset alone, DAY's arc down-left (12 cm) took the wrist 0.586 m
            // from the shoulder joint on the reference humanoid, beyond the 0.55 m arm: the arm
            // ran straight, the elbow slid 6 cm along the other hand and the upper arm went
            // 5.6 mm into the torso.
            const glm::vec3 path = h.target - state_target + wrist_from_contact[i];
            const float forearm_m = glm::length(wrist_from_contact[i]);
            if (forearm_m > 1e-4f)
              h.target = state_target + forearm_m * safe_normalize(path, wrist_from_contact[i] / forearm_m) -
                         wrist_from_contact[i];
          }
          ft.hand[i] = h;
        }
        // A hand placed on the other hand that makes a path of its own while the other hand makes
        // one too (a symmetric pair on each other: AUGUST5's "hampalm hamclose hamcircleu", the
        // palms circling against each other) goes its own path in space. Its target is an offset
        // from the other hand's place as posed at each frame, which already carries the other
        // hand's path; the two added sent the right hand round about twice as far in and out,
        // through the chest (AUGUST5 55 mm deep with its orientation pair read; strzelać 14 mm,
        // przerwa 8.5 mm). A hand with no path of its own rides the other
        // (ride_on_the_carrying_hand).
        for (int i = 0; i < 2; ++i) {
          const int j = 1 - i;
          if (!plans[i].on_other_hand || !plans[j].active || plans[j].on_other_hand) continue;
          if (has_path_movement(ms[i]) && has_path_movement(ms[j])) ft.hand[i].target -= travel[j];
        }
        frames.push_back(ft);
        last = ft.hand;
      }
      spans->back().end = frames.size();
      state = last;
      if (hold > 0.0f) add_hold(hold);
    }
    add_hold(0.12f);
  }

  // Solve every frame: IK per hand (fixed swivel along the path, so the elbow moves smoothly),
  // fingers by FK, then push a hand out of the body if it entered it unintentionally.
  const int J = rig.joint_count;
  st.out = std::move(*result);
  SignMotion* const out = &st.out;
  out->mirror_laid_apart = mirror_laid_apart;
  out->mirror_fingers_cross = mirror_laid_apart && fingers_cross;
  out->frame_count = static_cast<int>(frames.size());
  out->rotations.resize(static_cast<size_t>(out->frame_count) * J);
  out->exempt.assign(out->frame_count, 0);
  std::uint8_t exempt = 0;
  for (int i = 0; i < 2; ++i) {
    if (plans[i].exempt_trunk) exempt |= exempt_bit(plans[i].side, false);
    if (plans[i].exempt_hand) exempt |= exempt_bit(plans[i].side, true);
  }
  // The arm itself: a swivel interpolated between two clear key poses can still take the elbow
  // or forearm through the trunk (a movement across the body), or a forearm through the other
  // one. Then this frame uses the nearest swivel that clears it (the hand's target, orientation
  // and fingers unchanged); the needed offset changes gradually along a path, so does the elbow.
  auto clear_arm = [&](const HandPlan& plan, bool check_forearm, ArmTarget* t, const HandState& h,
                       PoseBuilder* pb, glm::quat* applied_turn, float* applied_swivel, float prefer,
                       bool only_prefer, float min_gain_m, float clear_m) {
    // Scored with the hand's own penetration too: another swivel leaves the wrist other angles
    // within its limits, and the hand must not turn into the body instead.
    auto depth_of = [&]() {
      return std::max(arm_penetration(ctx.body, *pb, plan.side, true, plan.exempt_trunk, check_forearm).depth_m,
                      hand_penetration(ctx.body, *pb, plan.side, !plan.exempt_trunk, check_forearm).depth_m);
    };
    // Poses this arm (and its fingers) as `ap` and scores it.
    auto depth_with = [&](const ArmPose& ap) {
      apply_arm(rig, plan.side, ap, pb);
      pose_fingers(rig, plan.side, h.angles, ap.hand, pb);
      pb->finalize();
      return depth_of();
    };
    if (arm_penetration(ctx.body, *pb, plan.side, true, plan.exempt_trunk, check_forearm).depth_m <= clear_m) return;
    float depth = depth_of();
    const float base = t->swivel_rad;
    const ArmPose base_pose = solve_arm(rig, plan.side, *t);
    const float base_reach = base_pose.reach_error_m;
    float best_depth = depth, best_swivel = base;
    ArmPose best_pose = base_pose;  // the winner's pose, kept (solving it again gave the same)
    // With a preferred side (the way earlier ramp rounds already turned this frame's elbow),
    // the nearest clear swivel on the other side no longer wins at once: it flipped the fix's
    // sign between neighbouring frames (TELL's, THANK-YOU's elbow leaving the chin: -0.1 then
    // +0.1 rad, where +0.2 also cleared the first), and the ramp, which follows the larger
    // neighbour, then jumped by 0.3 rad between them (the elbow 78 mm in a frame).
    std::array<ArmPose, 25> tried;  // by step: 12 + k on the + side, 12 - k on the - side
    const SwivelChoice choice = nearest_clear_swivel(depth, 0.002f, prefer, min_gain_m, [&](float offset, bool* usable) {
      t->swivel_rad = base + offset;
      ArmPose& ap = tried[static_cast<size_t>(12 + std::lround(offset * 10.0f))];
      ap = solve_arm(rig, plan.side, *t);
      *usable = ap.reach_error_m <= base_reach + 0.002f;  // a touch must still touch
      return *usable ? depth_with(ap) : 0.0f;
    }, only_prefer);
    if (choice.offset_rad != 0.0f) {
      best_depth = choice.depth_m;
      best_swivel = base + choice.offset_rad;
      best_pose = tried[static_cast<size_t>(12 + std::lround(choice.offset_rad * 10.0f))];
    }
    t->swivel_rad = best_swivel;
    *applied_swivel = best_swivel - base;
    ArmPose ap = best_pose;
    if (best_depth > 0.002f) {
      // No swivel clears it: the wrist itself is in the body; the hand turns out about its
      // contact point (kept only if that helps the arm without pushing the hand in).
      ArmTarget turned = *t;
      ArmPose tp = ap;
      if (turn_hand_out_of_body(rig, plan.side, &turned, &tp)) {
        float d = depth_with(tp);
        if (d < best_depth - 1e-4f) {
          best_depth = d;
          ap = tp;
          *t = turned;
          *applied_turn = turned.hand_delta * glm::conjugate(h.delta);
        }
      }
    }
    apply_arm(rig, plan.side, ap, pb);
    pose_fingers(rig, plan.side, h.angles, ap.hand, pb);
    pb->finalize();
    if (best_swivel != base || t->hand_delta != h.delta) ++out->pushes;
  };
  PoseBuilder rest(rig);
  rest.set_from_local(ctx.rest_locals.data());
  // The hand turns and swivel offsets clear_arm applied, per frame and hand (identity / 0: none).
  auto& turns = st.turns;
  turns.resize(frames.size());
  auto& swivel_fixes = st.swivel_fixes;
  swivel_fixes.resize(frames.size());
  // The swivel offsets the ramp rounds added to each frame so far (clear_arm's preferred side).
  auto& swivel_ramped = st.swivel_ramped;
  swivel_ramped.resize(frames.size(), {0.0f, 0.0f});
  // The side a run of swivel fixes is given as a whole (+1 / -1; 0: chosen per frame), per hand.
  std::vector<std::array<float, 2>> forced_side(frames.size(), {0.0f, 0.0f});
  // The per-frame push out of the body / the other hand, per frame and hand (zero: none).
  auto& push_offsets = st.push_offsets;
  push_offsets.resize(frames.size(), {glm::vec3(0.0f), glm::vec3(0.0f)});
  // A wrist that flips: where a hand's requested orientation is out of the wrist's reach, the
  // clamped wrist angles can change branch between two frames (twist and flexion from one limit
  // to the other: LEARN's pinched hand on its way to the forehead, the wrist 17 cm in a frame).
  // A change of a wrist angle faster than kWristFlipRadPerS (the top of a wrist's speed: forearm
  // rotation and wrist flexion peak at about 10-15 rad/s in fast movements; written wrist
  // movements here turn at 3-4 rad/s; measured, 20 rad/s left GOOD's wrist jumping on the
  // reference rig) marks a flip; that frame holds the
  // previous frame's wrist angles (arm_ik.h ArmTarget::previous; the reach rounds keep the
  // contact on its target), and the next ones turn from there at kWristTurnRadPerS until the
  // free solution is within that step again (hysteresis: the wrist turns through, then joins
  // the free solution without a jump). Frames without a flip are solved as before.
  // kWristTurnRadPerS: 6 rad/s, an unhurried wrist turn; measured on the lexicon, 4 rad/s left
  // LEARN's wrist so far behind its target at the forehead that the arm solve broke away (37 cm
  // in a frame), 9 rad/s raised STUDENT's step change to 96 mm.
  constexpr float kWristFlipRadPerS = 15.0f;
  constexpr float kWristTurnRadPerS = 6.0f;
  // On a path (a frame whose states differ from the previous one's), a swivel that leaves the
  // arm in the body gaining less than kMinSwivelGainM is no fix: among near-equal depths the
  // best moved by noise from frame to frame (THANK-YOU at the end of its path, arm 80 mm in at
  // any swivel: +0.1 rad gaining 0.1 mm at one frame, +0.6 gaining 0.4 mm at the next, each
  // with its own turn of the hand: 71 mm change of step). Held frames keep every gain (a key
  // pose has no neighbour to jump against, and the transitions start from it: 1 mm there
  // deepened the far-side rest transitions by up to 2 mm).
  constexpr float kMinSwivelGainM = 0.001f;
  // The arm pose each frame ended its first solve with, per hand, and whether it was continued.
  auto& solved = st.solved;
  solved.resize(frames.size());
  auto& continued = st.continued;
  continued.resize(frames.size(), {0, 0});
  // Each frame's finished wrist per hand (after its pushes and arm clearing), and how much deeper
  // than the usual start's a continued frame solved from the previous wrist may end (0.5 mm:
  // below the collision checks' rounding of a posed capsule, and a quarter of the 2 mm a push
  // lets stand).
  auto& final_wrist = st.final_wrist;
  final_wrist.resize(frames.size(), {glm::vec3(0.0f), glm::vec3(0.0f)});
  constexpr float kBranchDepthSlackM = 0.0005f;
  auto wrist_change = [](const ArmPose& a, const ArmPose& b) {
    return std::max({std::fabs(a.twist_rad - b.twist_rad), std::fabs(a.wrist_dev_rad - b.wrist_dev_rad),
                     std::fabs(a.wrist_flex_rad - b.wrist_flex_rad)});
  };
  // `redo` (second pass): only the frames whose orientation or swivel the ramps changed are
  // solved again; the others would come out identical (every frame is solved from scratch), and
  // re-solving them doubled the time of every sign with one corrected frame.
  bool ramp_only = false;  // the last ramp round: ramp the earlier corrections, add none
  // In it, only an arm deeper than kRampOnlyClearM is still corrected (at once): the lexicon's
  // arm depth bound, 5 mm (the clip's check measures these frames as they are), less 0.1 mm for
  // rounding. Without that net the ramped residuals left THANK-YOU's and TELL's forearms 9.9 mm
  // and GOOD's 10.9 mm in the torso on the reference humanoid (25 fps x 1, 30 fps x 1.25); with
  // it at 2 mm (every round alike) the one-frame fixes stayed (OLD above). At 4 mm (a 1 mm
  // margin) it still made one: OLD on the reference humanoid at 60 fps, where the swivel each
  // frame needs changes faster than any ramp (the frame before clear at +1.2 rad and over 2 mm
  // deep at +1.5, this one in the torso at +1.2): the forearm 4.x mm deep got +0.3 rad for
  // that frame alone, the elbow 8.7 cm up and back (153 m/s^2). A frame within the bound is not
  // worth a jerk: at 4.9 mm OLD's elbow keeps to 22-32 m/s^2 at 60 fps and its arm goes 4.6 ->
  // 4.7 mm deep (MotionSmoothness.EveryLexiconSignMovesHumanlyAndKeepsItsArmsOut...); nothing
  // else in the lexicon changes.
  constexpr float kRampOnlyClearM = 0.0049f;
  // How much deeper than the key pose's place a movement's contact point may go into the trunk
  // (trunk_crossing's allowed_m): a touch's acceptance, 1 cm.
  constexpr float kMovementStopDepthM = 0.01f;
  // Which hands stop at the body (collision.h trunk_crossing). A hand moved only by directions
  // (HamNoSys's hamchest hamclose hammovei hamtouch: in to the chest and touch) goes no further
  // in than the body: a direction's amplitude is a size, not a place, and the touch that ends it
  // is at the body (FEAR1's, SICK1's fist 5 cm into the chest, the forearm 33 mm in the torso
  // behind it). A hand with a movement to a place (DEAF's ear to the mouth) goes between places
  // on the body: its straight line may cut a chord of the head and stays as written, unless at
  // some frame it goes through the body (its target past the far side of a capsule's axis). Every
  // frame of a stopping hand stops, so its path halts at the body instead of going in and jumping
  // back.
  std::array<bool, 2> stops_at_body = {false, false};
  for (int i = 0; i < 2 && ctx.options.avoid_collisions; ++i) {
    if (!plans[i].active || plans[i].on_other_hand) continue;
    bool to_place = false;
    for (const auto& step : plans[i].steps)
      for (const Movement& m : step) to_place = to_place || (m.kind == MovementKind::Target && m.to_location);
    // Checked once per target along the sign, against the trunk at rest: a hand none of whose
    // targets would stop is not checked frame by frame (no lexicon sign's is).
    const glm::vec3& from = frames[0].hand[i].target;
    for (size_t f = 1; f < frames.size() && !stops_at_body[i]; ++f) {
      const glm::vec3& to = frames[f].hand[i].target;
      if (to == frames[f - 1].hand[i].target) continue;
      const TrunkCrossing c = trunk_crossing(ctx.body, rest, from, to, kMovementStopDepthM);
      stops_at_body[i] = c.stop != to && (!to_place || c.through);
    }
  }
  // A continued frame's pose before its first way and after it (choose_branch, below); made once,
  // their buffers reused.
  PoseBuilder pb_start(rig), pb_usual(rig);
  // A hand caught between two trunk or hand capsules (the hand at the chin: out of the head is
  // into the torso and back) is pushed out of each in turn, and the way it finally leaves by
  // depends on which was deepest at each attempt: it flipped between neighbouring frames (the
  // corpus's cztery tygodnie temu, sign frames 21-23: (0.150, 0.005, -0.079), (-0.038, -0.039,
  // -0.196), (-0.141, -0.068, -0.072) m, the wrist 25 cm in a frame). `any_jam`: some push in
  // the solve went against the attempt before it; `jam_rule`: such a push goes along the sum of
  // the two ways and forward (away from the body) instead (the choice after the ramps below).
  bool jam_rule = false, any_jam = false;
  auto solve_frames = [&](const std::vector<char>* redo) {
    if (!redo || (*redo)[0]) {
      out->max_reach_error_m = 0.0f;
      out->contact_distance_m.clear();
    }
    if (!redo) out->pushes = 0;
    int prev_pushes = 0;  // what the previous frame of this pass added to out->pushes
    // One builder for the pass, set to a new one's state at each frame by assignment, which
    // keeps its storage (4 k builders a lexicon pass were allocated per frame, speed-wasm).
    const PoseBuilder fresh(rig);
    PoseBuilder pb(rig);
    for (int f = 0; f < out->frame_count; ++f) {
      if (redo && !(*redo)[f]) continue;
      // A hold repeats its frame's hand states, and a frame is solved from its states alone but
      // for a wrist turning through a flip (`continued`, below): the frame just solved in this
      // pass with the same states has this one's solution unless that frame's wrist was turning
      // through (it moves on while the states hold). Holds are a third of a sign's frames (all
      // but one of a static sign's), each an IK solve and collision checks per hand. A copied
      // frame hands its first solve on to the next frame's flip check: copying without it made
      // the next frame see a jump from a zero pose and hold a wrist that never flipped.
      if (f > 0 && (!redo || (*redo)[f - 1]) && !continued[f - 1][0] && !continued[f - 1][1] &&
          same_states(frames[f], frames[f - 1])) {
        std::copy_n(&out->rotations[static_cast<size_t>(f - 1) * J], J, &out->rotations[static_cast<size_t>(f) * J]);
        solved[f] = solved[f - 1];
        continued[f] = continued[f - 1];
        out->exempt[f] = exempt;
        turns[f] = turns[f - 1];
        swivel_fixes[f] = swivel_fixes[f - 1];
        push_offsets[f] = push_offsets[f - 1];
        final_wrist[f] = final_wrist[f - 1];
        out->pushes += prev_pushes;
        continue;
      }
      const int pushes_before = out->pushes;
      const bool moving = f > 0 && !same_states(frames[f], frames[f - 1]);
      pb = fresh;
      // Inactive hands keep the rest pose (the arm swung out of the other hand's way, if it is
      // in it: resting_arm_gives_way).
      for (int i = 0; i < 2; ++i)
        if (!plans[i].active) pose_arm_at_rest(rig, rest, plans[i].side, give_way[i], &pb);
      pb.finalize();
      for (int oi = 0; oi < 2; ++oi) {
        int i = order[oi];
        const HandPlan& plan = plans[i];
        if (!plan.active) continue;
        const HandState& h = frames[f].hand[i];
        ArmTarget t;
        t.point = h.target;
        if (plan.on_other_hand) {
          PartPoint place = solver.other_hand_place(pb, plan);
          t.point = place.point + plan.place_distance_m * glm::normalize(place.normal) + h.target;
        } else if (h.on_arm_place > 0.0f && oi == 1 && plans[1 - i].active) {
          // On the way to a place on the other arm: that arm is solved first (order), and the
          // hand follows where its place is now, by the share of the way it has come. (Not the
          // hand solved first: the other arm is not posed yet. A symmetric pair each moving to
          // the other's forearm, the corpus's zapomnieć: 21 -> 92 mm when it read the unposed arm.)
          const ArmPlace& a = arm_place[i];
          const PartPoint place = solver.other_hand_place(pb, plan.side, a.place, a.finger);
          t.point += h.on_arm_place *
                     (place.point + a.distance_m * glm::normalize(place.normal) - a.at_key);
        }
        // The contact point stops at the body (stops_at_body, above), the line from the key pose's.
        if (stops_at_body[i] && f > 0)
          t.point = trunk_crossing(ctx.body, pb, frames[0].hand[i].target, t.point, kMovementStopDepthM).stop;
        t.contact_offset = h.offset;
        if (wrist_led[i]) {
          t.point += wrist_from_contact[i];
          t.contact_offset = glm::vec3(0.0f);
        }
        t.hand_delta = h.delta;
        t.auto_swivel = false;
        t.swivel_rad = h.swivel;
        t.wrist_motion = h.wrist_turn;
        t.body = ctx.options.avoid_collisions ? &ctx.body : nullptr;
        t.hand_contact = plan.exempt_trunk;
        bool check_hand = oi == 1 && !plan.exempt_hand && plans[order[0]].active;
        const glm::vec3 start_point = t.point;
        // A frame that continues a wrist flip (`continued`) is solved twice: from solve_at's usual
        // start, then from the previous wrist's (ArmTarget::start_at_previous_wrist), each with its
        // pushes and arm clearing. The iteration has an answer on either side of the contact point
        // and the start picks one (TO-SLEEP2^ swapped sides, the right elbow 437 mm in a frame).
        // Chosen per arm solve, before the pushes and the clearing, the near side left arms in the
        // trunk that those then had to fix (contact-turn, rule E: rajstopy 34.7 -> 95.9 mm): the
        // frame's final depth decides, so the choice is made here, on the finished frame.
        const ArmTarget t_start = t;
        if (choose_branch) pb_start = pb;
        const int pushes_start = out->pushes;
        ArmTarget t_usual;
        ArmPose solved_usual;
        glm::vec3 push_usual(0.0f);
        glm::quat turn_usual(1, 0, 0, 0);
        float fix_usual = 0.0f;
        int pushes_usual = 0;
        float depth_usual = 0.0f;
        // The finished frame's depth: what the push loop and clear_arm measure (the arm and hand
        // in the trunk; this hand and forearm in the other's, and the other hand in this forearm).
        auto frame_depth = [&]() {
          float d = std::max(arm_penetration(ctx.body, pb, plan.side, true, plan.exempt_trunk, check_hand).depth_m,
                             hand_penetration(ctx.body, pb, plan.side, !plan.exempt_trunk, check_hand).depth_m);
          if (check_hand) d = std::max(d, hand_penetration(ctx.body, pb, plans[order[0]].side, false, true).depth_m);
          return d;
        };
        const int hand_joint = rig.arms[plan.side].hand;
        for (int way = 0; way < 2; ++way) {
          if (way == 1) {
            pb_usual = pb;
            t_usual = t;
            solved_usual = solved[f][i];
            push_usual = push_offsets[f][i];
            turn_usual = turns[f][i];
            fix_usual = swivel_fixes[f][i];
            pushes_usual = out->pushes;
            depth_usual = frame_depth();
            pb = pb_start;
            t = t_start;
            out->pushes = pushes_start;
            t.start_at_previous_wrist = true;
            t.previous_wrist = final_wrist[f - 1][i];
          }
          glm::vec3 last_push_dir(0.0f);
          for (int attempt = 0; attempt < 6; ++attempt) {
            ArmPose ap = solve_arm(rig, plan.side, t);
            if (attempt == 0) {
              continued[f][i] = 0;
              // A contact part on the arm (DAY's elbow) continues like any other: it moves with
              // the forearm (arm_ik.cpp solve_at), not on a lever the wrist angles swing.
              if (f > 0) {
                const float step = wrist_change(ap, solved[f - 1][i]);
                const float turn_step = kWristTurnRadPerS * speed / fps;
                if (step > (continued[f - 1][i] ? turn_step : kWristFlipRadPerS * speed / fps)) {
                  // The pushes and the arm clearing below continue from there too (a fresh solve
                  // there would flip the wrist back: THANK-YOU).
                  t.previous = &solved[f - 1][i];
                  // Where the flip starts, the wrist holds its angles (a flip for one frame, THANK-YOU,
                  // is then no excursion at all); while it lasts, it turns through at turn_step.
                  t.max_wrist_step_rad = continued[f - 1][i] ? turn_step : 0.0f;
                  ap = solve_arm(rig, plan.side, t);
                  continued[f][i] = 1;
                }
              }
              solved[f][i] = ap;
            }
            apply_arm(rig, plan.side, ap, &pb);
            pose_fingers(rig, plan.side, h.angles, ap.hand, &pb);
            pb.finalize();
            if (f == 0 && attempt == 0 && is_touch(plan.spec.location.contact)) {
              float reach_m = ap.reach_error_m;
              // A wrist-led hand reports its contact part's miss (on the forearm: carried by it,
              // arm_ik.cpp solve_at), not the wrist's.
              if (wrist_led[i])
                reach_m = glm::length(arm_segments(rig, plan.side, ap).wrist + ap.lower * h.offset -
                                      (t.point - wrist_from_contact[i]));
              out->max_reach_error_m = std::max(out->max_reach_error_m, reach_m);
            }
            if (!ctx.options.avoid_collisions) break;
            Penetration pen = hand_penetration(ctx.body, pb, plan.side, !plan.exempt_trunk, check_hand);
            if (check_hand) {
              // The first hand in this forearm: solved before this arm was placed, it is checked
              // by nothing else, and mirrored hands at the centre of neutral space (the corpus's
              // hamsymmlr circles and strokes, wrists 8-12 cm apart) drove it 37 mm (median) into
              // this forearm. This arm gives way, opposite to the first hand's way out.
              Penetration into = hand_penetration(ctx.body, pb, plans[order[0]].side, false, true);
              if (into.depth_m > pen.depth_m) {
                pen.depth_m = into.depth_m;
                pen.push_dir = -into.push_dir;
              }
              // Pushed out of the hand only, the forearms then crossed instead (50 corpus signs
              // deeper, forearm in forearm): the forearms count in the same push.
              Penetration forearms = arm_penetration(ctx.body, pb, plan.side, false, false, true);
              if (forearms.depth_m > pen.depth_m) {
                pen.depth_m = forearms.depth_m;
                pen.push_dir = forearms.push_dir;
              }
            }
            if (pen.depth_m <= 0.002f) break;
            // Out along the escape direction and a little forward (away from the body), which the
            // arm can always follow.
            glm::vec3 dir = pen.push_dir;
            if (glm::dot(dir, last_push_dir) < 0.0f) {
              if (jam_rule) dir = safe_normalize(dir + last_push_dir + rig.forward, rig.forward);
              any_jam = true;
            }
            last_push_dir = dir;
            t.point += dir * (pen.depth_m + 0.006f) + (attempt >= 2 ? 0.01f : 0.0f) * rig.forward;
            if (attempt == 0) ++out->pushes;
          }
          push_offsets[f][i] = t.point - start_point;
          turns[f][i] = glm::quat(1, 0, 0, 0);
          swivel_fixes[f][i] = 0.0f;
          const float forced = forced_side[f][i];
          if (ctx.options.avoid_collisions)
            clear_arm(plan, check_hand, &t, h, &pb, &turns[f][i], &swivel_fixes[f][i],
                      forced != 0.0f                 ? forced
                      : swivel_ramped[f][i] > 0.05f  ? 1.0f
                      : swivel_ramped[f][i] < -0.05f ? -1.0f
                                                     : 0.0f,
                      forced != 0.0f, moving ? kMinSwivelGainM : 0.0f, ramp_only ? kRampOnlyClearM : 0.002f);
          if (way == 0 && !(choose_branch && continued[f][i] && ctx.options.avoid_collisions)) break;
          if (way == 1) {
            // The previous-wrist start is kept where the frame ends no deeper (within
            // kBranchDepthSlackM) and its wrist nearer the previous frame's finished wrist.
            const glm::vec3& before = final_wrist[f - 1][i];
            const bool keep = frame_depth() <= depth_usual + kBranchDepthSlackM &&
                              glm::length(pb.position(hand_joint) - before) <
                                  glm::length(pb_usual.position(hand_joint) - before);
            if (!keep) {
              pb = pb_usual;
              t = t_usual;
              solved[f][i] = solved_usual;
              push_offsets[f][i] = push_usual;
              turns[f][i] = turn_usual;
              swivel_fixes[f][i] = fix_usual;
              out->pushes = pushes_usual;
            }
          }
        }
        final_wrist[f][i] = pb.position(hand_joint);
      }
      pb.local_rotations(&out->rotations[static_cast<size_t>(f) * J]);
      out->exempt[f] = exempt;
      prev_pushes = out->pushes - pushes_before;
      if (f == 0) {
        // Measured distances of the contact parts to their places (acceptance: < 1 cm with touch,
        // 3-10 cm without).
        for (int i = 0; i < 2; ++i) {
          const HandPlan& plan = plans[i];
          if (!plan.active) continue;
          HandPlace place;
          int finger;
          contact_part(plan.spec, &place, &finger);
          PartPoint mine = hand_part(pb, plan.side, place, finger);
          PartPoint anchor;
          if (plan.on_other_hand) {
            anchor = solver.other_hand_place(pb, plan);
          } else if (plan.spec.location.kind == Location::Kind::Body) {
            if (!solver.body_anchor(body_anchor_name(plan.spec.location, plan.mirror_x), &anchor))
              continue;
          } else {
            continue;
          }
          out->contact_distance_m.push_back(glm::length(mine.point - anchor.point));
        }
      }
    }
  };
  // The state before the first solve: the clip is solved again from it with the jam rule.
  const ClipSolveState start = st;
  solve_frames(nullptr);
  // A turn decided frame by frame starts (and ends) at once: the hand would jump (a 60 degree
  // turn about a fingertip moves the wrist 17 cm in one frame). Ramp every turn in and out over
  // the kRamp frames around it (the largest of the neighbours' turns, scaled by the smoothstep
  // envelope of frame_corrections.h), fold the ramped turns into the frames' orientations, and
  // solve once more. The envelope was a linear tent over 6 frames: a turn needed by one frame
  // (THANK-YOU's hand at the end of its path) then peaked with a kink, the wrist went out and
  // came back at once (94 mm change of step on the reference rig; a smoothstep over 6 frames
  // 74 mm, over 8 frames 71 mm).
  //
  // The swivel fix has the same defect: it holds the elbow (and, through the wrist limits, the
  // wrist) out of the body for the frames that need it and lets go at once (GOOD: the wrist moved
  // 17 cm in one frame). The offsets are ramped the same way over kSwivelRamp frames and added
  // to the frames' swivels before the second solve; clear_arm then finds those frames clear
  // and leaves them alone.
  // The ramps are a motion in seconds, not in frames: kRampS is the 8 frames they spanned at
  // 30 fps (0.27 s: a 1.2 rad swivel fix moves the elbow < 4 cm per 1/30 s). Counted in frames,
  // the same correction came on twice as fast at 60 fps (THANK-YOU's elbow 4.3 m/s at 60 fps x
  // 1.25 on the reference humanoid) and the frame rate decided which frames a ramp reached. The
  // ramp does not shrink with the speed factor: a correction is not part of the written movement,
  // and at speed 1.25 it already has a fifth less of the sign's time to come on in (scaling it
  // with 1/speed, 20 frames at 60 fps x 0.8, reached over the sign's key pose into frames that
  // then needed their own fixes: TELL 5.6 m/s; measured over the lexicon from the key pose at 9
  // settings x 2 rigs, 2 rounds: 23 sign-settings over the human bounds with 8-frame ramps, 20
  // with fixed-time ones, 26 with them scaled by 1/speed).
  constexpr float kRampS = 8.0f / 30.0f;
  const int kRamp = std::max(1, static_cast<int>(std::lround(kRampS * fps)));
  const int kSwivelRamp = kRamp;
  // The second solve can still find a frame that needs a correction (the corrections of the two
  // hands interact: BOOK's palms together, the left elbow cleared for 3 frames, 11 cm change of
  // step), and that one again came on at once; so the residual corrections are ramped and solved
  // again, up to kRampRounds times (each round re-solves only the frames it changed).
  // The last round ramps what the one before still corrected and corrects again only what is
  // deep (kRampOnlyClearM): the corrections a final solve applied came on at once (OLD at 60 fps:
  // a -0.3 rad swivel fix at one frame against the ramped +1.5, the elbow 8 cm out and back,
  // 149 m/s^2; TELL at 25 fps: the sign's first frame without the fix its neighbour had, 15 cm).
  // Measured over the lexicon from the key pose, 141 signs x 9 settings x 2 rigs, wrists and
  // elbows over 3 m/s or 50 m/s^2: 20 sign-settings with the 2 rounds as before, 18 with this
  // third (a third round correcting at 2 mm like the others: also 18, but HOSPITAL's small
  // last fixes came on at once, 34 -> 14 m/s^2 with the net; a fourth round: 19).
  constexpr int kRampRounds = 3;
  // Last rounds more where the last one's corrections leap (ramp_rounds below), and what counts
  // as a jump between neighbouring frames' corrections.
  constexpr int kExtraRampRounds = 3;
  constexpr float kResidualJumpRad = 0.5f;
  constexpr float kResidualJumpM = 0.1f;
  // The ramp rounds, from the first solve's corrections (run once, or once per swivel side a run
  // of fixes is tried with: choose_run_sides_and_ramp below).
  // One ramp round: the corrections so far ramped into the frames and the frames they reach
  // solved again, `last` correcting again only what is deep. False where there was nothing to
  // ramp (the rounds end).
  auto ramp_round = [&](bool last) {
  bool any_turn = false, any_swivel = false;
  for (const auto& ft : turns)
    for (const auto& q : ft) any_turn = any_turn || rotation_angle(q) > 1e-3f;
  for (const auto& fs : swivel_fixes)
    for (float s : fs) any_swivel = any_swivel || std::abs(s) > 1e-4f;
  std::vector<char> redo(frames.size(), 0);
  if (any_swivel) {
    const int n = out->frame_count;
    for (int i = 0; i < 2; ++i) {
      std::vector<float> fix(n);
      for (int f = 0; f < n; ++f) fix[f] = swivel_fixes[f][i];
      const std::vector<float> ramped = ramp_scalars(fix, kSwivelRamp);
      for (int f = 0; f < n; ++f) {
        frames[f].hand[i].swivel += ramped[f];
        swivel_ramped[f][i] += ramped[f];
        if (ramped[f] != 0.0f) redo[f] = 1;
      }
    }
  }
  // The push out of the body or the other hand is decided per frame too: it switched on and off
  // at once (6-24 cm in one frame). Ramped like the swivel fix (smoothstep over kSwivelRamp
  // frames, the largest weighted neighbouring push) and folded into the frames' targets, so the
  // second solve finds those frames clear and the hand eases out and back in.
  bool any_push = false;
  for (const auto& fp : push_offsets)
    for (const auto& v : fp) any_push = any_push || glm::length(v) > 1e-4f;
  if (any_push) {
    const int n = out->frame_count;
    for (int i = 0; i < 2; ++i) {
      std::vector<glm::vec3> fix(n);
      for (int f = 0; f < n; ++f) fix[f] = push_offsets[f][i];
      const std::vector<glm::vec3> ramped = ramp_offsets(fix, kSwivelRamp);
      for (int f = 0; f < n; ++f) {
        frames[f].hand[i].target += ramped[f];
        if (glm::length(ramped[f]) > 0.0f) redo[f] = 1;
      }
    }
  }
  if (any_turn || any_swivel || any_push) {
    const int n = out->frame_count;
    for (int i = 0; any_turn && i < 2; ++i) {
      std::vector<glm::quat> fix(n);
      for (int f = 0; f < n; ++f) fix[f] = turns[f][i];
      const std::vector<glm::quat> ramped = ramp_turns(fix, kRamp);
      for (int f = 0; f < n; ++f) {
        frames[f].hand[i].delta = ramped[f] * frames[f].hand[i].delta;
        if (rotation_angle(ramped[f]) > 0.0f) redo[f] = 1;
      }
    }
    ramp_only = last;
    solve_frames(&redo);
    ramp_only = false;
  }
  if (!(any_turn || any_swivel || any_push)) return false;
  // Frames the round did not solve again had no correction; the ones it did now hold only the
  // residual corrections of this solve (the ramped ones are in their targets).
  for (int f = 0; f < out->frame_count; ++f)
    if (!redo[f])
      for (int i = 0; i < 2; ++i) {
        turns[f][i] = glm::quat(1, 0, 0, 0);
        swivel_fixes[f][i] = 0.0f;
        push_offsets[f][i] = glm::vec3(0.0f);
      }
  return true;
  };
  // The ramped clip's depth (the arms and hands, as the clip's check measures them) and its
  // largest wrist or elbow step in one frame.
  struct Score {
    float depth_m, step_m;
  };
  auto score = [&]() {
    Clip c;
    c.fps = fps;
    c.frame_count = out->frame_count;
    c.rotations = out->rotations;
    return Score{max_penetration(ctx, out->rotations.data(), c.frame_count, out->exempt.data(), nullptr, nullptr),
                 measure_frame_steps(rig, c).step_m};
  };
  // Whether the last round's own corrections (applied at once: nothing ramps them) can make a
  // leap: one that differs from a neighbouring frame's by more than kResidualJumpRad of swivel
  // or hand turn, or kResidualJumpM of push (at the avatar's arm, 0.5 rad swings the elbow some
  // 13 cm). Counted on the corrections, no posing: most clips have none.
  auto residual_jumps = [&]() {
    const int n = out->frame_count;
    for (int f = 0; f < n; ++f)
      for (int i = 0; i < 2; ++i)
        for (int g : {f - 1, f + 1}) {
          if (g < 0 || g >= n) continue;
          if (std::abs(swivel_fixes[f][i] - swivel_fixes[g][i]) > kResidualJumpRad ||
              rotation_angle(glm::conjugate(turns[g][i]) * turns[f][i]) > kResidualJumpRad ||
              glm::length(push_offsets[f][i] - push_offsets[g][i]) > kResidualJumpM)
            return true;
        }
    return false;
  };
  // The clip as it will be kept (the thorax turn applied, the elbow's path made continuous, as
  // sign_depth_and_step measures a finished sign): its deepest frame and largest arm step.
  auto carried_score = [&]() {
    std::vector<glm::quat> c = out->rotations;
    if (solver.turn.active())
      for (int f = 0; f < out->frame_count; ++f) apply_thorax_turn(rig, solver.turn, &c[static_cast<size_t>(f) * J]);
    Score sc{0.0f, 0.0f};
    continue_elbow_paths(rig, &ctx.body, fps, out->frame_count, &c, &sc.step_m);
    sc.depth_m = max_penetration(ctx, c.data(), out->frame_count, out->exempt.data(), nullptr, nullptr);
    return sc;
  };
  auto ramp_rounds = [&]() {
    for (int round = 0; round < kRampRounds; ++round)
      if (!ramp_round(round + 1 == kRampRounds)) return;
    // The last round's corrections come on at once (TO-BEAT9^: its left elbow raised over the
    // shoulder, a -1.0 rad swivel fix at one frame against none at the one before, the elbow
    // 257 mm in a frame). Where they jump and the clip leaps (an arm step over
    // kSwivelChoiceStepM), more last rounds ramp them in, each kept only where the clip (as it
    // will be kept: carried_score) is no deeper (kBranchSignSlackM) and steps less
    // (docs/SYNTHESIS.md leap). Only where the phrase asks (synthesize_sign_motion_ramped_again).
    for (int extra = 0; extra_ramp_rounds && extra < kExtraRampRounds && ctx.options.avoid_collisions; ++extra) {
      if (!residual_jumps()) return;
      const Score before = carried_score();
      if (!(before.step_m > kSwivelChoiceStepM)) return;
      ClipSolveState kept = st;
      if (!ramp_round(true)) return;
      const Score after = carried_score();
      if (!(after.depth_m <= before.depth_m + kBranchSignSlackM && after.step_m < before.step_m)) {
        st = std::move(kept);
        return;
      }
    }
  };
  // One side per run of swivel fixes. Where no swivel offset clears an arm, the first solve's
  // fix is the largest gain, and its side can flip between neighbouring frames (the corpus's
  // kelner, the right elbow at sign frames 7-14: -1.2, +1.2, -1.1, +1.2, -1.2, -1.2, -1.2, +1.2
  // rad); ramp_scalars follows the larger weighted neighbour, and over the rounds the ramped
  // fixes added up to -2.23 rad at one frame and +0.23 at the next (the elbow 551 mm in a frame).
  // Preferring the previous frame's side changed nothing, a ramp through zero lost the depth of
  // both sides (docs/SYNTHESIS.md step-census): the choice was still per frame. Here a run of
  // fixes (fixes within the ramp's reach of each other, 2 kSwivelRamp frames, are one run: their
  // ramps meet) whose sides mix is cleared again with one side forced on all its frames, each
  // side in turn, and ramped as before; a side is kept only if the ramped clip's arms are no
  // deeper than with the sides chosen per frame and its largest wrist or elbow step per frame is
  // smaller. Scored after the ramps: the depth a forced side leaves frame by frame foretold the
  // ramped clip's badly (a side at most 1 mm deeper at any frame before the ramps sank 6 corpus
  // signs by over 2 mm after them). Runs whose fixes share a side, most, cost nothing.
  auto choose_run_sides_and_ramp = [&]() {
    const int n = out->frame_count;
    struct SideRun {
      int hand, first, last;
    };
    std::vector<SideRun> runs;
    std::vector<char> in_run(frames.size(), 0);
    for (int i = 0; i < 2 && ctx.options.avoid_collisions; ++i) {
      for (int f = 0; f < n;) {
        if (std::abs(swivel_fixes[f][i]) <= 1e-4f) {
          ++f;
          continue;
        }
        SideRun r{i, f, f};
        bool plus = false, minus = false;
        for (int g = f; g < n && g - r.last <= 2 * kSwivelRamp; ++g) {
          const float x = swivel_fixes[g][i];
          if (std::abs(x) <= 1e-4f) continue;
          r.last = g;
          plus = plus || x > 0.0f;
          minus = minus || x < 0.0f;
        }
        if (plus && minus) {
          runs.push_back(r);
          for (int g = r.first; g <= r.last; ++g) in_run[g] = in_run[g] || std::abs(swivel_fixes[g][i]) > 1e-4f;
        }
        f = r.last + 1;
      }
    }
    if (runs.empty()) {
      ramp_rounds();
      return;
    }
    // The state after the first solve, each side's rounds start from it.
    const ClipSolveState first = st;
    ramp_rounds();
    Score best_score = score();
    const float free_depth = best_score.depth_m;
    ClipSolveState best = st;
    for (float side : {1.0f, -1.0f}) {
      st = first;
      for (const SideRun& r : runs)
        for (int g = r.first; g <= r.last; ++g) forced_side[g][r.hand] = side;
      solve_frames(&in_run);
      for (auto& fs : forced_side) fs = {0.0f, 0.0f};
      ramp_rounds();
      const Score sc = score();
      // No deeper (0.1 mm: rounding), a smaller step: a side that trades depth for steps is not
      // taken (kelner's, either side 7-12 mm deeper, both still 0.45 m steps).
      if (sc.depth_m <= free_depth + 1e-4f && sc.step_m < best_score.step_m) {
        best_score = sc;
        best = st;
      }
    }
    // The kept side's clip, arm poses and wrist flips (synthesize_sign_motion counts them to
    // decide the second solve).
    st = std::move(best);
  };
  choose_run_sides_and_ramp();
  // Where a push went against the one before it, the whole clip is solved again with the jam
  // rule (one way out for the caught hand: the two pushes' sum and forward) and kept only where
  // the ramped clip is no deeper (0.1 mm: rounding) and its largest wrist or elbow step smaller.
  // Chosen per frame (the shallower end of the two push loops, or the shorter push), 37 corpus
  // signs sank by over 2 mm: a frame's depth before the ramps does not foretell the ramped
  // clip's (as ramp-side's sides). Measured (docs/SYNTHESIS.md, push-side): cztery tygodnie temu
  // 45.1 mm deep and a 489 mm step -> 11.3 and 390; HamNoSys corpus over 5 mm 185 -> 133.
  // The choice sees the sign's own frames only: where the jam rule's clip is kept, the usual one
  // goes back too (`usual_alternative`), and the phrase compares the two with the transitions it
  // builds next to the sign (synthesize.cpp), which start from a changed first frame.
  bool alternative = false;
  ClipSolveState usual_state;
  if (any_jam && ctx.options.avoid_collisions) {
    const Score usual = score();
    usual_state = std::move(st);
    st = start;
    jam_rule = true;
    solve_frames(nullptr);
    choose_run_sides_and_ramp();
    jam_rule = false;
    const Score jam = score();
    if (jam.depth_m <= usual.depth_m + 1e-4f && jam.step_m < usual.step_m)
      alternative = usual_alternative != nullptr;
    else
      st = std::move(usual_state);
  }
  if (continued_frames) {
    // With both clips handed back, both clips' (the caller's second solve is for either).
    *continued_frames = 0;
    for (const auto& c : continued) *continued_frames += c[0] + c[1];
    if (alternative)
      for (const auto& c : usual_state.continued) *continued_frames += c[0] + c[1];
  }
  auto finish = [&](ClipSolveState* s, SignMotion* m) {
    s->out.orientation_error_rad.assign(s->frames.size(), 0.0f);
    for (size_t f = 0; f < s->frames.size(); ++f)
      for (int i = 0; i < 2; ++i)
        if (plans[i].active)
          s->out.orientation_error_rad[f] =
              std::max(s->out.orientation_error_rad[f], s->solved[f][i].orientation_error_rad);
    // Solved in the thorax frame: the clip's frames carry the turn in the trunk chain.
    if (solver.turn.active())
      for (int f = 0; f < s->out.frame_count; ++f)
        apply_thorax_turn(rig, solver.turn, &s->out.rotations[static_cast<size_t>(f) * J]);
    *m = std::move(s->out);
  };
  finish(&st, result);
  if (usual_alternative) {
    if (alternative)
      finish(&usual_state, usual_alternative);
    else
      *usual_alternative = SignMotion{};
  }
  return true;
}

// The peak speed (m/s) and acceleration (m/s^2) of each step's wrists, elbows and fingertips in
// the solved clip, over kStepHandAccelWindowS: the first and second differences of the posed
// points, the window's frames before the step and after it (the clip's last frame held) included.
struct StepPeaks {
  float speed = 0.0f, accel = 0.0f;
};
std::vector<StepPeaks> step_peaks(const Rig& rig, const SignMotion& m,
                                  const std::vector<StepSpan>& spans, float fps) {
  const int window = std::max(1, static_cast<int>(std::lround(kStepHandAccelWindowS * fps)));
  const float window_s = static_cast<float>(window) / fps;
  const int J = rig.joint_count, last = m.frame_count - 1;
  // Each frame's points, posed once (steps' windows overlap).
  constexpr int kPoints = 2 * 7;  // per side: wrist, elbow, five fingertips
  std::vector<glm::vec3> pos(static_cast<size_t>(m.frame_count) * kPoints);
  PoseBuilder pb(rig);
  for (int f = 0; f < m.frame_count; ++f) {
    pb.set_from_local(&m.rotations[static_cast<size_t>(f) * J]);
    glm::vec3* p = &pos[static_cast<size_t>(f) * kPoints];
    for (Side s : {kLeft, kRight}) {
      *p++ = pb.position(rig.arms[s].hand);
      *p++ = pb.position(rig.arms[s].lower);
      for (int finger = 0; finger < 5; ++finger) *p++ = pb.tip(s, finger);
    }
  }
  auto at = [&](int f, int k) {
    return pos[static_cast<size_t>(std::min(std::max(f, 0), last)) * kPoints + k];
  };
  std::vector<StepPeaks> out;
  for (const StepSpan& span : spans) {
    float step = 0.0f, change = 0.0f;
    for (int f = static_cast<int>(span.begin) - window; f <= static_cast<int>(span.end); ++f)
      for (int k = 0; k < kPoints; ++k) {
        step = std::max(step, glm::length(at(f + window, k) - at(f, k)));
        change =
            std::max(change, glm::length(at(f + window, k) - 2.0f * at(f, k) + at(f - window, k)));
      }
    out.push_back({step / window_s, change / (window_s * window_s)});
  }
  return out;
}

// A sign's clip's deepest frame (returned) and largest arm step (`step`), measured as the clip has
// them by default: after the elbow's path is made continuous (synthesize.cpp, elbow_path.h),
// which moves the elbows of a sign whose wrist changes side. Measured without it, 4 signs newly
// stepped over 100 mm in a frame (wynajmować 83 -> 173 mm). Also where the options switch the
// elbow's path off: the solve is then the same one, with and without it
// (CorpusSynthesis.CarryingAnElbowRound... compares the two). ctx: the phrase's (the measures
// read positions, the same whichever swivel zero solved the clip).
float sign_depth_and_step(const SynthContext& ctx, const SignMotion& m, float* step) {
  Clip c;
  c.fps = ctx.options.fps;
  c.frame_count = m.frame_count;
  c.rotations = m.rotations;
  continue_elbow_paths(ctx.rig, &ctx.body, c.fps, c.frame_count, &c.rotations);
  *step = measure_frame_steps(ctx.rig, c).step_m;
  std::string what;
  return max_penetration(ctx, c.rotations.data(), c.frame_count, m.exempt.data(), &what, nullptr);
}

// Whether a sign's second solve is kept over its first: its deepest frame no deeper
// (kBranchSignSlackM) and its largest arm step smaller (frame-branch, swivel-choice).
bool sign_second_is_better(const SynthContext& ctx, const SignMotion& first, const SignMotion& second) {
  float step = 0.0f, second_step = 0.0f;
  const float depth = sign_depth_and_step(ctx, first, &step);
  const float second_depth = sign_depth_and_step(ctx, second, &second_step);
  return second_depth <= depth + kBranchSignSlackM && second_step < step;
}

bool synthesize_sign_motion_in_zero(const SynthContext& ctx, const notation::SignSpec& sign,
                                    const std::string& where, SignMotion* out,
                                    std::vector<SynthesisError>* errors, SignMotion* usual_alternative,
                                    bool extra_ramp_rounds = false);
void choose_zero(const SynthContext& ctx, const SynthContext& fixed, const notation::SignSpec& sign,
                 const std::string& where, SignMotion* out, SignMotion* usual_alternative,
                 OtherZeroSolve* other_zero, bool* kept_fixed);

}  // namespace

// The sign in the usual swivel zero, and where its clip still leaps (an arm step over
// kSwivelChoiceStepM, measured after the elbow's path) once more in the zero of fixed handedness
// (Rig::fixed_handed_swivel_zero, on a copy of the context), kept by the branch choice's rule:
// no deeper (kBranchSignSlackM) and a smaller largest arm step. The usual zero turns the elbow
// half round where the wrist crosses the shoulder joint's coronal plane (elbow-leap); the fixed
// one does not, but as every sign's zero it sank hands at the shoulders (swivel-pref: 54 signs
// deeper by > 2 mm), so each sign keeps the zero that serves it. The clips without the jam rule
// (`usual_alternative`) are chosen between by the same rule on their own, as in the branch
// choice. The alternative's errors repeat the first solve's (the same sign and key pose).
// The threshold (sign_motion.h kSwivelChoiceStepM): main's HamNoSys corpus had 52 signs over it
// before the choice, among them the usual zero's half turns at the shoulder joint's coronal plane
// (szkoła 464 mm, TO-SLEEP2^ 553 mm: elbow-leap); the lexicon is never solved twice.
static bool synthesize_sign_motion_in_chosen_zero(const SynthContext& ctx, const notation::SignSpec& sign,
                                                  const std::string& where, SignMotion* out,
                                                  std::vector<SynthesisError>* errors,
                                                  SignMotion* usual_alternative, OtherZeroSolve* other_zero) {
  if (other_zero) {
    *other_zero = OtherZeroSolve{};
    other_zero->protraction_zone = ctx.rig.protraction_zone;
  }
  if (!synthesize_sign_motion_in_zero(ctx, sign, where, out, errors, usual_alternative)) return false;
  if (ctx.rig.fixed_handed_swivel_zero || !ctx.options.avoid_collisions || out->frame_count == 0) return true;
  float step = 0.0f;
  out->sign_depth_m = sign_depth_and_step(ctx, *out, &step);
  if (!(step > kSwivelChoiceStepM)) return true;
  SynthContext fixed = ctx;
  fixed.rig.fixed_handed_swivel_zero = true;
  bool kept_fixed = false;
  choose_zero(ctx, fixed, sign, where, out, usual_alternative, other_zero, &kept_fixed);
  if (other_zero) other_zero->kept_fixed = kept_fixed;
  if (kept_fixed) {
    float fixed_step = 0.0f;
    out->sign_depth_m = sign_depth_and_step(ctx, *out, &fixed_step);
  }
  return true;
}

// A symmetric pair written at one place is laid apart to both sides (lay_mirror_pair_apart); the
// laid-apart clip is kept only where mirror_apart_is_kept says so against the clip with the
// dominant hand alone moved out of the way (as before that rule): the movements, frame pushes and
// ramps that follow were tuned on the old key pose, and some signs' movements fare better from it
// (docs/SYNTHESIS.md, sign-hands). The phrase judges the two with the transitions next to the
// sign (`mirror_judged_by_caller`, synthesize.cpp choose_mirror_apart); without it they are judged
// here, on the sign's own frames.
bool synthesize_sign_motion(const SynthContext& ctx, const notation::SignSpec& sign,
                            const std::string& where, SignMotion* out,
                            std::vector<SynthesisError>* errors, SignMotion* usual_alternative,
                            OtherZeroSolve* other_zero, bool mirror_judged_by_caller) {
  if (!synthesize_sign_motion_in_chosen_zero(ctx, sign, where, out, errors, usual_alternative, other_zero))
    return false;
  if (mirror_judged_by_caller || !out->mirror_laid_apart || !ctx.mirror_pairs_apart ||
      !ctx.options.avoid_collisions)
    return true;
  SignMotion other, other_alternative;
  OtherZeroSolve other_zero_of_escape;
  std::vector<SynthesisError> repeated;
  if (!synthesize_sign_motion_escaping(ctx, sign, where, &other, &repeated,
                                       usual_alternative ? &other_alternative : nullptr,
                                       other_zero ? &other_zero_of_escape : nullptr))
    return true;
  float step = 0.0f, other_step = 0.0f;
  const float depth = sign_depth_and_step(ctx, *out, &step);
  const float other_depth = sign_depth_and_step(ctx, other, &other_step);
  if (!mirror_apart_is_kept(*out, depth, step, other_depth, other_step)) {
    *out = std::move(other);
    if (usual_alternative) *usual_alternative = std::move(other_alternative);
    if (other_zero) *other_zero = std::move(other_zero_of_escape);
  }
  return true;
}

bool synthesize_sign_motion_escaping(const SynthContext& ctx, const notation::SignSpec& sign,
                                     const std::string& where, SignMotion* out,
                                     std::vector<SynthesisError>* errors, SignMotion* usual_alternative,
                                     OtherZeroSolve* other_zero) {
  SynthContext escape_ctx = ctx;
  escape_ctx.mirror_pairs_apart = false;
  return synthesize_sign_motion_in_chosen_zero(escape_ctx, sign, where, out, errors, usual_alternative,
                                               other_zero);
}

bool synthesize_sign_motion_ramped_again(const SynthContext& ctx, const notation::SignSpec& sign,
                                         const std::string& where, SignMotion* out,
                                         std::vector<SynthesisError>* errors, SignMotion* usual_alternative) {
  return synthesize_sign_motion_in_zero(ctx, sign, where, out, errors, usual_alternative, true);
}

// The solves above measure the kept clip's depth (sign_depth_and_step) and leave it in
// sign_depth_m; a clip they did not measure (the jam rule's usual alternative, the other zero's
// solve, the phrase's solves again) is measured here.
float sign_motion_depth(const SynthContext& ctx, const SignMotion& m) {
  if (m.sign_depth_m >= 0.0f) return m.sign_depth_m;
  float step = 0.0f;
  return m.frame_count > 0 ? sign_depth_and_step(ctx, m, &step) : 0.0f;
}

namespace {

// The zero choice of synthesize_sign_motion: the sign solved in the fixed zero and kept by the
// branch choice's rule (`kept_fixed`), the zero not kept into `other_zero`.
void choose_zero(const SynthContext& ctx, const SynthContext& fixed, const notation::SignSpec& sign,
                 const std::string& where, SignMotion* out, SignMotion* usual_alternative,
                 OtherZeroSolve* other_zero, bool* kept_fixed) {
  SignMotion other, other_alternative;
  std::vector<SynthesisError> repeated;
  if (!synthesize_sign_motion_in_zero(fixed, sign, where, &other, &repeated,
                                      usual_alternative ? &other_alternative : nullptr))
    return;
  // Each zero's own clip without the jam rule, before the two are chosen between below.
  SignMotion first_alternative = usual_alternative ? *usual_alternative : SignMotion{};
  if (usual_alternative && (usual_alternative->frame_count > 0 || other_alternative.frame_count > 0)) {
    const SignMotion& first = usual_alternative->frame_count > 0 ? *usual_alternative : *out;
    const SignMotion& second = other_alternative.frame_count > 0 ? other_alternative : other;
    SignMotion kept = sign_second_is_better(ctx, first, second) ? second : first;
    *usual_alternative = std::move(kept);
  }
  if (sign_second_is_better(ctx, *out, other)) {
    if (other_zero) {
      other_zero->motion = std::move(*out);
      other_zero->usual_alternative = std::move(first_alternative);
    }
    *out = std::move(other);
    *kept_fixed = true;
  } else if (other_zero) {
    other_zero->motion = std::move(other);
    other_zero->usual_alternative = std::move(other_alternative);
  }
  if (other_zero) other_zero->solved = true;
}

bool synthesize_sign_motion_in_zero(const SynthContext& ctx, const notation::SignSpec& sign,
                                    const std::string& where, SignMotion* out,
                                    std::vector<SynthesisError>* errors, SignMotion* usual_alternative,
                                    bool extra_ramp_rounds) {
  // The sign's arm solves asked again with the same target are answered from memory (arm_ik.h;
  // the clip is the same to the bit), also in the second solve at a stretched timing below.
  ArmSolveMemo arm_solves;
  std::vector<StepSpan> spans;
  int continued_frames = 0;
  if (!synthesize_sign_motion_timed(ctx, sign, where, {}, false, out, errors, &spans, &continued_frames,
                                    usual_alternative, extra_ramp_rounds))
    return false;
  // A sign with frames that continue a wrist flip is solved once more with each such frame's
  // branch chosen on the finished frame (solve_frames: the usual start or the previous wrist's).
  // A choice no deeper at its own frame still sank neighbouring frames (the ramps carry the kept
  // branch's pushes and swivel fixes into them: HOUSE1A^ 1.0 -> 14.4 mm at frames that continue
  // nothing) and alternated between frames, so the whole sign decides: the second solve is kept
  // where the sign's deepest frame is no deeper (kBranchSignSlackM) and its largest arm step
  // (clip_steps.h) smaller. The cost: a second solve of the signs with such frames (3 of the
  // lexicon's 141; 450 of the HamNoSys corpus's 4,481).
  bool choose_branch = false;
  if (continued_frames > 0 && ctx.options.avoid_collisions) {
    SignMotion chosen;
    std::vector<SynthesisError> repeated;
    std::vector<StepSpan> chosen_spans;
    SignMotion chosen_alternative;
    if (synthesize_sign_motion_timed(ctx, sign, where, {}, true, &chosen, &repeated, &chosen_spans, nullptr,
                                     usual_alternative ? &chosen_alternative : nullptr, extra_ramp_rounds) &&
        chosen_spans.size() == spans.size()) {
      // Measured as the clip has them by default, after the elbow's path (sign_depth_and_step).
      auto second_is_better = [&](const SignMotion& first, const SignMotion& second) {
        return sign_second_is_better(ctx, first, second);
      };
      // The clips without the jam rule (each solve's alternative, or its clip where it has none)
      // are chosen between by the same rule, on their own: the caller weighs the jam rule's
      // result against the clip the sign would have had without it.
      if (usual_alternative && (usual_alternative->frame_count > 0 || chosen_alternative.frame_count > 0)) {
        const SignMotion& first = usual_alternative->frame_count > 0 ? *usual_alternative : *out;
        const SignMotion& second = chosen_alternative.frame_count > 0 ? chosen_alternative : chosen;
        SignMotion kept = second_is_better(first, second) ? second : first;
        *usual_alternative = std::move(kept);
      }
      if (second_is_better(*out, chosen)) {
        *out = std::move(chosen);
        spans = std::move(chosen_spans);
        choose_branch = true;
      }
    }
  }
  // A faster signer still has a human hand: the speed factor divides a step's time, so along
  // the same path its speeds grow with the factor and its accelerations with its square. Above
  // speed 1, a step whose wrist, elbow or a fingertip moves faster than kStepHandPeakSpeedMPerS
  // or accelerates beyond kStepHandPeakAccelMPerS2 in the solved clip gets more states (by the
  // speed's excess or the square root of the acceleration's: accelerations go as 1/duration^2),
  // never more than it has at speed 1, and the sign is synthesised again with them. A step within
  // bounds keeps its timing, and speeds up to 1 are untouched (no second solve).
  if (!(ctx.options.speed > 1.0f) || spans.empty()) return true;
  // The worst of a clip's steps' excesses over the bounds (1: at a bound).
  auto excess_of = [](const StepPeaks& p) {
    return std::max(std::sqrt(p.accel / kStepHandPeakAccelMPerS2),
                    p.speed / kStepHandPeakSpeedMPerS);
  };
  auto worst_excess = [&](const std::vector<StepPeaks>& peaks) {
    float worst = 0.0f;
    for (const StepPeaks& p : peaks) worst = std::max(worst, excess_of(p));
    return worst;
  };
  std::vector<StepPeaks> peaks = step_peaks(ctx.rig, *out, spans, ctx.options.fps);
  std::vector<int> states(spans.size(), 0);
  for (int round = 0; round < kStepAccelRounds; ++round) {
    bool stretched = false;
    for (size_t i = 0; i < spans.size(); ++i) {
      const float excess = excess_of(peaks[i]);
      if (excess <= 1.0f || spans[i].states >= spans[i].states_at_speed_1) continue;
      states[i] = std::min(spans[i].states_at_speed_1,
                           static_cast<int>(std::ceil(spans[i].states * excess)));
      stretched = true;
    }
    if (!stretched) return true;
    // The same sign, the same key pose: the second solve's errors repeat the first's.
    SignMotion slower;
    std::vector<SynthesisError> repeated;
    std::vector<StepSpan> again;
    SignMotion slower_alternative;
    if (!synthesize_sign_motion_timed(ctx, sign, where, states, choose_branch, &slower, &repeated, &again, nullptr,
                                      usual_alternative ? &slower_alternative : nullptr, extra_ramp_rounds) ||
        again.size() != spans.size())
      return true;
    // Not exactly 1/duration^2 (above): a stretch that measures no better is not taken.
    std::vector<StepPeaks> slower_peaks = step_peaks(ctx.rig, slower, again, ctx.options.fps);
    if (worst_excess(slower_peaks) >= worst_excess(peaks)) return true;
    *out = std::move(slower);
    if (usual_alternative) *usual_alternative = std::move(slower_alternative);
    spans = std::move(again);
    peaks = std::move(slower_peaks);
  }
  return true;
}

}  // namespace

}  // namespace sw::synthesis

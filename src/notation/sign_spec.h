// SignSpec: the formal model of a sign (seed 004, §1 of docs SOURCES.md), shared by every parser
// (formula, HamNoSys, H-SiGML, G-SiGML), every printer, the synthesis and the server.
//
// A sign = per hand (hand configuration F, orientation D, localisation L) + movements + repetition
// + symmetry + non-manual tracks. The names follow the seed where it has one (F_i^k(t), D_i,
// L_i(mu)) and HamNoSys where the seed is silent (26 directions, 8 palm orientations, movement kinds).
//
// Signer space (ARCHITECTURE.md conventions): the avatar faces +Z, +Y is up, so +X is the SIGNER'S
// LEFT. A Direction {x, y, z} with components in {-1, 0, 1}: x=+1 left (HamNoSys "l"), x=-1 right
// ("r"), y=+1 up ("u"), y=-1 down ("d"), z=+1 away from the body ("o"), z=-1 towards it ("i").
//
// This header has data only; the parsers live beside it, the meaning (angles, anchors, paths) in
// synthesis/.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sw::notation {

// ---------------------------------------------------------------------------------------------
// Hand configuration, seed 004 eq. (4): the hand is a superposition of per-finger states
// F_i^k(t), k = 1 thumb ... 5 little finger; a state with t interpolates begin -> end.
enum class Finger : std::uint8_t { Thumb = 0, Index = 1, Middle = 2, Ring = 3, Little = 4 };
constexpr int kFingerCount = 5;

// Configuration ids i of F_i^k. 0..3 are the seed's own inventory; the rest extend it so that the
// twelve HamNoSys base handshapes with every thumb and bending modifier can be written.
// Thumb (k = 1):
enum ThumbConfig : int {
  kThumbPressedToStraight = 0,  // seed F_0^1(t): pressed (t=0) -> straight (t=1)
  kThumbPadOnIndex = 1,         // seed F_1^1: thumb pad joined with the index finger
  kThumbAgainstPalm = 2,        // seed F_2^1: thumb pressed against the palm
  kThumbOut = 3,                // HamNoSys thumb out (abducted, straight)
  kThumbAcross = 4,             // HamNoSys thumb across the palm / fingers
  kThumbOpposed = 5,            // HamNoSys thumb open/opposed (round, as in a C)
  kThumbOnMiddle = 6,           // tip touching the middle finger (pinch / between)
  kThumbOnRing = 7,
  kThumbOnLittle = 8,
  kThumbAlongside = 9,          // straight, adducted alongside the index (flat hand)
};
// Fingers (k = 2..5):
enum FingerConfigId : int {
  kFingerPressedToStraight = 0,  // seed F_0^k(t): pressed into the palm (t=0) -> straight (t=1)
  kFingerHorizontal = 1,         // seed F_1^k: bent 90 degrees at the knuckle (HamNoSys bent)
  kFingerSpread = 2,             // seed F_2^k: straight and spread from its neighbour
  kFingerCrossed = 3,            // seed F_3^3: middle lies on the straight index
  kFingerRound = 4,              // HamNoSys round: every joint partly bent (C, O)
  kFingerHooked = 5,             // HamNoSys hooked: knuckle straight, PIP and DIP bent (claw)
  kFingerDoubleBent = 6,         // HamNoSys double-bent: knuckle and PIP bent
  kFingerDoubleHooked = 7,       // HamNoSys double-hooked: all three fully bent at the tip
};

struct FingerConfig {
  int id = 0;            // i in F_i^k (ThumbConfig for the thumb, FingerConfigId for the others)
  bool has_t = false;    // seed: "a configuration without t is a fixed state"
  float t = 1.0f;        // interpolation begin -> end, [0, 1]
  float spread = 0.0f;   // extra abduction from the neighbour: 0 adjacent, 1 fully spread
};

struct HandShape {
  std::array<FingerConfig, kFingerCount> fingers{};  // index with static_cast<int>(Finger)
  // HamNoSys base shape and modifiers it came from, for printing back (empty for formula input).
  std::string hamnosys_base;
};

// ---------------------------------------------------------------------------------------------
// Orientation: the seed's D1..D5 and HamNoSys's extended finger direction + palm orientation.
struct Direction {
  std::int8_t x = 0, y = 0, z = 0;  // each in {-1, 0, 1}; see the signer-space note at the top
  bool is_zero() const { return x == 0 && y == 0 && z == 0; }
  bool operator==(const Direction& o) const { return x == o.x && y == o.y && z == o.z; }
  bool operator!=(const Direction& o) const { return !(*this == o); }
};

// Seed 004 (5): D1 up, D2 standard, D3 down, D4 towards oneself, D5 to the side (palm normal).
enum class SeedPalm : std::uint8_t { None = 0, D1 = 1, D2 = 2, D3 = 3, D4 = 4, D5 = 5 };

struct Orientation {
  Direction extended_finger{0, 1, 1};  // where the fingers point if they were straight
  Direction palm{0, 0, -1};            // where the palm faces (HamNoSys: relative to the finger
                                       // direction; synthesis projects it onto the plane ⟂ fingers)
  SeedPalm seed_palm = SeedPalm::None; // set when written in the seed formula (D_i)
};

// ---------------------------------------------------------------------------------------------
// Localisation, seed 004 (6): L_i(mu) = {K_i, mu}, places at the crossing of a level and a side.
enum class BodyLevel : std::uint8_t {
  AboveHead, HeadTop, Head, Forehead, Eyebrows, Eyes, Nose, Ears, Cheeks, Mouth, Lips, Teeth,
  Tongue, Chin, UnderChin, Neck, Shoulders, ShoulderTop, Chest, Stomach, Belly, Waist, BelowWaist,
  NeutralSpace,
};
enum class Side : std::uint8_t { RightBeside, Right, Centre, Left, LeftBeside };  // signer's sides
enum class Contact : std::uint8_t { None, Close, Touch, ArmExtended, Brush, Grasp, Between,
                                    // HamNoSys haminterlock, hamcross, hambehind:
                                    Interlock, Cross, Behind };

// Places on the other hand and arm (two-handed contact; HamNoSys location finger / arm-hand).
enum class HandPlace : std::uint8_t {
  Palm, BackOfHand, ThumbSide, LittleSide, Fingertip, FingerPad, FingerNail, FingerBase,
  FingerMiddleJoint, FingerSide, Wrist, WristBack, Forearm, ForearmBack, Elbow, UpperArm,
  ThumbBall, ElbowInside,  // HamNoSys hamthumbball, hamelbowinside
};

struct Location {
  enum class Kind : std::uint8_t { Body, NeutralSpace, OtherHand } kind = Kind::NeutralSpace;
  BodyLevel level = BodyLevel::NeutralSpace;
  Side side = Side::Centre;
  Contact contact = Contact::None;
  // For Kind::OtherHand: where on the other hand/arm, and which finger (Finger) when relevant.
  HandPlace hand_place = HandPlace::Palm;
  std::int8_t finger = -1;
  // Which part of THIS hand makes the contact (fingertip of the index, palm, ...).
  std::optional<HandPlace> contact_part;
  std::int8_t contact_finger = -1;
  int seed_id = 0;  // i of L_i when written in the seed formula, 0 otherwise
};

// ---------------------------------------------------------------------------------------------
// Movement (HamNoSys movement groups; seed 004 "trajectory and character of movement").
enum class MovementKind : std::uint8_t {
  Straight, Arc, Circle, Ellipse, Wavy, Zigzag, Spiral,
  FingerPlay, WristNod, WristSwing, WristTwist, WristCircle,
  Replace,  // change of handshape and/or orientation in place (HamNoSys hamreplace)
  Target,   // move to a location (HamNoSys location after a movement)
};
enum class Size : std::uint8_t { Normal, Small, Large };
enum class Manner : std::uint8_t { Normal, Fast, Slow, Tense, Halt, Rest };

struct Movement {
  MovementKind kind = MovementKind::Straight;
  Direction direction{};        // straight / arc / zigzag / wavy: the main direction
  Direction arc_bulge{};        // arcs: the side the path bulges to (HamNoSys arc u/d/l/r)
  Direction circle_axis{};      // circles, ellipses, spirals: axis (right-hand rule gives sense)
  Direction ellipse_axis{};     // ellipses: the long axis in the circle's plane (HamNoSys
                                // hamellipseh {1,0,0}, v {0,1,0}, ur {-1,1,0}, ul {1,1,0})
  bool clockwise = false;       // as seen by the signer looking along circle_axis
  Size size = Size::Normal;
  Manner manner = Manner::Normal;
  // A change of hand during the movement (hamreplace / tgt_motion handconfig).
  std::optional<HandShape> to_shape;
  std::optional<Orientation> to_orientation;
  std::optional<Location> to_location;
  bool alternating = false;     // the two hands move out of phase
};

// A movement sequence item: the movements in `parallel` happen at the same time (HamNoSys
// parbegin/parend); items of SignSpec::movements happen one after the other (seqbegin/seqend).
struct MovementStep {
  std::vector<Movement> dominant;      // all at once for the dominant hand
  std::vector<Movement> nondominant;   // all at once for the other hand (empty: follows symmetry)
  // The other hand holds its place during this step although the sign has a symmetry (HamNoSys
  // `hamparbegin MOTION hamplus hamnomotion hamparend`, G-SiGML `<split_motion>` with
  // `<nomotion/>` for the other hand): its empty list then does not follow the symmetry. Only
  // with `nondominant` empty (the readers set it so). The dominant hand needs no such mark: an
  // empty `dominant` is already a hand that stays (`hamparbegin hamnomotion hamplus MOTION`).
  bool nondominant_stays = false;
};

enum class RepeatKind : std::uint8_t { None, FromStart, Continuing, Reverse, FromStartSeveral,
                                       ContinuingSeveral };
struct Repetition {
  RepeatKind kind = RepeatKind::None;
  int count = 1;  // extra repetitions (several = 2 unless stated)
};

// Two hands (HamNoSys two-handed operators).
enum class Symmetry : std::uint8_t { None, MirrorLR, MirrorLRUD, MirrorLRIO, Parallel,
                                     ParallelUD, ParallelIO };

struct HandSpec {
  HandShape shape;
  Orientation orientation;
  Location location;
};

// Non-manual tracks (seed 000/001/002: mouthing, expression, gaze, head).
struct NonManual {
  std::string mouthing;      // spoken-word picture (SAMPA / plain text as in SiGML mouth_picture)
  std::string mouth_gesture; // HamNoSys mouth gesture code, e.g. "C01"
  std::string eyebrows;      // "up", "down", "" (neutral)
  std::string expression;    // emotion name: happy, sad, angry, surprised, fear, disgust, ...
  float expression_intensity = 0.0f;  // 0..1
  std::string head;          // "nod", "shake", "tilt_l", ...
  std::string gaze;          // "addressee", "hands", "up", ...
};

enum class NotationFormat : std::uint8_t { Formula, HamNoSys, HSiGML, GSiGML };

struct SignSpec {
  std::string gloss;
  HandSpec dominant;
  std::optional<HandSpec> nondominant;  // empty: one-handed sign
  Symmetry symmetry = Symmetry::None;
  bool nondominant_is_place = false;    // the other hand is the location, it does not move
  // A one-handed sign made with the non-dominant hand (HamNoSys hamnondominant before the
  // configuration, G-SiGML <sign_manual nondominant="true">): `dominant` describes that hand, in
  // the same absolute directions and places as a written non-dominant hand; the dominant hand rests.
  bool one_hand_is_nondominant = false;
  std::vector<MovementStep> movements;  // empty: a static sign (a hold, as in most letters)
  Repetition repetition;
  NonManual nonmanual;
};

}  // namespace sw::notation

// HamNoSys location/contact symbols <-> SignSpec enums (see hamnosys_places.h).
#include "notation/hamnosys_places.h"

#include "notation/hamnosys_symbols.h"

namespace sw::notation {

BodyLevel level_of(char32_t c) {
  switch (c) {
    case hamhead: return BodyLevel::Head;
    case hamheadtop: return BodyLevel::HeadTop;
    case hamforehead: return BodyLevel::Forehead;
    case hameyebrows: return BodyLevel::Eyebrows;
    case hameyes: return BodyLevel::Eyes;
    case hamnose: case hamnostrils: return BodyLevel::Nose;
    case hamear: case hamearlobe: return BodyLevel::Ears;
    case hamcheek: return BodyLevel::Cheeks;
    case hamlips: return BodyLevel::Lips;
    case hamtongue: return BodyLevel::Tongue;
    case hamteeth: return BodyLevel::Teeth;
    case hamchin: return BodyLevel::Chin;
    case hamunderchin: return BodyLevel::UnderChin;
    case hamneck: return BodyLevel::Neck;
    case hamshouldertop: return BodyLevel::ShoulderTop;
    case hamshoulders: return BodyLevel::Shoulders;
    case hamchest: return BodyLevel::Chest;
    case hamstomach: return BodyLevel::Stomach;
    default: return BodyLevel::Belly;  // hambelowstomach
  }
}

HandPlace place_of(char32_t c) {
  switch (c) {
    case hamupperarm: return HandPlace::UpperArm;
    case hamelbow: return HandPlace::Elbow;
    case hamelbowinside: return HandPlace::ElbowInside;
    case hamlowerarm: return HandPlace::Forearm;
    case hamwristback: case hamwristtoback: return HandPlace::WristBack;
    case hamwristpulse: case hamwristtopulse: return HandPlace::Wrist;
    case hamthumbball: return HandPlace::ThumbBall;
    case hampalm: return HandPlace::Palm;
    case hamhandback: return HandPlace::BackOfHand;
    case hamthumbside: case hamwristtothumb: return HandPlace::ThumbSide;
    case hampinkyside: case hamwristtopinky: return HandPlace::LittleSide;
    case hamfingertip: return HandPlace::Fingertip;
    case hamfingernail: return HandPlace::FingerNail;
    case hamfingerpad: return HandPlace::FingerPad;
    case hamfingermidjoint: return HandPlace::FingerMiddleJoint;
    case hamfingerbase: return HandPlace::FingerBase;
    default: return HandPlace::FingerSide;  // hamfingerside
  }
}

Contact contact_of(char32_t c) {
  switch (c) {
    case hamclose: return Contact::Close;
    case hamtouch: return Contact::Touch;
    case haminterlock: return Contact::Interlock;
    case hamcross: return Contact::Cross;
    case hamarmextended: return Contact::ArmExtended;
    case hambehind: return Contact::Behind;
    default: return Contact::Brush;  // hambrushing
  }
}

char32_t level_symbol(BodyLevel level) {
  switch (level) {
    case BodyLevel::AboveHead: case BodyLevel::HeadTop: return hamheadtop;
    case BodyLevel::Head: return hamhead;
    case BodyLevel::Forehead: return hamforehead;
    case BodyLevel::Eyebrows: return hameyebrows;
    case BodyLevel::Eyes: return hameyes;
    case BodyLevel::Nose: return hamnose;
    case BodyLevel::Ears: return hamear;
    case BodyLevel::Cheeks: return hamcheek;
    case BodyLevel::Mouth: case BodyLevel::Lips: return hamlips;
    case BodyLevel::Teeth: return hamteeth;
    case BodyLevel::Tongue: return hamtongue;
    case BodyLevel::Chin: return hamchin;
    case BodyLevel::UnderChin: return hamunderchin;
    case BodyLevel::Neck: return hamneck;
    case BodyLevel::Shoulders: return hamshoulders;
    case BodyLevel::ShoulderTop: return hamshouldertop;
    case BodyLevel::Chest: return hamchest;
    case BodyLevel::Stomach: case BodyLevel::Waist: return hamstomach;
    case BodyLevel::Belly: case BodyLevel::BelowWaist: return hambelowstomach;
    case BodyLevel::NeutralSpace: return hamneutralspace;
  }
  return hamneutralspace;
}

char32_t place_symbol(HandPlace p) {
  switch (p) {
    case HandPlace::Palm: return hampalm;
    case HandPlace::BackOfHand: return hamhandback;
    case HandPlace::ThumbSide: return hamthumbside;
    case HandPlace::LittleSide: return hampinkyside;
    case HandPlace::Fingertip: return hamfingertip;
    case HandPlace::FingerPad: return hamfingerpad;
    case HandPlace::FingerNail: return hamfingernail;
    case HandPlace::FingerBase: return hamfingerbase;
    case HandPlace::FingerMiddleJoint: return hamfingermidjoint;
    case HandPlace::FingerSide: return hamfingerside;
    case HandPlace::Wrist: return hamwristpulse;
    case HandPlace::WristBack: return hamwristback;
    case HandPlace::Forearm: case HandPlace::ForearmBack: return hamlowerarm;
    case HandPlace::Elbow: return hamelbow;
    case HandPlace::UpperArm: return hamupperarm;
    case HandPlace::ThumbBall: return hamthumbball;
    case HandPlace::ElbowInside: return hamelbowinside;
  }
  return hampalm;
}

char32_t contact_symbol(Contact c) {
  switch (c) {
    case Contact::Close: return hamclose;
    case Contact::Touch: case Contact::Grasp: case Contact::Between: return hamtouch;
    case Contact::ArmExtended: return hamarmextended;
    case Contact::Brush: return hambrushing;
    case Contact::Interlock: return haminterlock;
    case Contact::Cross: return hamcross;
    case Contact::Behind: return hambehind;
    case Contact::None: return 0;
  }
  return 0;
}

}  // namespace sw::notation

// The seed's numbered localisations L_i (seed 004 (6); docs/NOTATION.md, "Seed localisation
// table"): one table, read by the formula parser (L1(0) -> chest, right) and by the printer (a
// location that came from L_i prints back as L_i). Index i - 1.
#pragma once

#include "notation/sign_spec.h"

namespace sw::notation {

struct SeedPlace {
  BodyLevel level;
  Side side;
};

inline constexpr SeedPlace kSeedPlaces[] = {
    {BodyLevel::Chest, Side::Right},        {BodyLevel::Chest, Side::Centre},
    {BodyLevel::Chest, Side::Left},         {BodyLevel::NeutralSpace, Side::Centre},
    {BodyLevel::NeutralSpace, Side::Right}, {BodyLevel::Forehead, Side::Centre},
    {BodyLevel::Eyes, Side::Centre},        {BodyLevel::Nose, Side::Centre},
    {BodyLevel::Mouth, Side::Centre},       {BodyLevel::Chin, Side::Centre},
    {BodyLevel::Cheeks, Side::Right},       {BodyLevel::Ears, Side::Right},
    {BodyLevel::Neck, Side::Centre},        {BodyLevel::Shoulders, Side::Right},
    {BodyLevel::Waist, Side::Centre},       {BodyLevel::AboveHead, Side::Right},
    {BodyLevel::Eyebrows, Side::Centre},    {BodyLevel::UnderChin, Side::Centre},
    {BodyLevel::BelowWaist, Side::Right},
};
inline constexpr int kSeedPlaceCount = static_cast<int>(sizeof kSeedPlaces / sizeof kSeedPlaces[0]);

}  // namespace sw::notation

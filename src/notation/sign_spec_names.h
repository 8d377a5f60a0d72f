// The words SignSpec's enums are written with — in the formula notation, in the JSON form and in
// the CLI — one table per enum so that every reader and printer agrees (docs/NOTATION.md lists
// them).
#pragma once

#include <string>
#include <string_view>

#include "notation/sign_spec.h"

namespace sw::notation {

const char* name_of(BodyLevel v);    // "above_head" ... "below_waist", "neutral"
const char* name_of(Side v);         // "right_beside" "right" "centre" "left" "left_beside"
const char* name_of(Contact v);      // "none" "close" "touch" "arm_extended" "brush" ...
const char* name_of(HandPlace v);    // "palm" "back" "thumb_side" ... "upper_arm"
const char* name_of(MovementKind v); // "straight" "arc" ... "replace" "to"
const char* name_of(Size v);         // "normal" "small" "large"
const char* name_of(Manner v);       // "normal" "fast" "slow" "tense" "halt" "rest"
const char* name_of(RepeatKind v);   // "none" "fromstart" ... "continuing_several"
const char* name_of(Symmetry v);     // "none" "lr" "lrud" "lrio" "par" "parud" "pario"
const char* name_of(Location::Kind v);  // "body" "neutral" "hand"
const char* name_of(SeedPalm v);     // "none" "D1" .. "D5"

bool from_name(std::string_view s, BodyLevel* v);
bool from_name(std::string_view s, Side* v);
bool from_name(std::string_view s, Contact* v);
bool from_name(std::string_view s, HandPlace* v);
bool from_name(std::string_view s, MovementKind* v);
bool from_name(std::string_view s, Size* v);
bool from_name(std::string_view s, Manner* v);
bool from_name(std::string_view s, RepeatKind* v);
bool from_name(std::string_view s, Symmetry* v);
bool from_name(std::string_view s, Location::Kind* v);
bool from_name(std::string_view s, SeedPalm* v);

// All names of an enum joined by ", " for "expected one of ..." messages.
template <typename E>
std::string names_list();
template <> std::string names_list<BodyLevel>();
template <> std::string names_list<Side>();
template <> std::string names_list<Contact>();
template <> std::string names_list<HandPlace>();
template <> std::string names_list<MovementKind>();
template <> std::string names_list<RepeatKind>();
template <> std::string names_list<Symmetry>();

}  // namespace sw::notation

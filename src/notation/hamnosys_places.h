// HamNoSys location and contact symbols <-> SignSpec's BodyLevel, HandPlace and Contact, shared
// by the HamNoSys reader/printer and the G-SiGML ones (whose attribute values are the symbol names
// without "ham": location="shoulders" is hamshoulders).
#pragma once

#include "notation/sign_spec.h"

namespace sw::notation {

// Symbol -> SignSpec (callers pass a symbol of the right group).
BodyLevel level_of(char32_t body_location_symbol);
HandPlace place_of(char32_t hand_or_finger_place_symbol);
Contact contact_of(char32_t contact_symbol);
// SignSpec -> the nearest symbol (0 for Contact::None).
char32_t level_symbol(BodyLevel level);
char32_t place_symbol(HandPlace place);
char32_t contact_symbol(Contact contact);

}  // namespace sw::notation

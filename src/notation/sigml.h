// SiGML, both kinds, read and printed: H-SiGML (`hns_sign`: HamNoSys one element per symbol,
// read by the HamNoSys reader) and G-SiGML (`hamgestural_sign`: handconfig/location/motion
// elements with attributes). A document is `<sigml>` or `<sigml_collection>` holding sign
// elements of either kind; a bare sign element is accepted too.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "notation/parse.h"
#include "notation/sign_spec.h"
#include "notation/xml_reader.h"

namespace sw::notation {

// Every hns_sign and hamgestural_sign of the document, in order.
std::vector<SignParse> parse_sigml_text(std::string_view text);

// One sign element each (the reader for the other kind is in gsigml_reader.cpp / hsigml.cpp).
SignParse read_hns_sign(const XmlElement& sign);
SignParse read_hamgestural_sign(const XmlElement& sign);

// `<sigml>` documents of hns_sign / hamgestural_sign elements.
std::string print_hsigml(const std::vector<SignSpec>& signs);
std::string print_gsigml(const std::vector<SignSpec>& signs);
// One sign element, indented by `indent` spaces (for composing documents).
std::string print_hns_sign(const SignSpec& sign, int indent);
std::string print_hamgestural_sign(const SignSpec& sign, int indent);

}  // namespace sw::notation

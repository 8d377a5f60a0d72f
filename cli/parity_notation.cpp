// Parity cases for src/notation: fixed texts in every notation (good and broken) parsed natively;
// the node test (tests/node/notation.test.mjs) parses the same inputs with the WASM module's
// notationParse and expects the same JSON (SignSpec and diagnostics, positions included).
#include <string>
#include <utility>
#include <vector>

#include "notation/parse.h"
#include "notation/sign_spec_json.h"
#include "parity.h"

namespace sw::cli {
namespace {

// {format name, text}
const std::vector<std::pair<const char*, const char*>>& inputs() {
  static const std::vector<std::pair<const char*, const char*>> texts = {
      {"formula",
       "# seed 004 Table 2\n"
       "\xD0\x92 = R(L1(0), D1, F_0^1(0.5), F_0^2(1), F_0^3(1), F_0^4(1), F_0^5(1))\n"
       "\xD0\x93 = R(L1(0), D5, F_0^1(1), F_0^2(1), F_0^3(0), F_0^4(0), F_0^5(0))\n"
       "HELLO = R(H(flat, thumbacross), E(uo), P(l), Loc(forehead, right, touch), M(arc, or, bulge=u, small)) "
       "L(H(fist), Loc(chest, left)) Sym(lr) Rep(fromstart, 2) N(mouth=\"hallo\", expression=happy:0.6)\n"
       "BAD = R(F_0^1(1.5))\n"},
      {"hamnosys",
       "HOUSE = hamflathand,hamextfingerul,hampalmdr,hamparbegin,hammovedr,hamplus,hammovedl,hamparend\n"
       "SIGN = hamsymmlr,hamfinger2,hamthumboutmod,hamextfingeruo,hampalmdl,hamshoulders,hamlrat,hamclose,"
       "hamcirclei,hamellipsev,hamrepeatfromstart\n"
       "BROKEN = hamfist,hamzzz,hamextfingeru,hamparbegin,hammoveu\n"},
      {"hamnosys", "\xEE\x80\x81\xEE\x80\x8C\xEE\x80\xA0\xEE\x80\xBE\xEE\x81\x92\xEE\x83\x91\xEE\x82\x89"},
      {"gsigml",
       "<sigml><hamgestural_sign gloss=\"TIEN\"><sign_manual both_hands=\"true\" lr_symm=\"true\">"
       "<handconfig handshape=\"finger2345\" thumbpos=\"out\" bend5=\"dblhooked\" extfidir=\"u\" palmor=\"d\"/>"
       "<location_bodyarm location=\"shoulders\" side=\"right_beside\" contact=\"close\"/>"
       "<rpt_motion repetition=\"fromstart\"><circularmotion axis=\"l\" size=\"small\"/></rpt_motion>"
       "</sign_manual></hamgestural_sign></sigml>"},
      {"hsigml",
       "<sigml><hns_sign gloss=\"A\"><hamnosys_manual><hamfist/><hamthumbacrossmod/><hamextfingeru/>"
       "<hampalml/><hamchin/><hamtouch/></hamnosys_manual></hns_sign><hns_sign gloss=\"B\">"
       "<hamnosys_manual><hamflathand/><hamUpperarm/></hamnosys_manual></hns_sign></sigml>"},
      {"gsigml", "<sigml><hamgestural_sign gloss=\"CUT\"><sign_manual><handconfig handshape=\"flat\""},
  };
  return texts;
}

nlohmann::json notation_parse_case() {
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& [format_name, text] : inputs()) {
    notation::NotationFormat format = notation::NotationFormat::Formula;
    notation::format_from_name(format_name, &format);
    cases.push_back({{"format", format_name},
                     {"text", text},
                     {"result", notation::parse_result_to_json(notation::parse_signs(text, format), format)}});
  }
  return {{"cases", cases}};
}

}  // namespace

SW_PARITY_CASE("notation_parse", "formula, HamNoSys, H/G-SiGML texts -> SignSpec JSON + diagnostics", notation_parse_case);

}  // namespace sw::cli

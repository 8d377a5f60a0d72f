// Tests of SignSpec <-> JSON (src/notation/sign_spec_json.h).
#include "notation/sign_spec_json.h"

#include <gtest/gtest.h>

#include "notation/formula.h"

namespace sw::notation {
namespace {

TEST(SignSpecJson, BothDirectionsGiveTheSameSign) {
  const std::vector<SignParse> p = parse_formula_text(
      "X = R(H(ceeall, thumbopen), F_2^3(0.25, 0.5), E(dol), Loc(hand, tip, 3, left, touch), C(pad, 1), "
      "M(ellipse, axis=o, ellipse=ul, large, slow, alt), M(replace, H(fist), P(u), Loc(chin, centre))) "
      "L(H(flat), M(nod)) Sym(lrio) Rep(reverse, 3) N(mouth=\"a b\", expression=sad:0.25)");
  ASSERT_TRUE(p[0].ok());
  const SignSpec& a = *p[0].spec;
  const nlohmann::json j = sign_to_json(a);
  EXPECT_EQ(j["dominant"]["location"]["kind"], "hand");
  EXPECT_EQ(j["dominant"]["orientation"]["extended_finger"], nlohmann::json::array({1, -1, 1}));
  EXPECT_EQ(j["symmetry"], "lrio");
  SignSpec b;
  std::string error;
  ASSERT_TRUE(sign_from_json_text(sign_to_json_text(a), &b, &error)) << error;
  EXPECT_EQ(sign_to_json(b), j);
  EXPECT_EQ(print_formula(b), print_formula(a));
}

// The mark that the other hand stays in a step goes through JSON; JSON written before the mark
// (without the field) still reads, as a step whose other hand follows the symmetry.
TEST(SignSpecJson, AStepsOtherHandStayingGoesThroughJson) {
  SignSpec a = *parse_formula_text("R(D1) Sym(lr)")[0].spec;
  MovementStep step;
  step.dominant.push_back(Movement{});
  step.nondominant_stays = true;
  a.movements.push_back(step);
  nlohmann::json j = sign_to_json(a);
  EXPECT_EQ(j["movements"][0]["nondominant_stays"], true);
  SignSpec b;
  std::string error;
  ASSERT_TRUE(sign_from_json(j, &b, &error)) << error;
  ASSERT_EQ(b.movements.size(), 1u);
  EXPECT_TRUE(b.movements[0].nondominant_stays);
  j["movements"][0].erase("nondominant_stays");
  ASSERT_TRUE(sign_from_json(j, &b, &error)) << error;
  EXPECT_FALSE(b.movements[0].nondominant_stays);
  j["movements"][0]["nondominant_stays"] = "yes";
  EXPECT_FALSE(sign_from_json(j, &b, &error));
  EXPECT_EQ(error, "sign.movements[0].nondominant_stays: expected true or false");
}

TEST(SignSpecJson, MalformedDocumentsNameTheField) {
  SignSpec s;
  std::string error;
  EXPECT_FALSE(sign_from_json_text("{not json", &s, &error));
  EXPECT_EQ(error, "not valid JSON");
  EXPECT_FALSE(sign_from_json_text("[1, 2]", &s, &error));
  nlohmann::json j = sign_to_json(*parse_formula_text("R(D1)")[0].spec);
  j["dominant"]["location"]["level"] = "ceiling";
  EXPECT_FALSE(sign_from_json(j, &s, &error));
  EXPECT_EQ(error, "sign.dominant.location.level: expected a known name");
  j = sign_to_json(*parse_formula_text("R(D1)")[0].spec);
  j["dominant"]["shape"]["fingers"][2]["t"] = "half";
  EXPECT_FALSE(sign_from_json(j, &s, &error));
  EXPECT_EQ(error, "sign.dominant.shape.fingers[2].t: expected a number");
  j = sign_to_json(*parse_formula_text("R(D1)")[0].spec);
  j["dominant"]["orientation"]["palm"] = nlohmann::json::array({0, 2, 0});
  EXPECT_FALSE(sign_from_json(j, &s, &error));
  j.erase("movements");
  EXPECT_FALSE(sign_from_json(j, &s, &error));
}

TEST(SignSpecJson, ParseResultCarriesDiagnosticsForTheEditor) {
  const nlohmann::json r = parse_result_to_json(parse_formula_text("A = R(D1)\nB = R(D9)"), NotationFormat::Formula);
  EXPECT_EQ(r["format"], "formula");
  EXPECT_EQ(r["ok"], false);
  ASSERT_EQ(r["signs"].size(), 2u);
  EXPECT_EQ(r["signs"][0]["ok"], true);
  EXPECT_TRUE(r["signs"][1]["spec"].is_null());
  ASSERT_EQ(r["diagnostics"].size(), 1u);
  EXPECT_EQ(r["diagnostics"][0]["line"], 2);
  EXPECT_EQ(r["diagnostics"][0]["column"], 7);
  EXPECT_EQ(r["diagnostics"][0]["offset"], 16);
  EXPECT_EQ(r["diagnostics"][0]["length"], 2);
  EXPECT_EQ(r["diagnostics"][0]["symbol"], "D9");
}

}  // namespace
}  // namespace sw::notation

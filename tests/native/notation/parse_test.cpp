// Tests of the one entry point for every notation (src/notation/parse.h) and of diagnostics'
// formatting (diagnostic.h).
#include "notation/parse.h"

#include <gtest/gtest.h>

#include "notation/sign_spec_json.h"

namespace sw::notation {
namespace {

TEST(Parse, DetectsEachNotation) {
  EXPECT_EQ(detect_format("R(L1(0), D1, F_0^1(0.5))"), NotationFormat::Formula);
  EXPECT_EQ(detect_format("  В = R(D5)"), NotationFormat::Formula);
  EXPECT_EQ(detect_format("hamflathand,hamextfingeru"), NotationFormat::HamNoSys);
  EXPECT_EQ(detect_format("\xEE\x80\x81\xEE\x80\xA0"), NotationFormat::HamNoSys);  // U+E001 U+E020
  EXPECT_EQ(detect_format("\xEF\xBB\xBF\n<?xml version=\"1.0\"?><sigml><hns_sign/></sigml>"), NotationFormat::HSiGML);
  EXPECT_EQ(detect_format("<sigml><hamgestural_sign gloss=\"A\"/></sigml>"), NotationFormat::GSiGML);
  EXPECT_EQ(detect_format("R(H(hamflathand))"), NotationFormat::Formula);  // ham names inside a formula
}

TEST(Parse, FormatNamesRoundTrip) {
  for (NotationFormat f : {NotationFormat::Formula, NotationFormat::HamNoSys, NotationFormat::HSiGML, NotationFormat::GSiGML}) {
    NotationFormat back = NotationFormat::Formula;
    ASSERT_TRUE(format_from_name(format_name(f), &back));
    EXPECT_EQ(back, f);
  }
  NotationFormat out;
  EXPECT_FALSE(format_from_name("signwriting", &out));
  EXPECT_STREQ(format_name(NotationFormat::HSiGML), "hsigml");
}

TEST(Parse, OutcomeKeepsGoodSignsAndAllDiagnostics) {
  const ParseOutcome o = parse_notation("A = R(D1)\nB = R(D9)\nC = R(D2)", NotationFormat::Formula);
  EXPECT_FALSE(o.ok());
  ASSERT_EQ(o.signs.size(), 2u);
  EXPECT_EQ(o.signs[1].gloss, "C");
  ASSERT_EQ(o.diagnostics.size(), 1u);
  const std::string line = format_diagnostic(o.diagnostics[0]);
  EXPECT_EQ(line.rfind("line 2, column 7: expected a hand item (F_i^k, H, D<i>, E, P, L<i>, Loc, C, M, Par, Rep), found 'D9'", 0), 0u) << line;
  const ParseOutcome empty = parse_notation("# nothing\n", NotationFormat::Formula);
  EXPECT_FALSE(empty.ok());
  EXPECT_TRUE(empty.signs.empty());
}

TEST(Parse, WarningsDoNotFailAParse) {
  std::vector<Diagnostic> d(1);
  d[0].severity = Severity::Warning;
  EXPECT_FALSE(has_error(d));
  d.push_back(Diagnostic{});
  EXPECT_TRUE(has_error(d));
  EXPECT_NE(format_diagnostic(d[0]).find("warning"), std::string::npos);
}

TEST(Parse, PrintNotationReadsBackInEveryFormat) {
  const ParseOutcome o = parse_notation(
      "HOUSE = hamsymmlr,hamflathand,hamextfingerul,hampalmdr,hamchest,hamclose,hammovedr,hamsmallmod,hamrepeatfromstart",
      NotationFormat::HamNoSys);
  ASSERT_TRUE(o.ok());
  for (NotationFormat f : {NotationFormat::Formula, NotationFormat::HamNoSys, NotationFormat::HSiGML, NotationFormat::GSiGML}) {
    const std::string text = print_notation(o.signs, f);
    EXPECT_EQ(detect_format(text), f) << text;
    const ParseOutcome again = parse_notation(text, f);
    ASSERT_TRUE(again.ok()) << format_name(f) << ": " << text;
    EXPECT_EQ(sign_to_json(again.signs[0]), sign_to_json(o.signs[0])) << format_name(f) << ": " << text;
  }
}

}  // namespace
}  // namespace sw::notation

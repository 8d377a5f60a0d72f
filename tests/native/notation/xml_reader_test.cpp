// Tests of the small XML reader (src/notation/xml_reader.h).
#include "notation/xml_reader.h"

#include <gtest/gtest.h>

namespace sw::notation {
namespace {

TEST(XmlReader, ElementsAttributesEntitiesCommentsCdata) {
  const std::string text =
      "\xEF\xBB\xBF<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<!DOCTYPE sigml [ <!ELEMENT sigml ANY> ]>\n"
      "<!-- a comment -->\n"
      "<sigml a='1' b=\"x &amp; y &lt;&#65;&#x42;&quot;\">\n"
      "  <hns_sign gloss=\"Г\"><![CDATA[<raw & text>]]> t&apos;x <hamfist/></hns_sign>\n"
      "</sigml>\n";
  XmlElement root;
  std::vector<Diagnostic> d;
  ASSERT_TRUE(read_xml(text, &root, &d)) << (d.empty() ? "" : format_diagnostic(d[0]));
  EXPECT_EQ(root.name, "sigml");
  EXPECT_TRUE(root.closed);
  ASSERT_NE(root.attribute("b"), nullptr);
  EXPECT_EQ(*root.attribute("a"), "1");
  EXPECT_EQ(*root.attribute("b"), "x & y <AB\"");
  ASSERT_EQ(root.children.size(), 1u);
  const XmlElement& sign = root.children[0];
  EXPECT_EQ(*sign.attribute("gloss"), "Г");
  EXPECT_EQ(sign.line, 5);
  EXPECT_EQ(sign.column, 3);
  EXPECT_EQ(sign.text, "<raw & text> t'x ");
  ASSERT_EQ(sign.children.size(), 1u);
  EXPECT_EQ(sign.children[0].name, "hamfist");
  EXPECT_EQ(sign.children[0].column, 57);  // "Г" (2 bytes) is one column
  EXPECT_EQ(root.attribute("missing"), nullptr);
}

TEST(XmlReader, ErrorsHaveLineColumnAndKeepCompleteElements) {
  XmlElement root;
  std::vector<Diagnostic> d;
  EXPECT_FALSE(read_xml("<a>\n  <b x=\"1\"/>\n  <c>\n</a>", &root, &d));
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].line, 4);
  EXPECT_EQ(d[0].column, 1);
  EXPECT_NE(d[0].message.find("expected the end tag </c>"), std::string::npos);
  ASSERT_EQ(root.children.size(), 2u);
  EXPECT_TRUE(root.children[0].closed);   // <b/> complete
  EXPECT_FALSE(root.children[1].closed);  // <c> cut off

  const char* bad[] = {"<a x=1/>", "<a x=\"1\" x=\"2\"/>", "<a>&bogus;</a>", "<a>", "<a></b>",
                       "<a/><b/>", "", "<a x=\"1/>", "<a><!-- never closed", "<1a/>", "<a>&#x110000;</a>"};
  for (const char* text : bad) {
    d.clear();
    EXPECT_FALSE(read_xml(text, &root, &d)) << text;
    ASSERT_FALSE(d.empty()) << text;
    EXPECT_NE(d[0].message.find("expected"), std::string::npos) << d[0].message;
  }
}

TEST(XmlReader, NestingBeyondTheLimitIsAnError) {
  std::string text;
  for (int i = 0; i <= kMaxXmlDepth; ++i) text += "<a>";
  XmlElement root;
  std::vector<Diagnostic> d;
  EXPECT_FALSE(read_xml(text, &root, &d));
  ASSERT_FALSE(d.empty());
  EXPECT_NE(d[0].message.find("deeper"), std::string::npos);
}

TEST(XmlReader, DiagnosticAtPointsAtTheStartTag) {
  const std::string text = "<sigml>\n  <hns_sign gloss=\"x\"><hamfist/></hns_sign>\n</sigml>";
  XmlElement root;
  std::vector<Diagnostic> d;
  ASSERT_TRUE(read_xml(text, &root, &d));
  ASSERT_EQ(root.children.size(), 1u);
  const XmlElement& sign = root.children[0];
  Diagnostic diag = diagnostic_at(sign, "hns_sign", "expected a manual part", Severity::Warning);
  EXPECT_EQ(diag.line, 2);
  EXPECT_EQ(diag.column, 3);
  EXPECT_EQ(text.substr(diag.offset, diag.length), "<hns_sign gloss=\"x\">");
  EXPECT_EQ(diag.symbol, "hns_sign");
  EXPECT_EQ(diag.severity, Severity::Warning);
  EXPECT_EQ(diagnostic_at(sign, "s", "m").severity, Severity::Error);
}

TEST(XmlReader, EscapeRoundTrips) {
  const std::string value = "a<b>&\"c'";
  XmlElement root;
  std::vector<Diagnostic> d;
  ASSERT_TRUE(read_xml("<x v=\"" + xml_escape(value) + "\">" + xml_escape(value) + "</x>", &root, &d));
  EXPECT_EQ(*root.attribute("v"), value);
  EXPECT_EQ(root.text, value);
}

}  // namespace
}  // namespace sw::notation

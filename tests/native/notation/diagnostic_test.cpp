// Diagnostic helpers (notation/diagnostic.h).
#include "notation/diagnostic.h"

#include <gtest/gtest.h>

namespace sw::notation {
namespace {

TEST(Diagnostic, HasErrorIgnoresWarnings) {
  std::vector<Diagnostic> list;
  EXPECT_FALSE(has_error(list));
  Diagnostic warning;
  warning.severity = Severity::Warning;
  list.push_back(warning);
  EXPECT_FALSE(has_error(list));
  list.push_back(Diagnostic{});
  EXPECT_TRUE(has_error(list));
}

TEST(Diagnostic, FormatsLineColumnMessageAndSymbol) {
  Diagnostic d;
  d.line = 3;
  d.column = 14;
  d.symbol = "hamfoo";
  d.message = "unknown symbol";
  EXPECT_EQ(format_diagnostic(d), "line 3, column 14: unknown symbol 'hamfoo'");
}

TEST(Diagnostic, FormatsWarningsWithoutSymbol) {
  Diagnostic d;
  d.severity = Severity::Warning;
  d.message = "repetition count ignored";
  EXPECT_EQ(format_diagnostic(d), "line 1, column 1: warning: repetition count ignored");
}

}  // namespace
}  // namespace sw::notation

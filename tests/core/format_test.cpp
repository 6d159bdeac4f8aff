#include "topocut/core/format.h"

#include <string>

#include <gtest/gtest.h>

namespace topocut {
namespace {

TEST(Format, PrintsLikePrintf) {
  EXPECT_EQ(format("%.3f ms, p95 %.1f %%", 1.23456, 99.95), "1.235 ms, p95 100.0 %");
  EXPECT_EQ(format("%d of %zu", 3, std::size_t{40}), "3 of 40");
  EXPECT_EQ(format("plain"), "plain");
}

TEST(Format, LongTextIsNotCut) {
  const std::string word(1000, 'x');
  const std::string out = format("<%s|%.2f>", word.c_str(), 2.5);
  EXPECT_EQ(out, "<" + word + "|2.50>");
}


TEST(Format, TerminalTextEscapesEveryControlCharacterAndKeepsTheRest) {
  EXPECT_EQ(terminal_text("office_a"), "office_a");
  EXPECT_EQ(terminal_text("caf\xc3\xa9 \xc2\xb1"), "caf\xc3\xa9 \xc2\xb1");  // UTF-8 stays
  EXPECT_EQ(terminal_text("a\x1b[31mb"), "a\\x1B[31mb");                     // an escape sequence
  EXPECT_EQ(terminal_text("one\rtwo\nthree\x7f"), "one\\x0Dtwo\\x0Athree\\x7F");
  EXPECT_EQ(terminal_text("c1 \xc2\x9b" "2J"), "c1 \\xC2\\x9B2J");            // CSI as a C1 control
  for (const std::string& name : {std::string("\x1b]0;title\x07"), std::string(1, '\0') + "x"})
    for (const char c : terminal_text(name)) EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 || c == 0x7f) << name;
}

TEST(Format, CsvCellsAreQuotedWhenASpreadsheetWouldRunOrSplitThem) {
  EXPECT_EQ(csv_cell("office_a"), "office_a");
  EXPECT_EQ(csv_cell("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_cell("say \"hi\""), "\"say \"\"hi\"\"\"");
  for (const std::string formula : {"=1+1", "+1", "-2+3", "@SUM(A1)", "\tx", "\rx"})
    EXPECT_EQ(csv_cell(formula), "\"'" + formula + "\"") << formula;
  EXPECT_EQ(csv_cell("=HYPERLINK(\"x\")"), "\"'=HYPERLINK(\"\"x\"\")\"");
  EXPECT_EQ(csv_cell(""), "");
}

}  // namespace
}  // namespace topocut

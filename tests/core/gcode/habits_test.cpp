// Comments and typing habits of real lathe programs (issue 26 items 8 and 9):
// nested and unclosed comments, a bare text line, blanks inside a word, the
// letter O for the digit 0, a comma for the decimal point, and an M code a
// Haas lathe does not have. Each gives one diagnostic on its line, or none.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"

namespace klueng::core::gcode {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

// "CODE line:column+length" for each diagnostic, in order.
std::vector<std::string> listOf(const std::vector<Diagnostic>& diags) {
  std::vector<std::string> out;
  for (const Diagnostic& d : diags)
    out.push_back(d.code + " " + std::to_string(d.range.line) + ":" + std::to_string(d.range.column) + "+" +
                  std::to_string(d.range.length));
  return out;
}

std::vector<Diagnostic> checked(const std::string& text, Dialect dialect = Dialect::Fanuc) {
  CheckOptions o;
  o.dialect = dialect;
  o.modalRules = false;
  return check(parse(text), o);
}

// A banner in the French habit: a lone "(" line, a title never closed, and a
// cutting-speed formula whose parentheses nest.
const char* const kBanner =
    "%\n"
    "O0042 (BAGUE)\n"
    "(\n"
    "(OUTILS :\n"
    "(  T1 : CARBURE  )\n"
    "(  n = Vc*1000/(pi*D) = 25000/78.5 = 318 tr/min  )\n"
    "G21 G99\n"
    "M30\n";

TEST(Comments, NestedParenthesesThatBalanceAreOneComment) {
  const Program p = parse("(n = Vc*1000/(pi*D) = 25000/78.5 = 318) G00 X25.");
  EXPECT_THAT(p.lexicalDiagnostics, IsEmpty());
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_EQ(p.blocks[0].comment(), "n = Vc*1000/(pi*D) = 25000/78.5 = 318");
  ASSERT_EQ(p.blocks[0].words.size(), 2u);
  EXPECT_EQ(p.blocks[0].words[0].range.column, 41);
}

TEST(Comments, ANestedNoteInsideATitleReadsToTheOuterParenthesis) {
  const Program p = parse("(  DIAMETRE VISE : 25.010 (MILIEU TOL)      )\nG00 X25.");
  EXPECT_THAT(p.lexicalDiagnostics, IsEmpty());
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_EQ(p.blocks[0].line, 2);
}

TEST(Comments, BannerGivesOneWarningPerUnclosedLineOnAFanuc) {
  // A Fanuc's comment ends at its first ')': the formula's "= 25000/78.5 = 318 tr/min" after
  // it is read as words and stops the control (issue 38 item 5); Haas reads the nesting.
  EXPECT_THAT(listOf(checked(kBanner)), ElementsAre("W108 3:1+1", "W108 4:1+9", "E142 6:22+20"));
  const auto diags = checked(kBanner);
  EXPECT_EQ(diags[0].severity, Severity::Warning);
  EXPECT_FALSE(hasErrors(checked(kBanner, Dialect::Haas)));
}

TEST(Comments, BannerIsOneErrorPerUnclosedLineInClassic) {
  const auto diags = checked(kBanner, Dialect::Classic);
  std::vector<std::string> lexical;
  for (const Diagnostic& d : diags)
    if (d.range.line == 3 || d.range.line == 4) lexical.push_back(d.code + "@" + std::to_string(d.range.line));
  EXPECT_THAT(lexical, ElementsAre("E105@3", "E105@4"));
  for (const Diagnostic& d : diags) {
    if (d.code == "E105") {
      EXPECT_EQ(d.severity, Severity::Error);
    }
  }
}

TEST(Comments, AnUnclosedCommentAfterWordsKeepsTheWords) {
  const Program p = parse("G01 X20. (finish pass");
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_EQ(p.blocks[0].words.size(), 2u);
  EXPECT_EQ(p.blocks[0].comment(), "finish pass");
  EXPECT_THAT(listOf(p.lexicalDiagnostics), ElementsAre("W108 1:10+12"));
}

TEST(TextLine, ABareTextLineIsOneError) {
  const auto diags = checked("G21\nroughing pass\nM30\n");
  EXPECT_THAT(listOf(diags), ElementsAre("E138 2:1+13"));
  EXPECT_EQ(diags[0].severity, Severity::Error);
  EXPECT_EQ(diags[0].args, (std::vector<std::string>{"roughing pass"}));
}

TEST(TextLine, IndentedTextBeforeACommentAndTextAfterWords) {
  EXPECT_THAT(listOf(checked("   face the end  (then chamfer)")), ElementsAre("E138 1:4+12"));
  const Program p = parse("G00 X20. go back");
  EXPECT_THAT(listOf(p.lexicalDiagnostics), ElementsAre("E138 1:10+7"));
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_EQ(p.blocks[0].words.size(), 2u);
}

TEST(TextLine, AThaiTextLineIsOneError) {
  // "กลึงหยาบ ผิวงาน" is 15 code points.
  EXPECT_THAT(listOf(checked("G21\nกลึงหยาบ ผิวงาน\nM30\n")), ElementsAre("E138 2:1+15"));
}

TEST(TextLine, TwoLettersBeforeAValueAreStillWords) {
  // "XZ5." is a lone X then Z5. (E101), not text.
  EXPECT_THAT(listOf(parse("G01 XZ5.").lexicalDiagnostics), ElementsAre("E101 1:5+1"));
  // Macro statements are not text.
  EXPECT_THAT(parse("WHILE [#1 LT 3] DO 1\nEND 1\nGOTO 10\nN10 M30").lexicalDiagnostics, IsEmpty());
}

TEST(Blanks, ABlankBetweenTheLetterAndItsNumberIsSkipped) {
  const Program p = parse("G1 X 38 Z - 5.");
  EXPECT_THAT(p.lexicalDiagnostics, IsEmpty());
  ASSERT_EQ(p.blocks.size(), 1u);
  const auto& w = p.blocks[0].words;
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[1].text(), "X38");
  EXPECT_DOUBLE_EQ(w[1].value, 38.0);
  EXPECT_EQ(w[1].range.column, 4);
  EXPECT_EQ(w[1].range.length, 4);
  EXPECT_EQ(w[2].text(), "Z-5.");
  EXPECT_DOUBLE_EQ(w[2].value, -5.0);
  EXPECT_EQ(w[2].range.column, 9);
  EXPECT_EQ(w[2].range.length, 6);
  EXPECT_THAT(checked("G1 X 38 Z - 5. F0.2"), IsEmpty());
}

TEST(Blanks, ClassicNeedsTheNumberRightAfterTheLetter) {
  EXPECT_THAT(listOf(checked("G01 X 38 Z-5. F0.2", Dialect::Classic)), ElementsAre("E135 1:5+4"));
}

TEST(Blanks, DigitsSplitByABlankJoinWithAWarning) {
  const Program p = parse("G01 X20 30");
  ASSERT_EQ(p.blocks.size(), 1u);
  ASSERT_EQ(p.blocks[0].words.size(), 2u);
  EXPECT_DOUBLE_EQ(p.blocks[0].words[1].value, 2030.0);
  EXPECT_THAT(listOf(p.lexicalDiagnostics), ElementsAre("W109 1:5+6"));
  EXPECT_EQ(p.lexicalDiagnostics[0].args, (std::vector<std::string>{"X20 30", "X2030"}));
  EXPECT_EQ(p.lexicalDiagnostics[0].severity, Severity::Warning);
}

TEST(Typos, LetterOForZeroIsOneErrorThatNamesTheCode) {
  const auto diags = checked("GO1 X20. Z-5. F0.2");
  EXPECT_THAT(listOf(diags), ElementsAre("E136 1:1+3"));
  EXPECT_EQ(diags[0].args, (std::vector<std::string>{"GO1", "G01"}));
  const auto m = checked("G97 S1000 mO3");
  EXPECT_THAT(listOf(m), ElementsAre("E136 1:11+3"));
  EXPECT_EQ(m[0].args, (std::vector<std::string>{"MO3", "M03"}));
}

TEST(Typos, CommaForTheDecimalPointIsOneError) {
  const auto diags = checked("G00 Z,15");
  EXPECT_THAT(listOf(diags), ElementsAre("E137 1:5+4"));
  EXPECT_EQ(diags[0].args, (std::vector<std::string>{"Z,15", "Z.15"}));
  const auto x = checked("G01 X2,5 F0.1");
  EXPECT_THAT(listOf(x), ElementsAre("E137 1:5+4"));
  EXPECT_EQ(x[0].args, (std::vector<std::string>{"X2,5", "X2.5"}));
  // A chamfer word still reads: the comma is followed by its letter.
  EXPECT_THAT(parse("G01 X20.,C1. F0.1").lexicalDiagnostics, IsEmpty());
}

TEST(HaasMCodes, AnMCodeTheHaasLatheDoesNotHaveIsAnError) {
  // M93 (meant as M03) on a Haas: the control alarms, so the run must not cut with the spindle stopped.
  const auto haas = checked("G97 S1000 M93 (spindle on)", Dialect::Haas);
  EXPECT_THAT(listOf(haas), ElementsAre("E115 1:11+3"));
  // An option's code above 99 (live tooling M133) stays a warning.
  EXPECT_THAT(listOf(checked("M133 P1000", Dialect::Haas)), ElementsAre("W101 1:1+4"));
  // The Fanuc manual leaves M codes to the machine builder: a warning there.
  EXPECT_THAT(listOf(checked("G97 S1000 M93", Dialect::Fanuc)), ElementsAre("W101 1:11+3"));
}

}  // namespace
}  // namespace klueng::core::gcode

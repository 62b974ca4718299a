// Grammar checker tests (SPEC 4, 5, 13 and the "ext" rules): for each rule a
// passing and a failing program, asserting code, line and column.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <string>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/messages.h"

namespace klueng::core::gcode {
namespace {

enum class In { Both, Fanuc, Classic };

std::vector<Dialect> dialectsOf(In in) {
  switch (in) {
    case In::Fanuc: return {Dialect::Fanuc};
    case In::Classic: return {Dialect::Classic};
    case In::Both: break;
  }
  return {Dialect::Fanuc, Dialect::Classic};
}

std::string listing(const std::vector<Diagnostic>& diags) {
  std::ostringstream s;
  for (const auto& d : diags)
    s << "  " << d.code << " " << d.range.line << ":" << d.range.column << "+" << d.range.length << " "
      << formatMessage(d, Lang::En) << "\n";
  return s.str();
}

std::vector<Diagnostic> checkText(const std::string& text, Dialect dialect,
                                  std::optional<std::vector<int>> tools = {}) {
  CheckOptions o;
  o.dialect = dialect;
  o.toolsWithBitmap = std::move(tools);
  return check(parse(text), o);
}

// Every message fills all of its placeholders, in both languages.
void expectMessagesComplete(const std::vector<Diagnostic>& diags) {
  for (const auto& d : diags) {
    ASSERT_NE(findMessage(d.code), nullptr) << d.code;
    for (Lang lang : {Lang::En, Lang::Th}) {
      const std::string text = formatMessage(d, lang);
      EXPECT_EQ(text.find('?'), std::string::npos) << d.code << ": " << text;
      EXPECT_EQ(text.find('{'), std::string::npos) << d.code << ": " << text;
    }
  }
}

// ---- programs that must be clean -------------------------------------------

struct CleanCase {
  const char* text;
  In in;
};

class Clean : public ::testing::TestWithParam<CleanCase> {};

TEST_P(Clean, HasNoDiagnostics) {
  for (Dialect dialect : dialectsOf(GetParam().in)) {
    const auto diags = checkText(GetParam().text, dialect, std::vector<int>{1, 2, 3});
    EXPECT_TRUE(diags.empty()) << GetParam().text << " (" << dialectName(dialect) << ")\n" << listing(diags);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table, Clean,
    ::testing::Values(
        // rule 1: the lathe letters, and the ext R P Q
        CleanCase{"N10 G01 X20. Z5. F0.2 S500 T0101 M03", In::Both}, CleanCase{"G02 X20. Z-5. R2.", In::Both},
        CleanCase{"G04 P500", In::Both}, CleanCase{"M41\nC10.\nH5.\nM91", In::Classic},
        // rule 2: each letter once; G and M may repeat
        CleanCase{"G00 G21 G40 X20. Z5.", In::Both}, CleanCase{"M03 M08 S800", In::Both},
        // rule 3: M00/M01/M02/M30 alone, N allowed before them
        CleanCase{"N10 M00", In::Both}, CleanCase{"M01", In::Both}, CleanCase{"N9999 M02", In::Both},
        CleanCase{"M30 (end)", In::Both},
        // rule 4: codes of different M groups may share a block
        CleanCase{"M04 M09 S300", In::Both}, CleanCase{"M86 M91", In::Both},
        CleanCase{"M41 M91", In::Fanuc},  // M41 is a gear range on a Fanuc, not C-axis mode
        // rule 5/6: different modal groups; G50 S alone
        CleanCase{"G99 G21 G97 G40 G00 X100. Z100.", In::Fanuc}, CleanCase{"G50 S2500", In::Both},
        CleanCase{"G28 U0. W0.", In::Both}, CleanCase{"G50 X100. Z200.", In::Both},
        // rule 7 is classic only
        CleanCase{"N15 G99", In::Both}, CleanCase{"G98", In::Both}, CleanCase{"G98 F100.", In::Fanuc},
        CleanCase{"G18 G21 G40 G80 G99", In::Fanuc},
        // rule 8: O first and alone
        CleanCase{"O0001\nN10 G00 X20.", In::Both}, CleanCase{"%\nO9999 (part)\nG00 X1.", In::Both},
        // rule 9: N first
        CleanCase{"N1 X30.", In::Both}, CleanCase{"/N20 X30.", In::Both},
        // rule 10: one word per axis
        CleanCase{"X30. W2.", In::Both}, CleanCase{"U2. Z-5.", In::Both},
        // rule 11: G04 with a time
        CleanCase{"G04 U0.5", In::Both}, CleanCase{"G04 X1.", In::Both}, CleanCase{"G04 P0", In::Both},
        // rule 12: any word order
        CleanCase{"X20. G01 Z5. F0.1", In::Both}, CleanCase{"Z5. F0.1 X20. G01", In::Both},
        // word formats at their limits
        CleanCase{"X9999.999 Z-9999.999\nU-.5 W.001", In::Both}, CleanCase{"F0.001 S9999.999", In::Both},
        CleanCase{"G20\nX1.2345 Z-0.0001", In::Both}, CleanCase{"G20\nG21\nX1.234", In::Both},
        CleanCase{"N1\nN9999 G00", In::Both}, CleanCase{"T0316", In::Both}, CleanCase{"T0100", In::Both},
        CleanCase{"T101", In::Fanuc}, CleanCase{"T0101\nT0000", In::Fanuc}, CleanCase{"G1 X1.\ng01 x2.", In::Both},
        CleanCase{"M3 S100", In::Both}, CleanCase{"G76 P020060 Q50 R0.05", In::Both},
        CleanCase{"G71 P100 Q200 U0.5 W0.1 F0.25\nN100 G00 X30.\nN200 G01 Z-20.", In::Both},
        CleanCase{"M98 P1234\nM30\nO1234\nM99", In::Fanuc}, CleanCase{"M42", In::Fanuc},
        CleanCase{"G54\nG53 X0. Z0.", In::Fanuc},
        // ext arc rules
        CleanCase{"G02 X20. Z-5. I2. K0.", In::Both}, CleanCase{"G03 U4. W-2. R2.", In::Both},
        CleanCase{"G02 X20. Z-5. R2.\nX22. Z-6. R1.", In::Both},
        CleanCase{"G42 G00 X24. Z2.\nG01 Z-20. F0.1\nG02 X30. Z-23. R3.\nG40 G00 X50.", In::Both},
        CleanCase{"G02 X20. Z-5. R2.\nG40\nG01 X30.", In::Both},  // G40 with no motion is not "on an arc"
        CleanCase{"G90 X45. Z-30. R-2. F0.2", In::Both}, CleanCase{"T0303", In::Both}));

// ---- programs with one error (or warning) at a known place -----------------------

struct FailCase {
  const char* text;
  In in;
  const char* code;
  int line;
  int column;
  int length;
};

std::ostream& operator<<(std::ostream& os, const FailCase& c) { return os << c.code << " in \"" << c.text << "\""; }

class Fails : public ::testing::TestWithParam<FailCase> {};

TEST_P(Fails, ReportsCodeLineAndColumn) {
  const FailCase& c = GetParam();
  for (Dialect dialect : dialectsOf(c.in)) {
    const auto diags = checkText(c.text, dialect, std::vector<int>{1, 2, 3});
    const auto hit = std::find_if(diags.begin(), diags.end(), [&](const Diagnostic& d) { return d.code == c.code; });
    ASSERT_NE(hit, diags.end()) << c << " (" << dialectName(dialect) << ")\n" << listing(diags);
    EXPECT_EQ(hit->range, (SourceRange{c.line, c.column, c.length})) << c << "\n" << listing(diags);
    // An E code no manual of the machine's control makes a stop is a warning there (docs/dialects.md §10).
    const auto& demoted = machineProfile(dialect).errorsAsWarnings;
    const bool warning =
        c.code[0] == 'W' || std::find(demoted.begin(), demoted.end(), std::atoi(c.code + 1)) != demoted.end();
    EXPECT_EQ(hit->severity, warning ? Severity::Warning : Severity::Error) << c << " (" << dialectName(dialect) << ")";
    if (c.code[0] == 'W' || !warning) {  // (a demoted case may hold another error, as E310 beside E302)
      EXPECT_EQ(hasErrors(diags), !warning) << c << " (" << dialectName(dialect) << ")\n" << listing(diags);
    }
    expectMessagesComplete(diags);
    EXPECT_TRUE(std::is_sorted(diags.begin(), diags.end(), [](const Diagnostic& a, const Diagnostic& b) {
      return a.range.line != b.range.line ? a.range.line < b.range.line : a.range.column < b.range.column;
    }));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Rules, Fails,
    ::testing::Values(
        // rule 1
        FailCase{"G01 X30. Y5. F0.2", In::Both, "E201", 1, 10, 3}, FailCase{"N10 A90.", In::Both, "E201", 1, 5, 4},
        FailCase{"G00 X1.\nB2", In::Both, "E201", 2, 1, 2},
        // rule 2
        FailCase{"G01 X30. X31.", In::Both, "E202", 1, 10, 4}, FailCase{"F0.2 Z1. F0.3", In::Both, "E202", 1, 10, 4},
        FailCase{"T0101 T0202", In::Both, "E202", 1, 7, 5},
        // rule 3
        FailCase{"M00 X20.", In::Classic, "E203", 1, 1, 3}, FailCase{"N5 X20. M02", In::Classic, "E203", 1, 9, 3},
        FailCase{"G00 M30", In::Classic, "E203", 1, 5, 3}, FailCase{"M01 M08", In::Classic, "E203", 1, 1, 3},
        // Fanuc, Haas: no manual says the control stops; the move first, then the stop (W118).
        FailCase{"M00 X20.", In::Fanuc, "W118", 1, 1, 3}, FailCase{"G00 X100. Z100. M30", In::Fanuc, "W118", 1, 17, 3},
        // rule 4
        FailCase{"M03 M05", In::Both, "E204", 1, 5, 3}, FailCase{"M04 S500 M03", In::Both, "E204", 1, 10, 3},
        FailCase{"M08 M09", In::Both, "E204", 1, 5, 3}, FailCase{"M41 M91", In::Classic, "E204", 1, 5, 3},
        FailCase{"M86 M87", In::Both, "E204", 1, 5, 3}, FailCase{"M41 M42", In::Fanuc, "E204", 1, 5, 3},
        // rule 5
        FailCase{"G00 G01 X35.", In::Classic, "E205", 1, 5, 3}, FailCase{"G96 S100 G97", In::Classic, "E205", 1, 10, 3},
        FailCase{"G20 G21", In::Classic, "E205", 1, 5, 3}, FailCase{"G41 G42 G00 X1.", In::Classic, "E205", 1, 5, 3},
        FailCase{"G04 U1. G50 S100", In::Both, "E205", 1, 9, 3},
        // A Fanuc uses the last G code of a modal group (issue 38): a warning at the second.
        FailCase{"G00 G01 X35. F0.2", In::Fanuc, "W116", 1, 5, 3},
        FailCase{"G96 S100 G97", In::Fanuc, "W116", 1, 10, 3}, FailCase{"G20 G21", In::Fanuc, "W116", 1, 5, 3},
        FailCase{"G41 G42 G00 X1.", In::Fanuc, "W116", 1, 5, 3},
        // rule 6
        FailCase{"G04 G01 U1.", In::Both, "E206", 1, 5, 3}, FailCase{"G01 X20. G28", In::Classic, "E206", 1, 10, 3},
        FailCase{"G50 S2000 G00", In::Both, "E206", 1, 11, 3},
        // rule 7
        FailCase{"G98 F100.", In::Classic, "E207", 1, 1, 3}, FailCase{"N5 G01 G99", In::Classic, "E207", 1, 8, 3},
        FailCase{"G18 G21 G40 G80 G99", In::Classic, "E207", 1, 17, 3},
        // rule 8
        FailCase{"N10 O0001", In::Both, "E208", 1, 5, 5}, FailCase{"O0001 G00", In::Both, "E208", 1, 1, 5},
        // (an O block alone later in the file starts a subprogram on Fanuc and Haas)
        FailCase{"O0001\nO0002", In::Classic, "E208", 2, 1, 5},
        FailCase{"G00 X1.\nO0002", In::Classic, "E208", 2, 1, 5},
        FailCase{"G00 X1.\nO0002 G00", In::Both, "E208", 2, 1, 5},
        // rule 9
        FailCase{"X30. N200", In::Both, "E209", 1, 6, 4}, FailCase{"/G00 N5", In::Both, "E209", 1, 6, 2},
        // rule 10
        FailCase{"G01 X30. U2.", In::Both, "E210", 1, 10, 3}, FailCase{"Z-5. W-2.", In::Both, "E210", 1, 6, 4},
        FailCase{"W1. Z2.", In::Both, "E210", 1, 5, 3}, FailCase{"G01 C10. H5.", In::Both, "E210", 1, 10, 3},
        // rule 11
        FailCase{"G04", In::Both, "E211", 1, 1, 3}, FailCase{"N5 G4 F0.1", In::Both, "E211", 1, 4, 2},
        // word formats (SPEC 4)
        FailCase{"G01 X12345.6", In::Both, "E110", 1, 5, 8}, FailCase{"Z-10000.", In::Both, "E110", 1, 1, 8},
        FailCase{"I9999.9991", In::Both, "E110", 1, 1, 10}, FailCase{"F10000.", In::Both, "E110", 1, 1, 7},
        FailCase{"X1.2345", In::Classic, "E111", 1, 1, 7}, FailCase{"G21\nZ-0.0001", In::Classic, "E111", 2, 1, 8},
        FailCase{"G20\nX1.23456", In::Classic, "E111", 2, 1, 8},
        FailCase{"G20 X1.\nG21\nK1.2345", In::Classic, "E111", 3, 1, 7}, FailCase{"F-0.2", In::Both, "E112", 1, 1, 5},
        FailCase{"F0", In::Both, "E112", 1, 1, 2}, FailCase{"M03 S0.0001", In::Both, "E112", 1, 5, 7},
        FailCase{"G1.5 X1.", In::Both, "E113", 1, 1, 4}, FailCase{"M3.", In::Both, "E113", 1, 1, 3},
        FailCase{"G07 X30.", In::Both, "E114", 1, 1, 3}, FailCase{"G100", In::Both, "E114", 1, 1, 4},
        FailCase{"G-1", In::Both, "E114", 1, 1, 3}, FailCase{"G18", In::Classic, "E114", 1, 1, 3},
        FailCase{"G54", In::Classic, "E114", 1, 1, 3}, FailCase{"G80", In::Classic, "E114", 1, 1, 3},
        FailCase{"G53 X0.", In::Classic, "E114", 1, 1, 3}, FailCase{"M77", In::Classic, "E115", 1, 1, 3},
        FailCase{"M42", In::Classic, "E115", 1, 1, 3}, FailCase{"N0 G00", In::Both, "E116", 1, 1, 2},
        FailCase{"N10000", In::Classic, "E116", 1, 1, 6}, FailCase{"N1.5", In::Both, "E116", 1, 1, 4},
        FailCase{"O0", In::Classic, "E116", 1, 1, 2}, FailCase{"O0", In::Fanuc, "W117", 1, 1, 2},
        FailCase{"T0917", In::Classic, "E117", 1, 1, 5},
        FailCase{"T0000", In::Classic, "E117", 1, 1, 5},  // Fanuc/Haas: the turret stays, the offset is cancelled
        FailCase{"T1317", In::Fanuc, "E118", 1, 1, 5}, FailCase{"T0900", In::Classic, "E117", 1, 1, 5},
        FailCase{"T0017", In::Fanuc, "E118", 1, 1, 5}, FailCase{"T101", In::Classic, "E117", 1, 1, 4},
        FailCase{"T01", In::Classic, "E117", 1, 1, 3}, FailCase{"T01", In::Fanuc, "E118", 1, 1, 3},
        FailCase{"T01.01", In::Classic, "E117", 1, 1, 6}, FailCase{"G04 P1.5", In::Both, "E119", 1, 5, 4},
        FailCase{"G04 P-5", In::Both, "E119", 1, 5, 3}, FailCase{"M98 Q1.5", In::Both, "E119", 1, 5, 4},
        // lexical errors reach the checker's report
        FailCase{"G01 X", In::Both, "E101", 1, 5, 1},
        // ext rules
        FailCase{"G02", In::Both, "E301", 1, 1, 3}, FailCase{"G03 F0.1 R2.", In::Both, "E301", 1, 1, 3},
        FailCase{"G02 X20. Z-5. R2. I1.", In::Both, "E302", 1, 15, 3},
        FailCase{"G03 X20. Z-5.\nZ-6. K1. R1.", In::Both, "E302", 2, 10, 3},
        FailCase{"G41 G02 X20. Z-5. R2.", In::Both, "E303", 1, 1, 3},
        FailCase{"G03 X20. Z-5. R2.\nG42 X22. Z-7. R2.", In::Both, "E303", 2, 1, 3},
        FailCase{"G40 G03 X20. Z-5. R2.", In::Both, "E304", 1, 1, 3},
        FailCase{"G02 X20. Z-5. R2.\nG40 X30. Z-10. R5.", In::Both, "E304", 2, 1, 3},
        FailCase{"T0404", In::Both, "E305", 1, 1, 5}, FailCase{"G04 U-1.", In::Both, "E306", 1, 5, 4},
        FailCase{"G04 P500 U1.", In::Both, "E307", 1, 10, 3}, FailCase{"G04 X1. P100", In::Both, "E307", 1, 9, 4},
        FailCase{"G04 U1. Z5.", In::Both, "E308", 1, 9, 3}, FailCase{"G28", In::Classic, "E309", 1, 1, 3},
        // warnings of the Fanuc dialect
        FailCase{"M77", In::Fanuc, "W101", 1, 1, 3}, FailCase{"N5 G28", In::Fanuc, "W102", 1, 4, 3}));

TEST(Checker, EveryDiagnosticOfTheProgramIsReportedInOrder) {
  const auto diags = checkText("G00 G01 X1. U1.\nM03 M04 Y1.\nG04\nN5 N6", Dialect::Classic);
  std::vector<std::string> got;
  for (const auto& d : diags)
    got.push_back(d.code + "@" + std::to_string(d.range.line) + ":" + std::to_string(d.range.column));
  EXPECT_THAT(got, ::testing::ElementsAre("E205@1:5", "E210@1:13", "E204@2:5", "E201@2:9", "E211@3:1", "E209@4:4"));
}

TEST(Checker, StopAtFirstErrorAnswersOnlyWhetherTheProgramIsAccepted) {
  const Program program = parse("G00 G01 X1. U1.\nM03 M04 Y1.\nG04\nN5 N6", 1);
  CheckOptions options;
  options.dialect = Dialect::Classic;
  options.stopAtFirstError = true;
  const auto first = check(program, options);
  // The first block's errors, nothing after it (the whole list is in the test above).
  ASSERT_FALSE(first.empty());
  EXPECT_TRUE(hasErrors(first));
  for (const auto& d : first) EXPECT_EQ(d.range.line, 1) << d.code;
  options.stopAtFirstError = false;
  EXPECT_GT(check(program, options).size(), first.size());
  // A clean program is checked to its end either way.
  options.stopAtFirstError = true;
  EXPECT_TRUE(check(parse("G00 X10. Z2.\nM30", 1), options).empty());
}

TEST(Checker, ANumberWithAnExponentIsNamedAsOne) {
  // X1e9 reads as X1 and E9: not "E is not a lathe word" but what was meant.
  const auto diags = checkText("G00 X1e9 Z2.\nG01 Z2.5E-3 F0.2\nG00 X20.E3", Dialect::Fanuc);
  ASSERT_EQ(diags.size(), 3u) << listing(diags);
  EXPECT_EQ(diags[0].code, "E134");
  EXPECT_EQ(diags[0].range.line, 1);
  EXPECT_EQ(diags[0].range.column, 5);
  EXPECT_EQ(diags[0].range.length, 4);  // X1e9
  EXPECT_EQ(formatMessage(diags[0], Lang::En),
            "X1E9: a G-code number has no exponent (E): write the value of X1E9 in digits with a decimal point");
  EXPECT_EQ(diags[1].code, "E134");
  EXPECT_EQ(diags[1].range.column, 5);  // Z2.5E-3
  EXPECT_EQ(diags[2].code, "E134");
  // A lone E with a space before it is still just a letter the lathe does not know.
  const auto lone = checkText("G00 X1. E9", Dialect::Fanuc);
  ASSERT_EQ(lone.size(), 1u);
  EXPECT_EQ(lone[0].code, "E201");
}

// Issue 29 item 10: #1=1e300 said "E300 cannot share a block with a macro statement".
TEST(Checker, ANumberWithAnExponentInAMacroExpressionIsNamedAsOne) {
  const auto diags = checkText("#1=1e300\n#2=[2.5E-3*2]\nG00 X[1E+3] Z2.\n#3=2.5\n", Dialect::Fanuc);
  ASSERT_EQ(diags.size(), 3u) << listing(diags);
  EXPECT_EQ(diags[0].code, "E139");
  EXPECT_EQ(diags[0].range.line, 1);
  EXPECT_EQ(diags[0].range.column, 4);
  EXPECT_EQ(formatMessage(diags[0], Lang::En),
            "1e300: a number in a macro expression has no exponent (E): write the value of 1e300 in digits with a "
            "decimal point");
  EXPECT_EQ(formatMessage(diags[0], Lang::Th),
            "1e300: ตัวเลขในนิพจน์มาโครเขียนแบบยกกำลัง (E) ไม่ได้: ให้เขียนค่าของ 1e300 เป็นตัวเลขพร้อมจุดทศนิยม");
  EXPECT_EQ(diags[1].code, "E139");
  EXPECT_EQ(diags[1].args, std::vector<std::string>{"2.5E-3"});
  EXPECT_EQ(diags[2].code, "E139");
  EXPECT_EQ(diags[2].range.line, 3);
  EXPECT_EQ(diags[2].args, std::vector<std::string>{"1E+3"});
}

TEST(Checker, MessagesNameTheWordAndSayHowToFixIt) {
  const auto diags = checkText("G01 X30. U2.", Dialect::Fanuc);
  ASSERT_EQ(diags.size(), 1u);
  EXPECT_EQ(formatMessage(diags[0], Lang::En), "X and U in one block: use X (absolute) or U (incremental), not both");
  EXPECT_EQ(formatMessage(diags[0], Lang::Th), "X และ U อยู่ในบล็อกเดียวกัน: ใช้ X (ค่าสัมบูรณ์) หรือ U (ค่าส่วนเพิ่ม) อย่างใดอย่างหนึ่ง");
  const auto range = checkText("G01 X12345.6", Dialect::Fanuc);
  ASSERT_EQ(range.size(), 1u);
  EXPECT_EQ(formatMessage(range[0], Lang::En),
            "X12345.6 is out of range: the value must be from -9999.999 to 9999.999");
}

TEST(Checker, ToolBitmapsAreNotCheckedWithoutATable) {
  EXPECT_TRUE(checkText("T0808", Dialect::Classic).empty());
  const auto diags = checkText("T0808", Dialect::Classic, std::vector<int>{1, 2, 3, 4, 5, 6, 7});
  ASSERT_EQ(diags.size(), 1u);
  EXPECT_EQ(diags[0].code, "E305");
  EXPECT_EQ(diags[0].args, (std::vector<std::string>{"T0808", "08"}));
}

TEST(Checker, FanucStartLineIsCleanButClassicSaysG99MustStandAlone) {
  const auto fanuc = checkText("G18 G21 G40 G80 G99", Dialect::Fanuc);
  EXPECT_TRUE(fanuc.empty()) << listing(fanuc);
  const auto classic = checkText("G18 G21 G40 G80 G99", Dialect::Classic);
  EXPECT_TRUE(hasErrors(classic));
  EXPECT_TRUE(std::any_of(classic.begin(), classic.end(), [](const Diagnostic& d) {
    return d.code == "E207" && d.range.column == 17 && d.severity == Severity::Error;
  })) << listing(classic);
}

TEST(Checker, OnlyG28WithoutAxesIsToldItMovesNothing) {
  // G30 is a reference return too (its own action): a bare one is not G28's W102.
  EXPECT_TRUE(checkText("G30", Dialect::Fanuc).empty()) << listing(checkText("G30", Dialect::Fanuc));
  const auto diags = checkText("G30\nG28", Dialect::Fanuc);
  ASSERT_EQ(diags.size(), 1u) << listing(diags);
  EXPECT_EQ(diags[0].code, "W102");
  EXPECT_EQ(diags[0].range.line, 2);
}

TEST(Checker, UnitsAreTrackedLeftToRightAcrossBlocks) {
  // G20 in force: 4 decimals are fine; after G21 they are not.
  const auto diags = checkText("G20\nX1.2345\nG21\nX1.2345\nG20 X1.2345", Dialect::Classic);
  ASSERT_EQ(diags.size(), 1u) << listing(diags);
  EXPECT_EQ(diags[0].code, "E111");
  EXPECT_EQ(diags[0].range.line, 4);
  EXPECT_EQ(diags[0].args, (std::vector<std::string>{"X1.2345", "3"}));
}

TEST(Checker, ReportIsCappedWithAFinalNote) {
  std::string text;
  for (int i = 0; i < 20'000; ++i) text += "Y1.\n";
  const auto diags = checkText(text, Dialect::Fanuc);
  ASSERT_EQ(diags.size(), 10'000u);
  EXPECT_EQ(diags.front().code, "E201");
  EXPECT_EQ(diags.back().code, "E199");
  EXPECT_EQ(diags.back().args, (std::vector<std::string>{"10000"}));
}

TEST(Checker, HugeNumbersAreOutOfRangeNotUndefined) {
  for (const char* text : {"G99999999999999999999", "M1e5", "T99999999999999999999", "N99999999999999999999",
                           "P99999999999999999999", "X99999999999999999999"}) {
    const auto diags = checkText(text, Dialect::Classic);
    EXPECT_TRUE(hasErrors(diags)) << text;
  }
}

}  // namespace
}  // namespace klueng::core::gcode

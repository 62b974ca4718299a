// Machine profiles (issue 8, SPEC 13, docs/dialects.md): every dialect
// difference checked in each dialect, with the exact diagnostics (code@line:col).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/dialect_fit.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/gcode/word_format.h"
#include "klueng/core/messages.h"

namespace klueng::core::gcode {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

std::vector<std::string> got(const std::string& text, Dialect dialect, CheckOptions o = {}) {
  o.dialect = dialect;
  std::vector<std::string> out;
  for (const Diagnostic& d : check(parse(text), o)) {
    out.push_back(d.code + "@" + std::to_string(d.range.line) + ":" + std::to_string(d.range.column));
    // Every message fills its placeholders in both languages.
    for (Lang lang : {Lang::En, Lang::Th}) EXPECT_EQ(formatMessage(d, lang).find('{'), std::string::npos) << d.code;
  }
  return out;
}

struct Row {
  const char* text;
  std::vector<std::string> fanuc, haas, classic;
};

std::ostream& operator<<(std::ostream& os, const Row& r) { return os << '"' << r.text << '"'; }

class EachDialect : public ::testing::TestWithParam<Row> {};

TEST_P(EachDialect, ReportsExactlyTheseDiagnostics) {
  const Row& r = GetParam();
  EXPECT_EQ(got(r.text, Dialect::Fanuc), r.fanuc) << "fanuc";
  EXPECT_EQ(got(r.text, Dialect::Haas), r.haas) << "haas";
  EXPECT_EQ(got(r.text, Dialect::Classic), r.classic) << "classic";
}

using V = std::vector<std::string>;

INSTANTIATE_TEST_SUITE_P(
    Differences, EachDialect,
    ::testing::Values(
        // 1. program and sequence numbers
        Row{"%\nO20012 (PART NAME)\nG00 X1.", {}, {}, {"E116@2:1"}}, Row{"O12345678", {}, {"E116@1:1"}, {"E116@1:1"}},
        Row{"O123456789", {"E116@1:1"}, {"E116@1:1"}, {"E116@1:1"}},
        Row{":0100\nG00 X1.", {}, {"E104@1:1"}, {"E104@1:1"}},
        Row{"G00 X1.\n:0100", {}, {"E104@2:1"}, {"E104@2:1"}},  // Fanuc: a subprogram starts
        Row{"N99999 G00", {}, {}, {"E116@1:1"}}, Row{"N100000 G00", {"E116@1:1"}, {"E116@1:1"}, {"E116@1:1"}},
        // 2. more decimals than the least increment (Haas powers on in inch: 4 decimals)
        Row{"G00 X0.42928932", {"W103@1:5"}, {"W103@1:5"}, {"E111@1:5"}},
        Row{"G21\nG00 X0.4292", {"W103@2:5"}, {"W103@2:5"}, {"E111@2:5"}},
        // 3. power-on units: inch on a Haas (4 decimals, inch ranges)
        Row{"G00 X1.2345 Z-0.0625", {"W103@1:5", "W103@1:13"}, {}, {"E111@1:5", "E111@1:13"}},
        Row{"G00 X1000.", {}, {"E110@1:5"}, {}}, Row{"G20\nG01 Z-1. F0.0008", {}, {}, {"E112@2:10"}},
        Row{"G97 S2500 M03", {}, {}, {}},  // S is not a length: no inch range
        // 4. T words
        Row{"T1212", {}, {}, {"E117@1:1"}}, Row{"T101", {}, {}, {"E117@1:1"}},
        Row{"T1312", {"E118@1:1"}, {"E118@1:1"}, {"E117@1:1"}}, Row{"T0165", {"E118@1:1"}, {"E118@1:1"}, {"E117@1:1"}},
        Row{"T1", {"E118@1:1"}, {"E118@1:1"}, {"E117@1:1"}},
        // 5. one-shot G with a motion G; G30
        Row{"G53 G00 X0", {}, {}, {"E114@1:1"}}, Row{"G00 G53 X0 Z-2.", {}, {}, {"E114@1:5"}},
        Row{"G28 G00 U0 W0", {}, {}, {"E206@1:5"}}, Row{"G30 U0. W0.", {}, {}, {"E114@1:1"}},
        Row{"G00 G30 U0. W0.", {}, {}, {"E114@1:5"}}, Row{"G04 G01 U1.", {"E206@1:5"}, {"E206@1:5"}, {"E206@1:5"}},
        Row{"G50 S2000 G00", {"E206@1:11"}, {"E206@1:11"}, {"E206@1:11"}},
        // bare G28: Fanuc moves nothing (warning), Haas homes both axes
        Row{"N5 G28", {"W102@1:4"}, {}, {"E309@1:4"}},
        // 6. Haas one-block cycles; D is not a Fanuc word
        Row{"G71 P10 Q20 U0.02 W0.005 D0.1 F0.01\nN10 G00 X1.\nN20 G01 Z-1.", {"E201@1:26"}, {}, {"E201@1:26"}},
        Row{"G72 P10 Q20 U0.02 W0.005 D0.05 F0.01\nN10 G00 X1.\nN20 G01 Z-1.", {"E201@1:26"}, {}, {"E201@1:26"}},
        Row{"G73 P10 Q20 U0.02 W0.005 I0.3 K0.1 D3 F0.01\nN10 G00 X1.\nN20 G01 Z-1.", {"E201@1:36"}, {}, {"E201@1:36"}},
        Row{"G73 P10 Q20 I0.3 K0.1 D3. F0.01\nN10 G00 X1.\nN20 G01 Z-1.", {"E201@1:23"}, {"E119@1:23"}, {"E201@1:23"}},
        Row{"G70 P10 Q20\nN10 G00 X1.\nN20 G01 Z-1.", {}, {}, {}},
        Row{"G76 X0.9 Z-1. K0.0613 D0.01 F0.0833 A60",
            {"W103@1:15", "E201@1:23", "W103@1:29", "E201@1:37"},
            {},
            {"E111@1:15", "E201@1:23", "E111@1:29", "E201@1:37"}},
        Row{"G76 X0.9 Z-1. K0.0613 D0.01 F0.0833 A60 I-0.01 P2 Q0",
            {"W103@1:15", "E201@1:23", "W103@1:29", "E201@1:37"},
            {},
            {"E111@1:15", "E201@1:23", "E111@1:29", "E201@1:37"}},
        Row{"G76 X0.9 Z-1. K0.0613 D0.01 F0.0833 A60.",
            V{"W103@1:15", "E201@1:23", "W103@1:29", "E201@1:37"},
            {"E119@1:37"},
            {"E111@1:15", "E201@1:23", "E111@1:29", "E201@1:37"}},
        Row{"G75 X1.5 Z-0.8 I0.05 K0.1 F0.004", {}, {}, {}},
        Row{"G75 X1.5 Z-0.8 I0.05 K0.1 D0.02 F0.004", {"E201@1:27"}, {}, {"E201@1:27"}},
        Row{"G75 X1.5 Z-0.8 I-0.05 F0.004", {}, {"E112@1:16"}, {}}, Row{"G74 X1. Z-0.5 K0.1 F0.005", {}, {}, {}},
        // 7. G04 P: seconds with a decimal point on a Haas
        Row{"G04 P3.", {"E119@1:5"}, {}, {"E119@1:5"}}, Row{"G04 P3000", {}, {}, {}},
        Row{"G04 P-3.", {"E119@1:5"}, {"E306@1:5"}, {"E119@1:5"}},
        // 8. drilling on centre
        Row{"G81 Z-20. R2. F0.1", {}, {}, {"E114@1:1"}},
        Row{"G83 Z-30. R-48. Q5000 F0.1", {}, {"E110@1:17"}, {"E114@1:1"}},
        // Fanuc G83 Q: least increments, or a length with its decimal point (decimal point programming)
        Row{"G83 Z-1.5 R0.1 Q0.25 F0.005", {}, {}, {"E114@1:1", "E119@1:16"}},
        Row{"G83 Z-54. Q4. R2. F0.18", {}, {}, {"E114@1:1", "E119@1:11"}},
        Row{"G83 Z-54. Q-4. R2. F0.18", {"E112@1:11"}, {"E112@1:11"}, {"E114@1:1", "E119@1:11"}},
        Row{"G83 Z-54. Q-4000 R2. F0.18", {"E119@1:11"}, {"E112@1:11"}, {"E114@1:1", "E119@1:11"}},
        Row{"G82 Z-0.1 R0.1 P0.3 F0.005", {"E114@1:1", "E119@1:16"}, {}, {"E114@1:1", "E119@1:16"}},
        Row{"G80", {}, {}, {"E114@1:1"}},
        // 9. Haas machine M codes
        Row{"M21", {"W101@1:1"}, {}, {"E115@1:1"}},
        Row{"M21 M22", {"W101@1:1", "W101@1:5"}, {"E204@1:5"}, {"E115@1:1", "E115@1:5"}},
        Row{"M88 M08", {"W101@1:1"}, {}, {"E115@1:1"}}, Row{"M86 M87", {"E204@1:5"}, {"E115@1:5"}, {"E204@1:5"}},
        Row{"M85 M86", {"W101@1:1"}, {"E204@1:5"}, {"E115@1:1"}},
        Row{"M14 M15", {"W101@1:1", "W101@1:5"}, {"E204@1:5"}, {"E115@1:1", "E115@1:5"}},
        Row{"M91", {}, {"E115@1:1"}, {}}, Row{"M97 P1000\nN1000 M99", {"W101@1:1"}, {}, {"E115@1:1"}},
        Row{"M97 P1000", {"W101@1:1"}, {"E405@1:5"}, {"E115@1:1"}},  // Haas: no N1000
        // M97 and M98 share the one P: M98 calls O1000, which is not there.
        Row{"M97 P1000 M98 P2000\nN1000 M99\nO2000\nM99",
            {"W101@1:1", "E404@1:5"},
            {"E404@1:5", "E204@1:11"},
            {"E115@1:1", "E404@1:5", "E208@3:1"}},
        Row{"M133 P2000", {"W101@1:1"}, {"W101@1:1"}, {"E115@1:1"}},
        // 11. G70-G73 profiles: the P and Q blocks exist (E413 at the word), and on a
        // Fanuc the first block holds G00 or G01 (PS0065; E414 at the N block, once).
        Row{"G71 U2. R0.5\nG71 P140 Q220 U0.4 W0.1 F0.25\nN100 G00 X40. Z0\nN220 G01 Z-30.",
            {"E413@2:5"},
            {"E413@2:5"},
            {"E413@2:5"}},
        Row{"G71 U2. R0.5\nG71 P100 Q220 U0.4 W0.1 F0.25\nN100 G00 X40. Z0\nN200 G01 Z-30.\nG70 P100 Q220",
            {"E413@2:10", "E413@5:10"},
            {"E413@2:10", "E413@5:10"},
            {"E413@2:10", "E413@5:10"}},
        Row{"G71 U2. R0.5\nG71 P100 Q200 U0.4 W0.1 F0.25\nN100\nG00 X40. Z0\nG01 Z-30.\nN200\nG70 P100 Q200",
            {"E414@3:1"},
            {},
            {"E414@3:1"}},
        Row{"G70 P100 Q200\nN100 X1.2\nN200 G01 Z-1.", {"E414@2:1"}, {}, {"E414@2:1"}},
        Row{"G70 P100 Q200\nN100 G0 X1.2\nN200 G01 Z-1.", {}, {}, {}},
        // Q before P in the program: the profile would run backwards; the message says the block is
        // there, before P's (issue 29 item 10), not that it is missing.
        Row{"G70 P200 Q100\nN100 G01 X1.\nN200 G01 Z-1.", {"E415@1:10"}, {"E415@1:10"}, {"E415@1:10"}},
        // 10. lowercase, packed words
        Row{"n1g0x380.z300.t0101m16", {"W101@1:20"}, {"E115@1:20"}, {"E115@1:20"}},
        Row{"N1G0X38.Z3.T0101M3S500", {}, {}, {}}));

TEST(Dialects, HaasMachineCodesAreKnownByName) {
  const std::string program =
      "M10\nM11\nM12\nM13\nM14\nM15\nM19 P90\nM21\nM22\nM23\nM24\nM31\nM33\nM36\nM37\nM41\nM42\n"
      "M59 P1103\nM69 P1103\nM85\nM86\nM88\nM89\nM95\nM97 P1000\nM98 P2000\nM99\nN1000 M99\nO2000\nM99";
  EXPECT_THAT(got(program, Dialect::Haas), IsEmpty());
}

TEST(Dialects, AHaasProgramIsClean) {
  const std::string program =
      "%\nO20012 (SHAFT)\nG20\nT101 (OD ROUGH)\nG50 S2000\nG96 S500 M03\nG00 X2.1 Z0.1 M08\n"
      "G71 P10 Q20 U0.02 W0.005 D0.1 F0.01\nN10 G00 X0.8\nG01 Z-1. F0.006\nX1.2 Z-1.5\nN20 X2.1\n"
      "G70 P10 Q20\nG53 G00 X0\nG28 G00 U0 W0\nM01\nT1212 (CUT OFF)\nG97 S800 M03\nG00 X2.2 Z-2.\n"
      "G75 X0.9 Z-2. I0.05 F0.003\nG04 P1.\nG53 G00 X0\nG53 Z0\nT0303 (THREAD)\nG00 X1. Z0.2\n"
      "G76 X0.9 Z-1. K0.0613 D0.01 F0.0833 A60\nT0404 (DRILL)\nG00 X0 Z0.1\nG83 Z-1.5 R0.1 Q0.25 F0.005\n"
      "G80\nM05 M09\nM30\n%";
  EXPECT_THAT(got(program, Dialect::Haas), IsEmpty());
}

TEST(Dialects, PowerOnUnitsOption) {
  CheckOptions mm;
  mm.powerOnUnits = InputUnits::Millimetre;
  EXPECT_THAT(got("G00 X1.2345", Dialect::Haas, mm), ElementsAre("W103@1:5"));
  CheckOptions inch;
  inch.powerOnUnits = InputUnits::Inch;
  EXPECT_THAT(got("G00 X1.2345", Dialect::Fanuc, inch), IsEmpty());
  // G21 still switches to mm.
  EXPECT_THAT(got("G21\nG00 X1.2345", Dialect::Haas), ElementsAre("W103@2:5"));
}

TEST(Dialects, RoundingWarningNamesTheRoundedValue) {
  const auto diags = check(parse("G01 X0.42928932 F0.2"), CheckOptions{});
  ASSERT_EQ(diags.size(), 1u);
  EXPECT_EQ(diags[0].severity, Severity::Warning);
  EXPECT_EQ(diags[0].range, (SourceRange{1, 5, 11}));
  EXPECT_EQ(formatMessage(diags[0], Lang::En), "X0.42928932 has more than 3 decimals: the control rounds it to X0.429");
  EXPECT_EQ(formatMessage(diags[0], Lang::Th), "X0.42928932 มีทศนิยมเกิน 3 ตำแหน่ง: เครื่องจะปัดค่าเป็น X0.429");
  EXPECT_FALSE(hasErrors(diags));
}

// "X30. K-2." and "Z-20. R3." (the 90-degree chamfer and round without the comma): a Fanuc T
// series reads them (B-63944EN-1/02 §4.5, parameter 3405#4 CCR = 0), Haas reads I or K as ,C (its
// manual: "for chamfering a 90 degree angle only") but not R: a warning at the word says how to
// write it, instead of a corner silently left sharp. Arcs and cycles keep their I/K/R, and ",R" is
// no warning.
TEST(Dialects, CornerWordsWithoutTheCommaAreNamed) {
  const std::string text =
      "G99 G01 X30. K-2. F0.2\nZ-20. R3.\nX40. ,R2.\nZ-30.\nG02 X44. Z-32. R2.\nG01 X50.\nG90 X46. Z-40. R-1. F0.2\n";
  CheckOptions fanuc;
  EXPECT_TRUE(check(parse(text), fanuc).empty());
  CheckOptions haas;
  haas.dialect = gcode::Dialect::Haas;
  const auto h = check(parse(text), haas);
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h[0].code, "W107");
  EXPECT_EQ(h[0].severity, Severity::Warning);
  EXPECT_EQ(h[0].range, (SourceRange{2, 7, 3}));
  EXPECT_EQ(formatMessage(h[0], Lang::En),
            "R3. on a G01 is not read: a chamfer or corner round is written with a comma (,R3.), so the corner stays "
            "sharp");
  EXPECT_EQ(formatMessage(h[0], Lang::Th),
            "R3. ในบล็อก G01 ไม่ถูกอ่าน การลบมุมหรือการมนมุมต้องเขียนโดยมีจุลภาคนำหน้า (,R3.) มุมจึงยังคงเป็นมุมแหลม");
}

TEST(Dialects, ToolRangeComesFromTheTurret) {
  CheckOptions eight;
  eight.turretStations = 8;
  EXPECT_THAT(got("T1212", Dialect::Fanuc, eight), ElementsAre("E118@1:1"));
  EXPECT_THAT(got("T0808", Dialect::Fanuc, eight), IsEmpty());
  const auto diags = check(parse("T1312"), CheckOptions{});
  ASSERT_EQ(diags.size(), 1u);
  EXPECT_EQ(formatMessage(diags[0], Lang::En), "T1312: write T as tool 01-12 then offset 00-64, e.g. T0101 (or T101)");
  // Classic keeps the seed's E117 text.
  CheckOptions classic;
  classic.dialect = Dialect::Classic;
  const auto c = check(parse("T1212"), classic);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(formatMessage(c[0], Lang::En), "T1212: write T with 4 digits, tool 01-08 then offset 00-16 (e.g. T0101)");
}

TEST(Dialects, ClassicMessagesKeepTheSeedText) {
  CheckOptions classic;
  classic.dialect = Dialect::Classic;
  const auto n = check(parse("N10000"), classic);
  ASSERT_EQ(n.size(), 1u);
  EXPECT_EQ(formatMessage(n[0], Lang::En), "N10000: N must be a whole number from 1 to 9999");
  const auto y = check(parse("Y1."), classic);
  ASSERT_EQ(y.size(), 1u);
  EXPECT_EQ(formatMessage(y[0], Lang::En),
            "Y1.: letter Y is not a lathe word; use C F G H I K M N O P Q R S T U W X Z");
  const auto f = check(parse("F0"), classic);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(formatMessage(f[0], Lang::En), "F0: F must be positive (0.001 to 9999.999)");
  const auto x = check(parse("G20\nX12345.6"), classic);
  ASSERT_EQ(x.size(), 1u);
  EXPECT_EQ(formatMessage(x[0], Lang::En), "X12345.6 is out of range: the value must be from -9999.999 to 9999.999");
}

TEST(Dialects, HaasMessagesNameItsLettersAndInchRanges) {
  CheckOptions haas;
  haas.dialect = Dialect::Haas;
  const auto y = check(parse("Y1."), haas);
  ASSERT_EQ(y.size(), 1u);
  EXPECT_EQ(formatMessage(y[0], Lang::En),
            "Y1.: letter Y is not a lathe word; use A C D E F G H I J K L M N O P Q R S T U W X Z");
  const auto f = check(parse("F0"), haas);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(formatMessage(f[0], Lang::En), "F0: F must be positive (0.0001 to 999.9999)");
}

TEST(CodeTable, CodesCarryTheirWordKinds) {
  EXPECT_EQ(findCode('G', 83, Dialect::Haas)->words.of('Q'), WordKind::Positive);
  EXPECT_EQ(findCode('G', 83, Dialect::Fanuc)->words.of('Q'), WordKind::Increment);
  EXPECT_EQ(findCode('G', 76, Dialect::Haas)->words.of('K'), WordKind::Positive);
  EXPECT_EQ(findCode('G', 73, Dialect::Haas)->words.of('D'), WordKind::Whole);
  EXPECT_EQ(findCode('G', 4, Dialect::Classic)->words.of('P'), WordKind::Dwell);
  EXPECT_EQ(findCode('G', 71, Dialect::Fanuc)->words.of('D'), WordKind::Default);
  EXPECT_EQ(findCode('G', 71, Dialect::Haas)->words.of('U'), WordKind::Length);
  EXPECT_FALSE(findCode('G', 71, Dialect::Fanuc)->words.any());
  EXPECT_EQ(findCode('M', 86, Dialect::Haas)->group, ModalGroup::MDoor);
  EXPECT_EQ(findCode('M', 86, Dialect::Fanuc)->group, ModalGroup::MBrake);
  EXPECT_EQ(findCode('M', 14, Dialect::Haas)->group, ModalGroup::MBrake);
  EXPECT_EQ(findCode('M', 97, Dialect::Haas)->group, ModalGroup::MSubprogram);
  EXPECT_EQ(findCode('G', 30, Dialect::Classic), nullptr);
  EXPECT_EQ(findCode('G', 82, Dialect::Fanuc), nullptr);
}

TEST(WordFormat, RoundsHalfAwayFromZeroToTheIncrement) {
  const MachineProfile& fanuc = machineProfile(Dialect::Fanuc);
  EXPECT_DOUBLE_EQ(roundToIncrement(0.42928932, fanuc, InputUnits::Millimetre), 0.429);
  EXPECT_DOUBLE_EQ(roundToIncrement(0.42928932, fanuc, InputUnits::Inch), 0.4293);
  EXPECT_DOUBLE_EQ(roundToIncrement(1.2345, fanuc, InputUnits::Millimetre), 1.235);
  EXPECT_DOUBLE_EQ(roundToIncrement(-0.0005, fanuc, InputUnits::Millimetre), -0.001);
  EXPECT_DOUBLE_EQ(roundToIncrement(-12.3454, fanuc, InputUnits::Millimetre), -12.345);
  EXPECT_DOUBLE_EQ(roundToIncrement(25.4, fanuc, InputUnits::Millimetre), 25.4);
  EXPECT_EQ(incrementDecimals(fanuc, InputUnits::Inch), 4);
  EXPECT_EQ(formatFixed(-0.0001, 3), "0.000");
  EXPECT_EQ(formatFixed(0.4293, 4), "0.4293");
}

TEST(Lexer, ColonProgramNumberIsAnOWordThatRemembersItsColon) {
  const Program p = parse(":0100 (PART)\nG00 X1.");
  ASSERT_TRUE(p.lexicalDiagnostics.empty());
  ASSERT_EQ(p.blocks.size(), 2u);
  const Word& o = p.blocks[0].words.at(0);
  EXPECT_EQ(o.letter, 'O');
  EXPECT_TRUE(o.colon);
  EXPECT_EQ(o.number, "0100");
  EXPECT_EQ(o.code(), 100);
  EXPECT_EQ(o.text(), ":0100");
  EXPECT_EQ(o.range, (SourceRange{1, 1, 5}));
  EXPECT_EQ(p.blocks[0].comment(), "PART");
  // A ':' without digits stays an unknown character.
  const Program bad = parse("G00 : X1.");
  ASSERT_EQ(bad.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(bad.lexicalDiagnostics[0].code, "E104");
  EXPECT_EQ(bad.lexicalDiagnostics[0].range, (SourceRange{1, 5, 1}));
}

TEST(Lexer, LowercasePackedWords) {
  const Program p = parse("n1g0x380.z300.t0101m16\nN2G01X-.5Z-3.F.2");
  ASSERT_TRUE(p.lexicalDiagnostics.empty());
  ASSERT_EQ(p.blocks.size(), 2u);
  std::vector<std::string> words;
  for (const Block& b : p.blocks)
    for (const Word& w : b.words) words.push_back(w.text() + "@" + std::to_string(w.range.column));
  EXPECT_THAT(words, ElementsAre("N1@1", "G0@3", "X380.@5", "Z300.@10", "T0101@15", "M16@20", "N2@1", "G01@3", "X-.5@6",
                                 "Z-3.@10", "F.2@14"));
  EXPECT_DOUBLE_EQ(p.blocks[1].words[2].value, -0.5);
  EXPECT_DOUBLE_EQ(p.blocks[1].words[4].value, 0.2);
}

// ---- say which dialect fits -------------------------------------------------

const char* kHaasStyle =
    "%\nO20012 (PART)\nG20\nT0101\nG71 P10 Q20 U0.02 W0.005 D0.1 F0.01\nN10 G00 X1.\nN20 G01 Z-1.\n"
    "G70 P10 Q20\nG04 P3.\nM30\n%";

TEST(DialectFit, NamesTheDialectThatAcceptsTheProgram) {
  const Program program = parse(kHaasStyle);
  CheckOptions fanuc;
  const auto diags = check(program, fanuc);
  ASSERT_TRUE(hasErrors(diags));
  const auto fit = suggestDialect(program, fanuc, diags);
  ASSERT_TRUE(fit.has_value());
  EXPECT_EQ(fit->dialect, Dialect::Haas);
  EXPECT_EQ(fit->blocks, 2);
  EXPECT_EQ(fit->note.code, "I102");
  EXPECT_EQ(fit->note.severity, Severity::Note);
  EXPECT_EQ(fit->note.range, (SourceRange{5, 1, 0}));
  EXPECT_EQ(formatMessage(fit->note, Lang::En),
            "blocks with errors or warnings that are Haas ST (NGC) forms: 2; choose the Haas ST (NGC) dialect "
            "(--dialect haas)");
  EXPECT_EQ(formatMessage(fit->note, Lang::Th),
            "บล็อกที่ผิดพลาดหรือมีคำเตือน 2 บล็อกเป็นรูปแบบของ Haas ST (NGC): เลือกรูปแบบคำสั่ง Haas ST (NGC) (--dialect haas)");
}

TEST(DialectFit, ClassicProgramWithFanucCodesPointsToFanuc) {
  const Program program = parse("G18 G21 G40 G80 G99\nG53 X0.");
  CheckOptions classic;
  classic.dialect = Dialect::Classic;
  const auto fit = suggestDialect(program, classic, check(program, classic));
  ASSERT_TRUE(fit.has_value());
  EXPECT_EQ(fit->dialect, Dialect::Fanuc);
  EXPECT_EQ(fit->blocks, 2);
}

TEST(DialectFit, NothingWhenCleanOrWhenNoDialectAccepts) {
  const Program clean = parse("G00 X1.");
  EXPECT_FALSE(suggestDialect(clean, {}, check(clean, {})).has_value());
  const Program bad = parse("G00 Y1.");
  EXPECT_FALSE(suggestDialect(bad, {}, check(bad, {})).has_value());
  const Program lexical = parse("G00 X");
  EXPECT_FALSE(suggestDialect(lexical, {}, check(lexical, {})).has_value());
}

}  // namespace
}  // namespace klueng::core::gcode

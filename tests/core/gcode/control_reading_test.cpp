// How real controls read what real programs write (issue 38): an error only where the control
// stops. Safety lines with a bare G90 and a mill's G49, the leader before the first '%', T00 in a
// homing line, the angle without its comma, ';' and ')' as a Fanuc reads them, and the cycle rules
// the control checks (a shape holding its own cycle, roughing at feed zero). Each program is
// written in the habits of the shop programs the issue names (Doosan and Russian safety lines,
// Brazilian ';' comments, a Chinese label line).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/dialect_fit.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/parser.h"

namespace klueng::core::gcode {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

// "CODE line:column" of each diagnostic, in order.
std::vector<std::string> placesOf(const std::vector<Diagnostic>& diags) {
  std::vector<std::string> out;
  for (const Diagnostic& d : diags)
    out.push_back(d.code + " " + std::to_string(d.range.line) + ":" + std::to_string(d.range.column));
  return out;
}

std::vector<Diagnostic> readOn(const std::string& text, Dialect dialect = Dialect::Fanuc) {
  CheckOptions o;
  o.dialect = dialect;
  return check(parse(text), o);
}

std::vector<std::string> errorsOn(const std::string& text, Dialect dialect = Dialect::Fanuc) {
  std::vector<Diagnostic> errors;
  for (const Diagnostic& d : readOn(text, dialect))
    if (d.severity == Severity::Error) errors.push_back(d);
  return placesOf(errors);
}

// An American production shop's inch op: the safety line before every tool.
const char* const kDoosanStyle =
    "%\n"
    "O2201(CAP 2.00 OD)\n"
    "G18G20G40G80G90G99\n"
    "T0101G54\n"
    "G50S3000\n"
    "G96S600M03\n"
    "G00X2.1Z.05\n"
    "G01X-.03F.005\n"
    "G00Z.1\n"
    "M30\n"
    "%\n";

TEST(SafetyLine, ABareG90MovesNothingAndIsAWarningNotAnError) {
  const std::vector<Diagnostic> d = readOn(kDoosanStyle);
  EXPECT_THAT(placesOf(d), ElementsAre("W112 3:13"));
  EXPECT_EQ(d[0].severity, Severity::Warning);
  // A system-A safety line is no sign of system B: nothing is offered.
  CheckOptions o;
  o.dialect = Dialect::Fanuc;
  EXPECT_FALSE(suggestDialect(parse(kDoosanStyle), o, d).has_value());
}

TEST(SafetyLine, TheMillsG49IsReadAndDoesNothing) {
  const std::string russian = "G21G40G49G54G80G90\nT0808\nG97S1200M03\nG0Z10.X12.\nM30\n";
  EXPECT_THAT(errorsOn(russian), IsEmpty());
  EXPECT_THAT(placesOf(readOn(russian)), ElementsAre("W112 1:16"));
}

TEST(SafetyLine, G92WithOnlySInSystemAIsAWarningAndTheSystemBOffer) {
  const std::string brazil = "O0001\nG21 G40\nG92 S2500\nT0101\nG96 S200 M4\nG0 X40 Z2\nG1 X36 F0.2\nM30\n";
  const std::vector<Diagnostic> d = readOn(brazil);
  EXPECT_THAT(placesOf(d), ElementsAre("W115 3:1"));
  CheckOptions o;
  o.dialect = Dialect::Fanuc;
  const auto fit = suggestDialect(parse(brazil), o, d);
  ASSERT_TRUE(fit.has_value());
  EXPECT_EQ(machineProfile(fit->dialect).system, GcodeSystem::B);
  EXPECT_EQ(fit->note.severity, Severity::Note);
  EXPECT_EQ(fit->note.range.line, 3);
}

TEST(Offer, AHaasLocalCallIsAHaasProgramButABuildersMCodeIsNot) {
  const std::string local =
      "%\nO01234\nG20\nT101\nG97 S1000 M03\nG00 X1.1 Z0.1\nM97 P100 L2\nG28\nM30\n"
      "N100 G01 Z-0.5 F0.01\nG00 X1.2\nZ0.1\nM99\n%\n";
  const std::vector<Diagnostic> d = readOn(local);
  EXPECT_THAT(placesOf(d), ElementsAre("W101 7:1", "W102 8:1"));
  CheckOptions o;
  o.dialect = Dialect::Fanuc;
  const auto fit = suggestDialect(parse(local), o, d);
  ASSERT_TRUE(fit.has_value());
  EXPECT_EQ(fit->dialect, Dialect::Haas);
  EXPECT_EQ(fit->note.range.line, 7);
  // M31 (chip conveyor) is a builder's code on a Fanuc and Haas's own: no sign of the control.
  const std::string conveyor = "O0001\nG21\nT0101\nM31\nG97 S800 M03\nG00 X40. Z2.\nG01 Z-10. F0.2\nM30\n";
  const std::vector<Diagnostic> c = readOn(conveyor);
  EXPECT_THAT(placesOf(c), ElementsAre("W101 4:1"));
  EXPECT_FALSE(suggestDialect(parse(conveyor), o, c).has_value());
}

TEST(ProgramNumber, ACamPostsO0000IsAWarningWhereNoManualSaysTheControlStops) {
  const std::string mastercam = "%\nO0000(SHAFT - T)\nG21\nG0 T0101\nG97 S1000 M03\nG0 X52. Z2.\nM30\n%\n";
  EXPECT_THAT(placesOf(readOn(mastercam)), ElementsAre("W117 2:1"));
  EXPECT_THAT(placesOf(readOn(mastercam, Dialect::Haas)), ElementsAre("W117 2:1"));
  EXPECT_THAT(placesOf(readOn(mastercam, Dialect::Classic)), ElementsAre("E116 2:1"));
}

TEST(Leader, TheLabelBeforeTheFirstPercentIsSkippedWithANote) {
  const Program p = parse("法兰盘 6061\n%\nO0815\nG00 X40. Z2.\nM30\n%\n");
  EXPECT_THAT(placesOf(p.lexicalDiagnostics), ElementsAre("I105 1:1"));
  EXPECT_EQ(p.lexicalDiagnostics[0].severity, Severity::Note);
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_EQ(p.blocks[0].line, 3);
  EXPECT_EQ(p.blocks[1].line, 4);
  EXPECT_THAT(errorsOn("PART 7-A TITLE\n\n%\nO0001\nG00 X10.\nM30\n%\n"), IsEmpty());
}

TEST(Leader, APercentThatOnlyEndsTheFileLeavesTheProgramAsItIs) {
  const Program p = parse("O0001\nG00 X10.\nM30\n%\n");
  EXPECT_THAT(p.lexicalDiagnostics, IsEmpty());
  EXPECT_EQ(p.blocks.size(), 3u);
  // Without a '%' line after it, a text line is still the error it was.
  EXPECT_THAT(errorsOn("ROUGHING PASS\nG00 X10.\nM30\n"), ElementsAre("E138 1:1"));
}

TEST(ToolZero, T0AndT00CancelTheOffsetInAHomingLine) {
  EXPECT_THAT(errorsOn("N10 G53 G00 X100 Z150 T00\nN20 T0101\nN30 G53 X100 Z150 T0\nN40 T0000\n"), IsEmpty());
  EXPECT_THAT(errorsOn("T0017\n"), ElementsAre("E118 1:1"));
  // The 1999 trainer wants four digits, tool 01-08.
  EXPECT_THAT(errorsOn("T00\n", Dialect::Classic), ElementsAre("E117 1:1"));
}

TEST(AngleWithoutComma, OfferedAsANoteWhereTheMachineHasNoAAxis) {
  const std::vector<Diagnostic> d = readOn("G01 X40. A-45. F0.1\n");
  EXPECT_THAT(placesOf(d), ElementsAre("E201 1:10", "I106 1:10"));
  EXPECT_EQ(d[1].severity, Severity::Note);
}

TEST(AngleWithoutComma, AMachineThatReadsItTakesAAsTheCommaAngle) {
  Program p = parse("G00 X20. Z2.\nG01 Z0. F0.1\nG01 X40. A-45.\nZ-30.\n");
  readAnglesWithoutComma(p);
  ASSERT_NE(p.blocks[2].findComma('A'), nullptr);
  EXPECT_DOUBLE_EQ(p.blocks[2].findComma('A')->value, -45.0);
  CheckOptions o;
  o.dialect = Dialect::Fanuc;
  EXPECT_FALSE(hasErrors(check(p, o)));
}

TEST(EndOfBlock, TextAfterTheSemicolonStopsAFanuc) {
  const std::string line = "T0505 ;bedame de 3mm\n";
  EXPECT_THAT(errorsOn(line), ElementsAre("E141 1:8"));
  // Haas and the classic trainer read the rest of the line as a comment.
  EXPECT_THAT(errorsOn(line, Dialect::Haas), IsEmpty());
  EXPECT_THAT(errorsOn(line, Dialect::Classic), IsEmpty());
}

TEST(EndOfBlock, ACommentOrNothingAfterTheSemicolonIsFine) {
  EXPECT_THAT(placesOf(readOn("N60 T0202; (Ferramenta de desbaste)\nN135;\nG00 X10.;;\n")), IsEmpty());
}

TEST(EndOfBlock, WordsAfterTheSemicolonAreAWarningThatTheyRun) {
  EXPECT_THAT(placesOf(readOn("G00 X20. ; Z5.\n")), ElementsAre("W114 1:11"));
}

TEST(CommentEnd, AFanucCommentEndsAtItsFirstCloseParenthesis) {
  const std::string macro = "(USES MAX(#100,#112) AS FLOOR)\nG00 X10.\n";
  EXPECT_THAT(errorsOn(macro), ElementsAre("E142 1:21"));
  EXPECT_THAT(errorsOn(macro, Dialect::Haas), IsEmpty());
  // Only a ')' (or signs) after it: the control reads on, a warning.
  EXPECT_THAT(placesOf(readOn("(ROUGH (T01) )\n(--- WAIT (CLEAR #503) ---)\n")), ElementsAre("W113 1:13", "W113 2:23"));
}

TEST(CycleRules, AShapeThatHoldsItsOwnCycleStopsTheControl) {
  const std::string held =
      "G99\nT0101\nG00 X42. Z2.\nN10 G00 X20.\nG71 U1. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nG01 Z-20. F0.1\nN20 X42.\n"
      "M30\n";
  EXPECT_THAT(errorsOn(held), ElementsAre("E417 6:1"));
}

TEST(CycleRules, RoughingAtFeedZeroStopsTheControl) {
  const std::string lab =
      "G21 G98\nT0101\nM03 S1000\nG0 X32 Z2\nG71 U1 R1\nG71 P100 Q200 U0.4 W0.1\nN100 G0 X10\nG01 Z-15\nN200 X32\n"
      "G70 P100 Q200\nM30\n";
  EXPECT_THAT(errorsOn(lab), ElementsAre("E418 6:1"));
  // An F given before, or in the cycle's own block, is the feed.
  std::string fed = lab;
  fed.replace(fed.find("M03 S1000"), 9, "M03 S1000 F150.");
  EXPECT_THAT(errorsOn(fed), IsEmpty());
  std::string own = lab;
  own.replace(own.find("W0.1\n"), 5, "W0.1 F200.\n");
  EXPECT_THAT(errorsOn(own), IsEmpty());
}

// Codes the control has that change nothing Klueng draws (stroke check, spindle speed detection,
// exact stop, double-turret mirror off, AI contour control): read, no diagnostic. A Fanuc 0i-TF
// job shop's safety line and a Haas NGC post's preamble, as they write them.
TEST(ControlCodes, MachineFunctionsOfTheSafetyLineAreReadAndChangeNothing) {
  const std::string fanuc =
      "%\nO3105(SPACER)\nG40G97G99G23G25G69\nG05.1Q0\nT0101\nG13.1\nG61\nG96S180M03\nG50S2500\nG00X52.Z2.\n"
      "G09G01X50.F.15\nG64\nG22\nM30\n%\n";
  EXPECT_THAT(placesOf(readOn(fanuc)), IsEmpty());
  const std::string haas =
      "%\nO01234 (BUSHING)\nG103 P1\nG187 P1\nG15 G113\nG154 P1\nG20 G40 G99\nT101\nG50 S2000\nG96 S600 M03\n"
      "G00 X1.2 Z0.1\nG61\nG09 G01 X1.1 F0.006\nG64\nM30\n%\n";
  EXPECT_THAT(placesOf(readOn(haas, Dialect::Haas)), IsEmpty());
}

// A code of the control that Klueng does not simulate is no "not a G code of this lathe" (E113,
// E114): a warning at the check, and the run stops at it (A117, Klueng's own limit).
TEST(ControlCodes, CodesKluengDoesNotSimulateAreAWarningNotAnError) {
  const std::string polar = "G21 G99\nT0101\nG00 X40. Z2.\nG12.1\nG01 X20. C10. F0.1\nG13.1\nM30\n";
  EXPECT_THAT(placesOf(readOn(polar)), ElementsAre("W119 4:1"));
  EXPECT_THAT(placesOf(readOn("G21\nG68\nG00 X40.\nG69\nM30\n")), ElementsAre("W119 2:1"));
  EXPECT_THAT(placesOf(readOn("G20\nG112\nG113\nM30\n", Dialect::Haas)), ElementsAre("W119 2:1"));
  // A point in a number that is no code of this control stays E113; a number none has, E114.
  EXPECT_THAT(errorsOn("G21\nG12.5\nM30\n"), ElementsAre("E113 2:1"));
  EXPECT_THAT(errorsOn("G21\nG12.1\nM30\n", Dialect::Haas), ElementsAre("E113 2:1"));
  EXPECT_THAT(errorsOn("G21\nG48\nM30\n"), ElementsAre("E114 2:1"));
  EXPECT_THAT(errorsOn("G21\nG103 P1\nM30\n"), ElementsAre("E114 2:1"));  // Haas's, not the 0i-TF's
}

// The §10 audit: errors of the classic rules that no Fanuc or Haas manual or alarm list makes a stop
// are warnings there (machine key error_codes_as_warnings), and stay errors in the classic rules.
TEST(Audit, ErrorsNoManualMakesAStopAreWarningsOnFanucAndHaas) {
  struct Case {
    const char* text;
    const char* place;  // code line:column
    bool haasKeepsIt;
  };
  const Case cases[] = {
      {"G21 G99\nG00 X40. Z2.\nG01 X30. /Z-5. F0.2\n", "E106 3:10", false},
      {"%PART 7\nG21\nG00 X40.\n", "E108 1:2", false},
      {"G21\nM03 S0\nG00 X40.\n", "E143 2:5", false},
      {"G21 G99\nG00 X40. Z2.\nG50 G00 X40. Z2.\n", "E206 3:5", false},
      {"G21\nG00 N20 X40.\n", "E209 2:5", false},
      {"G21 G99\nG00 X40. Z2.\nG01 X30. U-2. F0.2\n", "E210 3:10", false},
      {"G21 G99\nG00 X40. Z2.\nG02 R5. F0.2\n", "E301 3:1", false},
      {"G21 G99\nG00 X40. Z2.\nG02 X30. Z-3. R5. K-5. F0.2\n", "E302 3:15", false},
      {"G21 G99\nG00 X40. Z2.\nG04\n", "E211 3:1", true},
      {"G21 G99\nG00 X40. X42. Z2.\n", "E202 2:10", true},
  };
  for (const Case& c : cases) {
    const std::vector<Diagnostic> classic = readOn(c.text, Dialect::Classic);
    EXPECT_THAT(placesOf(classic), ::testing::Contains(c.place)) << c.text;
    for (const Dialect d : {Dialect::Fanuc, Dialect::Haas}) {
      const std::vector<Diagnostic> read = readOn(c.text, d);
      bool found = false;
      for (const Diagnostic& diag : read) {
        if (placesOf({diag}).front() != c.place) continue;
        found = true;
        const bool error = d == Dialect::Haas && c.haasKeepsIt;
        EXPECT_EQ(diag.severity, error ? Severity::Error : Severity::Warning) << c.text << " " << c.place;
      }
      EXPECT_TRUE(found) << c.text << " " << c.place << " on " << static_cast<int>(d);
    }
  }
}

}  // namespace
}  // namespace klueng::core::gcode

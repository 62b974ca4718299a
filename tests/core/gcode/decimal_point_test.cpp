// Decimal point input (issue 26 item 6): which length words a standard control
// reads in least input increments, and what a program's numbers say.
#include "klueng/core/gcode/decimal_point.h"

#include <gtest/gtest.h>

#include "klueng/core/gcode/machine_file.h"
#include "klueng/core/gcode/parser.h"

namespace klueng::core::gcode {
namespace {

const Word& wordAt(const Program& p, std::size_t block, char letter) {
  const Word* w = p.blocks.at(block).find(letter);
  EXPECT_NE(w, nullptr) << "block " << block << " has no " << letter;
  static const Word none;
  return w ? *w : none;
}

TEST(DecimalPoint, IncrementsFollowTheUnitsInForceAtEachBlock) {
  Program p = parse(
      "G21 G00 X30000 Z2000 U-500 W250\n"
      "G02 X40. Z-5 R5000\n"
      "G20 G01 X1250 Z-.5 I25 K-5\n"
      "G04 X1500\n");
  readLengthsInIncrements(p, InputUnits::Millimetre, Dialect::Fanuc);
  EXPECT_DOUBLE_EQ(wordAt(p, 0, 'X').value, 30.0);
  EXPECT_DOUBLE_EQ(wordAt(p, 0, 'Z').value, 2.0);
  EXPECT_DOUBLE_EQ(wordAt(p, 0, 'U').value, -0.5);
  EXPECT_DOUBLE_EQ(wordAt(p, 0, 'W').value, 0.25);
  EXPECT_DOUBLE_EQ(wordAt(p, 1, 'X').value, 40.0);  // a point: as written
  EXPECT_DOUBLE_EQ(wordAt(p, 1, 'Z').value, -0.005);
  EXPECT_DOUBLE_EQ(wordAt(p, 1, 'R').value, 5.0);
  EXPECT_DOUBLE_EQ(wordAt(p, 2, 'X').value, 0.125);  // G20 from its own block on: 0.0001 in
  EXPECT_DOUBLE_EQ(wordAt(p, 2, 'Z').value, -0.5);
  EXPECT_DOUBLE_EQ(wordAt(p, 2, 'I').value, 0.0025);
  EXPECT_DOUBLE_EQ(wordAt(p, 2, 'K').value, -0.0005);
  EXPECT_DOUBLE_EQ(wordAt(p, 3, 'X').value, 1.5);  // a dwell's X is a time: 0.001 s under G20 too
}

TEST(DecimalPoint, CodesCountsFeedsExpressionsAndMacroArgumentsKeepTheirValues) {
  Program p = parse(
      "G73 U3000 W1000 R3\n"
      "G73 P10 Q20 U500 W100 F25\n"
      "G76 P021060 Q50 R50\n"
      "G65 P9010 X25 Z-40\n"
      "#1 = 30\n"
      "G01 X#1 Z-[#1] F2\n"
      "S1200 M03 T0101\n");
  readLengthsInIncrements(p, InputUnits::Millimetre, Dialect::Fanuc);
  EXPECT_DOUBLE_EQ(wordAt(p, 0, 'U').value, 3.0);
  EXPECT_DOUBLE_EQ(wordAt(p, 0, 'R').value, 3.0);  // G73's first block: R is the number of passes
  EXPECT_DOUBLE_EQ(wordAt(p, 1, 'P').value, 10.0);
  EXPECT_DOUBLE_EQ(wordAt(p, 1, 'U').value, 0.5);
  EXPECT_DOUBLE_EQ(wordAt(p, 1, 'F').value, 25.0);  // a feed keeps its own rule
  EXPECT_DOUBLE_EQ(wordAt(p, 2, 'P').value, 21060.0);
  EXPECT_DOUBLE_EQ(wordAt(p, 2, 'Q').value, 50.0);  // the cycle reads Q in increments itself
  EXPECT_DOUBLE_EQ(wordAt(p, 2, 'R').value, 0.05);
  EXPECT_DOUBLE_EQ(wordAt(p, 3, 'X').value, 25.0);  // G65 arguments are passed as written
  EXPECT_DOUBLE_EQ(wordAt(p, 3, 'Z').value, -40.0);
  EXPECT_GE(wordAt(p, 5, 'X').expr, 0);
  EXPECT_DOUBLE_EQ(wordAt(p, 6, 'S').value, 1200.0);
  EXPECT_DOUBLE_EQ(wordAt(p, 6, 'T').value, 101.0);
}

TEST(DecimalPoint, EvidenceNamesTheWordsOnlyOneReadingMakesSenseOf) {
  // A shop's habit: cycle words in increments, positions with a point.
  const Program shop = parse(
      "G20\n"
      "G00 X1.85 Z.1\n"
      "G71 U1250 R50\n"
      "G71 P10 Q20 U.02 W.005 F.012\n"
      "N10 G00 X1.0\n"
      "N20 X1.85\n");
  const PointEvidence e = weighDecimalPoints(shop, InputUnits::Millimetre, Dialect::Fanuc);
  ASSERT_EQ(e.forIncrements.size(), 2u);
  EXPECT_EQ(e.forIncrements[0].word, "U1250");
  EXPECT_EQ(e.forIncrements[0].range, (SourceRange{3, 5, 5}));
  EXPECT_TRUE(e.forIncrements[0].inch);
  EXPECT_NEAR(e.forIncrements[0].incrementMm, 3.175, 1e-9);
  EXPECT_EQ(e.forIncrements[1].word, "R50");
  EXPECT_TRUE(e.forWholeUnits.empty());

  // A student's habit: whole numbers everywhere; zero and plausible-both-ways words are no clue.
  const Program student = parse(
      "G21 G00 X52 Z2\n"
      "G71 U1 R1\n"
      "G71 P10 Q20 U0.5 W0.1 F0.2\n"
      "N10 G00 X0\n"
      "G01 Z0 X300\n"
      "N20 X200 Z-150\n");
  const PointEvidence s = weighDecimalPoints(student, InputUnits::Millimetre, Dialect::Fanuc);
  EXPECT_TRUE(s.forIncrements.empty());
  ASSERT_EQ(s.forWholeUnits.size(), 4u);
  EXPECT_EQ(s.forWholeUnits[0].word, "X52");
  EXPECT_EQ(s.forWholeUnits[1].word, "Z2");
  EXPECT_EQ(s.forWholeUnits[2].word, "U1");
  EXPECT_EQ(s.forWholeUnits[3].word, "R1");
}

TEST(DecimalPoint, WarningsGiveTheOtherReadingAndTheWordToWrite) {
  const Program p = parse("G21 G00 X60 Z5.\nG71 U2000 R500\n");
  const PointEvidence e = weighDecimalPoints(p, InputUnits::Millimetre, Dialect::Fanuc);
  const std::vector<Diagnostic> inc = decimalPointWarnings(e, true);
  ASSERT_EQ(inc.size(), 1u);
  EXPECT_EQ(inc[0].code, "W110");
  EXPECT_EQ(inc[0].severity, Severity::Warning);
  EXPECT_EQ(inc[0].range, (SourceRange{1, 9, 3}));
  EXPECT_EQ(inc[0].args, (std::vector<std::string>{"X60", "0.060 mm", "X60.", "60 mm"}));
  const std::vector<Diagnostic> whole = decimalPointWarnings(e, false);
  ASSERT_EQ(whole.size(), 2u);
  EXPECT_EQ(whole[0].code, "W111");
  EXPECT_EQ(whole[0].args, (std::vector<std::string>{"U2000", "2000 mm", "2.000 mm", "U2.000"}));
  EXPECT_EQ(whole[1].args, (std::vector<std::string>{"R500", "500 mm", "0.500 mm", "R0.500"}));
}

// Issue 27: in G-code system C the units are G70/G71 and the cycles G72-G78, so the
// same program reads its pointless lengths as system A reads G20/G21 and G70-G76.
TEST(DecimalPoint, SystemCFindsUnitsAndCyclesByTheirActions) {
  const MachineFileRead read =
      parseMachineFile("base = fanuc\nid = decimal-point-system-c\ngcode_system = C\n", "c.machine");
  ASSERT_TRUE(read.machine.has_value());
  const Dialect c = registerMachine(*read.machine);
  Program p = parse(
      "G70 G00 X1250 Z500\n"  // inch in system C: 0.0001 in
      "G71 G00 X30000\n"      // metric: 0.001 mm
      "G75 U3000 W1000 R3\n"  // system C's G73 pattern repeating: R the passes
      "G73 U1500 R500\n");    // system C's G71 stock removal, first block
  readLengthsInIncrements(p, InputUnits::Millimetre, c);
  EXPECT_DOUBLE_EQ(wordAt(p, 0, 'X').value, 0.125);
  EXPECT_DOUBLE_EQ(wordAt(p, 0, 'Z').value, 0.05);
  EXPECT_DOUBLE_EQ(wordAt(p, 1, 'X').value, 30.0);
  EXPECT_DOUBLE_EQ(wordAt(p, 2, 'U').value, 3.0);
  EXPECT_DOUBLE_EQ(wordAt(p, 2, 'R').value, 3.0);
  EXPECT_DOUBLE_EQ(wordAt(p, 3, 'U').value, 1.5);
  EXPECT_DOUBLE_EQ(wordAt(p, 3, 'R').value, 0.5);
  EXPECT_EQ(programInputUnits(parse("G70\nG00 X1.\n"), InputUnits::Millimetre, c), InputUnits::Inch);
  // System A reads the same G70 as the finishing cycle: no units change.
  EXPECT_EQ(programInputUnits(parse("G70\nG00 X1.\n"), InputUnits::Millimetre, Dialect::Fanuc), InputUnits::Millimetre);
  // A cycle's setting says "whole" in system C too: U1 is 0.001 mm in increments.
  const PointEvidence e = weighDecimalPoints(parse("G71\nG73 U1 R1\n"), InputUnits::Millimetre, c);
  ASSERT_EQ(e.forWholeUnits.size(), 2u);
  EXPECT_EQ(e.forWholeUnits[0].word, "U1");
}

}  // namespace
}  // namespace klueng::core::gcode

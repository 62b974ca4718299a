// Stock inferred from the program (issue 8 item 6, docs/program-file.md).
#include "klueng/core/infer/stock_inference.h"

#include <gtest/gtest.h>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/messages.h"
#include "../machine/test_support.h"

namespace klueng::core::machine {
namespace {

using testing::testSetup;

StockInference infer(const std::string& text) {
  return inferStock(gcode::parse(text, 1), testSetup());  // chuck grip 15 mm
}

std::string noteText(const std::string& text, const StockInference& r, std::size_t i, Lang lang = Lang::En) {
  io::JobHeader h;
  r.applyTo(h);
  const auto notes = stockNotes(h, &r, text, 1);
  return i < notes.size() ? formatMessage(notes[i], lang) : std::string("(no note)");
}

const std::string kFacingFirst =
    "O0001\n"
    "N10 G21 G99 G97 S800 M03\n"
    "N20 T0101\n"
    "N30 G00 X52. Z0. (approach)\n"
    "N40 G01 X-1.6 F0.2\n"
    "N50 G00 Z2.\n"
    "N60 X46.\n"
    "N70 G01 Z-60.\n"
    "N80 G00 X52. Z2.\n"
    "N90 T0303\n"
    "N100 G00 X55. Z-63.\n"
    "N110 G01 X0. F0.05\n"
    "N120 M30\n";

TEST(StockInference, FacingApproachGivesTheBarBelowIt) {
  const StockInference r = infer(kFacingFirst);
  ASSERT_TRUE(r.found);
  EXPECT_FALSE(r.inch);
  EXPECT_DOUBLE_EQ(r.approachDiameter, 52.0);
  EXPECT_DOUBLE_EQ(r.diameter, 50.0);
  EXPECT_EQ(r.diameterLine, 4);
  EXPECT_FALSE(r.cycleStart);
  EXPECT_DOUBLE_EQ(r.deepestZ, -63.0);
  EXPECT_EQ(r.lengthLine, 12);
  EXPECT_DOUBLE_EQ(r.length, 85.0);  // 63 + 5 + 15 = 83, up to 85
  EXPECT_DOUBLE_EQ(r.bore, 0.0);
  EXPECT_EQ(noteText(kFacingFirst, r, 0), "stock Ø50 x 85 mm inferred from N30 G00 X52. Z0. (first approach)");
  EXPECT_EQ(noteText(kFacingFirst, r, 1),
            "stock length 85: the deepest cut Z-63 (N110 G01 X0. F0.05) + 5 for the cut-off + 15 held in the chuck");
  EXPECT_EQ(noteText(kFacingFirst, r, 0, Lang::Th),
            "ชิ้นงาน Ø50 x 85 มม. ประมาณจาก N30 G00 X52. Z0. (ตำแหน่งเข้าหาชิ้นงานครั้งแรก)");
}

// A program that only works behind the face (the cut-off of a part turned by
// another program): no approach from in front of the face, so the bar lies
// below where the first cut starts (G00 X1.5 then Z-2.1: a Ø1.5 bar), never the
// Ø50 mm default a rapid along the bar would run into.
TEST(StockInference, OnlyBehindTheFaceTheFirstCutsStartGivesTheBar) {
  const std::string text =
      "%\nO2008 (CUT OFF ONLY)\nG20 G99\nT1212 (CUT OFF)\nG97 S1500 M03\nG00 X1.5 Z0.1\nZ-2.1\n"
      "G01 X1.4 F0.004\nX0. F0.002\nG00 X1.6\nM30\n%\n";
  const StockInference r = infer(text);
  ASSERT_TRUE(r.found);
  EXPECT_TRUE(r.inch);
  EXPECT_DOUBLE_EQ(r.approachDiameter, 1.5);
  EXPECT_DOUBLE_EQ(r.diameter, 1.5);
  EXPECT_EQ(r.diameterLine, 7);
  EXPECT_DOUBLE_EQ(r.deepestZ, -2.1);
}

// A program that works beyond the centre line (a rear tool post: X < 0) reads
// the same round bar: G00 Z0., a 1 mm step in Z and a face across to
// the centre give a bar a size above Ø30.5 — no tube: a step in Z followed by
// facing down to the centre line is a face cut, not a bore.
TEST(StockInference, BeyondTheCentreTheSameBarAndAFaceStepIsNoBore) {
  const std::string text =
      "G21 G98\nT0101\nG97 S600 M03\nG00 X-30.5 Z0.\nG01 Z-1. F60\nX0.\nG00 Z3.\n"
      "X-30.5\nG01 Z-2.\nX0.\nG00 Z3.\nM30\n";
  const StockInference r = infer(text);
  ASSERT_TRUE(r.found);
  EXPECT_DOUBLE_EQ(r.approachDiameter, 30.5);
  EXPECT_DOUBLE_EQ(r.diameter, 32.0);
  EXPECT_DOUBLE_EQ(r.bore, 0.0);
  EXPECT_EQ(r.diameterLine, 4);
  // The same in front of the centre line: the same bar.
  const StockInference f = infer("G21 G98\nT0101\nG97 S600 M03\nG00 X30.5 Z0.\nG01 Z-1. F60\nX0.\nG00 Z3.\nM30\n");
  ASSERT_TRUE(f.found);
  EXPECT_DOUBLE_EQ(f.diameter, 32.0);
  EXPECT_DOUBLE_EQ(f.bore, 0.0);
}

TEST(StockInference, CycleStartPoint) {
  const std::string text =
      "N10 G21 G99 G97 S800 M03\n"
      "N20 T0101\n"
      "N30 G00 X42. Z2.\n"
      "N40 G71 U1.5 R0.5\n"
      "N50 G71 P60 Q90 U0.4 W0.1 F0.25\n"
      "N60 G00 X20.\n"
      "N70 G01 Z-15.\n"
      "N80 X30. Z-25.\n"
      "N90 Z-40.\n"
      "N100 G70 P60 Q90\n"
      "N110 G00 X100. Z100.\n"
      "N120 M30\n";
  const StockInference r = infer(text);
  ASSERT_TRUE(r.found);
  EXPECT_DOUBLE_EQ(r.diameter, 40.0);
  EXPECT_TRUE(r.cycleStart);
  EXPECT_EQ(r.diameterLine, 3);
  EXPECT_DOUBLE_EQ(r.deepestZ, -40.0);
  EXPECT_DOUBLE_EQ(r.length, 60.0);
  EXPECT_EQ(noteText(text, r, 0), "stock Ø40 x 60 mm inferred from N30 G00 X42. Z2. (cycle start)");
}

TEST(StockInference, TurningFirstPassSitsInsideTheBar) {
  const StockInference r = infer("G21 G99 M03 S800\nT0101\nG00 X48. Z2.\nG01 Z-30. F0.2\nG00 X60.\nM30\n");
  ASSERT_TRUE(r.found);
  EXPECT_DOUBLE_EQ(r.diameter, 50.0);  // the smallest bar above Ø48
  EXPECT_DOUBLE_EQ(r.length, 50.0);    // 30 + 5 + 15
}

TEST(StockInference, InchProgramUsesEighthInchBars) {
  const std::string text =
      "%\nO01000\nG20 G99\nG97 S800 M03\nT0101\nG00 X2.1 Z0.1\nG01 X-0.06 F0.005\nG00 Z0.1\nX1.95\n"
      "G01 Z-2.5 F0.008\nG00 X2.1 Z0.1\nM30\n%\n";
  const StockInference r = infer(text);
  ASSERT_TRUE(r.found);
  EXPECT_TRUE(r.inch);
  EXPECT_NEAR(r.approachDiameter, 2.1, 1e-9);
  EXPECT_DOUBLE_EQ(r.diameter, 2.0);
  EXPECT_NEAR(r.deepestZ, -2.5, 1e-9);
  EXPECT_DOUBLE_EQ(r.length, 3.5);  // 2.5 + 0.2 + 0.59 = 3.29, up to 1/4 in
  io::JobHeader h;
  r.applyTo(h);
  EXPECT_EQ(h.stockSource, io::StockSource::Inferred);
  EXPECT_EQ(h.diameterUnit, io::LengthUnit::Inch);
  EXPECT_DOUBLE_EQ(h.diameterMm(), 50.8);
  EXPECT_EQ(noteText(text, r, 0), "stock Ø2 x 3.5 in inferred from G00 X2.1 Z0.1 (first approach)");
}

const std::string kTubeProgram =
    "G21 G99 G97 S500 M03\n"
    "T0101\n"
    "G00 X122. Z0.\n"
    "G01 X85. F0.2\n"
    "G00 Z2.\n"
    "T0404 (BORE)\n"
    "G00 X96. Z2.\n"
    "G01 Z-20. F0.1\n"
    "G01 X94.\n"
    "G00 Z2.\n"
    "G00 X92.\n"
    "G01 Z-40.\n"
    "G01 X90.\n"
    "G00 Z2.\n"
    "M30\n";

TEST(StockInference, InsideWorkWithoutDrillingIsATube) {
  const StockInference r = infer(kTubeProgram);
  ASSERT_TRUE(r.found);
  EXPECT_DOUBLE_EQ(r.diameter, 120.0);
  EXPECT_DOUBLE_EQ(r.insidePassDiameter, 92.0);
  EXPECT_EQ(r.boreLine, 12);
  EXPECT_DOUBLE_EQ(r.bore, 91.0);
  EXPECT_DOUBLE_EQ(r.length, 60.0);
  EXPECT_EQ(noteText(kTubeProgram, r, 0), "stock Ø120/Ø91 x 60 mm inferred from G00 X122. Z0. (first approach)");
  EXPECT_EQ(noteText(kTubeProgram, r, 2),
            "bore Ø91 inferred from G01 Z-40. (work inside without drilling first: tube stock)");
}

// A Fanuc boring program that never turns the outside: G71 with U-0.4 (inside)
// from X86. Roughing passes from X88 (U1. per side) out to the Ø100 profile.
const std::string kBoreOnly =
    "G21 G99 G97 S600 M03\n"         // 1
    "T0505\n"                        // 2
    "G00 X86. Z2.\n"                 // 3
    "G71 U1. R0.5\n"                 // 4
    "G71 P10 Q20 U-0.4 W0.1 F0.2\n"  // 5
    "N10 G00 X100.\n"                // 6
    "G01 Z0. F0.1\n"                 // 7
    "X96. Z-2.\n"                    // 8
    "Z-30.\n"                        // 9
    "X90.\n"                         // 10
    "N20 Z-45.\n"                    // 11
    "G70 P10 Q20\n"                  // 12
    "G00 Z100.\n"                    // 13
    "M30\n";                         // 14

TEST(StockInference, BoringOnlyProgramGetsABarAroundItsLargestCut) {
  const StockInference r = infer(kBoreOnly);
  ASSERT_TRUE(r.found);
  // Largest diameter cut: Ø100 (the profile's start, reached by G70) + 2 x 10 mm
  // wall = Ø120, a bar size; the smallest inside pass is the first G71 pass at
  // X86 + 2 x 1 = Ø88, so the bore is Ø87 (1 mm under it).
  EXPECT_TRUE(r.outsideFromInside);
  EXPECT_DOUBLE_EQ(r.largestCutDiameter, 100.0);
  EXPECT_DOUBLE_EQ(r.diameter, 120.0);
  EXPECT_DOUBLE_EQ(r.insidePassDiameter, 88.0);
  EXPECT_DOUBLE_EQ(r.bore, 87.0);
  EXPECT_EQ(r.boreLine, 5);
  EXPECT_EQ(noteText(kBoreOnly, r, 0),
            "stock Ø120/Ø87 x 65 mm inferred: the program works only inside a bore, so the bar is a size above "
            "its largest cut Ø100 with a wall around it");
}

// Issue 28 item 5: a bore needs inside evidence — the tool leaves the part
// through the hole (toward the centre behind the face, then out along Z below
// the pass). A neck on the outside (X44 Z-10, X40 Z-15, X44 Z-20, Z-30) comes
// back up to Ø44 before the tool leaves: a solid bar, in mm and inch, Fanuc and Haas.
StockInference inferIn(const std::string& text, gcode::Dialect dialect) {
  RunOptions options;
  options.dialect = dialect;
  return inferStock(gcode::parse(text, 1), testSetup(), options);
}

const std::string kVNeck =
    "G21 G99\n"            // 1
    "T0101\n"              // 2
    "G97 S800 M03\n"       // 3
    "G00 X52. Z2.\n"       // 4
    "G01 X44. Z0. F0.2\n"  // 5
    "Z-10.\n"              // 6
    "X40. Z-15.\n"         // 7
    "X44. Z-20.\n"         // 8
    "Z-30.\n"              // 9
    "G00 X60.\n"           // 10
    "Z100.\n"              // 11
    "M30\n";               // 12

TEST(StockInference, AnOutsideNeckIsNoBore) {
  for (const gcode::Dialect dialect : {gcode::Dialect::Fanuc, gcode::Dialect::Haas}) {
    const StockInference r = inferIn(kVNeck, dialect);
    ASSERT_TRUE(r.found);
    EXPECT_DOUBLE_EQ(r.insidePassDiameter, 0.0);
    EXPECT_DOUBLE_EQ(r.bore, 0.0);
    EXPECT_FALSE(r.outsideFromInside);
    EXPECT_DOUBLE_EQ(r.diameter, 50.0);  // X52. before a diagonal first cut: the bar below it
    EXPECT_EQ(r.diameterLine, 4);
    EXPECT_DOUBLE_EQ(r.length, 50.0);  // 30 + 5 + 15
    EXPECT_EQ(noteText(kVNeck, r, 0), "stock Ø50 x 50 mm inferred from G00 X52. Z2. (first approach)");
    io::JobHeader h;
    r.applyTo(h);
    EXPECT_EQ(stockNotes(h, &r, kVNeck, 1).size(), 2u);  // Ø and length, no I154
  }
  const std::string inch =
      "G20 G99\nT0101\nG97 S800 M03\nG00 X2.05 Z0.1\nG01 X1.75 Z0. F0.008\nZ-0.4\nX1.55 Z-0.6\nX1.75 Z-0.8\n"
      "Z-1.2\nG00 X2.5\nZ4.\nM30\n";
  for (const gcode::Dialect dialect : {gcode::Dialect::Fanuc, gcode::Dialect::Haas}) {
    const StockInference r = inferIn(inch, dialect);
    ASSERT_TRUE(r.found);
    EXPECT_TRUE(r.inch);
    EXPECT_DOUBLE_EQ(r.bore, 0.0);
    EXPECT_DOUBLE_EQ(r.insidePassDiameter, 0.0);
    EXPECT_DOUBLE_EQ(r.diameter, 2.0);
    EXPECT_EQ(noteText(inch, r, 0), "stock Ø2 x 2 in inferred from G00 X2.05 Z0.1 (first approach)");
  }
}

// Passes that retract along the cut (G00 Z2. at the pass's own X) and step
// down for the next: outside roughing, not a bore (main read Ø50/Ø47).
TEST(StockInference, RetractAlongTheCutIsNoBore) {
  const std::string text =
      "G21 G99\nT0101\nG97 S800 M03\nG00 X48. Z2.\nG01 Z-30. F0.2\nG00 Z2.\nX46.\n"
      "G01 Z-30.\nG00 Z2.\nX100. Z100.\nM30\n";
  const StockInference r = infer(text);
  ASSERT_TRUE(r.found);
  EXPECT_DOUBLE_EQ(r.bore, 0.0);
  EXPECT_DOUBLE_EQ(r.diameter, 50.0);  // the first pass at Ø48 sits inside the bar
  EXPECT_EQ(noteText(text, r, 0), "stock Ø50 x 50 mm inferred from G00 X48. Z2. (first approach)");
}

// A CAM post's outside profile: rapid to just above the part, a lead-in feed,
// passes that follow the neck, a lead-out at 45°. The lead-in from X44.8 reads
// as a Ø40 bar, but the program turns Ø44 along -Z: the bar is the next size
// above that, solid (main read "Ø60/Ø42 ... works only inside a bore").
const std::string kCamOutside =
    "%\n"                        // 1
    "O2001 (OUTSIDE PROFILE)\n"  // 2
    "(T1 OD 55DEG R0.8)\n"       // 3
    "N10 G21 G99 G40\n"          // 4
    "N20 G28 U0.\n"              // 5
    "N30 T0101\n"                // 6
    "N40 G50 S2500\n"            // 7
    "N50 G96 S180 M03\n"         // 8
    "N60 G00 X44.8 Z3.\n"        // 9
    "N70 G01 X43.6 Z1. F0.3\n"   // 10
    "N80 Z-10.\n"                // 11
    "N90 X39.6 Z-15.\n"          // 12
    "N100 X43.6 Z-20.\n"         // 13
    "N110 Z-30.\n"               // 14
    "N120 X47.6 Z-28.\n"         // 15
    "N130 G00 Z3.\n"             // 16
    "N140 X45.\n"                // 17
    "N150 G01 X41. Z1.\n"        // 18
    "N160 X44. Z-0.5 F0.15\n"    // 19
    "N170 Z-10.\n"               // 20
    "N180 X40. Z-15.\n"          // 21
    "N190 X44. Z-20.\n"          // 22
    "N200 Z-30.\n"               // 23
    "N210 X47. Z-31.5\n"         // 24
    "N220 G00 X100. Z100.\n"     // 25
    "N230 M30\n"                 // 26
    "%\n";                       // 27

TEST(StockInference, CamOutsideProfileIsASolidBarAboveWhatItTurns) {
  for (const gcode::Dialect dialect : {gcode::Dialect::Fanuc, gcode::Dialect::Haas}) {
    const StockInference r = inferIn(kCamOutside, dialect);
    ASSERT_TRUE(r.found);
    EXPECT_FALSE(r.outsideFromInside);
    EXPECT_DOUBLE_EQ(r.insidePassDiameter, 0.0);
    EXPECT_DOUBLE_EQ(r.bore, 0.0);
    EXPECT_DOUBLE_EQ(r.largestTurnedDiameter, 44.0);
    EXPECT_DOUBLE_EQ(r.diameter, 45.0);
    EXPECT_EQ(r.diameterLine, 20);
    EXPECT_DOUBLE_EQ(r.length, 55.0);  // 31.5 + 5 + 15 = 51.5, up to 55
    EXPECT_EQ(noteText(kCamOutside, r, 0),
              "stock Ø45 x 55 mm inferred from N170 Z-10. (the largest diameter it turns)");
    EXPECT_EQ(noteText(kCamOutside, r, 0, Lang::Th),
              "ชิ้นงาน Ø45 x 55 มม. ประมาณจาก N170 Z-10. (เส้นผ่านศูนย์กลางใหญ่สุดที่กลึงด้านนอก)");
  }
}

// A Haas G76 started below the thread's first passes (X0.94 under a Ø0.99
// major): each pass returns to X0.94 and goes back along Z under it, but the
// cycle cuts down from its start — an outside thread, not a bore (M24: no
// pull-out at the thread's end, so the tool never rises above a pass).
TEST(StockInference, AThreadCycleCuttingDownIsNoBore) {
  const std::string text =
      "G20 G99\nT0101\nG97 S1000 M03\nG00 X1.1 Z0.\nG01 X-0.03 F0.004\nG00 Z0.1\nX0.99\nG01 Z-1. F0.006\n"
      "G00 X1.1\nT0505 (THREAD)\nG00 X0.94 Z0.2\nM24\nG76 X0.849 Z-0.9 K0.0707 D0.0177 F0.125\nG00 Z0.1\nM30\n";
  const StockInference r = inferIn(text, gcode::Dialect::Haas);
  ASSERT_TRUE(r.found);
  EXPECT_TRUE(r.inch);
  EXPECT_DOUBLE_EQ(r.insidePassDiameter, 0.0);
  EXPECT_DOUBLE_EQ(r.bore, 0.0);
  EXPECT_DOUBLE_EQ(r.diameter, 1.0);
  EXPECT_DOUBLE_EQ(r.length, 2.0);  // 1 + 0.2 + 0.59 = 1.79, up to 1/4 in
}

// The same profile bored: the tool goes in through the hole, follows the
// wall outward and comes back out along Z below each pass — inside evidence.
TEST(StockInference, BoringRetractBelowThePassIsATube) {
  const std::string text =
      "G21 G99\nT0404 (BORING BAR)\nG97 S600 M03\nG00 X120. Z0.\nG01 X80. F0.2\nG00 Z2.\n"
      "X86.\nG01 Z-30. F0.15\nX85.6\nG00 Z2.\nX88.\nG01 Z-12.\nX87.6\nG00 Z2.\nX100. Z100.\nM30\n";
  const StockInference r = infer(text);
  ASSERT_TRUE(r.found);
  EXPECT_DOUBLE_EQ(r.insidePassDiameter, 86.0);
  EXPECT_EQ(r.boreLine, 8);
  EXPECT_DOUBLE_EQ(r.bore, 85.0);
  EXPECT_DOUBLE_EQ(r.diameter, 120.0);
  EXPECT_EQ(noteText(text, r, 0), "stock Ø120/Ø85 x 50 mm inferred from G00 X120. Z0. (first approach)");
  // Leaving the bore in one slanting move from the wall (G01 X85.6 Z2.) is the same evidence.
  const StockInference slant = infer(
      "G21 G99\nT0404 (BORING BAR)\nG97 S600 M03\nG00 X120. Z0.\nG01 X80. F0.2\nG00 Z2.\n"
      "X86.\nG01 Z-30. F0.15\nG01 X85.6 Z2.\nG00 X100. Z100.\nM30\n");
  ASSERT_TRUE(slant.found);
  EXPECT_DOUBLE_EQ(slant.insidePassDiameter, 86.0);
  EXPECT_DOUBLE_EQ(slant.bore, 85.0);
}

TEST(StockInference, DrilledFirstIsASolidBar) {
  const std::string text =
      "G21 G99 G97 S800 M03\nT0303 (DRILL)\nG00 X0. Z2.\nG01 Z-30. F0.1\nG00 Z2.\n"
      "T0404\nG00 X14. Z2.\nG01 Z-20.\nG01 X12.\nG00 Z2.\n"
      "T0101\nG00 X34. Z0.\nG01 X-1.6 F0.2\nG00 Z2.\nM30\n";
  const StockInference r = infer(text);
  ASSERT_TRUE(r.found);
  EXPECT_DOUBLE_EQ(r.diameter, 32.0);
  EXPECT_EQ(r.diameterLine, 12);
  EXPECT_DOUBLE_EQ(r.bore, 0.0);
  EXPECT_DOUBLE_EQ(r.length, 50.0);
}

TEST(StockInference, NothingToGoBy) {
  const StockInference r = infer("G21\nM30\n");
  EXPECT_FALSE(r.found);
  io::JobHeader h;  // defaults, source Default
  const auto notes = stockNotes(h, &r, "G21\nM30\n", 1);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].code, "I155");
  EXPECT_EQ(formatMessage(notes[0], Lang::En),
            "stock Ø50 x 100 mm is the default: the program has no approach to infer it from; "
            "set it in Job details or with --stock");
}

TEST(StockInference, BarSeries) {
  EXPECT_DOUBLE_EQ(metricBarSize(52.0), 50.0);
  EXPECT_DOUBLE_EQ(metricBarSize(50.0), 50.0);
  EXPECT_DOUBLE_EQ(metricBarSize(26.0), 25.0);
  EXPECT_DOUBLE_EQ(metricBarSize(48.0, true), 50.0);
  EXPECT_DOUBLE_EQ(metricBarSize(2.5), 2.0);
  EXPECT_DOUBLE_EQ(inchBarSize(2.1), 2.0);
  EXPECT_DOUBLE_EQ(inchBarSize(1.3), 1.25);
  EXPECT_DOUBLE_EQ(inchBarSize(1.95, true), 2.0);
}

TEST(StockNotes, EachSourceSaysWhereTheStockCameFrom) {
  io::JobHeader h;
  h.diameter = 118;
  h.bore = 90;
  h.length = 80;
  const std::pair<io::StockSource, const char*> cases[] = {
      {io::StockSource::Header, "stock Ø118/Ø90 x 80 mm from the file's job header"},
      {io::StockSource::CommandLine, "stock Ø118/Ø90 x 80 mm from the command line (--stock)"},
      {io::StockSource::JobDetails, "stock Ø118/Ø90 x 80 mm from Job details set for this file"},
  };
  for (const auto& [source, text] : cases) {
    h.stockSource = source;
    const auto notes = stockNotes(h, nullptr, "", 1);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(formatMessage(notes[0], Lang::En), text);
    EXPECT_NE(formatMessage(notes[0], Lang::Th).find("ชิ้นงาน Ø118/Ø90 x 80 มม."), std::string::npos);
  }
}

}  // namespace
}  // namespace klueng::core::machine

namespace klueng::core::machine {
namespace {

// An op-2 program of a production shop (issue 38): it faces the tube down to X30. only, spots it
// with a drill 5 mm deep, then bores to Z-25.: the boring passes deeper than the drill's hole ran
// in the tube's own bore.
TEST(StockInference, BoringDeeperThanAShallowDrillIsATube) {
  const StockInference r = inferStock(gcode::parse("O0201\n"
                                                   "G21 G99 G97 S800 M03\n"
                                                   "T0101\n"
                                                   "G00 X62. Z0.\n"
                                                   "G01 X30. F0.2\n"
                                                   "G00 Z2.\n"
                                                   "T0606\n"
                                                   "G00 X0. Z2.\n"
                                                   "G01 Z-5. F0.1\n"
                                                   "G00 Z2.\n"
                                                   "T0505\n"
                                                   "G00 X26. Z2.\n"
                                                   "G01 Z-25. F0.15\n"
                                                   "G00 X25.\n"
                                                   "G00 Z2.\n"
                                                   "M30\n",
                                                   1),
                                      testing::testSetup());
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.boreLine, 13);       // G01 Z-25. at X26.
  EXPECT_DOUBLE_EQ(r.bore, 25.0);  // a size below the pass
}

}  // namespace
}  // namespace klueng::core::machine

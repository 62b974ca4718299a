// Stock inferred from the program (issue 8 item 6, docs/program-file.md).
#include "klueng/core/machine/stock_inference.h"

#include <gtest/gtest.h>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/messages.h"
#include "test_support.h"

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
            "ชิ้นงาน Ø50 x 85 mm ประมาณจาก N30 G00 X52. Z0. (ตำแหน่งเข้าหาชิ้นงานครั้งแรก)");
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
  const std::string text = "G21 G98\nT0101\nG97 S600 M03\nG00 X-30.5 Z0.\nG01 Z-1. F60\nX0.\nG00 Z3.\n"
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
    "G21 G99 G97 S600 M03\n"                  // 1
    "T0505\n"                                 // 2
    "G00 X86. Z2.\n"                          // 3
    "G71 U1. R0.5\n"                          // 4
    "G71 P10 Q20 U-0.4 W0.1 F0.2\n"           // 5
    "N10 G00 X100.\n"                         // 6
    "G01 Z0. F0.1\n"                          // 7
    "X96. Z-2.\n"                             // 8
    "Z-30.\n"                                 // 9
    "X90.\n"                                  // 10
    "N20 Z-45.\n"                             // 11
    "G70 P10 Q20\n"                           // 12
    "G00 Z100.\n"                             // 13
    "M30\n";                                  // 14

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
    EXPECT_NE(formatMessage(notes[0], Lang::Th).find("ชิ้นงาน Ø118/Ø90 x 80 mm"), std::string::npos);
  }
}

}  // namespace
}  // namespace klueng::core::machine

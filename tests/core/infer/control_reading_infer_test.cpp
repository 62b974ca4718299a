// What a program says of itself that the control never reads (issue 38 items 7 and 8): a bar
// puller named in a comment is no cutting tool, and a plain program without G20/G21 whose sizes
// are inches is read in inches on a machine that powers on in mm.
#include <gtest/gtest.h>

#include <string>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/infer/tool_inference.h"
#include "klueng/core/infer/stock_inference.h"
#include "klueng/core/infer/units_reading.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/messages.h"

namespace klueng::core::machine {
namespace {

MachineSetup barPullerSetup() {
  const std::string dir = KLUENG_SOURCE_DIR;
  MachineSetup setup;
  setup.tools = *io::readToolTable(dir + "/tools.cfg").value;
  setup.offsets = *io::readOffsetTable(dir + "/offset.cfg").value;
  return setup;
}

// A Russian shop's habit: the bar puller's station named in the T line's comment.
TEST(BarHolder, APullerOrAStopNamedInAT_LineCommentHoldsTheBar) {
  const std::string text =
      "T0303(PROXODNOI R0.4)\nG97S1500M03\nG0X22.Z2.\nG1Z-20.F0.2\nG0X30.Z10.\nM5\n"
      "T0505(BARPULER)\nG98\nG0X0.Z10.\nG1Z-10.F2000.\nG4X2.\nG1Z-2.F500.\n"
      "T0707 (BAR STOP)\nG0X0.Z1.\nM30\n";
  const gcode::Program program = gcode::parse(text, 1);
  const ToolInference r = inferTools(program, text, 1, barPullerSetup(), io::shippedToolLibrary(), {});
  EXPECT_TRUE(r.setup.tools.isBarHolder(5));
  EXPECT_TRUE(r.setup.tools.pullsBar(5));
  EXPECT_TRUE(r.setup.tools.isBarHolder(7));
  EXPECT_FALSE(r.setup.tools.pullsBar(7));  // a stop only stands in the bar's way
  EXPECT_FALSE(r.setup.tools.isBarHolder(3));
}

std::optional<UnitsReading> unitsOf(const std::string& text, gcode::Dialect d = gcode::Dialect::Fanuc) {
  return readPowerOnUnits(gcode::parse(text, 1), d, gcode::powerOnUnitsOf(d, {}));
}

TEST(UnitsReading, AnInchRoughingProgramWithoutG20IsReadInInches) {
  // An American production shop's 13 lines: depth .1, retract .02, 500 ft/min.
  const auto r = unitsOf(
      "O1002\nG50S1250\nG0T0101\nG96S500M3\nX8.Z.04\nG71U.1R.02\nG71P10Q20U.02F.04\n"
      "N10G0X6.\nG1Z-2.\nN20G1X8.\nG0X11.Z6.\nM30\n");
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->units, gcode::InputUnits::Inch);
  EXPECT_EQ(r->note.code, "I107");
  EXPECT_EQ(r->note.range.line, 4);  // G96S500: the first word that spoke inch
  EXPECT_EQ(r->note.args[1], "S500");
}

TEST(UnitsReading, AMetricProgramAndOneThatNamesItsUnitsStayAsTheyAre) {
  EXPECT_FALSE(unitsOf("T0101\nG96S200M3\nG0X52.Z2.\nG71U2.R0.5\nG71P1Q2U0.4W0.1F0.25\nN1G0X30.\nG1Z-20.\nN2X52.\n"
                       "M30\n")
                   .has_value());                                                 // mm: the machine's own units
  EXPECT_FALSE(unitsOf("G20\nT0101\nG96S500M3\nG71U.1R.02\nM30\n").has_value());  // G20 says it
  // Too little to tell: the machine's units stand.
  EXPECT_FALSE(unitsOf("T0101\nG0X8.Z1.\nG1Z-2.F.04\nM30\n").has_value());
}

TEST(UnitsReading, AMetricProgramOnAnInchHaasIsReadInMm) {
  const auto r = unitsOf(
      "T101\nG96 S180 M03\nG00 X52. Z2.\nG71 P1 Q2 U0.4 W0.1 D1.5 F0.25\nN1 G00 X30.\n"
      "G01 Z-20.\nN2 X52.\nM30\n",
      gcode::Dialect::Haas);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->units, gcode::InputUnits::Millimetre);
}

TEST(StockComment, TheBarAShopNamesInAMaterialCommentWins) {
  StockInference r;
  r.found = true;
  r.inch = true;
  r.diameter = 2.375;  // from the approach X2.4
  r.length = 2.25;
  const char* text =
      "%\nO2260(CARRIER BUSHING OP1)\n(T08 ID TURN 3/4\" SHANK BORING BAR CCGT-AS/AF)\n(G54 Z OFFSET: 7.335)\n"
      "(MATERIAL: 2.25\"OD X 1.5\"ID X 2.32\"L BRONZE TUBING)\nG20\n";
  ASSERT_TRUE(readStockComment(r, text, 1));
  EXPECT_EQ(r.commentLine, 5);
  EXPECT_DOUBLE_EQ(r.diameter, 2.25);
  EXPECT_DOUBLE_EQ(r.bore, 1.5);
  EXPECT_DOUBLE_EQ(r.length, 2.32);
}

TEST(StockComment, AGradeAToolListOrAnOffsetIsNoBar) {
  StockInference r;
  r.found = true;
  r.diameter = 50.0;
  r.length = 80.0;
  EXPECT_FALSE(readStockComment(r, "(MATERIAL: 1018 CRS)\n(G54:FACE OF STOCK)\n(T12 - CCGT 431 BAR)\n", 1));
  EXPECT_DOUBLE_EQ(r.diameter, 50.0);
  EXPECT_TRUE(readStockComment(r, "O0001\n(STOCK: DIA 52 X 120 C45)\n", 1));
  EXPECT_EQ(r.commentLine, 2);
  EXPECT_DOUBLE_EQ(r.diameter, 52.0);
  EXPECT_DOUBLE_EQ(r.length, 120.0);
}

}  // namespace
}  // namespace klueng::core::machine

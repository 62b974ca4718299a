// How a job reads lengths without a decimal point (issue 26 item 6): the
// user's choice, else a plain program's numbers, else the machine.
#include "klueng/core/infer/point_reading.h"

#include <gtest/gtest.h>

#include "klueng/core/gcode/parser.h"

namespace klueng::core::machine {
namespace {

constexpr const char* kShopHabit =
    "G21 G00 X52. Z2.\n"
    "G71 U1500 R500\n"
    "G71 P10 Q20 U0.4 W0.1 F0.25\n"
    "N10 G00 X30.\n"
    "N20 G01 Z-20.\n";

TEST(PointReading, APlainProgramsNumbersDecideWithANote) {
  gcode::Program p = gcode::parse(kShopHabit);
  const PointReading r =
      readDecimalPoints(p, true, std::nullopt, true, gcode::InputUnits::Millimetre, gcode::Dialect::Fanuc);
  EXPECT_FALSE(r.calculatorInput);
  EXPECT_TRUE(r.fromProgram);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "I103");
  EXPECT_EQ(r.diagnostics[0].severity, Severity::Note);
  EXPECT_EQ(r.diagnostics[0].range, (SourceRange{2, 5, 5}));
  EXPECT_EQ(r.diagnostics[0].args, (std::vector<std::string>{"U1500", "2", "1.500 mm"}));
  EXPECT_DOUBLE_EQ(p.blocks[1].find('U')->value, 1.5);
  EXPECT_DOUBLE_EQ(p.blocks[1].find('R')->value, 0.5);
}

TEST(PointReading, TheUsersChoiceWinsAndAHeaderFileFollowsTheMachine) {
  gcode::Program chosen = gcode::parse(kShopHabit);
  const PointReading c =
      readDecimalPoints(chosen, true, true, false, gcode::InputUnits::Millimetre, gcode::Dialect::Fanuc);
  EXPECT_TRUE(c.calculatorInput);
  EXPECT_FALSE(c.fromProgram);
  ASSERT_EQ(c.diagnostics.size(), 2u);  // W111 on U1500 and R500, nothing else
  EXPECT_EQ(c.diagnostics[0].code, "W111");
  EXPECT_DOUBLE_EQ(chosen.blocks[1].find('U')->value, 1500.0);

  gcode::Program header = gcode::parse(kShopHabit);
  const PointReading h =
      readDecimalPoints(header, false, std::nullopt, true, gcode::InputUnits::Millimetre, gcode::Dialect::Fanuc);
  EXPECT_TRUE(h.calculatorInput);
  EXPECT_FALSE(h.fromProgram);
  EXPECT_DOUBLE_EQ(header.blocks[1].find('R')->value, 500.0);
}

TEST(PointReading, WholeNumbersOnAMachineSetToIncrementsAreReadWholeAndSaidSo) {
  gcode::Program p = gcode::parse("G21 G00 X40 Z2\nG01 Z-30 F0.2\nX44\n");
  const PointReading r =
      readDecimalPoints(p, true, std::nullopt, false, gcode::InputUnits::Millimetre, gcode::Dialect::Fanuc);
  EXPECT_TRUE(r.calculatorInput);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "I104");
  EXPECT_EQ(r.diagnostics[0].args, (std::vector<std::string>{"X40", "1", "40 mm"}));
  EXPECT_DOUBLE_EQ(p.blocks[0].find('X')->value, 40.0);
  // The same on a machine that reads whole: nothing to say.
  gcode::Program q = gcode::parse("G21 G00 X40 Z2\nG01 Z-30 F0.2\nX44\n");
  EXPECT_TRUE(readDecimalPoints(q, true, std::nullopt, true, gcode::InputUnits::Millimetre, gcode::Dialect::Fanuc)
                  .diagnostics.empty());
}

TEST(PointReading, ATieIsTheMachines) {
  // One word for each reading: U2000 (2 m depth whole) and X30 (0.03 mm in increments).
  gcode::Program p = gcode::parse("G21 G00 X30 Z2.\nG71 U2000 R0.5\n");
  const PointReading r =
      readDecimalPoints(p, true, std::nullopt, false, gcode::InputUnits::Millimetre, gcode::Dialect::Fanuc);
  EXPECT_FALSE(r.calculatorInput);
  EXPECT_FALSE(r.fromProgram);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "W110");  // X30 read as 0.030 mm
  EXPECT_DOUBLE_EQ(p.blocks[0].find('X')->value, 0.03);
}

}  // namespace
}  // namespace klueng::core::machine

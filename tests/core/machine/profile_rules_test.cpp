// The interpreter's rules that differ between the machine profiles (SPEC 13):
// power-on units, G04 P, one-shot G codes with G00/G01, a bare G28, G30, T
// limits, rounding to the least increment, the brake M codes. Every value is
// derived by hand in the comments.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>

#include "klueng/core/gcode/code_table.h"
#include "klueng/core/machine/interpreter.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

using gcode::Dialect;
using testing::runText;

RunOptions in(Dialect d) {
  RunOptions o;
  o.dialect = d;
  return o;
}

Vec2 endPosition(const Timeline& t) { return t.snapshots.back().machine.position; }

// ---- power-on units -----------------------------------------------------------

TEST(PowerOnUnits, HaasRunsAProgramWithoutG20InInch) {
  // X1. Z0.1 in inch: diameter 25.4 mm, Z 2.54 mm.
  const Timeline t = runText("G00 X1. Z0.1\n", in(Dialect::Haas));
  ASSERT_FALSE(t.alarm);
  EXPECT_EQ(t.snapshots.back().modal.units, Units::Inch);
  EXPECT_POINT(endPosition(t), 25.4, 2.54);
}

TEST(PowerOnUnits, FanucAndClassicStartInMm) {
  for (const Dialect d : {Dialect::Fanuc, Dialect::Classic}) {
    const Timeline t = runText("G00 X1. Z0.1\n", in(d));
    EXPECT_EQ(t.snapshots.back().modal.units, Units::Mm);
    EXPECT_POINT(endPosition(t), 1.0, 0.1);
  }
}

TEST(PowerOnUnits, TheRunOptionOverridesTheProfile) {
  RunOptions haasMm = in(Dialect::Haas);
  haasMm.powerOnUnits = gcode::InputUnits::Millimetre;
  EXPECT_POINT(endPosition(runText("G00 X1. Z0.1\n", haasMm)), 1.0, 0.1);
  RunOptions fanucInch = in(Dialect::Fanuc);
  fanucInch.powerOnUnits = gcode::InputUnits::Inch;
  EXPECT_POINT(endPosition(runText("G00 X1. Z0.1\n", fanucInch)), 25.4, 2.54);
  // G21 in the program still wins over the power-on units.
  EXPECT_POINT(endPosition(runText("G21 G00 X1. Z0.1\n", in(Dialect::Haas))), 1.0, 0.1);
}

// ---- G04 P ------------------------------------------------------------------------

double dwellTime(const Timeline& t) {
  double s = 0.0;
  for (const Move& m : t.moves)
    if (m.kind == MoveKind::Dwell) s += m.tEnd - m.tStart;
  return s;
}

TEST(DwellP, HaasPWithADecimalPointIsSeconds) {
  // Haas: P3. = 3 s; P3000 (no point) = 3000 ms = 3 s; P1.5 = 1.5 s.
  EXPECT_DOUBLE_EQ(dwellTime(runText("G98\nG04 P3.\n", in(Dialect::Haas))), 3.0);
  EXPECT_DOUBLE_EQ(dwellTime(runText("G98\nG04 P3000\n", in(Dialect::Haas))), 3.0);
  EXPECT_DOUBLE_EQ(dwellTime(runText("G98\nG04 P1.5\n", in(Dialect::Haas))), 1.5);
}

TEST(DwellP, FanucPIsMilliseconds) {
  // Fanuc and classic: P3000 = 3 s; (P3. would be 3 ms: the checker refuses it).
  EXPECT_DOUBLE_EQ(dwellTime(runText("G98\nG04 P3000\n", in(Dialect::Fanuc))), 3.0);
  EXPECT_DOUBLE_EQ(dwellTime(runText("G98\nG04 P3000\n", in(Dialect::Classic))), 3.0);
  EXPECT_DOUBLE_EQ(dwellTime(runText("G98\nG04 P3.\n", in(Dialect::Fanuc))), 0.003);
}

// ---- one-shot G codes with G00/G01 -----------------------------------------------

TEST(OneShotWithMotion, G53G00MovesInMachineCoordinatesAndG00StaysModal) {
  const Timeline t = runText(
      "G98 G97 S500 M03\n"     // 1
      "G01 X40. Z-5. F100.\n"  // 2
      "G53 G00 X0\n"           // 3: machine X0 = the reference point's X, work X0
      "X10.\n",                // 4: a rapid (G00 is modal now)
      in(Dialect::Fanuc));
  ASSERT_FALSE(t.alarm);
  EXPECT_POINT(t.snapshots[2].machine.position, 0.0, -5.0);
  EXPECT_EQ(t.snapshots[2].modal.motion, MotionMode::Rapid);
  EXPECT_EQ(t.moves.back().kind, MoveKind::Rapid);
  EXPECT_EQ(t.moves.back().line, 4);
  EXPECT_POINT(endPosition(t), 10.0, -5.0);
}

TEST(OneShotWithMotion, G00G53WithXAndZ) {
  // G00 G53 X0 Z-2.: both axes to the machine position; machine zero is the
  // reference point X0 Z300, so Z-2. (mm after G21) is work Z298.
  const Timeline t = runText("G21\nG00 X40. Z10.\nG00 G53 X0 Z-2.\n", in(Dialect::Haas));
  ASSERT_FALSE(t.alarm);
  EXPECT_POINT(endPosition(t), 0.0, 298.0);
}

TEST(OneShotWithMotion, G28G01UWReturnsAndLeavesG01Modal) {
  const Timeline t = runText(
      "G98 G97 S500 M03\n"     // 1
      "G00 X40. Z10.\n"        // 2
      "G28 G01 U0 W0 F100.\n"  // 3: intermediate = here, then the reference X0 Z300 at rapid
      "X20. Z290.\n",          // 4: G01 from the reference point
      in(Dialect::Fanuc));
  ASSERT_FALSE(t.alarm);
  EXPECT_POINT(t.snapshots[2].machine.position, 0.0, 300.0);
  EXPECT_EQ(t.snapshots[2].modal.motion, MotionMode::Line);
  for (const Move& m : t.moves) {
    if (m.line == 3) {
      EXPECT_EQ(m.kind, MoveKind::Rapid);
    }
  }
  EXPECT_EQ(t.moves.back().kind, MoveKind::Line);
  // Line 4: from X0 Z300 to X20 Z290: sqrt(10^2 + 10^2) = 14.142 mm at 100 mm/min = 8.485 s.
  EXPECT_NEAR(t.moves.back().tEnd - t.moves.back().tStart, std::sqrt(200.0) / 100.0 * 60.0, 1e-9);
}

TEST(OneShotWithMotion, G28G00UWInHaasInch) {
  // Haas, inch: G00 X2. Z0.5 = X50.8 Z12.7 mm; G28 G00 U0 W0 homes both axes
  // (the intermediate point is where the tool is), G00 stays modal.
  const Timeline t = runText("G00 X2. Z0.5\nG28 G00 U0 W0\nX1.\n", in(Dialect::Haas));
  ASSERT_FALSE(t.alarm);
  EXPECT_POINT(t.snapshots[1].machine.position, 0.0, 300.0);
  EXPECT_EQ(t.moves.back().kind, MoveKind::Rapid);
  EXPECT_POINT(endPosition(t), 25.4, 300.0);
}

// ---- G28 without axes, G30 -----------------------------------------------------------

TEST(BareG28, HaasHomesXAndZ) {
  const Timeline t = runText("G21\nG00 X50. Z10.\nG28\n", in(Dialect::Haas));
  ASSERT_FALSE(t.alarm);
  // The reference point of the test setup is X0 Z300.
  EXPECT_POINT(endPosition(t), 0.0, 300.0);
  EXPECT_TRUE(t.snapshots.back().machine.positionCheck);
  // Rapid dog-leg: X 25 mm (radius) at 4000 mm/min = 0.375 s, Z 290 mm at
  // 8000 mm/min = 2.175 s; the axes move at once, so the block takes 2.175 s.
  double start = 1e9, end = 0.0;
  for (const Move& m : t.moves)
    if (m.line == 3) start = std::min(start, m.tStart), end = std::max(end, m.tEnd);
  EXPECT_NEAR(end - start, 2.175, 1e-9);
}

TEST(BareG28, FanucMovesNothing) {
  const Timeline t = runText("G00 X50. Z10.\nG28\n", in(Dialect::Fanuc));
  ASSERT_FALSE(t.alarm);
  EXPECT_POINT(endPosition(t), 50.0, 10.0);
  for (const Move& m : t.moves) EXPECT_NE(m.line, 2);
}

TEST(G30, ReturnsViaTheIntermediatePointToTheReferencePoint) {
  // No second reference point is configured: G30 goes to the reference point
  // X0 Z300, via X60 (U10. from X50) first; Z stays (no W).
  const Timeline t = runText("G00 X50. Z10.\nG30 U10.\n", in(Dialect::Fanuc));
  ASSERT_FALSE(t.alarm);
  EXPECT_POINT(endPosition(t), 0.0, 10.0);
  std::vector<double> xs;
  for (const Move& m : t.moves)
    if (m.line == 2) xs.push_back(2.0 * xOf(m.path.end));
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_NEAR(xs[0], 60.0, 1e-9);
  EXPECT_NEAR(xs[1], 0.0, 1e-9);
}

// ---- T limits --------------------------------------------------------------------------

TEST(ToolWord, LimitsComeFromTheTablesAndTheProfile) {
  const MachineSetup setup = testing::testSetup();
  const int stations = static_cast<int>(setup.tools.bitmap.size());
  const int offsets =
      std::min(gcode::machineProfile(Dialect::Fanuc).maxOffset, static_cast<int>(setup.offsets.offsets.size()));
  // The last station with the last offset is fine.
  const std::string last = fmt::format("T{:02d}{:02d}\n", stations, offsets);
  const Timeline ok = runText(last, in(Dialect::Fanuc));
  ASSERT_FALSE(ok.alarm);
  EXPECT_EQ(ok.snapshots.back().machine.tool, stations);
  EXPECT_EQ(ok.snapshots.back().machine.offset, offsets);
  // One station more: A128 with the limit.
  const Timeline station = runText(fmt::format("T{:02d}01\n", stations + 1), in(Dialect::Haas));
  ASSERT_TRUE(station.alarm);
  EXPECT_EQ(station.alarm->code, "A128");
  EXPECT_EQ(station.alarm->args[1], fmt::format("{:02d}", stations + 1));
  EXPECT_EQ(station.alarm->args[2], fmt::format("{:02d}", stations));
  // One offset more: A118 with the limit.
  const Timeline offset = runText(fmt::format("T01{:02d}\n", offsets + 1), in(Dialect::Fanuc));
  ASSERT_TRUE(offset.alarm);
  EXPECT_EQ(offset.alarm->code, "A118");
  EXPECT_EQ(offset.alarm->args[2], fmt::format("{:02d}", offsets));
}

TEST(ToolWord, ClassicStopsAtSixteenOffsets) {
  const Timeline t = runText("T0117\n", in(Dialect::Classic));
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A118");
  EXPECT_EQ(t.alarm->args[2], "16");
}

// ---- more decimals than the least increment ---------------------------------------------

TEST(Rounding, FanucRoundsMmToThreeDecimals) {
  // X0.42928932 -> 0.429; Z1.0006 -> 1.001 (half away from zero).
  const Timeline t = runText("G00 X0.42928932 Z1.0006\n", in(Dialect::Fanuc));
  EXPECT_POINT(endPosition(t), 0.429, 1.001);
}

TEST(Rounding, HaasRoundsInchToFourDecimals) {
  // Inch at power-on: X0.42928932 -> 0.4293 in = 10.90422 mm; Z-0.12345678 -> -0.1235 in = -3.1369 mm.
  const Timeline t = runText("G00 X0.42928932 Z-0.12345678\n", in(Dialect::Haas));
  EXPECT_POINT(endPosition(t), 0.4293 * 25.4, -0.1235 * 25.4);
}

TEST(Rounding, TheUnitsOfTheBlockDecide) {
  // G21 in the block: 3 decimals although Haas powers on in inch.
  const Timeline t = runText("G21 G00 X10.12345 Z2.00049\n", in(Dialect::Haas));
  EXPECT_POINT(endPosition(t), 10.123, 2.0);
}

TEST(Rounding, ClassicKeepsTheValue) {
  // Classic: extra decimals are the checker's error E111; the run is not rounded.
  const Timeline t = runText("G00 X0.42928932 Z1.0006\n", in(Dialect::Classic));
  EXPECT_POINT(endPosition(t), 0.42928932, 1.0006);
}

// ---- M codes ---------------------------------------------------------------------------------

TEST(MCodes, UnknownMCodesAreNoOps) {
  // M21/M22 (Haas tailstock), M31/M33 (chip conveyor): not in the brake, spindle
  // or program groups, so they change nothing (known by name or not).
  const Timeline t = runText("G21 M21\nG00 X10. Z5. M31\nM33 M22\n", in(Dialect::Haas));
  ASSERT_FALSE(t.alarm);
  EXPECT_POINT(endPosition(t), 10.0, 5.0);
}

TEST(MCodes, HaasM14M15BehaveLikeM86M87) {
  // M14/M15 are Haas codes of the brake group: a code missing from the table is a
  // failure here, never a skip.
  for (const int number : {14, 15}) {
    const gcode::CodeInfo* code = gcode::findCode('M', number, Dialect::Haas);
    ASSERT_NE(code, nullptr) << "M" << number << " is missing from the Haas code table";
    EXPECT_EQ(code->group, gcode::ModalGroup::MBrake) << "M" << number;
  }
  // M14 with the spindle turning: A107, as M86.
  const Timeline turning = runText("G97 S500 M03\nM14\n", in(Dialect::Haas));
  ASSERT_TRUE(turning.alarm);
  EXPECT_EQ(turning.alarm->code, "A107");
  // M14 then M15 releases: the spindle may start again.
  const Timeline t = runText("M14\nM15\nG97 S500 M03\n", in(Dialect::Haas));
  ASSERT_FALSE(t.alarm);
  EXPECT_TRUE(t.snapshots[0].machine.brake);
  EXPECT_FALSE(t.snapshots[1].machine.brake);
}

}  // namespace
}  // namespace klueng::core::machine

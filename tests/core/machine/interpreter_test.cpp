// The interpreter: modal state, in-block order, motion geometry, time model.
#include "klueng/core/machine/interpreter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "klueng/core/machine/kinematics.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

using testing::at;
using testing::runText;
using testing::testSetup;

TEST(Interpreter, InitialStateFollowsSpec6) {
  const Timeline t = runText("G04 P0\n");
  // G04 under the initial G99 with the spindle stopped is an alarm (SPEC 8),
  // so read the initial state from a block that does nothing instead.
  const Timeline idle = runText("G97\n");
  ASSERT_EQ(idle.snapshots.size(), 1u);
  const StateSnapshot& s = idle.snapshots[0];
  EXPECT_EQ(s.modal.motion, MotionMode::Rapid);
  EXPECT_EQ(s.modal.units, Units::Mm);
  EXPECT_EQ(s.modal.noseComp, NoseCompMode::Off);
  EXPECT_EQ(s.modal.spindleMode, SpindleMode::ConstantRpm);
  EXPECT_EQ(s.modal.feedMode, FeedMode::PerRev);
  EXPECT_EQ(s.machine.spindle, SpindleDir::Stopped);
  EXPECT_FALSE(s.machine.brake);
  EXPECT_FALSE(s.machine.coolant);
  EXPECT_FALSE(s.machine.cAxisMode);
  EXPECT_EQ(s.machine.offset, 0);
  EXPECT_POINT(s.machine.position, 0.0, 300.0);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A104");
}

TEST(Interpreter, ModalStateIsKeptAndSnapshottedPerBlock) {
  const Timeline t = runText(
      "G98 G96 S120 M03\n"     // 1
      "G01 X40. Z290. F150\n"  // 2
      "Z280.\n"                // 3: still G01, F150
      "G97 S800 M08\n"         // 4
      "G99 G01 W-5. F0.1\n"    // 5
      "M09 M05\n");            // 6
  ASSERT_FALSE(t.alarm);
  ASSERT_EQ(t.snapshots.size(), 6u);
  EXPECT_EQ(t.snapshots[0].modal.feedMode, FeedMode::PerMinute);
  EXPECT_EQ(t.snapshots[0].modal.spindleMode, SpindleMode::ConstantSurface);
  EXPECT_DOUBLE_EQ(t.snapshots[0].modal.sWord, 120.0);
  EXPECT_EQ(t.snapshots[0].machine.spindle, SpindleDir::Cw);
  EXPECT_EQ(t.snapshots[2].modal.motion, MotionMode::Line);
  EXPECT_DOUBLE_EQ(t.snapshots[2].modal.feed, 150.0);
  EXPECT_POINT(t.snapshots[2].machine.position, 40.0, 280.0);
  EXPECT_TRUE(t.snapshots[3].machine.coolant);
  EXPECT_DOUBLE_EQ(t.snapshots[3].machine.rpm, 800.0);
  EXPECT_EQ(t.snapshots[4].modal.feedMode, FeedMode::PerRev);
  EXPECT_FALSE(t.snapshots[5].machine.coolant);
  EXPECT_EQ(t.snapshots[5].machine.spindle, SpindleDir::Stopped);
  EXPECT_DOUBLE_EQ(t.snapshots[5].machine.rpm, 0.0);
  // Each snapshot's time and moveEnd point at the end of its block's moves.
  for (const auto& s : t.snapshots) {
    if (s.moveEnd > 0) {
      EXPECT_DOUBLE_EQ(s.time, t.moves[static_cast<std::size_t>(s.moveEnd - 1)].tEnd);
    }
  }
  EXPECT_EQ(t.snapshots[5].moveEnd, static_cast<int>(t.moves.size()));
}

// T0000 on a Fanuc or Haas turret (a student's habit at the top of a program
// and before a tool change): tool 00 indexes nothing, offset 00 cancels the
// offset; the turret keeps the tool it has.
TEST(Interpreter, ToolZeroKeepsTheTurretAndCancelsTheOffset) {
  const Timeline t = runText("T0101\nG00 X40. Z10.\nT0000\nG00 X40. Z20.\n");
  ASSERT_FALSE(t.alarm);
  ASSERT_EQ(t.snapshots.size(), 4u);
  EXPECT_EQ(t.snapshots[0].machine.tool, 1);
  EXPECT_EQ(t.snapshots[0].machine.offset, 1);
  EXPECT_EQ(t.snapshots[2].machine.tool, 1);
  EXPECT_EQ(t.snapshots[2].machine.offset, 0);
  EXPECT_DOUBLE_EQ(t.snapshots[2].machine.offsetX, 0.0);
  EXPECT_DOUBLE_EQ(t.snapshots[2].machine.offsetZ, 0.0);
  EXPECT_EQ(t.moves.back().tool, 1);
}

TEST(Interpreter, InBlockOrderSpindleStartBeforeAndStopAfterTheMotion) {
  // M03 acts before the cut (no "spindle stopped" alarm), M05 after it.
  const Timeline t = runText(
      "G97 S1000\n"
      "G00 X20. Z290.\n"
      "M03 G01 W-10. F0.1\n"
      "G01 W-10. M05\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  ASSERT_EQ(t.moves.size(), 4u);  // rapid dog-leg (2) + two cuts
  EXPECT_EQ(t.moves[2].spindle, SpindleDir::Cw);
  EXPECT_DOUBLE_EQ(t.moves[2].rpm, 1000.0);
  EXPECT_EQ(t.moves[3].spindle, SpindleDir::Cw);  // still turning while it cuts
  EXPECT_EQ(t.snapshots.back().machine.spindle, SpindleDir::Stopped);
  // State words first: G98 and F in the same block as the move apply to it.
  const Timeline u = runText("G98 G01 X20. Z290. F600\n");
  ASSERT_FALSE(u.alarm);
  ASSERT_EQ(u.moves.size(), 1u);
  EXPECT_DOUBLE_EQ(u.moves[0].feed, 600.0);
}

TEST(Interpreter, G00IsADogLegEachAxisAtItsOwnRate) {
  // dX = 50 mm radius at 4000 mm/min = 0.75 s; dZ = 200 mm at 8000 = 1.5 s.
  // Both run 0.75 s (Z covers 100 mm), then Z alone for 0.75 s.
  const Timeline t = runText("G00 X100. Z100.\n");
  ASSERT_EQ(t.moves.size(), 2u);
  EXPECT_EQ(t.moves[0].kind, MoveKind::Rapid);
  EXPECT_POINT(t.moves[0].path.start, 0.0, 300.0);
  EXPECT_POINT(t.moves[0].path.end, 100.0, 200.0);
  EXPECT_NEAR(t.moves[0].tEnd, 0.75, 1e-9);
  EXPECT_POINT(t.moves[1].path.end, 100.0, 100.0);
  EXPECT_NEAR(t.moves[1].tEnd, 1.5, 1e-9);
  EXPECT_NEAR(t.moves[1].feed, 8000.0, 1e-6);
  EXPECT_NEAR(t.moves[0].feed, std::hypot(4000.0, 8000.0), 1e-6);
  EXPECT_NEAR(t.cycleTime(), 1.5, 1e-9);
  // One axis only, or both arriving together: one straight rapid.
  const Timeline u = runText("G00 X20. Z280.\n");  // 10 mm radius / 4000 = 20 mm / 8000 = 0.15 s
  ASSERT_EQ(u.moves.size(), 1u);
  EXPECT_NEAR(u.moves[0].tEnd, 0.15, 1e-9);
}

TEST(Interpreter, G99LineTimeIsLengthOverFeedTimesRpm) {
  const Timeline t = runText(
      "G97 S1000 M03\n"
      "G00 X40. Z250.\n"
      "G01 Z200. F0.2\n");
  ASSERT_FALSE(t.alarm);
  const Move& m = t.moves.back();
  EXPECT_EQ(m.kind, MoveKind::Line);
  EXPECT_NEAR(m.tEnd - m.tStart, 50.0 / (0.2 * 1000.0) * 60.0, 1e-9);  // 15 s
  EXPECT_DOUBLE_EQ(m.feed, 200.0);
  EXPECT_DOUBLE_EQ(m.rpm, 1000.0);
}

TEST(Interpreter, G98LineTimeIsLengthOverFeed) {
  const Timeline t = runText("G98\nG01 X60. Z260. F100.\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_NEAR(t.moves[0].tEnd, std::hypot(30.0, 40.0) / 100.0 * 60.0, 1e-9);  // 30 s
}

TEST(Interpreter, G96FacingTimeMatchesTheAnalyticIntegral) {
  // Face from X60 to X0 at F0.25 mm/rev, S150 m/min, clamp G50 S2000.
  // rpm(x) = 1000 S / (2 pi x) with x the radius, until it reaches 2000 at
  // x_c = 1000 S / (2 pi 2000). Time = (60 / F) * integral of dx / rpm(x):
  //   x from x_c to 30: x / C    -> (30^2 - x_c^2) / (2 C),  C = 1000 S / (2 pi)
  //   x from 0 to x_c:  1 / 2000 -> x_c / 2000
  const double c = 1000.0 * 150.0 / (2.0 * std::numbers::pi);
  const double xc = c / 2000.0;
  const double expected = 60.0 / 0.25 * ((30.0 * 30.0 - xc * xc) / (2.0 * c) + xc / 2000.0);
  const Timeline t = runText(
      "G50 S2000\n"
      "G96 S150 M03\n"
      "G00 X60. Z0.\n"
      "G01 X0. F0.25\n");
  ASSERT_FALSE(t.alarm);
  const Move& m = t.moves.back();
  EXPECT_NEAR(m.tEnd - m.tStart, expected, 1e-9);
  EXPECT_NEAR(m.rpm, 1000.0 * 150.0 / (std::numbers::pi * 60.0), 1e-9);  // 795.77 at X60
  EXPECT_DOUBLE_EQ(m.rpmEnd, 2000.0);                                    // clamped at the centre
  EXPECT_NEAR(m.feed, 0.25 * m.rpm, 1e-9);
  // Without G50 S the machine maximum (3000) clamps.
  const Timeline u = runText("G96 S150 M03\nG00 X60. Z0.\nG01 X0. F0.25\n");
  EXPECT_DOUBLE_EQ(u.moves.back().rpmEnd, 3000.0);
}

TEST(Interpreter, G96ArcTimeMatchesAFineNumericIntegral) {
  // A quarter circle R10 from X20 Z0 (radius 10) to X40 Z-10 under G96 S100,
  // checked against a 200000-step midpoint rule of ds / (F rpm(x)).
  const Timeline t = runText("G96 S100 M03\nG00 X20. Z0.\nG02 X40. Z-10. R10. F0.2\n");
  ASSERT_FALSE(t.alarm);
  const Move& m = t.moves.back();
  ASSERT_EQ(m.kind, MoveKind::Arc);
  const int n = 200000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec2 p = m.path.pointAt((i + 0.5) / n);
    const double rpm = std::min(1000.0 * 100.0 / (std::numbers::pi * 2.0 * p.y()), 3000.0);
    sum += m.path.length() / n / (0.2 * rpm);
  }
  EXPECT_NEAR(m.tEnd - m.tStart, sum * 60.0, 1e-6);
}

TEST(Interpreter, ArcByRadiusShortAndLongAndByCentre) {
  // From X20 Z0: G02 to X30 Z-5 with R5. Chord (dz, dx) = (-5, 5), half 3.536,
  // the centre lies 3.536 mm from the chord's middle (Z-2.5, x 12.5) on the
  // right of travel (clockwise, short arc): (Z0, x 15). Sweep 90 degrees.
  const char* prefix = "G98 G00 X20. Z0.\n";
  Timeline t = runText(std::string(prefix) + "G02 X30. Z-5. R5. F100\n");
  ASSERT_FALSE(t.alarm);
  Move m = t.moves.back();
  ASSERT_EQ(m.kind, MoveKind::Arc);
  EXPECT_FALSE(m.path.ccw);
  EXPECT_POINT(m.path.centre, 30.0, 0.0);
  EXPECT_NEAR(m.path.sweep(), std::numbers::pi / 2, 1e-9);
  EXPECT_NEAR(m.tEnd - m.tStart, 5.0 * std::numbers::pi / 2 / 100.0 * 60.0, 1e-9);
  // the long way round (270 degrees), centre mirrored across the chord.
  t = runText(std::string(prefix) + "G02 X30. Z-5. R-5. F100\n");
  m = t.moves.back();
  EXPECT_POINT(m.path.centre, 20.0, -5.0);
  EXPECT_NEAR(m.path.sweep(), 3 * std::numbers::pi / 2, 1e-9);
  // The same arc by I/K (I as a radius): centre = start + (K, I).
  t = runText(std::string(prefix) + "G02 X30. Z-5. I5. K0. F100\n");
  m = t.moves.back();
  EXPECT_POINT(m.path.centre, 30.0, 0.0);
  // G03 X40 Z-22 R2 from X36 Z-20 (sample 01): centre Z-22 X36, quarter circle.
  t = runText("G98 G00 X36. Z-20.\nG03 X40. Z-22. R2. F100\n");
  m = t.moves.back();
  EXPECT_TRUE(m.path.ccw);
  EXPECT_POINT(m.path.centre, 36.0, -22.0);
}

TEST(Interpreter, G28GoesViaTheIntermediatePointAndG29ComesBackThroughIt) {
  const Timeline t = runText(
      "G00 X40. Z50.\n"    // 1
      "G28 X60. Z100.\n"   // 2: via X60 Z100 to the reference X0 Z300
      "G29 X30. Z20.\n");  // 3: via X60 Z100 to X30 Z20
  ASSERT_FALSE(t.alarm);
  std::vector<Move> g28, g29;
  for (const Move& m : t.moves) (m.line == 2 ? g28 : m.line == 3 ? g29 : g28).push_back(m);
  g28.erase(g28.begin(), g28.begin() + 2);  // the two rapids of line 1
  ASSERT_EQ(g28.size(), 4u);
  // To the intermediate point: dX 10 (0.15 s), dZ 50 (0.375 s).
  EXPECT_POINT(g28[0].path.end, 60.0, 70.0);
  EXPECT_POINT(g28[1].path.end, 60.0, 100.0);
  // To the reference point: dX 30 (0.45 s), dZ 200 (1.5 s): Z covers 60 first.
  EXPECT_POINT(g28[2].path.end, 0.0, 160.0);
  EXPECT_POINT(g28[3].path.end, 0.0, 300.0);
  EXPECT_NEAR(g28[3].tEnd - g28[0].tStart, 0.375 + 1.5, 1e-9);
  EXPECT_TRUE(t.snapshots[1].machine.positionCheck);
  ASSERT_EQ(g29.size(), 4u);
  EXPECT_POINT(g29[0].path.end, 60.0, 240.0);
  EXPECT_POINT(g29[1].path.end, 60.0, 100.0);
  EXPECT_POINT(g29[2].path.end, 30.0, 70.0);
  EXPECT_POINT(g29[3].path.end, 30.0, 20.0);
  EXPECT_FALSE(t.snapshots[2].machine.positionCheck);
}

TEST(Interpreter, G28WithoutAxesMovesNothingAndOnlyGivenAxesReturn) {
  Timeline t = runText("G00 X40. Z50.\nG28\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_EQ(t.moves.size(), 2u);
  t = runText("G00 X40. Z50.\nG28 U0.\n");  // X only: straight up to X0, Z stays
  ASSERT_EQ(t.moves.size(), 3u);
  EXPECT_POINT(t.moves.back().path.end, 0.0, 50.0);
}

TEST(Interpreter, G27LightsThePositionCheckLampAtTheReferencePoint) {
  const Timeline t = runText("G00 X40. Z50.\nG27 X0. Z300.\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_TRUE(t.snapshots.back().machine.positionCheck);
  EXPECT_POINT(t.moves.back().path.end, 0.0, 300.0);
}

TEST(Interpreter, G50SetsTheCoordinatesOfTheCurrentPosition) {
  const Timeline t = runText(
      "G50 X100. Z50.\n"  // the tool (at the start position) now reads X100 Z50
      "G00 X80. Z40.\n"   // dX 10 radius (0.15 s), dZ 10 (0.075 s)
      "G28 U0. W0.\n");   // the reference point is where the tool started
  ASSERT_FALSE(t.alarm);
  EXPECT_POINT(t.snapshots[0].machine.position, 100.0, 50.0);
  EXPECT_TRUE(t.moves.empty() || t.moves[0].line == 2);
  ASSERT_GE(t.moves.size(), 2u);
  EXPECT_POINT(t.moves[0].path.start, 100.0, 50.0);
  EXPECT_POINT(t.moves[0].path.end, 90.0, 40.0);
  EXPECT_POINT(t.moves[1].path.end, 80.0, 40.0);
  EXPECT_POINT(t.moves.back().path.end, 100.0, 50.0);
}

TEST(Interpreter, G50SClampsTheRpmUnderG96) {
  const Timeline t = runText("G50 S1200\nG96 S200 M03\nG00 X10. Z5.\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_DOUBLE_EQ(t.snapshots[0].modal.rpmClamp, 1200.0);
  EXPECT_DOUBLE_EQ(t.snapshots.back().machine.rpm, 1200.0);  // 6366 rpm at X10, clamped
}

TEST(Interpreter, ToolOffsetsShiftTheControlledPointAndOffset00Cancels) {
  // Offset 02: X +0.4 (diameter), Z -0.2.
  const Timeline t = runText(
      "T0202\n"
      "G00 X20. Z10.\n"
      "G00 U-2.\n"
      "T0200\n"
      "G00 X20.\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_EQ(t.snapshots[0].machine.tool, 2);
  EXPECT_EQ(t.snapshots[0].machine.offset, 2);
  EXPECT_DOUBLE_EQ(t.snapshots[0].machine.offsetX, 0.4);
  EXPECT_POINT(t.snapshots[0].machine.position, 0.0, 300.0);  // a new offset does not jump
  EXPECT_POINT(t.snapshots[1].machine.position, 20.4, 9.8);
  EXPECT_POINT(t.snapshots[2].machine.position, 18.4, 9.8);  // U is a plain displacement
  EXPECT_EQ(t.snapshots[3].machine.offset, 0);
  EXPECT_POINT(t.snapshots[4].machine.position, 20.0, 9.8);
  // The nose of offset 01 (R0.8, tip 3) sits up and right of the controlled point.
  const Timeline u = runText("T0101\nG00 X20.\n");
  EXPECT_NEAR(u.moves[0].noseCentre.x(), 0.8, 1e-12);
  EXPECT_NEAR(u.moves[0].noseCentre.y(), 0.8, 1e-12);
}

TEST(Interpreter, G20ConvertsInchWordsToMillimetres) {
  const Timeline t = runText("G20 G98\nG00 X1. Z1.\nG01 W-1. F10.\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_POINT(t.snapshots[1].machine.position, 25.4, 25.4);
  EXPECT_POINT(t.moves.back().path.end, 25.4, 0.0);
  EXPECT_NEAR(t.moves.back().feed, 254.0, 1e-9);
  EXPECT_NEAR(t.moves.back().tEnd - t.moves.back().tStart, 6.0, 1e-9);  // 25.4 mm at 254 mm/min
}

TEST(Interpreter, G04DwellsForSecondsOrMilliseconds) {
  const Timeline t = runText("G98\nG04 X1.5\nG04 U2.\nG04 P500\n");
  ASSERT_FALSE(t.alarm);
  ASSERT_EQ(t.moves.size(), 3u);
  EXPECT_EQ(t.moves[0].kind, MoveKind::Dwell);
  EXPECT_NEAR(t.moves[0].tEnd, 1.5, 1e-12);
  EXPECT_NEAR(t.moves[1].tEnd, 3.5, 1e-12);
  EXPECT_NEAR(t.moves[2].tEnd, 4.0, 1e-12);
  EXPECT_POINT(t.moves[2].path.start, 0.0, 300.0);
}

TEST(Interpreter, G32RunsAtLeadTimesRpm) {
  const Timeline t = runText("G97 S500 M03\nG00 X30. Z5.\nG32 Z-25. F1.5\n");
  ASSERT_FALSE(t.alarm);
  const Move& m = t.moves.back();
  EXPECT_EQ(m.kind, MoveKind::Thread);
  EXPECT_DOUBLE_EQ(m.lead, 1.5);
  EXPECT_DOUBLE_EQ(m.feed, 750.0);
  EXPECT_NEAR(m.tEnd - m.tStart, 30.0 / 750.0 * 60.0, 1e-9);
}

TEST(Interpreter, ProgramStopsOptionalStopAndEnd) {
  const char* text = "M00\nM01\nG00 X10.\nM30\nG00 X50.\n";
  Timeline t = runText(text);
  ASSERT_EQ(t.snapshots.size(), 4u);  // nothing after M30 runs
  EXPECT_TRUE(t.snapshots[0].stopped);
  EXPECT_FALSE(t.snapshots[1].stopped);  // switch off
  EXPECT_TRUE(t.snapshots[3].stopped);
  EXPECT_POINT(t.moves.back().path.end, 10.0, 300.0);
  RunOptions on;
  on.optionalStop = true;
  t = runText(text, on);
  EXPECT_TRUE(t.snapshots[1].stopped);
  EXPECT_TRUE(t.snapshots[1].machine.optionalStopSwitch);
  on.stopAtM00 = true;
  t = runText(text, on);
  EXPECT_EQ(t.snapshots.size(), 1u);
}

TEST(Interpreter, BlockSkipSwitch) {
  const char* text = "G00 X10.\n/G00 X50.\nG00 Z250.\n";
  Timeline t = runText(text);
  EXPECT_EQ(t.snapshots.size(), 3u);
  EXPECT_POINT(t.moves.back().path.end, 50.0, 250.0);
  RunOptions skip;
  skip.blockSkip = true;
  t = runText(text, skip);
  ASSERT_EQ(t.snapshots.size(), 2u);
  EXPECT_EQ(t.snapshots[1].line, 3);
  EXPECT_POINT(t.moves.back().path.end, 10.0, 250.0);
}

TEST(Interpreter, CAxisModeWithBrakeInClassicDialect) {
  RunOptions classic;
  classic.dialect = gcode::Dialect::Classic;
  const Timeline t = runText("M86\nM41\nG00 C90.\nG00 H-100.\nM91\nM87\n", classic);
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  EXPECT_TRUE(t.snapshots[1].machine.cAxisMode);
  EXPECT_DOUBLE_EQ(t.snapshots[2].machine.cAngle, 90.0);
  EXPECT_DOUBLE_EQ(t.snapshots[3].machine.cAngle, 350.0);
  EXPECT_FALSE(t.snapshots[5].machine.brake);
}

TEST(Interpreter, FanucM41SelectsAGearRangeWithoutMotion) {
  const Timeline t = runText("M42\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_EQ(t.snapshots[0].machine.gearRange, 2);
  EXPECT_TRUE(t.moves.empty());
}

TEST(Interpreter, FanucExtrasAreNoOpsOrMachineCoordinates) {
  const Timeline t = runText("G18 G21 G40 G80 G99\nG55\nG50 X100. Z50.\nG53 X0. Z-20.\nG53 X0. Z0.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  EXPECT_EQ(t.snapshots[1].modal.workCoordinate, 55);
  // Machine zero is the reference point (X0 Z300, where the tool started),
  // which reads X100 Z50 after G50; machine Z-20 is 20 mm short of it.
  EXPECT_POINT(t.snapshots[3].machine.position, 100.0, 30.0);
  EXPECT_POINT(t.snapshots.back().machine.position, 100.0, 50.0);
}

TEST(Interpreter, SampleOneCycleTimeMatchesAHandCalculation) {
  // See SampleCycleTime in samples_test.cpp for the full derivation; here the
  // G96 facing move N70 alone: X54 -> X-1.6 at Z0, F0.2, S180, clamp 2500.
  const double c = 1000.0 * 180.0 / (2.0 * std::numbers::pi);  // 28647.9 rpm*mm
  const double xc = c / 2500.0;                                // 11.459 mm radius
  const double expected = 60.0 / 0.2 * ((27.0 * 27.0 - xc * xc) / (2.0 * c) + (xc + 0.8) / 2500.0);
  const Timeline t = runText("G99\nT0101\nG50 S2500\nG96 S180 M03\nG00 X54. Z2. M08\nZ0.\nG01 X-1.6 F0.2\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_NEAR(t.moves.back().tEnd - t.moves.back().tStart, expected, 1e-9);
  EXPECT_NEAR(expected, 4.6006, 1e-4);
}

TEST(Kinematics, SpindleRpmUnderG96IsClampedAndZeroWhenStopped) {
  MotionContext c;
  c.spindleMode = SpindleMode::ConstantSurface;
  c.sWord = 100.0;
  c.rpmCap = 2000.0;
  c.spindle = SpindleDir::Cw;
  EXPECT_NEAR(spindleRpm(c, 25.0), 1000.0 * 100.0 / (std::numbers::pi * 50.0), 1e-9);
  EXPECT_DOUBLE_EQ(spindleRpm(c, 0.0), 2000.0);
  EXPECT_DOUBLE_EQ(spindleRpm(c, -1.0), 2000.0);
  c.spindle = SpindleDir::Stopped;
  EXPECT_DOUBLE_EQ(spindleRpm(c, 25.0), 0.0);
}

}  // namespace
}  // namespace klueng::core::machine

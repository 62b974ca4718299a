// Cycle time with acceleration (issue 11): with machine.cfg accel_x/accel_z set,
// every move speeds up and slows down as the control plans it. Each expected
// time below is worked out by hand from the move's length, feed and limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/kinematics.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

using testing::at;
using testing::runText;
using testing::testSetup;

// Z 500 mm/s², X 250 mm/s² (radial): a slow school lathe, so the ramps are long
// enough to see in the figures.
MachineSetup acceleratingSetup() {
  MachineSetup s = testSetup();
  s.machine.accelZ = 500.0;
  s.machine.accelX = 250.0;
  return s;
}

constexpr char kProgram[] =
    "G98 T0101\n"
    "G00 X20. Z2.\n"    // 2: rapid, both axes
    "G01 Z1.9 F600.\n"  // 3: 0.1 mm at 10 mm/s: too short to reach the feed
    "Z-48.1\n"          // 4: 50 mm: trapezoid
    "X40. Z-58.1\n"     // 5: 10 mm radial and 10 mm along Z: X holds the ramp
    "M30\n";

double blockSeconds(const Timeline& t, int line) {
  double seconds = 0.0;
  for (const Move& m : t.moves)
    if (m.line == line) seconds += m.tEnd - m.tStart;
  return seconds;
}

TEST(Acceleration, AShortMoveIsATriangleThatNeverReachesItsFeed) {
  const Timeline t = runText(kProgram, {}, acceleratingSetup());
  ASSERT_FALSE(t.alarm);
  // 0.1 mm would need v²/a = 10²/500 = 0.2 mm to speed up and slow down:
  // up 0.05 mm and down again, T = 2 * sqrt(0.1 / 500).
  EXPECT_NEAR(blockSeconds(t, 3), 2.0 * std::sqrt(0.1 / 500.0), 1e-9);
  EXPECT_NEAR(blockSeconds(t, 3), 0.0282843, 1e-6);
}

TEST(Acceleration, ALongMoveCruisesAtItsFeedBetweenTwoRamps) {
  const Timeline t = runText(kProgram, {}, acceleratingSetup());
  // 50 mm at 10 mm/s = 5 s, plus half of each 0.02 s ramp (10 / 500).
  EXPECT_NEAR(blockSeconds(t, 4), 5.02, 1e-9);
  const Move& m = *std::find_if(t.moves.begin(), t.moves.end(), [](const Move& mv) { return mv.line == 4; });
  EXPECT_NEAR(m.rampUp, 0.02, 1e-7);
  EXPECT_NEAR(m.rampDown, 0.02, 1e-7);
  // Half way in time is half way along; at the end of the first ramp the tool
  // has covered 0.1 mm (v * up / 2) of 50. (Ramps are kept as floats: 1e-7.)
  EXPECT_NEAR(m.fractionAt((m.tStart + m.tEnd) / 2.0), 0.5, 1e-12);
  EXPECT_NEAR(m.fractionAt(m.tStart + 0.02) * 50.0, 0.1, 1e-7);
  EXPECT_NEAR(m.timeAt(0.1 / 50.0), m.tStart + 0.02, 1e-7);
  const Vec2 early = t.positionAt(m.tStart + 0.01);  // a t² / 2 = 500 * 0.01² / 2 = 0.025 mm in
  EXPECT_NEAR(early.x(), 1.9 - 0.025, 1e-7);
}

TEST(Acceleration, ADiagonalMoveIsHeldByTheAxisThatReachesItsLimitFirst) {
  const Timeline t = runText(kProgram, {}, acceleratingSetup());
  // 10 mm radial and 10 mm in Z: each axis carries 1/sqrt(2) of the path
  // acceleration, so X (250) allows 250 * sqrt(2) = 353.55 mm/s² along the path.
  const double length = std::sqrt(200.0);
  const double accel = 250.0 * std::sqrt(2.0);
  EXPECT_NEAR(blockSeconds(t, 5), length / 10.0 + 10.0 / accel, 1e-9);
  EXPECT_NEAR(blockSeconds(t, 5), 1.4424978, 1e-6);
}

TEST(Acceleration, ARapidMovesEachAxisAtItsOwnRateAndAcceleration) {
  const Timeline t = runText(kProgram, {}, acceleratingSetup());
  // From X0 Z300 to X20 Z2. Z: 298 mm at 8000/60 mm/s, ramps of (8000/60)/500 s:
  // 298 / 133.33 + 133.33 / 500 = 2.50167 s. X: 10 mm (radius) at 4000/60 mm/s
  // cannot reach its rate (66.67² / 250 = 17.8 mm > 10): 2 * sqrt(10 / 250) = 0.4 s.
  const double rateZ = 8000.0 / 60.0;
  EXPECT_NEAR(blockSeconds(t, 2), 298.0 / rateZ + rateZ / 500.0, 1e-9);
  // The dog-leg turns where X arrives: Z has come 35.56 mm by 0.4 s
  // (ramp of 0.2667 s, then cruising).
  const double ramp = rateZ / 500.0;
  const double zDone = rateZ * ramp / 2.0 + rateZ * (0.4 - ramp);
  int rapids = 0;
  for (const Move& m : t.moves)
    if (m.line == 2) {
      if (rapids == 0) {
        EXPECT_NEAR(m.tEnd - m.tStart, 0.4, 1e-9);
        EXPECT_POINT(m.path.end, 20.0, 300.0 - zDone);
      }
      ++rapids;
    }
  EXPECT_EQ(rapids, 2);
}

TEST(Acceleration, TheProgramTotalIsTheSumOfItsMoves) {
  const Timeline t = runText(kProgram, {}, acceleratingSetup());
  const double rateZ = 8000.0 / 60.0;
  const double expected = (298.0 / rateZ + rateZ / 500.0) + 2.0 * std::sqrt(0.1 / 500.0) + 5.02 +
                          (std::sqrt(200.0) / 10.0 + 10.0 / (250.0 * std::sqrt(2.0)));
  EXPECT_NEAR(t.cycleTime(), expected, 1e-9);
  // Without acceleration the same program takes length / feed, as before.
  const Timeline plain = runText(kProgram);
  const double plainExpected = 298.0 / rateZ + 0.1 / 10.0 + 5.0 + std::sqrt(200.0) / 10.0;
  EXPECT_NEAR(plain.cycleTime(), plainExpected, 1e-9);
  EXPECT_GT(t.cycleTime(), plain.cycleTime());
}

TEST(Acceleration, FeedPerRevolutionRampsToFeedTimesRpm) {
  MachineSetup s = acceleratingSetup();
  // G99 F0.2 at S1500: 300 mm/min = 5 mm/s; 20 mm along Z: 4 s + 5/500 s.
  const Timeline t = runText("G99 G97 S1500 M03 T0101\nG00 X20. Z2.\nG01 Z-18. F0.2\nM30\n", {}, s);
  ASSERT_FALSE(t.alarm);
  EXPECT_NEAR(blockSeconds(t, 3), 4.0 + 5.0 / 500.0, 1e-9);
}

TEST(Acceleration, RampsAddUpToTheMoveAndMapBothWays) {
  EXPECT_NEAR(rampMove(50.0, 5.0, 10.0, 10.0, 500.0).seconds, 5.02, 1e-12);
  EXPECT_NEAR(rampMove(0.1, 0.01, 10.0, 10.0, 500.0).seconds, 2.0 * std::sqrt(0.1 / 500.0), 1e-12);
  EXPECT_DOUBLE_EQ(rampMove(50.0, 5.0, 10.0, 10.0, 0.0).seconds, 5.0);  // off
  EXPECT_NEAR(axisDistanceAt(0.2, 10.0, 66.0, 250.0), 250.0 * 0.04 / 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(axisDistanceAt(1.0, 10.0, 66.0, 250.0), 10.0);
  Move m;
  m.tStart = 1.0;
  m.tEnd = 3.0;
  m.rampUp = 0.5f;
  m.rampDown = 0.25f;
  for (double f : {0.0, 0.01, 0.1, 0.3, 0.5, 0.8, 0.95, 0.999, 1.0}) EXPECT_NEAR(m.fractionAt(m.timeAt(f)), f, 1e-9);
  EXPECT_DOUBLE_EQ(m.fractionAt(0.5), 0.0);
  EXPECT_DOUBLE_EQ(m.fractionAt(4.0), 1.0);
}

TEST(Acceleration, MachineCfgReadsTheLimitsAndRefusesNegativeOnes) {
  const auto r = io::parseMachineConfig("accel_x = 1200\naccel_z = 2500\n", "m.cfg");
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(r.value->accelX, 1200.0);
  EXPECT_DOUBLE_EQ(r.value->accelZ, 2500.0);
  const auto bad = io::parseMachineConfig("accel_z = -5\n", "m.cfg");
  ASSERT_EQ(bad.diagnostics.size(), 1u);
  EXPECT_EQ(bad.diagnostics[0].range.line, 1);
  EXPECT_EQ(bad.diagnostics[0].range.column, 11);
  const auto defaults = io::parseMachineConfig("rapid_x = 4000\n", "m.cfg");
  ASSERT_TRUE(defaults.ok());
  EXPECT_DOUBLE_EQ(defaults.value->accelX, 0.0);
}

}  // namespace
}  // namespace klueng::core::machine

namespace klueng::core::machine {
namespace {

TEST(CycleTime, SplitsByToolInTheOrderTheToolsAreFirstUsed) {
  // T01: rapid 298 mm in Z (2.235 s) and 10 mm at 100 mm/min (6 s); T04: 1 s dwell
  // and 5 mm at 100 mm/min (3 s); back to T01 for a 5 mm move (3 s).
  const Timeline t =
      testing::runText("G98 T0101\nG00 X20. Z2.\nG01 Z-8. F100.\nT0404\nG04 P1000\nG01 Z-13.\nT0101\nG01 Z-18.\nM30\n");
  ASSERT_FALSE(t.alarm);
  const std::vector<ToolTime> byTool = t.timeByTool();
  ASSERT_EQ(byTool.size(), 2u);
  EXPECT_EQ(byTool[0].tool, 1);
  EXPECT_NEAR(byTool[0].seconds, 298.0 / (8000.0 / 60.0) + 6.0 + 3.0, 1e-9);
  EXPECT_EQ(byTool[1].tool, 4);
  EXPECT_NEAR(byTool[1].seconds, 1.0 + 3.0, 1e-9);
  EXPECT_NEAR(byTool[0].seconds + byTool[1].seconds, t.cycleTime(), 1e-9);
}

}  // namespace
}  // namespace klueng::core::machine

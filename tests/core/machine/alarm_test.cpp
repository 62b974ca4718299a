// Run-time alarms (SPEC 8): code, line and column of the offending word; the
// run stops there and the timeline up to it stays usable.
#include <gtest/gtest.h>

#include <string>

#include "klueng/core/messages.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

using testing::runText;

struct AlarmCase {
  const char* name;
  const char* program;
  gcode::Dialect dialect;
  const char* code;
  int line;
  int column;
  int snapshotsBefore;  // blocks executed before the alarm
};

void PrintTo(const AlarmCase& c, std::ostream* os) { *os << c.name; }

class AlarmTest : public ::testing::TestWithParam<AlarmCase> {};

TEST_P(AlarmTest, StopsOnTheOffendingWord) {
  const AlarmCase& c = GetParam();
  RunOptions options;
  options.dialect = c.dialect;
  const Timeline t = runText(c.program, options);
  ASSERT_TRUE(t.alarm.has_value()) << "no alarm";
  EXPECT_EQ(t.alarm->code, c.code);
  EXPECT_EQ(t.alarm->severity, Severity::Alarm);
  EXPECT_EQ(t.alarm->range.line, c.line);
  EXPECT_EQ(t.alarm->range.column, c.column);
  EXPECT_EQ(static_cast<int>(t.snapshots.size()), c.snapshotsBefore);
  // Both languages have a real text with every placeholder filled.
  const std::string en = formatMessage(*t.alarm, Lang::En);
  const std::string th = formatMessage(*t.alarm, Lang::Th);
  EXPECT_EQ(en.find('?'), std::string::npos) << en;
  EXPECT_EQ(en.find('{'), std::string::npos) << en;
  EXPECT_NE(en, th);
  EXPECT_NE(en, c.code);
  // No move of the offending block is in the timeline (G27 moves, then checks).
  if (std::string(c.code) != "A115") {
    for (const Move& m : t.moves) EXPECT_NE(m.line, c.line);
  }
}

constexpr auto F = gcode::Dialect::Fanuc;
constexpr auto C = gcode::Dialect::Classic;

INSTANTIATE_TEST_SUITE_P(
    Spec8, AlarmTest,
    ::testing::Values(
        AlarmCase{"SpeedAboveMaximum", "G97 S3500 M03\n", C, "A101", 1, 5, 0},
        AlarmCase{"SpeedAboveMaximumLater", "G00 X20.\nS3001\n", C, "A101", 2, 1, 1},
        AlarmCase{"NoFeedG01", "G98\nG01 X10. Z10.\n", F, "A102", 2, 1, 1},
        AlarmCase{"NoFeedModalArc", "G98\nG02 X10. Z290. R20.\n", F, "A102", 2, 1, 1},
        AlarmCase{"NoFeedG32", "G97 S100 M03\nG32 Z10.\n", F, "A102", 2, 1, 1},
        AlarmCase{"G99WithoutS", "M03\nG01 X10. F0.2\n", F, "A103", 2, 1, 1},
        AlarmCase{"G99SpindleStopped", "G98 G01 X20. Z10. F100\nG99\n  X18.\n", F, "A104", 3, 3, 2},
        AlarmCase{"G04UnderG99SpindleStopped", "G04 X1.\n", F, "A104", 1, 1, 0},
        AlarmCase{"ReversalWithoutM05", "S500 M03\nM04\n", C, "A105", 2, 1, 1},
        AlarmCase{"StartWithBrakeOn", "M86\nS100 M03\n", F, "A106", 2, 6, 1},
        AlarmCase{"BrakeWhileTurning", "S100 M03\nM86\n", F, "A107", 2, 1, 1},
        AlarmCase{"ThreadUnderG96", "G96 S100 M03\nG32 Z-10. F1.\n", C, "A108", 2, 1, 1},
        AlarmCase{"COutsideCAxisMode", "G00 C90.\n", C, "A109", 1, 5, 0},
        AlarmCase{"HOutsideCAxisMode", "M86\nH10.\n", C, "A109", 2, 1, 1},
        // Fanuc and Haas profiles have no C-axis mode: "X30. C2." is a chamfer written without the comma.
        AlarmCase{"CWithoutCAxisIsAChamferWithoutItsComma", "G98 G01 X30. C2. F100\n", F, "A152", 1, 14, 0},
        AlarmCase{"CAxisWithoutBrake", "M41\n", C, "A110", 1, 1, 0},
        AlarmCase{"BrakeReleaseInCAxisMode", "M86\nM41\nM87\n", C, "A111", 3, 1, 2},
        AlarmCase{"TravelLimitZ", "G00 Z1200.\n", F, "A112", 1, 1, 0},
        AlarmCase{"TravelLimitArc", "G98 G00 X900. Z0.\nG03 X900. Z-200. R100. F100\n", F, "A112", 2, 1, 1},
        AlarmCase{"ArcNotOnOneCircle", "G98 G00 X20. Z0.\nG02 X30. Z-5. I5. K1. F100\n", F, "A113", 2, 15, 1},
        AlarmCase{"ArcRadiusTooSmall", "G98 G00 X20. Z0.\nG02 X30. Z-5. R3. F100\n", F, "A114", 2, 15, 1},
        AlarmCase{"G27NotAtReference", "G27 X10. Z20.\n", F, "A115", 1, 1, 0},
        AlarmCase{"ThreadSpindleStopped", "G97 S500\nG32 Z-10. F1.\n", F, "A116", 2, 1, 1},
        AlarmCase{"SubprogramMissing", "M98 P1000\n", F, "A135", 1, 1, 0},
        AlarmCase{"OffsetDoesNotExist", "G00 X10.\nT0165\n", F, "A118", 2, 1, 1},
        AlarmCase{"ThreadWithoutS", "M03\nG32 Z-10. F1.\n", F, "A119", 2, 1, 1},
        // Canned cycles (cycles_test.cpp has their motion).
        AlarmCase{"CycleProfileNotFound",
                  "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\n"
                  "G71 P10 Q20 U0.4 F100.\n",
                  F, "A120", 4, 5, 3},
        AlarmCase{"CycleProfileNotMonotonic",
                  "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\n"
                  "G71 P10 Q20 F100.\nN10 G00 X30.\nG01 Z-20.\nX40.\nZ-30.\nN20 X36.\n",
                  F, "A121", 9, 1, 3},
        // Fanuc PS0065: the profile's first block (N10 alone) holds no G00/G01.
        AlarmCase{"CycleProfileFirstBlockWithoutG00G01",
                  "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\n"
                  "G71 P10 Q20 F100.\nN10\nG00 X30.\nN20 G01 Z-20.\n",
                  F, "A153", 5, 1, 3},
        AlarmCase{"CycleDepthZero", "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U0 R0.5\n", F, "A122", 3, 5, 2},
        AlarmCase{"CycleUnderNoseComp", "G98 G97 S500 M03 T0101\nG42 G00 X50. Z2.\nG71 U2. R0.5\n", C, "A123", 3, 1, 2},
        // A first block that moves along Z without naming X is neither type I nor II.
        AlarmCase{"CycleProfileFirstBlockAlongZ",
                  "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\n"
                  "G71 P10 Q20 F100.\nN10 G00 Z0.\nN20 G01 X30.\n",
                  F, "A124", 5, 1, 3},
        AlarmCase{"CycleProfileWithoutMoves",
                  "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\n"
                  "G71 P10 Q20 F100.\nN10 G00 X30.\nN20 F0.2\n",
                  F, "A125", 4, 5, 3},
        AlarmCase{"CycleWithoutQ", "G98 G97 S500 M03\nG00 X50. Z2.\nG70 P10\nN10 G01 X30.\n", F, "A126", 3, 1, 2},
        AlarmCase{"CycleTooManyPecks", "G98 G97 S500 M03\nG00 X0. Z2.\nG74 R1.\nG74 Z-100. Q1 F100.\n", F, "A127", 4,
                  12, 3}),
    [](const ::testing::TestParamInfo<AlarmCase>& i) { return std::string(i.param.name); });

TEST(Alarm, SampleFiveStopsOnN40) {
  // 05-runtime-alarms.txt body, line 12 = N40 (after six header lines and O0005).
  const Timeline t = runText(
      "\n\n\n\n\n\n"
      "O0005\n"
      "N10 G21 G97\n"
      "N15 G99\n"
      "N20 T0101\n"
      "N30 G00 X45. Z2.\n"
      "N40 G01 X38. Z-10. F0.2 (alarm: cutting while the spindle is stopped)\n"
      "N50 M30\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A104");
  EXPECT_EQ(t.alarm->range.line, 12);
  EXPECT_EQ(t.alarm->range.column, 5);
  // The timeline up to it stays usable: the rapid of N30 is there.
  ASSERT_EQ(t.moves.size(), 2u);
  EXPECT_EQ(t.moves.back().line, 11);
  EXPECT_EQ(t.snapshots.back().line, 11);
  EXPECT_DOUBLE_EQ(t.cycleTime(), t.moves.back().tEnd);
}

// A Fanuc clamps an S above the spindle's maximum and reverses M03 -> M04 without M05: warnings
// W132/W133 (no source says the control stops; issue 38), the run goes on at the maximum.
TEST(Alarm, AFanucClampsTheSpeedAndReversesTheSpindle) {
  RunOptions fanuc;
  fanuc.dialect = gcode::Dialect::Fanuc;
  const Timeline t = runText("G97 S3500 M03\nG98 G01 X20. F100.\nM04\nG01 X30.\n", fanuc);
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  std::vector<std::string> codes;
  for (const Diagnostic& d : t.flow.notices) codes.push_back(d.code + "@" + std::to_string(d.range.line));
  EXPECT_EQ(codes, (std::vector<std::string>{"W132@1", "W133@3"}));
  ASSERT_FALSE(t.snapshots.empty());
  EXPECT_DOUBLE_EQ(t.snapshots.front().modal.sWord, testing::testSetup().machine.maxSpindleRpm);
}

TEST(Alarm, TheTimelineBeforeTheAlarmIsKept) {
  RunOptions classic;
  classic.dialect = gcode::Dialect::Classic;  // the 1999 trainer stops on M04 after M03
  const Timeline t = runText("G98\nG01 X20. Z290. F100\nG01 X30.\nS100 M03\nM04\nG00 X0.\n", classic);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A105");
  EXPECT_EQ(t.snapshots.size(), 4u);
  EXPECT_EQ(t.moves.size(), 2u);
  EXPECT_POINT(t.positionAt(1e9), 30.0, 290.0);
}

TEST(Alarm, NoseCompInterferenceComesFromTheKernel) {
  // A concave R0.3 fillet is smaller than the nose radius R0.8 of offset 01.
  const Timeline t = runText(
      "G98 T0101\n"
      "G42 G00 X20. Z2.\n"
      "G01 Z-10. F100\n"
      "G02 X20.6 Z-10.3 R0.3\n"
      "G01 X30.\n"
      "G40 G00 X50. Z10.\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A201");
  EXPECT_EQ(t.alarm->range.line, 4);
  EXPECT_EQ(t.alarm->range.column, 1);
  // The moves before the arc are there; nothing of the arc's block or later.
  ASSERT_FALSE(t.moves.empty());
  for (const Move& m : t.moves) EXPECT_LT(m.line, 4);
  for (const auto& s : t.snapshots) EXPECT_LT(s.line, 4);
}

}  // namespace
}  // namespace klueng::core::machine

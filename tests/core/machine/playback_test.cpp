// Playing a timeline back (playback.h): the stops of Go, Step, Step Over,
// Step Out, breakpoints, Run to cursor, M00/M01; Step Back; what shows mid-move.
#include "klueng/core/machine/playback.h"

#include <gtest/gtest.h>

#include "test_support.h"

namespace klueng::core::machine {
namespace {

using testing::runText;

// Line numbers are the text's lines (line 1 = O0001).
constexpr const char* kProgram =
    "O0001\n"           // 1
    "G21 G99 T0101\n"   // 2
    "G97 S1000 M03\n"   // 3
    "G00 X40. Z2.\n"    // 4
    "G01 Z-10. F0.2\n"  // 5
    "M01\n"             // 6
    "G00 X42.\n"        // 7
    "M98 P1000\n"       // 8
    "G00 Z5.\n"         // 9
    "M00\n"             // 10
    "G00 X50.\n"        // 11
    "M30\n"             // 12
    "O1000\n"           // 13
    "G01 X38. F0.1\n"   // 14
    "G00 X42.\n"        // 15
    "M99\n";            // 16

class Playback : public ::testing::Test {
 protected:
  void SetUp() override {
    RunOptions options;
    options.optionalStop = true;  // record every M01: the switch decides while playing
    timeline_ = runText(kProgram, options);
    ASSERT_FALSE(timeline_.alarm);
  }
  // The snapshot of the first block on `line` after snapshot `after`.
  int snapshotOf(int line, int after = -1) const {
    for (int i = after + 1; i < static_cast<int>(timeline_.snapshots.size()); ++i)
      if (timeline_.snapshots[static_cast<std::size_t>(i)].line == line) return i;
    ADD_FAILURE() << "no block on line " << line;
    return -1;
  }
  int lineOf(int snapshot) const { return timeline_.snapshots[static_cast<std::size_t>(snapshot)].line; }
  StopRequest request(RunCommand command, int done) const {
    StopRequest r;
    r.command = command;
    r.done = done;
    r.endTime = timeline_.cycleTime();
    return r;
  }
  Timeline timeline_;
};

TEST_F(Playback, GoStopsAtM00AndAtM01OnlyWithTheSwitchOn) {
  StopTarget stop = nextStop(timeline_, request(RunCommand::Go, -1));
  EXPECT_EQ(lineOf(stop.snapshot), 10);  // M00: after the block
  EXPECT_FALSE(stop.isEnd);
  EXPECT_FALSE(stop.beforeNext);
  EXPECT_DOUBLE_EQ(stop.time, timeline_.snapshots[static_cast<std::size_t>(stop.snapshot)].time);
  StopRequest on = request(RunCommand::Go, -1);
  on.optionalStop = true;
  EXPECT_EQ(lineOf(nextStop(timeline_, on).snapshot), 6);
  // From the M00 on: to the end of the program.
  stop = nextStop(timeline_, request(RunCommand::Go, stop.snapshot));
  EXPECT_TRUE(stop.isEnd);
  EXPECT_EQ(stop.snapshot, static_cast<int>(timeline_.snapshots.size()) - 1);
  EXPECT_DOUBLE_EQ(stop.time, timeline_.cycleTime());
}

TEST_F(Playback, ABreakpointStopsBeforeItsBlockButNotTheOneResumedOn) {
  const std::set<int> breakpoints{7};
  StopRequest r = request(RunCommand::Go, -1);
  r.breakpoints = &breakpoints;
  const StopTarget stop = nextStop(timeline_, r);
  EXPECT_EQ(lineOf(stop.snapshot), 6);  // the block before line 7 is done
  EXPECT_TRUE(stop.beforeNext);
  EXPECT_FALSE(stop.isEnd);
  // Go again: line 7 runs (it was stopped at), the run goes on to M00.
  r.done = stop.snapshot;
  EXPECT_EQ(lineOf(nextStop(timeline_, r).snapshot), 10);
}

TEST_F(Playback, RunToCursorStopsBeforeTheFirstBlockAtOrAfterTheLine) {
  StopRequest r = request(RunCommand::Go, -1);
  r.runToLine = 5;
  const StopTarget stop = nextStop(timeline_, r);
  EXPECT_EQ(lineOf(stop.snapshot), 4);
  EXPECT_TRUE(stop.beforeNext);
}

TEST_F(Playback, StepIntoOverAndOutOfASubprogram) {
  const int call = snapshotOf(8);
  const int beforeCall = call - 1;
  EXPECT_EQ(lineOf(beforeCall), 7);
  // Step (into): the next block, the M98 itself, then the subprogram's O block.
  EXPECT_EQ(lineOf(nextStop(timeline_, request(RunCommand::Step, beforeCall)).snapshot), 8);
  const int inside = nextStop(timeline_, request(RunCommand::Step, call)).snapshot;
  EXPECT_EQ(lineOf(inside), 13);
  EXPECT_EQ(timeline_.snapshots[static_cast<std::size_t>(inside)].callLevel, 1);
  // Step Over the call: the subprogram runs whole, the stop is line 9.
  EXPECT_EQ(lineOf(nextStop(timeline_, request(RunCommand::StepOver, call)).snapshot), 9);
  // Step Out of the subprogram: back in the main program.
  const StopTarget out = nextStop(timeline_, request(RunCommand::StepOut, inside));
  EXPECT_EQ(timeline_.snapshots[static_cast<std::size_t>(out.snapshot)].callLevel, 0);
  EXPECT_EQ(lineOf(out.snapshot), 9);
}

TEST_F(Playback, StepBackGoesOverTheLastBlockOrToTheStartOfThisOne) {
  const int k = snapshotOf(5);
  const double done = timeline_.snapshots[static_cast<std::size_t>(k)].time;
  StopTarget back = stepBackStop(timeline_, k, done);
  EXPECT_EQ(back.snapshot, k - 1);
  EXPECT_DOUBLE_EQ(back.time, timeline_.snapshots[static_cast<std::size_t>(k - 1)].time);
  // In the middle of the next block: back to its start (= block k done).
  back = stepBackStop(timeline_, k, done + 0.01);
  EXPECT_EQ(back.snapshot, k);
  EXPECT_DOUBLE_EQ(back.time, done);
  // Nothing before the first block.
  back = stepBackStop(timeline_, -1, 0.0);
  EXPECT_EQ(back.snapshot, -1);
  EXPECT_DOUBLE_EQ(back.time, 0.0);
}

TEST_F(Playback, MidMoveThePoseShowsTheMovesFeedAndPlace) {
  // G01 Z-10. F0.2 at 1000 rpm: 200 mm/min, 12 mm from Z2 in 3.6 s.
  const int k = snapshotOf(5);
  const Move& cut =
      timeline_.moves[static_cast<std::size_t>(timeline_.snapshots[static_cast<std::size_t>(k)].moveEnd - 1)];
  ASSERT_NEAR(cut.tEnd - cut.tStart, 3.6, 1e-9);
  const double half = (cut.tStart + cut.tEnd) / 2.0;
  const Pose pose = poseAt(timeline_, k - 1, half);
  EXPECT_NEAR(pose.feedMmPerMin, 200.0, 1e-9);
  EXPECT_NEAR(pose.rpm, 1000.0, 1e-9);
  EXPECT_NEAR(pose.programmedFeed, 0.2, 1e-12);
  EXPECT_NEAR(pose.position.x(), (cut.path.start.x() + cut.path.end.x()) / 2.0, 1e-9);
  EXPECT_EQ(shownSnapshot(timeline_, k - 1, half), k);  // the executing block's state
  // Between blocks there is no feed under way.
  EXPECT_EQ(poseAt(timeline_, k, cut.tEnd).feedMmPerMin, 0.0);
}

TEST_F(Playback, ASlowFrameNeverJumpsFurtherThanItsTravel) {
  const int k = snapshotOf(5);
  const Move& cut =
      timeline_.moves[static_cast<std::size_t>(timeline_.snapshots[static_cast<std::size_t>(k)].moveEnd - 1)];
  // 200 mm/min = 3.333 mm/s: 1 mm of travel is 0.3 s of the 3.6 s move.
  EXPECT_NEAR(limitTravel(timeline_, cut.tStart, 2.0, 1.0), 0.3, 1e-9);
  EXPECT_NEAR(limitTravel(timeline_, cut.tStart, 0.1, 1.0), 0.1, 1e-12);  // within the travel: all of dt
}

}  // namespace
}  // namespace klueng::core::machine

namespace klueng::core::machine {
namespace {

// Issue 11: stopped by an alarm, the pose shows the alarmed block's modal words
// (its F, the tool and offset in force), not the state before it.
TEST(PlaybackAlarm, ThePoseAtAnAlarmHasTheAlarmedBlocksModalWords) {
  const Timeline t = testing::runText("G21 G99\nT0101 G00 X60. Z5.\nG01 X40. Z-10. F0.2\nM30\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->range.line, 3);
  ASSERT_TRUE(t.flow.alarmState);
  EXPECT_EQ(t.flow.alarmState->line, 3);
  const int last = static_cast<int>(t.snapshots.size()) - 1;
  const Pose p = poseAt(t, last, t.cycleTime());
  EXPECT_TRUE(p.hasState);
  EXPECT_DOUBLE_EQ(p.programmedFeed, 0.2);
  EXPECT_EQ(p.feedMode, FeedMode::PerRev);
  EXPECT_EQ(p.machine.tool, 1);
  EXPECT_EQ(p.machine.offset, 1);
  EXPECT_DOUBLE_EQ(p.machine.noseRadius, 0.8);
  EXPECT_POINT(p.position, 60.0, 5.0);
  // Before the end the pose is the one of the blocks that ran.
  const Pose before = poseAt(t, 0, 0.0);
  EXPECT_DOUBLE_EQ(before.programmedFeed, 0.0);
  // A run without an alarm keeps no alarm state.
  EXPECT_FALSE(testing::runText("G21 G99\nT0101 G00 X60. Z5.\nM30\n").flow.alarmState);
}

}  // namespace
}  // namespace klueng::core::machine

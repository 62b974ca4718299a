// Issue 42 item 6: the loop limits stop what they must and say what stopped it. A
// subprogram called twice, then a long slow cut, is no loop; a finite WHILE longer than
// max_blocks is told which limit stopped it and how to raise it, never "without end". A loop
// is called endless (A155) only when the run comes back to a state it was in before, and
// then early, long before any limit.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "klueng/core/messages.h"
#include "test_support.h"

namespace loop_limit_test {
namespace {

using namespace klueng::core;
using namespace klueng::core::machine;
using klueng::core::machine::testing::runText;
using klueng::core::machine::testing::testSetup;

TEST(LoopLimits, ASubprogramCalledTwiceThenASlowCutIsNoLoop) {
  MachineSetup setup = testSetup();
  setup.machine.maxRunTime = 60.0;
  // O1000 runs twice (L2, a few seconds), then the main program feeds 100 mm at 1 mm/min:
  // 100 minutes of cutting, no block run again during it.
  const Timeline t = runText(
      "G98 G00 X20. Z0.\nM98 P1000 L2\nG01 W-100. F1.\nG00 W100.\nM30\n"
      "O1000\nG01 W-1. F100.\nG00 W1.\nM99\n",
      {}, setup);
  EXPECT_FALSE(t.alarm) << formatMessage(*t.alarm, Lang::En);
  EXPECT_GT(t.cycleTime(), 6000.0);
}

TEST(LoopLimits, AFiniteLoopPastMaxBlocksIsToldWhichLimitStoppedIt) {
  MachineSetup setup = testSetup();
  setup.machine.maxBlocks = 5000;
  const Timeline t = runText("#1=0\nWHILE [#1 LT 70000] DO1\n#1=#1+1\nEND1\nM30\n", {}, setup);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A132");
  EXPECT_EQ(t.alarm->range, (SourceRange{4, 1, 3}));  // END1, the jump that repeated
  EXPECT_EQ(formatMessage(*t.alarm, Lang::En),
            "END1: stopped at the block limit, machine.cfg max_blocks = 5000 (5000 blocks run again by loops, "
            "jumps and calls); if the program is meant to run longer, raise max_blocks in machine.cfg");
  const std::string th = formatMessage(*t.alarm, Lang::Th);
  EXPECT_EQ(th.find("ไม่รู้จบ"), std::string::npos) << th;
  EXPECT_NE(th.find("หยุดที่ขีดจำกัดจำนวนบล็อก max_blocks = 5000 ใน machine.cfg"), std::string::npos) << th;
  EXPECT_NE(th.find("ให้เพิ่มค่า max_blocks ใน machine.cfg"), std::string::npos) << th;
  // The run stopped there: the loop's counter did not reach its end.
  ASSERT_FALSE(t.snapshots.empty());
  EXPECT_EQ(t.snapshots.back().line, 3);
  // The same loop runs to its end under a limit that allows it.
  setup.machine.maxBlocks = 1000000;
  EXPECT_FALSE(runText("#1=0\nWHILE [#1 LT 70000] DO1\n#1=#1+1\nEND1\nM30\n", {}, setup).alarm);
}

TEST(LoopLimits, TheTimeLimitSaysItIsALimit) {
  MachineSetup setup = testSetup();
  setup.machine.maxBlocks = 1000000;
  setup.machine.maxRunTime = 60.0;
  // Each pass counts in #1: no pass comes back to the state of another, nothing is proven endless.
  const Timeline t = runText("G98 G00 X20. Z0.\nN5 G01 W-10. F100.\nG00 W10.\n#1=#1+1\nGOTO 5\n", {}, setup);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A133");
  EXPECT_EQ(t.alarm->range.line, 5);
  const std::string en = formatMessage(*t.alarm, Lang::En);
  EXPECT_NE(en.find("GOTO5: stopped at the time limit, machine.cfg max_run_time = 60.000 s ("), std::string::npos)
      << en;
  EXPECT_NE(en.find("raise max_run_time in machine.cfg"), std::string::npos) << en;
  EXPECT_EQ(en.find("without end"), std::string::npos) << en;
  const std::string th = formatMessage(*t.alarm, Lang::Th);
  EXPECT_NE(th.find("หยุดที่ขีดจำกัดเวลา max_run_time = 60.000 วินาที ใน machine.cfg"), std::string::npos) << th;
}

// A GOTO to itself with nothing changing: endless, said so at the loop's line, and stopped
// at once (the second time the run is back at N10), not after max_blocks.
TEST(EndlessLoop, AGotoToItselfIsEndlessAtOnce) {
  MachineSetup setup = testSetup();
  setup.machine.maxBlocks = 100000;
  const Timeline t = runText("G21 G99\n#1=5\nN10 GOTO 10\nM30\n", {}, setup);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A155");
  EXPECT_EQ(t.alarm->range, (SourceRange{3, 5, 4}));  // the GOTO of line 3
  EXPECT_EQ(t.alarm->args, (std::vector<std::string>{"GOTO10", "3"}));
  EXPECT_EQ(formatMessage(*t.alarm, Lang::En),
            "GOTO10 loops without end: the run came back to line 3 in the same state as on an earlier pass (the "
            "same variables, modes and position), so it would repeat for ever; a control runs it until RESET");
  EXPECT_EQ(formatMessage(*t.alarm, Lang::Th),
            "GOTO10 วนซ้ำไม่รู้จบ: การทำงานกลับมาที่บรรทัด 3 ในสภาพเดียวกับรอบก่อนหน้าทุกอย่าง (ตัวแปร โหมด และตำแหน่งเดิม) "
            "จึงจะวนซ้ำเช่นนี้ตลอดไป เครื่องจริงจะทำงานต่อไปจนกว่าจะกด RESET");
  EXPECT_LE(t.snapshots.size(), 6u);  // stopped early: a handful of blocks, not 100,000
}

// A loop that cuts the same pass again and again, with a WHILE whose condition never changes:
// endless, found within a few passes (the moves of those passes are kept).
TEST(EndlessLoop, AWhileWhoseConditionNeverChangesIsEndless) {
  MachineSetup setup = testSetup();
  const Timeline t =
      runText("G98 G00 X20. Z0.\n#1=1\nWHILE [#1 EQ 1] DO1\nG01 W-10. F100.\nG00 W10.\nEND1\nM30\n", {}, setup);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A155");
  EXPECT_EQ(t.alarm->range.line, 6);  // END1
  EXPECT_EQ(t.alarm->args, (std::vector<std::string>{"END1", "3"}));
  EXPECT_GE(t.moves.size(), 3u);
  EXPECT_LE(t.moves.size(), 9u);
}

// A loop whose state cycles through a few values (#1 = 1, 2, 3, 1, 2, 3 ...) is endless too.
TEST(EndlessLoop, AStateThatCyclesIsEndless) {
  const Timeline t = runText("#1=0\nN5 #1=#1+1\nIF [#1 LT 3] GOTO 5\n#1=0\nGOTO 5\nM30\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A155");
  EXPECT_LE(t.snapshots.size(), 60u);
}

// A loop of macro calls that pass the same arguments: endless, though each call is a new frame.
TEST(EndlessLoop, ALoopOfTheSameCallsIsEndless) {
  const Timeline t = runText("N5 G65 P9000 A2.\nGOTO 5\nM30\nO9000\n#100=#1*2\nM99\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A155");
  EXPECT_EQ(t.alarm->args, (std::vector<std::string>{"GOTO5", "1"}));
  EXPECT_LE(t.snapshots.size(), 12u);
}

// What makes a loop finite is never called endless: a counter, a subprogram repeat, a call
// that passes a different argument each time, a program that reads the clock.
TEST(EndlessLoop, LoopsThatEndAreNotEndless) {
  MachineSetup setup = testSetup();
  setup.machine.maxBlocks = 1000000;
  EXPECT_FALSE(runText("#1=0\nWHILE [#1 LT 70000] DO1\n#1=#1+1\nEND1\nM30\n", {}, setup).alarm);
  // The same pass three times by M98 L3: the repeat count is state.
  EXPECT_FALSE(runText("G98 G00 X20. Z0.\nM98 P1000 L3\nM30\nO1000\nG01 W-1. F100.\nG00 W1.\nM99\n", {}, setup).alarm);
  // The position is state: an incremental move each pass, until Z (#5002) is at -50.
  EXPECT_FALSE(runText("G98 G00 X20. Z0.\nN5 G01 W-1. F100.\nIF [#5002 GT -50.] GOTO 5\nM30\n", {}, setup).alarm);
  // The offsets are state: a program that corrects its own wear until a value is reached.
  EXPECT_FALSE(runText("N5 #2001=#2001+0.01\nIF [#2001 LT 1.] GOTO 5\nM30\n", {}, setup).alarm);
  // A macro's argument is state: each call passes the next value.
  EXPECT_FALSE(
      runText("#100=0\nN5 G65 P9000 A#100\nIF [#100 LT 20] GOTO 5\nM30\nO9000\n#100=#1+1\nM99\n", {}, setup).alarm);
  // A loop that waits on the timer (#3001) ends when the time is up: the clock is state.
  const Timeline timer = runText("G98\n#3001=0\nN5 G04 X1.\nIF [#3001 LT 5000] GOTO 5\nM30\n", {}, setup);
  EXPECT_FALSE(timer.alarm) << formatMessage(*timer.alarm, Lang::En);
}

// Nothing changes from pass to pass, but the program reads the clock: no proof, the time
// limit stops it and says so.
TEST(EndlessLoop, AProgramThatReadsTheClockIsStoppedByALimitNotCalledEndless) {
  MachineSetup setup = testSetup();
  setup.machine.maxRunTime = 60.0;
  const Timeline t = runText("G98\n#2=#3001\nN5 G04 X1.\nGOTO 5\n", {}, setup);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A133");
}

}  // namespace
}  // namespace loop_limit_test

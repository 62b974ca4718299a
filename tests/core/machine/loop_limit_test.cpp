// Issue 42 item 6: the loop limits stop what they must and say what stopped it. A
// subprogram called twice, then a long slow cut, is no loop; a finite WHILE longer than
// max_blocks is told which limit stopped it and how to raise it, never "without end".
#include <gtest/gtest.h>

#include <string>

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
  const std::string en = formatMessage(*t.alarm, Lang::En);
  const std::string th = formatMessage(*t.alarm, Lang::Th);
  EXPECT_EQ(en.find("without end"), std::string::npos) << en;
  EXPECT_NE(en.find("max_blocks = 5000"), std::string::npos) << en;
  EXPECT_NE(en.find("raise it"), std::string::npos) << en;
  EXPECT_EQ(th.find("ไม่รู้จบ"), std::string::npos) << th;
  EXPECT_NE(th.find("ให้เพิ่มค่านี้"), std::string::npos) << th;
  // The same loop runs to its end under a limit that allows it.
  setup.machine.maxBlocks = 1000000;
  EXPECT_FALSE(runText("#1=0\nWHILE [#1 LT 70000] DO1\n#1=#1+1\nEND1\nM30\n", {}, setup).alarm);
}

TEST(LoopLimits, TheTimeLimitSaysItIsALimit) {
  MachineSetup setup = testSetup();
  setup.machine.maxBlocks = 1000000;
  setup.machine.maxRunTime = 60.0;
  const Timeline t = runText("G98 G00 X20. Z0.\nN5 G01 W-10. F100.\nG00 W10.\nGOTO 5\n", {}, setup);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A133");
  const std::string en = formatMessage(*t.alarm, Lang::En);
  EXPECT_NE(en.find("max_run_time = 60.000 s; raise it"), std::string::npos) << en;
}

}  // namespace
}  // namespace loop_limit_test

// G10: a program writes its own offsets (Fanuc 16i/18i-TB B-63524EN/01 §14.5.2).
#include <gtest/gtest.h>

#include "klueng/core/gcode/checker.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

using testing::at;
using testing::runText;

// The snapshot of the last block on `line`.
const StateSnapshot& lastOn(const Timeline& t, int line) {
  const StateSnapshot* found = nullptr;
  for (const StateSnapshot& s : t.snapshots)
    if (s.line == line) found = &s;
  EXPECT_NE(found, nullptr) << "no snapshot on line " << line;
  return *found;
}

TEST(DataSetting, GeometryOffsetWrittenByTheProgramCountsFromTheNextT) {
  const std::string text =
      "G21 G99\n"                   // 1
      "T0303\n"                     // 2: R0 tip 8 from the table
      "G10 P10003 X0 Z0 R0.4 Q3\n"  // 3: geometry 03 rewritten
      "G97 S800 M03\n"              // 4
      "G00 X40. Z2.\n"              // 5
      "T0303\n"                     // 6: now R0.4 tip 3
      "G10 P3 U0.1 W-0.05 R0.8\n"   // 7: wear: X and Z added, R not a wear value here
      "G01 Z-10. F0.2\n"            // 8: the G10 X/Z/U/W moved nothing
      "T0303\n"                     // 9
      "M30\n";
  const Timeline t = runText(text);
  ASSERT_FALSE(t.alarm.has_value()) << t.alarm->code;
  EXPECT_DOUBLE_EQ(lastOn(t, 2).machine.noseRadius, 0.0);
  EXPECT_EQ(lastOn(t, 2).machine.tip, 8);
  EXPECT_EQ(lastOn(t, 4).machine.tip, 8);  // written, not yet called
  EXPECT_DOUBLE_EQ(lastOn(t, 6).machine.noseRadius, 0.4);
  EXPECT_EQ(lastOn(t, 6).machine.tip, 3);
  EXPECT_POINT(lastOn(t, 7).machine.position, 40.0, 2.0);
  EXPECT_POINT(lastOn(t, 8).machine.position, 40.0, -10.0);
  EXPECT_NEAR(lastOn(t, 9).machine.offsetX, 0.1, 1e-9);
  EXPECT_NEAR(lastOn(t, 9).machine.offsetZ, -0.05, 1e-9);
  EXPECT_DOUBLE_EQ(lastOn(t, 9).machine.noseRadius, 0.4);
}

TEST(DataSetting, TheCheckReadsG10AsTheControlDoes) {
  gcode::CheckOptions o;
  const gcode::Program p = gcode::parse("G21 G99\nG10 P10001 X0 Z0 R0.8 Q3\nG10 L2 P1 Z-250.\nT0101\nM30\n", 1);
  EXPECT_TRUE(gcode::check(p, o).empty());
  // An offset the control has not: the alarm of a T word naming it.
  const Timeline t = runText("G21\nG10 P10099 R0.4\nM30\n");
  ASSERT_TRUE(t.alarm.has_value());
  EXPECT_EQ(t.alarm->code, "A118");
  EXPECT_EQ(t.alarm->range.line, 2);
}

}  // namespace
}  // namespace klueng::core::machine

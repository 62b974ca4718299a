// Issue 42 item 3: a run's memory is bounded. An endless loop under max_blocks = 100000000
// stops with A156 once its moves and states would pass the budget (it ended in std::bad_alloc at
// 10.9 GB), counting the lists it outgrew (a batch run's heap keeps them), and a record read only
// for evidence keeps a 24-byte mark a block, not a StateSnapshot, and a 40-byte packed move, not
// a Move, with its feeds and speeds (48 bytes) only when the check measures its cutting data.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <cstdint>
#include <string>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/messages.h"
#include "test_support.h"

namespace run_memory_test {
namespace {

using namespace klueng::core;
using namespace klueng::core::machine;
using klueng::core::machine::testing::runText;
using klueng::core::machine::testing::testSetup;

// What the run keeps, and the copy each full list makes when it grows next (the budget's measure
// but for the lists it outgrew).
std::size_t neededBytes(const Timeline& t) {
  std::size_t needed = 0;
  const auto add = [&](const auto& list) {
    const std::size_t bytes = list.size() * sizeof(list.front());
    needed += list.size() == list.capacity() ? 2 * bytes : bytes;
  };
  add(t.moves);
  add(t.snapshots);
  add(t.marks);
  add(t.recordMoves.packed());
  add(t.flow.writes);
  add(t.flow.wordValues);
  return needed;
}

// The lists a list left behind as it grew by doubling from `first` elements (interpret() reserves
// one a block; the value logs start empty and grow from one) to its capacity.
template <typename List>
std::size_t outgrownBytes(const List& list, std::size_t first) {
  return list.capacity() <= first ? 0 : (list.capacity() - first) * sizeof(list.front());
}

constexpr const char* kEndlessMacroLoop = "#1=0\nWHILE [1 EQ 1] DO1\n#1=#1+1\nEND1\nM30\n";

TEST(RunMemory, AnEndlessLoopUnderAHugeBlockLimitStopsAtTheBudget) {
  MachineSetup setup = testSetup();
  setup.machine.maxBlocks = 100000000;
  RunOptions options;
  options.memoryBudgetMb = 4;
  const Timeline t = runText(kEndlessMacroLoop, options, setup);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A156");
  const int line = t.alarm->range.line;
  EXPECT_GE(line, 2);
  EXPECT_LE(line, 4);
  // Just past the budget: what the run keeps, the copy a full list makes when it grows and the
  // lists it outgrew (as much again as it keeps) are more than 4 MB; what it keeps and outgrew
  // is at most a block's more than 4 MB.
  const std::size_t held = t.snapshots.size() * sizeof(StateSnapshot) + t.flow.writes.size() * sizeof(VariableWrite);
  const std::size_t outgrown = outgrownBytes(t.snapshots, 5) + outgrownBytes(t.flow.writes, 1);
  EXPECT_GT(neededBytes(t) + outgrown, std::size_t{4} << 20);
  EXPECT_LE(held + outgrown, (std::size_t{4} << 20) + sizeof(StateSnapshot) + sizeof(VariableWrite));
  EXPECT_GT(held, std::size_t{1} << 20);
  const std::string en = formatMessage(*t.alarm, Lang::En);
  const std::string th = formatMessage(*t.alarm, Lang::Th);
  EXPECT_NE(en.find("would need more than 4 MB of memory"), std::string::npos) << en;
  EXPECT_NE(en.find("it stops at line " + std::to_string(line)), std::string::npos) << en;
  EXPECT_NE(th.find("หน่วยความจำเกิน 4 MB"), std::string::npos) << th;
  EXPECT_NE(th.find("จึงหยุดที่บรรทัด " + std::to_string(line)), std::string::npos) << th;
}

TEST(RunMemory, ARecordThroughAlarmsStopsAtTheBudget) {
  // The check's record of marks (through alarms, as the tool inference makes it) is bounded too.
  MachineSetup setup = testSetup();
  setup.machine.maxBlocks = 100000000;
  RunOptions options;
  options.memoryBudgetMb = 4;
  options.blockMarksOnly = true;
  const Timeline t = recordRun(gcode::parse(kEndlessMacroLoop, 1), setup, options);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A156");
  const std::size_t held = t.marks.size() * sizeof(BlockMark) + t.flow.writes.size() * sizeof(VariableWrite);
  const std::size_t outgrown = outgrownBytes(t.marks, 5) + outgrownBytes(t.flow.writes, 1);
  EXPECT_GT(neededBytes(t) + outgrown, std::size_t{4} << 20);
  EXPECT_LE(held + outgrown, (std::size_t{4} << 20) + sizeof(BlockMark) + sizeof(VariableWrite));
  EXPECT_GT(held, std::size_t{1} << 20);
}

TEST(RunMemory, ALongProgramOfMovesStopsAtTheBudgetToo) {
  std::string text = "G98 G00 X20. Z0.\nF100.\n";
  for (int i = 0; i < 20000; ++i) text += i % 2 ? "G01 X20.\n" : "G01 X19.\n";
  text += "M30\n";
  RunOptions options;
  options.memoryBudgetMb = 1;
  const Timeline t = runText(text, options);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A156");
  const std::size_t held = t.moves.size() * sizeof(Move) + t.snapshots.size() * sizeof(StateSnapshot);
  EXPECT_GT(neededBytes(t), std::size_t{1} << 20);
  EXPECT_LE(held, (std::size_t{1} << 20) + sizeof(Move) + sizeof(StateSnapshot));
  // The default budget (4096 MB) lets the same program run to its end.
  EXPECT_EQ(RunOptions{}.memoryBudgetMb, 4096u);
  const Timeline whole = runText(text);
  EXPECT_FALSE(whole.alarm);
  EXPECT_EQ(whole.moves.size(), 20002u);  // the first rapid's two legs and the 20,000 feeds
  EXPECT_EQ(whole.snapshots.size(), 20003u);
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool sameBits(const Vec2& a, const Vec2& b) { return sameBits(a.x(), b.x()) && sameBits(a.y(), b.y()); }

// A packed move read back says, bit for bit, what the move says.
void expectSameMove(const RecordMove& r, const Move& m) {
  EXPECT_TRUE(sameBits(r.path.start, m.path.start));
  EXPECT_TRUE(sameBits(r.path.end, m.path.end));
  EXPECT_TRUE(sameBits(r.path.centre, m.path.centre));
  EXPECT_EQ(r.path.kind, m.path.kind);
  EXPECT_EQ(r.path.ccw, m.path.ccw);
  EXPECT_EQ(r.line, m.line);
  EXPECT_EQ(r.blockIndex, m.blockIndex);
  EXPECT_EQ(r.file, m.file);
  EXPECT_EQ(r.tool, m.tool);
  EXPECT_EQ(r.offset, m.offset);
  EXPECT_EQ(r.kind, m.kind);
  EXPECT_EQ(r.spindle, m.spindle);
}

TEST(RunMemory, ARecordOfMarksKeepsWhatTheSnapshotsSay) {
  const char* text =
      "G21 G99\nT0101\nG96 S180 M03\nG50 S2500\nG00 X52. Z2.\nG01 X48. F0.2\nZ-30.\nG20\nG00 X3. Z1.\n"
      "T0202\nG97 S800\nG01 X1. F0.01\nM98 P1000 L2\nM30\nO1000\nG01 W-0.1\nG00 W0.1\nM99\n";
  const gcode::Program program = gcode::parse(text, 1);
  ASSERT_TRUE(program.lexicalDiagnostics.empty());
  RunOptions full;
  RunOptions marks;
  marks.blockMarksOnly = true;
  const Timeline a = recordRun(program, testSetup(), full);
  const Timeline b = recordRun(program, testSetup(), marks);
  EXPECT_TRUE(a.marks.empty() && a.recordMoves.empty());
  EXPECT_TRUE(b.snapshots.empty() && b.moves.empty());
  ASSERT_EQ(a.snapshots.size(), b.marks.size());
  ASSERT_EQ(a.moves.size(), b.recordMoves.size());
  ASSERT_EQ(a.moveCount(), b.moveCount());
  // Each kept move says what the move says of its path, block, line, file, tool, offset and kind.
  for (std::size_t k = 0; k < a.moves.size(); ++k) {
    expectSameMove(b.recordMoves[k], a.moves[k]);
  }
  EXPECT_EQ(sideOfCuts(a), sideOfCuts(b));
  ASSERT_GT(a.snapshots.size(), 15u);
  bool inch = false, clamped = false, secondTool = false;
  for (std::size_t k = 0; k < a.snapshots.size(); ++k) {
    const StateSnapshot& s = a.snapshots[k];
    const BlockMark& m = b.marks[k];
    EXPECT_EQ(m.blockIndex, s.blockIndex);
    EXPECT_EQ(m.moveEnd, s.moveEnd);
    EXPECT_EQ(m.line, s.line);
    EXPECT_EQ(m.file, s.file);
    EXPECT_EQ(m.tool, s.machine.tool);
    EXPECT_EQ(m.offset, s.machine.offset);
    EXPECT_EQ(m.units, s.modal.units);
    EXPECT_EQ(m.motion, s.modal.motion);
    EXPECT_EQ(m.spindleMode, s.modal.spindleMode);
    EXPECT_EQ(m.rpmClamped, s.modal.rpmClamp > 0.0);
    inch = inch || m.units == Units::Inch;
    clamped = clamped || m.rpmClamped;
    secondTool = secondTool || m.tool == 2;
    // The evidence reads both kinds of record alike.
    EXPECT_EQ(a.blockMark(k).moveEnd, b.blockMark(k).moveEnd);
  }
  EXPECT_TRUE(inch && clamped && secondTool);
  EXPECT_EQ(a.blockCount(), b.blockCount());
}

// Arcs both ways, a G50 that moves the controlled point without a move, a dwell, a rapid's two
// legs, G96 along a taper, a thread, acceleration: the moves a packed record keeps apart.
constexpr const char* kEveryKindOfMove =
    "G21 G99\nT0101\nG96 S180 M03\nG50 S2500\nG00 X52. Z2.\nG01 X48. F0.2\nG01 X40. Z-10.\n"
    "G02 X44. Z-12. R2.\nG03 X40. Z-14. R2.\nG04 X0.5\nG50 X60. Z5.\nG00 X30. Z1.\nG97 S600\n"
    "G32 Z-10. F1.5\nG00 X50.\nZ5.\nM05\nG01 X20. F0.1\nM30\n";

TEST(RunMemory, APackedRecordKeepsEveryMoveBitForBitAndTheCheckSpeedsWhenAsked) {
  MachineSetup setup = testSetup();
  setup.machine.accelX = 2000.0;
  setup.machine.accelZ = 3000.0;
  const gcode::Program program = gcode::parse(kEveryKindOfMove, 1);
  ASSERT_TRUE(program.lexicalDiagnostics.empty());
  RunOptions full;
  RunOptions packed;
  packed.blockMarksOnly = true;
  packed.recordSpeeds = true;
  const Timeline a = recordRun(program, setup, full);
  const Timeline b = recordRun(program, setup, packed);
  ASSERT_GT(a.moves.size(), 12u);
  ASSERT_EQ(a.moves.size(), b.recordMoves.size());
  ASSERT_EQ(b.recordSpeeds.size(), b.recordMoves.size());
  bool arc = false, jump = false, thread = false, dwell = false, ramp = false, g96 = false;
  std::size_t k = 0;
  for (const RecordMove r : b.recordMoves) {  // read in order, without a search
    const Move& m = a.moves[k];
    SCOPED_TRACE("move " + std::to_string(k) + " line " + std::to_string(m.line));
    expectSameMove(r, m);
    expectSameMove(b.recordMoves[k], m);  // read by index
    // The check's cutting data reads the move back whole: its times, feeds, speeds and ramps.
    const Move w = b.recordedMove(k);
    EXPECT_TRUE(sameBits(w.tStart, m.tStart) && sameBits(w.tEnd, m.tEnd));
    EXPECT_TRUE(sameBits(w.feed, m.feed) && sameBits(w.lead, m.lead));
    EXPECT_TRUE(sameBits(w.rpm, m.rpm) && sameBits(w.rpmEnd, m.rpmEnd));
    EXPECT_EQ(w.rampUp, m.rampUp);
    EXPECT_EQ(w.rampDown, m.rampDown);
    EXPECT_EQ(w.spindle, m.spindle);
    expectSameMove(RecordMove::of(w), m);
    arc = arc || m.path.isArc();
    jump = jump || (k > 0 && m.path.start != a.moves[k - 1].path.end);
    thread = thread || m.kind == MoveKind::Thread;
    dwell = dwell || m.kind == MoveKind::Dwell;
    ramp = ramp || m.rampUp > 0.0f;
    g96 = g96 || m.rpm != m.rpmEnd;
    ++k;
  }
  EXPECT_EQ(k, a.moves.size());
  EXPECT_TRUE(arc && jump && thread && dwell && ramp && g96);
  // Only the first move and the jump keep their start apart; only the arcs their centre.
  EXPECT_EQ(b.recordMoves.starts().size(), 2u);
  EXPECT_EQ(b.recordMoves.centres().size(), 2u);
  // Without recordSpeeds the record keeps none: the moves' times and speeds read as zero.
  packed.recordSpeeds = false;
  const Timeline c = recordRun(program, setup, packed);
  EXPECT_TRUE(c.recordSpeeds.empty());
  ASSERT_EQ(c.recordMoves.size(), a.moves.size());
  EXPECT_EQ(c.recordedMove(3).tEnd, 0.0);
  EXPECT_EQ(c.recordedMove(3).rpm, 0.0);
  // A move seen from beyond the centre (a line's ccw flag turned, its zero centre's sign too)
  // packs and reads back bit for bit as well.
  RecordMoveList mirrored;
  for (const Move& m : a.moves) mirrored.push_back(RecordMove::of(mirroredAcrossCentre(m)));
  for (std::size_t i = 0; i < a.moves.size(); ++i) expectSameMove(mirrored[i], mirroredAcrossCentre(a.moves[i]));
}

}  // namespace
}  // namespace run_memory_test

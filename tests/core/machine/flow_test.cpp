// Program flow at run time and in the check (issue 9): subprogram nesting,
// macro calls and variables, and every kind of bad input giving a clear
// message with line and column (English and Thai), never a hang.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/messages.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

using testing::runText;

std::vector<Diagnostic> checkText(const std::string& text, gcode::Dialect d = gcode::Dialect::Fanuc) {
  gcode::CheckOptions o;
  o.dialect = d;
  return gcode::check(gcode::parse(text, 1), o);
}

// The one diagnostic with `code`, else a failure.
const Diagnostic* find(const std::vector<Diagnostic>& ds, const std::string& code) {
  for (const Diagnostic& d : ds)
    if (d.code == code) return &d;
  ADD_FAILURE() << "no " << code;
  return nullptr;
}

void expectBilingual(const Diagnostic& d) {
  const std::string en = formatMessage(d, Lang::En);
  const std::string th = formatMessage(d, Lang::Th);
  EXPECT_FALSE(en.empty());
  EXPECT_NE(en, th) << d.code;
  EXPECT_EQ(en.find("{0}"), std::string::npos) << en;
  EXPECT_EQ(th.find("{0}"), std::string::npos) << th;
}

TEST(FlowCheck, UnmatchedDoAndEnd) {
  const auto ds = checkText("#1=0\nWHILE [#1 LT 3] DO1\n#1=#1+1\nEND2\n");
  const Diagnostic* end = find(ds, "E402");
  const Diagnostic* open = find(ds, "E401");
  ASSERT_TRUE(end && open);
  EXPECT_EQ(end->range, (SourceRange{4, 1, 3}));
  EXPECT_EQ(open->range, (SourceRange{2, 1, 5}));  // the WHILE
  expectBilingual(*end);
  expectBilingual(*open);
}

TEST(FlowCheck, LoopsMustNestAndAtMostThreeDeep) {
  auto ds = checkText("DO1\nDO2\nEND1\nEND2\n");
  const Diagnostic* cross = find(ds, "E409");
  ASSERT_TRUE(cross);
  EXPECT_EQ(cross->range.line, 3);
  ds = checkText("DO1\nDO2\nDO3\nDO1\nEND1\nEND3\nEND2\nEND1\n");
  const Diagnostic* deep = find(ds, "E408");
  ASSERT_TRUE(deep);
  EXPECT_EQ(deep->range.line, 4);
}

TEST(FlowCheck, GotoToNowhere) {
  const auto ds = checkText("N10 G00 X10.\nIF [#1 GT 2] GOTO 20\nGOTO 10\n");
  const Diagnostic* d = find(ds, "E403");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->range, (SourceRange{2, 19, 2}));  // the 20 of GOTO 20
  EXPECT_EQ(d->args.at(1), "20");
  EXPECT_EQ(ds.size(), 1u);  // GOTO 10 finds N10
  expectBilingual(*d);
}

TEST(FlowCheck, UnconditionalRecursionIsAnErrorAtTheCall) {
  const auto ds = checkText("M98 P1000\nM30\nO1000\nG00 U1.\nM98 P1000\nM99\n");
  const Diagnostic* d = find(ds, "E411");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->range.line, 5);
  EXPECT_EQ(d->range.column, 1);
  expectBilingual(*d);
}

TEST(FlowCheck, MacroArgumentsAndTheClassicDialect) {
  auto ds = checkText("G65 P9000 A1. Y2. V3.\nM30\nO9000\nM99\n");
  EXPECT_TRUE(ds.empty()) << ds.front().code;  // Y and V are arguments (#25, #22)
  ds = checkText("G65 P9000 A1. O5\nM30\nO9000\nM99\n");
  ASSERT_TRUE(find(ds, "E406"));
  ds = checkText("#1=2\nG00 X#1\n", gcode::Dialect::Classic);
  const Diagnostic* d = find(ds, "E407");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->range.line, 1);
}

TEST(FlowRun, DivisionByZeroStopsAtTheExpression) {
  const Timeline t = runText("#1=0\n#2=10/#1\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A131");
  EXPECT_EQ(t.alarm->range.line, 2);
  EXPECT_EQ(t.alarm->range.column, 4);
  expectBilingual(*t.alarm);
}

TEST(FlowRun, VacantAxisWordIsLeftOutWithAWarning) {
  const Timeline t = runText("G00 X40. Z#5\n");
  ASSERT_FALSE(t.alarm);
  ASSERT_EQ(t.flow.notices.size(), 1u);
  const Diagnostic& n = t.flow.notices[0];
  EXPECT_EQ(n.code, "W130");
  EXPECT_EQ(n.severity, Severity::Warning);
  EXPECT_EQ(n.range, (SourceRange{1, 10, 3}));
  expectBilingual(n);
  // X moved, Z stayed at 300.
  EXPECT_POINT(t.moves.back().path.end, 40.0, 300.0);
}

TEST(FlowRun, RecursionPastTheLimitStopsWithAnAlarm) {
  // An IF the run never takes: the check lets it through, the run stops at level 11.
  const std::string text = "#100=0\nM98 P1000\nM30\nO1000\n#100=#100+1\nIF [#100 LT 0] GOTO 9\nM98 P1000\nN9 M99\n";
  EXPECT_TRUE(checkText(text).empty());
  const Timeline t = runText(text);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A134");
  EXPECT_EQ(t.alarm->range, (SourceRange{7, 1, 3}));
  EXPECT_EQ(t.alarm->args.at(1), "10");
  expectBilingual(*t.alarm);
}

TEST(FlowRun, EndlessLoopsStopByBlocksOrByTime) {
  MachineSetup setup = testing::testSetup();
  setup.machine.maxBlocks = 5000;
  Timeline t = runText("#1=0\nWHILE [1 EQ 1] DO1\n#1=#1+1\nEND1\n", {}, setup);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A132");
  EXPECT_EQ(t.alarm->range, (SourceRange{4, 1, 3}));
  EXPECT_EQ(t.alarm->args.at(0), "END1");
  expectBilingual(*t.alarm);
  // With motion, the time limit comes first: 10 mm at 100 mm/min = 6 s a pass (each pass
  // counts in #1, so no pass comes back to the state of another: no proven endless loop).
  setup.machine.maxBlocks = 1000000;
  setup.machine.maxRunTime = 60.0;
  t = runText("G98 G00 X20. Z0.\nN5 G01 W-10. F100.\nG00 W10.\n#1=#1+1\nGOTO 5\n", {}, setup);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A133");
  EXPECT_EQ(t.alarm->range, (SourceRange{5, 1, 4}));
  EXPECT_GE(t.cycleTime(), 60.0);
  EXPECT_LT(t.cycleTime(), 67.0);
  // A straight program longer than the limit is no loop (issue 29 item 5): it runs to its
  // M30 (ten 10 mm passes at 100 mm/min = 60 s of feed and more, against a 30 s limit).
  setup.machine.maxRunTime = 30.0;
  std::string straight = "G98 G00 X20. Z0.\n";
  for (int i = 0; i < 10; ++i) straight += "G01 W-10. F100.\nG00 W10.\n";
  straight += "M30\n";
  t = runText(straight, {}, setup);
  EXPECT_FALSE(t.alarm) << t.alarm->code;
  EXPECT_GT(t.cycleTime(), 60.0);
}

TEST(FlowRun, ModalMacroRunsAfterEachMoveUntilG67) {
  // G66 P9100: after each move, O9100 dips 1 mm (U-2.) and back.
  const Timeline t = runText(
      "G98 G00 X40. Z0.\nG66 P9100 F60.\nG01 W-5. F300.\nW-5.\nG67\nW-5.\nM30\n"
      "O9100\nG01 U-2. F#9\nG00 U2.\nM99\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  int dips = 0;
  for (const Move& m : t.moves)
    if (m.kind == MoveKind::Line && m.line == 9) {
      ++dips;
      EXPECT_EQ(m.callLevel, 1);
      EXPECT_EQ(m.program, 9100);
      EXPECT_NEAR(m.feed, 60.0, 1e-9);  // F60. passed as #9
    }
  EXPECT_EQ(dips, 2);  // after the two moves under G66, not after the one under G67
}

TEST(FlowRun, SystemVariablesReadTheMachineState) {
  // #5001/#5002: the end point of the last block (X as a diameter); #4001 G01;
  // #4006 G21; #4109 the F.
  const Timeline t =
      runText("G21 G98 G00 X40. Z5.\nG01 Z-10. F250.\n#100=#5001\n#101=#5002\n#102=#4001\n#103=#4006\n#104=#4109\n");
  ASSERT_FALSE(t.alarm);
  std::map<int, double> got;
  for (const VariableWrite& w : t.flow.writes) got[w.number] = w.value;
  EXPECT_DOUBLE_EQ(got[100], 40.0);
  EXPECT_DOUBLE_EQ(got[101], -10.0);
  EXPECT_DOUBLE_EQ(got[102], 1.0);
  EXPECT_DOUBLE_EQ(got[103], 21.0);
  EXPECT_DOUBLE_EQ(got[104], 250.0);
}

TEST(FlowRun, StopWithMessageAndPartsCounter) {
  const Timeline t = runText("#3006=1 (CHECK THE INSERT)\n#3901=#3901+1\nM30\n");
  ASSERT_FALSE(t.alarm);
  ASSERT_EQ(t.flow.notices.size(), 1u);
  EXPECT_EQ(t.flow.notices[0].code, "A147");
  EXPECT_EQ(t.flow.notices[0].args.at(0), "CHECK THE INSERT");
  ASSERT_GE(t.snapshots.size(), 1u);
  EXPECT_TRUE(t.snapshots[0].stopped);
}

TEST(FlowRun, PersistentVariablesComeAndGoThroughTheRunOptions) {
  std::map<int, double> keep{{500, 4.0}};
  RunOptions o;
  o.persistentVariables = &keep;
  runText("#500=#500+1\n#501=#500*2\n#100=7\n", o);
  EXPECT_EQ(keep, (std::map<int, double>{{500, 5.0}, {501, 10.0}}));
  runText("#500=#500+1\n", o);
  EXPECT_DOUBLE_EQ(keep[500], 6.0);
}

TEST(FlowRun, CallStacksAndVariableWritesAreRecordedForTheWatch) {
  const Timeline t = runText("G65 P9000 A3.\nM30\nO9000\n#2=#1*2\nM98 P9100\nM99\nO9100\nM99\n");
  ASSERT_FALSE(t.alarm);
  // Snapshot of #2=#1*2 (line 4): stack main -> O9000 (G65).
  const StateSnapshot* s4 = nullptr;
  const StateSnapshot* s8 = nullptr;
  for (const StateSnapshot& s : t.snapshots) {
    if (s.line == 4) s4 = &s;
    if (s.line == 8) s8 = &s;
  }
  ASSERT_TRUE(s4 && s8);
  EXPECT_EQ(s4->callLevel, 1);
  EXPECT_EQ(s4->program, 9000);
  const auto& stack = t.flow.stacks.at(static_cast<std::size_t>(s8->callStack));
  ASSERT_EQ(stack.size(), 3u);
  EXPECT_EQ(stack[1].kind, CallFrame::Kind::Macro);
  EXPECT_EQ(stack[1].callLine, 1);
  EXPECT_EQ(stack[2].kind, CallFrame::Kind::Subprogram);
  EXPECT_EQ(stack[2].program, 9100);
  EXPECT_EQ(stack[2].callLine, 5);
  // #1 = 3 (the argument), then #2 = 6, both in the macro's local frame.
  bool arg = false, product = false;
  for (const VariableWrite& w : t.flow.writes) {
    if (w.number == 1 && w.value == 3.0 && w.localFrame == stack[1].locals) arg = true;
    if (w.number == 2 && w.value == 6.0 && w.localFrame == stack[1].locals) product = true;
  }
  EXPECT_TRUE(arg);
  EXPECT_TRUE(product);
}

}  // namespace
}  // namespace klueng::core::machine

#include "klueng/core/machine/flow_view.h"

namespace klueng::core::machine {
namespace {

TEST(FlowView, VariablesOfTheRunningLevelAndTheLastStepsChanges) {
  // Line 1: #100=1; line 2 G65 A5. -> O9000: line 5 #2=#1*2, line 6 #100=#2; back: line 3.
  const Timeline t = runText("#100=1\nG65 P9000 A5.\nG00 X10.\nM30\nO9000\n#2=#1*2\n#100=#2\nM99\n");
  ASSERT_FALSE(t.alarm);
  auto snapOfLine = [&t](int line) {
    for (std::size_t i = 0; i < t.snapshots.size(); ++i)
      if (t.snapshots[i].line == line) return static_cast<int>(i);
    return -1;
  };
  const int s6 = snapOfLine(6), s7 = snapOfLine(7), s3 = snapOfLine(3);
  ASSERT_TRUE(s6 >= 0 && s7 >= 0 && s3 >= 0);
  auto v = variablesAt(t, s6, s6 - 1);
  // Inside the macro: #1 = 5 (argument), #2 = 10 (just written), #100 = 1.
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[0].number, 1);
  EXPECT_DOUBLE_EQ(v[0].value, 5.0);
  EXPECT_EQ(v[1].number, 2);
  EXPECT_DOUBLE_EQ(v[1].value, 10.0);
  EXPECT_TRUE(v[1].changed);
  EXPECT_EQ(v[2].number, 100);
  EXPECT_FALSE(v[2].changed);
  v = variablesAt(t, s7, s6);
  EXPECT_DOUBLE_EQ(v[2].value, 10.0);
  EXPECT_TRUE(v[2].changed);
  // Back in the main program: the macro's locals are gone.
  v = variablesAt(t, s3, s7);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0].number, 100);
  // Step Over from the G65 block lands on line 3; Step Out of the macro too.
  const int s2 = snapOfLine(2);
  EXPECT_EQ(nextSnapshotAtLevel(t, s2, t.snapshots[static_cast<std::size_t>(s2)].callLevel), s3);
  EXPECT_EQ(nextSnapshotAtLevel(t, s6, 0), s3);
}

TEST(FlowView, TheValueAWordHadTheLastTimeItsLineRan) {
  const Timeline t = runText("G98\n#1=10.\nN5 G01 X#1 F100.\n#1=#1+10.\nIF [#1 LE 30.] GOTO 5\n");
  ASSERT_FALSE(t.alarm);
  const int last = static_cast<int>(t.snapshots.size()) - 1;
  const auto v = wordValueAt(t, last, 0, 3, 8);
  ASSERT_TRUE(v);
  EXPECT_DOUBLE_EQ(v->value, 30.0);
  EXPECT_FALSE(wordValueAt(t, 0, 0, 3, 8));  // not run yet at the first snapshot
}

}  // namespace
}  // namespace klueng::core::machine

namespace klueng::core::machine {
namespace {

// Found by fuzz_macro: values the checker never sees reach the interpreter through variables.
TEST(FlowRun, CodesFromVariablesAreRefusedNotCrashedOn) {
  Timeline t = runText("#1=-6\nT#1\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A128");
  EXPECT_EQ(t.alarm->range.line, 2);
  t = runText("#1=POW[10,84]/3\nG#1\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A143");
  t = runText("#1=3.3333\nM#1\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A143");
}

}  // namespace
}  // namespace klueng::core::machine

namespace klueng::core::machine {
namespace {

// Found by fuzz_macro (issue 13): an endless WHILE around a G75 of thousands
// of pecks ran 15 s and filled gigabytes before the block limit came near.
// Blocks run again may make 10 moves per max_blocks; here 10 x 1000.
TEST(FlowRun, AnEndlessLoopAroundABigCycleStopsOnItsMoves) {
  MachineSetup setup = testing::testSetup();
  setup.machine.maxBlocks = 1000;
  // G75 from X52 Z2 to X40 Z-60: 6 mm deep in 1 mm pecks (P1000), a position
  // every 0.1 mm (Q100): 621 positions, each 6 feeds, 5 retracts between them,
  // the way out and the step to the next (the last: back to the start) =
  // 621 x 13 = 8073 moves a pass. Each pass counts in #1: no pass comes back to the state of
  // another (a loop that did would be proven endless, A155, before its third pass).
  const Timeline t = runText(
      "G21 G99 G97 S500 M03\nG00 X52. Z2.\n#1=0\nWHILE [#1 LT 10] DO1\n#1=#1+1\nG75 R0.5\nG75 X40. Z-60. P1000 "
      "Q100 F0.05\nEND1\nM30\n",
      RunOptions{}, setup);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A151");
  EXPECT_EQ(t.alarm->range.line, 8);  // END1, the jump that repeated
  EXPECT_EQ(t.alarm->args.at(2), "1000");
  EXPECT_EQ(t.alarm->args.at(3), "10000");
  // The first pass is not repeated; the second counts 8073 and the third passes 10000.
  EXPECT_EQ(t.alarm->args.at(1), std::to_string(2 * 8073));
  EXPECT_LT(t.moves.size(), 4u * 8073u);
  expectBilingual(*t.alarm);
}

// The profile runs through the interpreter (issue 12): a value such as X#1 is
// read like any block's; a statement inside the profile is refused.
TEST(FlowRun, ACycleProfileWithAMacroStatementIsAnAlarmNotAWrongPart) {
  const Timeline t = runText(
      "G98 G97 S500 M03\nG00 X50. Z2.\n#1=30.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 F100.\nN10 G00 X#1\n#2=-20.\nG01 "
      "Z#2\nN20 X50.\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A148");
  EXPECT_EQ(t.alarm->range.line, 5);
  EXPECT_EQ(t.alarm->args.at(1), "7");
}

}  // namespace
}  // namespace klueng::core::machine

namespace klueng::core::machine {
namespace {

// Issue 13: peck cycles that would expand into millions of moves (and gigabytes)
// are refused before anything is allocated; their moves, not only their passes, count.
TEST(CycleBounds, HugePeckAndPatternCyclesAreAlarmsNotBlowUps) {
  const char* cases[] = {
      "G98 G97 S500 M03\nG00 X50. Z2.\nG75 R0.5\nG75 X40. Z-100. P1 Q2 F50.\n",
      "G98 G97 S500 M03\nG00 X0. Z2.\nG74 R1.\nG74 X999. Z-40. P1 Q1000 F50.\n",
      "G98 G97 S500 M03\nG00 X50. Z2.\nG75 R0.5\nG75 X40. Z-999. P1000 Q1 F50.\n",
  };
  for (const char* text : cases) {
    const Timeline t = runText(text);
    ASSERT_TRUE(t.alarm) << text;
    EXPECT_EQ(t.alarm->code, "A149") << text;
    EXPECT_EQ(t.alarm->range.line, 4) << text;
    EXPECT_LT(t.moves.size(), 10u);
  }
  // G73 R9999 over a 30-block profile: 9999 x 31 moves.
  std::string g73 = "G98 G97 S500 M03\nG00 X60. Z2.\nG73 U3. W0. R9999\nG73 P10 Q20 U0.4 F100.\nN10 G00 X20.\n";
  for (int k = 1; k <= 28; ++k) g73 += "G01 Z-" + std::to_string(k) + ".\n";
  g73 += "N20 X60.\n";
  const Timeline t = runText(g73);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A149");
}

}  // namespace
}  // namespace klueng::core::machine

namespace klueng::core::machine {
namespace {

// Issue 13: "G02 X40. Z-20." said "not on one circle (radius 0.000)" at run time.
TEST(FlowCheck, AnArcWithoutRadiusOrCentreSaysSo) {
  const auto ds = checkText("G98 G00 X20. Z0.\nG02 X40. Z-20. F100.\nG03 X50. Z-25. R5.\n");
  ASSERT_EQ(ds.size(), 1u);
  EXPECT_EQ(ds[0].code, "E310");
  EXPECT_EQ(ds[0].range, (SourceRange{2, 1, 3}));
  EXPECT_EQ(formatMessage(ds[0], Lang::En),
            "G02 needs its radius R or its centre I/K: an arc cannot be cut from its end point alone");
}

}  // namespace
}  // namespace klueng::core::machine

namespace klueng::core::machine {
namespace {

// A program that corrects its own wear: #2002 (X of offset 02) written, then T0202 uses it.
TEST(FlowRun, WritingAnOffsetCountsFromTheNextTWord) {
  const Timeline t = runText("#2002 = #2002 + 0.2\n#100 = #2002\nT0202\nG98 G00 X20. Z10.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  double got = 0.0;
  for (const VariableWrite& w : t.flow.writes)
    if (w.number == 100) got = w.value;
  EXPECT_NEAR(got, 0.6, 1e-9);  // the test setup's offset 02 has X +0.4
  // X20 with X offset 0.6 (diameter): the controlled point at diameter 20.6.
  EXPECT_NEAR(2.0 * t.moves.back().path.end.y(), 20.6, 1e-9);
  const Timeline bad = runText("#2202 = -1.\n");
  ASSERT_TRUE(bad.alarm);
  EXPECT_EQ(bad.alarm->code, "A139");
}

}  // namespace
}  // namespace klueng::core::machine

namespace klueng::core::machine {
namespace {

// Found by fuzz_macro: a G65 block with expressions read its P through the
// letter index of the block before, which pointed into that block's evaluated
// words — here at this block's A, so it called O1000 instead of O9000.
TEST(FlowRun, G65ReadsItsOwnPAfterABlockWithExpressions) {
  const Timeline t = testing::runText("O0001\nG98\n#1=1000\nG04 P#1\nG65 A#1 P9000\nM30\nO9000\n#100=#1+1\nM99\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  bool called = false;
  for (const VariableWrite& w : t.flow.writes)
    if (w.number == 100) called = w.value == 1001.0;
  EXPECT_TRUE(called);
}

}  // namespace
}  // namespace klueng::core::machine

// Going back in a cut (issue 12): the stock restored from a checkpoint and cut
// forward again is the stock a fresh simulator cuts to the same time.
#include <gtest/gtest.h>

#include "cut_test_util.h"
#include "klueng/core/cut/cut_simulator.h"

namespace klueng::core::cut {
namespace {

using machine::MoveKind;
using testing::barSetup;
using testing::libraryWith;
using testing::move;
using testing::squareTool;
using testing::timelineOf;

// 300 roughing passes, 0.05 mm deeper each: every pass removes material, so
// any move cut twice or skipped shows in the stock.
machine::Timeline passes(int count) {
  std::vector<machine::Move> moves;
  for (int k = 0; k < count; ++k) {
    const double r = 24.9 - 0.05 * k;
    const double zEnd = -40.0 + 0.1 * (k % 7);
    moves.push_back(move(MoveKind::Line, Segment::line(zx(1, r), zx(zEnd, r)), 0, 2, 10 + k));
    moves.push_back(move(MoveKind::Line, Segment::line(zx(zEnd, r), zx(zEnd, r + 0.5)), 0, 0.2, 10 + k));
    moves.push_back(move(MoveKind::Rapid, Segment::line(zx(zEnd, r + 0.5), zx(1, r + 0.5)), 0, 0.3, 10 + k));
  }
  return timelineOf(std::move(moves));
}

void expectSameStock(const Stock& a, const Stock& b) {
  ASSERT_EQ(a.columnCount(), b.columnCount());
  for (int i = 0; i < a.columnCount(); ++i) {
    ASSERT_EQ(a.outerRadius(i), b.outerRadius(i)) << "column " << i;
    ASSERT_EQ(a.innerRadius(i), b.innerRadius(i)) << "column " << i;
  }
  EXPECT_DOUBLE_EQ(a.removedVolume(), b.removedVolume());
}

TEST(CutCheckpoints, GoingBackGivesTheStockOfAFreshCut) {
  const machine::Timeline tl = passes(300);  // 900 moves, 750 s
  CutSimulator sim(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)));
  sim.runToEnd();
  ASSERT_FALSE(sim.alarm());
  EXPECT_EQ(sim.checkpointCount(), 900u / 64u);  // one every 64 moves
  // Back to a block boundary, into the middle of a move, to the start, and forward again.
  for (const double t : {600.0, 333.3, 1.0, 0.0, 512.75, 749.0, 64.0}) {
    sim.advanceTo(t);
    CutSimulator fresh(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)));
    fresh.advanceTo(t);
    EXPECT_DOUBLE_EQ(sim.time(), t);
    expectSameStock(sim.stock(), fresh.stock());
  }
}

TEST(CutCheckpoints, AStepBackCutsAtMostOneCheckpointSpan) {
  const machine::Timeline tl = passes(300);
  CutSimulator sim(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)));
  sim.runToEnd();
  const double back = tl.moves[700].tStart + 0.1;
  EXPECT_LE(sim.movesToCut(back), 64u);
  EXPECT_GE(sim.movesToCut(back), 1u);
  // Forward from where it stands costs only the moves between: the rest of 700, then 701-705.
  sim.advanceTo(back);
  EXPECT_EQ(sim.movesToCut(tl.moves[705].tEnd), 6u);
  // Before the first checkpoint: from the bar.
  EXPECT_EQ(sim.movesToCut(tl.moves[10].tEnd), 11u);
}

TEST(CutCheckpoints, TheBudgetSpreadsThemOverALongRun) {
  const machine::Timeline tl = passes(3000);  // 9000 moves
  CutOptions options;
  // Room for about 20 copies of the Ø50 x 100 bar (2000 columns of 0.05 mm).
  options.checkpointBudgetBytes = 20 * (64 * 2000 + 256);
  CutSimulator sim(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)), options);
  sim.runToEnd();
  EXPECT_LE(sim.checkpointCount(), 20u);
  EXPECT_GE(sim.checkpointCount(), 19u);
}

// A run that only goes forward (the CLI) asks for none: no copies, the same part.
TEST(CutCheckpoints, ABudgetOfZeroKeepsNone) {
  const machine::Timeline tl = passes(300);
  CutOptions none;
  none.checkpointBudgetBytes = 0;
  CutSimulator lean(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)), none);
  lean.runToEnd();
  EXPECT_EQ(lean.checkpointCount(), 0u);
  CutSimulator usual(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)));
  usual.runToEnd();
  EXPECT_GT(usual.checkpointCount(), 0u);
  EXPECT_DOUBLE_EQ(lean.stock().volume(), usual.stock().volume());
}

}  // namespace
}  // namespace klueng::core::cut

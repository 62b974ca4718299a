// Start-up (Fanuc type A) and cancel moves, with expected coordinates worked
// out by hand. Points are (z, x radius); R = 0.8 throughout.
#include <gtest/gtest.h>

#include <cmath>

#include "comp_test_support.h"
#include "klueng/core/comp/nose_comp.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace klueng::core::comp::nose_comp_startup_cancel_test {
namespace {

using testing::expectWellFormed;
using testing::PathBuilder;
using testing::piecesOf;

constexpr double R = 0.8;
const double kHalfRoot2 = std::sqrt(0.5);

// G42 G00 from (50,30) to (2,10), then G01 -Z along X10.
// Before start-up the imaginary tip (tip 3, vector (-1,-1)) is at (50,30), so
// the centre starts at (50,30) - 0.8*(-1,-1) = (50.8, 30.8). The next move runs
// -Z; its right-hand normal is +X, so the start-up ends at (2, 10.8).
TEST(StartUp, EndsPerpendicularToTheNextMoveOnTheRight) {
  const auto moves = PathBuilder(50, 30).lineTo(2, 10).lineTo(-10, 10).build();
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, 3, false});
  ASSERT_FALSE(out.interference);
  expectWellFormed(out, 2);
  const auto up = piecesOf(out, 0);
  ASSERT_EQ(up.size(), 1u);
  EXPECT_FALSE(up[0].isArc());
  EXPECT_VEC_NEAR(up[0].start, Vec2(50.8, 30.8), 1e-12);
  EXPECT_VEC_NEAR(up[0].end, Vec2(2, 10.8), 1e-12);
  // The controlled point starts where the tool was: exactly the programmed point.
  EXPECT_VEC_NEAR(controlledPoint(up[0].start, R, 3), Vec2(50, 30), 1e-12);
  EXPECT_VEC_NEAR(piecesOf(out, 1)[0].end, Vec2(-10, 10.8), 1e-12);
}

// Same start-up, but the next move is a 45-degree chamfer up and to the left,
// direction (-1,1)/sqrt2: its right-hand normal is (1,1)/sqrt2, so the
// start-up ends at (2,10) + 0.8*(0.7071, 0.7071) = (2.565685, 10.565685).
TEST(StartUp, UsesTheStartDirectionOfAChamfer) {
  const auto moves = PathBuilder(50, 30).lineTo(2, 10).lineTo(-1, 13).build();
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, 3, false});
  EXPECT_VEC_NEAR(piecesOf(out, 0)[0].end, Vec2(2.565685, 10.565685), 1e-6);
}

// The next move is a G03 arc from (0,10) around (-3,6) (radius 5): its start
// radius vector is (3,4)/5 and, the tool being right of a counter-clockwise
// arc, i.e. outside, the start-up ends at (0,10) + 0.8*(0.6,0.8) = (0.48, 10.64).
TEST(StartUp, UsesTheStartDirectionOfAnArc) {
  const auto moves = PathBuilder(50, 30).lineTo(0, 10).arcTo(-8, 6, -3, 6, false).build();
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, 3, false});
  ASSERT_FALSE(out.interference);
  EXPECT_VEC_NEAR(piecesOf(out, 0)[0].end, Vec2(0.48, 10.64), 1e-12);
  const auto arc = piecesOf(out, 1);
  ASSERT_EQ(arc.size(), 1u);
  EXPECT_NEAR(arc[0].radius(), 5.8, 1e-12);
  EXPECT_VEC_NEAR(arc[0].end, Vec2(-8.8, 6), 1e-12);
}

// G41 boring towards the chuck with a boring bar (tip 2, vector (-1,1)):
// G41 G00 from (50,2) to (2,10), then -Z along X10. Centre starts at
// (50,2) - 0.8*(-1,1) = (50.8, 1.2); left of -Z travel is -X, so the
// start-up ends at (2, 9.2).
TEST(StartUp, LeftSideForBoring) {
  const auto moves = PathBuilder(50, 2).lineTo(2, 10).lineTo(-20, 10).build();
  const CompOutput out = compensate(CompInput{moves, Side::Left, R, 2, false});
  EXPECT_VEC_NEAR(piecesOf(out, 0)[0].start, Vec2(50.8, 1.2), 1e-12);
  EXPECT_VEC_NEAR(piecesOf(out, 0)[0].end, Vec2(2, 9.2), 1e-12);
  EXPECT_VEC_NEAR(piecesOf(out, 1)[0].end, Vec2(-20, 9.2), 1e-12);
}

// The program ends right after the start-up: offset perpendicular to the
// start-up itself. (10,20) -> (0,10) runs along (-1,-1)/sqrt2; its right-hand
// normal is (-1,1)/sqrt2, so the end is (-0.565685, 10.565685).
TEST(StartUp, WithoutANextMoveUsesItsOwnDirection) {
  const auto moves = PathBuilder(10, 20).lineTo(0, 10).build();
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, 3, false});
  ASSERT_EQ(out.pieces.size(), 1u);
  EXPECT_VEC_NEAR(out.pieces[0].path.end, Vec2(-0.565685, 10.565685), 1e-6);
}

// G42 issued where the tool already stands (zero-length start-up at (2,10)):
// the nose still moves from the uncompensated centre (2.8, 10.8) to (2, 10.8).
TEST(StartUp, ZeroLengthStartUpStillShiftsTheNose) {
  const auto moves = PathBuilder(2, 10).lineTo(2, 10).lineTo(-10, 10).build();
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, 3, false});
  EXPECT_VEC_NEAR(piecesOf(out, 0)[0].start, Vec2(2.8, 10.8), 1e-12);
  EXPECT_VEC_NEAR(piecesOf(out, 0)[0].end, Vec2(2, 10.8), 1e-12);
}

// ... -Z along X10 to (-20,10), then G40 G00 X100 Z50 (radius point (50,30)).
// The cancel starts perpendicular to the END of the previous move, (-20,10.8),
// and ends at the uncompensated centre (50,30) - 0.8*(-1,-1) = (50.8, 30.8).
TEST(Cancel, StartsPerpendicularToThePreviousEnd) {
  const auto moves = PathBuilder(50, 30).lineTo(2, 10).lineTo(-20, 10).lineTo(50, 30).build();
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, 3, true});
  ASSERT_FALSE(out.interference);
  expectWellFormed(out, 3);
  const auto cancel = piecesOf(out, 2);
  ASSERT_EQ(cancel.size(), 1u);
  EXPECT_VEC_NEAR(cancel[0].start, Vec2(-20, 10.8), 1e-12);
  EXPECT_VEC_NEAR(cancel[0].end, Vec2(50.8, 30.8), 1e-12);
  EXPECT_VEC_NEAR(controlledPoint(cancel[0].end, R, 3), Vec2(50, 30), 1e-12);
}

// After a face up to (-20,15) the cancel starts at (-20 + 0.8, 15): right of +X travel is +Z.
TEST(Cancel, AfterAFaceUp) {
  const auto moves = PathBuilder(50, 30).lineTo(2, 10).lineTo(-20, 10).lineTo(-20, 15).lineTo(50, 30).build();
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, 8, true});
  const auto cancel = piecesOf(out, 3);
  EXPECT_VEC_NEAR(cancel[0].start, Vec2(-19.2, 15), 1e-12);
  EXPECT_VEC_NEAR(cancel[0].end, Vec2(50, 30.8), 1e-12);  // tip 8: vector (0,-1)
}

// After a G03 arc ending at (-8,6) around (-3,6): its end radius vector is
// (-1,0), the nose (outside) is at (-8.8, 6), where the cancel starts.
TEST(Cancel, AfterAnArc) {
  const auto moves = PathBuilder(50, 30).lineTo(0, 10).arcTo(-8, 6, -3, 6, false).lineTo(-20, 40).build();
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, 3, true});
  EXPECT_VEC_NEAR(piecesOf(out, 2)[0].start, Vec2(-8.8, 6), 1e-12);
  EXPECT_VEC_NEAR(piecesOf(out, 2)[0].end, Vec2(-19.2, 40.8), 1e-12);
}

// G42 start-up (50,30) -> (2,10) followed at once by G40 back to (50,30).
// The next move after the start-up is the cancel, direction (48,20)/52 =
// (12,5)/13; its right-hand normal is (5,-12)/13, so both meet at
// (2,10) + 0.8*(5,-12)/13 = (2.307692, 9.261538).
TEST(Cancel, RightAfterStartUp) {
  const auto moves = PathBuilder(50, 30).lineTo(2, 10).lineTo(50, 30).build();
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, 3, true});
  ASSERT_EQ(out.pieces.size(), 2u);
  EXPECT_VEC_NEAR(out.pieces[0].path.end, Vec2(2 + 0.8 * 5 / 13, 10 - 0.8 * 12 / 13), 1e-12);
  EXPECT_VEC_NEAR(out.pieces[1].path.start, out.pieces[0].path.end, 0.0);
  EXPECT_VEC_NEAR(out.pieces[1].path.end, Vec2(50.8, 30.8), 1e-12);
}

// One move that both starts and cancels: uncompensated at both ends.
TEST(Cancel, LoneMoveIsUncompensated) {
  const auto moves = PathBuilder(10, 10).lineTo(0, 10).build();
  const CompOutput out = compensate(CompInput{moves, Side::Left, R, 2, true});
  ASSERT_EQ(out.pieces.size(), 1u);
  EXPECT_VEC_NEAR(out.pieces[0].path.start, Vec2(10.8, 9.2), 1e-12);
  EXPECT_VEC_NEAR(out.pieces[0].path.end, Vec2(0.8, 9.2), 1e-12);
}

// Tip 0 / 9: the controlled point is the centre, so the uncompensated centre
// is the programmed point itself.
TEST(StartUp, TipZeroAndNineStartAtTheProgrammedPoint) {
  const auto moves = PathBuilder(50, 30).lineTo(2, 10).lineTo(-10, 10).lineTo(50, 30).build();
  for (int tip : {0, 9}) {
    const CompOutput out = compensate(CompInput{moves, Side::Right, R, tip, true});
    EXPECT_VEC_NEAR(out.pieces.front().path.start, Vec2(50, 30), 0.0);
    EXPECT_VEC_NEAR(out.pieces.back().path.end, Vec2(50, 30), 0.0);
    EXPECT_VEC_NEAR(out.pieces.front().path.end, Vec2(2, 10.8), 1e-12);
  }
}

// R = 0 (a sharp tool): the path is returned unchanged, one piece per move.
TEST(StartUp, ZeroRadiusLeavesThePathAlone) {
  const auto moves =
      PathBuilder(50, 30).lineTo(2, 10).lineTo(-10, 10).arcTo(-12, 12, -12, 10, false).lineTo(50, 30).build();
  const CompOutput out = compensate(CompInput{moves, Side::Right, 0.0, 3, true});
  ASSERT_EQ(out.pieces.size(), moves.size());
  for (std::size_t i = 0; i < moves.size(); ++i) {
    EXPECT_EQ(out.pieces[i].source, static_cast<int>(i));
    EXPECT_VEC_NEAR(out.pieces[i].path.end, moves[i].end, 0.0);
    EXPECT_EQ(out.pieces[i].path.isArc(), moves[i].isArc());
  }
}

TEST(StartUp, EmptyInputGivesNothing) {
  const CompOutput out = compensate(CompInput{{}, Side::Right, R, 3, true});
  EXPECT_TRUE(out.pieces.empty());
  EXPECT_FALSE(out.interference);
}

}  // namespace
}  // namespace klueng::core::comp::nose_comp_startup_cancel_test

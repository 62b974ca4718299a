// Corners between consecutive compensated moves: line-line against the seed's
// closed form, line-arc / arc-line / arc-arc by hand, bridging arcs, tangents,
// and zero-length moves.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "comp_test_support.h"
#include "klueng/core/comp/nose_comp.h"

namespace klueng::core::comp {
namespace {

using testing::expectWellFormed;
using testing::kDeg;
using testing::PathBuilder;
using testing::piecesOf;

constexpr double R = 0.8;

// [start-up, m1, m2] without cancel: the corner is between m1 and m2.
CompOutput compensateCorner(const std::vector<Segment>& moves, Side side, int tip = 3) {
  return compensate(CompInput{moves, side, R, tip, false});
}

class LineLineCorner : public ::testing::TestWithParam<std::tuple<Side, int>> {};

// For every pair of directions (alpha into the corner, beta out of it) the
// nose centre where the two offset lines meet is, by the seed's closed form
// (SPEC 9, written for tip 1 and generalised by the tip vector):
//   controlled - P = R * (tip.z - c*sin((a+b)/2)/cos((a-b)/2), tip.x + c*cos((a+b)/2)/cos((a-b)/2))
// with c = +1 for G41, -1 for G42. It holds for every concave corner and for
// convex turns up to 90 degrees; sharper convex corners get a bridging arc.
TEST_P(LineLineCorner, MatchesTheSeedClosedFormOrBridges) {
  const auto [side, tip] = GetParam();
  const double c = static_cast<int>(side);
  const Vec2 P(5, 10);
  const double length = 20;
  for (int alphaDeg = 0; alphaDeg < 360; alphaDeg += 15) {
    for (int turnDeg :
         {-170, -150, -120, -91, -90, -89, -60, -45, -30, -15, 15, 30, 45, 60, 89, 90, 91, 120, 150, 170}) {
      SCOPED_TRACE(::testing::Message() << "alpha " << alphaDeg << " turn " << turnDeg);
      const double a = alphaDeg * kDeg, b = (alphaDeg + turnDeg) * kDeg;
      const Vec2 t1(std::cos(a), std::sin(a)), t2(std::cos(b), std::sin(b));
      const std::vector<Segment> moves{Segment::line(P - 1.5 * length * t1, P - length * t1),
                                       Segment::line(P - length * t1, P), Segment::line(P, P + length * t2)};
      const CompOutput out = compensateCorner(moves, side, tip);
      ASSERT_FALSE(out.interference.has_value());
      expectWellFormed(out, 3);
      const auto first = piecesOf(out, 1);
      const auto second = piecesOf(out, 2);
      ASSERT_EQ(first.size(), 1u);
      const bool concave = c * std::sin(b - a) > 0;
      if (concave || std::abs(turnDeg) <= 90) {
        ASSERT_EQ(second.size(), 1u);
        const double k = 1.0 / std::cos((a - b) / 2);
        const Vec2 tv = tipVector(tip);
        const Vec2 seed = P + R * Vec2(tv.x() - c * std::sin((a + b) / 2) * k, tv.y() + c * std::cos((a + b) / 2) * k);
        EXPECT_VEC_NEAR(controlledPoint(first[0].end, R, tip), seed, 1e-9);
        EXPECT_VEC_NEAR(second[0].start, first[0].end, 1e-12);
      } else {
        ASSERT_EQ(second.size(), 2u);
        const Segment& bridge = second[0];
        ASSERT_TRUE(bridge.isArc());
        EXPECT_VEC_NEAR(bridge.centre, P, 1e-12);
        EXPECT_NEAR(bridge.radius(), R, 1e-12);
        EXPECT_EQ(bridge.ccw, side == Side::Right);
        EXPECT_NEAR(bridge.sweep(), std::abs(turnDeg) * kDeg, 1e-9);
        EXPECT_VEC_NEAR(bridge.start, P + c * R * Vec2(-t1.y(), t1.x()), 1e-12);
        EXPECT_VEC_NEAR(bridge.end, P + c * R * Vec2(-t2.y(), t2.x()), 1e-12);
      }
      // Nowhere along them does the nose come closer than R to the two programmed lines.
      const std::vector<Segment> contour{moves[1], moves[2]};
      for (const CompPiece& piece : out.pieces) {
        if (piece.source == 0) continue;
        for (int k = 0; k <= 40; ++k)
          EXPECT_GE(testing::distanceToPath(piece.path.pointAt(k / 40.0), contour), R - 1e-9);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllTipsBothSides, LineLineCorner,
                         ::testing::Combine(::testing::Values(Side::Left, Side::Right), ::testing::Range(0, 10)));

// G42 along X10 towards the chuck, then a G03 R5 arc leaving upwards (centre
// (-5,10)): a concave corner; the nose is outside the arc, offset radius 5.8.
// Offset line X = 10.8 meets (z+5)^2 + 0.8^2 = 5.8^2 at z = -5 + sqrt(33).
TEST(ArcCorner, LineIntoArcConcave) {
  const auto moves = PathBuilder(12, 10).lineTo(10, 10).lineTo(0, 10).arcTo(-5, 15, -5, 10, false).build();
  const CompOutput out = compensateCorner(moves, Side::Right);
  ASSERT_FALSE(out.interference);
  expectWellFormed(out, 3);
  const Vec2 x(-5 + std::sqrt(33.0), 10.8);
  EXPECT_VEC_NEAR(piecesOf(out, 1).back().end, x, 1e-9);
  const auto arc = piecesOf(out, 2);
  ASSERT_EQ(arc.size(), 1u);
  EXPECT_VEC_NEAR(arc[0].start, x, 1e-9);
  EXPECT_VEC_NEAR(arc[0].end, Vec2(-5, 15.8), 1e-9);
  EXPECT_NEAR(arc[0].radius(), 5.8, 1e-9);
}

// G03 R5 around the origin ending along -Z at (0,5), then a face up: concave.
// Offset arc radius 5.8 meets the offset face Z = 0.8 at x = sqrt(5.8^2 - 0.8^2) = sqrt(33).
TEST(ArcCorner, ArcIntoLineConcave) {
  const auto moves = PathBuilder(5, -3).lineTo(5, 0).arcTo(0, 5, 0, 0, false).lineTo(0, 8).build();
  const CompOutput out = compensateCorner(moves, Side::Right);
  ASSERT_FALSE(out.interference);
  expectWellFormed(out, 3);
  const Vec2 x(0.8, std::sqrt(33.0));
  EXPECT_VEC_NEAR(piecesOf(out, 1).back().end, x, 1e-9);
  EXPECT_VEC_NEAR(piecesOf(out, 2).front().start, x, 1e-9);
  EXPECT_VEC_NEAR(piecesOf(out, 2).front().end, Vec2(0.8, 8), 1e-9);
}

// G42 along X10, then a G02 R5 arc turning down (centre (-5,10)): a convex
// 90-degree corner. The nose is inside that arc (radius 4.2); the offset line
// X = 10.8 is extended to meet it at z = -5 + sqrt(4.2^2 - 0.8^2) = -5 + sqrt(17).
TEST(ArcCorner, LineIntoArcConvexExtendsTheLine) {
  const auto moves = PathBuilder(12, 10).lineTo(10, 10).lineTo(0, 10).arcTo(-5, 5, -5, 10, true).build();
  const CompOutput out = compensateCorner(moves, Side::Right);
  ASSERT_FALSE(out.interference);
  expectWellFormed(out, 3);
  const Vec2 x(-5 + std::sqrt(17.0), 10.8);
  EXPECT_VEC_NEAR(piecesOf(out, 1).back().end, x, 1e-9);
  ASSERT_EQ(piecesOf(out, 2).size(), 1u);
  EXPECT_NEAR(piecesOf(out, 2)[0].radius(), 4.2, 1e-9);
  const std::vector<Segment> contour{moves[1], moves[2]};
  for (const CompPiece& p : out.pieces)
    for (int k = 0; k <= 100; ++k) EXPECT_GE(testing::distanceToPath(p.path.pointAt(k / 100.0), contour), R - 1e-9);
}

// G03 R5 around the origin to (0,5), then G03 R5 around (-5,5) leaving upwards:
// concave; both offsets have radius 5.8 and meet on the bisector of the centres
// at (-2.5,2.5) + sqrt(5.8^2 - 12.5) * (1,1)/sqrt(2).
TEST(ArcCorner, ArcIntoArcConcave) {
  const auto moves = PathBuilder(5, -3).lineTo(5, 0).arcTo(0, 5, 0, 0, false).arcTo(-5, 10, -5, 5, false).build();
  const CompOutput out = compensateCorner(moves, Side::Right);
  ASSERT_FALSE(out.interference);
  expectWellFormed(out, 3);
  const double h = std::sqrt(5.8 * 5.8 - 12.5) / std::sqrt(2.0);
  const Vec2 x(-2.5 + h, 2.5 + h);
  EXPECT_VEC_NEAR(piecesOf(out, 1).back().end, x, 1e-9);
  EXPECT_VEC_NEAR(piecesOf(out, 2).front().start, x, 1e-9);
}

// G03 R5 to (0,5), then G02 R5 around (-5,5) turning down: convex 90 degrees.
// Offsets: radius 5.8 around (0,0) and 4.2 around (-5,5); they meet
// 33/sqrt(50) along the centre line from the origin, sqrt(5.8^2 - 33^2/50) off it.
TEST(ArcCorner, ArcIntoArcConvexExtendsBoth) {
  const auto moves = PathBuilder(5, -3).lineTo(5, 0).arcTo(0, 5, 0, 0, false).arcTo(-5, 0, -5, 5, true).build();
  const CompOutput out = compensateCorner(moves, Side::Right);
  ASSERT_FALSE(out.interference);
  expectWellFormed(out, 3);
  const double along = 33 / std::sqrt(50.0), h = std::sqrt(5.8 * 5.8 - along * along);
  const Vec2 u = Vec2(-1, 1) / std::sqrt(2.0);
  const Vec2 x = along * u + h * Vec2(u.y(), -u.x());
  EXPECT_VEC_NEAR(piecesOf(out, 1).back().end, x, 1e-9);
  ASSERT_EQ(piecesOf(out, 2).size(), 1u);
  EXPECT_VEC_NEAR(piecesOf(out, 2)[0].start, x, 1e-9);
}

// G03 R5 to (0,5), then a line down to the right at 45 degrees: a convex turn
// of 135 degrees. The nose goes round the corner on a bridging arc of radius R
// from (0, 5.8) to (0,5) + 0.8*(-1,-1)/sqrt(2), counter-clockwise (G42).
TEST(ArcCorner, SharpConvexCornerGetsABridgingArc) {
  const auto moves = PathBuilder(5, -3).lineTo(5, 0).arcTo(0, 5, 0, 0, false).lineTo(3, 2).build();
  const CompOutput out = compensateCorner(moves, Side::Right);
  ASSERT_FALSE(out.interference);
  expectWellFormed(out, 3);
  const auto after = piecesOf(out, 2);
  ASSERT_EQ(after.size(), 2u);
  ASSERT_TRUE(after[0].isArc());
  EXPECT_VEC_NEAR(after[0].start, Vec2(0, 5.8), 1e-9);
  EXPECT_VEC_NEAR(after[0].end, Vec2(-0.8 / std::sqrt(2.0), 5 - 0.8 / std::sqrt(2.0)), 1e-9);
  EXPECT_VEC_NEAR(after[0].centre, Vec2(0, 5), 1e-12);
  EXPECT_TRUE(after[0].ccw);
  EXPECT_NEAR(after[0].sweep(), 135 * kDeg, 1e-9);
}

// Going -Z and straight back +Z: the nose passes round the end point on a
// half circle from above (G42) to below it.
TEST(ArcCorner, FullReversalIsAHalfCircleRoundTheEndPoint) {
  const auto moves = PathBuilder(12, 10).lineTo(10, 10).lineTo(0, 10).lineTo(10, 10).build();
  const CompOutput out = compensateCorner(moves, Side::Right);
  ASSERT_FALSE(out.interference);
  const auto after = piecesOf(out, 2);
  ASSERT_EQ(after.size(), 2u);
  EXPECT_VEC_NEAR(after[0].start, Vec2(0, 10.8), 1e-12);
  EXPECT_VEC_NEAR(after[0].end, Vec2(0, 9.2), 1e-12);
  EXPECT_VEC_NEAR(after[0].pointAt(0.5), Vec2(-0.8, 10), 1e-9);  // goes round the front, not through the part
  EXPECT_VEC_NEAR(after[1].end, Vec2(10, 9.2), 1e-12);
}

// G42 along X15, a tangent G02 R2 fillet (centre (-20,17); the nose is inside
// it, offset radius 1.2, so it ends at (-20 - 1.2, 17)) and a tangent face up
// (offset Z = -22 + 0.8): one piece per move, no trimming.
TEST(ArcCorner, TangentContinuationAddsNothing) {
  const auto moves =
      PathBuilder(2, 15).lineTo(0, 15).lineTo(-20, 15).arcTo(-22, 17, -20, 17, true).lineTo(-22, 20).build();
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, 3, false});
  ASSERT_FALSE(out.interference);
  expectWellFormed(out, 4);
  ASSERT_EQ(out.pieces.size(), 4u);
  EXPECT_VEC_NEAR(out.pieces[1].path.start, Vec2(0, 15.8), 1e-12);
  EXPECT_VEC_NEAR(out.pieces[1].path.end, Vec2(-20, 15.8), 1e-12);
  ASSERT_TRUE(out.pieces[2].path.isArc());
  EXPECT_VEC_NEAR(out.pieces[2].path.end, Vec2(-21.2, 17), 1e-12);
  EXPECT_NEAR(out.pieces[2].path.radius(), 1.2, 1e-12);
  EXPECT_VEC_NEAR(out.pieces[3].path.end, Vec2(-21.2, 20), 1e-12);
}

// Zero and near-zero moves (a repeated point, a 1e-12 step, a zero-radius
// arc) have no direction: they get a zero-length piece where the nose is, the
// corner is taken between their neighbours, and nothing becomes NaN.
TEST(ArcCorner, ZeroLengthMovesGiveNoNaN) {
  const std::vector<Segment> moves{Segment::line({5, 12}, {2, 10}),
                                   Segment::line({2, 10}, {0, 10}),
                                   Segment::line({0, 10}, {0, 10}),
                                   Segment::line({0, 10}, {-1e-12, 10}),
                                   Segment::arc({-1e-12, 10}, {-1e-12, 10}, {-1e-12, 10}, true),
                                   Segment::line({-1e-12, 10}, {-5, 15}),  // 45 degrees up: concave for G42
                                   Segment::line({-5, 15}, {-5, 15}),
                                   Segment::line({-5, 15}, {20, 20})};
  for (const Side side : {Side::Left, Side::Right}) {
    for (const bool cancel : {false, true}) {
      const CompOutput out = compensate(CompInput{moves, side, R, 3, cancel});
      ASSERT_FALSE(out.interference);
      expectWellFormed(out, static_cast<int>(moves.size()));
      for (int zero : {2, 3, 4}) {
        const auto p = piecesOf(out, zero);
        ASSERT_EQ(p.size(), 1u);
        EXPECT_NEAR(p[0].length(), 0.0, 1e-9);
      }
    }
  }
  // G42: the corner between moves 1 and 5 is the concave 45-degree one.
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, 3, true});
  EXPECT_VEC_NEAR(piecesOf(out, 1)[0].end, Vec2(R * std::tan(22.5 * kDeg), 10.8), 1e-9);
  // A stretch made of nothing but a zero-length start-up.
  const std::vector<Segment> still{Segment::line({1, 1}, {1, 1})};
  const CompOutput none = compensate(CompInput{still, Side::Right, R, 3, false});
  ASSERT_EQ(none.pieces.size(), 1u);
  EXPECT_TRUE(testing::finite(none.pieces[0].path.end));
}

}  // namespace
}  // namespace klueng::core::comp

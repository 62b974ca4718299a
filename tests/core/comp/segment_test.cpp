// Segment basics, distances, offsets of single segments and carrier intersections.
#include "klueng/core/comp/segment.h"

#include <gtest/gtest.h>

#include "comp_test_support.h"
#include "klueng/core/comp/intersect.h"
#include "klueng/core/comp/nose_comp.h"

namespace klueng::core::comp {
namespace {

using testing::kDeg;

TEST(Segment, QuarterArcLengthSweepAndTangents) {
  // G03 from (5,0) to (0,5) around the origin: a quarter circle, counter-clockwise.
  const Segment ccw = Segment::arc({5, 0}, {0, 5}, {0, 0}, true);
  EXPECT_NEAR(ccw.sweep(), 90 * kDeg, 1e-12);
  EXPECT_NEAR(ccw.length(), 5 * 90 * kDeg, 1e-12);
  EXPECT_VEC_NEAR(ccw.startTangent(), Vec2(0, 1), 1e-12);
  EXPECT_VEC_NEAR(ccw.endTangent(), Vec2(-1, 0), 1e-12);
  EXPECT_VEC_NEAR(ccw.pointAt(0.5), Vec2(5 / std::sqrt(2.0), 5 / std::sqrt(2.0)), 1e-12);
  // The same end points clockwise go the long way round: three quarters.
  const Segment cw = Segment::arc({5, 0}, {0, 5}, {0, 0}, false);
  EXPECT_NEAR(cw.sweep(), 270 * kDeg, 1e-12);
  EXPECT_VEC_NEAR(cw.startTangent(), Vec2(0, -1), 1e-12);
  EXPECT_VEC_NEAR(cw.pointAt(0.5), Vec2(-5 / std::sqrt(2.0), -5 / std::sqrt(2.0)), 1e-12);
}

TEST(Segment, FullCircleAndZeroLengthLine) {
  const Segment full = Segment::arc({2, 0}, {2, 0}, {0, 0}, true);
  EXPECT_NEAR(full.sweep(), 2 * std::numbers::pi, 1e-12);
  const Segment dot = Segment::line({1, 1}, {1, 1});
  EXPECT_EQ(dot.length(), 0.0);
  EXPECT_EQ(dot.startTangent(), Vec2::Zero());  // no direction, and no NaN
}

TEST(Segment, TranslatedMovesEveryPoint) {
  const Segment a = Segment::arc({5, 0}, {0, 5}, {0, 0}, true).translated({1, -2});
  EXPECT_EQ(a.start, Vec2(6, -2));
  EXPECT_EQ(a.end, Vec2(1, 3));
  EXPECT_EQ(a.centre, Vec2(1, -2));
  EXPECT_TRUE(a.ccw);
}

struct DistanceCase {
  Vec2 p;
  double expected;
};

TEST(Segment, DistanceToLineClampsToTheEnds) {
  const Segment s = Segment::line({0, 0}, {10, 0});
  for (const DistanceCase& c :
       {DistanceCase{{5, 3}, 3.0}, DistanceCase{{-4, 3}, 5.0}, DistanceCase{{13, -4}, 5.0}, DistanceCase{{10, 0}, 0.0}})
    EXPECT_NEAR(distanceTo(s, c.p), c.expected, 1e-12) << c.p.transpose();
}

TEST(Segment, DistanceToArcUsesItsAngularRange) {
  const Segment quarter = Segment::arc({5, 0}, {0, 5}, {0, 0}, true);  // first quadrant
  for (const DistanceCase& c : {
           DistanceCase{{6, 6}, std::sqrt(72.0) - 5},                 // inside the range, outside the circle
           DistanceCase{{1, 1}, 5 - std::sqrt(2.0)},                  // inside the range, inside the circle
           DistanceCase{{0, 0}, 5.0},                                 // the centre
           DistanceCase{{-3, -4}, std::sqrt(8.0 * 8.0 + 4.0 * 4.0)},  // out of range: end point (5,0) is nearer
       })
    EXPECT_NEAR(distanceTo(quarter, c.p), c.expected, 1e-12) << c.p.transpose();
  // Clockwise from (0,5) to (5,0) covers the same quadrant.
  const Segment back = Segment::arc({0, 5}, {5, 0}, {0, 0}, false);
  EXPECT_NEAR(distanceTo(back, {6, 6}), std::sqrt(72.0) - 5, 1e-12);
  EXPECT_NEAR(distanceTo(back, {0, -7}), (Vec2(0, -7) - Vec2(5, 0)).norm(), 1e-12);
}

TEST(OffsetSegment, LineMovesByDToTheLeftOfTravel) {
  // Travel -Z: left is -X (down), right is +X (up).
  const Segment l = Segment::line({0, 10}, {-10, 10});
  EXPECT_VEC_NEAR(offsetSegment(l, 0.8)->start, Vec2(0, 9.2), 1e-12);
  EXPECT_VEC_NEAR(offsetSegment(l, -0.8)->end, Vec2(-10, 10.8), 1e-12);
  // Travel +X (up): left is -Z.
  const Segment up = Segment::line({0, 0}, {0, 4});
  EXPECT_VEC_NEAR(offsetSegment(up, 0.5)->end, Vec2(-0.5, 4), 1e-12);
}

struct ArcOffsetCase {
  bool ccw;
  double d;
  double expectedRadius;  // < 0: collapses
};

class OffsetArc : public ::testing::TestWithParam<ArcOffsetCase> {};

TEST_P(OffsetArc, RadiusShrinksOnTheInsideGrowsOnTheOutside) {
  const ArcOffsetCase& c = GetParam();
  const Segment arc = c.ccw ? Segment::arc({2, 0}, {0, 2}, {0, 0}, true) : Segment::arc({0, 2}, {2, 0}, {0, 0}, false);
  const auto off = offsetSegment(arc, c.d);
  if (c.expectedRadius < 0) {
    EXPECT_FALSE(off.has_value());
    return;
  }
  ASSERT_TRUE(off.has_value());
  EXPECT_NEAR(off->radius(), c.expectedRadius, 1e-12);
  EXPECT_NEAR((off->end - off->centre).norm(), c.expectedRadius, 1e-12);
  EXPECT_EQ(off->ccw, arc.ccw);
  EXPECT_NEAR(off->sweep(), arc.sweep(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Table, OffsetArc,
                         ::testing::Values(ArcOffsetCase{true, 0.8, 1.2},    // G03, left = inside
                                           ArcOffsetCase{true, -0.8, 2.8},   // G03, right = outside
                                           ArcOffsetCase{false, 0.8, 2.8},   // G02, left = outside
                                           ArcOffsetCase{false, -0.8, 1.2},  // G02, right = inside
                                           ArcOffsetCase{true, 2.5, -1},     // collapses
                                           ArcOffsetCase{false, -2.0, -1}));

TEST(IntersectCarriers, LinesMeetBeyondTheirEnds) {
  const auto hits = intersectCarriers(Segment::line({0, 0}, {1, 0}), Segment::line({5, 3}, {5, 2}));
  ASSERT_EQ(hits.count, 1);
  EXPECT_VEC_NEAR(hits.points[0], Vec2(5, 0), 1e-12);
  EXPECT_EQ(intersectCarriers(Segment::line({0, 0}, {1, 0}), Segment::line({0, 1}, {3, 1})).count, 0);
  EXPECT_EQ(intersectCarriers(Segment::line({0, 0}, {0, 0}), Segment::line({0, 1}, {3, 1})).count, 0);
}

TEST(IntersectCarriers, LineAndCircle) {
  const Segment circle = Segment::arc({5, 0}, {0, 5}, {0, 0}, true);
  const auto two = intersectCarriers(Segment::line({-10, 3}, {-9, 3}), circle);
  ASSERT_EQ(two.count, 2);
  EXPECT_VEC_NEAR(two.points[0], Vec2(-4, 3), 1e-12);
  EXPECT_VEC_NEAR(two.points[1], Vec2(4, 3), 1e-12);
  const auto touching = intersectCarriers(circle, Segment::line({-1, 5 + 1e-10}, {1, 5 + 1e-10}));
  ASSERT_EQ(touching.count, 1);
  EXPECT_VEC_NEAR(touching.points[0], Vec2(0, 5), 1e-9);
  EXPECT_EQ(intersectCarriers(Segment::line({-1, 6}, {1, 6}), circle).count, 0);
}

TEST(IntersectCarriers, TwoCircles) {
  const Segment a = Segment::arc({5, 0}, {0, 5}, {0, 0}, true);
  const Segment b = Segment::arc({11, 0}, {3, 0}, {7, 0}, true);  // radius 4 around (7,0)
  const auto hits = intersectCarriers(a, b);
  ASSERT_EQ(hits.count, 2);
  // x = (49 + 25 - 16) / 14, h = sqrt(25 - x^2)
  const double z = 58.0 / 14.0, x = std::sqrt(25 - z * z);
  EXPECT_VEC_NEAR(hits.points[0], Vec2(z, x), 1e-12);
  EXPECT_VEC_NEAR(hits.points[1], Vec2(z, -x), 1e-12);
  EXPECT_EQ(intersectCarriers(a, Segment::arc({3, 0}, {0, 3}, {0, 0}, true)).count, 0);     // concentric
  EXPECT_EQ(intersectCarriers(a, Segment::arc({21, 0}, {19, 0}, {20, 0}, true)).count, 0);  // apart
}

}  // namespace
}  // namespace klueng::core::comp

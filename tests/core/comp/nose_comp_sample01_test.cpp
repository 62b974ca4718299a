// End to end through the kernel: the finishing stretch of
// samples/01-step-shaft.txt (N330-N440), G42 with offset 01 (R0.8, tip 3).
// Programmed points in (z, x radius); diameters halved from the X words.
#include <gtest/gtest.h>

#include <cmath>

#include "comp_test_support.h"
#include "klueng/core/comp/nose_comp.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace klueng::core::comp::nose_comp_sample01_test {
namespace {

using testing::PathBuilder;

constexpr double R = 0.8;
constexpr int kTip = 3;

std::vector<Segment> finishingStretch() {
  return PathBuilder(100, 50)          // N320 G00 X100. Z100.
      .lineTo(2, 12)                   // N330 G42 G00 X24. Z2.   start-up
      .lineTo(0, 12)                   // N340 G01 Z0.
      .lineTo(-3, 15)                  // N350 X30. Z-3.          3x45 chamfer
      .lineTo(-20, 15)                 // N360 Z-20.
      .lineTo(-20, 18)                 // N370 X36.
      .arcTo(-22, 20, -22, 18, false)  // N380 G03 X40. Z-22. R2. (centre left of the chord)
      .lineTo(-40, 20)                 // N390 G01 Z-40.
      .lineTo(-40, 22)                 // N400 X44.
      .lineTo(-41, 23)                 // N410 X46. Z-41.         1x45 chamfer
      .lineTo(-60, 23)                 // N420 Z-60.
      .lineTo(-60, 26)                 // N430 X52.
      .lineTo(100, 50)                 // N440 G40 G00 X100. Z100. cancel
      .build();
}

// Worked by hand. G42 puts the nose above -Z travel, +Z of upward travel and
// (1,1)/sqrt2 off a chamfer running up to the left. t = R*tan(22.5 deg) =
// 0.8*(sqrt2 - 1) = 0.331371 is how far a 45-degree corner moves the
// intersection of two offset lines along each of them.
//  N330 start-up: from (100,50) - 0.8*(-1,-1) = (100.8, 50.8) to the point
//       perpendicular to N340's start: (2, 12) + (0, 0.8) = (2, 12.8).
//  N340/N350, concave 45 deg: offset X12.8 meets the chamfer offset
//       z + x = 0 + 12 + 0.8*sqrt2 at (t, 12.8).
//  N350/N360, convex 45 deg (<= 90: extend): X15.8 meets the same chamfer
//       offset at (-3 + t, 15.8).
//  N360/N370, concave 90 deg: (-20 + 0.8, 15 + 0.8) = (-19.2, 15.8).
//  N370/N380, tangent: the face offset Z-19.2 runs into the G03 offset
//       (centre (-22,18), radius 2 + 0.8 = 2.8, the nose outside) at (-19.2, 18).
//  N380/N390, tangent: the arc ends at (-22, 18 + 2.8) = (-22, 20.8).
//  N390/N400, concave 90 deg: (-40 + 0.8, 20.8) = (-39.2, 20.8).
//  N400/N410, convex 45 deg: Z-39.2 meets the 1x45 chamfer's offset
//       z + x = -40 + 22 + 0.8*sqrt2 at (-39.2, 22 + t).
//  N410/N420, convex 45 deg: X23.8 meets it at (-41 + t, 23.8).
//  N420/N430, concave 90 deg: (-59.2, 23.8).
//  N430 ends perpendicular to its own end: (-60 + 0.8, 26) = (-59.2, 26).
//  N440 cancel: from there to (100,50) - 0.8*(-1,-1) = (100.8, 50.8).
TEST(Sample01, FinishingStretchNoseCentreCorners) {
  const auto moves = finishingStretch();
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, kTip, true});
  ASSERT_FALSE(out.interference.has_value());
  testing::expectWellFormed(out, 12);
  ASSERT_EQ(out.pieces.size(), 12u);  // no convex corner sharper than 90 degrees: no bridging arcs

  const double t = 0.8 * (std::sqrt(2.0) - 1);
  const Vec2 expected[][2] = {
      {{100.8, 50.8}, {2, 12.8}},       {{2, 12.8}, {t, 12.8}},           {{t, 12.8}, {-3 + t, 15.8}},
      {{-3 + t, 15.8}, {-19.2, 15.8}},  {{-19.2, 15.8}, {-19.2, 18}},     {{-19.2, 18}, {-22, 20.8}},
      {{-22, 20.8}, {-39.2, 20.8}},     {{-39.2, 20.8}, {-39.2, 22 + t}}, {{-39.2, 22 + t}, {-41 + t, 23.8}},
      {{-41 + t, 23.8}, {-59.2, 23.8}}, {{-59.2, 23.8}, {-59.2, 26}},     {{-59.2, 26}, {100.8, 50.8}},
  };
  for (int i = 0; i < 12; ++i) {
    SCOPED_TRACE(::testing::Message() << "piece " << i);
    EXPECT_EQ(out.pieces[i].source, i);
    EXPECT_EQ(out.pieces[i].path.isArc(), i == 5);
    EXPECT_VEC_NEAR(out.pieces[i].path.start, expected[i][0], 1e-9);
    EXPECT_VEC_NEAR(out.pieces[i].path.end, expected[i][1], 1e-9);
  }
  const Segment& arc = out.pieces[5].path;
  EXPECT_VEC_NEAR(arc.centre, Vec2(-22, 18), 1e-12);
  EXPECT_TRUE(arc.ccw);
  EXPECT_NEAR(arc.radius(), 2.8, 1e-12);
}

// What the trace shows (controlled point = centre + 0.8*(-1,-1)): the tip of a
// tip-3 tool runs exactly on the drawn diameters and faces, so the part comes
// out as Ø30 / Ø40 / Ø46 with faces at Z-20, Z-40 and Z-60.
TEST(Sample01, ControlledPointRunsOnTheDrawnDiametersAndFaces) {
  const CompOutput out = compensate(CompInput{finishingStretch(), Side::Right, R, kTip, true});
  ASSERT_EQ(out.pieces.size(), 12u);
  const auto ctrl = [&](int i) { return controlledPath(out.pieces[i].path, R, kTip); };
  EXPECT_NEAR(2 * ctrl(3).start.y(), 30.0, 1e-9);
  EXPECT_NEAR(2 * ctrl(3).end.y(), 30.0, 1e-9);
  EXPECT_NEAR(ctrl(4).start.x(), -20.0, 1e-9);
  EXPECT_NEAR(2 * ctrl(6).end.y(), 40.0, 1e-9);
  EXPECT_NEAR(ctrl(7).start.x(), -40.0, 1e-9);
  EXPECT_NEAR(2 * ctrl(9).start.y(), 46.0, 1e-9);
  EXPECT_NEAR(ctrl(10).end.x(), -60.0, 1e-9);
  EXPECT_VEC_NEAR(ctrl(0).start, Vec2(100, 50), 1e-12);
  EXPECT_VEC_NEAR(ctrl(11).end, Vec2(100, 50), 1e-12);
}

// The whole finished contour (N340-N430) is reproduced: every point of it the
// nose can reach is touched at exactly R, and nothing is cut deeper.
TEST(Sample01, FinishedContourMatchesTheDrawing) {
  const auto moves = finishingStretch();
  const CompOutput out = compensate(CompInput{moves, Side::Right, R, kTip, true});
  const std::span<const Segment> contour(moves.data() + 1, moves.size() - 2);
  const auto nose = testing::centrePath(out);
  for (const Segment& piece : nose)
    for (int j = 0; j <= 400; ++j) EXPECT_GE(testing::distanceToPath(piece.pointAt(j / 400.0), contour), R - 1e-9);
  // Mid-points of the chamfers and of the R2 corner are touched.
  for (int i : {2, 5, 8}) EXPECT_NEAR(testing::distanceToPath(moves[i].pointAt(0.5), nose), R, 1e-9) << i;
}

}  // namespace
}  // namespace klueng::core::comp::nose_comp_sample01_test

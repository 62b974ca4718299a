// Without compensation (G40) the imaginary tip follows the program, so a round
// nose leaves material on tapers and arcs (or cuts into them, for a tip that
// points the wrong way). The leftover predicted from first principles must
// match the distance between the programmed contour and the nose-centre path
// the kernel reports (uncompensatedCentrePath), minus R.
#include <gtest/gtest.h>

#include <cmath>

#include "comp_test_support.h"
#include "klueng/core/comp/nose_comp.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace klueng::core::comp::nose_comp_uncompensated_test {
namespace {

using testing::kDeg;
using testing::PathBuilder;

constexpr double R = 0.8;

// Material left at programmed point q: how far the nose surface stays from it
// (negative: the nose cuts that deep into the part).
double leftover(const std::vector<Segment>& contour, int tip, const Vec2& q) {
  std::vector<Segment> nose;
  for (const Segment& s : contour) nose.push_back(uncompensatedCentrePath(s, R, tip));
  return testing::distanceToPath(q, nose) - R;
}

class OutsideTaper : public ::testing::TestWithParam<int> {};

// Outside turning, a taper rising phi degrees towards the chuck between two
// diameters. Its outward unit normal is n = (sin phi, cos phi). A tip-3 tool
// (tip vector (-1,-1)) keeps its nose centre at q + R*(1,1), which is
// R*(1,1).n = R*(sin phi + cos phi) from the taper line, so the nose surface
// leaves R*(sin phi + cos phi - 1): 0 on faces (phi = 90) and diameters, R*(sqrt2 - 1) =
// 0.331 mm on a 45-degree chamfer, 0.293 mm on a 30-degree taper.
TEST_P(OutsideTaper, TipThreeLeavesRTimesSinPlusCosMinusOne) {
  const double phi = GetParam() * kDeg;
  const double rise = 3;
  const double run = GetParam() == 90 ? 0.0 : rise / std::tan(phi);
  const auto contour = PathBuilder(5, 8).lineTo(0, 8).lineTo(-run, 8 + rise).lineTo(-run - 10, 8 + rise).build();
  const Vec2 middle = contour[1].pointAt(0.5);
  const double expected = R * (std::sin(phi) + std::cos(phi) - 1);
  EXPECT_NEAR(leftover(contour, 3, middle), expected, 1e-9);
  if (GetParam() == 45) {
    EXPECT_NEAR(leftover(contour, 3, middle), R * (std::sqrt(2.0) - 1), 1e-9);
  }
  // A centre-programmed tool (tip 0) would cut the whole radius into it.
  EXPECT_NEAR(leftover(contour, 0, middle), -R, 1e-9);
  // Along the diameters on either side the tip-3 nose touches exactly.
  EXPECT_NEAR(leftover(contour, 3, contour[2].pointAt(0.6)), 0.0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Angles, OutsideTaper, ::testing::Values(15, 30, 45, 60, 75, 90));

// The G03 R2 convex corner of sample 01 (from Z-20 X36 to Z-22 X40, centre
// (-22,18) in radius coordinates). At its 45-degree point q = C + 2u,
// u = (1,1)/sqrt2, the tip-3 nose centre path is the same arc moved by
// R*(1,1) = R*sqrt2*u, so q lies on the ray from the moved centre and is
// |2 - (2 - R*sqrt2)| = R*sqrt2 from the path: leftover R*(sqrt2 - 1).
TEST(UncompensatedArc, ConvexR2LeavesRTimesRootTwoMinusOneAtItsMiddle) {
  const auto contour =
      PathBuilder(-10, 15).lineTo(-20, 15).lineTo(-20, 18).arcTo(-22, 20, -22, 18, false).lineTo(-40, 20).build();
  const Vec2 q = contour[2].pointAt(0.5);
  EXPECT_VEC_NEAR(q, Vec2(-22 + std::sqrt(2.0), 18 + std::sqrt(2.0)), 1e-12);
  EXPECT_NEAR(leftover(contour, 3, q), R * (std::sqrt(2.0) - 1), 1e-9);
  // The face below and the diameter after it are cut exactly.
  EXPECT_NEAR(leftover(contour, 3, contour[1].pointAt(0.3)), 0.0, 1e-9);
  EXPECT_NEAR(leftover(contour, 3, contour[3].pointAt(0.5)), 0.0, 1e-9);
}

// A concave G02 R2 fillet from a diameter (X12 radius) up to a face, centre
// (-16,14). Its middle q = C - 2u; the tip-3 centre path is the fillet moved by
// R*sqrt2*u, i.e. centred R*sqrt2 further from q: |q - C'| = 2 + R*sqrt2, so
// the path (radius 2) is R*sqrt2 away and R*(sqrt2 - 1) stays in the fillet.
TEST(UncompensatedArc, ConcaveR2FilletKeepsRTimesRootTwoMinusOne) {
  const auto contour = PathBuilder(-10, 12).lineTo(-16, 12).arcTo(-18, 14, -16, 14, true).lineTo(-18, 17).build();
  const Vec2 q = contour[1].pointAt(0.5);
  EXPECT_NEAR(leftover(contour, 3, q), R * (std::sqrt(2.0) - 1), 1e-9);
}

// A boring bar (tip 2, vector (-1,1)) on a 45-degree entry chamfer of a bore
// going down towards the chuck: the outward normal (into the bore) is
// (1,-1)/sqrt2 and the centre sits at q + R*(1,-1), R*sqrt2 from the chamfer.
TEST(UncompensatedTaper, BoringBarOnAnEntryChamfer) {
  const auto contour = PathBuilder(3, 12).lineTo(0, 12).lineTo(-2, 10).lineTo(-20, 10).build();
  EXPECT_NEAR(leftover(contour, 2, contour[1].pointAt(0.5)), R * (std::sqrt(2.0) - 1), 1e-9);
  EXPECT_NEAR(leftover(contour, 2, contour[2].pointAt(0.5)), 0.0, 1e-9);
}

// A tip-3 tool on an outside chamfer that faces the chuck (diameter falling
// towards the chuck): its tip vector (-1,-1) lies along the chamfer, so the
// nose centre runs on the chamfer itself and cuts R deep into it.
TEST(UncompensatedTaper, TipThreeGougesAChamferFacingTheChuck) {
  const auto contour = PathBuilder(0, 20).lineTo(-10, 20).lineTo(-12, 18).lineTo(-20, 18).build();
  EXPECT_NEAR(leftover(contour, 3, contour[1].pointAt(0.5)), -R, 1e-9);
}

TEST(Uncompensated, CentreAndControlledPointAreInverse) {
  for (int tip = 0; tip <= 9; ++tip) {
    const Vec2 p(-3.5, 12.25);
    EXPECT_VEC_NEAR(controlledPoint(uncompensatedCentre(p, R, tip), R, tip), p, 1e-15);
    const Segment arc = Segment::arc({0, 10}, {-2, 12}, {-2, 10}, true);
    const Segment back = controlledPath(uncompensatedCentrePath(arc, R, tip), R, tip);
    EXPECT_VEC_NEAR(back.start, arc.start, 1e-15);
    EXPECT_VEC_NEAR(back.centre, arc.centre, 1e-15);
  }
}

}  // namespace
}  // namespace klueng::core::comp::nose_comp_uncompensated_test

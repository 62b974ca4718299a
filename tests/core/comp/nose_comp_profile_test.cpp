// Whole compensated stretches for every imaginary tip 0-9 and both sides, on
// profiles a real tool cuts: tapers (45 and 30 degrees), concave G02 and convex
// G03 arcs, steps and faces. What must hold (SPEC 9: "the finished part must
// match the programmed contour"):
//  (a) the nose centre never comes closer than R to the programmed contour;
//  (b) it is exactly R from every contour point the nose can reach, i.e. all
//      of each segment except the unreachable bit R*tan(turn/2) at each
//      concave corner, where the corner itself is R/cos(turn/2) away;
//  (c) the controlled point is centre + R*tipVector: it starts and ends at
//      the programmed points, and at each line-line corner it is where the
//      seed's closed form puts it.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <tuple>

#include "comp_test_support.h"
#include "klueng/core/comp/nose_comp.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace klueng::core::comp::nose_comp_profile_test {
namespace {

using testing::distanceToPath;
using testing::expectWellFormed;
using testing::PathBuilder;

constexpr double R = 0.8;
constexpr double kTol = 1e-6;  // far inside the 0.001 mm display resolution

struct Profile {
  std::string name;
  std::vector<Segment> moves;  // start-up, contour, cancel
  Side side;
};

// Outside turning towards the chuck with G42 (tool above the path):
// diameters grow towards the chuck, so every face is cut upwards.
std::vector<Segment> outsideTowardsChuck() {
  const double taper30 = 2 / std::tan(30 * testing::kDeg);  // 30-degree taper rising 2 mm
  return PathBuilder(30, 25)
      .lineTo(2, 8)                           // start-up (G42 G00)
      .lineTo(0, 8)                           // approach the chamfer
      .lineTo(-2, 10)                         // 45-degree chamfer
      .lineTo(-8, 10)                         // diameter 20
      .lineTo(-8 - taper30, 12)               // 30-degree taper
      .lineTo(-16, 12)                        // diameter 24
      .arcTo(-18, 14, -16, 14, /*cw=*/true)   // G02 R2 concave fillet
      .lineTo(-18, 17)                        // face up
      .arcTo(-20, 19, -20, 17, /*cw=*/false)  // G03 R2 convex corner
      .lineTo(-26, 19)                        // diameter 38
      .lineTo(-26, 21)                        // step
      .lineTo(-30, 21)                        // diameter 42
      .lineTo(-30, 24)                        // face up, off the part
      .lineTo(30, 30)                         // cancel (G40 G00)
      .build();
}

// Reflections keep each cut physically sensible and flip G41/G42 and G02/G03.
Segment reflect(const Segment& s, const std::function<Vec2(const Vec2&)>& f) {
  return s.isArc() ? Segment::arc(f(s.start), f(s.end), f(s.centre), !s.ccw) : Segment::line(f(s.start), f(s.end));
}

std::vector<Segment> reflected(const std::vector<Segment>& moves, const std::function<Vec2(const Vec2&)>& f) {
  std::vector<Segment> out;
  for (const Segment& s : moves) out.push_back(reflect(s, f));
  return out;
}

std::vector<Profile> profiles() {
  const auto od = outsideTowardsChuck();
  return {
      {"OutsideTowardsChuckG42", od, Side::Right},
      // Mirror about Z = -15: outside turning away from the chuck, tool above, G41.
      {"OutsideAwayFromChuckG41", reflected(od, [](const Vec2& p) { return Vec2(-30 - p.x(), p.y()); }), Side::Left},
      // Mirror about X = 15: boring towards the chuck, tool below, G41; faces cut downwards.
      {"BoringTowardsChuckG41", reflected(od, [](const Vec2& p) { return Vec2(p.x(), 30 - p.y()); }), Side::Left},
      // Swap the axes: a face with a raised hub cut downwards from X34 at Z0,
      // tool on the +Z side, G41.
      {"FaceDownwardsG41", reflected(od, [](const Vec2& p) { return Vec2(p.y() - 8, p.x() + 32); }), Side::Left},
  };
}

// Unreachable length at a corner seen from the segment: R*tan(turn/2) when the
// path bends towards the tool (concave), else 0. Tangent arcs give 0 too.
double concaveShadow(const Segment& before, const Segment& after, Side side) {
  const Vec2 t1 = before.endTangent(), t2 = after.startTangent();
  const double turnSin = t1.x() * t2.y() - t1.y() * t2.x();
  if (static_cast<int>(side) * turnSin <= 1e-9) return 0.0;
  return R * std::tan(std::atan2(std::abs(turnSin), t1.dot(t2)) / 2);
}

bool isBridge(const Segment& piece, const Segment& programmed) {
  return piece.isArc() && (piece.centre - programmed.start).norm() < 1e-9 && std::abs(piece.radius() - R) < 1e-9;
}

class ProfileAllTips : public ::testing::TestWithParam<std::tuple<Profile, int>> {};

TEST_P(ProfileAllTips, NoseTouchesTheContourEverywhereItCanAndNeverCutsIntoIt) {
  const auto& [profile, tip] = GetParam();
  const auto& moves = profile.moves;
  const int n = static_cast<int>(moves.size());
  const std::span<const Segment> contour(moves.data() + 1, n - 2);
  const CompOutput out = compensate(CompInput{moves, profile.side, R, tip, true});
  ASSERT_FALSE(out.interference.has_value());
  expectWellFormed(out, n);
  const std::vector<Segment> nose = testing::centrePath(out);

  // (a) every piece, start-up and cancel included, keeps R from the contour.
  for (std::size_t k = 0; k < nose.size(); ++k)
    for (int j = 0; j <= 200; ++j)
      ASSERT_GE(distanceToPath(nose[k].pointAt(j / 200.0), contour), R - kTol) << "piece " << k << " at " << j;

  for (int i = 1; i < n - 1; ++i) {
    const Segment& m = moves[i];
    SCOPED_TRACE(::testing::Message() << "move " << i);
    // (b1) each piece of the move (bridges aside) runs at R from the move's carrier.
    for (const Segment& piece : testing::piecesOf(out, i)) {
      if (isBridge(piece, m)) continue;
      for (int j = 1; j < 50; ++j) {
        const Vec2 c = piece.pointAt(j / 50.0);
        const double fromCarrier = m.isArc()
                                       ? std::abs((c - m.centre).norm() - m.radius())
                                       : std::abs((c - m.start).dot(Vec2(-m.startTangent().y(), m.startTangent().x())));
        EXPECT_NEAR(fromCarrier, R, kTol);
      }
    }
    // (b2) every reachable point of the programmed segment is touched: the nose is exactly R away.
    const double fromStart = i > 1 ? concaveShadow(moves[i - 1], m, profile.side) : 0.0;
    const double fromEnd = i < n - 2 ? concaveShadow(m, moves[i + 1], profile.side) : 0.0;
    for (int j = 0; j < 60; ++j) {
      const double s = (j + 0.5) / 60.0;
      const double along = s * m.length();
      if (along < fromStart + 1e-4 || along > m.length() - fromEnd - 1e-4) {
        // In a concave corner's shadow material stays: the nose is farther than R.
        EXPECT_GT(distanceToPath(m.pointAt(s), nose), R - kTol);
        continue;
      }
      EXPECT_NEAR(distanceToPath(m.pointAt(s), nose), R, kTol) << "at s = " << s;
    }
    // At a concave line-line corner the nose stops R/cos(turn/2) from the corner point.
    if (fromEnd > 0 && !m.isArc() && !moves[i + 1].isArc()) {
      const double turn = std::acos(std::clamp(m.endTangent().dot(moves[i + 1].startTangent()), -1.0, 1.0));
      EXPECT_NEAR(distanceToPath(m.end, nose), R / std::cos(turn / 2), kTol);
    }
  }

  // (c) the controlled point: where the tool was before G41/G42 and where G40 sends it.
  EXPECT_VEC_NEAR(controlledPoint(nose.front().start, R, tip), moves.front().start, 1e-12);
  EXPECT_VEC_NEAR(controlledPoint(nose.back().end, R, tip), moves.back().end, 1e-12);
  for (const CompPiece& p : out.pieces) {
    const Segment ctrl = controlledPath(p.path, R, tip);
    EXPECT_VEC_NEAR(ctrl.start - p.path.start, R * tipVector(tip), 1e-12);
    EXPECT_VEC_NEAR(ctrl.end - p.path.end, R * tipVector(tip), 1e-12);
  }
  // ... and at every line-line corner of the contour, the seed's closed form.
  const double c = static_cast<int>(profile.side);
  for (int i = 1; i + 1 < n - 1; ++i) {
    const Segment &a = moves[i], &b = moves[i + 1];
    if (a.isArc() || b.isArc()) continue;
    const double alpha = std::atan2(a.endTangent().y(), a.endTangent().x());
    const double beta = std::atan2(b.startTangent().y(), b.startTangent().x());
    if (std::abs(std::sin(beta - alpha)) < 1e-9) continue;
    const double k = 1 / std::cos((alpha - beta) / 2);
    const Vec2 tv = tipVector(tip);
    const Vec2 seed =
        a.end + R * Vec2(tv.x() - c * std::sin((alpha + beta) / 2) * k, tv.y() + c * std::cos((alpha + beta) / 2) * k);
    SCOPED_TRACE(::testing::Message() << "corner after move " << i);
    EXPECT_VEC_NEAR(controlledPoint(testing::piecesOf(out, i).back().end, R, tip), seed, 1e-9);
  }
}

// The contour's nose path is the same for every tip: only the start and the
// end of the stretch (uncompensated) depend on it.
TEST_P(ProfileAllTips, ContourPathDoesNotDependOnTheTip) {
  const auto& [profile, tip] = GetParam();
  const CompOutput mine = compensate(CompInput{profile.moves, profile.side, R, tip, true});
  const CompOutput centre = compensate(CompInput{profile.moves, profile.side, R, 0, true});
  ASSERT_EQ(mine.pieces.size(), centre.pieces.size());
  for (std::size_t k = 1; k + 1 < mine.pieces.size(); ++k) {
    EXPECT_VEC_NEAR(mine.pieces[k].path.start, centre.pieces[k].path.start, 0.0);
    EXPECT_VEC_NEAR(mine.pieces[k].path.end, centre.pieces[k].path.end, 0.0);
  }
  EXPECT_VEC_NEAR(mine.pieces.front().path.start - centre.pieces.front().path.start, -R * tipVector(tip), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(AllProfiles, ProfileAllTips,
                         ::testing::Combine(::testing::ValuesIn(profiles()), ::testing::Range(0, 10)),
                         [](const ::testing::TestParamInfo<ProfileAllTips::ParamType>& info) {
                           return std::get<0>(info.param).name + "_Tip" + std::to_string(std::get<1>(info.param));
                         });

// The profile's own shape, checked once so the cases above test what they claim.
TEST(ProfileShape, HasTapersArcsStepsAndFaces) {
  const auto od = outsideTowardsChuck();
  ASSERT_EQ(od.size(), 14u);
  EXPECT_NEAR(std::atan2(od[2].startTangent().y(), -od[2].startTangent().x()), 45 * testing::kDeg, 1e-12);
  EXPECT_NEAR(std::atan2(od[4].startTangent().y(), -od[4].startTangent().x()), 30 * testing::kDeg, 1e-12);
  EXPECT_TRUE(od[6].isArc() && !od[6].ccw);  // G02
  EXPECT_TRUE(od[8].isArc() && od[8].ccw);   // G03
  // Every arc is entered and left tangentially.
  for (int i : {6, 8}) {
    EXPECT_NEAR(od[i - 1].endTangent().dot(od[i].startTangent()), 1.0, 1e-12);
    EXPECT_NEAR(od[i].endTangent().dot(od[i + 1].startTangent()), 1.0, 1e-12);
  }
}

TEST(TipVector, FollowsTheSpecGrid) {
  EXPECT_EQ(tipVector(3), Vec2(-1, -1));  // outside turning tool
  EXPECT_EQ(tipVector(2), Vec2(-1, 1));   // boring bar
  EXPECT_EQ(tipVector(8), Vec2(0, -1));
  EXPECT_EQ(tipVector(0), Vec2(0, 0));
  EXPECT_EQ(tipVector(9), Vec2(0, 0));
  EXPECT_EQ(tipVector(5), Vec2(1, 0));
}

}  // namespace
}  // namespace klueng::core::comp::nose_comp_profile_test

// Interference: where the nose cannot follow the contour the kernel stops
// with the move index and keeps the pieces before it.
#include <gtest/gtest.h>

#include "comp_test_support.h"
#include "klueng/core/comp/nose_comp.h"
#include "klueng/core/messages.h"

namespace klueng::core::comp {
namespace {

using testing::expectWellFormed;
using testing::PathBuilder;
using testing::piecesOf;

// G42 towards the chuck along X10, a G02 R1 concave fillet (centre (0,11))
// into a face up at Z-1, then G40.
std::vector<Segment> filletProfile() {
  return PathBuilder(5, 15)
      .lineTo(2, 10)
      .lineTo(0, 10)
      .arcTo(-1, 11, 0, 11, true)
      .lineTo(-1, 14)
      .lineTo(20, 30)
      .build();
}

TEST(Interference, ConcaveArcSmallerThanTheNose) {
  const auto moves = filletProfile();
  const CompInput in{moves, Side::Right, 1.2, 3, true};
  const CompOutput out = compensate(in);
  ASSERT_TRUE(out.interference.has_value());
  EXPECT_EQ(out.interference->source, 2);
  EXPECT_EQ(out.interference->kind, Interference::Kind::ArcSmallerThanRadius);
  expectWellFormed(out, 2);  // start-up and the line before the fillet only
  EXPECT_VEC_NEAR(out.pieces.back().path.end, Vec2(0, 11.2), 1e-12);
  EXPECT_EQ(interferenceCode(out.interference->kind), "A201");
  EXPECT_EQ(interferenceArgs(*out.interference, in), (std::vector<std::string>{"1", "1.2"}));
  const Diagnostic d{Severity::Alarm, "A201", {}, interferenceArgs(*out.interference, in)};
  EXPECT_EQ(formatMessage(d, Lang::En),
            "Nose radius compensation interference: the concave arc's radius 1 mm is smaller than the tool nose "
            "radius 1.2 mm, so the nose cannot follow it");
  EXPECT_NE(formatMessage(d, Lang::Th).find("รัศมีจมูกมีด 1.2 มม."), std::string::npos);
}

TEST(Interference, SmallerNoseFollowsTheSameFillet) {
  const CompOutput out = compensate(CompInput{filletProfile(), Side::Right, 0.8, 3, true});
  EXPECT_FALSE(out.interference);
  expectWellFormed(out, 5);
  const auto fillet = piecesOf(out, 2);
  ASSERT_EQ(fillet.size(), 1u);
  EXPECT_NEAR(fillet[0].radius(), 0.2, 1e-12);  // 1 - 0.8
}

// A nose exactly as big as the fillet sits still at the fillet centre (0,11):
// the line's offset X = 11 ends there and the face's offset Z = 0 starts there.
TEST(Interference, NoseEqualToTheFilletStandsAtItsCentre) {
  const CompOutput out = compensate(CompInput{filletProfile(), Side::Right, 1.0, 3, true});
  EXPECT_FALSE(out.interference);
  expectWellFormed(out, 5);
  const auto fillet = piecesOf(out, 2);
  ASSERT_EQ(fillet.size(), 1u);
  EXPECT_VEC_NEAR(fillet[0].start, Vec2(0, 11), 1e-9);
  EXPECT_NEAR(fillet[0].length(), 0.0, 1e-9);
  EXPECT_VEC_NEAR(piecesOf(out, 3)[0].end, Vec2(0, 14), 1e-9);
}

// A convex arc smaller than the nose is no problem: the nose goes round it.
TEST(Interference, ConvexArcSmallerThanTheNoseIsFine) {
  const auto moves = PathBuilder(5, 15)
                         .lineTo(2, 10)
                         .lineTo(0, 10)
                         .lineTo(0, 12)
                         .arcTo(-0.5, 12.5, -0.5, 12, false)
                         .lineTo(-5, 12.5)
                         .build();
  const CompOutput out = compensate(CompInput{moves, Side::Right, 0.8, 3, false});
  EXPECT_FALSE(out.interference);
  EXPECT_NEAR(piecesOf(out, 3)[0].radius(), 1.3, 1e-12);
}

// A groove 1 mm wide and 3 mm deep cut with G42 and R0.8: between the two
// walls the bottom's offset (X12.8) would run from Z-5.8 to Z-5.2, i.e. +Z,
// against its programmed -Z direction.
std::vector<Segment> groove(double width) {
  return PathBuilder(5, 20)
      .lineTo(2, 15)
      .lineTo(-5, 15)
      .lineTo(-5, 12)
      .lineTo(-5 - width, 12)
      .lineTo(-5 - width, 15)
      .lineTo(-15, 15)
      .lineTo(20, 30)
      .build();
}

TEST(Interference, GrooveNarrowerThanTheNoseReversesThePath) {
  const auto moves = groove(1.0);
  const CompInput in{moves, Side::Right, 0.8, 3, true};
  const CompOutput out = compensate(in);
  ASSERT_TRUE(out.interference.has_value());
  EXPECT_EQ(out.interference->source, 3);
  EXPECT_EQ(out.interference->kind, Interference::Kind::PathReversal);
  expectWellFormed(out, 3);
  // The wall's piece before it is still valid: down the right wall, trimmed at the bottom offset.
  EXPECT_VEC_NEAR(out.pieces.back().path.start, Vec2(-5.8, 15.8), 1e-12);
  EXPECT_VEC_NEAR(out.pieces.back().path.end, Vec2(-5.8, 12.8), 1e-12);
  EXPECT_EQ(interferenceCode(out.interference->kind), "A202");
  EXPECT_EQ(interferenceArgs(*out.interference, in), (std::vector<std::string>{"0.8"}));
}

TEST(Interference, GrooveExactlyTwiceTheRadiusOrWiderIsCut) {
  for (const double width : {1.6, 2.0, 4.0}) {
    const CompOutput out = compensate(CompInput{groove(width), Side::Right, 0.8, 3, true});
    EXPECT_FALSE(out.interference) << width;
    const auto bottom = piecesOf(out, 3);
    ASSERT_EQ(bottom.size(), 1u);
    EXPECT_NEAR(bottom[0].length(), width - 1.6, 1e-9) << width;
    EXPECT_NEAR(bottom[0].start.y(), 12.8, 1e-12);
  }
}

TEST(Interference, ArcOnStartUpOrCancelIsRefused) {
  const auto arcStart = PathBuilder(10, 10).arcTo(0, 20, 0, 10, false).lineTo(-10, 20).build();
  const CompOutput a = compensate(CompInput{arcStart, Side::Right, 0.8, 3, false});
  ASSERT_TRUE(a.interference);
  EXPECT_EQ(a.interference->source, 0);
  EXPECT_EQ(a.interference->kind, Interference::Kind::ArcInStartUpOrCancel);
  EXPECT_TRUE(a.pieces.empty());

  const auto arcCancel = PathBuilder(10, 30).lineTo(0, 20).lineTo(-10, 20).arcTo(-20, 10, -10, 10, false).build();
  const CompInput in{arcCancel, Side::Right, 0.8, 3, true};
  const CompOutput c = compensate(in);
  ASSERT_TRUE(c.interference);
  EXPECT_EQ(c.interference->source, 2);
  expectWellFormed(c, 2);
  EXPECT_EQ(interferenceCode(c.interference->kind), "A203");
  EXPECT_TRUE(interferenceArgs(*c.interference, in).empty());
  // The same arc is a fine contour move when the stretch does not cancel on it.
  EXPECT_FALSE(compensate(CompInput{arcCancel, Side::Right, 0.8, 3, false}).interference);
}

TEST(Interference, EveryCodeHasEnglishAndThaiText) {
  for (const auto kind : {Interference::Kind::ArcSmallerThanRadius, Interference::Kind::PathReversal,
                          Interference::Kind::ArcInStartUpOrCancel}) {
    const MessageText* m = findMessage(interferenceCode(kind));
    ASSERT_NE(m, nullptr) << interferenceCode(kind);
    EXPECT_NE(m->th.find("จมูกมีด"), std::string_view::npos);
  }
}

}  // namespace
}  // namespace klueng::core::comp

// Chamfer ,C, corner ,R and angle ,A on G01 (Fanuc 0i-TF manual, "Chamfering
// and corner R", "Direct drawing dimension programming"): exact segments and
// the alarms, with line and column.
#include <gtest/gtest.h>

#include "klueng/core/gcode/checker.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

using testing::at;
using testing::runText;

std::vector<const Move*> cuts(const Timeline& t) {
  std::vector<const Move*> out;
  for (const Move& m : t.moves)
    if (m.kind != MoveKind::Rapid) out.push_back(&m);
  return out;
}

TEST(Corner, ChamferBetweenAFaceAndADiameter) {
  // Face up to X30 at Z0 with a 2 mm chamfer, then along Z: the chamfer runs
  // from X26 Z0 to X30 Z-2 (2 mm on the radius and 2 mm in Z from the corner).
  const Timeline t = runText("G98 G00 X20. Z0.\nG01 X30. ,C2. F100.\nZ-20.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  const auto c = cuts(t);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_POINT(c[0]->path.start, 20.0, 0.0);
  EXPECT_POINT(c[0]->path.end, 26.0, 0.0);
  EXPECT_EQ(c[0]->line, 2);
  EXPECT_POINT(c[1]->path.end, 30.0, -2.0);  // the chamfer, on the G01's line
  EXPECT_EQ(c[1]->line, 2);
  EXPECT_POINT(c[2]->path.start, 30.0, -2.0);
  EXPECT_POINT(c[2]->path.end, 30.0, -20.0);
  EXPECT_EQ(c[2]->line, 3);
}

TEST(Corner, RadiusBetweenADiameterAndAShoulder) {
  // Along Z to Z-20 then up the shoulder to X50 with R3: the arc runs from
  // X30 Z-17 to X36 Z-20, centre X36 Z-17, clockwise (G02) seen from +Y.
  const Timeline t = runText("G98 G00 X30. Z2.\nG01 Z-20. ,R3. F100.\nX50.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  const auto c = cuts(t);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_POINT(c[0]->path.end, 30.0, -17.0);
  ASSERT_TRUE(c[1]->path.isArc());
  EXPECT_FALSE(c[1]->path.ccw);
  EXPECT_POINT(c[1]->path.centre, 36.0, -17.0);
  EXPECT_POINT(c[1]->path.end, 36.0, -20.0);
  EXPECT_POINT(c[2]->path.start, 36.0, -20.0);
  EXPECT_POINT(c[2]->path.end, 50.0, -20.0);
}

TEST(Corner, ChamferOnATaperUsesTheDistanceAlongEachMove) {
  // 45-degree taper into a face: ,C1.414 ends 1 mm back in X and Z on the taper.
  const Timeline t = runText("G98 G00 X20. Z0.\nG01 X24. Z-2. ,C1.4142 F100.\nX40.\n");
  ASSERT_FALSE(t.alarm);
  const auto c = cuts(t);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_NEAR(2.0 * c[0]->path.end.y(), 22.0, 1e-3);
  EXPECT_NEAR(c[0]->path.end.x(), -1.0, 1e-3);
  EXPECT_NEAR(2.0 * c[1]->path.end.y(), 24.0 + 2.0 * 1.4142, 1e-3);
  EXPECT_NEAR(c[1]->path.end.x(), -2.0, 1e-6);
}

TEST(Corner, AngleGivesTheMissingCoordinate) {
  // ,A135 from X20 Z0 to X30: 5 mm up on the radius at 135 degrees from +Z
  // goes 5 mm toward -Z.
  const Timeline t = runText("G98 G00 X20. Z0.\nG01 X30. ,A135. F100.\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_POINT(t.moves.back().path.end, 30.0, -5.0);
}

TEST(Corner, TheNextBlockMustMove) {
  Timeline t = runText("G98 G00 X20. Z0.\nG01 X30. ,C2. F100.\nM08\nZ-20.\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A144");
  EXPECT_EQ(t.alarm->range, (SourceRange{2, 10, 4}));
  t = runText("G98 G00 X20. Z0.\nG01 X30. ,R2. F100.\nG00 Z5.\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A144");
  t = runText("G98 G00 X20. Z0.\nG01 X30. ,C2. F100.\n");  // the program ends
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A144");
}

TEST(Corner, HaasLetsADwellComeBetweenTheTwoMoves) {
  const std::string text = "G21 G98 G00 X20. Z0.\nG01 X30. ,C2. F100.\nG04 P500\nZ-20.\n";
  RunOptions haas;
  haas.dialect = gcode::Dialect::Haas;
  Timeline t = runText(text, haas);
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  const auto c = cuts(t);
  ASSERT_EQ(c.size(), 4u);  // the dwell, then the cut short face, the chamfer, the diameter
  EXPECT_POINT(c.back()->path.start, 30.0, -2.0);
  t = runText(text);  // Fanuc: the move must come next
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A144");
}

TEST(Corner, HaasReadsIOrKAsTheChamferOfA90DegreeCorner) {
  // Haas: "an I or K value can be substituted where ,C is used" - the same chamfer as
  // ChamferBetweenAFaceAndADiameter, from K on the face move and from I on a Z move.
  RunOptions haas;
  haas.dialect = gcode::Dialect::Haas;
  for (const char* text :
       {"G21 G98 G00 X20. Z0.\nG01 X30. K-2. F100.\nZ-20.\n", "G21 G98 G00 X30. Z5.\nG01 Z0. I2. F100.\nX20.\n"}) {
    const Timeline t = runText(text, haas);
    ASSERT_FALSE(t.alarm) << t.alarm->code;
    const auto c = cuts(t);
    ASSERT_EQ(c.size(), 3u) << text;
    EXPECT_EQ(c[1]->line, 2);
  }
  const Timeline face = runText("G21 G98 G00 X20. Z0.\nG01 X30. K-2. F100.\nZ-20.\n", haas);
  const auto c = cuts(face);  // (pointers into `face`: it must outlive them)
  EXPECT_POINT(c[0]->path.end, 26.0, 0.0);
  EXPECT_POINT(c[1]->path.end, 30.0, -2.0);
  // Along Z to the face with I2, then down the face: the Z move stops at Z2, the chamfer ends at X26 Z0.
  const Timeline along = runText("G21 G98 G00 X30. Z5.\nG01 Z0. I2. F100.\nX20.\n", haas);
  const auto d = cuts(along);
  EXPECT_POINT(d[0]->path.end, 30.0, 2.0);
  EXPECT_POINT(d[1]->path.end, 26.0, 0.0);
  // A Fanuc T series reads it too (B-63944EN-1/02 §4.5, CCR = 0); the classic rules do not: the face
  // runs to the corner, sharp (the checker's W107 says so).
  const Timeline fanuc = runText("G98 G00 X20. Z0.\nG01 X30. K-2. F100.\nZ-20.\n");
  const auto f = cuts(fanuc);
  ASSERT_EQ(f.size(), 3u);
  EXPECT_POINT(f[1]->path.end, 30.0, -2.0);
  RunOptions classic;
  classic.dialect = gcode::Dialect::Classic;
  const Timeline sharp = runText("G98\nG00 X20. Z0.\nG01 X30. K-2. F100.\nZ-20.\n", classic);
  const auto k = cuts(sharp);
  ASSERT_EQ(k.size(), 2u);
  EXPECT_POINT(k[0]->path.end, 30.0, 0.0);
}

TEST(Corner, TwoCornersInARowShareTheMoveBetweenThem) {
  // Face to X30 with ,C2, along Z to Z-20 with ,R3, up to X50: the Z move
  // runs between the chamfer's end (X30 Z-2) and the arc's start (X30 Z-17).
  const Timeline t = runText("G98 G00 X20. Z0.\nG01 X30. ,C2. F100.\nZ-20. ,R3.\nX50.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  const auto c = cuts(t);
  ASSERT_EQ(c.size(), 5u);
  EXPECT_POINT(c[0]->path.end, 26.0, 0.0);
  EXPECT_POINT(c[1]->path.end, 30.0, -2.0);
  EXPECT_EQ(c[1]->line, 2);
  EXPECT_POINT(c[2]->path.start, 30.0, -2.0);
  EXPECT_POINT(c[2]->path.end, 30.0, -17.0);
  EXPECT_EQ(c[2]->line, 3);
  ASSERT_TRUE(c[3]->path.isArc());
  EXPECT_POINT(c[3]->path.centre, 36.0, -17.0);
  EXPECT_POINT(c[3]->path.end, 36.0, -20.0);
  EXPECT_EQ(c[3]->line, 3);
  EXPECT_POINT(c[4]->path.start, 36.0, -20.0);
  EXPECT_POINT(c[4]->path.end, 50.0, -20.0);
  EXPECT_EQ(c[4]->line, 4);
}

TEST(Corner, ARadiusStraightOnRoundsNothing) {
  // ,R between two moves in one direction: no corner; the G01 runs whole.
  const Timeline t = runText("G98 G00 X30. Z2.\nG01 Z-10. ,R2. F100.\nZ-20.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  const auto c = cuts(t);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_FALSE(c[0]->path.isArc());
  EXPECT_POINT(c[0]->path.start, 30.0, 2.0);
  EXPECT_POINT(c[0]->path.end, 30.0, -10.0);
  EXPECT_POINT(c[1]->path.end, 30.0, -20.0);
}

TEST(Corner, ACornerLongerThanAMoveIsAnAlarm) {
  Timeline t = runText("G98 G00 X20. Z0.\nG01 X24. ,C3. F100.\nZ-20.\n");  // the face is 2 mm
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A145");
  EXPECT_EQ(t.alarm->range, (SourceRange{2, 10, 4}));
  t = runText("G98 G00 X20. Z0.\nG01 X40. ,R5. F100.\nZ-2.\n");  // the next move is 2 mm
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A145");
}

TEST(Corner, TheCheckerKeepsCornersOnG01) {
  gcode::CheckOptions o;
  auto ds = gcode::check(gcode::parse("G00 X20. ,C1.\n"), o);
  ASSERT_EQ(ds.size(), 1u);
  EXPECT_EQ(ds[0].code, "E132");
  EXPECT_EQ(ds[0].range, (SourceRange{1, 10, 4}));
  ds = gcode::check(gcode::parse("G01 X20. ,C1. ,R2. F0.1\n"), o);
  ASSERT_EQ(ds.size(), 1u);
  EXPECT_EQ(ds[0].code, "E133");
  EXPECT_TRUE(gcode::check(gcode::parse("G01 X20. ,C1. F0.1\nZ-5. ,R0.5\nX30. ,A90.\n"), o).empty());
  // ,C is not the C axis: no "two C words" and no C-axis rule.
  EXPECT_TRUE(gcode::check(gcode::parse("G01 X20. C0. ,C1. F0.1\nZ-5.\n"), o).empty());
}

}  // namespace
}  // namespace klueng::core::machine

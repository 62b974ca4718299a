#include "klueng/core/cut/finished_part.h"

#include <gtest/gtest.h>

#include <sstream>

#include "cut_test_util.h"

namespace klueng::core::cut {
namespace {

// A Ø40 x 10 bar turned to Ø30 over Z-4..0 and bored Ø12 over Z-6..0 (by hand).
Stock steppedBush() {
  Stock s(40.0, 10.0, 0.5);
  for (int i = 0; i < s.columnCount(); ++i) {
    if (s.zCentre(i) > -4.0) s.remove(i, 15.0, 20.0);
    if (s.zCentre(i) > -6.0) s.remove(i, 0.0, 6.0);
  }
  return s;
}

TEST(FinishedPart, MeasuresDiametersStepsAndVolume) {
  const Stock s = steppedBush();
  const FinishedPart part(s);
  EXPECT_DOUBLE_EQ(*part.outerDiameterAt(-2.0), 30.0);
  EXPECT_DOUBLE_EQ(*part.outerDiameterAt(-8.0), 40.0);
  EXPECT_DOUBLE_EQ(*part.innerDiameterAt(-3.0), 12.0);
  EXPECT_DOUBLE_EQ(*part.innerDiameterAt(-8.0), 0.0);
  EXPECT_FALSE(part.outerDiameterAt(1.0).has_value());
  EXPECT_DOUBLE_EQ(part.rightFaceZ(), 0.0);
  EXPECT_DOUBLE_EQ(part.leftFaceZ(), -10.0);
  EXPECT_DOUBLE_EQ(part.length(), 10.0);
  EXPECT_DOUBLE_EQ(part.maxDiameter(), 40.0);
  const auto [a, b] = part.stepExtent(-1.0);
  EXPECT_DOUBLE_EQ(a, -4.0);
  EXPECT_DOUBLE_EQ(b, 0.0);
  EXPECT_DOUBLE_EQ(part.stepLength(-7.0), 6.0);
  const double pi = 3.14159265358979323846;
  EXPECT_NEAR(part.volume(), pi * (400.0 * 6.0 + 225.0 * 4.0 - 36.0 * 6.0), 1e-6);
  // Interpolation between column centres over a step.
  EXPECT_DOUBLE_EQ(*part.outerDiameterAt(-4.0), 35.0);
}

TEST(FinishedPart, ProfilesAreClosedPolylinesWithVerticalSteps) {
  const Stock s = steppedBush();
  const FinishedPart part(s);
  const std::vector<Vec2> outer = part.outerProfile();
  const std::vector<Vec2> expected = {zx(-10, 0), zx(-10, 20), zx(-4, 20), zx(-4, 15), zx(0, 15), zx(0, 0)};
  ASSERT_EQ(outer.size(), expected.size());
  for (std::size_t k = 0; k < outer.size(); ++k) {
    EXPECT_NEAR(outer[k].x(), expected[k].x(), 1e-12) << k;
    EXPECT_NEAR(outer[k].y(), expected[k].y(), 1e-12) << k;
  }
  const std::vector<Vec2> inner = part.innerProfile();
  ASSERT_EQ(inner.size(), 4u);
  EXPECT_NEAR(inner[1].x(), -6.0, 1e-12);
  EXPECT_NEAR(inner[2].y(), 6.0, 1e-12);
  EXPECT_NEAR(inner[3].x(), 0.0, 1e-12);
}

TEST(FinishedPart, CsvHasOneRowPerColumnPlusTheFaces) {
  const Stock s = steppedBush();
  const std::string csv = FinishedPart(s).toCsv();
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "z,x_outer,x_inner");
  std::vector<std::string> rows;
  while (std::getline(in, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 22u);
  EXPECT_EQ(rows.front(), "-10.0000,40.0000,0.0000");
  EXPECT_EQ(rows[1], "-9.7500,40.0000,0.0000");
  EXPECT_EQ(rows[20], "-0.2500,30.0000,12.0000");
  EXPECT_EQ(rows.back(), "0.0000,30.0000,12.0000");
}

TEST(FinishedPart, SvgDrawsBothHalvesAndTheBore) {
  const Stock s = steppedBush();
  const std::string svg = FinishedPart(s).toSvg();
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find("-4.0000,-20.0000"), std::string::npos);  // upper half (SVG y is down)
  EXPECT_NE(svg.find("-4.0000,20.0000"), std::string::npos);   // mirrored lower half
  std::size_t polygons = 0;
  for (std::size_t at = svg.find("<polygon"); at != std::string::npos; at = svg.find("<polygon", at + 1)) ++polygons;
  EXPECT_EQ(polygons, 4u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST(FinishedPart, DxfHasALinePerProfileEdgeOnBothHalves) {
  const Stock s = steppedBush();
  const std::string dxf = FinishedPart(s).toDxf();
  std::size_t lines = 0;
  for (std::size_t at = dxf.find("0\nLINE\n"); at != std::string::npos; at = dxf.find("0\nLINE\n", at + 1)) ++lines;
  EXPECT_EQ(lines, 2u * (6 - 1) + 2u * (4 - 1));  // outer: 6 points, bore: 4 points, mirrored
  EXPECT_NE(dxf.find("8\nPART\n10\n-10.0000\n20\n0.0000\n30\n0.0\n11\n-10.0000\n21\n20.0000\n"), std::string::npos);
  EXPECT_NE(dxf.find("8\nBORE\n"), std::string::npos);
  EXPECT_TRUE(dxf.ends_with("ENDSEC\n0\nEOF\n"));
}

TEST(FinishedPart, DrilledAndBoredWithTheShippedTools) {
  const std::string text =
      "Bore test\nBush\nSteel\n140\n150\nKlueng tests\n"
      "N10 G21 G97 S600 M03\nN15 G99\nN20 T0606 (drill, tip 7 on the axis)\nN30 G00 X0. Z5.\nN40 G01 Z-30. F0.1\n"
      "N50 G00 Z5.\nN60 G00 X100. Z100.\nN70 T0505 (boring bar, R0.4 tip 2)\nN80 G00 X16. Z2.\nN90 G01 Z-20. F0.1\n"
      "N100 G01 X12.\nN110 G00 Z2.\nN120 G00 X100. Z100.\nN130 M30\n";
  const testing::Run run = testing::runProgramText(text);
  ASSERT_FALSE(run.timeline.alarm.has_value());
  CutSimulator sim(run.timeline, CutSetup::from(run.file.header, run.setup));
  sim.runToEnd();
  ASSERT_FALSE(sim.alarm().has_value()) << sim.alarm()->code << " line " << sim.alarm()->range.line;
  const FinishedPart part(sim.stock());
  for (double z = -19.0; z <= -0.5; z += 0.5) EXPECT_NEAR(*part.innerDiameterAt(z), 16.0, 1e-9) << z;
  // Full Ø10 to Z-27: the drill point (tip 7, on the axis at Z-30) is a cone 3 mm long.
  for (double z = -26.5; z <= -21.0; z += 0.5) EXPECT_NEAR(*part.innerDiameterAt(z), 10.0, 1e-9) << z;
  EXPECT_LT(*part.innerDiameterAt(-29.0), 10.0);
  EXPECT_GT(*part.innerDiameterAt(-29.0), 0.0);
  EXPECT_NEAR(*part.innerDiameterAt(-40.0), 0.0, 1e-12);
  for (double z = -49.0; z <= -0.5; z += 0.5) EXPECT_NEAR(*part.outerDiameterAt(z), 40.0, 1e-12) << z;
}

}  // namespace
}  // namespace klueng::core::cut

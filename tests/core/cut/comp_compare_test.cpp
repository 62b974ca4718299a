// What nose compensation changes (issue 10, item 3), on sample 01: its C3
// chamfer (N350) and R2 corner (N380) finished under G42 with R0.8, tip 3.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cut_test_util.h"
#include "klueng/core/cut/comp_compare.h"
#include "klueng/core/gcode/parser.h"

namespace klueng::core::cut {
namespace {

using testing::readText;
using testing::runProgramText;
using testing::samplesDir;

const CompDifference* at(const CompComparison& c, const std::string& label) {
  for (const CompDifference& d : c.differences)
    if (d.label == label) return &d;
  return nullptr;
}

TEST(CompCompare, Sample01WithoutCompensationLeavesTheChamferAndTheCornerShort) {
  const testing::Run run = runProgramText(readText(samplesDir() + "/01-step-shaft.txt"));
  const gcode::Program program = gcode::parse(run.file.gcode, run.file.gcodeFirstLine);
  const CompComparison c = compareCompensation(program, run.setup, machine::RunOptions{},
                                               CutSetup::from(run.file.header, run.setup), CompareWith::NoCompensation);
  EXPECT_TRUE(c.usesCompensation);
  EXPECT_FALSE(c.alarm.has_value());
  ASSERT_TRUE(c.compensated && c.other);
  // By hand: without compensation the imaginary tip (tip 3) runs on the path
  // and the nose centre R·(1, 1) above-right of it. Square to a 45° chamfer the
  // nose then stands √2·R - R = 0.8·(√2 - 1) = 0.331 mm off the line; on the
  // convex R2 corner (centre Z-22 X36) the nose centres run on a circle of R2
  // about the centre moved by (0.8, 0.8), so the surface is a circle of
  // 2 - 0.8 about that point: its gap from the R2 is 0.8·(cos φ + sin φ) - 0.8,
  // largest at φ = 45°: the same 0.331 mm.
  const double expected = 0.8 * (std::sqrt(2.0) - 1.0);
  const CompDifference* chamfer = at(c, "C3");
  ASSERT_NE(chamfer, nullptr) << [&] {
    std::string all;
    for (const CompDifference& d : c.differences)
      all += describeDifference(d, program, CompareWith::NoCompensation, Lang::En) + " z " + std::to_string(d.z) + "\n";
    return all;
  }();
  EXPECT_EQ(chamfer->feature, FeatureKind::Chamfer);
  EXPECT_NEAR(chamfer->normal, expected, 0.005);
  EXPECT_GE(chamfer->radial, expected - 0.005);  // on the radius: up to √2 times as much (0.469)
  EXPECT_LE(chamfer->radial, expected * std::sqrt(2.0) + 0.01);
  EXPECT_EQ(chamfer->line, 43);  // N350
  const CompDifference* corner = at(c, "R2");
  ASSERT_NE(corner, nullptr);
  EXPECT_EQ(corner->feature, FeatureKind::Arc);
  EXPECT_NEAR(corner->normal, expected, 0.01);
  EXPECT_NEAR(corner->z, -22.0 + 2.0 * std::cos(M_PI / 4.0), 0.1);  // at 45° round the corner
  EXPECT_EQ(corner->line, 46);                                      // N380
  // The C1 chamfer (N410) is 45° too; the nose's own R0.8 where the C3 meets
  // the face differs as well. Cylinders and faces of a tip-3 tool need no
  // compensation: nothing else differs.
  const CompDifference* c1 = at(c, "C1");
  ASSERT_NE(c1, nullptr);
  EXPECT_NEAR(c1->normal, expected, 0.005);
  EXPECT_EQ(c1->line, 49);
  for (const CompDifference& d : c.differences)
    EXPECT_TRUE(d.label == "C3" || d.label == "R2" || d.label == "C1" || d.label == "R0.8") << d.label;

  EXPECT_EQ(describeDifference(*chamfer, program, CompareWith::NoCompensation, Lang::En),
            "chamfer C3 N350: 0.33 mm short without compensation");
  EXPECT_EQ(describeDifference(*corner, program, CompareWith::NoCompensation, Lang::Th),
            "ส่วนโค้ง R2 N380: เนื้อเหลือเกิน 0.33 มม. เมื่อไม่ชดเชยรัศมีจมูกมีด");
}

TEST(CompCompare, ASharpNoseCutsTheProgrammedContour) {
  const testing::Run run = runProgramText(readText(samplesDir() + "/01-step-shaft.txt"));
  const gcode::Program program = gcode::parse(run.file.gcode, run.file.gcodeFirstLine);
  const CompComparison c = compareCompensation(program, run.setup, machine::RunOptions{},
                                               CutSetup::from(run.file.header, run.setup), CompareWith::SharpNose);
  // With compensation the R0.8 part is the programmed contour except in the
  // inside corners, where the nose leaves its radius (material a sharp nose takes).
  ASSERT_FALSE(c.differences.empty());
  for (const CompDifference& d : c.differences) {
    EXPECT_LT(d.normal, 0.0) << d.label;  // the sharp nose cuts deeper, never less
    EXPECT_LT(std::abs(d.normal), 0.8 * (std::sqrt(2.0) - 1.0) + 0.01) << d.label;
  }
}

TEST(CompCompare, AProgramWithoutCompensationHasNothingToCompare) {
  const testing::Run run = runProgramText(readText(samplesDir() + "/02-thread.txt"));
  const gcode::Program program = gcode::parse(run.file.gcode, run.file.gcodeFirstLine);
  const CompComparison c = compareCompensation(program, run.setup, machine::RunOptions{},
                                               CutSetup::from(run.file.header, run.setup), CompareWith::NoCompensation);
  EXPECT_FALSE(c.usesCompensation);
  EXPECT_TRUE(c.differences.empty());
}

}  // namespace
}  // namespace klueng::core::cut

// Tube stock (a bore in the header) and the spindle bore behind the chuck
// (issue 8 item 6), through the whole pipeline with the shipped tables.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "cut_test_util.h"
#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/finished_part.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace klueng::core::cut::tube_stock_test {
namespace {

using testing::Run;
using testing::runProgramText;

struct Cut {
  Run run;
  std::unique_ptr<CutSimulator> sim;
};

Cut cut(const std::string& text, double spindleBore = -1.0) {
  Cut c;
  c.run = runProgramText(text);
  EXPECT_FALSE(hasErrors(c.run.checkDiagnostics));
  CutSetup setup = CutSetup::from(c.run.file.header, c.run.setup);
  if (spindleBore >= 0.0) setup.machine.spindleBore = spindleBore;
  c.sim = std::make_unique<CutSimulator>(c.run.timeline, setup);
  c.sim->runToEnd();
  return c;
}

// Ø118 tube with a Ø90 bore, 80 mm long: turn the outside to Ø112 over 30 mm,
// bore the inside to Ø94 over 20 mm with the boring bar (T05, R0.4 tip 2).
const std::string kTube =
    "Bush\nB-1\nSteel\n1118x90\n180\nKlueng tests\n"
    "N10 G21 G97 S500 M03\n"
    "N20 T0101\n"
    "N30 G00 X112. Z2.\n"
    "N40 G01 Z-30. F0.2\n"
    "N50 G01 X120.\n"
    "N60 G00 Z2.\n"
    "N70 T0505\n"
    "N80 G00 X94. Z2.\n"
    "N90 G01 Z-20. F0.1\n"
    "N100 G01 X92.\n"
    "N110 G00 Z2.\n"
    "N120 G00 X200. Z100.\n"
    "N130 M30\n";

TEST(TubeStock, CutLeavesExactDiametersAndTheBoreUntouched) {
  const Cut c = cut(kTube);
  ASSERT_FALSE(c.sim->stoppingAlarm().has_value()) << c.sim->stoppingAlarm()->code;
  EXPECT_DOUBLE_EQ(c.sim->stock().bore(), 90.0);
  const FinishedPart part(c.sim->stock());
  for (double z = -29.0; z <= -0.5; z += 0.25) EXPECT_NEAR(*part.outerDiameterAt(z), 112.0, 0.01) << z;
  for (double z = -79.0; z <= -31.0; z += 0.25) EXPECT_DOUBLE_EQ(*part.outerDiameterAt(z), 118.0) << z;
  for (double z = -19.0; z <= -0.5; z += 0.25) EXPECT_NEAR(*part.innerDiameterAt(z), 94.0, 0.01) << z;
  for (double z = -79.0; z <= -21.0; z += 0.25) EXPECT_DOUBLE_EQ(*part.innerDiameterAt(z), 90.0) << z;
  EXPECT_DOUBLE_EQ(part.maxDiameter(), 118.0);
  EXPECT_NEAR(part.length(), 80.0, 1e-9);
  // The tube's material: the ring only.
  EXPECT_NEAR(c.sim->stock().initialVolume(), 3.14159265358979 * (118.0 * 118.0 - 90.0 * 90.0) / 4.0 * 80.0, 1e-6);
  const std::string csv = part.toCsv();
  EXPECT_NE(csv.find(",118.0000,90.0000"), std::string::npos);
}

TEST(TubeStock, SolidBarHeaderIsStillSolid) {
  const Cut c = cut("P\nQ\nS\n150\n1100\nMe\nN10 G21\nN20 M30\n");
  EXPECT_DOUBLE_EQ(c.sim->stock().bore(), 0.0);
  EXPECT_DOUBLE_EQ(c.sim->stock().innerRadius(0), 0.0);
}

// Ø50 x 60 bar: the chuck body is Z-100..-60; the 10 mm drill (T06) goes 10 mm
// past the part's left end into the 40 mm spindle bore.
const std::string kDrillThrough =
    "P\nQ\nSteel\n150\n160\nMe\n"
    "N10 G21 G97 S800 M03\n"
    "N20 T0606\n"
    "N30 G00 X0. Z2.\n"
    "N40 G01 Z-70. F0.1\n"
    "N50 G00 Z50.\n"
    "N60 M30\n";

TEST(SpindleBore, DrillThroughThePartIntoTheSpindleBoreIsNoCrash) {
  const Cut c = cut(kDrillThrough);
  EXPECT_FALSE(c.sim->alarm().has_value()) << c.sim->alarm()->code << " at Z" << c.sim->alarm()->args.at(0);
  const FinishedPart part(c.sim->stock());
  for (double z = -59.0; z <= -1.0; z += 0.5) EXPECT_NEAR(*part.innerDiameterAt(z), 10.0, 0.01) << z;
}

TEST(SpindleBore, WithoutASpindleBoreTheDrillHitsTheChuckBody) {
  const Cut c = cut(kDrillThrough, 0.0);
  ASSERT_TRUE(c.sim->alarm().has_value());
  EXPECT_EQ(c.sim->alarm()->code, "A304");
  EXPECT_EQ(c.sim->alarm()->range.line, 10);                        // N40
  EXPECT_NEAR(std::stod(c.sim->alarm()->args.at(0)), -60.0, 0.05);  // the part's left end
}

TEST(SpindleBore, ToolIntoAJawIsStillACrash) {
  // Tube Ø118: the jaws hold Z-80..-65 from r59 outward.
  const Cut c =
      cut("Bush\nB-1\nSteel\n1118x90\n180\nMe\n"
          "N10 G21 G97 S500 M03\nN20 T0101\nN30 G00 X116. Z2.\nN40 G01 Z-70. F0.2\nN50 M30\n");
  ASSERT_TRUE(c.sim->alarm().has_value());
  EXPECT_EQ(c.sim->alarm()->code, "A304");
  EXPECT_EQ(c.sim->alarm()->range.line, 10);
}

}  // namespace
}  // namespace klueng::core::cut::tube_stock_test

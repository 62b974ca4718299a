// Part check (issue 10, item 2): the described part (the ideal tool: nose
// circle and front edges) against the real cut, on a pawn's neck.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "cut_test_util.h"
#include "klueng/core/cut/part_check.h"
#include "klueng/core/messages.h"

namespace klueng::core::cut {
namespace {

using testing::readText;
using testing::runProgramText;
using testing::samplesDir;

constexpr double kPi = 3.14159265358979323846;

// A Ø24 bar: along Ø24 to Z-10, down a 15° slope to the Ø22 neck (N70, line
// 14), along it, up 45° and back to Ø24 — finished in one pass under G42.
const std::string kPawnNeck =
    "Pawn neck\nPawn P-1\nBrass\n124\n160\nKlueng tests\n"
    "O0100\n"
    "N10 G21 G40 G99\n"
    "N20 T0101\n"
    "N30 G97 S1200 M03\n"
    "N40 G00 X28. Z2.\n"
    "N50 G42 G01 X24. Z0. F0.1\n"
    "N60 G01 Z-10.\n"
    "N70 X22. Z-13.732\n"
    "N80 Z-20.\n"
    "N90 X24. Z-22.\n"
    "N100 Z-40.\n"
    "N110 X28.\n"
    "N120 G40 G00 X60. Z20.\n"
    "N130 M30\n";

// An exact insert for T01 (offset 01: R0.8, tip 3): the nose and a 3 mm band
// of edge whose underside leaves the nose tangentially at `trailingDeg` above +Z.
ToolShape insert(double trailingDeg) {
  ToolShape s;
  s.noseRadius = 0.8;
  s.tip = 3;
  s.noseCentre = Vec2(0.8, 0.8);
  const double b = trailingDeg * kPi / 180.0;
  const Vec2 t = s.noseCentre + 0.8 * Vec2(std::sin(b), -std::cos(b));
  const double run = 12.0;
  const double rise = run * std::tan(b);
  s.cutting = {Trapezoid{t.x(), t.x() + run, t.y(), t.y() + rise, t.y() + 3.0, t.y() + rise + 3.0}};
  s.bounds = Box{0.0, t.x() + run, 0.0, t.y() + rise + 3.0};
  return s;
}

PartCheck checkWith(const std::string& program, double trailingDeg) {
  const testing::Run run = runProgramText(program);
  EXPECT_FALSE(hasErrors(run.checkDiagnostics));
  const CutSetup setup = CutSetup::from(run.file.header, run.setup);
  ToolLibrary tools(setup.tools, setup.offsets);
  tools.set(1, 1, insert(trailingDeg));
  return checkPart(run.timeline, run.programmed, setup, tools);
}

TEST(PartCheck, An80DegreeInsertGougesThePawnsNeckByItsTrailingEdge) {
  const PartCheck check = checkWith(kPawnNeck, 7.0);  // CNMG 80° in a 93° holder: trailing edge 7°
  ASSERT_EQ(check.defects.size(), 1u);
  const PartDefect& g = check.defects[0];
  EXPECT_EQ(g.kind, DefectKind::Gouge);
  EXPECT_EQ(g.side, FeatureSide::Outside);
  EXPECT_EQ(g.line, 14);  // N70, the way down into the neck
  // By hand: at the end of N70 the nose centre sits tangent to the slope and the
  // Ø22 neck: x = 11 + 0.8, z = -10 + (11.8 - 12 - 0.8/cos15°)/tan15°. The
  // trailing edge's underside is the line tangent to the nose at 7°; the
  // described part keeps the sharp corner (Z-10, r 12) where the slope starts.
  const double a = 15.0 * kPi / 180.0, b = 7.0 * kPi / 180.0;
  const double cz = -10.0 + (11.8 - 12.0 - 0.8 / std::cos(a)) / std::tan(a);
  const auto edge = [&](double z) { return 11.8 + (z - cz) * std::tan(b) - 0.8 / std::cos(b); };
  const double atCorner = 12.0 - edge(-10.0);  // 0.535 mm
  EXPECT_NEAR(atCorner, 0.5348, 0.0005);
  // The deepest column is beside the corner (centres at Z-9.975 and -10.025).
  EXPECT_NEAR(g.depth, 12.0 - edge(-9.975), 0.003);
  EXPECT_NEAR(g.z, -10.0, 0.05);
  EXPECT_NEAR(g.diameter, 24.0, 0.02);
  // It runs right until the edge climbs out of Ø24.
  const double out = cz + (12.0 - 0.005 - 11.8 + 0.8 / std::cos(b)) / std::tan(b);
  EXPECT_NEAR(g.zRight, out, 0.06);
  EXPECT_LT(g.zLeft, -12.0);
  EXPECT_GT(g.zLeft, cz - 0.1);
  EXPECT_FALSE(check.stoppedBy.has_value());

  const std::vector<Diagnostic> ds = partCheckDiagnostics(check);
  ASSERT_EQ(ds.size(), 1u);
  EXPECT_EQ(ds[0].code, "W320");
  EXPECT_EQ(ds[0].severity, Severity::Warning);
  EXPECT_EQ(ds[0].range.line, 14);
  EXPECT_NE(formatMessage(ds[0], Lang::En).find("Gouge 0.53"), std::string::npos) << formatMessage(ds[0], Lang::En);
  EXPECT_NE(formatMessage(ds[0], Lang::Th).find("ลึก 0.53"), std::string::npos);
  EXPECT_NE(formatMessage(ds[0], Lang::En).find(fmt::format("Gouge {:.3f} mm deep", g.depth)), std::string::npos);
  // Issue 28 item 4: the same finding in inches, its unit named in each language.
  const std::vector<Diagnostic> in = partCheckDiagnostics(check, UnitFormat(DisplayUnits::Inch));
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].range.line, 14);
  const std::string en = formatMessage(in[0], Lang::En);
  EXPECT_NE(en.find(fmt::format("Gouge {:.4f} in deep", g.depth / 25.4)), std::string::npos) << en;
  EXPECT_NE(en.find(fmt::format("(deepest at Z{:.4f}, Ø{:.4f})", g.z / 25.4, g.diameter / 25.4)), std::string::npos)
      << en;
  EXPECT_NE(formatMessage(in[0], Lang::Th).find(fmt::format("ลึก {:.4f} นิ้ว", g.depth / 25.4)), std::string::npos);
}

TEST(PartCheck, A35DegreeInsertFollowsTheSameNeck) {
  // VNMG 35° in a 93° holder: trailing edge 52°, steeper than the 15° slope.
  EXPECT_TRUE(checkWith(kPawnNeck, 52.0).defects.empty());
}

// The samples with one thing changed, run as runProgramText runs them.
testing::Run runWith(const std::string& text, int row, io::Offset offset) {
  testing::Run run = testing::runProgramText(text);
  run.setup.offsets.at(row) = offset;
  const gcode::Program program = gcode::parse(run.file.gcode, run.file.gcodeFirstLine);
  run.timeline = machine::interpret(program, run.setup);
  machine::RunOptions plain;
  plain.noseCompensation = false;
  run.programmed = machine::interpret(program, run.setup, plain);
  return run;
}

TEST(PartCheck, AWrongTipNumberOnTheThreadingToolIsAGougeOnTheFirstPass) {
  // Row 03 says tip 7 (the left middle of the tool) for the 60° threading tool,
  // whose point is its bottom middle (tip 8): the point runs half the tool's
  // height below every programmed pass. The programmed passes end at X28.16.
  const std::string sample = readText(samplesDir() + "/02-thread.txt");
  const testing::Run run = runWith(sample, 3, io::Offset{0.0, 0.0, 0.0, 7});
  const CutSetup setup = CutSetup::from(run.file.header, run.setup);
  const PartCheck check = checkPart(run.timeline, run.programmed, setup);
  ASSERT_FALSE(check.defects.empty());
  const PartDefect& g = check.defects.front();
  EXPECT_EQ(g.kind, DefectKind::Gouge);
  EXPECT_EQ(g.side, FeatureSide::Outside);
  EXPECT_EQ(g.line, 21);  // N130, the first G32 pass
  // How far the point lies below the controlled point: half the cutting edge's height.
  ToolLibrary tools(setup.tools, setup.offsets);
  const ToolShape* shape = tools.get(3, 3);
  ASSERT_NE(shape, nullptr);
  double lowest = 0.0, highest = 0.0;
  for (const Trapezoid& t : shape->cutting) {
    lowest = std::min({lowest, t.bottom0, t.bottom1});
    highest = std::max({highest, t.top0, t.top1});
  }
  const double below = -lowest;
  EXPECT_NEAR(below, highest, 0.26);  // the middle, to the half pixel
  EXPECT_GT(below, 5.0);
  // Each pass's point at its X minus that; the last (X28.16) is the deepest.
  EXPECT_NEAR(g.depth, below, 0.01);
  EXPECT_NEAR(g.diameter, 28.16, 0.001);
  EXPECT_NEAR(g.zRight, 0.0, 1e-9);
  const std::vector<Diagnostic> ds = partCheckDiagnostics(check);
  EXPECT_EQ(ds.front().code, "W320");
  // With the row's own tip 8 the same thread is clean.
  const testing::Run right = runWith(sample, 3, io::Offset{0.0, 0.0, 0.0, 8});
  EXPECT_TRUE(
      checkPart(right.timeline, right.programmed, CutSetup::from(right.file.header, right.setup)).defects.empty());
}

TEST(PartCheck, WithoutNoseCompensationTheChamfersAndTheRoundAreLeftFat) {
  // Sample 01 finished without its G42: the imaginary tip follows the drawn
  // contour and the R0.8 nose leaves, square to a 45° chamfer, 0.8(√2-1); on the
  // radius that is 0.8(√2-1)√2 = 0.8(2-√2). The cylinders and the shoulders'
  // inside corners (the nose's own fillet) are not defects.
  std::string program = readText(samplesDir() + "/01-step-shaft.txt");
  program.replace(program.find("G42 "), 4, "");
  const testing::Run run = runProgramText(program);
  const PartCheck check = checkPart(run.timeline, run.programmed, CutSetup::from(run.file.header, run.setup));
  ASSERT_EQ(check.defects.size(), 3u);
  const double radial = 0.8 * (2.0 - std::sqrt(2.0));
  const PartDefect& c3 = check.defects[0];  // right to left
  EXPECT_EQ(c3.kind, DefectKind::Leftover);
  EXPECT_EQ(c3.line, 43);  // N350 X30. Z-3.
  EXPECT_NEAR(c3.depth, radial, 0.002);
  EXPECT_NEAR(c3.zRight, 0.0, 1e-9);
  EXPECT_NEAR(c3.zLeft, -3.0, 0.06);
  EXPECT_EQ(check.defects[1].line, 46);  // N380 G03 X40. Z-22. R2.
  EXPECT_EQ(check.defects[1].kind, DefectKind::Leftover);
  const PartDefect& c1 = check.defects[2];
  EXPECT_EQ(c1.line, 49);  // N410 X46. Z-41.
  EXPECT_NEAR(c1.depth, radial, 0.002);
  EXPECT_NEAR(c1.zRight, -40.0, 0.06);
  EXPECT_NEAR(c1.zLeft, -41.0, 0.06);
  for (const Diagnostic& d : partCheckDiagnostics(check)) EXPECT_EQ(d.code, "W321");
}

// An inch pin in an old shop's habits: G20, no G41/G42, a .05 chamfer and a
// 10° taper finished by G70 with the R0.8 (1/32") insert of row 01.
const std::string kInchPin =
    "Guide pin\nGP-2\nCRS\n138\n180\nKlueng tests\n"
    "O2010 (GUIDE PIN - NO TNC)\n"
    "G20\n"
    "G00 G18 G40 G99\n"
    "T0101\n"
    "G50 S3000\n"
    "G96 S500 M03\n"
    "G00 X1.6 Z.1 M08\n"
    "G71 U.05 R.02\n"
    "G71 P10 Q20 U.02 W.005 F.01\n"
    "N10 G00 X.9\n"
    "G01 Z0. F.005\n"
    "X1. Z-.05\n"
    "Z-.75\n"
    "X1.2 Z-1.317\n"
    "Z-1.6\n"
    "N20 X1.6\n"
    "G70 P10 Q20\n"
    "G00 X3. Z2. M09\n"
    "M30\n";

TEST(PartCheck, AnInchChamferWithoutCompensationComesOutSmallerThanDrawn) {
  const testing::Run run = runProgramText(kInchPin);
  EXPECT_FALSE(hasErrors(run.checkDiagnostics));
  const PartCheck check = checkPart(run.timeline, run.programmed, CutSetup::from(run.file.header, run.setup));
  ASSERT_GE(check.defects.size(), 2u);
  // The .05" chamfer (Z0 to Z-1.27): 0.8(2-√2) mm left on the radius.
  const PartDefect& chamfer = check.defects[0];
  EXPECT_EQ(chamfer.kind, DefectKind::Leftover);
  EXPECT_EQ(chamfer.line, 23);  // the G70 block: its moves are the profile's
  EXPECT_NEAR(chamfer.depth, 0.8 * (2.0 - std::sqrt(2.0)), 0.002);
  EXPECT_NEAR(chamfer.zLeft, -1.27, 0.06);
  // The 10° taper (Z-19.05 to Z-33.45) is left fat too.
  bool taper = false;
  for (const PartDefect& d : check.defects)
    taper = taper || (d.kind == DefectKind::Leftover && d.zLeft < -30.0 && d.zRight > -21.0);
  EXPECT_TRUE(taper);
}

TEST(PartCheck, TheSamplesAsTheyAreHaveNoDefects) {
  for (const char* name : {"/01-step-shaft.txt", "/02-thread.txt"}) {
    const testing::Run run = runProgramText(readText(samplesDir() + name));
    const PartCheck check = checkPart(run.timeline, run.programmed, CutSetup::from(run.file.header, run.setup));
    EXPECT_TRUE(check.defects.empty()) << name << ": " << check.defects.size() << " first at line "
                                       << (check.defects.empty() ? 0 : check.defects[0].line);
    EXPECT_FALSE(check.nothingCut);
  }
}

TEST(PartCheck, ARunStoppedByAnAlarmChecksWhatWasCutAndSaysSo) {
  // N75 rapids into the bar (A301): the check stops where the run stopped.
  std::string program = kPawnNeck;
  program.replace(program.find("N80 Z-20.\n"), 10, "N75 G00 X10.\nN80 Z-20.\n");
  const PartCheck check = checkWith(program, 7.0);
  ASSERT_TRUE(check.stoppedBy.has_value());
  EXPECT_EQ(check.stoppedBy->code, "A301");
  ASSERT_EQ(check.defects.size(), 1u);  // N70's gouge was already made
  EXPECT_EQ(check.defects[0].line, 14);
  const std::vector<Diagnostic> ds = partCheckDiagnostics(check);
  ASSERT_EQ(ds.size(), 2u);
  EXPECT_EQ(ds[1].code, "I324");
  EXPECT_EQ(ds[1].range.line, 15);
  EXPECT_NE(formatMessage(ds[1], Lang::En).find("A301"), std::string::npos);
}

TEST(PartCheck, NothingCutSaysSo) {
  const std::string rapidsOnly =
      "Rapids\nR-1\nSteel\n150\n1100\nKlueng tests\nO0001\nN10 G21 G99\nN20 T0101\nN30 G00 X60. Z5.\nN40 X80. "
      "Z50.\nN50 M30\n";
  const testing::Run run = runProgramText(rapidsOnly);
  const PartCheck check = checkPart(run.timeline, run.programmed, CutSetup::from(run.file.header, run.setup));
  EXPECT_TRUE(check.nothingCut);
  EXPECT_TRUE(check.defects.empty());
  const std::vector<Diagnostic> ds = partCheckDiagnostics(check);
  ASSERT_EQ(ds.size(), 1u);
  EXPECT_EQ(ds[0].code, "I325");
  // No moves at all, and an empty timeline: no crash.
  EXPECT_TRUE(checkPart(machine::Timeline{}, machine::Timeline{}, CutSetup{}).nothingCut);
}

}  // namespace
}  // namespace klueng::core::cut

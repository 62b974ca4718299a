// The real samples and crash programs through the whole pipeline:
// program file -> parse -> check -> interpret -> cut, with the shipped tools.cfg,
// offset.cfg and machine.cfg.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "cut_test_util.h"
#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/finished_part.h"
#include "../../../bench/program_generator.h"

namespace klueng::core::cut {
namespace {

using testing::readText;
using testing::Run;
using testing::runProgramText;
using testing::samplesDir;

std::string sample(const char* name) { return readText(samplesDir() + "/" + name); }

// Line of the block starting with `n` ("N40 ") in the program text (1-based, header included).
int lineOf(const std::string& text, const std::string& n) {
  int line = 1;
  std::size_t pos = 0;
  while (pos < text.size()) {
    if (text.compare(pos, n.size(), n) == 0) return line;
    pos = text.find('\n', pos);
    if (pos == std::string::npos) break;
    ++pos;
    ++line;
  }
  return -1;
}

using Cut = testing::CutRun;

Cut cutProgram(const std::string& text) {
  Cut c = testing::cutToEnd(text);
  EXPECT_FALSE(hasErrors(c.run.checkDiagnostics));
  EXPECT_TRUE(c.sim->toolDiagnostics().empty());
  return c;
}

void expectDiameter(const FinishedPart& part, double z0, double z1, double diameter, double tol = 0.01) {
  for (double z = z0; z <= z1 + 1e-9; z += 0.05) {
    const auto d = part.outerDiameterAt(z);
    ASSERT_TRUE(d.has_value()) << z;
    EXPECT_NEAR(*d, diameter, tol) << "Z" << z;
  }
}

TEST(Sample01, FinishedPartHasTheDrawnDimensions) {
  const Cut c = cutProgram(sample("01-step-shaft.txt"));
  ASSERT_FALSE(c.run.timeline.alarm.has_value());
  ASSERT_FALSE(c.sim->alarm().has_value()) << c.sim->alarm()->code << " line " << c.sim->alarm()->range.line;
  const FinishedPart part(c.sim->stock());
  expectDiameter(part, -19.0, -4.0, 30.0);
  expectDiameter(part, -39.0, -23.0, 40.0);
  expectDiameter(part, -59.0, -42.0, 46.0);
  expectDiameter(part, -84.0, -61.0, 50.0);  // the raw bar left of the Ø46 shoulder
  EXPECT_NEAR(part.rightFaceZ(), 0.0, 0.01);
  EXPECT_NEAR(part.leftFaceZ(), -100.0, 1e-9);
  // 3 x 45 degree chamfer: Ø = 24 + 2|z| from Z0 to Z-3 (away from the face's corner,
  // where the compensated approach along Ø24 keeps the nose R off the corner).
  for (double z = -2.9; z <= -0.3; z += 0.1) EXPECT_NEAR(*part.outerDiameterAt(z), 24.0 - 2.0 * z, 0.01) << z;
  // 1 x 45 degree chamfer from Ø44 at Z-40 to Ø46 at Z-41.
  for (double z = -40.95; z <= -40.05; z += 0.1) EXPECT_NEAR(*part.outerDiameterAt(z), 44.0 + 2.0 * (-40.0 - z), 0.01);
  // R2 corner (G03 X40 Z-22 R2 from X36 Z-20): centre Z-22 X36, radius 2.
  for (double z = -21.95; z <= -20.3; z += 0.05) {
    const double r = *part.outerDiameterAt(z) / 2.0;
    EXPECT_NEAR(std::hypot(z + 22.0, r - 18.0), 2.0, 0.005) << z;
  }
  // Step lengths: the Ø30 runs from the chamfer (Z-3) to the nose fillet in the
  // inner corner at Z-20 (a round nose R0.8 cannot cut a sharp inside corner).
  const auto [a, b] = part.stepExtent(-10.0);
  EXPECT_NEAR(b, -3.0, 0.05);
  EXPECT_NEAR(a, -19.2, 0.06);
  EXPECT_NEAR(part.stepLength(-50.0), 60.0 - 41.0 - 0.8, 0.06);  // Ø46: chamfer end to the fillet at Z-60
  // The Ø50 -> Ø46 shoulder is at Z-60.
  EXPECT_NEAR(*part.outerDiameterAt(-60.1), 50.0, 1e-9);
  EXPECT_GT(c.sim->removedVolume(), 0.0);
  EXPECT_NEAR(c.sim->removedVolume() + part.volume(), c.sim->stock().initialVolume(), 1e-6 * part.volume());
}

TEST(Sample01, WithoutNoseCompensationTheChamferIsOffByTheNoseGeometry) {
  std::string text = sample("01-step-shaft.txt");
  const std::size_t at = text.find("G42 ");
  ASSERT_NE(at, std::string::npos);
  text.erase(at, 4);
  const Cut c = cutProgram(text);
  ASSERT_FALSE(c.sim->alarm().has_value());
  const FinishedPart part(c.sim->stock());
  // Tip 3, R0.8: the imaginary tip follows the 45 degree chamfer, so the nose
  // centre is R*(1,1) from it; the surface it leaves lies R*sqrt2 - R off the line
  // along the normal, i.e. R*(2 - sqrt2) more radius at every Z.
  const double r = 0.8;
  const double extraDiameter = 2.0 * r * (2.0 - std::sqrt(2.0));
  for (double z = -2.5; z <= -0.5; z += 0.1)
    EXPECT_NEAR(*part.outerDiameterAt(z), 24.0 - 2.0 * z + extraDiameter, 0.01) << z;
  // Cylinders are cut by the nose's bottom: unaffected.
  expectDiameter(part, -19.0, -4.0, 30.0);
}

TEST(Sample02, FourThreadPassesCutTeethOfThePitch) {
  const std::string text = sample("02-thread.txt");
  const testing::Run r = runProgramText(text);
  ASSERT_FALSE(r.timeline.alarm.has_value());
  std::vector<const machine::Move*> passes;
  for (const auto& m : r.timeline.moves)
    if (m.kind == machine::MoveKind::Thread) passes.push_back(&m);
  ASSERT_EQ(passes.size(), 4u);
  CutSimulator sim(r.timeline, CutSetup::from(r.file.header, r.setup));
  // Each pass deepens the same grooves: the section shows the tool once per lead.
  const double roots[] = {29.4, 28.9, 28.5, 28.16};
  for (int k = 0; k < 4; ++k) {
    sim.advanceTo(passes[static_cast<std::size_t>(k)]->tEnd);
    ASSERT_FALSE(sim.alarm().has_value()) << sim.alarm()->code << " line " << sim.alarm()->range.line;
    const FinishedPart part(sim.stock());
    EXPECT_NEAR(*part.outerDiameterAt(-5.5), roots[k], 1e-9) << "pass " << k + 1;
    EXPECT_NEAR(*part.outerDiameterAt(-6.25), 30.0, 1e-9) << "pass " << k + 1;
  }
  sim.runToEnd();
  ASSERT_FALSE(sim.alarm().has_value());
  const FinishedPart part(sim.stock());
  // Roots every 1.5 mm from the start Z5: Z5 - 1.5k; crests half a pitch away.
  int roots01 = 0;
  for (int k = 4; 5.0 - 1.5 * k >= -28.0; ++k) {
    const double z = 5.0 - 1.5 * k;
    EXPECT_NEAR(*part.outerDiameterAt(z), 28.16, 0.01) << z;
    EXPECT_NEAR(*part.outerDiameterAt(z - 0.75), 30.0, 0.01) << z - 0.75;
    // Flanks, not square notches: half way up the tooth the diameter is in between.
    EXPECT_GT(*part.outerDiameterAt(z - 0.5), 28.5) << z - 0.5;
    EXPECT_LT(*part.outerDiameterAt(z - 0.5), 29.9) << z - 0.5;
    ++roots01;
  }
  EXPECT_EQ(roots01, 19);
  // Count grooves along Z0..Z-29 from the profile itself: each is a run below Ø30.
  int grooves = 0;
  bool in = true;  // a groove cut off by the ends of the range does not count
  double firstStart = 0, lastStart = 0;
  for (const ProfileRow& row : part.rows()) {
    if (row.z < -29.0 || row.z > 0.0) continue;
    const bool below = row.outerDiameter < 29.99;
    if (below && !in) {
      if (grooves == 0) firstStart = row.z;
      lastStart = row.z;
      ++grooves;
    }
    in = below;
  }
  ASSERT_GE(grooves, 2);
  EXPECT_NEAR((lastStart - firstStart) / (grooves - 1), 1.5, 0.01);
  // Outside the thread the Ø30 turning is untouched.
  expectDiameter(part, -39.0, -31.5, 30.0);
}

TEST(Sample05, StopsOnN40) {
  const std::string text = sample("05-runtime-alarms.txt");
  const Cut c = cutProgram(text);
  const std::optional<Diagnostic> stop = c.sim->stoppingAlarm();
  ASSERT_TRUE(stop.has_value());
  EXPECT_EQ(stop->range.line, lineOf(text, "N40 "));
  EXPECT_EQ(c.sim->removedVolume(), 0.0);
}

TEST(Sample05, UnderG98TheStockCatchesTheCutWithTheSpindleStopped) {
  // Per minute feed: the interpreter has no rule against it; cutting the bar is the crash.
  std::string text = sample("05-runtime-alarms.txt");
  text.replace(text.find("N15 G99"), 7, "N15 G98");
  text.replace(text.find("F0.2"), 4, "F100");
  const Cut c = cutProgram(text);
  ASSERT_FALSE(c.run.timeline.alarm.has_value());
  ASSERT_TRUE(c.sim->alarm().has_value());
  EXPECT_EQ(c.sim->alarm()->code, "A302");
  EXPECT_EQ(c.sim->alarm()->range.line, lineOf(text, "N40 "));
  EXPECT_EQ(c.sim->removedVolume(), 0.0);
}

const char* kHeader = "Crash test\nPart\nSteel\n150\n1100\nKlueng tests\n";

TEST(Crash, RapidIntoTheStockOnTheDogLegsSecondLeg) {
  // From X60 Z40 to X40 Z-10: X (4000 mm/min) ends after 0.15 s, when Z has
  // reached Z20 (8000 mm/min): the first leg ends in air, the second runs along
  // X40 into the face at Z0.
  const std::string text =
      std::string(kHeader) + "N10 G21 G97 S800 M03\nN20 T0101\nN30 G00 X60. Z40.\nN40 G00 X40. Z-10.\nN50 M30\n";
  const Cut c = cutProgram(text);
  ASSERT_FALSE(c.run.timeline.alarm.has_value());
  int legs = 0;
  for (const auto& m : c.run.timeline.moves) legs += m.line == lineOf(text, "N40 ") ? 1 : 0;
  ASSERT_EQ(legs, 2);
  ASSERT_TRUE(c.sim->alarm().has_value());
  const Diagnostic& d = *c.sim->alarm();
  EXPECT_EQ(d.code, "A301");
  EXPECT_EQ(d.range.line, lineOf(text, "N40 "));
  EXPECT_NEAR(std::stod(d.args.at(0)), 0.0, 0.06);
  EXPECT_EQ(d.args.at(1), "40.000");
}

// Textbook habit: the last rapid home cancels the offset with T0100. Offset 00
// takes away the offset's shift, not the insert: the tool stays the T01 it was,
// so leaving a shoulder 1 mm above the bar is no crash (it was A301 when the
// tool was drawn about its nose centre for offset 00, 0.8 mm lower and further left).
TEST(Crash, T0100OnTheWayHomeKeepsTheInsert) {
  const std::string text = std::string(kHeader) +
                           "N10 G21 G97 S800 M03\nN20 T0101\nN30 G00 X45. Z2.\nN40 G01 Z-30. F0.2\n"
                           "N50 X52.\nN60 G00 X200. Z150. T0100\nN70 M30\n";
  const Cut c = cutProgram(text);
  ASSERT_FALSE(c.run.timeline.alarm.has_value());
  EXPECT_FALSE(c.sim->alarm().has_value()) << c.sim->alarm()->code << " line " << c.sim->alarm()->range.line;
  const FinishedPart part(c.sim->stock());
  expectDiameter(part, -28.0, -1.0, 45.0);
}

TEST(Crash, RapidThroughTheStockOnTheFirstLeg) {
  const std::string text =
      std::string(kHeader) + "N10 G21 G97 S800 M03\nN20 T0101\nN30 G00 X70. Z-10.\nN40 G00 X40. Z-60.\nN50 M30\n";
  const Cut c = cutProgram(text);
  ASSERT_TRUE(c.sim->alarm().has_value());
  EXPECT_EQ(c.sim->alarm()->code, "A301");
  EXPECT_EQ(c.sim->alarm()->range.line, lineOf(text, "N40 "));
  // X is done after 0.225 s, Z then stands at Z-40: the diagonal first leg
  // (Z-10 X70 -> Z-40 X40) meets the bar's surface (X50) half way, at Z-30.
  EXPECT_NEAR(std::stod(c.sim->alarm()->args.at(0)), -30.0, 0.01);
  EXPECT_NEAR(std::stod(c.sim->alarm()->args.at(1)), 50.0, 0.01);
}

TEST(Crash, HolderIntoTheStock) {
  // A plunge far deeper than the insert is tall: the holder follows it into the bar.
  const std::string text =
      std::string(kHeader) + "N10 G21 G97 S800 M03\nN20 T0101\nN30 G00 X60. Z-30.\nN40 G01 X10. F0.1\nN50 M30\n";
  const Cut c = cutProgram(text);
  ASSERT_TRUE(c.sim->alarm().has_value());
  EXPECT_EQ(c.sim->alarm()->code, "A303");
  EXPECT_EQ(c.sim->alarm()->range.line, lineOf(text, "N40 "));
  EXPECT_EQ(c.sim->alarm()->args.at(0), "-30.000");
  const double x = std::stod(c.sim->alarm()->args.at(1));
  EXPECT_LT(x, 50.0);
  EXPECT_GT(x, 10.0);
  EXPECT_GT(c.sim->removedVolume(), 0.0);  // the insert did cut on the way in
}

TEST(Crash, ToolIntoTheChuck) {
  // machine.cfg: the jaws grip the left 15 mm (Z-100..-85) and stand 20 mm above the bar.
  const std::string text =
      std::string(kHeader) + "N10 G21 G97 S800 M03\nN20 T0101\nN30 G00 X52. Z2.\nN40 G01 Z-95. F0.3\nN50 M30\n";
  const Cut c = cutProgram(text);
  ASSERT_TRUE(c.sim->alarm().has_value());
  EXPECT_EQ(c.sim->alarm()->code, "A304");
  EXPECT_EQ(c.sim->alarm()->range.line, lineOf(text, "N40 "));
  EXPECT_NEAR(std::stod(c.sim->alarm()->args.at(0)), -85.0, 0.06);
  EXPECT_EQ(c.sim->alarm()->args.at(1), "52.000");
}

TEST(Crash, CutWithTheSpindleStopped) {
  const std::string text =
      std::string(kHeader) + "N10 G21 G98\nN20 T0101\nN30 G00 X40. Z2.\nN40 G01 Z-10. F100.\nN50 M30\n";
  const Cut c = cutProgram(text);
  ASSERT_FALSE(c.run.timeline.alarm.has_value());
  ASSERT_TRUE(c.sim->alarm().has_value());
  EXPECT_EQ(c.sim->alarm()->code, "A302");
  EXPECT_EQ(c.sim->alarm()->range.line, lineOf(text, "N40 "));
  EXPECT_NEAR(std::stod(c.sim->alarm()->args.at(0)), 0.0, 0.06);
  EXPECT_EQ(c.sim->alarm()->args.at(1), "40.000");
}

}  // namespace
}  // namespace klueng::core::cut

namespace klueng::core::cut {
namespace {

// Turning to a shoulder and retracting straight up with G00, as most lathe
// programs do: the tool's flank leaves a sliver beside the shoulder (the
// shipped tool 01's left edge leans about 8 degrees), which the rapid shaves.
// That is grazing (SPEC 8), not a crash.
TEST(Crash, RapidRetractBesideAShoulderJustTurnedIsGrazing) {
  const std::string text = std::string(kHeader) +
                           "N10 G21 G97 G99 S1000 M03\nN20 T0101\nN30 G00 X52. Z2.\nN40 X40.\n"
                           "N50 G01 Z-30. F0.2\nN60 G00 X52.\nN70 Z2.\nN80 M30\n";
  const Cut c = cutProgram(text);
  ASSERT_FALSE(c.run.timeline.alarm.has_value());
  EXPECT_FALSE(c.sim->alarm().has_value()) << c.sim->alarm()->code << " on line " << c.sim->alarm()->range.line;
}

// The same retract 1 mm to the left of the shoulder runs into it: a crash.
TEST(Crash, RapidRetractIntoTheShoulderIsStillACrash) {
  const std::string text = std::string(kHeader) +
                           "N10 G21 G97 G99 S1000 M03\nN20 T0101\nN30 G00 X52. Z2.\nN40 X40.\n"
                           "N50 G01 Z-30. F0.2\nN60 G00 X40. Z-31.\nN70 G00 X52.\nN80 M30\n";
  const Cut c = cutProgram(text);
  ASSERT_TRUE(c.sim->alarm().has_value());
  EXPECT_EQ(c.sim->alarm()->code, "A301");
  EXPECT_EQ(c.sim->alarm()->range.line, lineOf(text, "N60 "));
}

// The benchmark's heavy roughing job (issue 29 item 14) on a short budget: every
// level is taken, the spring passes over it change nothing, the shoulder stands.
TEST(RoughingBench, TurnsTheBarDownToTheLastLevelAndLeavesTheShoulder) {
  const Cut c = cutProgram(klueng::bench::RoughingGenerator::generate(3000));
  ASSERT_FALSE(c.run.timeline.alarm.has_value());
  ASSERT_FALSE(c.sim->alarm().has_value()) << c.sim->alarm()->code << " line " << c.sim->alarm()->range.line;
  const FinishedPart part(c.sim->stock());
  expectDiameter(part, -98.0, -0.05, 21.0, 1e-9);
  expectDiameter(part, -119.95, -101.0, 60.0, 1e-9);
  // Ø60 -> Ø21 over 100 mm, but for the nose's fillet in the corner (R0.8: at most 0.15 cm3).
  const double turned = std::numbers::pi / 4 * (60.0 * 60.0 - 21.0 * 21.0) * 100.0;
  EXPECT_LT(c.sim->removedVolume(), turned);
  EXPECT_GT(c.sim->removedVolume(), turned - 150.0);
  EXPECT_NEAR(c.sim->removedVolume(), c.sim->stock().initialVolume() - c.sim->stock().volume(), 1e-6 * turned);
}

}  // namespace
}  // namespace klueng::core::cut

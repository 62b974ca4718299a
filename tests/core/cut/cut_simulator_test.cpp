#include "klueng/core/cut/cut_simulator.h"

#include <unistd.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>

#include "cut_test_util.h"
#include "klueng/core/cut/finished_part.h"

namespace klueng::core::cut {
namespace {

using machine::MoveKind;
using machine::SpindleDir;
using testing::barSetup;
using testing::blankImage;
using testing::libraryWith;
using testing::move;
using testing::paint;
using testing::squareTool;
using testing::timelineOf;

double radiusAt(const Stock& s, double z) { return s.outerRadius(s.columnAt(z)); }

TEST(CutSimulator, StraightPassLeavesTheExactDiameter) {
  const machine::Timeline tl = timelineOf({
      move(MoveKind::Line, Segment::line(zx(2, 23), zx(-50, 23)), 0, 10, 10),
      move(MoveKind::Line, Segment::line(zx(-50, 23), zx(-50, 26)), 0, 1, 11),
      move(MoveKind::Rapid, Segment::line(zx(-50, 26), zx(2, 26)), 0, 1, 12),
  });
  CutSimulator sim(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)));
  sim.runToEnd();
  EXPECT_FALSE(sim.alarm().has_value());
  const Stock& s = sim.stock();
  for (double z = -49.0; z < -0.01; z += 0.37) EXPECT_DOUBLE_EQ(radiusAt(s, z), 23.0) << z;
  // The nose's left edge stops at Z-50: everything left of it is the raw bar.
  EXPECT_DOUBLE_EQ(radiusAt(s, -50.01), 25.0);
  EXPECT_DOUBLE_EQ(radiusAt(s, -70.0), 25.0);
  // Removed volume: the 50 mm ring plus the nose's rounded end (less than one R x R square of ring).
  const double ring = std::numbers::pi * (25.0 * 25.0 - 23.0 * 23.0) * 50.0;
  EXPECT_GT(sim.removedVolume(), ring - std::numbers::pi * (625.0 - 529.0) * 0.8);
  EXPECT_LT(sim.removedVolume(), ring + 1e-6);
  const FinishedPart part(s);
  // Flat from the face to where the nose's rounding starts (Z-50 + R).
  EXPECT_NEAR(part.stepLength(-20.0), 49.2, 0.051);
  EXPECT_DOUBLE_EQ(*part.outerDiameterAt(-20.0), 46.0);
  EXPECT_DOUBLE_EQ(part.rightFaceZ(), 0.0);
}

TEST(CutSimulator, CompensatedChamferIsExact) {
  // 45 degree chamfer from (Z0, r12) to (Z-3, r15) on a Ø30 bar; nose centre
  // offset R along the outward normal (1,1)/sqrt2, controlled point = centre - (R, R).
  const double r = 0.8;
  const Vec2 n = Vec2(1, 1).normalized() * r;
  const Vec2 toTip(r, r);
  const Vec2 a = zx(1, 11) + n - toTip, b = zx(-4, 16) + n - toTip;
  const machine::Timeline tl = timelineOf({move(MoveKind::Line, Segment::line(a, b), 0, 5, 20)});
  CutSimulator sim(tl, barSetup(30, 20), libraryWith(squareTool(r, 3)));
  sim.runToEnd();
  ASSERT_FALSE(sim.alarm().has_value());
  const Stock& s = sim.stock();
  for (int i = s.columnAt(-2.9); i <= s.columnAt(-0.1); ++i)
    EXPECT_NEAR(s.outerRadius(i), 12.0 - s.zCentre(i), 1e-9) << s.zCentre(i);
  EXPECT_DOUBLE_EQ(radiusAt(s, -3.5), 15.0);
}

TEST(CutSimulator, UncompensatedChamferLeavesTheNoseError) {
  // The imaginary tip on the programmed line: the round nose leaves R(2 - sqrt2) of radius.
  const double r = 0.8;
  const machine::Timeline tl = timelineOf({move(MoveKind::Line, Segment::line(zx(1, 11), zx(-4, 16)), 0, 5, 20)});
  CutSimulator sim(tl, barSetup(30, 20), libraryWith(squareTool(r, 3)));
  sim.runToEnd();
  const double excess = r * (2.0 - std::sqrt(2.0));
  const Stock& s = sim.stock();
  for (int i = s.columnAt(-2.0); i <= s.columnAt(-1.0); ++i)
    EXPECT_NEAR(s.outerRadius(i), 12.0 - s.zCentre(i) + excess, 1e-9);
}

// A round insert: the controlled point is the nose centre (tip 0); the single
// cutting pixel lies inside the nose square, so only the exact circle cuts.
ToolShape discTool(double r) {
  io::RgbImage img = blankImage(1, 1);
  paint(img, 0, 0, 0, 0, 0xE0A000);
  return *makeToolShape(img, "disc.bmp", r, 0).value;
}

TEST(CutSimulator, NoseSweptAlongAnArcLeavesTheExactCorner) {
  // Sample 01's R2 corner: surface r = 18 + sqrt(4 - (z + 22)^2) for z in [-22, -20].
  const double r = 0.8;
  const Vec2 o = zx(-22, 18);
  const machine::Timeline tl = timelineOf({
      move(MoveKind::Line, Segment::line(zx(-19.2, 22), zx(-19.2, 18)), 0, 1, 30),
      move(MoveKind::Arc, Segment::arc(zx(-19.2, 18), zx(-22, 20.8), o, true), 0, 1, 31),
      move(MoveKind::Line, Segment::line(zx(-22, 20.8), zx(-24, 20.8)), 0, 1, 32),
  });
  CutSimulator sim(tl, barSetup(42, 40), libraryWith(discTool(r)));
  sim.runToEnd();
  ASSERT_FALSE(sim.alarm().has_value());
  const Stock& s = sim.stock();
  // Within 0.001 mm normal to the surface (radially too where it is not steep).
  for (int i = s.columnAt(-21.99); i <= s.columnAt(-20.01); ++i) {
    const double dz = s.zCentre(i) + 22.0;
    EXPECT_NEAR((zx(s.zCentre(i), s.outerRadius(i)) - o).norm(), 2.0, 0.001) << s.zCentre(i);
    if (dz < 1.5) {
      EXPECT_NEAR(s.outerRadius(i), 18.0 + std::sqrt(4.0 - dz * dz), 0.001) << s.zCentre(i);
    }
  }
  EXPECT_NEAR(radiusAt(s, -23.0), 20.0, 1e-9);
}

TEST(CutSimulator, RapidIntoTheStockStopsOnTheDogLegsSecondLeg) {
  // Both legs come from the block on line 30; the first is in air.
  const machine::Timeline tl = timelineOf({
      move(MoveKind::Line, Segment::line(zx(5, 30), zx(5, 28)), 0, 1, 20),
      move(MoveKind::Rapid, Segment::line(zx(5, 28), zx(5, 20)), 0, 1, 30),
      move(MoveKind::Rapid, Segment::line(zx(5, 20), zx(-10, 20)), 0, 1, 30),
      move(MoveKind::Line, Segment::line(zx(-10, 20), zx(-20, 20)), 0, 1, 40),
  });
  CutSimulator sim(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)));
  sim.runToEnd();
  ASSERT_TRUE(sim.alarm().has_value());
  const Diagnostic& d = *sim.alarm();
  EXPECT_EQ(d.code, "A301");
  EXPECT_EQ(d.severity, Severity::Alarm);
  EXPECT_EQ(d.range.line, 30);
  // Where: the nose's left edge reaches the first stock column's centre (Z-0.025) on X40.
  EXPECT_NEAR(std::stod(d.args.at(0)), -0.025, 0.002);
  EXPECT_EQ(d.args.at(1), "40.000");
  EXPECT_EQ(sim.removedVolume(), 0.0);
  EXPECT_NEAR(sim.toolPosition().x(), -0.025, 0.002);
  EXPECT_NEAR(sim.endTime(), 2.0 + 5.025 / 15.0, 0.001);
  EXPECT_TRUE(sim.finished());
}

TEST(CutSimulator, RapidOnTheFirstLegIsCaughtThere) {
  const machine::Timeline tl = timelineOf({
      move(MoveKind::Rapid, Segment::line(zx(-10, 30), zx(-10, 20)), 0, 1, 50),
      move(MoveKind::Rapid, Segment::line(zx(-10, 20), zx(-30, 20)), 0, 1, 50),
  });
  CutSimulator sim(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)));
  sim.runToEnd();
  ASSERT_TRUE(sim.alarm().has_value());
  EXPECT_EQ(sim.alarm()->code, "A301");
  EXPECT_EQ(sim.alarm()->range.line, 50);
  EXPECT_EQ(sim.alarm()->args.at(0), "-10.000");
  EXPECT_NEAR(std::stod(sim.alarm()->args.at(1)), 50.0, 0.003);
}

TEST(CutSimulator, GrazingRapidsAreNotCollisions) {
  const machine::Timeline tl = timelineOf({
      // Face at Z0 with feed, then leave the face with a rapid.
      move(MoveKind::Line, Segment::line(zx(0, 27), zx(0, -0.8)), 0, 1, 10),
      move(MoveKind::Rapid, Segment::line(zx(0, -0.8), zx(2, -0.8)), 0, 1, 11),
      move(MoveKind::Rapid, Segment::line(zx(2, -0.8), zx(2, 23)), 0, 1, 12),
      // Turn to r23, then rapid back along the surface just cut.
      move(MoveKind::Line, Segment::line(zx(2, 23), zx(-30, 23)), 0, 1, 13),
      move(MoveKind::Rapid, Segment::line(zx(-30, 23), zx(2, 23)), 0, 1, 14),
      // Rapid along the raw bar's surface.
      move(MoveKind::Rapid, Segment::line(zx(2, 25), zx(-60, 25)), 0, 1, 15),
  });
  CutSimulator sim(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)));
  sim.runToEnd();
  EXPECT_FALSE(sim.alarm().has_value()) << sim.alarm()->code << " line " << sim.alarm()->range.line;
  EXPECT_DOUBLE_EQ(radiusAt(sim.stock(), -10.0), 23.0);
  EXPECT_DOUBLE_EQ(FinishedPart(sim.stock()).rightFaceZ(), 0.0);
}

TEST(CutSimulator, CuttingWithTheSpindleStoppedIsAnAlarm) {
  const machine::Timeline tl = timelineOf({
      move(MoveKind::Rapid, Segment::line(zx(2, 30), zx(2, 22.5)), 0, 1, 30, SpindleDir::Stopped),
      move(MoveKind::Line, Segment::line(zx(2, 22.5), zx(-10, 19)), 0, 1, 40, SpindleDir::Stopped),
  });
  CutSimulator sim(tl, barSetup(45, 80), libraryWith(squareTool(0.8, 3)));
  sim.runToEnd();
  ASSERT_TRUE(sim.alarm().has_value());
  EXPECT_EQ(sim.alarm()->code, "A302");
  EXPECT_EQ(sim.alarm()->range.line, 40);
  EXPECT_EQ(sim.removedVolume(), 0.0);
}

// Insert 5 x 5 mm; the holder above it is 3 mm wider to the right.
ToolShape wideHolderTool() {
  io::RgbImage img = blankImage(16, 30);
  paint(img, 0, 20, 9, 29, 0xE0A000);
  paint(img, 0, 0, 15, 19, 0x000000);
  return *makeToolShape(img, "wide-holder.bmp", 0.4, 3).value;
}

TEST(CutSimulator, HolderIntoTheStockIsAnAlarm) {
  const ToolShape tool = wideHolderTool();
  const machine::Timeline tl = timelineOf({
      move(MoveKind::Rapid, Segment::line(zx(-10, 40), zx(-10, 26)), 0, 1, 60),
      move(MoveKind::Line, Segment::line(zx(-10, 26), zx(-10, 15)), 0, 1, 70),
  });
  CutSimulator sim(tl, barSetup(50, 100), libraryWith(tool));
  sim.runToEnd();
  ASSERT_TRUE(sim.alarm().has_value());
  EXPECT_EQ(sim.alarm()->code, "A303");
  EXPECT_EQ(sim.alarm()->range.line, 70);
  // The holder's bottom (5 mm above the tip) reaches the bar's r25 at tip r20.
  EXPECT_EQ(sim.alarm()->args.at(0), "-10.000");
  EXPECT_NEAR(std::stod(sim.alarm()->args.at(1)), 40.0, 0.003);
}

TEST(CutSimulator, ToolIntoTheChuckIsAnAlarm) {
  CutSetup setup = barSetup(50, 100);
  setup.machine.chuckGrip = 15.0;
  const machine::Timeline tl = timelineOf({
      move(MoveKind::Rapid, Segment::line(zx(5, 30), zx(-50, 30)), 0, 1, 80),
      move(MoveKind::Rapid, Segment::line(zx(-50, 30), zx(-95, 30)), 0, 1, 90),
  });
  CutSimulator sim(tl, setup, libraryWith(squareTool(0.8, 3)));
  sim.runToEnd();
  ASSERT_TRUE(sim.alarm().has_value());
  EXPECT_EQ(sim.alarm()->code, "A304");
  EXPECT_EQ(sim.alarm()->range.line, 90);
  EXPECT_NEAR(std::stod(sim.alarm()->args.at(0)), -85.0, 0.03);
  EXPECT_EQ(sim.alarm()->args.at(1), "60.000");
}

// Issue 26: a tool Klueng guessed from a plain program (ToolTable::guessed) whose
// holder touches the bar: a warning naming the station, once, and the run goes on.
TEST(CutSimulator, GuessedToolsHolderIsAWarningOnceAndTheRunGoesOn) {
  const ToolShape tool = wideHolderTool();
  const machine::Timeline tl = timelineOf({
      move(MoveKind::Rapid, Segment::line(zx(-10, 40), zx(-10, 26)), 0, 1, 60),
      move(MoveKind::Line, Segment::line(zx(-10, 26), zx(-10, 15)), 0, 1, 70),
      move(MoveKind::Rapid, Segment::line(zx(-10, 15), zx(-10, 40)), 0, 1, 80),
      move(MoveKind::Rapid, Segment::line(zx(-10, 40), zx(-20, 40)), 0, 1, 90),
      move(MoveKind::Line, Segment::line(zx(-20, 40), zx(-20, 15)), 0, 1, 100),
  });
  CutSetup setup = barSetup(50, 100);
  setup.tools.guessed[0] = true;
  CutSimulator sim(tl, setup, libraryWith(tool));
  sim.runToEnd();
  EXPECT_FALSE(sim.alarm().has_value());
  ASSERT_EQ(sim.warnings().size(), 1u);
  EXPECT_EQ(sim.warnings()[0].code, "W324");
  EXPECT_EQ(sim.warnings()[0].severity, Severity::Warning);
  EXPECT_EQ(sim.warnings()[0].range.line, 70);
  EXPECT_EQ(sim.warnings()[0].args.at(0), "01");
  EXPECT_EQ(sim.warnings()[0].args.at(2), "-10.000");
  EXPECT_NEAR(std::stod(sim.warnings()[0].args.at(3)), 40.0, 0.003);
  // Both plunges cut to Ø30: the run did not stop at the first.
  EXPECT_NEAR(sim.stock().outerRadius(sim.stock().columnAt(-17.5)), 15.0, 0.03);
}

// A guessed tool's cutting edge in a rapid is still the program's fault (A301).
TEST(CutSimulator, GuessedToolsEdgeInARapidIsStillAnAlarm) {
  const machine::Timeline tl = timelineOf({
      move(MoveKind::Rapid, Segment::line(zx(-10, 40), zx(-10, 20)), 0, 1, 60),
  });
  CutSetup setup = barSetup(50, 100);
  setup.tools.guessed[0] = true;
  CutSimulator sim(tl, setup, libraryWith(squareTool(0.8, 3)));
  sim.runToEnd();
  ASSERT_TRUE(sim.alarm().has_value());
  EXPECT_EQ(sim.alarm()->code, "A301");
  EXPECT_TRUE(sim.warnings().empty());
}

// A guessed tool's edge brushing the bar by 0.1 mm in a rapid (its flank beside a
// shoulder; the shop's insert is shaped otherwise): W326 and the run goes on; by
// 0.3 mm it is the program's rapid into the stock (A301).
TEST(CutSimulator, GuessedToolsEdgeBrushingInARapidIsAWarningUpTo0_2mm) {
  for (const double depth : {0.1, 0.3}) {
    const machine::Timeline tl = timelineOf({
        move(MoveKind::Rapid, Segment::line(zx(5, 25.0 - depth), zx(-30, 25.0 - depth)), 0, 1, 60),
    });
    CutSetup setup = barSetup(50, 100);
    setup.tools.guessed[0] = true;
    CutSimulator sim(tl, setup, libraryWith(squareTool(0.0, 3)));
    sim.runToEnd();
    if (depth < 0.2) {
      EXPECT_FALSE(sim.alarm().has_value()) << depth;
      ASSERT_EQ(sim.warnings().size(), 1u) << depth;
      EXPECT_EQ(sim.warnings()[0].code, "W326");
      EXPECT_EQ(sim.warnings()[0].range.line, 60);
    } else {
      ASSERT_TRUE(sim.alarm().has_value()) << depth;
      EXPECT_EQ(sim.alarm()->code, "A301");
    }
  }
}

// The body of a guessed tool reaching the chuck: W325, and the run goes on.
TEST(CutSimulator, GuessedToolsBodyAtTheChuckIsAWarning) {
  CutSetup setup = barSetup(50, 100);
  setup.machine.chuckGrip = 15.0;
  setup.tools.guessed[0] = true;
  const machine::Timeline tl = timelineOf({
      move(MoveKind::Rapid, Segment::line(zx(5, 30), zx(-50, 30)), 0, 1, 80),
      move(MoveKind::Rapid, Segment::line(zx(-50, 30), zx(-85, 30)), 0, 1, 90),
  });
  // Holder 20 mm to the left of the insert: the insert stops 5 mm short of the jaws.
  io::RgbImage img = blankImage(50, 30);
  paint(img, 40, 20, 49, 29, 0xE0A000);
  paint(img, 0, 0, 49, 19, 0x000000);
  const ToolShape tool = *makeToolShape(img, "long-body.bmp", 0.0, 3).value;
  CutSimulator sim(tl, setup, libraryWith(tool));
  sim.runToEnd();
  EXPECT_FALSE(sim.alarm().has_value()) << sim.alarm()->code;
  ASSERT_EQ(sim.warnings().size(), 1u);
  EXPECT_EQ(sim.warnings()[0].code, "W325");
  EXPECT_EQ(sim.warnings()[0].range.line, 90);
}

TEST(CutSimulator, ThreadingStampsTheToolOncePerLead) {
  // A V insert 4.5 mm wide, 0.5 mm narrower per row downwards, tip 8 (bottom middle).
  io::RgbImage img = blankImage(9, 30);
  for (int k = 0; k < 5; ++k) paint(img, 4 - k, 29 - k, 4 + k, 29 - k, 0xE0A000);
  paint(img, 0, 0, 8, 24, 0x000000);
  const ToolShape v = *makeToolShape(img, "v.bmp", 0.0, 8).value;
  machine::Move pass = move(MoveKind::Thread, Segment::line(zx(5, 14.6), zx(-30, 14.6)), 0, 1, 130);
  pass.lead = 1.5;
  const machine::Timeline tl =
      timelineOf({move(MoveKind::Rapid, Segment::line(zx(5, 16), zx(5, 14.6)), 0, 1, 120), pass,
                  move(MoveKind::Rapid, Segment::line(zx(-30, 14.6), zx(-30, 16)), 0, 1, 140)});
  CutSimulator sim(tl, barSetup(30, 50), libraryWith(v));
  sim.runToEnd();
  ASSERT_FALSE(sim.alarm().has_value()) << sim.alarm()->code << " line " << sim.alarm()->range.line;
  const Stock& s = sim.stock();
  // The sharp tip (R 0, one pixel) cuts a V: the pixel rows' steps become straight
  // 45 degree flanks between column centres. Columns are sampled at their centres,
  // 0.025 mm from the roots here.
  for (int k = 4; 5 - 1.5 * k > -29; ++k) {
    const double root = 5 - 1.5 * k;
    EXPECT_NEAR(radiusAt(s, root), 14.6, 0.0251) << root;
    EXPECT_NEAR(radiusAt(s, root - 0.2), 14.8, 0.0251) << root;
    EXPECT_NEAR(radiusAt(s, root + 0.2), 14.8, 0.0251) << root;
    EXPECT_DOUBLE_EQ(radiusAt(s, root - 0.75), 15.0) << root;  // crest between two passes of the tool
  }
  EXPECT_NEAR(radiusAt(s, -30.0), 14.6, 0.0251);  // where the tool stood before retracting
}

TEST(CutSimulator, ALeadFinerThanTheColumnsCutsAGroove) {
  io::RgbImage img = blankImage(9, 30);
  for (int k = 0; k < 5; ++k) paint(img, 4 - k, 29 - k, 4 + k, 29 - k, 0xE0A000);
  const ToolShape v = *makeToolShape(img, "v.bmp", 0.0, 8).value;
  machine::Move pass = move(MoveKind::Thread, Segment::line(zx(5, 14.6), zx(-30, 14.6)), 0, 1, 130);
  pass.lead = 0.05;  // = one column: no teeth can be resolved
  const machine::Timeline tl = timelineOf({pass});
  CutSimulator sim(tl, barSetup(30, 50), libraryWith(v));
  sim.runToEnd();
  for (double z = -29.0; z < -0.1; z += 0.11) EXPECT_DOUBLE_EQ(radiusAt(sim.stock(), z), 14.6) << z;
}

TEST(CutSimulator, AdvancingInStepsEqualsRunningToTheEnd) {
  const machine::Timeline tl = timelineOf({
      move(MoveKind::Line, Segment::line(zx(2, 23), zx(-48, 23)), 0, 10, 10),
      move(MoveKind::Line, Segment::line(zx(-48, 23), zx(-48, 26)), 0, 1, 11),
  });
  CutSimulator stepped(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)));
  stepped.advanceTo(5.0);  // half way along the pass: tool at Z-23
  EXPECT_NEAR(stepped.toolPosition().x(), -23.0, 1e-9);
  EXPECT_DOUBLE_EQ(radiusAt(stepped.stock(), -22.0), 23.0);
  EXPECT_DOUBLE_EQ(radiusAt(stepped.stock(), -23.5), 25.0);
  for (double t = 5.0; t <= 11.0; t += 0.013) stepped.advanceTo(t);
  stepped.advanceTo(11.0);
  CutSimulator whole(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)));
  whole.runToEnd();
  for (int i = 0; i < whole.stock().columnCount(); ++i)
    ASSERT_DOUBLE_EQ(stepped.stock().outerRadius(i), whole.stock().outerRadius(i)) << i;
  stepped.advanceTo(1.0);  // back in time: re-cut from the start
  EXPECT_DOUBLE_EQ(radiusAt(stepped.stock(), -10.0), 25.0);
  EXPECT_DOUBLE_EQ(radiusAt(stepped.stock(), -1.0), 23.0);
}

TEST(CutSimulator, ARefusedBitmapStopsTheRunWhereTheToolIsFirstUsed) {
  io::RgbImage img = blankImage(10, 10);
  paint(img, 0, 0, 9, 4, 0x000000);  // holder only, no cutting edge
  const std::string path =
      (std::filesystem::temp_directory_path() / ("klueng_cut_holder_only-" + std::to_string(::getpid()) + ".bmp"))
          .string();
  ASSERT_TRUE(io::writeBmp(path, img));
  CutSetup setup = barSetup(50, 100);
  setup.tools.bitmap[0] = path;
  const machine::Timeline tl = timelineOf({
      move(MoveKind::Rapid, Segment::line(zx(300, 0), zx(2, 30)), 0, 1, 12),
      move(MoveKind::Line, Segment::line(zx(2, 23), zx(-50, 23)), 0, 10, 13),
  });
  CutSimulator sim(tl, setup);
  sim.runToEnd();
  ASSERT_TRUE(sim.alarm().has_value());
  EXPECT_EQ(sim.alarm()->code, "A310");
  EXPECT_EQ(sim.alarm()->severity, Severity::Error);
  EXPECT_EQ(sim.alarm()->range.line, 12);
  EXPECT_EQ(sim.alarm()->args.at(0), path);
  ASSERT_EQ(sim.toolDiagnostics().size(), 1u);
  EXPECT_EQ(sim.removedVolume(), 0.0);
  EXPECT_DOUBLE_EQ(sim.endTime(), 0.0);
  std::filesystem::remove(path);
}

TEST(CutSimulator, GarbageMovesNeverCrashOrHang) {
  // Random lines, arcs, threads and rapids with feed (never alarms: collisions
  // are off), plus non-finite coordinates: the run must finish and keep the
  // stock consistent.
  std::uint64_t seed = 12345;
  auto next = [&seed](double lo, double hi) {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * static_cast<double>(seed >> 11) / 9007199254740992.0;
  };
  std::vector<machine::Move> moves;
  Vec2 at = zx(5, 30);
  for (int k = 0; k < 400; ++k) {
    const Vec2 to = zx(next(-120, 20), next(-5, 40));
    const int kind = static_cast<int>(next(0, 4));
    machine::Move m =
        kind == 0   ? move(MoveKind::Line, Segment::line(at, to), 0, 1, k)
        : kind == 1 ? move(MoveKind::Arc, Segment::arc(at, to, (at + to) / 2 + zx(0, next(-3, 3)), k % 2 == 0), 0, 1, k)
        : kind == 2 ? move(MoveKind::Thread, Segment::line(at, to), 0, 1, k)
                    : move(MoveKind::Rapid, Segment::line(at, to), 0, 1, k);
    m.lead = next(0.0, 3.0);
    moves.push_back(m);
    at = to;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  moves.push_back(move(MoveKind::Line, Segment::line(at, zx(nan, 3)), 0, 1, 999));
  moves.push_back(move(MoveKind::Arc, Segment::arc(zx(1e300, 0), zx(-1e300, 1), zx(0, nan), true), 0, 1, 1000));
  CutOptions options;
  options.detectCollisions = false;
  const machine::Timeline tl = timelineOf(moves);
  CutSimulator sim(tl, barSetup(50, 100), libraryWith(squareTool(0.8, 3)), options);
  sim.runToEnd();
  EXPECT_TRUE(sim.finished());
  EXPECT_FALSE(sim.alarm().has_value());
  EXPECT_NEAR(sim.removedVolume() + sim.stock().volume(), sim.stock().initialVolume(),
              1e-6 * sim.stock().initialVolume());
  for (int i = 0; i < sim.stock().columnCount(); ++i)
    for (const Interval& in : sim.stock().column(i)) ASSERT_LT(in.lo, in.hi);
}

TEST(CutSimulator, MovesOfAToolWithoutABitmapCutNothing) {
  const machine::Timeline tl = timelineOf({move(MoveKind::Line, Segment::line(zx(2, 23), zx(-50, 23)), 0, 10, 10)});
  CutSimulator sim(tl, barSetup(50, 100), ToolLibrary{});
  sim.runToEnd();
  EXPECT_EQ(sim.removedVolume(), 0.0);
  EXPECT_TRUE(sim.finished());
}

}  // namespace
}  // namespace klueng::core::cut

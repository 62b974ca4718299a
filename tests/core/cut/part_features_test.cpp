// The finished part's features (issue 10, item 1): profiles carved by hand
// into a stock, then the real samples through the whole pipeline.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "cut_test_util.h"
#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/part_features.h"

namespace klueng::core::cut {
namespace {

using testing::readText;
using testing::runProgramText;
using testing::samplesDir;

// Cuts every column of a Ø50 × 100 bar down to r(z) (radius at the column's centre).
Stock carved(const std::function<double(double)>& r, double bore = 0.0) {
  Stock s(50.0, 100.0, 0.05, bore);
  for (int i = 0; i < s.columnCount(); ++i) s.remove(i, r(s.zCentre(i)), 25.0);
  return s;
}

// Right to left: C2, Ø30, a 3 mm groove to Ø24, Ø30, a face up to an R2
// round, Ø40, an 11.31° taper to Ø44, Ø44, an R3 fillet up to the bar, Ø50.
double handProfile(double z) {
  if (z > -2.0) return 13.0 - z;
  if (z > -15.0) return 15.0;
  if (z > -18.0) return 12.0;
  if (z > -25.0) return 15.0;
  if (z > -27.0) return 18.0 + std::sqrt(4.0 - (z + 27.0) * (z + 27.0));
  if (z > -40.0) return 20.0;
  if (z > -50.0) return 20.0 + (-40.0 - z) * 0.2;
  if (z > -57.0) return 22.0;
  if (z > -60.0) return 25.0 - std::sqrt(std::max(0.0, 9.0 - (z + 57.0) * (z + 57.0)));
  return 25.0;
}

const PartFeature* find(const std::vector<PartFeature>& fs, FeatureKind kind, double zInside) {
  for (const PartFeature& f : fs)
    if (f.kind == kind && f.zLeft - 1e-6 <= zInside && zInside <= f.zRight + 1e-6) return &f;
  return nullptr;
}

TEST(PartFeatures, HandCarvedProfileReadsAsADraughtsmanDrawsIt) {
  const Stock s = carved(handProfile);
  const PartFeatures p = partFeatures(s);
  std::vector<FeatureKind> kinds;
  for (const PartFeature& f : p.outside) kinds.push_back(f.kind);
  using K = FeatureKind;
  const std::vector<FeatureKind> expected{K::Face,     K::Chamfer, K::Cylinder, K::Face,     K::Groove, K::Face,
                                          K::Cylinder, K::Face,    K::Arc,      K::Cylinder, K::Taper,  K::Cylinder,
                                          K::Arc,      K::Face,    K::Cylinder, K::Face};
  ASSERT_EQ(kinds, expected) << [&] {
    std::string all;
    for (const PartFeature& f : p.outside) all += describeFeature(f, Lang::En) + "\n";
    return all;
  }();
  EXPECT_TRUE(p.inside.empty());
  EXPECT_DOUBLE_EQ(p.zRight, 0.0);
  EXPECT_DOUBLE_EQ(p.zLeft, -100.0);

  const PartFeature& chamfer = p.outside[1];
  EXPECT_TRUE(chamfer.isFortyFiveChamfer());
  EXPECT_NEAR(chamfer.radialHeight, 2.0, 0.005);
  EXPECT_NEAR(chamfer.axialLength, 2.0, 0.005);
  EXPECT_EQ(featureLabel(chamfer, Lang::En), "C2");

  const PartFeature& d30 = p.outside[2];
  EXPECT_NEAR(d30.diameter, 30.0, 0.002);
  EXPECT_NEAR(d30.zRight, -2.0, 0.005);  // where the chamfer's line meets the cylinder: exact
  EXPECT_NEAR(d30.zLeft, -15.0, 1e-9);   // a face: a column edge
  EXPECT_EQ(featureLabel(d30, Lang::En), "Ø30");

  const PartFeature& groove = p.outside[4];
  EXPECT_NEAR(groove.diameter, 24.0, 0.002);
  EXPECT_NEAR(groove.width, 3.0, 1e-9);
  EXPECT_NEAR(groove.depth, 3.0, 0.002);
  EXPECT_EQ(featureLabel(groove, Lang::En), "groove 3 × Ø24");
  EXPECT_EQ(featureLabel(groove, Lang::Th), "ร่อง 3 × Ø24");

  const PartFeature& shoulder = p.outside[7];
  EXPECT_DOUBLE_EQ(shoulder.zLeft, -25.0);
  EXPECT_NEAR(shoulder.diameterLeft, 36.0, 0.01);  // the round's end, Ø36 = 2 × 18
  EXPECT_NEAR(shoulder.diameterRight, 30.0, 0.002);

  const PartFeature& round = p.outside[8];
  EXPECT_TRUE(round.convex);
  EXPECT_NEAR(round.radius, 2.0, 0.005);
  EXPECT_NEAR(round.centre.x(), -27.0, 0.005);
  EXPECT_NEAR(round.centre.y(), 18.0, 0.005);
  EXPECT_NEAR(round.zLeft, -27.0, 0.01);  // its tangent point on Ø40
  EXPECT_EQ(featureLabel(round, Lang::En), "R2");

  const PartFeature& taper = p.outside[10];
  EXPECT_NEAR(taper.angle, std::atan(0.2) * 180.0 / M_PI, 0.02);
  EXPECT_NEAR(taper.zRight, -40.0, 0.005);
  EXPECT_NEAR(taper.zLeft, -50.0, 0.005);
  EXPECT_NEAR(taper.diameterLeft, 44.0, 0.005);
  EXPECT_NEAR(taper.diameterRight, 40.0, 0.005);

  const PartFeature& fillet = p.outside[12];
  EXPECT_FALSE(fillet.convex);
  EXPECT_NEAR(fillet.radius, 3.0, 0.005);
  EXPECT_NEAR(fillet.centre.x(), -57.0, 0.005);
  EXPECT_NEAR(fillet.centre.y(), 25.0, 0.005);

  const std::vector<double> shoulders = p.shoulderZ();
  ASSERT_GE(shoulders.size(), 5u);
  EXPECT_DOUBLE_EQ(shoulders[0], 0.0);
  EXPECT_DOUBLE_EQ(shoulders[1], -15.0);
  EXPECT_DOUBLE_EQ(shoulders[2], -18.0);
  EXPECT_DOUBLE_EQ(shoulders[3], -25.0);
  EXPECT_DOUBLE_EQ(shoulders.back(), -100.0);
}

TEST(PartFeatures, BoreWithAChamferedMouthAndAStep) {
  // Ø50 tube, Ø20 bore: bored to Ø30 for 20 mm with a C1 at the mouth.
  Stock s(50.0, 100.0, 0.05, 20.0);
  for (int i = 0; i < s.columnCount(); ++i) {
    const double z = s.zCentre(i);
    const double r = z > -1.0 ? 16.0 + z : z > -20.0 ? 15.0 : 10.0;
    if (r > 10.0) s.remove(i, 10.0, r);
  }
  const PartFeatures p = partFeatures(s);
  ASSERT_EQ(p.inside.size(), 4u);
  EXPECT_EQ(p.inside[0].kind, FeatureKind::Chamfer);
  EXPECT_EQ(featureLabel(p.inside[0], Lang::En), "C1");
  EXPECT_EQ(p.inside[0].side, FeatureSide::Inside);
  EXPECT_EQ(p.inside[1].kind, FeatureKind::Cylinder);
  EXPECT_NEAR(p.inside[1].diameter, 30.0, 0.002);
  EXPECT_NEAR(p.inside[1].zRight, -1.0, 0.005);
  EXPECT_EQ(p.inside[2].kind, FeatureKind::Face);
  EXPECT_DOUBLE_EQ(p.inside[2].zLeft, -20.0);
  EXPECT_NEAR(p.inside[2].diameterLeft, 20.0, 1e-9);
  EXPECT_NEAR(p.inside[2].diameterRight, 30.0, 0.002);
  EXPECT_EQ(p.inside[3].kind, FeatureKind::Cylinder);
  EXPECT_NEAR(p.inside[3].diameter, 20.0, 1e-9);
  // The end faces run from the outside down to the bore.
  EXPECT_EQ(p.outside.front().kind, FeatureKind::Face);
  EXPECT_NEAR(p.outside.front().diameterRight, 32.0, 0.01);  // the chamfer's mouth, Ø32
  EXPECT_NEAR(p.outside.back().diameterLeft, 20.0, 1e-9);
}

TEST(PartFeatures, EmptyAndUncutStock) {
  Stock gone(50.0, 10.0);
  for (int i = 0; i < gone.columnCount(); ++i) gone.remove(i, 0.0, 25.0);
  EXPECT_TRUE(partFeatures(gone).empty());
  EXPECT_TRUE(partFeatures(Stock()).empty());

  const PartFeatures bar = partFeatures(Stock(50.0, 100.0));
  ASSERT_EQ(bar.outside.size(), 3u);
  EXPECT_EQ(bar.outside[1].kind, FeatureKind::Cylinder);
  EXPECT_DOUBLE_EQ(bar.outside[1].diameter, 50.0);
  EXPECT_DOUBLE_EQ(bar.overallLength(), 100.0);
}

testing::CutRun cutText(const std::string& text) {
  testing::CutRun c = testing::cutToEnd(text);
  EXPECT_FALSE(hasErrors(c.run.checkDiagnostics));
  EXPECT_FALSE(c.sim->stoppingAlarm().has_value());
  return c;
}

// Sample 01's drawing (its README): Ø30 Z0…-20 with a C3, Ø40 -22…-40 after an
// R2 corner, a C1, Ø46 to -60; the nose's R0.8 stays in the inside corners.
TEST(PartFeatures, Sample01HasTheDrawnFeatures) {
  const testing::CutRun c = cutText(readText(samplesDir() + "/01-step-shaft.txt"));
  const PartFeatures p = partFeatures(c.sim->stock());
  const PartFeature* c3 = find(p.outside, FeatureKind::Chamfer, -1.5);
  ASSERT_NE(c3, nullptr);
  EXPECT_EQ(featureLabel(*c3, Lang::En), "C3");
  EXPECT_NEAR(c3->radialHeight, 3.0, 0.01);
  const PartFeature* d30 = find(p.outside, FeatureKind::Cylinder, -10.0);
  ASSERT_NE(d30, nullptr);
  EXPECT_NEAR(d30->diameter, 30.0, 0.01);
  EXPECT_NEAR(d30->zRight, -3.0, 0.01);
  const PartFeature* r2 = find(p.outside, FeatureKind::Arc, -21.0);
  ASSERT_NE(r2, nullptr);
  EXPECT_TRUE(r2->convex);
  EXPECT_NEAR(r2->radius, 2.0, 0.01);
  EXPECT_NEAR(r2->centre.x(), -22.0, 0.01);
  EXPECT_NEAR(2.0 * r2->centre.y(), 36.0, 0.02);
  const PartFeature* d40 = find(p.outside, FeatureKind::Cylinder, -30.0);
  ASSERT_NE(d40, nullptr);
  EXPECT_NEAR(d40->diameter, 40.0, 0.01);
  EXPECT_NEAR(d40->zRight, -22.0, 0.01);
  const PartFeature* c1 = find(p.outside, FeatureKind::Chamfer, -40.5);
  ASSERT_NE(c1, nullptr);
  EXPECT_EQ(featureLabel(*c1, Lang::En), "C1");
  const PartFeature* d46 = find(p.outside, FeatureKind::Cylinder, -50.0);
  ASSERT_NE(d46, nullptr);
  EXPECT_NEAR(d46->diameter, 46.0, 0.01);
  EXPECT_NEAR(d46->zRight, -41.0, 0.01);
  // The R0.8 nose leaves its radius in the inside corner at the Ø30 shoulder.
  const PartFeature* nose = find(p.outside, FeatureKind::Arc, -19.5);
  ASSERT_NE(nose, nullptr);
  EXPECT_FALSE(nose->convex);
  EXPECT_NEAR(nose->radius, 0.8, 0.01);
  const std::vector<double> shoulders = p.shoulderZ();
  const std::vector<double> expected{0.0, -20.0, -40.0, -60.0, -100.0};
  ASSERT_EQ(shoulders.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(shoulders[k], expected[k], 1e-9);
}

// A cylinder running into a 1:5 taper, cut without G41/G42: the R0.8 nose rolls
// over the shallow corner and leaves a few columns of arc whose fitted radius
// was noise (an "R7" callout). The corner is drawn as the two lines meeting,
// where the uncompensated nose put them: the taper's surface runs parallel to
// the programmed one, r(1 + b - sqrt(1 + b²))/b further right along Z (b = 0.2).
TEST(PartFeatures, AShallowCornerIsTheTwoLinesMeetingNotAnArc) {
  const testing::CutRun c = cutText(
      "Taper pin\nPin TP-1\nSteel S45C\n132\n180\nKlueng tests\nO2001 (1:5 TAPER PIN)\nG21 G40 G99\nT0101\nG96 S200 "
      "M03\nG50 S2500\nG00 X34. Z2. M08\n"
      "G01 Z0. F0.15\nX-1.6\nG00 X20. Z2.\nG01 Z-20.\nX28. Z-40.\nZ-50.\nX34.\nG00 X100. Z100.\nM30\n");
  const PartFeatures p = partFeatures(c.sim->stock());
  const double r = 0.8, b = 0.2;
  const double shift = r * (1.0 + b - std::sqrt(1.0 + b * b)) / b;
  const PartFeature* pin = find(p.outside, FeatureKind::Cylinder, -10.0);
  const PartFeature* taper = find(p.outside, FeatureKind::Taper, -30.0);
  ASSERT_NE(pin, nullptr);
  ASSERT_NE(taper, nullptr);
  EXPECT_NEAR(pin->diameter, 20.0, 0.005);
  EXPECT_DOUBLE_EQ(pin->zLeft, taper->zRight);  // nothing between them
  EXPECT_NEAR(taper->zRight, -20.0 + shift, 0.01);
  EXPECT_NEAR(taper->zLeft, -40.0 + shift, 0.01);
  EXPECT_NEAR(taper->diameterRight, 20.0, 0.01);
  EXPECT_NEAR(taper->diameterLeft, 28.0, 0.01);
  EXPECT_NEAR(taper->angle, std::atan(b) * 180.0 / M_PI, 0.01);
  for (const PartFeature& f : p.outside) {
    if (f.kind == FeatureKind::Arc) {
      EXPECT_LT(f.zRight, -45.0) << describeFeature(f, Lang::En);  // only the Ø28 shoulder's
    }
  }
}

// A threading pass that only grazes the Ø30 (0.01 mm deep on the radius, as when
// a second operation's thread lands on the wrong end) leaves one cylinder, not
// Ø29.98 and Ø30 in turn at every pitch.
TEST(PartFeatures, AGrazingPassLeavesOneCylinder) {
  const testing::CutRun c = cutText(
      "Grazed pin\nPin GP-1\nSteel S45C\n132\n180\nKlueng tests\nO2002\nG21 G40 G99\nT0101\nG97 S1000 M03\n"
      "G00 X34. Z2.\nG01 Z0. F0.15\nX-1.6\nG00 X30. Z2.\nG01 Z-30.\nX34.\nG00 X100. Z100.\n"
      "T0303\nG97 S600 M03\nG00 X29.98 Z5.\nG32 Z-20. F1.5\nG00 X34.\nX100. Z100.\nM30\n");
  const PartFeatures p = partFeatures(c.sim->stock());
  int cylinders = 0;
  for (const PartFeature& f : p.outside)
    if (f.kind == FeatureKind::Cylinder && f.zLeft > -30.5) ++cylinders;  // the Ø30, not the bar
  EXPECT_EQ(cylinders, 1);
  const PartFeature* pin = find(p.outside, FeatureKind::Cylinder, -10.0);
  ASSERT_NE(pin, nullptr);
  EXPECT_NEAR(pin->diameter, 30.0, 0.02);
  EXPECT_LT(pin->zLeft, -25.0);
}

// Issue 28: the pitch is read between the 0.05 mm columns, so a G76 thread's
// label says the pitch it was cut with (sample 06 read "M30×1.49" when the teeth
// were placed by whole columns).
TEST(PartFeatures, AThreadsPitchIsReadBetweenColumns) {
  for (const double pitch : {1.0, 1.25, 1.5, 1.75, 2.0, 25.4 / 16.0, 25.4 / 11.5}) {
    const double height = 0.6134 * pitch;  // ISO 68 external thread, on the radius
    const double minor = 30.0 - 2.0 * height;
    const std::string text = fmt::format(
        "O0100\nN10 G21 G40 G97 G99\nN20 T0101\nN30 S1200 M03\nN40 G00 X32. Z2.\nN50 G01 X30. F0.2\n"
        "N60 Z-30.\nN70 X32.\nN80 G00 X100. Z100.\nN90 T0303\nN100 S800 M03\nN110 G00 X32. Z5.\n"
        "N120 G76 P010060 Q50 R0.05\nN130 G76 X{:.3f} Z-20. P{:.0f} Q250 F{:.4f}\nN140 G00 X100. Z100.\nN150 M30\n",
        minor, height * 1000.0, pitch);
    const testing::CutRun c = cutText(text);
    const PartFeatures p = partFeatures(c.sim->stock());
    const PartFeature* t = find(p.outside, FeatureKind::Thread, -10.0);
    ASSERT_NE(t, nullptr) << pitch;
    EXPECT_NEAR(t->pitch, pitch, 0.002) << text;
  }
}

TEST(PartFeatures, Sample02ThreadIsFoundWithItsPitch) {
  const testing::CutRun c = cutText(readText(samplesDir() + "/02-thread.txt"));
  const PartFeatures p = partFeatures(c.sim->stock());
  const PartFeature* t = find(p.outside, FeatureKind::Thread, -15.0);
  ASSERT_NE(t, nullptr);
  EXPECT_NEAR(t->pitch, 1.5, 0.005);
  EXPECT_NEAR(t->diameter, 30.0, 0.005);
  EXPECT_NEAR(t->minorDiameter, 28.16, 0.005);  // the last pass, X28.16
  EXPECT_DOUBLE_EQ(t->zRight, 0.0);
  EXPECT_LT(t->zLeft, -30.0);  // the run-out where the tool stopped at Z-30 belongs to it
  EXPECT_GT(t->zLeft, -31.0);
  EXPECT_EQ(featureLabel(*t, Lang::En), "M30×1.5");
  // Nothing of the teeth is left over as tapers or cylinders.
  for (const PartFeature& f : p.outside) {
    if (f.kind == FeatureKind::Face || f.kind == FeatureKind::Thread) continue;
    EXPECT_LT(f.zRight, t->zLeft + 1e-9) << describeFeature(f, Lang::En);
  }
}

TEST(PartFeatures, GroovingToolCutsAGroove) {
  // T04: 3 mm grooving tool, R0.2, tip 3 (its left corner): a 3 mm groove to Ø24 at Z-15…-18.
  const testing::CutRun c = cutText(
      "Groove\nPart GR-1\nSteel\n132\n160\nKlueng tests\n"
      "N10 G21 G99 G97 S800 M03\n"
      "N20 T0404\n"
      "N30 G00 X34. Z-18.\n"
      "N40 G01 X24. F0.05\n"
      "N50 G00 X34.\n"
      "N60 G00 X100. Z50.\n"
      "N70 M30\n");
  const PartFeatures p = partFeatures(c.sim->stock());
  const PartFeature* g = find(p.outside, FeatureKind::Groove, -16.5);
  ASSERT_NE(g, nullptr) << [&] {
    std::string all;
    for (const PartFeature& f : p.outside) all += describeFeature(f, Lang::En) + "\n";
    return all;
  }();
  EXPECT_NEAR(g->diameter, 24.0, 0.01);
  EXPECT_NEAR(g->width, 3.0, 0.05);
  EXPECT_NEAR(g->depth, 4.0, 0.01);  // from Ø32
}

// Found by fuzz_pipeline: a Ø3 bore mouth on a Ø30 x 40 bar at 0.2 mm columns whose
// short pieces (a few columns each) let one join land left of the join before it;
// the arc between them came out with zLeft > zRight. Joins now go left to right.
TEST(PartFeatures, ShortPiecesInABoreMouthKeepTheirOrder) {
  Stock s(30.0, 40.0, 0.2);
  // Bore radius per column from the right face (z -0.1, -0.3, ...), as the fuzzer's cut left it
  // (the last one a rounding's 1.3e-15 above the axis: the bore's run reaches Z-2).
  const double bore[] = {1.5,
                         1.482500000000001,
                         1.4125000000000001,
                         1.3425000000000014,
                         1.2725000000000004,
                         1.2025000000000019,
                         1.0500000000000056,
                         0.64999999999999991,
                         0.25000000000000844,
                         1.3322676295501878e-15};
  const int n = s.columnCount();
  for (int k = 0; k < 10; ++k) s.remove(n - 1 - k, 0.0, bore[k]);
  const PartFeatures p = partFeatures(s);
  ASSERT_FALSE(p.inside.empty());
  double right = 0.0;
  for (const PartFeature& f : p.inside) {
    EXPECT_LE(f.zLeft, f.zRight + 1e-9) << describeFeature(f, Lang::En);
    EXPECT_LE(f.zRight, right + 1e-9) << describeFeature(f, Lang::En);  // listed from the right face
    right = std::min(right, f.zLeft);
  }
}

TEST(PartFeatures, DescriptionsInBothLanguages) {
  const PartFeatures p = partFeatures(carved(handProfile));
  EXPECT_EQ(describeFeature(p.outside[2], Lang::En), "Cylinder Ø30, Z-2 to Z-15, length 13");
  EXPECT_EQ(describeFeature(p.outside[2], Lang::Th), "ทรงกระบอก Ø30 Z-2 ถึง Z-15 ยาว 13");
  EXPECT_EQ(featureKindName(FeatureKind::Thread, Lang::Th), "เกลียว");
}

// Issue 28 item 4: the same features said in inches (the part stays in mm).
TEST(PartFeatures, InchTextsHaveTheInchMarkAndAControlsDecimals) {
  const PartFeatures p = partFeatures(carved(handProfile));
  const UnitFormat in(DisplayUnits::Inch);
  EXPECT_EQ(describeFeature(p.outside[2], Lang::En, in), "Cylinder Ø1.1811″, Z-0.0787 to Z-0.5906, length 0.5118″");
  EXPECT_EQ(describeFeature(p.outside[2], Lang::Th, in), "ทรงกระบอก Ø1.1811″ Z-0.0787 ถึง Z-0.5906 ยาว 0.5118″");
  EXPECT_EQ(featureLabel(p.outside[2], Lang::En, in), "Ø1.181″");
  const PartFeature* chamfer = find(p.outside, FeatureKind::Chamfer, -1.0);
  ASSERT_NE(chamfer, nullptr);
  EXPECT_EQ(featureLabel(*chamfer, Lang::En, in), "0.079″ × 45°");  // C2 = 0.0787″
  const PartFeature* groove = find(p.outside, FeatureKind::Groove, -16.5);
  ASSERT_NE(groove, nullptr);
  EXPECT_EQ(featureLabel(*groove, Lang::Th, in), "ร่อง 0.118″ × Ø0.945″");
  // The default is the millimetre text, unchanged.
  EXPECT_EQ(featureLabel(p.outside[2], Lang::En, UnitFormat{}), "Ø30");
}

TEST(PartFeatures, AnInchThreadIsNamedByItsThreadsPerInch) {
  PartFeature t;
  t.kind = FeatureKind::Thread;
  t.diameter = 0.75 * kMmPerInch;
  t.pitch = kMmPerInch / 16.0;
  t.minorDiameter = 0.6688 * kMmPerInch;
  EXPECT_EQ(featureLabel(t, Lang::En, UnitFormat(DisplayUnits::Inch)), "0.750″-16 TPI");
  t.pitch = 1.5;  // a metric pitch on an inch drawing: no whole number of threads per inch
  EXPECT_EQ(featureLabel(t, Lang::En, UnitFormat(DisplayUnits::Inch)), "Ø0.750″ × P0.059″");
}

}  // namespace
}  // namespace klueng::core::cut

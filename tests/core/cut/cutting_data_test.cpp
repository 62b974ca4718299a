// Cutting data (issue 39): the numbers of known cuts against hand calculations,
// and each teacher's warning on its block, never on a sound program.
#include "klueng/core/cut/cutting_data.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "cut_test_util.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/messages.h"

namespace klueng::core::cut {
namespace {

using testing::runProgramText;

constexpr double kPi = std::numbers::pi;

// Within 1 % of the hand calculation.
void expectWithin1Percent(double actual, double hand, const char* what) {
  EXPECT_NEAR(actual, hand, std::abs(hand) * 0.01) << what;
}

// Station 1 holds the library's CNMG R0.8 insert (coated carbide, 12.9 mm edge), offset 01 R0.8 tip 3.
struct CdRun {
  testing::Run run;
  CuttingDataOptions options;
  CuttingData data;
};

CdRun cdRun(const std::string& text, const std::function<void(CuttingDataOptions&)>& adjust = {}) {
  CdRun r;
  r.run = runProgramText(text);
  const io::ToolLibrary& library = io::shippedToolLibrary();
  const io::LibraryTool* insert = library.find("cnmg-80-r08");
  EXPECT_NE(insert, nullptr);
  if (insert) r.run.setup.tools.setLibraryTool(1, insert->id, library.bitmapPath(*insert), insert->pixelsPerMm);
  r.run.setup.offsets.at(1) = io::Offset{0, 0, 0.8, 3};
  r.options =
      cuttingDataOptions(r.run.file.header.material, r.run.setup.tools, r.run.setup.machine, shippedMaterials());
  if (adjust) adjust(r.options);
  r.data = measureCuts(r.run.timeline, CutSetup::from(r.run.file.header, r.run.setup), r.options);
  return r;
}

std::vector<std::string> warningCodesOn(const CuttingData& d, int line) {
  std::vector<std::string> out;
  for (const Diagnostic& w : d.warnings)
    if (w.range.line == line) out.push_back(w.code);
  return out;
}

// A Ø50 S45C bar turned to Ø46 over 30 mm at 1000 rpm, 0.2 mm/rev (line 12).
const std::string kSteelTurn =
    "Cutting data\nSteel turn\nS45C\n150\n1100\nTest\n"
    "G21 G40 G99\n"     // 7
    "T0101\n"           // 8
    "G97 S1000 M03\n"   // 9
    "G00 X60. Z2.\n"    // 10
    "X46.\n"            // 11
    "G01 Z-30. F0.2\n"  // 12
    "G00 X60.\n"        // 13
    "Z50.\n"            // 14
    "M30\n";

TEST(CuttingDataTest, SteelWithCarbideMatchesHandCalculation) {
  const CdRun r = cdRun(kSteelTurn);
  ASSERT_NE(r.options.material, nullptr);
  EXPECT_EQ(r.options.material->id, "s45c");
  EXPECT_EQ(r.options.toolMaterial[0], ToolMaterial::CoatedCarbide);
  const std::optional<CutNumbers> c = r.data.ofLine(0, 12);
  ASSERT_TRUE(c.has_value());
  // Hand calculation:
  //   Vc = pi * 46 * 1000 / 1000 = 144.51 m/min; f = 200 mm/min / 1000 rpm = 0.2 mm/rev
  //   ap = (50 - 46) / 2 = 2 mm; h = 0.2 * sin 95 deg = 0.19924 mm
  //   kc = 1500 * 0.19924^-0.22 = 2139.0 N/mm^2; Fc = 2139.0 * 2 * 0.2 = 855.6 N
  //   Pc = 855.6 * 144.51 / 60000 = 2.061 kW; M = 855.6 * 46 / 2000 = 19.68 N*m
  //   Q = 144.51 * 2 * 0.2 = 57.80 cm^3/min; Rz = 0.2^2 / (8 * 0.8) * 1000 = 6.25 um; Ra = 1.5625 um
  expectWithin1Percent(c->vc, 144.51, "Vc");
  expectWithin1Percent(c->feed, 0.2, "f");
  expectWithin1Percent(c->depth, 2.0, "ap");
  expectWithin1Percent(c->chipThickness, 0.19924, "h");
  expectWithin1Percent(c->kc, 2139.0, "kc");
  expectWithin1Percent(c->force, 855.6, "Fc");
  expectWithin1Percent(c->power, 2.061, "Pc");
  expectWithin1Percent(c->torque, 19.68, "torque");
  expectWithin1Percent(c->removalRate, 57.80, "Q");
  ASSERT_TRUE(c->rz && c->ra);
  expectWithin1Percent(*c->rz, 6.25, "Rz");
  expectWithin1Percent(*c->ra, 1.5625, "Ra");
  // 144.5 m/min is inside carbide's 120-220 for S45C, and the machine.cfg names no limits: sound.
  EXPECT_TRUE(r.data.warnings.empty()) << formatMessage(r.data.warnings.front(), Lang::En);
  // Rapids and air moves are not cuts.
  EXPECT_FALSE(r.data.ofLine(0, 11).has_value());
  EXPECT_FALSE(r.data.ofLine(0, 13).has_value());
}

TEST(CuttingDataTest, SteelWithHssIsTooFastOnItsBlock) {
  const CdRun r = cdRun(kSteelTurn, [](CuttingDataOptions& o) { o.toolMaterial[0] = ToolMaterial::Hss; });
  ASSERT_EQ(r.data.warnings.size(), 1u);
  const Diagnostic& w = r.data.warnings[0];
  EXPECT_EQ(w.code, codes::kCutSpeedHigh);
  EXPECT_EQ(w.severity, Severity::Warning);
  EXPECT_EQ(w.range.line, 12);
  // HSS in S45C: 20-35 m/min; the fix aims at the middle, 27.5 m/min at Ø46: 27500 / (pi * 46) = 190 rpm.
  EXPECT_EQ(formatMessage(w, Lang::En),
            "cutting speed 145 m/min is above the 35 m/min a HSS tool stands in Carbon steel S45C (C 0.45 %): the "
            "edge burns; lower the spindle speed to about S190 (rpm, G97) or the G96 S value");
  EXPECT_NE(formatMessage(w, Lang::Th).find("ไฮสปีด"), std::string::npos);
}

// tools.cfg's ` | material=hss` (Tool Select) wins over the library tool's coated carbide.
TEST(CuttingDataTest, TheStationsToolMaterialWinsOverTheLibrarys) {
  testing::Run run = runProgramText(kSteelTurn);
  const io::ToolLibrary& library = io::shippedToolLibrary();
  const io::LibraryTool* insert = library.find("cnmg-80-r08");
  ASSERT_NE(insert, nullptr);
  run.setup.tools.setLibraryTool(1, insert->id, library.bitmapPath(*insert), insert->pixelsPerMm);
  EXPECT_EQ(cuttingDataOptions("S45C", run.setup.tools, run.setup.machine, shippedMaterials()).toolMaterial[0],
            ToolMaterial::CoatedCarbide);
  run.setup.tools.material[0] = "hss";
  EXPECT_EQ(cuttingDataOptions("S45C", run.setup.tools, run.setup.machine, shippedMaterials()).toolMaterial[0],
            ToolMaterial::Hss);
  // A plain bitmap says nothing of its material until its line does.
  EXPECT_EQ(cuttingDataOptions("S45C", io::ToolTable{}, run.setup.machine, shippedMaterials()).toolMaterial[0],
            ToolMaterial::Unknown);
}

TEST(CuttingDataTest, MachineLimitsWarnOnTheCuttingBlock) {
  const CdRun r = cdRun(kSteelTurn, [](CuttingDataOptions& o) {
    o.spindlePowerKw = 1.5;  // the cut needs 2.06 kW
    o.spindleTorqueNm = 10;  // and 19.7 N*m
    o.chuckMaxRpm = 800;     // at 1000 rpm
    o.edgeLength[0] = 2.4;   // 2/3 of it = 1.6 mm < 2 mm
  });
  EXPECT_EQ(warningCodesOn(r.data, 12),
            (std::vector<std::string>{codes::kRpmOverChuck, codes::kDepthOverEdge, codes::kPowerOverSpindle,
                                      codes::kTorqueOverSpindle}));
  for (const Diagnostic& w : r.data.warnings) {
    if (w.code != std::string(codes::kPowerOverSpindle)) continue;
    EXPECT_EQ(formatMessage(w, Lang::En),
              "this cut needs 2.1 kW at the edge (depth 2.00 mm, feed 0.200 mm/rev) but the spindle gives 1.5 kW: "
              "the spindle stalls; take a smaller depth or feed");
  }
  // The chuck's limit is said on the first block that turns too fast (the rapids at line 10), once a block.
  EXPECT_EQ(warningCodesOn(r.data, 10), (std::vector<std::string>{codes::kRpmOverChuck}));
}

// Aluminium 6061 Ø50, G96 S300 clamped by G50 S1500: at Ø40 the clamp holds the spindle at 1500 rpm.
TEST(CuttingDataTest, AluminiumUnderG96ClampIsTooSlowForCarbide) {
  const CdRun r = cdRun(
      "Cutting data\nAluminium\nAl 6061\n150\n1100\nTest\n"
      "G21 G40 G99\n"      // 7
      "T0101\n"            // 8
      "G50 S1500\n"        // 9
      "G96 S300 M03\n"     // 10
      "G00 X60. Z2.\n"     // 11
      "X40.\n"             // 12
      "G01 Z-20. F0.25\n"  // 13: ap 5 mm
      "G00 X60.\n"         // 14
      "M30\n");
  ASSERT_NE(r.options.material, nullptr);
  EXPECT_EQ(r.options.material->id, "al6061");
  const std::optional<CutNumbers> c = r.data.ofLine(0, 13);
  ASSERT_TRUE(c.has_value());
  // pi * 40 * 1500 / 1000 = 188.50 m/min (300 wanted 2387 rpm); f = 0.25; ap = 5
  // kc = 800 * (0.25 sin 95)^-0.25 = 800 * 0.24905^-0.25 = 1132.0; Fc = 1132.0 * 5 * 0.25 = 1415.0 N
  // Pc = 1415.0 * 188.50 / 60000 = 4.445 kW
  expectWithin1Percent(c->rpm, 1500.0, "rpm");
  expectWithin1Percent(c->vc, 188.50, "Vc");
  expectWithin1Percent(c->depth, 5.0, "ap");
  expectWithin1Percent(c->power, 4.445, "Pc");
  EXPECT_EQ(warningCodesOn(r.data, 13), (std::vector<std::string>{codes::kCutSpeedLow}));
}

// Inch: Ø2 in SS400 with an HSS tool, 400 rpm, 0.008 in/rev, 0.05 in deep.
TEST(CuttingDataTest, InchProgramInFeetPerMinute) {
  const CdRun r = cdRun(
      "Cutting data\nInch\nSS400\n02\n04\nTest\n"
      "G20 G40 G99\n"      // 7
      "T0101\n"            // 8
      "G97 S400 M03\n"     // 9
      "G00 X2.5 Z0.1\n"    // 10
      "X1.9\n"             // 11
      "G01 Z-1. F0.008\n"  // 12
      "G00 X2.5\n"         // 13
      "M30\n",
      [](CuttingDataOptions& o) {
        o.toolMaterial[0] = ToolMaterial::Hss;
        o.units = DisplayUnits::Inch;
      });
  const std::optional<CutNumbers> c = r.data.ofLine(0, 12);
  ASSERT_TRUE(c.has_value());
  // SFM = pi * 1.9 in * 400 / 12 = 198.97 ft/min = 60.65 m/min (HSS in SS400: 25-40 m/min: too fast)
  // f = 0.008 in = 0.2032 mm; ap = 0.05 in = 1.27 mm
  expectWithin1Percent(c->vc / 0.3048, 198.97, "SFM");
  expectWithin1Percent(c->feed, 0.2032, "f");
  expectWithin1Percent(c->depth, 1.27, "ap");
  ASSERT_EQ(warningCodesOn(r.data, 12), (std::vector<std::string>{codes::kCutSpeedHigh}));
  EXPECT_EQ(formatMessage(r.data.warnings[0], Lang::En).substr(0, 51),
            "cutting speed 199 ft/min is above the 131 ft/min a ");
  const std::string csv = formatCuttingDataCsv(r.data, DisplayUnits::Inch);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "line,file,tool,t_start_s,t_end_s,moves,diameter_in,rpm,vc_ft_min,f_in_rev,ap_in,chip_width_in,"
            "chip_thickness_in,q_in3_min,nose_radius_in,rz_um,ra_um,kc_n_mm2,fc_n,pc_kw,torque_nm,warnings");
  EXPECT_NE(csv.find("\n12,0,1,"), std::string::npos);
  EXPECT_NE(csv.find(",1.9000,400,199,0.0080,0.0500,0.0502,0.0080,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",W330\n"), std::string::npos);
}

// A finishing pass (0.3 mm deep) at 0.3 mm/rev.
TEST(CuttingDataTest, FinishingFeedTooLargeForTheNose) {
  const CdRun r = cdRun(
      "Cutting data\nFinish\nS45C\n150\n1100\nTest\n"
      "G21 G40 G99\n"     // 7
      "T0101\n"           // 8
      "G97 S800 M03\n"    // 9
      "G00 X60. Z2.\n"    // 10
      "X49.4\n"           // 11
      "G01 Z-20. F0.3\n"  // 12
      "G00 X60.\n"        // 13
      "M30\n",
      [](CuttingDataOptions& o) { o.noseRadius[0] = 0.4; });
  // The library says R0.4 but the offset row says R0.8, and the row is what the control and the
  // cut use: Ra = 0.09 / (32 * 0.8) * 1000 = 3.52 um > 3.2.
  const std::optional<CutNumbers> c = r.data.ofLine(0, 12);
  ASSERT_TRUE(c && c->ra);
  expectWithin1Percent(c->depth, 0.3, "ap");
  expectWithin1Percent(*c->ra, 3.516, "Ra");
  ASSERT_EQ(warningCodesOn(r.data, 12), (std::vector<std::string>{codes::kFinishTooRough}));
  // The largest feed for Ra 3.2 with R0.8: sqrt(3.2 * 32 * 0.8 / 1000) = 0.286 mm/rev.
  EXPECT_EQ(formatMessage(r.data.warnings[0], Lang::En),
            "finishing feed 0.300 mm/rev with nose radius R0.80 leaves Ra 3.5 um (Rz 14.1 um), rougher than Ra 3.2 "
            "um (the default, N8: the drawing gives no mark here): use F0.286 or less, or an insert with a larger "
            "nose radius");
}

TEST(CuttingDataTest, FacingDepthIsTheAxialWidth) {
  const CdRun r = cdRun(
      "Cutting data\nFace\nS45C\n150\n1100\nTest\n"
      "G21 G40 G99\n"    // 7
      "T0101\n"          // 8
      "G97 S800 M03\n"   // 9
      "G00 X55. Z-1.\n"  // 10: 1 mm into the bar's face
      "G01 X0. F0.15\n"  // 11
      "G00 Z5.\n"        // 12
      "M30\n");
  const std::optional<CutNumbers> c = r.data.ofLine(0, 11);
  ASSERT_TRUE(c.has_value());
  // ap = 1 mm (along Z); Vc at the path's largest diameter, where it starts: pi * 55 * 800 / 1000 = 138.23
  expectWithin1Percent(c->depth, 1.0, "ap");
  expectWithin1Percent(c->vc, 138.23, "Vc");
}

TEST(CuttingDataTest, MaterialsTableNamesAsTeachersWriteThem) {
  const MaterialTable& t = shippedMaterials();
  ASSERT_GE(t.rows.size(), 6u);
  for (const char* name :
       {"S45C", "s45c", "SS400", "Al 6061", "AL6061", "brass", "ทองเหลือง", "cast iron", "POM", "aluminium"})
    EXPECT_NE(t.find(name), nullptr) << name;
  EXPECT_EQ(t.find("unobtainium"), nullptr);
  // With more words, as teachers write it: the longest name held wins ("s45c" over "steel").
  ASSERT_NE(t.find("Steel S45C"), nullptr);
  EXPECT_EQ(t.find("Steel S45C")->id, "s45c");
  EXPECT_EQ(t.find("Aluminium 6061")->id, "al6061");
  EXPECT_EQ(t.find("เหล็กเหนียว SS400 ยาว")->id, "ss400");
  EXPECT_EQ(t.find(""), nullptr);
  const Material* pom = t.find("Delrin");
  ASSERT_NE(pom, nullptr);
  EXPECT_EQ(pom->kc11, 0.0);  // no published kc1.1: no power
  for (const Material& m : t.rows) {
    EXPECT_FALSE(m.source.empty()) << m.id;
    EXPECT_LT(m.hssMax, m.carbideMax) << m.id;
  }
}

TEST(CuttingDataTest, MaterialsFileErrors) {
  const auto r = parseMaterials("# note\nx | x | X | เอกซ์ | 10-20 | 50-40 | 1000 | 0.2 | book\ny | y\n", "m.cfg");
  ASSERT_TRUE(r.value.has_value());
  EXPECT_TRUE(r.value->rows.empty());
  ASSERT_EQ(r.diagnostics.size(), 2u);
  EXPECT_EQ(r.diagnostics[0].code, codes::kMaterialBadNumber);
  EXPECT_EQ(r.diagnostics[0].range.line, 2);
  EXPECT_EQ(r.diagnostics[1].code, codes::kMaterialLineFields);
  EXPECT_EQ(r.diagnostics[1].range.line, 3);
  // CRLF lines read as LF lines; a missing file is said as a missing file, not as a line of 0 fields.
  const auto crlf = parseMaterials("x | x | X | เอกซ์ | 10-20 | 40-50 | 1000 | 0.2 | book\r\n", "m.cfg");
  ASSERT_TRUE(crlf.value.has_value());
  EXPECT_TRUE(crlf.diagnostics.empty());
  ASSERT_EQ(crlf.value->rows.size(), 1u);
  EXPECT_EQ(crlf.value->rows[0].source, "book");
  const auto missing = readMaterials("/nonexistent-klueng-folder/materials.cfg");
  EXPECT_FALSE(missing.value.has_value());
  ASSERT_EQ(missing.diagnostics.size(), 1u);
  EXPECT_EQ(missing.diagnostics[0].code, codes::kNoSuchFile);
}

TEST(CuttingDataTest, RoughnessAndKienzleFormulas) {
  EXPECT_DOUBLE_EQ(roughnessRz(0.2, 0.8), 6.25);
  EXPECT_DOUBLE_EQ(roughnessRa(0.2, 0.8), 1.5625);
  EXPECT_DOUBLE_EQ(roughnessRz(0.2, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(specificCuttingForce(1500, 0.22, 1.0), 1500.0);
  EXPECT_NEAR(specificCuttingForce(1500, 0.22, 0.1), 1500.0 * std::pow(10.0, 0.22), 1e-9);
}

// Issue 39 item 2: the drawing's roughness mark judges the finishing feed where it lies, the
// message says which limit it was; the 3.2 um default only where no mark lies under the cut.
const std::string kFinishPass =
    "Cutting data\nFinish\nS45C\n150\n1100\nTest\n"
    "G21 G40 G99\n"      // 7
    "T0101\n"            // 8
    "G97 S800 M03\n"     // 9
    "G00 X60. Z2.\n"     // 10
    "X49.4\n"            // 11
    "G01 Z-20. F0.25\n"  // 12: Ra = 0.0625 / (32 * 0.8) * 1000 = 2.441 um, ap 0.3 mm
    "G00 X60.\n"         // 13
    "M30\n";

TEST(CuttingDataTest, TheDrawingsRoughnessMarkJudgesTheFinishingFeed) {
  // No mark: 2.44 um is within the default 3.2: sound.
  EXPECT_TRUE(cdRun(kFinishPass).data.warnings.empty());
  // The drawing asks Ra 1.6 on Ø49.4 from Z0 to Z-20: the largest feed is sqrt(1.6 * 32 * 0.8 / 1000) = 0.202.
  const CdRun marked = cdRun(kFinishPass, [](CuttingDataOptions& o) {
    o.finishMarks.push_back(FinishMark{false, -20.0, 0.0, 49.4, 49.4, 1.6});
  });
  ASSERT_EQ(warningCodesOn(marked.data, 12), (std::vector<std::string>{codes::kFinishTooRough}));
  EXPECT_EQ(formatMessage(marked.data.warnings[0], Lang::En),
            "finishing feed 0.250 mm/rev with nose radius R0.80 leaves Ra 2.4 um (Rz 9.8 um), rougher than Ra 1.6 "
            "um (the drawing's mark for diameter 49.40 from Z0.00 to Z-20.00): use F0.202 or less, or an insert "
            "with a larger nose radius");
  EXPECT_NE(formatMessage(marked.data.warnings[0], Lang::Th).find("ตามสัญลักษณ์ความหยาบผิวในแบบงาน"), std::string::npos);
  // A mark on another surface (Ø30) leaves this one to the default: sound again.
  const CdRun elsewhere = cdRun(kFinishPass, [](CuttingDataOptions& o) {
    o.finishMarks.push_back(FinishMark{false, -20.0, 0.0, 30.0, 30.0, 1.6});
  });
  EXPECT_TRUE(elsewhere.data.warnings.empty());
  // A coarser mark (Ra 6.3) allows more than the default: a 0.3 feed (Ra 3.5) passes there.
  const CdRun coarse = cdRun(
      "Cutting data\nFinish\nS45C\n150\n1100\nTest\nG21 G40 G99\nT0101\nG97 S800 M03\nG00 X60. Z2.\nX49.4\n"
      "G01 Z-20. F0.3\nG00 X60.\nM30\n",
      [](CuttingDataOptions& o) {
        o.finishMarks.push_back(FinishMark{false, -20.0, 0.0, 49.4, 49.4, 6.3});
      });
  EXPECT_TRUE(coarse.data.warnings.empty());
  // finishLimit itself: the mark's side and diameter (within 0.5 mm) and Z overlap.
  CuttingDataOptions o;
  o.finishMarks.push_back(FinishMark{false, -20.0, -5.0, 30.0, 30.0, 0.8});
  const FinishMark* mark = nullptr;
  EXPECT_DOUBLE_EQ(finishLimit(o, false, 30.3, -10.0, -30.0, &mark), 0.8);
  EXPECT_NE(mark, nullptr);
  EXPECT_DOUBLE_EQ(finishLimit(o, true, 30.0, -10.0, -30.0, &mark), 3.2);  // a bore: not this mark
  EXPECT_EQ(mark, nullptr);
  EXPECT_DOUBLE_EQ(finishLimit(o, false, 31.0, -10.0, -30.0), 3.2);  // 1 mm off its diameter
  EXPECT_DOUBLE_EQ(finishLimit(o, false, 30.0, -1.0, 0.0), 3.2);     // right of it
}

// Issue 39 item 1: the check's warnings-only measure gives the very warnings the full one does,
// on their blocks, and stops at the record's first alarm.
TEST(CuttingDataTest, WarningsOnlyGivesTheSameWarnings) {
  const std::string rough =
      "Cutting data\nRough\nS45C\n150\n1100\nTest\n"
      "G21 G40 G99\n"     // 7
      "T0101\n"           // 8
      "G97 S1000 M03\n"   // 9
      "G00 X60. Z2.\n"    // 10
      "X46.\n"            // 11
      "G01 Z-30. F0.2\n"  // 12: sound
      "G00 X60.\n"        // 13
      "Z2.\n"             // 14
      "X45.4\n"           // 15
      "G01 Z-30. F0.4\n"  // 16: ap 0.3, Ra = 0.16 / 25.6 * 1000 = 6.25 um > 3.2
      "G00 X60.\n"        // 17
      "M30\n";
  const CdRun full = cdRun(rough, [](CuttingDataOptions& o) { o.toolMaterial[0] = ToolMaterial::Hss; });
  // HSS in S45C (20-35 m/min): line 12 at pi * 46 * 1000 / 1000 = 144.5 and line 16 at 142.6 are too fast.
  EXPECT_EQ(warningCodesOn(full.data, 12), (std::vector<std::string>{codes::kCutSpeedHigh}));
  EXPECT_EQ(warningCodesOn(full.data, 16), (std::vector<std::string>{codes::kCutSpeedHigh, codes::kFinishTooRough}));
  CuttingDataOptions only = full.options;
  only.warningsOnly = true;
  const CuttingData quick = measureCuts(full.run.timeline, CutSetup::from(full.run.file.header, full.run.setup), only);
  ASSERT_EQ(quick.warnings.size(), full.data.warnings.size());
  for (std::size_t i = 0; i < quick.warnings.size(); ++i) {
    EXPECT_EQ(quick.warnings[i].code, full.data.warnings[i].code);
    EXPECT_EQ(quick.warnings[i].range.line, full.data.warnings[i].range.line);
    EXPECT_EQ(quick.warnings[i].args, full.data.warnings[i].args);
  }
  EXPECT_TRUE(quick.cuts.empty());  // the check keeps no numbers
  // Measured only up to move 5 (the first cut and its retract): line 16 is not reached.
  only.moveEnd = 5;
  const CuttingData part = measureCuts(full.run.timeline, CutSetup::from(full.run.file.header, full.run.setup), only);
  ASSERT_EQ(part.warnings.size(), 1u);
  EXPECT_EQ(part.warnings[0].range.line, 12);
  // The sound carbide run: nothing to say, in either mode.
  CdRun sound = cdRun(kSteelTurn);
  sound.options.warningsOnly = true;
  EXPECT_TRUE(measureCuts(sound.run.timeline, CutSetup::from(sound.run.file.header, sound.run.setup), sound.options)
                  .warnings.empty());
}

// The check stops measuring once every code the run could raise has been said its 20 times: 30
// passes of 0.1 mm at F0.4 (Ra 6.25 um, W332 each) give the same 20 warnings as the full measure.
TEST(CuttingDataTest, TheCheckStopsWhenEverythingItCouldSayIsSaid) {
  std::string text = "Cutting data\nPasses\nS45C\n150\n1100\nTest\nG21 G40 G99\nT0101\nG97 S800 M03\nG00 X52. Z2.\n";
  for (int pass = 1; pass <= 30; ++pass)  // 0.1 mm a pass on the radius: X49.8, X49.6 ...
    text += fmt::format("G00 X{:.1f}\nG01 Z-10. F0.4\nG00 X52.\nZ2.\n", 50.0 - 0.2 * pass);
  text += "M30\n";
  // A tool whose material and edge are not known: W332 is the only code the run could raise.
  CdRun full = cdRun(text, [](CuttingDataOptions& o) {
    o.toolMaterial[0] = ToolMaterial::Unknown;
    o.edgeLength[0] = 0.0;
  });
  ASSERT_EQ(full.data.warnings.size(), 20u);  // at most 20 of one code
  CuttingDataOptions only = full.options;
  only.warningsOnly = true;
  const CuttingData quick = measureCuts(full.run.timeline, CutSetup::from(full.run.file.header, full.run.setup), only);
  ASSERT_EQ(quick.warnings.size(), 20u);
  for (std::size_t i = 0; i < 20; ++i) {
    EXPECT_EQ(quick.warnings[i].code, codes::kFinishTooRough);
    EXPECT_EQ(quick.warnings[i].range.line, full.data.warnings[i].range.line);
  }
}

// Issue 39 item 3: the roughness each finished surface got is the last cut's over it.
TEST(CuttingDataTest, EachSurfaceGetsTheRoughnessOfItsLastCut) {
  const CdRun r = cdRun(
      "Cutting data\nSurfaces\nS45C\n150\n1100\nTest\n"
      "G21 G40 G99\n"     // 7
      "T0101\n"           // 8
      "G97 S1000 M03\n"   // 9
      "G00 X60. Z2.\n"    // 10
      "X46.\n"            // 11
      "G01 Z-30. F0.3\n"  // 12: Ø46 over 30 mm, Ra = 0.3^2 / (32 * 0.8) * 1000 = 3.516 um
      "G00 X60.\n"        // 13
      "Z2.\n"             // 14
      "X40.\n"            // 15
      "G01 Z-20. F0.1\n"  // 16: Ø40 over 20 mm, Ra = 0.1^2 / 25.6 * 1000 = 0.3906 um, Rz 1.5625 um
      "X48. F0.15\n"      // 17: the shoulder at Z-20 faced out, Ra = 0.15^2 / 25.6 * 1000 = 0.8789 um
      "G00 X60.\n"        // 18
      "M30\n");
  ASSERT_FALSE(r.data.cuts.empty());
  CutSimulator sim(r.run.timeline, CutSetup::from(r.run.file.header, r.run.setup));
  sim.runToEnd();
  const std::vector<SurfaceFinish> got = surfaceFinishes(r.data, sim.stock());
  const auto find = [&](double dMax, bool face) -> const SurfaceFinish* {
    for (const SurfaceFinish& s : got)
      if (s.face == face && std::abs(s.dMax - dMax) < 0.05 && (face || std::abs(s.dMin - dMax) < 0.05)) return &s;
    return nullptr;
  };
  const SurfaceFinish* finished = find(40.0, false);
  ASSERT_NE(finished, nullptr);
  EXPECT_EQ(finished->line, 16);
  expectWithin1Percent(finished->ra, 0.3906, "Ra of the Ø40");
  expectWithin1Percent(finished->rz, 1.5625, "Rz of the Ø40");
  // Ø46 left of the shoulder: line 12's surface (Z-20 to Z-30).
  const SurfaceFinish* left = find(46.0, false);
  ASSERT_NE(left, nullptr);
  EXPECT_EQ(left->line, 12);
  expectWithin1Percent(left->ra, 3.516, "Ra of the Ø46");
  // The shoulder face up to Ø46 at Z-20: the facing move of line 17.
  const SurfaceFinish* shoulder = find(46.0, true);
  ASSERT_NE(shoulder, nullptr);
  EXPECT_EQ(shoulder->line, 17);
  expectWithin1Percent(shoulder->ra, 0.8789, "Ra of the shoulder");
}

TEST(CuttingDataTest, ARecordIsMeasuredUpToItsFirstAlarm) {
  machine::Timeline t;
  for (int i = 0; i < 4; ++i) {
    t.moves.emplace_back();
    machine::StateSnapshot s;
    s.line = 10 + i;
    s.moveEnd = i + 1;
    t.snapshots.push_back(s);
  }
  EXPECT_EQ(movesBeforeAlarm(t), 4u);
  t.alarm = Diagnostic{Severity::Alarm, "A104", SourceRange{12, 1, 0, 0}, {}};
  EXPECT_EQ(movesBeforeAlarm(t), 2u);  // lines 10 and 11's moves
}

}  // namespace
}  // namespace klueng::core::cut

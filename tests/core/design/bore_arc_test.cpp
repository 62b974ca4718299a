// The generator's bores (a tube bored with the boring bar) and arc steps:
// the threaded bush — groove, M30x1.5 and a stepped bore — turned in every
// dialect to the drawing; bores and arcs that cannot be turned say why.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "design_test_util.h"
#include "klueng/core/cut/part_check.h"

namespace klueng::core::design {
namespace {

PartDesign threadedBush() {
  const auto d = readPartDesign(slurp(KLUENG_SOURCE_DIR "/resources/parts/threaded-bush.json"), "threaded-bush.json");
  EXPECT_TRUE(d.ok());
  return d.value.value_or(PartDesign{});
}

std::size_t defectsOf(const std::string& text, const machine::MachineSetup& setup, gcode::Dialect dialect) {
  const auto file = io::parseProgramFile(text);
  job::JobInput input;
  input.file = *file.value;
  input.setup = setup;
  input.run.dialect = dialect;
  input.inferTools = false;  // the generated program's own setup
  const std::shared_ptr<const job::Job> job = job::makeJob(input);
  const machine::Timeline programmed = cut::programmedPath(*job->program(), setup, input.run, *job->timeline());
  return cut::checkPart(*job->timeline(), programmed, cut::CutSetup::from(file.value->header, setup)).defects.size();
}

class BushInEveryDialect : public ::testing::TestWithParam<gcode::Dialect> {};

TEST_P(BushInEveryDialect, GrooveThreadAndBoreAreCutToTheDrawing) {
  const machine::MachineSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
  std::vector<Diagnostic> why;
  const auto program = generateProgram(threadedBush(), optionsFor(GetParam(), setup), &why);
  ASSERT_TRUE(program) << (why.empty() ? "" : why[0].code);
  // The header names the tube: Ø50 with a Ø16 hole.
  EXPECT_NE(program->text.find("\n150x16\n180\n"), std::string::npos);
  const Turned t = turn(program->text, GetParam(), setup);
  ASSERT_TRUE(t.sim);
  EXPECT_FALSE(t.sim->stoppingAlarm().has_value()) << t.sim->stoppingAlarm()->code << "\n" << program->text;
  const cut::PartFeatures part = cut::partFeatures(t.sim->stock());
  // Outside: M30x1.5 from the face (minor 30 - 2 x 0.6134 x 1.5), the 4 mm relief groove to Ø27, Ø46 with C1.
  const cut::PartFeature* thread = find(part, cut::FeatureKind::Thread, "M30×1.5");
  ASSERT_NE(thread, nullptr) << program->text;
  EXPECT_NEAR(thread->minorDiameter, 30.0 - 2.0 * 0.6134 * 1.5, 0.01);
  const cut::PartFeature* groove = nullptr;
  for (const cut::PartFeature& f : part.outside)
    if (f.kind == cut::FeatureKind::Groove) groove = &f;
  ASSERT_NE(groove, nullptr);
  EXPECT_NEAR(groove->diameter, 27.0, 0.01);
  EXPECT_NEAR(groove->zRight, -24.0, 0.06);
  EXPECT_NEAR(groove->width, 4.0, 0.06);
  EXPECT_NE(find(part, cut::FeatureKind::Cylinder, "Ø46"), nullptr);
  EXPECT_NE(find(part, cut::FeatureKind::Chamfer, "C1"), nullptr);
  // The bore: C1 at the mouth, Ø20 to Z-30, Ø18 on through the part to Z-50, the tube's Ø16 beyond.
  const cut::PartFeature* mouth = find(part, cut::FeatureKind::Chamfer, "C1", true);
  ASSERT_NE(mouth, nullptr);
  EXPECT_NEAR(mouth->diameterRight, 22.0, 0.01);
  for (const auto& [label, d, zLeft] : {std::tuple{"Ø20", 20.0, -30.0}, std::tuple{"Ø18", 18.0, -50.0}}) {
    const cut::PartFeature* bore = find(part, cut::FeatureKind::Cylinder, label, true);
    ASSERT_NE(bore, nullptr) << label;
    EXPECT_NEAR(bore->diameter, d, 0.01) << label;
    EXPECT_NEAR(bore->zLeft, zLeft + 0.4, 0.01) << label;  // the R0.4 boring bar's fillet in the corner
  }
  EXPECT_EQ(defectsOf(program->text, setup, GetParam()), 0u);
}

INSTANTIATE_TEST_SUITE_P(Generator, BushInEveryDialect,
                         ::testing::Values(gcode::Dialect::Fanuc, gcode::Dialect::Haas, gcode::Dialect::Classic));

TEST(Generator, BoresThatCannotBeCutSayWhy) {
  std::vector<Diagnostic> why;
  const auto firstCode = [&](const PartDesign& p) {
    why.clear();
    EXPECT_FALSE(generateProgram(p, {}, &why));
    return why.empty() ? std::string() : why[0].code;
  };
  PartDesign part = threadedBush();
  part.stockBore = 0.0;  // a solid bar, and a bore too small to drill Ø10 and bore out
  part.inside = {{StepKind::Cylinder, 11.0, 20.0}};
  EXPECT_EQ(firstCode(part), "E514");
  EXPECT_EQ(formatMessage(why[0], Lang::En),
            "The bore Ø11. is too small to drill with the Ø10. drill and bore out (at least Ø12.) in a solid bar: give "
            "the stock a hole (\"bore\" under \"stock\", a tube) no larger than the bore");
  part = threadedBush();
  part.inside[1].diameter = 14.0;  // below the tube's Ø16 hole
  EXPECT_EQ(firstCode(part), "E515");
  part = threadedBush();
  part.inside[1].diameter = 24.0;  // wider behind a Ø20: the bar cannot reach it
  EXPECT_EQ(firstCode(part), "E512");
  part = threadedBush();
  part.inside[1].length = 30.0;  // 60 mm of bore in a 50 mm part
  EXPECT_EQ(firstCode(part), "E516");
  part = threadedBush();
  part.inside[1].edge = EdgeBreak::Chamfer;
  part.inside[1].edgeSize = 1.5;  // C1.5 on a 1 mm step (Ø20 to Ø18)
  EXPECT_EQ(firstCode(part), "E513");
}

TEST(Generator, ArcStepsAreTurnedAndArcsThatDoNotMeetAreRefused) {
  const machine::MachineSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
  PartDesign part;
  part.name = "Arc shaft";
  part.stockDiameter = 50.0;
  part.stockLength = 100.0;
  OutsideStep bulge{StepKind::Arc, 40.0, 5.0};
  bulge.radius = 5.0;  // a quarter circle from Ø30 at Z-20 up to Ø40 at Z-25, centre Z-25 X30
  OutsideStep hollow{StepKind::Arc, 46.0, 3.0};
  hollow.radius = 3.0;  // a quarter fillet from Ø40 at Z-40 up to Ø46 at Z-43, centre Z-40 X46
  hollow.concave = true;
  part.outside = {{StepKind::Cylinder, 30.0, 20.0, EdgeBreak::Chamfer, 1.0},
                  bulge,
                  {StepKind::Cylinder, 40.0, 15.0},
                  hollow,
                  {StepKind::Cylinder, 46.0, 17.0}};
  GenerateOptions options;
  options.machine = setup.machine;
  for (const gcode::Dialect dialect : {gcode::Dialect::Fanuc, gcode::Dialect::Haas, gcode::Dialect::Classic}) {
    options.dialect = dialect;
    const auto program = generateProgram(part, options);
    ASSERT_TRUE(program);
    EXPECT_NE(program->text.find("G03 X40. Z-25. R5."), std::string::npos) << program->text;
    EXPECT_NE(program->text.find("G02 X46. Z-43. R3."), std::string::npos);
    const Turned t = turn(program->text, dialect, setup);
    ASSERT_TRUE(t.sim);
    EXPECT_FALSE(t.sim->stoppingAlarm().has_value()) << program->text;
    const cut::PartFeatures cut = cut::partFeatures(t.sim->stock());
    const cut::PartFeature* r5 = find(cut, cut::FeatureKind::Arc, "R5");
    ASSERT_NE(r5, nullptr) << program->text;
    EXPECT_TRUE(r5->convex);
    EXPECT_NEAR(r5->centre.x(), -25.0, 0.01);
    EXPECT_NEAR(r5->centre.y(), 15.0, 0.01);
    const cut::PartFeature* r3 = find(cut, cut::FeatureKind::Arc, "R3");
    ASSERT_NE(r3, nullptr);
    EXPECT_FALSE(r3->convex);
    EXPECT_NEAR(r3->centre.x(), -40.0, 0.01);
    EXPECT_NEAR(r3->centre.y(), 23.0, 0.01);
    EXPECT_EQ(defectsOf(program->text, setup, dialect), 0u);
  }
  // R2 cannot join Ø30 at Z-20 to Ø40 at Z-25: the ends are √(5² + 5²) = 7.071 mm apart, more than 4.
  std::vector<Diagnostic> why;
  part.outside[1].radius = 2.0;
  EXPECT_FALSE(generateProgram(part, options, &why));
  ASSERT_FALSE(why.empty());
  EXPECT_EQ(why[0].code, "E517");
  EXPECT_EQ(
      formatMessage(why[0], Lang::En),
      "Step 2's arc R2. does not meet its neighbours: from Ø30. to Ø40. its ends are 7.071 mm apart, more than 2 × R");
  // R10 over Ø30 to Ø34 in 8 mm bulges over its top (centre Z-26.21 X7.16) and falls back: an undercut.
  part.outside[1] = {StepKind::Arc, 34.0, 8.0};
  part.outside[1].radius = 10.0;
  part.outside[2].diameter = 34.0;
  why.clear();
  EXPECT_FALSE(generateProgram(part, options, &why));
  ASSERT_FALSE(why.empty());
  EXPECT_EQ(why[0].code, "E518");
  const double dz = -8.0, dr = 2.0, chord = std::hypot(dz, dr), h = std::sqrt(100.0 - chord * chord / 4.0);
  const double centreR = 16.0 - h * (-dz / chord);
  EXPECT_NEAR(std::stod(why[0].args.at(2)), 2.0 * (centreR + 10.0), 0.001);
}

TEST(Generator, PartFilesReadBoresAndArcs) {
  const auto bush = readPartDesign(slurp(KLUENG_SOURCE_DIR "/resources/parts/threaded-bush.json"), "b.json");
  ASSERT_TRUE(bush.ok());
  EXPECT_DOUBLE_EQ(bush.value->stockBore, 16.0);
  ASSERT_EQ(bush.value->inside.size(), 2u);
  EXPECT_DOUBLE_EQ(bush.value->inside[0].diameter, 20.0);
  EXPECT_EQ(bush.value->inside[0].edge, EdgeBreak::Chamfer);
  const auto arc = readPartDesign(
      R"({"stock": {"diameter": 50, "length": 90}, "outside": [{"cylinder": 30, "length": 20},)"
      R"( {"arc": 40, "length": 5, "radius": 5}, {"arc": 46, "length": 3, "radius": 3, "concave": true}]})",
      "a.json");
  ASSERT_TRUE(arc.ok());
  EXPECT_EQ(arc.value->outside[1].kind, StepKind::Arc);
  EXPECT_DOUBLE_EQ(arc.value->outside[1].radius, 5.0);
  EXPECT_TRUE(arc.value->outside[2].concave);
  const auto noRadius =
      readPartDesign(R"({"stock": {"diameter": 50, "length": 90}, "outside": [{"arc": 40, "length": 5}]})", "n.json");
  EXPECT_EQ(noRadius.diagnostics.at(0).code, "F181");
  EXPECT_EQ(noRadius.diagnostics.at(0).args.at(1), "outside[0].radius");
  const auto holeTooBig = readPartDesign(
      R"({"stock": {"diameter": 50, "length": 90, "bore": 50}, "outside": [{"cylinder": 30, "length": 20}]})",
      "h.json");
  EXPECT_EQ(holeTooBig.diagnostics.at(0).code, "F182");
}

}  // namespace
}  // namespace klueng::core::design

namespace klueng::core::design {
namespace {

// Every block of a Fanuc or Haas program says what its numbers are, in the UI language; the classic
// dialect's repeated passes say it on their first pass.
TEST(Generator, EveryBlockIsExplainedInTheUiLanguage) {
  const machine::MachineSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
  PartDesign part = threadedBush();
  part.stockBore = 0.0;  // drilled too
  part.partOff = true;
  for (const gcode::Dialect dialect : {gcode::Dialect::Fanuc, gcode::Dialect::Haas}) {
    for (const Lang lang : {Lang::En, Lang::Th}) {
      GenerateOptions options = optionsFor(dialect, setup);
      options.lang = lang;
      const auto program = generateProgram(part, options);
      ASSERT_TRUE(program);
      std::istringstream lines(program->text);
      int n = 0, thai = 0;
      for (std::string line; std::getline(lines, line);) {
        if (++n <= 6 || line == "%" || line.rfind("(", 0) == 0) continue;  // header, tape marks, comment lines
        EXPECT_NE(line.find(" ("), std::string::npos) << "line " << n << ": " << line;
        if (line.find("\xE0\xB8") != std::string::npos) ++thai;  // a Thai letter (U+0E00 block)
      }
      if (lang == Lang::Th) {
        EXPECT_GT(thai, n / 2);
      }
    }
  }
}

}  // namespace
}  // namespace klueng::core::design

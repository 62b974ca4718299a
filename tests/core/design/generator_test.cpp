// From drawing to program (issue 14, first step): sample 01's part as a design
// file, generated in all three dialects, checked, run, cut and part-checked.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/part_check.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/design/part_design.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/setup_files.h"
#include "design_test_util.h"

namespace klueng::core::design {
namespace {

class EveryDialect : public ::testing::TestWithParam<gcode::Dialect> {};

TEST_P(EveryDialect, Sample01sPartIsTurnedToTheDrawing) {
  const machine::MachineSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
  GenerateOptions options;
  options.dialect = GetParam();
  options.machine = setup.machine;
  std::vector<Diagnostic> why;
  const auto program = generateProgram(stepShaft(), options, &why);
  ASSERT_TRUE(program) << (why.empty() ? "" : why[0].code);
  const Turned t = turn(program->text, GetParam(), setup);
  ASSERT_TRUE(t.sim);
  EXPECT_FALSE(t.sim->stoppingAlarm().has_value()) << t.sim->stoppingAlarm()->code;
  const cut::PartFeatures part = cut::partFeatures(t.sim->stock());
  for (const char* label : {"Ø30", "Ø40", "Ø46"}) {
    const cut::PartFeature* f = find(part, cut::FeatureKind::Cylinder, label);
    ASSERT_NE(f, nullptr) << label;
    EXPECT_NEAR(f->diameter, std::stod(std::string(label).substr(2)), 0.01) << label;
  }
  EXPECT_NE(find(part, cut::FeatureKind::Chamfer, "C3"), nullptr);
  EXPECT_NE(find(part, cut::FeatureKind::Chamfer, "C1"), nullptr);
  const cut::PartFeature* r2 = find(part, cut::FeatureKind::Arc, "R2");
  ASSERT_NE(r2, nullptr);
  EXPECT_NEAR(r2->centre.x(), -22.0, 0.01);
  // Part check: no gouge, nothing left beyond 0.01 mm.
  const cut::PartCheck check = cut::checkPart(
      *t.job->timeline(), t.programmed, cut::CutSetup::from(io::parseProgramFile(program->text).value->header, setup));
  EXPECT_TRUE(check.defects.empty()) << check.defects.size();
}

INSTANTIATE_TEST_SUITE_P(Generator, EveryDialect,
                         ::testing::Values(gcode::Dialect::Fanuc, gcode::Dialect::Haas, gcode::Dialect::Classic));

TEST(Generator, GroovesArePlungedWithTheBladeToTheirWidthAndDiameter) {
  const machine::MachineSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
  PartDesign part = stepShaft();
  part.grooves = {{-26.0, 5.0, 34.0}, {-48.0, 3.0, 42.0}};  // on Ø40 (5 wide, two plunges) and on Ø46
  GenerateOptions options;
  options.machine = setup.machine;
  for (const gcode::Dialect dialect : {gcode::Dialect::Fanuc, gcode::Dialect::Haas, gcode::Dialect::Classic}) {
    options.dialect = dialect;
    std::vector<Diagnostic> why;
    const auto program = generateProgram(part, options, &why);
    ASSERT_TRUE(program) << (why.empty() ? "" : why[0].code);
    const Turned t = turn(program->text, dialect, setup);
    ASSERT_TRUE(t.sim);
    EXPECT_FALSE(t.sim->stoppingAlarm().has_value()) << program->text;
    const cut::PartFeatures features = cut::partFeatures(t.sim->stock());
    std::vector<const cut::PartFeature*> grooves;
    for (const cut::PartFeature& f : features.outside)
      if (f.kind == cut::FeatureKind::Groove) grooves.push_back(&f);
    ASSERT_EQ(grooves.size(), 2u) << program->text;
    // Right to left: the one on Ø46 is further left.
    EXPECT_NEAR(grooves[0]->diameter, 34.0, 0.01);
    EXPECT_NEAR(grooves[0]->width, 5.0, 0.06);
    EXPECT_NEAR(grooves[0]->zRight, -26.0, 0.06);
    EXPECT_NEAR(grooves[0]->depth, 3.0, 0.01);  // Ø40 to Ø34
    EXPECT_NEAR(grooves[1]->diameter, 42.0, 0.01);
    EXPECT_NEAR(grooves[1]->width, 3.0, 0.06);
    const cut::PartCheck check =
        cut::checkPart(*t.job->timeline(), t.programmed,
                       cut::CutSetup::from(io::parseProgramFile(program->text).value->header, setup));
    EXPECT_TRUE(check.defects.empty()) << check.defects.size();
  }
  // Refused: narrower than the blade, over a shoulder, through the part.
  std::vector<Diagnostic> why;
  part.grooves = {{-26.0, 2.0, 34.0}};
  EXPECT_FALSE(generateProgram(part, options, &why));
  EXPECT_EQ(why.at(0).code, "E507");
  why.clear();
  part.grooves = {{-18.0, 4.0, 26.0}};  // Z-18 to Z-22 crosses the Ø30/Ø40 shoulder at Z-20
  EXPECT_FALSE(generateProgram(part, options, &why));
  EXPECT_EQ(why.at(0).code, "E508");
  why.clear();
  part.grooves = {{-26.0, 4.0, 44.0}};  // deeper than nothing: Ø44 on a Ø40 cylinder
  EXPECT_FALSE(generateProgram(part, options, &why));
  EXPECT_EQ(why.at(0).code, "E509");
}

TEST(Generator, AnM30ThreadIsCutInEveryDialect) {
  const machine::MachineSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
  PartDesign part;
  part.name = "Bolt M30";
  part.stockDiameter = 50.0;
  part.stockLength = 100.0;
  part.outside = {{StepKind::Cylinder, 30.0, 30.0, EdgeBreak::Chamfer, 1.5},
                  {StepKind::Cylinder, 40.0, 20.0, EdgeBreak::Round, 2.0}};
  part.threads = {{0.0, 22.0, 1.5}};
  GenerateOptions options;
  options.machine = setup.machine;
  // ISO: thread height 0.6134 x 1.5 = 0.920 mm a side, minor Ø 30 - 1.840 = 28.16.
  const double minor = 30.0 - 2.0 * 0.6134 * 1.5;
  for (const gcode::Dialect dialect : {gcode::Dialect::Fanuc, gcode::Dialect::Haas, gcode::Dialect::Classic}) {
    options.dialect = dialect;
    const auto program = generateProgram(part, options);
    ASSERT_TRUE(program);
    const Turned t = turn(program->text, dialect, setup);
    ASSERT_TRUE(t.sim);
    EXPECT_FALSE(t.sim->stoppingAlarm().has_value()) << program->text;
    const cut::PartFeatures features = cut::partFeatures(t.sim->stock());
    const cut::PartFeature* thread = find(features, cut::FeatureKind::Thread, "M30×1.5");
    ASSERT_NE(thread, nullptr) << program->text;
    EXPECT_NEAR(thread->pitch, 1.5, 0.01);
    EXPECT_NEAR(thread->minorDiameter, minor, 0.01);
    EXPECT_DOUBLE_EQ(thread->zRight, 0.0);
    EXPECT_LT(thread->zLeft, -21.0);
    const cut::PartCheck check =
        cut::checkPart(*t.job->timeline(), t.programmed,
                       cut::CutSetup::from(io::parseProgramFile(program->text).value->header, setup));
    EXPECT_TRUE(check.defects.empty());
    // Comments are read by people: sizes as a drawing writes them, never with G-code's trailing point.
    EXPECT_NE(program->text.find("(M30x1.5: thread height 0.6134 x 1.5 = 0.92 mm, minor D28.16)"), std::string::npos)
        << program->text;
    EXPECT_EQ(program->text.find("M30.x"), std::string::npos);
    for (std::size_t open = program->text.find('('); open != std::string::npos;
         open = program->text.find('(', open + 1)) {
      const std::string comment = program->text.substr(open, program->text.find(')', open) - open + 1);
      for (std::size_t k = 1; k + 1 < comment.size(); ++k) {
        if (comment[k] == '.' && std::isdigit(static_cast<unsigned char>(comment[k - 1]))) {
          EXPECT_TRUE(std::isdigit(static_cast<unsigned char>(comment[k + 1]))) << comment;
        }
      }
    }
  }
  // Longer than its cylinder, or a pitch that does not fit: refused.
  std::vector<Diagnostic> why;
  part.threads = {{0.0, 35.0, 1.5}};
  EXPECT_FALSE(generateProgram(part, options, &why));
  EXPECT_EQ(why.at(0).code, "E510");
  why.clear();
  part.threads = {{0.0, 10.0, 8.0}};
  EXPECT_FALSE(generateProgram(part, options, &why));
  EXPECT_EQ(why.at(0).code, "E511");
}

// Issue 27: a machine in G-code system B gets its own numbers through the code
// table's renamed rows (G92 S for the clamp, G95 for feed per revolution), checks
// clean on that machine and cuts the same part as the system-A program, to 0.01 mm.
TEST(Generator, ASystemBMachineGetsItsOwnNumbersAndTheSamePart) {
  const machine::MachineSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
  gcode::Dialect romi{};
  ASSERT_TRUE(gcode::parseDialectId("romi-gl240m", romi));
  PartDesign part = stepShaft();
  part.threads = {{0.0, 12.0, 1.5}};
  part.grooves = {{-26.0, 5.0, 34.0}};
  const auto a = generateProgram(part, optionsFor(gcode::Dialect::Fanuc, setup));
  const auto b = generateProgram(part, optionsFor(romi, setup));
  ASSERT_TRUE(a && b);
  EXPECT_NE(a->text.find(" G50 S"), std::string::npos);
  EXPECT_NE(b->text.find(" G92 S"), std::string::npos) << b->text;
  EXPECT_EQ(b->text.find("G50"), std::string::npos) << b->text;
  EXPECT_NE(b->text.find(" G95"), std::string::npos) << b->text;
  EXPECT_EQ(b->text.find("G99"), std::string::npos) << b->text;
  EXPECT_NE(b->text.find(" G76 "), std::string::npos);  // G70-G76 keep their numbers in system B
  // The program names its machine at its head.
  EXPECT_EQ(io::parseProgramFile(b->text).value->header.machine, "romi-gl240m");
  EXPECT_EQ(io::parseProgramFile(a->text).value->header.machine, "");
  // Read as system A, the system-B program is refused (G95 is no system-A code).
  gcode::CheckOptions asA;
  asA.dialect = gcode::Dialect::Fanuc;
  const auto asAProgram = io::parseProgramFile(b->text);
  EXPECT_TRUE(hasErrors(gcode::check(gcode::parse(asAProgram.value->gcode, asAProgram.value->gcodeFirstLine), asA)));

  const Turned ta = turn(a->text, gcode::Dialect::Fanuc, setup);
  const Turned tb = turn(b->text, romi, setup);
  ASSERT_TRUE(ta.sim && tb.sim);
  EXPECT_FALSE(tb.sim->stoppingAlarm().has_value()) << b->text;
  const cut::PartFeatures fa = cut::partFeatures(ta.sim->stock());
  const cut::PartFeatures fb = cut::partFeatures(tb.sim->stock());
  ASSERT_EQ(fa.outside.size(), fb.outside.size());
  ASSERT_GE(fa.outside.size(), 6u);
  for (std::size_t i = 0; i < fa.outside.size(); ++i) {
    EXPECT_EQ(cut::featureLabel(fa.outside[i], Lang::En), cut::featureLabel(fb.outside[i], Lang::En));
    EXPECT_NEAR(fa.outside[i].diameter, fb.outside[i].diameter, 0.01) << i;
    EXPECT_NEAR(fa.outside[i].zLeft, fb.outside[i].zLeft, 0.01) << i;
    EXPECT_NEAR(fa.outside[i].zRight, fb.outside[i].zRight, 0.01) << i;
  }
  EXPECT_NE(find(fb, cut::FeatureKind::Thread, "M30×1.5"), nullptr);
  EXPECT_DOUBLE_EQ(ta.job->timeline()->cycleTime(), tb.job->timeline()->cycleTime());
}

TEST(Generator, SpeedsComeFromTheTableAndTheSpindleIsClamped) {
  const auto speeds = readCuttingSpeeds();
  ASSERT_TRUE(speeds.ok());
  const auto row = std::find_if(speeds.value->begin(), speeds.value->end(),
                                [](const CuttingSpeed& s) { return s.material == "aluminium"; });
  ASSERT_NE(row, speeds.value->end());
  EXPECT_DOUBLE_EQ(row->carbide, 500.0);
  EXPECT_DOUBLE_EQ(row->hss, 120.0);
  // A Ø36 aluminium bar, carbide: G96 S500, G50 at the machine's maximum. The
  // facing pass starts at Ø40 (4 mm over the bar).
  PartDesign part;
  part.material = "aluminium";
  part.stockDiameter = 36.0;
  part.stockLength = 80.0;
  part.outside = {{StepKind::Cylinder, 30.0, 20.0, EdgeBreak::Chamfer, 1.0}};
  const machine::MachineSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
  GenerateOptions options;
  options.machine = setup.machine;
  const auto program = generateProgram(part, options);
  ASSERT_TRUE(program);
  EXPECT_NE(program->text.find("G96 S500. M03"), std::string::npos);
  EXPECT_NE(program->text.find("G50 S" + std::to_string(static_cast<int>(setup.machine.maxSpindleRpm))),
            std::string::npos);
  // S = 1000·Vc/(π·D) at Ø40: 3979 rpm, more than the machine's maximum: the run holds it there.
  const double atForty = 1000.0 * 500.0 / (M_PI * 40.0);
  EXPECT_NEAR(spindleRpm(500.0, 40.0), atForty, 1e-9);
  EXPECT_GT(atForty, setup.machine.maxSpindleRpm);
  // The rpm where the tool starts facing at Ø40, as the run computes it.
  const auto rpmAtForty = [&](const std::string& text) {
    const Turned t = turn(text, gcode::Dialect::Fanuc, setup);
    EXPECT_TRUE(t.job->timeline());
    for (const machine::Move& m : t.job->timeline()->moves)
      if (m.kind == machine::MoveKind::Line && std::abs(2.0 * m.path.start.y() - 40.0) < 1e-6) return m.rpm;
    return -1.0;
  };
  EXPECT_NEAR(rpmAtForty(program->text), setup.machine.maxSpindleRpm, 0.5);
  // With HSS, 120 m/min: 955 rpm at Ø40, below the limit.
  part.toolMaterial = "hss";
  const auto slow = generateProgram(part, options);
  ASSERT_TRUE(slow);
  EXPECT_NE(slow->text.find("G96 S120. M03"), std::string::npos);
  EXPECT_NEAR(rpmAtForty(slow->text), 1000.0 * 120.0 / (M_PI * 40.0), 0.5);
}

TEST(Generator, PartsThatCannotBeTurnedSayWhyAndWriteNothing) {
  PartDesign part = stepShaft();
  std::vector<Diagnostic> why;
  part.outside[1].diameter = 26.0;  // Ø26 after Ø30: an undercut
  EXPECT_FALSE(generateProgram(part, {}, &why));
  ASSERT_FALSE(why.empty());
  EXPECT_EQ(why[0].code, "E501");
  EXPECT_EQ(formatMessage(why[0], Lang::En),
            "Step 2 (Ø26.) is thinner than the step before it (Ø30.): an undercut the turning tool cannot reach from "
            "the right");
  part = stepShaft();
  part.outside[2].edgeSize = 4.0;  // C4 on a 3 mm step (Ø40 to Ø46)
  why.clear();
  EXPECT_FALSE(generateProgram(part, {}, &why));
  ASSERT_EQ(why.size(), 1u);
  EXPECT_EQ(why[0].code, "E502");
  part = stepShaft();
  part.stockLength = 60.0;  // 60 mm of part, 45 outside the jaws
  why.clear();
  EXPECT_FALSE(generateProgram(part, {}, &why));
  EXPECT_EQ(why.at(0).code, "E503");
  part = stepShaft();
  part.material = "unobtainium";
  why.clear();
  EXPECT_FALSE(generateProgram(part, {}, &why));
  EXPECT_EQ(why.at(0).code, "E505");
  EXPECT_NE(formatMessage(why[0], Lang::Th).find("aluminium, brass, cast-iron, steel"), std::string::npos);
}

// Found by fuzz_design: a name with ")" closed the O line's comment early (E102).
TEST(Generator, APartsNameCannotBreakTheProgram) {
  const machine::MachineSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
  PartDesign part = stepShaft();
  part.name = "Bush (TB)-02\nsecond line";
  for (const gcode::Dialect dialect : {gcode::Dialect::Fanuc, gcode::Dialect::Haas}) {
    const auto program = generateProgram(part, optionsFor(dialect, setup), nullptr);
    ASSERT_TRUE(program);
    const auto file = io::parseProgramFile(program->text);
    ASSERT_TRUE(file.value);
    EXPECT_EQ(file.value->header.part, "Bush [TB]-02 second line");
    EXPECT_NE(program->text.find("(Bush [TB]-02 second line)\n"), std::string::npos);
    const Turned t = turn(program->text, dialect, setup);  // no error on any line
    EXPECT_TRUE(t.sim);
  }
  // Found by fuzz_design: a name the header would read as G-code made the file plain G-code.
  part.name = "%M10 bolt";
  const auto program = generateProgram(part, optionsFor(gcode::Dialect::Fanuc, setup), nullptr);
  ASSERT_TRUE(program);
  const auto file = io::parseProgramFile(program->text);
  ASSERT_TRUE(file.value);
  EXPECT_FALSE(file.value->plainGcode);
  EXPECT_EQ(file.value->header.part, "%M10 bolt");
  EXPECT_TRUE(turn(program->text, gcode::Dialect::Fanuc, setup).sim);
}

TEST(Generator, BadPartFilesNameTheirPlace) {
  const auto broken = readPartDesign("{\n  \"stock\": { \"diameter\": 50,\n  \"length\" 100 }\n}\n", "p.json");
  EXPECT_FALSE(broken.ok());
  ASSERT_EQ(broken.diagnostics.size(), 1u);
  EXPECT_EQ(broken.diagnostics[0].code, "F180");
  EXPECT_EQ(broken.diagnostics[0].range.line, 3);
  const auto empty = readPartDesign("", "e.json");
  EXPECT_EQ(empty.diagnostics.at(0).code, "F180");
  const auto negative = readPartDesign(
      "{\"stock\": {\"diameter\": 50, \"length\": 100}, \"outside\": [{\"cylinder\": -3, \"length\": 5}]}", "n.json");
  EXPECT_FALSE(negative.ok());
  EXPECT_EQ(negative.diagnostics.at(0).code, "F182");
  EXPECT_EQ(negative.diagnostics.at(0).args.at(1), "outside[0].cylinder");
  // Found by fuzz_design: a number too big for a double threw past the reader.
  const auto overflow = readPartDesign("{\"stock\": {\"diameter\": 50,\n \"length\": 2.5e553}}", "o.json");
  ASSERT_EQ(overflow.diagnostics.size(), 1u);
  EXPECT_EQ(overflow.diagnostics[0].code, "F180");
  EXPECT_EQ(overflow.diagnostics[0].range.line, 2);
  EXPECT_EQ(overflow.diagnostics[0].range.column, 12);
  // In our words (issue 42 item 6), not the JSON library's "number overflow parsing '2.5e553'".
  EXPECT_EQ(formatMessage(overflow.diagnostics[0], Lang::En),
            "o.json is not a part file: a number is too large for this program (at most about 1e308) (line 2, column "
            "12)");
  const auto binary = readPartDesign(std::string("\x89PNG\r\n\x1a\n\0\0", 10), "b.json");
  EXPECT_EQ(binary.diagnostics.at(0).code, "F180");
}

// Issue 29 item 6: block numbers stay within what the dialect reads (Fanuc and
// Haas N1-N99999, classic N1-N9999): N10 steps as by hand while they fit, closer
// steps when they do not, and a refusal (E519) when not even N1, N2, ... fit.
PartDesign manySteps(int steps) {
  PartDesign part;
  part.name = "Many steps";
  part.material = "aluminium";
  part.stockDiameter = 60.0;
  part.stockLength = 130.0;
  for (int k = 0; k < steps; ++k) {
    OutsideStep s;
    s.diameter = 10.0 + k * 0.004;
    s.length = 0.01;
    part.outside.push_back(s);
  }
  return part;
}

// The program's blocks checked in `dialect`; its N numbers, each block's words by N.
std::map<long, std::string> checkedBlocks(const std::string& text, gcode::Dialect dialect) {
  const auto file = io::parseProgramFile(text);
  EXPECT_TRUE(file.value.has_value());
  if (!file.value) return {};
  gcode::CheckOptions options;
  options.dialect = dialect;
  for (const Diagnostic& d : gcode::check(gcode::parse(file.value->gcode, file.value->gcodeFirstLine), options))
    EXPECT_NE(d.severity, Severity::Error) << d.code << " line " << d.range.line << ": " << formatMessage(d, Lang::En);
  std::map<long, std::string> blocks;
  std::istringstream in(file.value->gcode);
  long previous = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] != 'N') continue;
    const long n = std::stol(line.substr(1));
    EXPECT_GT(n, previous) << line;
    previous = n;
    blocks[n] = line.substr(line.find(' ') + 1);
  }
  return blocks;
}

TEST(Generator, ALongProgramIsNumberedCloserNeverPastTheLargestN) {
  // An ordinary part keeps N10, N20, ...
  std::map<long, std::string> blocks = checkedBlocks(generateProgram(stepShaft(), {})->text, gcode::Dialect::Fanuc);
  ASSERT_FALSE(blocks.empty());
  EXPECT_EQ(blocks.begin()->first, 10);
  EXPECT_EQ(std::next(blocks.begin())->first, 20);

  // 10,500 steps: 21,000 blocks, N210000 at N10 steps (the issue saw N100000 refused by the checker).
  GenerateOptions options;
  const auto fanuc = generateProgram(manySteps(10'500), options);
  ASSERT_TRUE(fanuc);
  blocks = checkedBlocks(fanuc->text, gcode::Dialect::Fanuc);
  ASSERT_GT(blocks.size(), 21'000u);
  EXPECT_LE(blocks.rbegin()->first, 99'999);
  EXPECT_EQ(blocks.begin()->first, 2);  // the widest step that fits
  // G71's P and Q still name the profile's first and last blocks.
  const auto g71 = fanuc->text.find("G71 P");
  ASSERT_NE(g71, std::string::npos);
  long p = 0, q = 0;
  ASSERT_EQ(std::sscanf(fanuc->text.c_str() + g71, "G71 P%ld Q%ld", &p, &q), 2);
  EXPECT_EQ(blocks.at(p).rfind("G00 X", 0), 0u) << blocks.at(p);
  EXPECT_EQ(blocks.at(q).rfind("G01 X", 0), 0u) << blocks.at(q);
  ASSERT_NE(blocks.upper_bound(q), blocks.end());
  EXPECT_EQ(blocks.upper_bound(q)->second.rfind("G00 G42", 0), 0u) << blocks.upper_bound(q)->second;

  // Classic reads N1-N9999: 1,200 steps already pass it at N10 steps.
  options.dialect = gcode::Dialect::Classic;
  const auto classic = generateProgram(manySteps(1'200), options);
  ASSERT_TRUE(classic);
  blocks = checkedBlocks(classic->text, gcode::Dialect::Classic);
  EXPECT_LE(blocks.rbegin()->first, 9'999);

  // Not even N1, N2, ... fit: refused, in both languages.
  std::vector<Diagnostic> why;
  EXPECT_FALSE(generateProgram(manySteps(10'500), options, &why));
  ASSERT_EQ(why.size(), 1u);
  EXPECT_EQ(why[0].code, "E519");
  EXPECT_EQ(formatMessage(why[0], Lang::En),
            "The program would have 21065 blocks, but Rook classic (1999 rules) numbers blocks only from N1 to N9999: "
            "it is not written; turn the part in fewer steps");
  EXPECT_EQ(formatMessage(why[0], Lang::Th),
            "โปรแกรมจะมี 21065 บล็อก แต่ รุก คลาสสิก (กฎปี 2542) ใช้หมายเลขบล็อกได้เพียง N1 ถึง N9999: "
            "จึงไม่เขียนโปรแกรม ให้ลดจำนวนขั้นของชิ้นงาน");
}

// A part design or drawing is read with a limit, as program files are (issue 29 item 6).
TEST(Generator, PartFilesAreReadWithALimit) {
  const auto shipped = readPartFile(KLUENG_SOURCE_DIR "/resources/parts/step-shaft.json");
  ASSERT_TRUE(shipped.ok());
  EXPECT_TRUE(readPartDesign(*shipped.value, "step-shaft.json").ok());
  const auto device = readPartFile("/dev/zero");
  EXPECT_FALSE(device.ok());
  ASSERT_EQ(device.diagnostics.size(), 1u);
  EXPECT_EQ(device.diagnostics[0].code, "F103");
  EXPECT_EQ(device.diagnostics[0].args.at(2), "16 MB");
  EXPECT_EQ(readPartFile("/no/such/part.dxf").diagnostics.at(0).code, "F101");
  EXPECT_EQ(readPartFile(KLUENG_SOURCE_DIR "/resources/parts").diagnostics.at(0).code, "F102");
}

}  // namespace
}  // namespace klueng::core::design

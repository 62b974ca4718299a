// Machine files on disk (issue 27): a machine from a user folder runs a
// program; its machine.cfg keys win over the setup's; a broken one is located;
// a system-B course program runs with the same trace as its system-A twin.
#include "klueng/core/machine/machine_files.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/dialect_fit.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/machine/trace.h"
#include "klueng/core/messages.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

namespace fs = std::filesystem;

// A system-B program in the habits of Brazilian course programs (issue 27):
// G90 G95 G21 on one line, G92 S, G75 used for facing, two-block G71/G70 with an
// indented profile, G78 with X-only repeat lines, G33 passes (one of them under
// G91), ';' closing every block, a bare N119; block.
constexpr const char* kSystemB =
    "O0027;\n"
    "(EIXO ROSCADO M20X1.5);\n"
    "G90 G95 G21;\n"
    "G92 S3000;\n"
    "T0101;\n"
    "G96 S200 M03;\n"
    "G00 X54. Z0. M08;\n"
    "G75 R0.5;\n"
    "G75 X0. Z-1. P3000 Q500 F0.15;\n"
    "G00 X52. Z2.;\n"
    "G71 U1.5 R0.5;\n"
    "G71 P10 Q20 U0.4 W0.1 F0.25;\n"
    "N10 G00 X18.;\n"
    "    G01 Z0.;\n"
    "    X20. Z-1.;\n"
    "    Z-15.;\n"
    "    X30. Z-25.;\n"
    "    Z-40.;\n"
    "N20 X52.;\n"
    "G70 P10 Q20 F0.1;\n"
    "G00 X100. Z100.;\n"
    "T0303;\n"
    "G97 S800 M03;\n"
    "G00 X24. Z5.;\n"
    "G78 X19.4 Z-13. F1.5;\n"
    "X18.9;\n"
    "X18.5;\n"
    "X18.38;\n"
    "G00 X24. Z5.;\n"
    "X18.3;\n"
    "G33 Z-13. F1.5;\n"
    "G00 X24.;\n"
    "Z5.;\n"
    "G91 G00 X-6.;\n"
    "G33 Z-18. F1.5;\n"
    "G00 X6.;\n"
    "Z18.;\n"
    "G90;\n"
    "N119;\n"
    "G00 X100. Z100. M09;\n"
    "M30;\n";

// The same program in system A, line for line.
constexpr const char* kSystemA =
    "O0027;\n"
    "(EIXO ROSCADO M20X1.5);\n"
    "G99 G21;\n"
    "G50 S3000;\n"
    "T0101;\n"
    "G96 S200 M03;\n"
    "G00 X54. Z0. M08;\n"
    "G75 R0.5;\n"
    "G75 X0. Z-1. P3000 Q500 F0.15;\n"
    "G00 X52. Z2.;\n"
    "G71 U1.5 R0.5;\n"
    "G71 P10 Q20 U0.4 W0.1 F0.25;\n"
    "N10 G00 X18.;\n"
    "    G01 Z0.;\n"
    "    X20. Z-1.;\n"
    "    Z-15.;\n"
    "    X30. Z-25.;\n"
    "    Z-40.;\n"
    "N20 X52.;\n"
    "G70 P10 Q20 F0.1;\n"
    "G00 X100. Z100.;\n"
    "T0303;\n"
    "G97 S800 M03;\n"
    "G00 X24. Z5.;\n"
    "G92 X19.4 Z-13. F1.5;\n"
    "X18.9;\n"
    "X18.5;\n"
    "X18.38;\n"
    "G00 X24. Z5.;\n"
    "X18.3;\n"
    "G32 Z-13. F1.5;\n"
    "G00 X24.;\n"
    "Z5.;\n"
    "G00 U-6.;\n"
    "G32 W-18. F1.5;\n"
    "G00 U6.;\n"
    "W18.;\n"
    "(ABSOLUTE);\n"
    "N119;\n"
    "G00 X100. Z100. M09;\n"
    "M30;\n";

std::vector<Diagnostic> errorsOf(const std::string& text, gcode::Dialect dialect) {
  gcode::CheckOptions options;
  options.dialect = dialect;
  std::vector<Diagnostic> errors;
  for (const Diagnostic& d : gcode::check(gcode::parse(text, 1), options))
    if (isError(d.severity)) errors.push_back(d);
  return errors;
}

std::string traceOf(const std::string& text, gcode::Dialect dialect, const MachineSetup& setup = testing::testSetup()) {
  RunOptions options;
  options.dialect = dialect;
  const Timeline t = testing::runText(text, options, setup);
  EXPECT_FALSE(t.alarm.has_value()) << (t.alarm ? formatMessage(*t.alarm, Lang::En) : "");
  return formatTraceCsv(t);
}

TEST(MachineFiles, UserFolderMachineRunsAProgram) {
  const testing::ScratchFolder folder{"machines", "machines"};
  folder.write("machines/school-lathe.machine",
               "# our lathe\n"
               "base = fanuc\n"
               "id = school-lathe\n"
               "name_en = School lathe\n"
               "name_th = เครื่องกลึงของโรงเรียน\n"
               "gcode_system = B\n"
               "max_spindle_rpm = 2500\n"
               "rapid_x = 6000\n");
  const std::vector<std::string> folders = machineFolders(folder.path());
  ASSERT_EQ(folders.size(), 1u);
  EXPECT_TRUE(loadMachineFolders(folders).empty());
  gcode::Dialect school{};
  ASSERT_TRUE(gcode::parseDialectId("school-lathe", school));
  const gcode::MachineProfile& p = gcode::machineProfile(school);
  EXPECT_EQ(p.nameTh, "เครื่องกลึงของโรงเรียน");
  EXPECT_EQ(p.system, gcode::GcodeSystem::B);

  // Its machine.cfg keys win over the setup's; the others keep the setup's.
  MachineSetup setup = testing::testSetup();
  setup.machine.rapidZ = 9000.0;
  setup.machine = withMachineKeys(setup.machine, p);
  EXPECT_DOUBLE_EQ(setup.machine.maxSpindleRpm, 2500.0);
  EXPECT_DOUBLE_EQ(setup.machine.rapidX, 6000.0);
  EXPECT_DOUBLE_EQ(setup.machine.rapidZ, 9000.0);

  EXPECT_TRUE(errorsOf(kSystemB, school).empty());
  RunOptions options;
  options.dialect = school;
  const Timeline t = testing::runText(kSystemB, options, setup);
  ASSERT_FALSE(t.alarm.has_value()) << formatMessage(*t.alarm, Lang::En);
  // G92 S3000 clamps at 3000, but the machine's own limit is 2500 rpm.
  EXPECT_FALSE(t.moves.empty());
}

TEST(MachineFiles, BrokenMachineCfgKeyIsLocated) {
  const testing::ScratchFolder folder{"machines", "machines"};
  const std::string file = folder.write("bad.machine",
                                        "base = fanuc\n"
                                        "id = bad\n"
                                        "\n"
                                        "rapid_x = -4000\n"
                                        "rapid_y = 10\n");
  const MachineFileResult r = readMachineFile(file);
  EXPECT_FALSE(r.machine.has_value());
  ASSERT_EQ(r.diagnostics.size(), 2u);
  EXPECT_EQ(r.diagnostics[0].code, codes::kParameterNotPositive);
  EXPECT_EQ(r.diagnostics[0].range.line, 4);
  EXPECT_EQ(r.diagnostics[0].range.column, 11);
  EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::En), file + ": rapid_x must be greater than 0 (-4000)");
  EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::Th), file + ": rapid_x ต้องมากกว่า 0 (-4000)");
  EXPECT_EQ(r.diagnostics[1].code, codes::kUnknownParameter);
  EXPECT_EQ(r.diagnostics[1].range.line, 5);

  std::vector<SetupDiagnostic> why;
  EXPECT_FALSE(resolveMachine(file, why).has_value());
  EXPECT_EQ(why.size(), 2u);
  why.clear();
  EXPECT_FALSE(resolveMachine("no-such-lathe", why).has_value());
  ASSERT_EQ(why.size(), 1u);
  EXPECT_EQ(why[0].diagnostic.code, codes::kUnknownMachine);
}

// Issue 27 acceptance: the system-B course program checks clean and runs with
// the same trace as its system-A twin; read as system A it gets the offer of
// the system-B machine.
TEST(MachineFiles, SystemBProgramRunsAsItsSystemATwin) {
  gcode::Dialect romi{};
  ASSERT_TRUE(gcode::parseDialectId("romi-gl240m", romi));
  const auto bErrors = errorsOf(kSystemB, romi);
  EXPECT_TRUE(bErrors.empty()) << bErrors[0].code << " line " << bErrors[0].range.line << ": "
                               << formatMessage(bErrors[0], Lang::En);
  const auto aErrors = errorsOf(kSystemA, gcode::Dialect::Fanuc);
  EXPECT_TRUE(aErrors.empty()) << aErrors[0].code << " line " << aErrors[0].range.line << ": "
                               << formatMessage(aErrors[0], Lang::En);
  const std::string b = traceOf(kSystemB, romi);
  const std::string a = traceOf(kSystemA, gcode::Dialect::Fanuc);
  EXPECT_GT(std::count(a.begin(), a.end(), '\n'), 50);
  EXPECT_EQ(b, a);
  // Read as system A, the program has errors and another machine accepts it.
  EXPECT_FALSE(errorsOf(kSystemB, gcode::Dialect::Fanuc).empty());
}

// Issue 27 acceptance: the course program cuts its part (Ø30 to 0.01 mm, the
// M20x1.5 thread) and, read as system A, is offered the system-B machine at its
// first G95 (line 3); a program whose first system-B form is G92 S gets the offer there.
TEST(MachineFiles, SystemBProgramCutsItsPartAndIsOfferedTheRomi) {
  gcode::Dialect romi{};
  ASSERT_TRUE(gcode::parseDialectId("romi-gl240m", romi));
  RunOptions options;
  options.dialect = romi;
  // The shipped setup: its tools have their bitmaps, which the cut draws.
  const MachineSetup setup = loadMachineSetup(KLUENG_SOURCE_DIR).setup;
  const Timeline t = testing::runText(kSystemB, options, setup);
  ASSERT_FALSE(t.alarm.has_value());
  cut::CutSimulator sim(t, cut::CutSetup::from(io::JobHeader{}, setup));
  sim.runToEnd();
  EXPECT_FALSE(sim.stoppingAlarm().has_value())
      << formatMessage(*sim.stoppingAlarm(), Lang::En) << " line " << sim.stoppingAlarm()->range.line;
  const cut::PartFeatures part = cut::partFeatures(sim.stock());
  bool d30 = false;
  std::vector<double> roots;  // the thread's roots: Ø18 (the G91 G33 pass at 24 - 6), right to left
  for (const cut::PartFeature& f : part.outside) {
    if (f.kind != cut::FeatureKind::Cylinder) continue;
    if (std::abs(f.diameter - 30.0) < 0.01) {
      // Z-40 to Z-25 less what the 0.8 mm nose leaves in the corners (the program has no G42).
      d30 = true;
      EXPECT_GT(f.zLeft, -40.01);
      EXPECT_LT(f.zRight, -24.0);
    }
    if (std::abs(f.diameter - 18.0) < 0.01) roots.push_back(f.zLeft);  // the first is cut short by the face at Z-1
  }
  EXPECT_TRUE(d30);
  // The thread M20x1.5 to Z-13: a root every 1.5 mm (the pitch), to 0.01 mm.
  ASSERT_GE(roots.size(), 8u);
  std::sort(roots.begin(), roots.end(), std::greater<>());
  for (std::size_t k = 1; k < roots.size(); ++k) EXPECT_NEAR(roots[k - 1] - roots[k], 1.5, 0.01) << k;

  const auto offer = [](const std::string& text) {
    gcode::CheckOptions asA;
    asA.dialect = gcode::Dialect::Fanuc;
    const gcode::Program p = gcode::parse(text, 1);
    return gcode::suggestDialect(p, asA, gcode::check(p, asA));
  };
  const auto fromG95 = offer(kSystemB);
  ASSERT_TRUE(fromG95.has_value());
  EXPECT_EQ(fromG95->dialect, romi);
  EXPECT_EQ(fromG95->note.range.line, 3);  // G90 G95 G21;
  const std::string g92Program =
      "O0001;\nG21;\nG92 S2500;\nT0101;\nG96 S200 M03;\nG00 X52. Z2.;\nG01 X48. F0.2;\n"
      "Z-20.;\nG00 X100. Z100.;\nM30;\n";
  const auto fromG92 = offer(g92Program);
  EXPECT_TRUE(errorsOf(g92Program, romi).empty());
  // In system A, G92 is the threading cycle: without its end point it moves nothing and sets
  // the speed. No manual says the control stops: W115 at the G92, never an error (issue 38).
  EXPECT_TRUE(errorsOf(g92Program, gcode::Dialect::Fanuc).empty());
  gcode::CheckOptions fanucA;
  fanucA.dialect = gcode::Dialect::Fanuc;
  const std::vector<Diagnostic> asA = gcode::check(gcode::parse(g92Program, 1), fanucA);
  ASSERT_EQ(asA.size(), 1u);
  EXPECT_EQ(asA[0].code, "W115");
  EXPECT_EQ(asA[0].severity, Severity::Warning);
  EXPECT_EQ(asA[0].range.line, 3);
  EXPECT_EQ(asA[0].range.column, 1);
  EXPECT_EQ(formatMessage(asA[0], Lang::En).substr(0, 60),
            "G92 S2500 in G-code system A selects the threading cycle wit");
  ASSERT_TRUE(fromG92.has_value());
  EXPECT_EQ(fromG92->dialect, romi);
  EXPECT_EQ(fromG92->note.range.line, 3);  // G92 S2500;
}

}  // namespace
}  // namespace klueng::core::machine

// Issue 28 item 4: `simulate --features` and `--part-check` on a G20 program
// write inches (Haas habits: G20, F0.008, Ø1.75 bar); --show-units overrides.
#include <unistd.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include "../scratch_folders.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_units_test {

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

struct Output {
  int exitCode = -1;
  std::string out;  // stdout and stderr, in that order of arrival
};

Output cli(const std::string& args) {
  const std::string command =
      "env LC_ALL= LC_MESSAGES= LANG=C '" KLUENG_CLI_PATH "' " + args + " --config '" KLUENG_SOURCE_DIR "' 2>&1";
  Output r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.out.append(buf, n);
  const int status = ::pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

fs::path write(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("klueng_cli_units_test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// Ø1.75 × 3 bar; the profile's last pass leaves Ø1.500 to Z-1.0 after a 0.050″ chamfer,
// without G42: the R0.8 mm nose leaves material in the chamfer (a leftover the check reports).
const std::string kHeader = "Inch shaft\nIN-01\n1018 steel\n01.75\n03\nKlueng tests\n";
const std::string kBody =
    "O01000 (INCH SHAFT)\n"
    "G20 G40 G99 (INCH, FEED PER REV)\n"
    "T0101 (OD TURN)\n"
    "G50 S2000\n"
    "G96 S500 M03\n"
    "G00 X1.85 Z0.1 M08\n"
    "G01 Z0. F0.008\n"
    "X-0.063\n"
    "G00 Z0.1\n"
    "G00 X1.3 Z0.05\n"
    "G01 X1.5 Z-0.05 F0.008\n"
    "Z-1.0\n"
    "X1.8\n"
    "G00 X2.0 Z0.1\n"
    "M09\n"
    "M05\n"
    "M30\n";

TEST(CliUnits, AG20ProgramsFeaturesAreInInches) {
  const fs::path file = write("inch-shaft.txt", kHeader + kBody);
  const Output r = cli("simulate '" + file.string() + "' --features");
  ASSERT_EQ(r.exitCode, 0) << r.out;
  // The bar left whole from the Z-1.0 shoulder; the 0.8 mm (0.0315″) nose's fillet in the corner.
  EXPECT_THAT(r.out, HasSubstr("Cylinder Ø1.7500″, Z-1.0000 to Z-3.0000, length 2.0000″\n"));
  EXPECT_THAT(r.out, HasSubstr("Cylinder Ø1.5000″, Z-0.0316 to Z-0.9685, length 0.9369″\n"));
  EXPECT_THAT(r.out, HasSubstr("Arc R0.0315″ fillet, centre Z-0.9685 X1.5630, Z-0.9685 to Z-1.0000\n"));
  // Without G42 the nose rounds the 0.050″ chamfer down to 0.032″ (issue 28: "came out C0.8").
  EXPECT_THAT(r.out, HasSubstr("Chamfer 0.032″ × 45° (0.0316″ × 45°), Ø1.4369″ to Ø1.5000″, Z0.0000 to Z-0.0316\n"));
  EXPECT_THAT(r.out, Not(HasSubstr("Ø38.1")));
  // Thai: the same numbers, Thai words.
  const Output th = cli("simulate '" + file.string() + "' --features --lang th");
  EXPECT_THAT(th.out, HasSubstr("ทรงกระบอก Ø1.7500″ Z-1.0000 ถึง Z-3.0000 ยาว 2.0000″\n"));
  // --show-units mm: the millimetre texts of the same part.
  const Output mm = cli("simulate '" + file.string() + "' --features --show-units mm");
  EXPECT_THAT(mm.out, HasSubstr("Cylinder Ø44.45, Z-25.4 to Z-76.2, length 50.8\n"));
  EXPECT_THAT(mm.out, HasSubstr("Chamfer C0.8 (0.801 × 45°)"));
  // An mm program says mm with no option, an inch override says inches.
  const fs::path metric = write("metric-shaft.txt",
                                "Metric shaft\nShaft MS-01\nSteel\n150\n1100\nKlueng tests\nG21 G99\nT0101\n"
                                "G97 S1000 M03\nG00 X52. Z0.\nG01 X-1.6 F0.2\nG00 X60. Z5.\nM30\n");
  EXPECT_THAT(cli("simulate '" + metric.string() + "' --features").out,
              HasSubstr("Cylinder Ø50, Z0 to Z-100, length 100\n"));
  EXPECT_THAT(cli("simulate '" + metric.string() + "' --features --show-units inch").out,
              HasSubstr("Cylinder Ø1.9685″, Z0.0000 to Z-3.9370, length 3.9370″\n"));
}

// The --profile CSV names its unit in the header and stays in millimetres on a G20 program
// (a machine reads it, so it has one unit; issue 30 item 5): the Ø1.500″ neck is 38.1 mm.
TEST(CliUnits, AG20ProgramsProfileIsInMillimetres) {
  const fs::path file = write("inch-profile.txt", kHeader + kBody);
  const fs::path csv = write("inch-profile.csv", "");
  const Output r = cli("simulate '" + file.string() + "' --profile '" + csv.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.out;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "z,x_outer,x_inner");
  bool neck = false, bar = false;
  while (std::getline(in, line)) {
    double z = 0, outer = 0, inner = 0;
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &z, &outer, &inner) != 3) continue;
    if (z < -5.0 && z > -20.0) neck = neck || std::abs(outer - 38.1) < 0.01;  // Ø1.500″ to Z-1.0″
    if (z < -30.0 && z > -70.0) bar = bar || std::abs(outer - 44.45) < 0.01;  // the Ø1.75″ bar
  }
  EXPECT_TRUE(neck);
  EXPECT_TRUE(bar);
}

// A pawn's neck in inches (Haas habits): down a 15° slope on line 14 the 80° CNMG's
// trailing edge gouges the Ø0.920 neck; the warning speaks inches on a G20 program.
TEST(CliUnits, AG20ProgramsPartCheckIsInInches) {
  const fs::path file = write("inch-pawn.txt",
                              "Pawn neck\nPawn P-1\nBrass\n01.0\n06\nKlueng tests\n"
                              "O01100 (PAWN NECK)\n"
                              "G20 G40 G99\n"
                              "T0101\n"
                              "G97 S1200 M03\n"
                              "G00 X1.1 Z0.1\n"
                              "G42 G01 X1.0 Z0. F0.004\n"
                              "G01 Z-0.4\n"
                              "X0.92 Z-0.5493\n"
                              "Z-0.8\n"
                              "X1.0 Z-0.84\n"
                              "Z-1.6\n"
                              "X1.1\n"
                              "G40 G00 X2.5 Z0.8\n"
                              "M30\n");
  const Output r = cli("simulate '" + file.string() + "' --part-check --tool 1=cnmg-80-r08");
  EXPECT_EQ(r.exitCode, 0) << r.out;
  // One gouge, the same numbers as the mm text below (0.463 mm = 0.0182″, Z-6.200 = Z-0.2441 ...).
  EXPECT_THAT(r.out, HasSubstr(file.string() + ":14:1: warning W320: Gouge 0.0182 in deep from Z-0.2441 to Z-0.5335 "
                                               "(deepest at Z-0.4045, Ø0.9976): "));
  const Output th = cli("simulate '" + file.string() + "' --part-check --tool 1=cnmg-80-r08 --lang th");
  EXPECT_THAT(th.out, HasSubstr(" นิ้ว จาก Z-0.")) << th.out;
  const Output mm = cli("simulate '" + file.string() + "' --part-check --tool 1=cnmg-80-r08 --show-units mm");
  EXPECT_THAT(mm.out, HasSubstr(":14:1: warning W320: Gouge 0.463 mm deep from Z-6.200 to Z-13.550 "
                                "(deepest at Z-10.275, Ø25.338): "));
  // What G41/G42 change, in the program's units: the 45° rise keeps 0.8(√2-1) = 0.33 mm = 0.0130″.
  const Output compare = cli("simulate '" + file.string() + "' --compare-compensation none");
  EXPECT_THAT(compare.out, HasSubstr(":16:1: note: taper 44.98° line 16: 0.0130 in short without compensation"));
  const Output compareMm = cli("simulate '" + file.string() + "' --compare-compensation none --show-units mm");
  EXPECT_THAT(compareMm.out, HasSubstr(":16:1: note: taper 44.98° line 16: 0.33 mm short without compensation"));
  const Output bad = cli("simulate '" + file.string() + "' --show-units feet");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_THAT(bad.out, HasSubstr("--show-units"));
}

}  // namespace

}  // namespace cli_units_test

// Its scratch folders go with the process: nothing left in /tmp after a run.
[[maybe_unused]] ::testing::Environment* const kCliUnitsScratchCleanup =
    klueng::test::removeScratchFoldersAtExit({"klueng_cli_units_test-"});

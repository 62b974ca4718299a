// klueng-cli simulate's cut outputs, end to end: --png --profile --json --svg
// --dxf --resolution, and stock alarms (A3xx) with their block.
#include <unistd.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "klueng/core/io/image.h"
#include "../scratch_folders.h"

#include "cli_shell.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_simulate_cut_test {

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kCut = KLUENG_CLI_PATH;
const std::string kCutSamples = KLUENG_SAMPLES_DIR;
const std::string kCutShipped = KLUENG_SOURCE_DIR;

struct Result {
  int exitCode = -1;
  std::string err;
};

// Runs `klueng-cli SUBCOMMAND` with stderr captured (and stdout too where `keepStdout`).
Result runCli(const std::string& subcommand, const std::string& args, const std::string& config, bool keepStdout) {
  std::string command = "env LC_ALL= LC_MESSAGES= LANG=C " + klueng::test::shellQuote(kCut) + " " + subcommand + " " +
                        args + " --config " + klueng::test::shellQuote(config);
  if (!keepStdout) command = "{ " + command + " >/dev/null; }";
  Result r;
  r.exitCode = klueng::test::runShell(command, r.err);
  return r;
}

// Runs klueng-cli simulate with stderr captured (stdout discarded).
Result simulate(const std::string& args, const std::string& config = kCutShipped) {
  return runCli("simulate", args, config, false);
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("klueng_cli_cut_test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

// Outer diameter in the profile CSV at the row nearest to z.
double diameterAt(const std::string& csv, double z) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  double best = 1e9, value = -1;
  while (std::getline(in, line)) {
    double rz, outer, inner;
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &rz, &outer, &inner) != 3) continue;
    if (std::abs(rz - z) < best) {
      best = std::abs(rz - z);
      value = outer;
    }
  }
  return value;
}

TEST(CliSimulateCut, Sample01WritesEveryOutput) {
  const fs::path png = scratch("01.png"), csv = scratch("01.csv"), json = scratch("01.json"), svg = scratch("01.svg"),
                 dxf = scratch("01.dxf");
  const Result r =
      simulate("'" + kCutSamples + "/01-step-shaft.txt' --png '" + png.string() + "' --profile '" + csv.string() +
               "' --json '" + json.string() + "' --svg '" + svg.string() + "' --dxf '" + dxf.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string image = slurp(png);
  ASSERT_GT(image.size(), 24u);
  EXPECT_EQ(image.substr(1, 3), "PNG");
  const std::string profile = slurp(csv);
  EXPECT_EQ(profile.substr(0, 18), "z,x_outer,x_inner\n");
  EXPECT_NEAR(diameterAt(profile, -10.0), 30.0, 0.01);
  EXPECT_NEAR(diameterAt(profile, -30.0), 40.0, 0.01);
  EXPECT_NEAR(diameterAt(profile, -50.0), 46.0, 0.01);
  EXPECT_NEAR(diameterAt(profile, 0.0), diameterAt(profile, -0.025), 1e-9);  // the face row
  const std::string summary = slurp(json);
  EXPECT_THAT(summary, HasSubstr("\"completed\": true"));
  EXPECT_THAT(summary, HasSubstr("\"alarms\": []"));
  EXPECT_THAT(summary, HasSubstr("\"diameter_mm\": 50.0000, \"length_mm\": 100.0000"));
  EXPECT_THAT(summary, HasSubstr("\"resolution_mm\": 0.0500"));
  EXPECT_THAT(slurp(svg), HasSubstr("<svg"));
  EXPECT_THAT(slurp(dxf), HasSubstr("ENTITIES"));
}

// A full disk (/dev/full) is reported, never taken for success; an existing output
// file is replaced whole or not at all (written beside it, then renamed).
TEST(CliSimulateCut, AFullDiskIsReportedAndAnOldOutputSurvives) {
  const Result full = simulate("'" + kCutSamples + "/01-step-shaft.txt' --png /dev/full");
  EXPECT_EQ(full.exitCode, 2);  // a failed output is exit 2 (issue 29)
  EXPECT_THAT(full.err, HasSubstr("/dev/full"));
  EXPECT_THAT(full.err, HasSubstr("the disk is full"));
  EXPECT_TRUE(fs::is_character_file("/dev/full"));

  const fs::path png = scratch("kept.png");
  { std::ofstream(png) << "old picture"; }
  const Result bad = simulate("'" + kCutSamples + "/no-such-file.txt' --png '" + png.string() + "'");
  EXPECT_NE(bad.exitCode, 0);
  EXPECT_EQ(slurp(png), "old picture");
  ASSERT_EQ(simulate("'" + kCutSamples + "/01-step-shaft.txt' --png '" + png.string() + "'").exitCode, 0);
  EXPECT_EQ(slurp(png).substr(1, 3), "PNG");
  for (const auto& e : fs::directory_iterator(png.parent_path()))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

// Without its picture module beside it, klueng-cli says so in the run's language
// (issue 30 item 5: the Thai text carried the English reason) and keeps the old picture.
TEST(CliSimulateCut, AMissingPictureModuleIsSaidInEitherLanguage) {
  const fs::path bin = scratch("lonely") / "bin";
  fs::create_directories(bin);
  const fs::path cli = bin / "klueng-cli";
  fs::copy_file(kCut, cli, fs::copy_options::overwrite_existing);
  const fs::path png = scratch("lonely-part.png");
  { std::ofstream(png) << "old picture"; }
  const auto run = [&](const std::string& lang) {
    const std::string command = "env LC_ALL= LC_MESSAGES= LANG=C '" + cli.string() + "' simulate '" + kCutSamples +
                                "/01-step-shaft.txt' --png '" + png.string() + "' --lang " + lang + " --config '" +
                                kCutShipped + "' 2>&1 >/dev/null";
    Result r;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return r;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.err.append(buf, n);
    const int status = ::pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
  };
  const Result en = run("en");
  EXPECT_EQ(en.exitCode, 2);
  EXPECT_THAT(en.err, HasSubstr(png.string() + ": error F108: " + png.string() +
                                ": cannot write the file (the picture module klueng-png.so is not installed beside " +
                                cli.string() + ")"));
  const Result th = run("th");
  EXPECT_EQ(th.exitCode, 2);
  EXPECT_THAT(th.err, HasSubstr("(ไม่ได้ติดตั้งโมดูลวาดภาพ klueng-png.so ไว้คู่กับ " + cli.string() + ")"));
  EXPECT_THAT(th.err, Not(HasSubstr("not installed")));
  EXPECT_EQ(slurp(png), "old picture");
}

// --png is drawn by the screen's painters (render/, through the picture module):
// the bar in the stock colour between the chuck's jaws, the chuck, the centre line.
TEST(CliSimulateCut, ThePngIsTheScreensSection) {
  const fs::path png = scratch("section.png");
  ASSERT_EQ(simulate("'" + kCutSamples + "/01-step-shaft.txt' --png '" + png.string() + "'").exitCode, 0);
  const auto image = klueng::core::io::readImage(png.string());
  ASSERT_TRUE(image.value);
  const auto& img = *image.value;
  EXPECT_TRUE(img.width == 2400 || img.height == 1600) << img.width << "x" << img.height;
  EXPECT_LE(img.width, 2400);
  EXPECT_LE(img.height, 1600);
  // render::palette(): stock fill (176,190,204), chuck (90,90,96), background (250,250,247).
  std::size_t stock = 0, chuck = 0, background = 0;
  for (std::uint32_t p : img.pixels) {
    stock += p == 0xB0BECCu;
    chuck += p == 0x5A5A60u;
    background += p == 0xFAFAF7u;
  }
  EXPECT_GT(stock, img.pixels.size() / 20);
  EXPECT_GT(chuck, img.pixels.size() / 100);
  EXPECT_GT(background, img.pixels.size() / 4);
  // The part is symmetric about the centre line (the row with most of its red):
  // a column through the bar has as much stock above that row as below it (the
  // tool path is drawn on the upper half only, so only columns clear of it count).
  int centre = 0, most = 0;
  for (int y = 0; y < img.height; ++y) {
    int red = 0;
    for (int col = 0; col < img.width; ++col) {  // anti-aliased: reddish, not exactly (200,40,40)
      const std::uint32_t p = img.at(col, y);
      red += (p >> 16) > 150 && ((p >> 8) & 0xFF) < 150 && (p & 0xFF) < 150;
    }
    if (red > most) most = red, centre = y;
  }
  ASSERT_GT(most, img.width / 4);
  int x = 0;
  for (int col = 0; col < img.width && x == 0; ++col)
    if (img.at(col, centre + 5) == 0xB0BECCu) x = col;
  ASSERT_GT(x, 0);
  int above = 0, below = 0;
  for (int y = 0; y < img.height; ++y)
    if (img.at(x + 5, y) == 0xB0BECCu) (y < centre ? above : below)++;
  EXPECT_GT(above, img.height / 10);
  EXPECT_NEAR(above, below, 3);
}

TEST(CliSimulateCut, ResolutionSetsTheColumnWidth) {
  const fs::path csv = scratch("01-coarse.csv");
  ASSERT_EQ(
      simulate("'" + kCutSamples + "/01-step-shaft.txt' --resolution 0.5 --profile '" + csv.string() + "'").exitCode,
      0);
  const std::string profile = slurp(csv);
  const long rows = std::count(profile.begin(), profile.end(), '\n');
  EXPECT_EQ(rows, 1 + 200 + 2);  // header, 100 mm / 0.5, both faces
  EXPECT_EQ(simulate("'" + kCutSamples + "/01-step-shaft.txt' --resolution zero").exitCode, 2);
  EXPECT_EQ(simulate("'" + kCutSamples + "/01-step-shaft.txt' --resolution 0").exitCode, 2);
}

TEST(CliSimulateCut, RapidIntoTheStockStopsWithItsBlock) {
  const fs::path program = scratch("crash.txt");
  std::ofstream(program) << "Crash\nPart\nSteel\n150\n1100\nKlueng tests\n"
                            "N10 G21 G97 S800 M03\nN20 T0101\nN30 G00 X60. Z40.\nN40 G00 X40. Z-10.\nN50 M30\n";
  const fs::path json = scratch("crash.json");
  const Result r = simulate("'" + program.string() + "' --json '" + json.string() + "'");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_THAT(r.err, HasSubstr("crash.txt:10:1: alarm A301"));
  EXPECT_THAT(r.err, HasSubstr("X40.000"));
  EXPECT_THAT(slurp(json), HasSubstr("\"completed\": false"));
  EXPECT_THAT(slurp(json), HasSubstr("\"code\": \"A301\""));
  // --no-stock: the interpreter alone finds nothing wrong.
  EXPECT_EQ(simulate("'" + program.string() + "' --no-stock").exitCode, 0);
}

TEST(CliSimulateCut, Sample05StopsOnN40) {
  const Result r = simulate("'" + kCutSamples + "/05-runtime-alarms.txt'");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_THAT(r.err, HasSubstr("05-runtime-alarms.txt:12:"));
}

}  // namespace

namespace {

// Issue 10: --part-check prints gouges and leftovers GCC-style on their block.
// A pawn's neck down a 15° slope (N70, line 14): the 80° CNMG's trailing edge
// (7°) cuts into it, the 35° VNMG's (52°) does not.
TEST(CliPartCheck, ThePawnsNeckGougesWithThe80DegreeInsertOnly) {
  const fs::path file = fs::temp_directory_path() / ("klueng_cli_pawn_neck-" + std::to_string(::getpid()) + ".nc");
  std::ofstream(file) << "Pawn neck\nPawn P-1\nBrass\n124\n160\nKlueng tests\nO0100\nN10 G21 G40 G99\nN20 T0101\n"
                         "N30 G97 S1200 M03\nN40 G00 X28. Z2.\nN50 G42 G01 X24. Z0. F0.1\nN60 G01 Z-10.\n"
                         "N70 X22. Z-13.732\nN80 Z-20.\nN90 X24. Z-22.\nN100 Z-40.\nN110 X28.\n"
                         "N120 G40 G00 X60. Z20.\nN130 M30\n";
  const Result cnmg = simulate("'" + file.string() + "' --part-check --tool 1=cnmg-80-r08");
  EXPECT_EQ(cnmg.exitCode, 0) << cnmg.err;  // a gouge is a warning: the program ran
  EXPECT_THAT(cnmg.err, HasSubstr(file.string() + ":14:1: warning W320: Gouge 0.4"));
  const Result vnmg = simulate("'" + file.string() + "' --part-check --tool 1=vnmg-35-r02");
  EXPECT_EQ(vnmg.exitCode, 0) << vnmg.err;
  EXPECT_EQ(vnmg.err.find("W320"), std::string::npos) << vnmg.err;
  const Result thai = simulate("'" + file.string() + "' --part-check --tool 1=cnmg-80-r08 --lang th");
  EXPECT_THAT(thai.err, HasSubstr("มีดตัดกินเนื้อชิ้นงานเกินแบบ"));
  fs::remove(file);
}

// Issue 28 item 1: the part check holds the cut to the programmed path, so a
// wrong offset row and a missing G41/G42 show — given with --config's own rows.
TEST(CliPartCheck, AWrongTipRowAndAMissingCompensationShowOnTheirBlocks) {
  const fs::path config = fs::temp_directory_path() / ("klueng_cli_wrong_tip-" + std::to_string(::getpid()));
  fs::remove_all(config);
  fs::create_directories(config);
  for (const char* f : {"tools.cfg", "machine.cfg"}) fs::copy_file(fs::path(KLUENG_SOURCE_DIR) / f, config / f);
  {
    std::ifstream in(fs::path(KLUENG_SOURCE_DIR) / "offset.cfg");
    std::ofstream out(config / "offset.cfg");
    std::string line;
    for (int row = 1; std::getline(in, line); ++row) out << (row == 3 ? "0 0 0 7" : line) << "\n";
  }
  fs::create_directory_symlink(fs::path(KLUENG_SOURCE_DIR) / "resources", config / "resources");
  const Result thread = simulate("'" + kCutSamples + "/02-thread.txt' --part-check", config.string());
  EXPECT_EQ(thread.exitCode, 0) << thread.err;
  EXPECT_THAT(thread.err, HasSubstr("02-thread.txt:21:1: warning W320: Gouge 7.750 mm deep from Z0.000"));

  const fs::path file = fs::temp_directory_path() / ("klueng_cli_no_g42-" + std::to_string(::getpid()) + ".txt");
  std::ifstream in(kCutSamples + "/01-step-shaft.txt");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("G42 "), 4, "");
  std::ofstream(file) << text;
  const Result fat = simulate("'" + file.string() + "' --part-check");
  EXPECT_EQ(fat.exitCode, 0) << fat.err;
  EXPECT_THAT(fat.err, HasSubstr(file.string() + ":43:1: warning W321: Material left 0.469 mm from Z0.000 to Z-3.000"));
  EXPECT_THAT(fat.err,
              HasSubstr(file.string() + ":49:1: warning W321: Material left 0.469 mm from Z-40.000 to Z-41.000"));
  fs::remove(file);
}

TEST(CliPartCheck, SamplesAreCleanAndAnAlarmedRunSaysWhatWasChecked) {
  const Result clean = simulate("'" + kCutSamples + "/01-step-shaft.txt' --part-check");
  EXPECT_EQ(clean.exitCode, 0);
  EXPECT_EQ(clean.err.find("W32"), std::string::npos) << clean.err;
  const Result alarmed = simulate("'" + kCutSamples + "/05-runtime-alarms.txt' --part-check");
  EXPECT_EQ(alarmed.exitCode, 1);
  EXPECT_THAT(alarmed.err, HasSubstr("note I324: The run stopped on alarm A104"));
}

// Issue 39: --cutting-data writes one row per cutting block with its units in the column names, prints the
// teacher's warnings on their blocks (never an error: exit 0), and is refused (F126) when it names an input.
TEST(CliCuttingData, WritesPerBlockAndWarnsOnTheBlock) {
  const fs::path config = scratch("cd-config");
  fs::create_directories(config);
  for (const char* name : {"offset.cfg", "machine.cfg"})
    fs::copy_file(kCutShipped + "/" + name, config / name, fs::copy_options::overwrite_existing);
  std::ofstream(config / "tools.cfg") << "library:cnmg-80-r08\n\n\n\n\n\n\n\n";
  std::ofstream(config / "machine.cfg", std::ios::app) << "spindle_power_kw = 1.5\n";
  const fs::path prog = scratch("cd.nc"), csv = scratch("cd.csv");
  const std::string moves =
      "G21 G40 G99\nT0101\nG97 S1000 M03\nG00 X60. Z2.\nX46.\nG01 Z-30. F0.2\nG00 X60.\nZ50.\nM30\n";
  std::ofstream(prog) << "Cutting data\nSteel\nSteel S45C\n150\n1100\nTest\n" << moves;
  const Result r = simulate("'" + prog.string() + "' --cutting-data '" + csv.string() + "'", config.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  // 2.06 kW at the edge (the hand calculation of cutting_data_test.cpp) on a 1.5 kW spindle.
  EXPECT_THAT(r.err, HasSubstr(prog.string() + ":12:1: warning W334: this cut needs 2.1 kW at the edge"));
  EXPECT_THAT(r.err, Not(HasSubstr("W330")));  // 145 m/min: inside coated carbide's range in S45C
  const std::string rows = slurp(csv);
  EXPECT_THAT(rows, HasSubstr("line,file,tool,t_start_s,t_end_s,moves,diameter_mm,rpm,vc_m_min,f_mm_rev,ap_mm,"));
  EXPECT_THAT(rows, HasSubstr("\n12,0,1,"));
  EXPECT_THAT(rows, HasSubstr(",46.00,1000,145,0.200,2.00,"));
  EXPECT_THAT(rows, HasSubstr(",W334\n"));
  // Naming the program as the output: refused, the program kept.
  const std::string before = slurp(prog);
  const Result refused = simulate("'" + prog.string() + "' --cutting-data '" + prog.string() + "'", config.string());
  EXPECT_EQ(refused.exitCode, 2) << refused.err;
  EXPECT_THAT(refused.err, HasSubstr("error F126"));
  EXPECT_EQ(slurp(prog), before);
  // A material the table does not know is said once, with the list.
  std::ofstream(prog) << "Cutting data\nSteel\nUnobtainium\n150\n1100\nTest\n" << moves;
  const Result unknown = simulate("'" + prog.string() + "' --cutting-data '" + csv.string() + "'", config.string());
  EXPECT_EQ(unknown.exitCode, 0) << unknown.err;
  EXPECT_THAT(unknown.err, HasSubstr("note I330: material 'Unobtainium' is not in materials.cfg"));
  EXPECT_THAT(unknown.err, HasSubstr("known materials: ss400, s45c,"));
}

// Runs `klueng-cli check` with stdout and stderr captured.
Result checkCommand(const std::string& args, const std::string& config) { return runCli("check", args, config, true); }

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Issue 39 item 1: the plain check says the cutting-data warnings on their blocks, in both
// languages and in --json, from the run it records; simulate says each once; --design gives
// W332 the part's roughness mark.
TEST(CliCuttingData, TheCheckSaysThemOnTheirBlocks) {
  const fs::path config = scratch("cc-config");
  fs::create_directories(config);
  for (const char* name : {"offset.cfg", "machine.cfg"})
    fs::copy_file(kCutShipped + "/" + name, config / name, fs::copy_options::overwrite_existing);
  std::ofstream(config / "tools.cfg") << "library:cnmg-80-r08\n\n\n\n\n\n\n\n";
  std::ofstream(config / "machine.cfg", std::ios::app) << "spindle_power_kw = 1.5\n";
  const fs::path prog = scratch("cc.nc");
  std::ofstream(prog) << "Cutting data\nSteel\nSteel S45C\n150\n1100\nTest\n"
                         "G21 G40 G99\nT0101\nG97 S1000 M03\nG00 X60. Z2.\nX46.\nG01 Z-30. F0.2\nG00 X60.\n"
                         "Z2.\nX45.4\nG01 Z-30. F0.25\nG00 X60.\nZ50.\nM30\n";
  const Result r = checkCommand("'" + prog.string() + "'", config.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;  // warnings: the real control runs the program
  EXPECT_THAT(r.err, HasSubstr(prog.string() + ":12:1: warning W334: this cut needs 2.1 kW at the edge (depth 2.00 "
                                               "mm, feed 0.200 mm/rev) but the spindle gives 1.5 kW"));
  // Line 16 takes 0.3 mm at 0.25 mm/rev: Ra 2.44 um, within the default 3.2, and 0.5 kW: sound.
  EXPECT_THAT(r.err, Not(HasSubstr(":16:1: warning W33")));
  const Result th = checkCommand("'" + prog.string() + "' --lang th", config.string());
  EXPECT_THAT(th.err, HasSubstr(":12:1: คำเตือน W334: การตัดนี้ต้องใช้กำลัง 2.1 กิโลวัตต์ที่คมมีด"));
  const Result json = checkCommand("'" + prog.string() + "' --json", config.string());
  EXPECT_THAT(json.err, HasSubstr("\"line\": 12, \"column\": 1, \"severity\": \"warning\", \"code\": \"W334\""));
  // The design asks Ra 1.6 on the Ø45.4: line 16's 2.44 um is too rough for it.
  const fs::path part = scratch("cc.json");
  std::ofstream(part) << "{ \"name\": \"Shaft\", \"material\": \"steel\", \"stock\": { \"diameter\": 50, "
                         "\"length\": 100 }, \"outside\": [ { \"cylinder\": 45.4, \"length\": 30, "
                         "\"roughness\": 1.6 } ] }\n";
  const Result marked = checkCommand("'" + prog.string() + "' --design '" + part.string() + "'", config.string());
  EXPECT_THAT(marked.err, HasSubstr(":16:1: warning W332: finishing feed 0.250 mm/rev with nose radius R0.80 leaves "
                                    "Ra 2.4 um (Rz 9.8 um), rougher than Ra 1.6 um (the drawing's mark for diameter "
                                    "45.40 from Z0.00 to Z-30.00)"))
      << marked.err;
  // simulate says the check's warnings once, --cutting-data or not.
  const Result sim =
      simulate("'" + prog.string() + "' --cutting-data '" + scratch("cc.csv").string() + "'", config.string());
  EXPECT_EQ(occurrences(sim.err, "warning W334"), 1u) << sim.err;
}

}  // namespace

}  // namespace cli_simulate_cut_test

// Its scratch folders go with the process: nothing left in /tmp after a run.
[[maybe_unused]] ::testing::Environment* const kCliSimulateCutScratchCleanup =
    klueng::test::removeScratchFoldersAtExit({"klueng_cli_cut_test-", "klueng_cli_wrong_tip-"});

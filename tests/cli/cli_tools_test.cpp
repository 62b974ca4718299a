// klueng-cli and tools from the program: notes, --tool accepted and refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_tools_test {

namespace {

using ::testing::HasSubstr;
using ::testing::Not;

const std::string kCli = KLUENG_CLI_PATH;

struct CliResult {
  int exitCode = -1;
  std::string out;  // stdout and stderr together
};

CliResult run(const std::string& args, const std::string& lang = "C") {
  const std::string command = "env LC_ALL= LC_MESSAGES= LANG=" + lang + " '" + kCli + "' " + args + " 2>&1";
  CliResult r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[65536];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, n);
  const int status = ::pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// This process's folder of test programs, removed when the tests end.
const std::filesystem::path& testFolder() {
  struct Folder {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("klueng-cli-tools-" + std::to_string(::getpid()));
    ~Folder() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Folder folder;
  return folder.path;
}

std::string writeProgram(const std::string& name, const std::string& text) {
  const auto& dir = testFolder();
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// A Fanuc program with a cut-off tool at station 10, which the shipped tools.cfg leaves empty.
const char* kProgram =
    "O0010\n"             // 1
    "G21 G40 G99\n"       // 2
    "T0101 (OD ROUGH)\n"  // 3
    "G97 S800 M03\n"      // 4
    "G00 X52. Z2.\n"      // 5
    "G01 Z-30. F0.2\n"    // 6
    "G00 X60. Z2.\n"      // 7
    "(CUT OFF)\n"         // 8
    "T1010\n"             // 9
    "G97 S500 M03\n"      // 10
    "G00 X55. Z-43.\n"    // 11
    "G01 X-1. F0.05\n"    // 12
    "G00 X60.\n"          // 13
    "M05\n"               // 14
    "M30\n";              // 15

TEST(CliTools, CheckPrintsTheChoiceAsANoteAndAcceptsTheStation) {
  const std::string file = writeProgram("cutoff.nc", kProgram);
  const CliResult r = run("check '" + file + "'");
  EXPECT_EQ(r.exitCode, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr(file + ":8:1: note I401: T10 = parting-3mm (comment \"CUT OFF\" on line 8)"));
  EXPECT_THAT(r.out,
              HasSubstr(file + ":8:1: note I410: offset 10 was 0 0 0 0: nose radius 0 and tip 3 of parting-3mm"));
  EXPECT_THAT(r.out, Not(HasSubstr("E305")));
  const CliResult th = run("check '" + file + "' --lang th");
  EXPECT_THAT(th.out, HasSubstr(file + ":8:1: หมายเหตุ I401: T10 = parting-3mm (หมายเหตุ \"CUT OFF\" ในบรรทัดที่ 8)"));
}

TEST(CliTools, ToolOptionOverridesAStationForThisRun) {
  const std::string file = writeProgram("cutoff2.nc", kProgram);
  const CliResult r = run("check '" + file + "' --tool 10=grooving-3mm --tool=3=threading-60");
  EXPECT_EQ(r.exitCode, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr(file + ": note I409: T10 = grooving-3mm (set for this job)"));
  EXPECT_THAT(r.out, HasSubstr(file + ": note I409: T03 = threading-60 (set for this job)"));
  EXPECT_THAT(r.out, Not(HasSubstr("parting-3mm (comment")));
  const CliResult sim = run("simulate '" + file + "' --tool 10=parting-3mm --cycle-time --no-stock");
  EXPECT_EQ(sim.exitCode, 0) << sim.out;
  EXPECT_THAT(sim.out, HasSubstr("note I409: T10 = parting-3mm (set for this job)"));
}

TEST(CliTools, SimulateCutsWithTheChosenTool) {
  const std::string file = writeProgram("cutoff3.nc", kProgram);
  const CliResult r = run("simulate '" + file + "' --cycle-time");
  EXPECT_EQ(r.exitCode, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("T10 = parting-3mm"));
}

TEST(CliTools, BadToolValuesExitTwoAndListTheLibrary) {
  const std::string file = writeProgram("cutoff4.nc", kProgram);
  for (const std::string bad : {"3=knurl-30", "13=parting-3mm", "threading-60", "0=threading-60", "x=drill-6mm"}) {
    const CliResult check = run("check '" + file + "' --tool " + bad);
    EXPECT_EQ(check.exitCode, 2) << bad << "\n" << check.out;
    const CliResult sim = run("simulate '" + file + "' --tool " + bad);
    EXPECT_EQ(sim.exitCode, 2) << bad << "\n" << sim.out;
  }
  const CliResult unknown = run("check '" + file + "' --tool 3=knurl-30");
  EXPECT_THAT(unknown.out, HasSubstr("no library tool 'knurl-30'"));
  EXPECT_THAT(unknown.out, HasSubstr("cnmg-80-r08, cnmg-80-r04"));
  EXPECT_THAT(unknown.out, HasSubstr("boring-bar-16"));
  const CliResult off = run("check '" + file + "' --tool 13=parting-3mm");
  EXPECT_THAT(off.out, HasSubstr("station 13 is not on the turret (1 to 12)"));
  const CliResult classic = run("check '" + file + "' --dialect classic --tool 9=parting-3mm");
  EXPECT_EQ(classic.exitCode, 2);
  EXPECT_THAT(classic.out, HasSubstr("(1 to 8)"));
  // In Thai under --lang th, as the rest of the command line (issue 29 item 10).
  const CliResult thai = run("simulate '" + file + "' --lang th --tool 13=parting-3mm");
  EXPECT_EQ(thai.exitCode, 2);
  EXPECT_THAT(thai.out, HasSubstr("klueng-cli simulate: --tool 13=parting-3mm: ป้อมมีดไม่มีตำแหน่ง 13 (มี 1 ถึง 12)\n"));
  EXPECT_THAT(run("check '" + file + "' --tool knurl --lang th").out,
              HasSubstr("--tool ต้องเป็น N=ID (หมายเลขป้อมมีดและมีดในคลังมีด เช่น 3=threading-60) ไม่ใช่ 'knurl'"));
  EXPECT_THAT(
      run("print '" + file + "' --pdf '" + (testFolder() / "never.pdf").string() + "' --tool 3=knurl-30 --lang th").out,
      HasSubstr("--tool 3=knurl-30: ไม่มีมีด 'knurl-30' ในคลังมีด มีดในคลังมีด: cnmg-80-r08"));
}

TEST(CliTools, AStationWithoutEvidenceKeepsE305) {
  const std::string file = writeProgram("idle.nc", "O0011\nT0101\nT1111\nM30\n");
  const CliResult r = run("check '" + file + "'");
  EXPECT_EQ(r.exitCode, 1) << r.out;
  EXPECT_THAT(r.out, HasSubstr(file + ":3:1: error E305"));
  EXPECT_THAT(r.out, Not(HasSubstr(" note I4")));
}

TEST(CliTools, HelpShowsTheToolOption) {
  EXPECT_THAT(run("--help").out, HasSubstr("--tool N=ID"));
  EXPECT_THAT(run("check --help").out, HasSubstr("--tool N=ID"));
}

}  // namespace

}  // namespace cli_tools_test

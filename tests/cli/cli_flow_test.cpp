// klueng-cli with subprograms and macro B (issue 9): subprogram files found in
// the program's folder, the trace's call level and program columns, #500-#999
// kept between runs in the folder's macro_variables.cfg, run notices.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_flow_test {

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

struct CliRun {
  int exitCode = -1;
  std::string out;  // stdout and stderr
};

CliRun runCli(const std::string& args) {
  const std::string command =
      "env LC_ALL= LC_MESSAGES= LANG=C '" + std::string(KLUENG_CLI_PATH) + "' " + args + " 2>&1";
  CliRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[65536];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, n);
  const int status = ::pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

// A fresh folder per test: it is the control's memory.
class CliFlow : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("klueng-cli-flow-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // The user's data folder, where #500-#999 are kept when no --config is given.
    ::setenv("XDG_DATA_HOME", (dir_ / "data").c_str(), 1);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  std::string read(const std::string& name) const {
    std::ifstream in(dir_ / name, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::vector<std::string> traceRows(const std::string& name) const {
    std::vector<std::string> rows;
    std::istringstream in(read(name));
    std::string line;
    while (std::getline(in, line)) rows.push_back(line);
    return rows;
  }
  fs::path dir_;
};

// Main program: two grooves by M98 P1000 L2 from the file O1000.nc beside it.
const char* kMain =
    "O0010 (TWO GROOVES)\n"
    "G21 G99\n"
    "T0101\n"
    "G97 S800 M03\n"
    "G00 X44. Z-8.\n"
    "M98 P1000 L2\n"
    "G00 X100. Z100.\n"
    "M30\n";
const char* kGroove =
    "O1000 (GROOVE AND STEP 10 MM LEFT)\n"
    "G01 X36. F0.05\n"
    "G00 X44.\n"
    "W-10.\n"
    "M99\n";

TEST_F(CliFlow, SubprogramFileFromTheFolderRunsWithItsCallLevel) {
  const std::string main = write("main.nc", kMain);
  write("O1000.nc", kGroove);
  const CliRun run = runCli("simulate " + main + " --stock 40x100 --trace " + (dir_ / "t.csv").string());
  ASSERT_EQ(run.exitCode, 0) << run.out;
  const auto rows = traceRows("t.csv");
  ASSERT_EQ(rows.size(), 1u + 2u + 3u * 2u + 2u) << read("t.csv");
  EXPECT_EQ(rows[0], "kind,line,t_start,t_end,x_start,z_start,x_end,z_end,i,k,dir,feed_mm_min,rpm,level,program");
  // The groove: X44 -> X36 at 0.05 mm/rev * 800 rpm = 40 mm/min, 4 mm on the radius: 6 s,
  // line 2 of O1000.nc, one level down, program O1000.
  EXPECT_THAT(rows[3], HasSubstr("LINE,2,"));
  EXPECT_THAT(rows[3], HasSubstr(",44.0000,-8.0000,36.0000,-8.0000,"));
  EXPECT_THAT(rows[3], HasSubstr(",40.0000,800.0000,1,O1000"));
  // The second pass starts 10 mm further left.
  EXPECT_THAT(rows[6], HasSubstr(",44.0000,-18.0000,36.0000,-18.0000,"));
  EXPECT_THAT(rows[6], HasSubstr(",1,O1000"));
  // Back in the main program.
  EXPECT_THAT(rows.back(), HasSubstr("RAPID,7,"));
  EXPECT_THAT(rows.back(), HasSubstr(",0,O0010"));
}

TEST_F(CliFlow, TheNumberAloneNamesTheFileToo) {
  const std::string main = write("main.nc", kMain);
  write("1000.nc", "G01 X36. F0.05\nG00 X44.\nW-10.\nM99\n");  // no O line: the file name says which program
  const CliRun run = runCli("simulate " + main + " --stock 40x100 --trace " + (dir_ / "t.csv").string());
  ASSERT_EQ(run.exitCode, 0) << run.out;
  EXPECT_EQ(traceRows("t.csv").size(), 11u);
}

TEST_F(CliFlow, AMissingSubprogramIsAnErrorAtItsCall) {
  const std::string main = write("main.nc", kMain);
  const CliRun run = runCli("check " + main);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_THAT(run.out,
              HasSubstr(main + ":6:5: error E404: M98 P1000: program O1000 is neither in this file nor in its folder"));
}

TEST_F(CliFlow, AnErrorInASubprogramFileNamesThatFile) {
  const std::string main = write("main.nc", kMain);
  const std::string sub = write("O1000.nc", "O1000\nG01 X36. Y2. F0.05\nM99\n");
  const CliRun run = runCli("check " + main);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_THAT(run.out, HasSubstr(sub + ":2:10: error E201"));
  EXPECT_THAT(run.out, Not(HasSubstr(main + ":2:10:")));
}

// #500-#999 survive the run in macro_variables.cfg: a parts counter counts 1, then 2.
TEST_F(CliFlow, PersistentVariablesAreKeptBetweenRuns) {
  const std::string main = write("count.nc",
                                 "O0020 (COUNT PARTS IN #500)\n"
                                 "G21 G99\n"
                                 "IF [#500 NE #0] GOTO 10\n"
                                 "#500 = 0\n"
                                 "N10 #500 = #500 + 1\n"
                                 "#501 = #500 * 2.5\n"
                                 "M30\n");
  const std::string kept = "data/klueng/macro_variables.cfg";
  ASSERT_EQ(runCli("simulate " + main + " --no-stock").exitCode, 0);
  EXPECT_EQ(read(kept),
            "; Klueng macro variables #500-#999 (kept between runs, as a control keeps them)\n#500 = 1\n#501 = 2.5\n");
  ASSERT_EQ(runCli("simulate " + main + " --no-stock").exitCode, 0);
  EXPECT_THAT(read(kept), HasSubstr("#500 = 2\n#501 = 5\n"));
  // --no-persist leaves the file as it was.
  ASSERT_EQ(runCli("simulate " + main + " --no-stock --no-persist").exitCode, 0);
  EXPECT_THAT(read(kept), HasSubstr("#500 = 2\n"));
  // The machine's variables are not the program's: nothing is written beside it.
  EXPECT_FALSE(fs::exists(dir_ / "macro_variables.cfg"));
}

// Issue 26 item 9: `check` writes nothing; `simulate --config DIR` keeps #500-#999 in DIR.
TEST_F(CliFlow, VariablesLiveInTheConfigFolderAndCheckWritesNothing) {
  const std::string main = write("count.nc", "O0021\nG21 G99\n#500 = #500 + 1\nM30\n");
  const fs::path config = dir_ / "config";
  fs::create_directories(config);
  for (const char* f : {"tools.cfg", "offset.cfg", "machine.cfg"})
    fs::copy_file(fs::path(KLUENG_SOURCE_DIR) / f, config / f);
  fs::create_directory_symlink(fs::path(KLUENG_SOURCE_DIR) / "resources", config / "resources");  // the tool bitmaps
  ASSERT_EQ(runCli("check " + main + " --config " + config.string()).exitCode, 0);
  ASSERT_EQ(runCli("check " + main).exitCode, 0);
  EXPECT_FALSE(fs::exists(dir_ / "macro_variables.cfg"));
  EXPECT_FALSE(fs::exists(config / "macro_variables.cfg"));
  EXPECT_FALSE(fs::exists(dir_ / "data"));
  const CliRun run = runCli("simulate " + main + " --no-stock --config " + config.string());
  ASSERT_EQ(run.exitCode, 0) << run.out;
  std::ifstream in(config / "macro_variables.cfg");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_THAT(text.str(), HasSubstr("#500 = 1\n"));
  EXPECT_FALSE(fs::exists(dir_ / "macro_variables.cfg"));
  EXPECT_FALSE(fs::exists(dir_ / "data"));
}

TEST_F(CliFlow, ABadLineInTheVariablesFileIsReportedWithItsLine) {
  const std::string main = write("p.nc", "G21\n#100 = #500 + 1\nM30\n");
  fs::create_directories(dir_ / "data" / "klueng");
  write("data/klueng/macro_variables.cfg", "#500 = 3\n#50 = 1\nrubbish\n");
  const CliRun run = runCli("simulate " + main + " --no-stock");
  EXPECT_EQ(run.exitCode, 0) << run.out;
  const std::string cfg = (dir_ / "data" / "klueng" / "macro_variables.cfg").string();
  EXPECT_THAT(run.out, HasSubstr(cfg + ":2:1: warning F171: " + cfg + ": #50 is not kept between runs"));
  EXPECT_THAT(run.out, HasSubstr(cfg + ":3:1: warning F170:"));
}

TEST_F(CliFlow, ProgramAlarmShowsItsText) {
  const std::string main = write("a.nc", "G21\n#1 = 2\nIF [#1 GT 1] THEN #3000 = 12 (STOCK TOO SHORT)\nM30\n");
  const CliRun run = runCli("simulate " + main + " --no-stock");
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_THAT(run.out, HasSubstr(main + ":3:1: alarm A130: program alarm 3012 (#3000 = 12): STOCK TOO SHORT"));
}

TEST_F(CliFlow, MainProgramM99RepeatsOnceWithANote) {
  const std::string main = write("loop.nc", "O0030\nG21 G99\nG00 X50. Z10.\nM99\n");
  const CliRun run = runCli("simulate " + main + " --no-stock --trace " + (dir_ / "t.csv").string());
  EXPECT_EQ(run.exitCode, 0) << run.out;
  EXPECT_THAT(run.out, HasSubstr(main + ":4:1: note I160: M99 at the end of the main program"));
  // The rapid runs in the first pass only: the second starts at X50 Z10 already.
  EXPECT_EQ(traceRows("t.csv").size(), 3u);
}

TEST_F(CliFlow, ALongLoopStopsAtTheBlockLimitNamingTheLoop) {
  // A finite WHILE of 70,000 turns runs 210,000 blocks again: past the shipped max_blocks.
  const std::string main = write("e.nc", "G21\n#1 = 0\nWHILE [#1 LT 70000] DO1\n#1 = #1 + 1\nEND1\nM30\n");
  const CliRun run = runCli("simulate " + main + " --no-stock");
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_THAT(run.out, HasSubstr(main + ":5:1: alarm A132: END1: stopped at the block limit, machine.cfg "
                                        "max_blocks = 200000 (200000 blocks run again by loops, jumps and calls); if "
                                        "the program is meant to run longer, raise max_blocks in machine.cfg"));
  EXPECT_THAT(run.out, Not(HasSubstr("without end")));
}

TEST_F(CliFlow, AnEndlessLoopIsSaidSoAtItsLine) {
  const std::string main = write("g.nc", "G21 G98\nG00 X50. Z2.\nN10 G01 Z-5. F100.\nG00 Z2.\nGOTO 10\nM30\n");
  const CliRun run = runCli("simulate " + main + " --no-stock");
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_THAT(run.out, HasSubstr(main + ":5:1: alarm A155: GOTO10 loops without end: the run came back to line 3 "
                                        "in the same state as on an earlier pass"));
}

}  // namespace

}  // namespace cli_flow_test

// klueng-cli --stock and --units, and the notes that say where a plain
// file's stock came from (SPEC 2 ext, issue 8).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_common.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_stock_test {

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

struct CliRun {
  int exitCode = -1;
  std::string out;  // stdout and stderr
};

CliRun runCli(const std::string& args, const std::string& lang = "LANG=C") {
  const std::string command =
      "env LC_ALL= LC_MESSAGES= " + lang + " '" + std::string(KLUENG_CLI_PATH) + "' " + args + " 2>&1";
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

// This process's folder of test files, removed when the tests end (one folder per run otherwise piles up in /tmp).
const fs::path& testFolder() {
  struct Folder {
    fs::path path = fs::temp_directory_path() / ("klueng-cli-stock-" + std::to_string(::getpid()));
    ~Folder() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  };
  static const Folder folder;
  return folder.path;
}

std::string writeFile(const std::string& name, const std::string& text) {
  const fs::path& dir = testFolder();
  fs::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// A plain Fanuc program: no header, a blank first line.
const std::string kPlain =
    "\nO0001\nN10 G21 G99 G97 S800 M03\nN20 T0101\nN30 G00 X52. Z0.\nN40 G01 X-1.6 F0.2\nN50 G00 Z2.\n"
    "N60 X46.\nN70 G01 Z-60.\nN80 G00 X52. Z2.\nN90 G00 X200. Z100.\nN100 M30\n";

TEST(CliStock, PlainFileTellsTheInferredStock) {
  const std::string file = writeFile("plain.nc", kPlain);
  const CliRun run = runCli("check " + file);
  EXPECT_EQ(run.exitCode, 0) << run.out;
  EXPECT_EQ(run.out, file + ":5:1: note I152: stock Ø50 x 80 mm inferred from N30 G00 X52. Z0. (first approach)\n" +
                         file +
                         ":9:1: note I157: stock length 80: the deepest cut Z-60 (N70 G01 Z-60.) + 5 for the cut-off"
                         " + 15 held in the chuck\n");
  const CliRun th = runCli("check --lang th " + file);
  EXPECT_THAT(th.out, HasSubstr(": หมายเหตุ I152: ชิ้นงาน Ø50 x 80 มม. ประมาณจาก N30 G00 X52. Z0."));
}

// A shop's thread to a shoulder with G32 passes: the guessed bar must leave the threading tool,
// whose insert reaches 10 mm behind its point, room before the jaws (it ran on the real lathe).
TEST(CliStock, InferredBarSticksOutFarEnoughForTheThreadingTool) {
  const std::string file =
      writeFile("thread.nc",
                "O1100\nG21 G99\nT0404\nG97 S500 M03\nG00 X26. Z5.\nX23.4\nG32 Z-20. F1.5\nG00 X26.\nZ5.\n"
                "X23.\nG32 Z-20. F1.5\nG00 X26.\nZ5.\nG28 U0 W0\nM30\n");
  const CliRun run = runCli("simulate " + file + " --cycle-time");
  EXPECT_EQ(run.exitCode, 0) << run.out;
  EXPECT_THAT(run.out, Not(HasSubstr("A304")));
  EXPECT_THAT(run.out, HasSubstr(file + ":7:1: note I162: stock length 50, not 40: T04 reaches Z-30 here, so the bar "
                                        "sticks out far enough for it to clear the chuck's jaws\n"));
  // The same bar given on the command line is the user's: a tool that meets its jaws is an alarm.
  const CliRun given = runCli("simulate " + file + " --stock 25x40");
  EXPECT_EQ(given.exitCode, 1) << given.out;
  EXPECT_THAT(given.out, HasSubstr(file + ":7:1: alarm A304: The tool hits the chuck at Z-16.000 X23.400"));
}

TEST(CliStock, HeaderFileHasNoNoteAndStockOptionWins) {
  const std::string file = writeFile("header.txt", "Job\nPart\nSteel\n150\n1100\nMe\n" + kPlain);
  EXPECT_EQ(runCli("check " + file).out, "");
  const CliRun run = runCli("check --stock 118x80x90 " + file);
  EXPECT_EQ(run.exitCode, 0);
  EXPECT_EQ(run.out, file + ": note I150: stock Ø118/Ø90 x 80 mm from the command line (--stock)\n");
  EXPECT_EQ(runCli("check --stock=2.1x4in " + file).out,
            file + ": note I150: stock Ø2.1 x 4 in from the command line (--stock)\n");
}

TEST(CliStock, SimulateCutsTheStockOptionsTube) {
  const std::string file = writeFile("tube.nc", kPlain);
  const std::string json = writeFile("tube.json", "");
  const CliRun run = runCli("simulate " + file + " --stock 50x100x20 --json " + json);
  EXPECT_EQ(run.exitCode, 0) << run.out;
  EXPECT_THAT(run.out, HasSubstr("note I150: stock Ø50/Ø20 x 100 mm from the command line (--stock)"));
  std::ifstream in(json);
  const std::string summary((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_THAT(summary, HasSubstr("\"diameter_mm\": 50.0000, \"length_mm\": 100.0000, \"bore_mm\": 20.0000"));
  // Without --stock: the inferred Ø50 x 80 bar.
  const CliRun inferred = runCli("simulate " + file + " --json " + json);
  EXPECT_EQ(inferred.exitCode, 0) << inferred.out;
  std::ifstream in2(json);
  const std::string s2((std::istreambuf_iterator<char>(in2)), std::istreambuf_iterator<char>());
  EXPECT_THAT(s2, HasSubstr("\"diameter_mm\": 50.0000, \"length_mm\": 80.0000, \"bore_mm\": 0.0000"));
}

TEST(CliStock, BadValuesExitTwoAndSayWhatIsAllowed) {
  const std::string file = writeFile("bad.nc", kPlain);
  // Bars no lathe holds (issue 29 item 9: 50x1e308 took minutes to draw, 1e308x1e308 gave "Taper nan°").
  for (const char* bad :
       {"50", "0x10", "50x0", "50x100x60", "ax10", "50x100in5", "-50x10", "50x1e308", "1e308x1e308", "10000x50"}) {
    for (const char* command : {"check", "simulate"}) {
      const CliRun run = runCli(std::string(command) + " " + file + " --stock " + bad);
      EXPECT_EQ(run.exitCode, 2) << command << " " << bad;
      EXPECT_THAT(run.out, HasSubstr("DxL[xBORE][in]")) << command << " " << bad;
      EXPECT_THAT(run.out, HasSubstr("118x80x90")) << command << " " << bad;
    }
  }
  for (const char* command : {"check", "simulate"}) {
    const CliRun run = runCli(std::string(command) + " " + file + " --units cm");
    EXPECT_EQ(run.exitCode, 2) << command;
    EXPECT_THAT(run.out, HasSubstr("mm or inch")) << command;
  }
  EXPECT_EQ(runCli("check " + file + " --units inch").exitCode, 0);
  EXPECT_EQ(runCli("check " + file + " --units mm").exitCode, 0);
}

TEST(CliStock, HelpShowsTheOptions) {
  const CliRun run = runCli("--help");
  EXPECT_THAT(run.out, HasSubstr("--stock DxL[xBORE][in]"));
  EXPECT_THAT(run.out, HasSubstr("--units mm|inch"));
  EXPECT_THAT(runCli("check --help").out, HasSubstr("118x80x90"));
}

TEST(CliStockParse, Forms) {
  using klueng::cli::parseStock;
  const auto a = parseStock("50x100");
  ASSERT_TRUE(a);
  EXPECT_DOUBLE_EQ(a->diameterMm(), 50.0);
  EXPECT_DOUBLE_EQ(a->lengthMm(), 100.0);
  EXPECT_DOUBLE_EQ(a->bore, 0.0);
  const auto b = parseStock("2.1x4in");
  ASSERT_TRUE(b);
  EXPECT_DOUBLE_EQ(b->diameterMm(), 53.34);
  EXPECT_DOUBLE_EQ(b->lengthMm(), 101.6);
  const auto c = parseStock("118x80x90");
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->boreMm(), 90.0);
  EXPECT_EQ(c->stockSource, klueng::core::io::StockSource::CommandLine);
  EXPECT_FALSE(parseStock("118x80x118"));
  EXPECT_FALSE(parseStock(""));
  EXPECT_FALSE(parseStock("50x"));
  EXPECT_TRUE(parseStock("9999.999x9999.999"));
  EXPECT_FALSE(parseStock("9999.999x10000"));
  EXPECT_TRUE(klueng::cli::parseUnits("inch"));
  EXPECT_FALSE(klueng::cli::parseUnits("in"));
}

}  // namespace

}  // namespace cli_stock_test

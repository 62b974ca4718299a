// Issue 30 item 5: every klueng-cli command parses its command line through one
// option table (cli_common.h parseCommandLine): the same forms, the same mistakes
// in English and Thai, exit 2, and --help printing the command's usage (exit 0).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <regex>
#include <set>
#include <string>

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_options_test {

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

struct CliRun {
  int exitCode = -1;
  std::string out;  // stdout, or stdout and stderr with `errors`
};

CliRun cli(const std::string& args, bool errors = true) {
  const std::string command =
      "env LC_ALL= LC_MESSAGES= LANG=C '" KLUENG_CLI_PATH "' " + args + (errors ? " 2>&1" : " 2>/dev/null");
  CliRun r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.out.append(buf, n);
  const int status = ::pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

const char* const kCommands[] = {"check", "simulate", "class", "print", "generate"};

TEST(CliOptions, EveryCommandRefusesAnUnknownOptionInBothLanguagesWithItsUsage) {
  for (const std::string command : kCommands) {
    const CliRun en = cli(command + " x.nc --bogus");
    EXPECT_EQ(en.exitCode, 2) << command;
    EXPECT_EQ(firstLine(en.out), "klueng-cli " + command + ": unknown option '--bogus'") << command;
    EXPECT_THAT(en.out, HasSubstr("\nusage: klueng-cli " + command + " ")) << command;
    const CliRun th = cli(command + " x.nc --bogus --lang th");
    EXPECT_EQ(th.exitCode, 2) << command;
    EXPECT_EQ(firstLine(th.out), "klueng-cli " + command + ": ไม่รู้จักตัวเลือก '--bogus'") << command;
    EXPECT_THAT(th.out, HasSubstr("\nวิธีใช้: klueng-cli " + command + " ")) << command;
    EXPECT_THAT(th.out, Not(HasSubstr("usage:"))) << command;
  }
}

TEST(CliOptions, EveryCommandsHelpPrintsItsOwnUsageOnStdoutAndExitsZero) {
  for (const std::string command : kCommands) {
    for (const std::string help : {"--help", "-h"}) {
      const CliRun en = cli(command + " " + help, false);
      EXPECT_EQ(en.exitCode, 0) << command << help;
      EXPECT_THAT(en.out, StartsWith("usage: klueng-cli " + command + " ")) << command << help;
    }
    const CliRun th = cli(command + " --help --lang=th", false);
    EXPECT_EQ(th.exitCode, 0) << command;
    EXPECT_THAT(th.out, StartsWith("วิธีใช้: klueng-cli " + command + " ")) << command;
    // --help wins over a mistake elsewhere on the line, as in any command.
    EXPECT_EQ(cli(command + " --bogus --help", false).exitCode, 0) << command;
  }
}

TEST(CliOptions, AMissingOrRefusedValueIsSaidTheSameWayByEveryCommand) {
  for (const std::string command : kCommands) {
    const CliRun missing = cli(command + " x.nc --dialect");
    EXPECT_EQ(missing.exitCode, 2) << command;
    EXPECT_EQ(firstLine(missing.out), "klueng-cli " + command + ": --dialect needs a value") << command;
    const CliRun refused = cli(command + " x.nc --dialect=okuma");
    EXPECT_EQ(refused.exitCode, 2) << command;
    EXPECT_EQ(firstLine(refused.out),
              "klueng-cli " + command + ": bad value 'okuma' for --dialect; allowed: fanuc, haas or classic")
        << command;
    const CliRun thai = cli(command + " x.nc --lang th --dialect okuma");
    EXPECT_EQ(firstLine(thai.out),
              "klueng-cli " + command + ": ค่า 'okuma' ใช้กับ --dialect ไม่ได้ ค่าที่ใช้ได้: fanuc, haas หรือ classic")
        << command;
    const CliRun two = cli(command + " x.nc y.nc");
    if (command == "check") continue;  // check takes many files
    EXPECT_EQ(two.exitCode, 2) << command;
    EXPECT_EQ(firstLine(two.out), "klueng-cli " + command + ": only one FILE (got 'x.nc' and 'y.nc')") << command;
  }
}

// Each command's own values, refused with what is allowed; a flag given a value is refused.
TEST(CliOptions, EachCommandsOwnValuesAreRefusedWithWhatIsAllowed) {
  EXPECT_EQ(firstLine(cli("generate part.json -o out.nc --tool-material wood").out),
            "klueng-cli generate: bad value 'wood' for --tool-material; allowed: hss or carbide");
  EXPECT_EQ(
      firstLine(cli("generate part.json -o out.nc --stock 50").out),
      "klueng-cli generate: bad value '50' for --stock; allowed: DxL[xBORE][in] with 0 < D, L <= 9999.999 and 0 < "
      "BORE < D, e.g. 50x100, 2.1x4in, 118x80x90");
  EXPECT_EQ(firstLine(cli("class dir --reference r.nc --tolerance lots").out),
            "klueng-cli class: bad value 'lots' for --tolerance; allowed: a number from 0 to 100 (mm)");
  EXPECT_EQ(firstLine(cli("print x.nc --pdf x.pdf --sheet=poster").out),
            "klueng-cli print: bad value 'poster' for --sheet; allowed: program, drawing or both");
  EXPECT_EQ(firstLine(cli("simulate x.nc --show-units feet").out),
            "klueng-cli simulate: bad value 'feet' for --show-units; allowed: auto, mm or inch");
  EXPECT_EQ(firstLine(cli("simulate x.nc --compare-compensation sideways").out),
            "klueng-cli simulate: bad value 'sideways' for --compare-compensation; allowed: none or sharp");
  EXPECT_EQ(firstLine(cli("check x.nc --json=yes").out), "klueng-cli check: bad value 'yes' for --json");
  EXPECT_EQ(cli("check x.nc --json=yes").exitCode, 2);
}

// The usage of each command and its table agree: every option its usage names is one it takes.
TEST(CliOptions, EveryOptionAUsageNamesIsTaken) {
  for (const std::string command : kCommands) {
    const CliRun help = cli(command + " --help", false);
    ASSERT_EQ(help.exitCode, 0) << command;
    std::set<std::string> named;
    const std::regex option(R"((^|[\[ ])(--[a-z][a-z-]*|-o)\b)");
    for (auto it = std::sregex_iterator(help.out.begin(), help.out.end(), option); it != std::sregex_iterator(); ++it)
      named.insert((*it)[2]);
    EXPECT_GE(named.size(), 5u) << command << "\n" << help.out;
    for (const std::string& name : named) {
      if (name == "--help") continue;
      // The option, a value, then a sure mistake: the parse stops there, before any work.
      const CliRun r = cli(command + " " + name + " zz --zz-end");
      EXPECT_EQ(r.exitCode, 2) << command << " " << name;
      EXPECT_THAT(r.out, Not(HasSubstr("unknown option '" + name + "'"))) << command << " " << name;
    }
  }
}

}  // namespace

}  // namespace cli_options_test

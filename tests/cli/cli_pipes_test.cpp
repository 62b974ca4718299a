// Issue 42 item 4: no command waits for ever on a named pipe (FIFO), as input, setup
// table or output (F157, exit 2, at once); a pipe that has data is a fine input:
// `check <(cat f)`, `/dev/stdin` and `check -` read it to its end (with the size limit
// of a file), and `-` is named `<stdin>` in the messages, as GCC names it.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../scratch_folders.h"
#include "cli_shell.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_pipes_test {

namespace {

namespace fs = std::filesystem;

const std::string kCli = klueng::test::cliUnderTest(KLUENG_CLI_PATH);

const auto* const kCleanup = klueng::test::removeScratchFoldersAtExit({"klueng_cli_pipes-"});

using klueng::test::put;
using klueng::test::slurp;
constexpr auto quote = &klueng::test::shellQuote;

// `shell` run by bash (stdout and stderr together), cut off after 30 s: a command that waits
// on a pipe is killed by `timeout` and its status is 124. {cli} stands for the CLI.
int sh(std::string shell, std::string& out) {
  for (std::size_t at; (at = shell.find("{cli}")) != std::string::npos;)
    shell.replace(at, 5, klueng::test::cliCommand(kCli, 30));
  return klueng::test::runShell("bash -c " + quote(shell), out);
}

fs::path scratch() {
  const fs::path p = fs::temp_directory_path() / ("klueng_cli_pipes-" + std::to_string(::getpid()));
  fs::create_directories(p);
  return p;
}

fs::path fifo(const std::string& name) {
  const fs::path p = scratch() / name;
  std::error_code ec;
  fs::remove(p, ec);
  EXPECT_EQ(::mkfifo(p.c_str(), 0600), 0);
  return p;
}

const std::string kSample = std::string(KLUENG_SAMPLES_DIR) + "/01-step-shaft.txt";
const std::string kConfig = std::string(" --config ") + quote(KLUENG_SOURCE_DIR);

bool refusedAsPipe(const std::string& out, const fs::path& pipe) {
  return out.find(pipe.string() + ": error F157: " + pipe.string() + ": this is a pipe (FIFO)") != std::string::npos;
}

}  // namespace

TEST(CliPipes, EveryCommandRefusesANamedPipeAsItsInput) {
  const fs::path pipe = fifo("prog.nc");
  const std::string p = quote(pipe.string());
  const std::string out = quote((scratch() / "out.pdf").string());
  std::string text;
  EXPECT_EQ(sh("{cli} check " + p + kConfig, text), 2) << text;
  EXPECT_TRUE(refusedAsPipe(text, pipe)) << text;
  EXPECT_EQ(sh("{cli} simulate " + p + " --no-persist" + kConfig, text), 2) << text;
  EXPECT_TRUE(refusedAsPipe(text, pipe)) << text;
  EXPECT_EQ(sh("{cli} print " + p + " --pdf " + out + kConfig, text), 2) << text;
  EXPECT_TRUE(refusedAsPipe(text, pipe)) << text;
  EXPECT_EQ(sh("{cli} generate " + p + " -o " + quote((scratch() / "g.nc").string()) + kConfig, text), 2) << text;
  EXPECT_TRUE(refusedAsPipe(text, pipe)) << text;
  EXPECT_EQ(sh("{cli} print " + quote(kSample) + " --design " + p + " --pdf " + out + kConfig, text), 2) << text;
  EXPECT_TRUE(refusedAsPipe(text, pipe)) << text;
  const fs::path cls = scratch() / "class";
  fs::create_directories(cls);
  fs::copy_file(kSample, cls / "a.nc", fs::copy_options::overwrite_existing);
  EXPECT_EQ(sh("{cli} class " + quote(cls.string()) + " --reference " + p + kConfig, text), 2) << text;
  EXPECT_TRUE(refusedAsPipe(text, pipe)) << text;
  EXPECT_FALSE(fs::exists(scratch() / "out.pdf"));
  EXPECT_FALSE(fs::exists(scratch() / "g.nc"));
}

TEST(CliPipes, ASetupTableThatIsANamedPipeIsRefused) {
  for (const char* table : {"tools.cfg", "offset.cfg", "machine.cfg"}) {
    const fs::path dir = scratch() / (std::string("setup-") + table);
    fs::create_directories(dir);
    for (const char* f : {"tools.cfg", "offset.cfg", "machine.cfg"})
      if (std::string(f) != table)
        fs::copy_file(fs::path(KLUENG_SOURCE_DIR) / f, dir / f, fs::copy_options::overwrite_existing);
    std::error_code ec;
    fs::remove(dir / table, ec);
    ASSERT_EQ(::mkfifo((dir / table).c_str(), 0600), 0);
    std::string text;
    EXPECT_EQ(sh("{cli} check " + quote(kSample) + " --config " + quote(dir.string()), text), 2) << table << text;
    EXPECT_TRUE(refusedAsPipe(text, dir / table)) << table << text;
  }
}

TEST(CliPipes, AMachineFileThatIsANamedPipeIsRefused) {
  const fs::path pipe = fifo("deep.machine");
  std::string text;
  EXPECT_EQ(sh("{cli} check " + quote(kSample) + " --machine " + quote(pipe.string()) + kConfig, text), 2) << text;
  EXPECT_NE(text.find("F157"), std::string::npos) << text;
}

// Output: a pipe nobody reads is refused (F157) within a second, never waited on for ever; one that
// is read is written, also when its reader opens it just after the run starts (`cat fifo & ...`).
TEST(CliPipes, OutputToAPipeNeverWaits) {
  const fs::path pipe = fifo("trace.csv");
  std::string text;
  EXPECT_EQ(sh("{cli} simulate " + quote(kSample) + " --no-persist --trace " + quote(pipe.string()) + kConfig, text), 2)
      << text;
  EXPECT_NE(text.find(pipe.string() + ": this is a pipe (FIFO) that nobody reads"), std::string::npos) << text;
  // Read: `cat` at the other end gets the trace.
  EXPECT_EQ(sh("cat " + quote(pipe.string()) + " > " + quote((scratch() / "got.csv").string()) + " & {cli} simulate " +
                   quote(kSample) + " --no-persist --trace " + quote(pipe.string()) + kConfig + "; s=$?; wait; exit $s",
               text),
            0)
      << text;
  EXPECT_TRUE(slurp(scratch() / "got.csv").starts_with("kind,line,")) << slurp(scratch() / "got.csv");
}

// A pipe with data is read to its end: the same diagnostics as the file itself.
TEST(CliPipes, APipeWithDataIsReadLikeTheFile) {
  const std::string bad = std::string(KLUENG_SAMPLES_DIR) + "/04-grammar-errors.txt";
  std::string direct;
  const int status = sh("{cli} check " + quote(bad) + kConfig, direct);
  ASSERT_EQ(status, 1) << direct;
  const std::string firstError = direct.substr(direct.find(": error E"), 40);

  std::string text;
  EXPECT_EQ(sh("{cli} check <(cat " + quote(bad) + ")" + kConfig, text), status) << text;
  EXPECT_EQ(text.find("the file is empty"), std::string::npos) << text;
  EXPECT_NE(text.find(firstError), std::string::npos) << text;

  EXPECT_EQ(sh("cat " + quote(bad) + " | {cli} check /dev/stdin" + kConfig, text), status) << text;
  EXPECT_NE(text.find("/dev/stdin:"), std::string::npos) << text;
  EXPECT_NE(text.find(firstError), std::string::npos) << text;

  // `check -`: an editor's linter pipes its buffer; the messages name it <stdin>.
  EXPECT_EQ(sh("cat " + quote(bad) + " | {cli} check -" + kConfig, text), status) << text;
  EXPECT_NE(text.find("<stdin>:"), std::string::npos) << text;
  EXPECT_NE(text.find(firstError), std::string::npos) << text;
  EXPECT_EQ(text.find("no such file"), std::string::npos) << text;

  EXPECT_EQ(sh("cat " + quote(kSample) + " | {cli} simulate - --no-persist --cycle-time" + kConfig, text), 0) << text;
  EXPECT_EQ(sh("cat " + quote(kSample) + " | {cli} check -" + kConfig, text), 0) << text;
}

// The size limit of a file holds for a pipe too (it never ends: /dev/zero).
TEST(CliPipes, APipeIsReadUpToTheSizeLimitOfAFile) {
  std::string text;
  EXPECT_EQ(sh("{cli} check - < /dev/zero" + kConfig, text), 2) << text;
  EXPECT_NE(text.find("<stdin>: error F103: "), std::string::npos) << text;
  EXPECT_EQ(sh("yes G01 X1. | {cli} check -" + kConfig, text), 2) << text.substr(0, 2000);
  EXPECT_NE(text.find("files over 64 MB are refused"), std::string::npos) << text.substr(0, 2000);
}

}  // namespace cli_pipes_test

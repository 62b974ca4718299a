// Issue 42 ("Harden, round 3"), items 1, 2, 5 and 7: a folder run reads only
// what lies in its folder and never quotes a file that is not a program; no
// output may replace a file the run reads; an interrupted write leaves no
// temporary file; parallel runs update #500-#999 under a lock.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_common.h"
#include "cli_shell.h"
#include "klueng/core/io/macro_variables.h"

extern char** environ;

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_harden_test {

namespace {

namespace fs = std::filesystem;

// The CLI under test; KLUENG_CLI_UNDER_TEST runs these tests against another build (an older one, to see them fail).
const std::string kCli = klueng::test::cliUnderTest(KLUENG_CLI_PATH);

const std::string kSecret = "SECRET-MARKER-do-not-print:$6$salt$hash:19000:0:99999:7:::";

using klueng::test::put;
using klueng::test::slurp;
constexpr auto quote = &klueng::test::shellQuote;

// klueng-cli ARGS (stdout and stderr together); the exit status.
int run(const std::string& args, std::string& out) {
  return klueng::test::runShell("env LC_ALL= LC_MESSAGES= LANG=C " + quote(kCli) + " " + args, out);
}

// A folder of its own per test and process, removed at the end.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / ("klueng_cli_harden_" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

std::string sample01() { return slurp(fs::path(KLUENG_SAMPLES_DIR) / "01-step-shaft.txt"); }

// The class folder of issue 42 item 1 and 7: one good program and every kind of entry a
// folder run must not read. The secret lies outside the folder.
fs::path makeClassFolder(const fs::path& root) {
  const fs::path dir = root / "class";
  fs::create_directories(dir / "d.nc");
  put(root / "secret.txt", kSecret + "\n" + kSecret + "\n");
  put(dir / "ok.nc", sample01());
  fs::create_symlink(root / "secret.txt", dir / "evil.nc");
  fs::create_symlink(root / "nothing-here.txt", dir / "dangling.nc");
  EXPECT_EQ(::mkfifo((dir / "pipe.nc").c_str(), 0600), 0);
  // Text that is no program (a password file copied in), and binary data without a NUL byte.
  put(dir / "copied.nc", "root:x:0:0:" + kSecret + "\ndaemon:x:1:1:" + kSecret + "\n");
  put(dir / "binary.nc", std::string("\x7f"
                                     "ELF\x02\x01\x01\x03\x04\x05\x06\x07\x08\x0e\x0f") +
                             kSecret + "\n");
  return dir;
}

bool hasLine(const std::string& out, const std::string& line) {
  std::istringstream in(out);
  for (std::string l; std::getline(in, l);)
    if (l == line) return true;
  return false;
}

// A setup folder of its own: the shipped tables and tool pictures, copied.
fs::path copyConfig(const fs::path& dst) {
  const fs::path src(KLUENG_SOURCE_DIR);
  fs::create_directories(dst / "resources" / "tools");
  for (const char* f : {"tools.cfg", "offset.cfg", "machine.cfg"}) fs::copy_file(src / f, dst / f);
  for (const fs::directory_entry& e : fs::directory_iterator(src / "resources" / "tools"))
    if (e.is_regular_file()) fs::copy_file(e.path(), dst / "resources" / "tools" / e.path().filename());
  return dst;
}

// klueng-cli ARGS as a child of its own (SIGINT and SIGTERM at their defaults, output to /dev/null).
pid_t spawnCli(const std::vector<std::string>& args) {
  std::vector<std::string> all{kCli};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&files, 2, "/dev/null", O_WRONLY, 0);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], &files, &attr, argv.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&files);
  posix_spawnattr_destroy(&attr);
  return pid;
}

// The temporary files of writes to `name` in `dir` (`.NAME.tmp-XXXXXX`).
int temporaries(const fs::path& dir, const std::string& name) {
  int n = 0;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
    if (e.path().filename().string().starts_with("." + name + ".tmp-")) ++n;
  return n;
}

// A program of `moves` feed moves: a trace of some 20 MB, written long enough to be interrupted.
std::string longProgram(int moves) {
  std::string text = "G21 G99\nT0101\nG97 S500 M03\nG00 X52. Z2.\n";
  for (int i = 0; i < moves; ++i) text += i % 2 ? "G01 X51. Z1. F0.2\n" : "G01 X52. Z2. F0.2\n";
  return text + "M30\n";
}

// Interrupts `simulate --trace` by `sig` while the trace's temporary file is there; true when it was.
bool interruptTraceWrite(const fs::path& dir, const fs::path& prog, int sig) {
  for (int attempt = 0; attempt < 5; ++attempt) {
    std::error_code ec;
    fs::remove(dir / "trace.csv", ec);
    const pid_t pid = spawnCli({"simulate", prog.string(), "--no-stock", "--no-persist", "--stock", "60x100",
                                "--config", KLUENG_SOURCE_DIR, "--trace", (dir / "trace.csv").string()});
    if (pid < 0) return false;
    int status = 0;
    bool signalled = false;
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < until) {
      if (::waitpid(pid, &status, WNOHANG) == pid) break;  // finished before we caught the write
      if (temporaries(dir, "trace.csv") > 0) {
        ::kill(pid, sig);
        signalled = true;
        ::waitpid(pid, &status, 0);
        break;
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    if (signalled && WIFSIGNALED(status) && WTERMSIG(status) == sig) return true;
  }
  return false;
}

}  // namespace

// Item 1 and 7: `check DIR` gives every entry a line, reads none outside, quotes no non-program.
TEST(CliHarden, CheckFolderReadsOnlyItsOwnProgramsAndQuotesNoOtherFile) {
  const TempDir tmp("check_folder");
  const fs::path dir = makeClassFolder(tmp.path);
  std::string out;
  EXPECT_EQ(run("check " + quote(dir.string()) + " --config " + quote(KLUENG_SOURCE_DIR), out), 2) << out;
  EXPECT_EQ(out.find("SECRET-MARKER"), std::string::npos) << out;
  EXPECT_TRUE(hasLine(out, (dir / "evil.nc").string() + ": error F158: " + (dir / "evil.nc").string() +
                               ": refused: points outside the folder, so it is not read"))
      << out;
  EXPECT_NE(out.find((dir / "dangling.nc").string() + ": error F101:"), std::string::npos) << out;
  EXPECT_NE(out.find((dir / "pipe.nc").string() + ": error F157:"), std::string::npos) << out;
  EXPECT_NE(out.find((dir / "d.nc").string() + ": error F102:"), std::string::npos) << out;
  EXPECT_TRUE(hasLine(out, (dir / "copied.nc").string() + ": error F159: " + (dir / "copied.nc").string() +
                               ": this is not a G-code program (no G-code in its first 20 lines), so its text is "
                               "not shown"))
      << out;
  EXPECT_NE(out.find((dir / "binary.nc").string() + ": error F159:"), std::string::npos) << out;
  EXPECT_EQ(out.find("E138"), std::string::npos) << out;
  EXPECT_EQ(out.find((dir / "ok.nc").string() + ": error"), std::string::npos) << out;
}

// Item 1 and 7: `class DIR` gives each of them a failed row and never reads them.
TEST(CliHarden, ClassFolderRefusesLinksOutAndListsEveryEntry) {
  const TempDir tmp("class_folder");
  const fs::path dir = makeClassFolder(tmp.path);
  put(tmp.path / "ref.nc", sample01());
  std::string out;
  const fs::path csv = tmp.path / "grades.csv";
  ASSERT_EQ(run("class " + quote(dir.string()) + " --reference " + quote((tmp.path / "ref.nc").string()) + " --csv " +
                    quote(csv.string()) + " --config " + quote(KLUENG_SOURCE_DIR),
                out),
            0)
      << out;
  EXPECT_EQ(out.find("SECRET-MARKER"), std::string::npos) << out;
  const std::string table = slurp(csv);
  EXPECT_EQ(table.find("SECRET-MARKER"), std::string::npos) << table;
  EXPECT_TRUE(hasLine(table, "evil.nc,fail,1,F158 refused: points outside the folder,,,,,,,")) << table;
  EXPECT_TRUE(hasLine(table, "dangling.nc,fail,1,F101 unreadable: a link to nothing,,,,,,,")) << table;
  EXPECT_TRUE(hasLine(table, "pipe.nc,fail,1,F157 unreadable: not an ordinary file,,,,,,,")) << table;
  EXPECT_TRUE(hasLine(table, "d.nc,fail,1,F102 unreadable: a folder,,,,,,,")) << table;
  EXPECT_TRUE(hasLine(table, "copied.nc,fail,1,F159,,,,,,,")) << table;
  EXPECT_TRUE(hasLine(table, "binary.nc,fail,1,F159,,,,,,,")) << table;
  EXPECT_NE(table.find("\nok.nc,pass,0,,,"), std::string::npos) << table;
  EXPECT_NE(out.find("7 programs: 1 pass, 6 fail"), std::string::npos) << out;
}

// Item 1: a subprogram file that is a link out of the program's folder is not read.
TEST(CliHarden, SubprogramLinkOutOfTheFolderIsRefused) {
  const TempDir tmp("subprogram_link");
  fs::create_directories(tmp.path / "prog");
  put(tmp.path / "secret.txt", kSecret + "\n");
  fs::create_symlink(tmp.path / "secret.txt", tmp.path / "prog" / "O1000.nc");
  const fs::path prog = tmp.path / "prog" / "main.nc";
  put(prog, "O0001\nG21 G99\nT0101\nG97 S500 M03\nM98 P1000\nM30\n");
  std::string out;
  EXPECT_EQ(run("check " + quote(prog.string()) + " --stock 50x100 --config " + quote(KLUENG_SOURCE_DIR), out), 1)
      << out;
  EXPECT_EQ(out.find("SECRET-MARKER"), std::string::npos) << out;
  EXPECT_NE(out.find("O1000.nc: error F158: "), std::string::npos) << out;
}

// Item 1: a file name holding a newline cannot forge a diagnostic line.
TEST(CliHarden, FileNameWithANewlineIsPrintedEscaped) {
  const TempDir tmp("newline_name");
  const std::string name = "x\nforged.nc:1:1: error E999: fake.nc";
  put(tmp.path / name, "G01 Y5.\n");
  std::string out;
  run("check " + quote(tmp.path.string()) + " --stock 50x100 --config " + quote(KLUENG_SOURCE_DIR), out);
  std::istringstream lines(out);
  for (std::string l; std::getline(lines, l);) EXPECT_FALSE(l.starts_with("forged.nc")) << out;
  EXPECT_NE(out.find("x\\nforged.nc:1:1: error E999: fake.nc:1:5: error E201: "), std::string::npos) << out;
  EXPECT_EQ(klueng::cli::printable("a\nb\rc\x1b[31m\td"), "a\\nb\\rc\\x1b[31m\td");
}

// Item 2: no output replaces a file the run reads: a tool picture of the setup folder, the
// tool library, a library picture, the cutting-speed table (F126, exit 2, the file unchanged).
TEST(CliHarden, OutputsNeverReplaceTheSetupTheRunReads) {
  const TempDir tmp("outputs_inputs");
  const fs::path config = copyConfig(tmp.path / "config");
  const fs::path prog = tmp.path / "prog.nc";
  put(prog, sample01());
  const fs::path bitmap1 = config / "resources" / "tools" / "01-outside-turning.bmp";
  const fs::path bitmap2 = config / "resources" / "tools" / "02-outside-left-hand.bmp";
  const std::string bytes1 = slurp(bitmap1), bytes2 = slurp(bitmap2);
  const std::string base = "simulate " + quote(prog.string()) + " --config " + quote(config.string());
  std::string out;
  EXPECT_EQ(run(base + " --png " + quote(bitmap1.string()), out), 2) << out;
  EXPECT_NE(out.find(bitmap1.string() + ": error F126: "), std::string::npos) << out;
  EXPECT_EQ(slurp(bitmap1), bytes1);
  EXPECT_EQ(run(base + " --trace " + quote(bitmap2.string()), out), 2) << out;
  EXPECT_NE(out.find(bitmap2.string() + ": error F126: "), std::string::npos) << out;
  EXPECT_EQ(slurp(bitmap2), bytes2);

  // The shipped library and table: kept as they were whatever happens (they are the sources').
  const fs::path library = fs::path(KLUENG_SOURCE_DIR) / "resources" / "tools" / "library" / "library.cfg";
  const fs::path picture = fs::path(KLUENG_SOURCE_DIR) / "resources" / "tools" / "library" / "cnmg-80-r08.png";
  const fs::path speeds = fs::path(KLUENG_SOURCE_DIR) / "resources" / "parts" / "cutting_speeds.cfg";
  const std::string libraryBytes = slurp(library), pictureBytes = slurp(picture), speedsBytes = slurp(speeds);
  ASSERT_FALSE(libraryBytes.empty());
  ASSERT_FALSE(pictureBytes.empty());
  ASSERT_FALSE(speedsBytes.empty());
  const int svg = run(base + " --svg " + quote(library.string()), out);
  const std::string svgOut = out;
  const int json = run(base + " --json " + quote(picture.string()), out);
  const std::string jsonOut = out;
  const int generate = run("generate " + quote(KLUENG_SOURCE_DIR "/resources/parts/step-shaft.json") + " -o " +
                               quote(speeds.string()) + " --config " + quote(config.string()),
                           out);
  const std::string generateOut = out;
  const bool libraryKept = slurp(library) == libraryBytes, pictureKept = slurp(picture) == pictureBytes,
             speedsKept = slurp(speeds) == speedsBytes;
  if (!libraryKept) put(library, libraryBytes);
  if (!pictureKept) put(picture, pictureBytes);
  if (!speedsKept) put(speeds, speedsBytes);
  EXPECT_EQ(svg, 2) << svgOut;
  EXPECT_NE(svgOut.find(library.string() + ": error F126: "), std::string::npos) << svgOut;
  EXPECT_EQ(json, 2) << jsonOut;
  EXPECT_NE(jsonOut.find(picture.string() + ": error F126: "), std::string::npos) << jsonOut;
  EXPECT_EQ(generate, 2) << generateOut;
  EXPECT_NE(generateOut.find(speeds.string() + ": error F126: "), std::string::npos) << generateOut;
  EXPECT_TRUE(libraryKept && pictureKept && speedsKept);
}

// Item 5: SIGTERM and SIGINT during a write remove its temporary file, and the process still ends by the signal.
TEST(CliHarden, InterruptedWriteLeavesNoTemporaryFile) {
  const TempDir tmp("interrupted");
  const fs::path prog = tmp.path / "long.nc";
  put(prog, longProgram(300000));
  for (const int sig : {SIGTERM, SIGINT}) {
    EXPECT_TRUE(interruptTraceWrite(tmp.path, prog, sig)) << "signal " << sig << ": the write was never caught";
    EXPECT_EQ(temporaries(tmp.path, "trace.csv"), 0) << "signal " << sig;
  }
}

// Item 5: twenty parallel runs of #500=#500+1 add twenty (read, run and write under one lock).
TEST(CliHarden, ParallelRunsUpdateMacroVariablesUnderALock) {
  const TempDir tmp("parallel");
  const fs::path config = copyConfig(tmp.path / "config");
  put(config / "macro_variables.cfg", "#500 = 0\n");
  const fs::path prog = tmp.path / "count.nc";
  put(prog, "O0001\n#500=#500+1\nM30\n");
  std::vector<pid_t> pids;
  for (int i = 0; i < 20; ++i)
    pids.push_back(spawnCli({"simulate", prog.string(), "--stock", "50x100", "--config", config.string()}));
  for (const pid_t pid : pids) {
    ASSERT_GT(pid, 0);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  }
  const auto stored = klueng::core::io::readMacroVariables((config / "macro_variables.cfg").string());
  ASSERT_TRUE(stored.value.has_value());
  EXPECT_EQ(stored.value->at(500), 20.0);
  EXPECT_EQ(temporaries(config, "macro_variables.cfg"), 0);
}

// Item 5: a failed write of macro_variables.cfg (no space: the file size limit) is F109 and exit 2.
TEST(CliHarden, FailedMacroVariablesWriteExitsTwo) {
  const TempDir tmp("variables_full");
  const fs::path config = copyConfig(tmp.path / "config");
  put(config / "macro_variables.cfg", "#500 = 0\n");
  const fs::path prog = tmp.path / "count.nc";
  put(prog, "O0001\n#500=#500+1\nM30\n");
  std::string out;
  const std::string inner = "trap '' XFSZ; ulimit -f 0; exec " + quote(kCli) + " simulate " + quote(prog.string()) +
                            " --stock 50x100 --config " + quote(config.string());
  const std::string command = "env LC_ALL= LC_MESSAGES= LANG=C sh -c " + quote(inner) + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  const int status = ::pclose(pipe);
  ASSERT_TRUE(WIFEXITED(status)) << out;
  EXPECT_EQ(WEXITSTATUS(status), 2) << out;
  EXPECT_NE(out.find((config / "macro_variables.cfg").string() + ": error F109: "), std::string::npos) << out;
  EXPECT_EQ(slurp(config / "macro_variables.cfg"), "#500 = 0\n");
}

// Unix manners (issue 42 item 4): a version, and an option's missing value is an error, never
// the next option taken as a file name nor an empty name that writes nothing.
TEST(CliHarden, VersionAndMissingOptionValues) {
  std::string out;
  EXPECT_EQ(run("--version", out), 0);
  EXPECT_EQ(out, "klueng-cli 0.1.0\n");
  EXPECT_EQ(run("--help", out), 0);
  EXPECT_NE(out.find("--machine ID|FILE"), std::string::npos) << out;
  const TempDir tmp("option_values");
  const fs::path prog = tmp.path / "p.nc";
  put(prog, sample01());
  const std::string cd = "cd " + quote(tmp.path.string()) + " && ";
  const std::string command =
      cd + "env LC_ALL= LC_MESSAGES= LANG=C " + quote(kCli) + " simulate p.nc --trace --cycle-time 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char buf[4096];
  out.clear();
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  const int status = ::pclose(pipe);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2) << out;
  EXPECT_NE(out.find("--trace needs a value"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(tmp.path / "--cycle-time"));
  EXPECT_EQ(run("simulate " + quote(prog.string()) + " --trace ''", out), 2);
  EXPECT_NE(out.find("--trace needs a value"), std::string::npos) << out;
}

}  // namespace cli_harden_test

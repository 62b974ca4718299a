// klueng-bench-cli-memory [--cli PATH] [--blocks N] [--command check|simulate] [--goal BYTES]
//
// The CLI's memory a block (issue 42 item 3): writes the yardstick one word a block
// (YardstickGenerator, --steps: 5,000,000 blocks by default, 42 MB, under the 64 MB a program
// file may have) into a scratch folder, runs `klueng-cli check FILE` once as a whole process and
// prints its peak RSS (the child's rusage) and that peak divided by the blocks. Goal: at most 100
// bytes a block (--goal); the exit code is 0 either way (a bench measures, the figure is in
// docs/performance.md). `--command simulate` runs `simulate FILE --config DIR` (the shipped setup
// with max_run_time raised so every block runs) instead.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scratch_config.h"
#include "program_generator.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;

struct PeakRun {
  long rssKb = 0;
  double wallMs = 0.0;
  double cpuMs = 0.0;
  int exitCode = -1;
};

PeakRun runOnce(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  PeakRun r;
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0) {
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    r.wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    r.rssKb = usage.ru_maxrss;
    const auto ms = [](const timeval& t) { return t.tv_sec * 1000.0 + t.tv_usec / 1000.0; };
    r.cpuMs = ms(usage.ru_utime) + ms(usage.ru_stime);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  posix_spawn_file_actions_destroy(&actions);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  std::string cli = KLUENG_CLI_PATH;
  std::string command = "check";
  int blocks = 5'000'000;
  double goal = 100.0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool value = i + 1 < argc;
    if (a == "--cli" && value)
      cli = argv[++i];
    else if (a == "--blocks" && value)
      blocks = std::atoi(argv[++i]);
    else if (a == "--command" && value)
      command = argv[++i];
    else if (a == "--goal" && value)
      goal = std::atof(argv[++i]);
    else {
      std::fprintf(stderr, "usage: %s [--cli PATH] [--blocks N] [--command check|simulate] [--goal BYTES_A_BLOCK]\n",
                   argv[0]);
      return 2;
    }
  }
  if (blocks < 100 || (command != "check" && command != "simulate")) {
    std::fprintf(stderr, "--blocks: at least 100; --command: check or simulate\n");
    return 2;
  }
  char pattern[] = "/tmp/klueng-bench-memory-XXXXXX";
  if (!mkdtemp(pattern)) {
    std::perror("mkdtemp");
    return 2;
  }
  const fs::path scratch = pattern;
  const fs::path program = scratch / "yardstick-steps.nc";
  {
    const std::string text = klueng::bench::YardstickGenerator::generate(blocks, false, true);
    std::ofstream(program, std::ios::binary) << text;
  }
  std::size_t lines = 0;
  {
    std::ifstream in(program);
    for (std::string line; std::getline(in, line);) ++lines;
  }
  std::vector<std::string> args = {cli, command, program.string()};
  if (command == "simulate") {
    args.push_back("--config");
    args.push_back(klueng::bench::makeLongRunConfig(scratch).string());
  }
  const PeakRun r = runOnce(args);
  std::error_code ignored;
  fs::remove_all(scratch, ignored);
  const double bytes = static_cast<double>(r.rssKb) * 1024.0;
  const double perBlock = bytes / static_cast<double>(lines);
  std::printf("program   yardstick, one word a block: %zu lines, %d blocks asked\n", lines, blocks);
  std::printf("command   klueng-cli %s (exit %d)\n", command.c_str(), r.exitCode);
  std::printf("peak RSS  %.0f MB (%ld kB; MB = 1000 kB, as docs/performance.md counts)\n", r.rssKb / 1000.0, r.rssKb);
  std::printf("a block   %.0f bytes (goal %.0f: %s)\n", perBlock, goal, perBlock <= goal ? "met" : "not met");
  std::printf("time      %.0f ms wall, %.0f ms CPU\n", r.wallMs, r.cpuMs);
  return r.exitCode < 0 ? 1 : 0;
}

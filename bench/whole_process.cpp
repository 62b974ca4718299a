// klueng-bench-whole-process [--cli PATH] [--runs N] [--sizes 10000,100000,1000000]
//
// What a user waits for (issue 13): `klueng-cli check` and `klueng-cli simulate`
// timed as whole processes (exec, page faults, reading, output, exit) on the
// generated 10k / 100k / 1M-block programs, median of N runs, with the peak RSS
// of the largest run; next to them the same work in-process (the calls the CLI
// makes, timed here), and the ratio. The machine's max_run_time is raised to its
// limit so every block of the long programs really runs (the shipped 10 h stops
// the 100k program at block ~25,500).
#include <spawn.h>
#include <sys/resource.h>
#include <fcntl.h>
#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/machine/job_file.h"
#include "klueng/core/machine/setup_files.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using namespace klueng::core;
using Clock = std::chrono::steady_clock;

struct Sample {
  double ms = 0.0;
  long rssKb = 0;
  int exitCode = -1;
};

Sample runProcess(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  Sample s;
  const auto start = Clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) return s;
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  s.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  s.rssKb = usage.ru_maxrss;
  s.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  posix_spawn_file_actions_destroy(&actions);
  return s;
}

double timeIt(const std::function<void()>& work) {
  const auto start = Clock::now();
  work();
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

// The shipped setup with max_run_time at its limit, in a scratch folder.
fs::path makeConfig(const fs::path& scratch) {
  const fs::path dir = scratch / "config";
  fs::create_directories(dir);
  const fs::path source = KLUENG_SOURCE_DIR;
  fs::copy_file(source / "tools.cfg", dir / "tools.cfg");
  fs::copy_file(source / "offset.cfg", dir / "offset.cfg");
  fs::create_directory_symlink(source / "resources", dir / "resources");
  std::ifstream in(source / "machine.cfg");
  std::ofstream out(dir / "machine.cfg");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("max_run_time", 0) != 0) out << line << '\n';
  out << "max_run_time = 10000000\n";
  return dir;
}

}  // namespace

int main(int argc, char** argv) {
  std::string cli = KLUENG_CLI_PATH;
  int runs = 5;
  std::vector<int> sizes = {10'000, 100'000, 1'000'000};
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--cli") cli = argv[i + 1];
    else if (key == "--runs") runs = std::max(1, std::atoi(argv[i + 1]));
    else if (key == "--sizes") {
      sizes.clear();
      for (std::string rest = argv[i + 1]; !rest.empty();) {
        const std::size_t comma = rest.find(',');
        sizes.push_back(std::atoi(rest.substr(0, comma).c_str()));
        rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
      }
    }
  }
  const fs::path scratch = fs::temp_directory_path() / ("klueng-whole-process-" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  const fs::path config = makeConfig(scratch);

  // 1. The programs, written before anything is timed.
  std::vector<fs::path> programs;
  for (int blocks : sizes) {
    programs.push_back(scratch / ("p" + std::to_string(blocks) + ".txt"));
    // By klueng-gen-program: this process stays small (see 2.).
    if (runProcess({KLUENG_GEN_PROGRAM_PATH, std::to_string(blocks), programs.back().string()}).exitCode != 0) {
      std::fprintf(stderr, "cannot generate %s\n", programs.back().c_str());
      return 1;
    }
  }
  // 2. The processes, while this one is still small: a spawned child starts with its
  // parent's peak RSS as its own (the kernel keeps the larger at exec), so every
  // in-process run comes after them.
  ::malloc_trim(0);
  const std::vector<std::string> commands = {"check", "simulate"};
  struct Row {
    std::vector<double> process, inProcess;
    long rssKb = 0;
    int exitCode = 0;
  };
  std::vector<Row> rows(sizes.size() * commands.size());
  for (std::size_t s = 0; s < sizes.size(); ++s)
    for (std::size_t c = 0; c < commands.size(); ++c)
      for (int r = 0; r < runs; ++r) {
        Row& row = rows[s * commands.size() + c];
        const Sample sample = runProcess({cli, commands[c], programs[s].string(), "--config", config.string()});
        row.process.push_back(sample.ms);
        row.rssKb = std::max(row.rssKb, sample.rssKb);
        row.exitCode = std::max(row.exitCode, sample.exitCode);
      }
  // 3. The same calls in-process, as the CLI makes them (a one-way cut keeps no checkpoints).
  const machine::LoadedSetup loaded = machine::loadMachineSetup(config.string());
  for (std::size_t s = 0; s < sizes.size(); ++s)
    for (std::size_t c = 0; c < commands.size(); ++c)
      for (int r = 0; r < runs; ++r)
        rows[s * commands.size() + c].inProcess.push_back(timeIt([&] {
          machine::JobFileRequest request;
          request.stations = loaded.setup.tools.stations;
          const machine::JobFile job =
              machine::loadJobFile(programs[s].string(), loaded.setup, request, io::shippedToolLibrary());
          if (commands[c] == "simulate" && job.program && job.file && !job.hasErrors()) {
            const machine::Timeline timeline = machine::interpret(*job.program, job.setup, request.run);
            cut::CutOptions options;
            options.checkpointBudgetBytes = 0;
            cut::CutSimulator sim(timeline, cut::CutSetup::from(job.file->header, job.setup), options);
            sim.runToEnd();
          }
        }));

  std::printf("%-9s %-8s %10s %10s %7s %9s %12s\n", "blocks", "command", "process", "in-proc", "ratio", "peak RSS",
              "process/1k");
  for (std::size_t s = 0; s < sizes.size(); ++s)
    for (std::size_t c = 0; c < commands.size(); ++c) {
      const Row& row = rows[s * commands.size() + c];
      const double p = median(row.process), q = median(row.inProcess);
      std::printf("%-9d %-8s %8.1f ms %7.1f ms %6.2fx %6ld MB %9.3f ms%s\n", sizes[s], commands[c].c_str(), p, q,
                  p / q, row.rssKb / 1024, p / (sizes[s] / 1000.0), row.exitCode ? "  (exit status not 0!)" : "");
    }
  fs::remove_all(scratch);
  return 0;
}

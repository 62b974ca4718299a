// klueng-bench-whole-process [--cli PATH] [--runs N] [--sizes 10000,100000,1000000]
//                            [--roughing BLOCKS] [--yardstick BLOCKS [--steps 1]] [--rs274 PATH]
//                            [--in-process 0|1]
//
// What a user waits for (issue 13): `klueng-cli check` and `klueng-cli simulate`
// timed as whole processes (exec, page faults, reading, output, exit) on the
// generated 10k / 100k / 1M-block programs, median of N runs, with the peak RSS
// of the largest run; next to them the same work in-process (the calls the CLI
// makes, timed here), and the ratio. The machine's max_run_time is raised to its
// limit so every block of the long programs really runs (the shipped 10 h stops
// the 100k program at block ~25,500).
//
// The roughing program (issue 29 item 14, RoughingGenerator: 100,000 blocks by
// default, 0 = none) weighs on the cut; its `--no-stock` row is the floor
// (reading and interpreting without the cut). With --rs274 /usr/bin/rs274
// (LinuxCNC, installed by hand: a reference, not a dependency) LinuxCNC's
// interpreter runs the same blocks in its dialect, turn about with ours, and
// each roughing row says its ratio to it, of wall time and of CPU time (user +
// system, from the child's rusage: what other work on the machine changes least).
//
// The yardstick (issue 40, YardstickGenerator: 100,000 blocks by default, 0 = none) is the
// program Klueng's speed is judged on: check and simulate beside rs274, as the roughing program.
// Goals: check <= 0.15 x rs274, simulate <= 0.5 x. `--in-process 0` times the processes only
// (`--steps 1`: the yardstick one word a block, so 5,000,000 blocks fit in a program file's 64 MB;
// its peak RSS: `--sizes 0 --roughing 0 --yardstick 5000000 --steps 1 --runs 1 --in-process 0`).
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

#include "scratch_config.h"
#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/setup_files.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using namespace klueng::core;
using Clock = std::chrono::steady_clock;

struct Sample {
  double ms = 0.0;
  double cpuMs = 0.0;  // user + system: what a busy machine changes least
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
  auto msOf = [](const timeval& t) { return t.tv_sec * 1000.0 + t.tv_usec / 1000.0; };
  s.cpuMs = msOf(usage.ru_utime) + msOf(usage.ru_stime);
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

}  // namespace

int main(int argc, char** argv) {
  std::string cli = KLUENG_CLI_PATH;
  std::string rs274;  // LinuxCNC's interpreter, a reference when given (never needed)
  int runs = 5;
  int roughing = 100'000;
  int yardstick = 100'000;
  bool inProcessRuns = true;
  bool steps = false;
  std::vector<int> sizes = {10'000, 100'000, 1'000'000};
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--cli")
      cli = argv[i + 1];
    else if (key == "--rs274")
      rs274 = argv[i + 1];
    else if (key == "--runs")
      runs = std::max(1, std::atoi(argv[i + 1]));
    else if (key == "--roughing")
      roughing = std::max(0, std::atoi(argv[i + 1]));
    else if (key == "--yardstick")
      yardstick = std::max(0, std::atoi(argv[i + 1]));
    else if (key == "--in-process")
      inProcessRuns = std::atoi(argv[i + 1]) != 0;
    else if (key == "--steps")
      steps = std::atoi(argv[i + 1]) != 0;
    else if (key == "--sizes") {
      sizes.clear();
      for (std::string rest = argv[i + 1]; !rest.empty();) {
        const std::size_t comma = rest.find(',');
        if (const int n = std::atoi(rest.substr(0, comma).c_str()); n > 0) sizes.push_back(n);
        rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
      }
    }
  }
  const fs::path scratch = fs::temp_directory_path() / ("klueng-whole-process-" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  const fs::path config = klueng::bench::makeLongRunConfig(scratch);

  // 1. The programs, written before anything is timed, by klueng-gen-program
  // (this process stays small, see 2.).
  struct Program {
    std::string name;
    int blocks = 0;
    fs::path path;
    fs::path ngc;        // the same blocks for rs274, when it is given
    fs::path toolTable;  // rs274's tool table for them
  };
  std::vector<Program> programs;
  auto generate = [&](const std::string& name, int blocks, std::vector<std::string> flags, const char* ext) {
    const fs::path path = scratch / (name + std::to_string(blocks) + ext);
    std::vector<std::string> args = {KLUENG_GEN_PROGRAM_PATH};
    args.insert(args.end(), flags.begin(), flags.end());
    args.push_back(std::to_string(blocks));
    args.push_back(path.string());
    if (runProcess(args).exitCode != 0) {
      std::fprintf(stderr, "cannot generate %s\n", path.c_str());
      std::exit(1);
    }
    return path;
  };
  for (int blocks : sizes) programs.push_back({"generated", blocks, generate("p", blocks, {}, ".txt"), {}, {}});
  if (roughing > 0) {
    programs.push_back({"roughing", roughing, generate("r", roughing, {"--roughing"}, ".txt"), {}, {}});
    if (!rs274.empty()) {
      programs.back().ngc = generate("r", roughing, {"--roughing", "--linuxcnc"}, ".ngc");
      programs.back().toolTable = scratch / "tool.tbl";
      std::ofstream(programs.back().toolTable) << "T1 P1 Z0 D0.8 ;turning\n";
    }
  }
  if (yardstick > 0) {
    std::vector<std::string> flags = {"--yardstick"};
    if (steps) flags.push_back("--steps");
    programs.push_back({"yardstick", yardstick, generate("y", yardstick, flags, ".txt"), {}, {}});
    if (!rs274.empty()) {
      flags.push_back("--linuxcnc");
      programs.back().ngc = generate("y", yardstick, flags, ".ngc");
      programs.back().toolTable = scratch / "yardstick.tbl";  // as ../shared/bench/README.md times it
      std::ofstream(programs.back().toolTable) << "T1 P1 X0 Z0 D0.063 I0 J0 Q2\n";
    }
  }

  // 2. The processes, while this one is still small: a spawned child starts with its
  // parent's peak RSS as its own (the kernel keeps the larger at exec), so every
  // in-process run comes after them. The rows take turns run by run, so a busy
  // moment of the machine falls on all of them alike.
  ::malloc_trim(0);
  struct Row {
    std::string label;
    std::size_t program = 0;
    std::vector<std::string> args;
    bool cut = false;       // in-process: interpret and cut (simulate), interpret only (--no-stock), or load (check)
    bool inProcess = true;  // rs274 has none
    std::vector<double> process, processCpu, inProcessMs;
    long rssKb = 0;
    int exitCode = 0;
  };
  std::vector<Row> rows;
  auto add = [&rows](std::string label, std::size_t program, std::vector<std::string> args, bool cut,
                     bool inProcess = true) {
    Row row;
    row.label = std::move(label);
    row.program = program;
    row.args = std::move(args);
    row.cut = cut;
    row.inProcess = inProcess;
    rows.push_back(std::move(row));
  };
  for (std::size_t p = 0; p < programs.size(); ++p) {
    const std::string& path = programs[p].path.string();
    add("check", p, {cli, "check", path, "--config", config.string()}, false);
    add("simulate", p, {cli, "simulate", path, "--config", config.string()}, true);
    if (programs[p].name == "roughing")  // the floor: everything but the cut
      add("--no-stock", p, {cli, "simulate", path, "--config", config.string(), "--no-stock"}, false);
    if (!programs[p].ngc.empty())
      add("rs274", p, {rs274, "-t", programs[p].toolTable.string(), "-g", programs[p].ngc.string(), "/dev/null"}, false,
          false);
  }
  for (int r = 0; r < runs; ++r)
    for (Row& row : rows) {
      const Sample sample = runProcess(row.args);
      row.process.push_back(sample.ms);
      row.processCpu.push_back(sample.cpuMs);
      row.rssKb = std::max(row.rssKb, sample.rssKb);
      row.exitCode = std::max(row.exitCode, sample.exitCode);
    }
  // 3. The same calls in-process, as the CLI makes them (a one-way cut keeps no checkpoints).
  const machine::LoadedSetup loaded = machine::loadMachineSetup(config.string());
  for (int r = 0; r < runs && inProcessRuns; ++r)
    for (Row& row : rows) {
      if (!row.inProcess) continue;
      const bool interpret = row.label != "check";
      row.inProcessMs.push_back(timeIt([&] {
        job::JobInput request;
        request.path = programs[row.program].path.string();
        request.setup = loaded.setup;
        request.stations = loaded.setup.tools.stations;
        request.timelineNext = interpret;  // as simulate asks
        const std::shared_ptr<const job::Job> job = job::makeJob(request);
        if (!interpret || !job->program() || !job->file() || job->hasErrors()) return;
        if (!row.cut)
          (void)job->timeline();
        else
          (void)job->cut();
      }));
    }

  std::printf("%-9s %-9s %-10s %10s %10s %10s %7s %9s %12s\n", "program", "blocks", "command", "process", "CPU",
              "in-proc", "ratio", "peak RSS", "process/1k");
  for (const Row& row : rows) {
    const Program& program = programs[row.program];
    double rs274Ms = 0.0, rs274Cpu = 0.0;  // LinuxCNC on the same program's blocks
    for (const Row& other : rows)
      if (!other.inProcess && other.program == row.program) {
        rs274Ms = median(other.process);
        rs274Cpu = median(other.processCpu);
      }
    const double p = median(row.process), c = median(row.processCpu), q = median(row.inProcessMs);
    std::printf("%-9s %-9d %-10s %8.1f ms %7.1f ms ", program.name.c_str(), program.blocks, row.label.c_str(), p, c);
    if (row.inProcess && inProcessRuns)
      std::printf("%7.1f ms %6.2fx", q, p / q);
    else
      std::printf("%10s %7s", "-", "-");
    std::printf(" %6ld MB %9.3f ms", row.rssKb / 1024, p / (program.blocks / 1000.0));
    if (rs274Ms > 0.0) std::printf("  %.2f x rs274 (CPU %.2f x)", p / rs274Ms, c / rs274Cpu);
    std::printf("%s\n", row.exitCode ? "  (exit status not 0!)" : "");
  }
  fs::remove_all(scratch);
  return 0;
}

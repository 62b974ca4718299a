// Check + interpret + cut of a generated program (issue 4 target: the
// 100,000-block program on the Ø50 x 100 bar at the default resolution in
// <= 1 s median, <= 300 MB), at 10k / 100k / 1M blocks to show linear cost.
//
//   klueng_bench_cut                           Google Benchmark, all sizes
//   klueng_bench_cut --cut-file=PROGRAM.txt    one run of a program file with
//                                              stage times, peak RSS and a digest
//                                              of the stock left (same digest =
//                                              the same cut, to the bit); the cut
//                                              as the CLI's simulate runs it (no
//                                              stock copies for going back), or
//                                              with --checkpoints as the window's
#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <time.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/interpreter.h"
#include "program_generator.h"

namespace {

using namespace klueng::core;

// The shipped machine files (tools.cfg names the real bitmaps).
machine::MachineSetup shippedSetup() {
  const std::string dir = KLUENG_SOURCE_DIR;
  machine::MachineSetup setup;
  setup.tools = *io::readToolTable(dir + "/tools.cfg").value;
  setup.offsets = *io::readOffsetTable(dir + "/offset.cfg").value;
  setup.machine = *io::readMachineConfig(dir + "/machine.cfg").value;
  return setup;
}

struct Outcome {
  double removed = 0.0;
  bool alarm = false;
  std::size_t moves = 0;
  std::uint64_t digest = 0;
};

// FNV-1a over the bits of every interval left and of the removed volume: a
// faster cut must leave exactly this stock.
std::uint64_t stockDigest(const cut::Stock& stock) {
  std::uint64_t h = 14695981039346656037ull;
  auto mix = [&h](double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    for (int k = 0; k < 8; ++k) h = (h ^ ((bits >> (8 * k)) & 0xFF)) * 1099511628211ull;
  };
  for (int i = 0; i < stock.columnCount(); ++i) {
    for (const cut::Interval& in : stock.column(i)) {
      mix(in.lo);
      mix(in.hi);
    }
    mix(-1.0);  // column boundary
  }
  mix(stock.removedVolume());
  return h;
}

using Clock = std::chrono::steady_clock;
struct StageTimes {
  double parseCheck = 0, interpret = 0, cut = 0;
  double cutCpu = 0;  // the cut's CPU time on this thread: steadier than the wall on a shared machine
};

double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
}

Outcome checkInterpretCut(const io::ProgramFile& file, const machine::MachineSetup& setup, StageTimes* times = nullptr,
                          const cut::CutOptions& cutOptions = {}) {
  const auto t0 = Clock::now();
  const gcode::Program program = gcode::parse(file.gcode, file.gcodeFirstLine);
  gcode::CheckOptions checkOptions;
  checkOptions.toolsWithBitmap = std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8};
  const auto diags = gcode::check(program, checkOptions);
  const auto t1 = Clock::now();
  const machine::Timeline timeline = machine::interpret(program, setup);
  const auto t2 = Clock::now();
  const double cpu0 = threadCpuMs();
  cut::CutSimulator sim(timeline, cut::CutSetup::from(file.header, setup), cutOptions);
  sim.runToEnd();
  const auto t3 = Clock::now();
  const double cpu1 = threadCpuMs();
  if (times) {
    times->parseCheck = std::chrono::duration<double, std::milli>(t1 - t0).count();
    times->interpret = std::chrono::duration<double, std::milli>(t2 - t1).count();
    times->cut = std::chrono::duration<double, std::milli>(t3 - t2).count();
    times->cutCpu = cpu1 - cpu0;
  }
  return {sim.removedVolume(), hasErrors(diags) || timeline.alarm.has_value() || sim.alarm().has_value(),
          timeline.moves.size(), stockDigest(sim.stock())};
}

void BM_CheckInterpretCut(benchmark::State& state) {
  const std::string text = klueng::bench::ProgramGenerator::generate(static_cast<int>(state.range(0)));
  const io::ProgramFile file = *io::parseProgramFile(text).value;
  const machine::MachineSetup setup = shippedSetup();
  Outcome outcome;
  for (auto _ : state) {
    outcome = checkInterpretCut(file, setup);
    // Not DoNotOptimize(double&): its "+m,r" asm corrupts doubles under GCC.
    benchmark::ClobberMemory();
  }
  if (outcome.alarm) state.SkipWithError("the generated program stopped on an error or alarm");
  state.counters["moves"] = static_cast<double>(outcome.moves);
  state.counters["removed_cm3"] = benchmark::Counter(outcome.removed / 1000.0);
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The cut alone, on a timeline built once.
void BM_CutOnly(benchmark::State& state) {
  const std::string text = klueng::bench::ProgramGenerator::generate(static_cast<int>(state.range(0)));
  const io::ProgramFile file = *io::parseProgramFile(text).value;
  const machine::MachineSetup setup = shippedSetup();
  const gcode::Program program = gcode::parse(file.gcode, file.gcodeFirstLine);
  const machine::Timeline timeline = machine::interpret(program, setup);
  for (auto _ : state) {
    cut::CutSimulator sim(timeline, cut::CutSetup::from(file.header, setup));
    sim.runToEnd();
    const double removed = sim.removedVolume();
    benchmark::DoNotOptimize(&removed);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The cut alone on the heavy roughing program (issue 29 item 14): nearly every
// feed touches the stock, most of them over a surface already cut.
void BM_CutOnlyRoughing(benchmark::State& state) {
  const std::string text = klueng::bench::RoughingGenerator::generate(static_cast<int>(state.range(0)));
  const io::ProgramFile file = *io::parseProgramFile(text).value;
  const machine::MachineSetup setup = shippedSetup();
  const gcode::Program program = gcode::parse(file.gcode, file.gcodeFirstLine);
  const machine::Timeline timeline = machine::interpret(program, setup);
  cut::CutOptions options;
  options.checkpointBudgetBytes = 0;  // as the CLI cuts
  double removed = 0.0;
  bool alarm = false;
  for (auto _ : state) {
    cut::CutSimulator sim(timeline, cut::CutSetup::from(file.header, setup), options);
    sim.runToEnd();
    removed = sim.removedVolume();
    alarm = sim.alarm().has_value() || timeline.alarm.has_value();
    benchmark::ClobberMemory();
  }
  if (alarm) state.SkipWithError("the roughing program stopped on an alarm");
  state.counters["moves"] = static_cast<double>(timeline.moves.size());
  state.counters["removed_cm3"] = benchmark::Counter(removed / 1000.0);
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// Step Back (issue 12: <= 16 ms a step on a 100,000-block program): the run is
// paused 70% of the way through; each iteration goes back one block.
void BM_StepBack(benchmark::State& state) {
  const std::string text = klueng::bench::ProgramGenerator::generate(static_cast<int>(state.range(0)));
  const io::ProgramFile file = *io::parseProgramFile(text).value;
  const machine::MachineSetup setup = shippedSetup();
  const gcode::Program program = gcode::parse(file.gcode, file.gcodeFirstLine);
  const machine::Timeline timeline = machine::interpret(program, setup);
  cut::CutOptions options;
  if (state.range(1) == 0) options.checkpointBudgetBytes = 0;  // the old way: re-cut from the bar
  cut::CutSimulator sim(timeline, cut::CutSetup::from(file.header, setup), options);
  const auto& snaps = timeline.snapshots;
  std::size_t k = snaps.size() * 7 / 10;
  sim.advanceTo(snaps[k].time);
  std::size_t moved = 0;
  for (auto _ : state) {
    // Back to the start of the previous block that moves (blocks without motion take no time).
    const double now = sim.time();
    while (k > 0 && snaps[k].time >= now) --k;
    moved += sim.movesToCut(snaps[k].time);
    sim.advanceTo(snaps[k].time);
    benchmark::ClobberMemory();
  }
  state.counters["checkpoints"] = static_cast<double>(sim.checkpointCount());
  state.counters["recut_moves"] = static_cast<double>(moved) / static_cast<double>(state.iterations());
}

// Scrubbing: jumps to pseudo-random times anywhere in the run, back and forth.
void BM_Scrub(benchmark::State& state) {
  const std::string text = klueng::bench::ProgramGenerator::generate(static_cast<int>(state.range(0)));
  const io::ProgramFile file = *io::parseProgramFile(text).value;
  const machine::MachineSetup setup = shippedSetup();
  const gcode::Program program = gcode::parse(file.gcode, file.gcodeFirstLine);
  const machine::Timeline timeline = machine::interpret(program, setup);
  cut::CutSimulator sim(timeline, cut::CutSetup::from(file.header, setup));
  sim.runToEnd();  // the first pass keeps the checkpoints
  std::uint64_t seed = 12345;
  for (auto _ : state) {
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    const double t = timeline.cycleTime() * static_cast<double>(seed >> 11) / 9007199254740992.0;
    sim.advanceTo(t);
    benchmark::ClobberMemory();
  }
}

}  // namespace

BENCHMARK(BM_StepBack)->Args({100'000, 1})->Iterations(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepBack)->Args({100'000, 0})->Iterations(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Scrub)->Arg(100'000)->Iterations(500)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CheckInterpretCut)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CutOnly)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CutOnlyRoughing)->Arg(100'000)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  cut::CutOptions cutOptions;
  cutOptions.checkpointBudgetBytes = 0;  // as the CLI cuts
  for (int i = 1; i < argc; ++i)
    if (std::string_view(argv[i]) == "--checkpoints")
      cutOptions.checkpointBudgetBytes = cut::CutOptions{}.checkpointBudgetBytes;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.rfind("--cut-file=", 0) != 0) continue;
    const auto file = io::readProgramFile(std::string(arg.substr(11)));
    if (!file.ok()) {
      std::fprintf(stderr, "cannot read %s\n", argv[i] + 11);
      return 1;
    }
    StageTimes times;
    const Outcome o = checkInterpretCut(*file.value, shippedSetup(), &times, cutOptions);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf(
        "moves %zu, parse+check %.1f ms, interpret %.1f ms, cut %.1f ms (CPU %.1f ms), total %.1f ms, "
        "removed %.0f mm3, "
        "%s, peak RSS %.1f MB, stock digest %016llx\n",
        o.moves, times.parseCheck, times.interpret, times.cut, times.cutCpu,
        times.parseCheck + times.interpret + times.cut, o.removed, o.alarm ? "STOPPED" : "ran to the end",
        static_cast<double>(usage.ru_maxrss) / 1024.0, static_cast<unsigned long long>(o.digest));
    return o.alarm ? 1 : 0;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

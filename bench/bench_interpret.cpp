// Interpreting a generated 100,000-block program (G96 roughing, arcs, dwells,
// the last tenth under G42) into a full Timeline (issue 3 target: <= 100 ms
// median, <= 150 MB). Parsing is done once, outside the timed loop.
// KLUENG_BENCH_PROGRAM=path interprets that program file instead.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/messages.h"
#include "program_generator.h"

namespace {

using namespace klueng::core;

gcode::Program loadProgram(int blocks) {
  io::ProgramFile file;
  if (const char* path = std::getenv("KLUENG_BENCH_PROGRAM"); path && *path) {
    auto read = io::readProgramFile(path);
    if (read.value) file = *read.value;
  } else {
    auto parsed = io::parseProgramFile(klueng::bench::ProgramGenerator::generate(blocks));
    if (parsed.value) file = *parsed.value;
  }
  return gcode::parse(file.gcode, file.gcodeFirstLine);
}

machine::MachineSetup benchSetup() {
  machine::MachineSetup setup;
  setup.offsets.offsets[0] = {0.0, 0.0, 0.8, 3};  // T0101: the shipped outside turning tool
  return setup;
}

double peakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kB
}

void BM_Interpret(benchmark::State& state) {
  const gcode::Program program = loadProgram(static_cast<int>(state.range(0)));
  const machine::MachineSetup setup = benchSetup();
  std::size_t moves = 0, compensated = 0;
  double cycle = 0.0;
  bool alarm = false;
  std::string alarmText;
  for (auto _ : state) {
    const machine::Timeline t = machine::interpret(program, setup);
    moves = t.moves.size();
    cycle = t.cycleTime();
    alarm = t.alarm.has_value();
    if (alarm)
      alarmText =
          t.alarm->code + " line " + std::to_string(t.alarm->range.line) + ": " + formatMessage(*t.alarm, Lang::En);
    compensated = 0;
    for (const auto& m : t.moves) compensated += m.compensated ? 1 : 0;
    benchmark::DoNotOptimize(t.moves.data());
  }
  if (alarm) state.SkipWithError(("the program stopped with an alarm: " + alarmText).c_str());
  state.counters["blocks"] = static_cast<double>(program.blocks.size());
  state.counters["moves"] = static_cast<double>(moves);
  state.counters["compensated"] = static_cast<double>(compensated);
  state.counters["cycle_s"] = cycle;
  state.counters["peak_rss_MB"] = peakRssMb();
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(program.blocks.size()));
}

// Issue 9 target: a 1,000-iteration WHILE loop of 10 blocks (WHILE, END and
// 8 inside: counters, a computed diameter, a cut and a retract) interprets in
// <= 10 ms. Parsing is outside the timed loop, as above.
void BM_MacroLoop(benchmark::State& state) {
  const std::string text =
      "O0001 (MACRO LOOP)\n"
      "G21 G98 G00 X40. Z2.\n"
      "#1 = 0\n"
      "WHILE [#1 LT 1000] DO1\n"
      "#2 = #1 MOD 10\n"
      "#3 = 40. - #2 * 0.5\n"
      "#4 = #3 + 2.\n"
      "G00 X#4\n"
      "G01 X#3 F500.\n"
      "G01 W-0.01\n"
      "G00 X#4\n"
      "#1 = #1 + 1\n"
      "END1\n"
      "M30\n";
  const gcode::Program program = gcode::parse(text, 1);
  const machine::MachineSetup setup = benchSetup();
  std::size_t snapshots = 0;
  for (auto _ : state) {
    const machine::Timeline t = machine::interpret(program, setup);
    if (t.alarm) state.SkipWithError(("alarm " + t.alarm->code).c_str());
    snapshots = t.snapshots.size();
    benchmark::DoNotOptimize(t.moves.data());
  }
  state.counters["blocks_run"] = static_cast<double>(snapshots);
}

}  // namespace

BENCHMARK(BM_Interpret)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MacroLoop)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

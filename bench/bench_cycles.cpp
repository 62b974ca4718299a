// Canned cycles: interpreting a G71 roughing of a long stepped shaft with a
// small depth of cut (thousands of passes, each crossing a 40-step profile),
// a G70 finish under G42 and a fine G76 thread, into a full Timeline.
#include <benchmark/benchmark.h>

#include <string>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/machine/interpreter.h"

namespace {

using namespace klueng::core;

// Start X200 Z2; a 40-step profile from X20 up to X180 over 400 mm;
// U0.02 per side: (200 - 20) / 2 / 0.02 = 4500 roughing passes.
std::string program() {
  std::string p =
      "G98 G97 S500 M03 T0101\nG00 X200. Z2.\n"
      "G71 U0.02 R0.01\nG71 P10 Q20 U0.4 W0.1 F200.\n";
  p += "N10 G00 X20.\n";
  for (int i = 1; i <= 40; ++i) {
    p += "G01 Z" + std::to_string(-10 * i) + ".\n";
    p += (i == 40 ? "N20 X" : "X") + std::to_string(20 + 4 * i) + ".\n";
  }
  p += "G42 G00 X200. Z2.\nG70 P10 Q20\nG40 G00 X250. Z50.\n"
       "G00 X32. Z5.\nG76 P010060 Q10 R0.01\nG76 X28.16 Z-30. P920 Q20 F1.5\n";
  return p;
}

void BM_InterpretCycles(benchmark::State& state) {
  const gcode::Program parsed = gcode::parse(program(), 1);
  machine::MachineSetup setup;
  setup.offsets.offsets[0] = {0.0, 0.0, 0.8, 3};
  std::size_t moves = 0;
  for (auto _ : state) {
    machine::Timeline t = machine::interpret(parsed, setup);
    if (t.alarm) state.SkipWithError(("alarm " + t.alarm->code).c_str());
    moves = t.moves.size();
    benchmark::DoNotOptimize(t);
  }
  state.counters["moves"] = static_cast<double>(moves);
}
BENCHMARK(BM_InterpretCycles)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

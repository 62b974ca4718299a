// The part designer's wait (issue 14): one change of a design to its verdict —
// generate, compile, cut twice (real and ideal tools), read the features and
// compare with the drawing — for the shipped parts, in each dialect.
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include "klueng/core/design/design_loop.h"

namespace {

using namespace klueng::core;

design::PartDesign shipped(const char* name) {
  std::ifstream in(std::string(KLUENG_SOURCE_DIR "/resources/parts/") + name);
  std::ostringstream s;
  s << in.rdbuf();
  return *design::readPartDesign(s.str(), name).value;
}

void BM_DesignLoop(benchmark::State& state, const char* name, gcode::Dialect dialect) {
  const machine::MachineSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
  const design::PartDesign part = shipped(name);
  design::GenerateOptions options;
  options.dialect = dialect;
  options.machine = setup.machine;
  for (auto _ : state) {
    const design::DesignLoop loop = design::runDesignLoop(part, options, setup);
    if (!loop.matches()) state.SkipWithError("the part does not match its drawing");
    benchmark::DoNotOptimize(loop.features.outside.size());
  }
}

BENCHMARK_CAPTURE(BM_DesignLoop, step_shaft_fanuc, "step-shaft.json", gcode::Dialect::Fanuc)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DesignLoop, step_shaft_classic, "step-shaft.json", gcode::Dialect::Classic)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DesignLoop, threaded_bush_haas, "threaded-bush.json", gcode::Dialect::Haas)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

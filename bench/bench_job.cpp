// The editor's check of a long program (issue 12: one edit of a 100,000-block
// program -> new diagnostics on screen <= 60 ms). job::makeJob is what the
// GUI runs off its thread after each typing pause; its stages are timed alone
// so the slowest one shows. The whole window is measured by
// tests/gui/gui_edit_probe.cpp.
#include <benchmark/benchmark.h>

#include <string>
#include <string_view>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/dialect_fit.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/infer/tool_inference.h"
#include "program_generator.h"

namespace {

using namespace klueng::core;

std::string gcodeOf(int blocks, bool withError) {
  const std::string file = klueng::bench::ProgramGenerator::generate(blocks);
  std::size_t pos = 0;
  for (int i = 0; i < 6; ++i) pos = file.find('\n', pos) + 1;
  std::string text = file.substr(pos);
  if (withError) {  // line ~50,000 gets a second X word, as the GUI probe types it
    std::size_t at = 0;
    for (int i = 0; i < blocks / 2; ++i) at = text.find('\n', at) + 1;
    text.insert(text.find('\n', at), " X1");
  }
  return text;
}

gcode::CheckOptions options(const machine::LoadedSetup& loaded) {
  gcode::CheckOptions o;
  o.toolsWithBitmap = loaded.toolsWithBitmap();
  o.turretStations = loaded.setup.tools.stations;
  return o;
}

void BM_CheckJob(benchmark::State& state) {
  const std::string text = gcodeOf(static_cast<int>(state.range(0)), state.range(1) != 0);
  const machine::LoadedSetup loaded = machine::loadMachineSetup(KLUENG_SOURCE_DIR);
  std::size_t errors = 0;
  for (auto _ : state) {
    // As the editor asks (MainWindow::checkRequest): the text with its header.
    job::JobInput input;
    input.setup = loaded.setup;
    input.stations = loaded.setup.tools.stations;
    io::ProgramFile file;
    file.header.diameter = 50;
    file.header.length = 100;
    file.header.stockSource = io::StockSource::Header;
    file.gcodeFirstLine = 7;
    file.gcode = text;
    input.file = std::move(file);
    const auto made = job::makeJob(std::move(input));
    const std::vector<Diagnostic> diagnostics = made->programFileDiagnostics();
    errors = static_cast<std::size_t>(
        std::count_if(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& d) { return isError(d.severity); }));
  }
  state.counters["errors"] = static_cast<double>(errors);
}

void BM_Stage(benchmark::State& state) {
  const std::string text = gcodeOf(100'000, state.range(1) != 0);
  const machine::LoadedSetup loaded = machine::loadMachineSetup(KLUENG_SOURCE_DIR);
  const gcode::Program program = gcode::parse(text, 7);
  const std::vector<Diagnostic> found = gcode::check(program, options(loaded));
  for (auto _ : state) {
    switch (state.range(0)) {
      case 0: benchmark::DoNotOptimize(gcode::parse(text, 7).blocks.data()); break;
      case 1: benchmark::DoNotOptimize(gcode::check(program, options(loaded)).data()); break;
      case 2:
        benchmark::DoNotOptimize(machine::inferTools(program, text, 7, loaded.setup, io::shippedToolLibrary(), {},
                                                     loaded.setup.tools.stations)
                                     .choices.data());
        break;
      case 3: benchmark::DoNotOptimize(gcode::suggestDialect(program, options(loaded), found).has_value()); break;
    }
  }
  static const char* const names[] = {"parse", "check", "inferTools", "suggestDialect"};
  state.SetLabel(std::string(names[state.range(0)]) + (state.range(1) ? ", with an error" : ", clean"));
}

}  // namespace

BENCHMARK(BM_CheckJob)->Args({100'000, 0})->Args({100'000, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Stage)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();

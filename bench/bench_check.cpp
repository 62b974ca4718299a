// Lex + parse + check of a generated 100,000-block program held in memory
// (issue 2 target: <= 50 ms median, <= 50 MB).
#include <benchmark/benchmark.h>

#include <string_view>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "program_generator.h"

namespace {

using namespace klueng::core;

// The G-code part of a generated file: everything after the 6 header lines.
std::string_view afterHeader(std::string_view file) {
  std::size_t pos = 0;
  for (int i = 0; i < 6; ++i) pos = file.find('\n', pos) + 1;
  return file.substr(pos);
}

void checkProgram(benchmark::State& state, gcode::Dialect dialect) {
  const std::string file = klueng::bench::ProgramGenerator::generate(static_cast<int>(state.range(0)));
  const std::string_view text = afterHeader(file);
  gcode::CheckOptions options;
  options.dialect = dialect;
  options.toolsWithBitmap = std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8};
  std::size_t diagnostics = 0;
  for (auto _ : state) {
    const gcode::Program program = gcode::parse(text, 7);
    const auto diags = gcode::check(program, options);
    diagnostics = diags.size();
    benchmark::DoNotOptimize(program.blocks.data());
  }
  if (diagnostics != 0) state.SkipWithError("the generated program has diagnostics");
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_ParseCheckFanuc(benchmark::State& state) { checkProgram(state, gcode::Dialect::Fanuc); }
void BM_ParseCheckClassic(benchmark::State& state) { checkProgram(state, gcode::Dialect::Classic); }

void BM_ParseOnly(benchmark::State& state) {
  const std::string file = klueng::bench::ProgramGenerator::generate(static_cast<int>(state.range(0)));
  const std::string_view text = afterHeader(file);
  for (auto _ : state) {
    const gcode::Program program = gcode::parse(text, 7);
    benchmark::DoNotOptimize(program.blocks.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

}  // namespace

BENCHMARK(BM_ParseCheckFanuc)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseCheckClassic)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseOnly)->Arg(100'000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

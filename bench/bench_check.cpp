// Lex + parse + check of a generated 100,000-block program held in memory
// (issue 2 target: <= 50 ms median, <= 50 MB).
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <string>
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

// The yardstick program (issue 40 item 1): lexing and parsing alone, and with the grammar check
// (the checker's block pass and checkFlow with its ProgramIndex), in memory: the part of
// `klueng-cli check` that is the parser's and the checker's.
void BM_YardstickParse(benchmark::State& state) {
  const std::string file = klueng::bench::YardstickGenerator::generate(static_cast<int>(state.range(0)));
  const std::string_view text = afterHeader(file);
  for (auto _ : state) {
    const gcode::Program program = gcode::parse(text, 7);
    benchmark::DoNotOptimize(program.blocks.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_YardstickParseCheck(benchmark::State& state) {
  const std::string file = klueng::bench::YardstickGenerator::generate(static_cast<int>(state.range(0)));
  const std::string_view text = afterHeader(file);
  gcode::CheckOptions options;
  options.toolsWithBitmap = std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8};
  for (auto _ : state) {
    const gcode::Program program = gcode::parse(text, 7);
    const auto diags = gcode::check(program, options);
    benchmark::DoNotOptimize(diags.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

}  // namespace

BENCHMARK(BM_ParseCheckFanuc)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseCheckClassic)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseOnly)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_YardstickParse)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_YardstickParseCheck)->Arg(100'000)->Unit(benchmark::kMillisecond);

// `klueng_bench_check --check-file=PROGRAM.txt` reads a program file, parses
// and checks it once and prints the peak resident memory: the figure for the
// <= 50 MB target, without the benchmark's own generator in the process.
int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.rfind("--check-file=", 0) != 0) continue;
    std::FILE* f = std::fopen(argv[i] + 13, "rb");
    if (!f) {
      std::fprintf(stderr, "cannot open %s\n", argv[i] + 13);
      return 1;
    }
    std::string file;
    char buf[65536];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) file.append(buf, n);
    std::fclose(f);
    const std::clock_t cpuStart = std::clock();
    const auto start = std::chrono::steady_clock::now();
    const gcode::Program program = gcode::parse(afterHeader(file), 7);
    const auto diags = gcode::check(program);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const double cpuMs = 1000.0 * static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("blocks %zu, diagnostics %zu, %.1f ms wall, %.1f ms CPU, peak RSS %.1f MB\n", program.blocks.size(),
                diags.size(), ms, cpuMs, static_cast<double>(usage.ru_maxrss) / 1024.0);
    return diags.empty() ? 0 : 1;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

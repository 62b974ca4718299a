// Reading files (issue 2 §4): a generated 100,000-block program through
// parseProgramFile (UTF-8 check, line split, header), the same bytes as
// TIS-620, and decoding the shipped tool bitmaps.
#include <benchmark/benchmark.h>

#include <string>

#include "klueng/core/io/image.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "program_generator.h"

namespace {

using namespace klueng::core;

void BM_ParseProgramFileUtf8(benchmark::State& state) {
  const std::string file = klueng::bench::ProgramGenerator::generate(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const auto r = io::parseProgramFile(file, {}, "bench.txt");
    if (!r.ok()) state.SkipWithError("the generated program does not read cleanly");
    benchmark::DoNotOptimize(r.value->gcode.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * file.size()));
}

void BM_ParseProgramFileTis620(benchmark::State& state) {
  std::string file = klueng::bench::ProgramGenerator::generate(static_cast<int>(state.range(0)));
  // One TIS-620 byte (a Thai letter in a comment) makes the whole file TIS-620.
  file.insert(file.find('\n', file.find("O0001")), " (\xA1\xC5\xD6\xA7)");
  for (auto _ : state) {
    const auto r = io::parseProgramFile(file, {}, "bench.txt");
    if (!r.value || r.value->encoding != io::SourceEncoding::Tis620) state.SkipWithError("not read as TIS-620");
    benchmark::DoNotOptimize(r.value->gcode.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * file.size()));
}

void BM_ReadShippedToolBitmaps(benchmark::State& state) {
  const auto tools = io::readToolTable(std::string(KLUENG_SOURCE_DIR) + "/tools.cfg");
  if (!tools.ok()) {
    state.SkipWithError("shipped tools.cfg does not read");
    return;
  }
  for (auto _ : state)
    for (int t = 1; t <= io::kToolCount; ++t) {
      const auto image = io::readImage(tools.value->bitmapPath(t));
      benchmark::DoNotOptimize(image.value->pixels.data());
    }
}

}  // namespace

BENCHMARK(BM_ParseProgramFileUtf8)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseProgramFileTis620)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadShippedToolBitmaps)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();

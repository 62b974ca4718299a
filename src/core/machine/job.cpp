// One compiled job (job.h).
#include "klueng/core/machine/job.h"

#include <algorithm>
#include <filesystem>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/decimal_point.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/machine/subprogram_files.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine {

std::vector<int> toolsWithBitmap(const MachineSetup& setup) {
  std::vector<int> out;
  std::error_code ec;
  const int stations = static_cast<int>(setup.tools.bitmap.size());
  for (int t = 1; t <= stations; ++t) {
    const std::string path = setup.tools.bitmapPath(t);
    if (setup.tools.bitmapUnreadable[static_cast<std::size_t>(t - 1)]) continue;
    if (!path.empty() && std::filesystem::is_regular_file(path, ec)) out.push_back(t);
  }
  return out;
}

CompiledJob compileJob(const io::ProgramFile& file, const MachineSetup& setup, const JobOptions& options) {
  CompiledJob job;
  job.program = gcode::parse(file.gcode, file.gcodeFirstLine);
  if (!options.folder.empty())
    job.diagnostics = attachSubprogramFiles(job.program, options.folder, options.run.dialect);
  // Lengths without a decimal point as the setup reads them (decided by the check: point_reading.h).
  if (!setup.machine.calculatorInput)
    gcode::readLengthsInIncrements(
        job.program, gcode::powerOnUnitsOf(options.run.dialect, options.run.powerOnUnits), options.run.dialect);
  gcode::CheckOptions check;
  check.dialect = options.run.dialect;
  check.powerOnUnits = options.run.powerOnUnits;
  check.turretStations = setup.tools.stations;
  // No bitmap at all means no tool table was read: T words are not checked against it.
  if (std::vector<int> tools = toolsWithBitmap(setup); !tools.empty()) check.toolsWithBitmap = std::move(tools);
  std::vector<Diagnostic> found = gcode::check(job.program, check);
  job.diagnostics.insert(job.diagnostics.end(), found.begin(), found.end());
  // The run needs a bar: a header without a size is reported on its line (SPEC 2).
  if (file.header.diameter <= 0 || file.header.length <= 0) {
    Diagnostic d;
    d.code = file.header.diameter <= 0 ? codes::kDiameterMissing : codes::kLengthMissing;
    d.range = SourceRange{file.header.diameter <= 0 ? 4 : 5, 1, 0};
    job.diagnostics.push_back(d);
  }
  std::stable_sort(job.diagnostics.begin(), job.diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
    if (a.range.file != b.range.file) return a.range.file < b.range.file;
    return a.range.line != b.range.line ? a.range.line < b.range.line : a.range.column < b.range.column;
  });
  if (!job.hasErrors()) job.timeline = interpret(job.program, setup, options.run);
  return job;
}

}  // namespace klueng::core::machine

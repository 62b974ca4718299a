// One program's check for the GUI (see job_check.h).
#include "klueng/core/machine/job_check.h"

#include "klueng/core/gcode/dialect_fit.h"
#include "klueng/core/gcode/parser.h"

namespace klueng::core::machine {

JobCheck checkJob(std::string_view gcode, int firstLine, gcode::CheckOptions options, const MachineSetup& setup,
                  const io::ToolLibrary& library, const std::vector<StationOverride>& overrides, int stations) {
  JobCheck result;
  const gcode::Program program = gcode::parse(gcode, firstLine);
  result.inference = inferTools(program, gcode, firstLine, setup, library, overrides, stations);
  if (options.toolsWithBitmap) {
    std::vector<int> withBitmap;
    for (int t = 1; t <= io::kMaxStations; ++t)
      if (!result.inference.setup.tools.bitmap[static_cast<std::size_t>(t - 1)].empty()) withBitmap.push_back(t);
    options.toolsWithBitmap = withBitmap;
  }
  result.diagnostics = gcode::check(program, options);
  // The dialect that accepts a program this one refuses (I102), for the offer bar.
  if (auto fit = gcode::suggestDialect(program, options, result.diagnostics)) {
    result.fit = fit->dialect;
    result.fitBlocks = fit->blocks;
    result.diagnostics.push_back(fit->note);
  }
  return result;
}

StockInference inferStockFromText(std::string_view gcode, int firstLine, const MachineSetup& setup,
                                  const RunOptions& options) {
  return inferStock(gcode::parse(gcode, firstLine), setup, options);
}

}  // namespace klueng::core::machine

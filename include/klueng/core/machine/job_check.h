#pragma once
// The check of one program as the GUI needs it, in one call: parse, the tools
// the program asks for (library choices), the grammar check against those
// tools, and the dialect that fits when this one refuses the program. The GUI
// asks this instead of parsing G-code itself.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/machine/stock_inference.h"
#include "klueng/core/machine/tool_inference.h"
#include "klueng/core/units.h"

namespace klueng::core::machine {

struct JobCheck {
  std::vector<Diagnostic> diagnostics;  // the checker's, plus the I102 note when another dialect fits
  ToolInference inference;              // the job's tools (setup amended by library choices)
  std::optional<gcode::Dialect> fit;    // another dialect that accepts the whole program
  int fitBlocks = 0;
  DisplayUnits units = DisplayUnits::Mm;  // the program's: its last G20/G21, else the power-on units
};

// options.toolsWithBitmap, when set, is replaced by the stations that have a
// tool after inference.
// `folder`: where subprogram files called by the program are read from
// (machine/subprogram_files.h; empty = none). The editor shows one file, so an
// error inside a subprogram file is reported once, as E412 on the call that
// reaches that file.
// `chosenCalculatorInput`: the user's reading of lengths without a decimal
// point for this file (io::JobHeader::calculatorInput); the inference's setup
// carries the reading used (machine.calculatorInput; machine/point_reading.h).
// `chosenToolsBeyondCentre`: the tool side chosen for this file (JobHeader::toolsBeyondCentre).
JobCheck checkJob(std::string_view gcode, int firstLine, gcode::CheckOptions options, const MachineSetup& setup,
                  const io::ToolLibrary& library, const std::vector<StationOverride>& overrides, int stations,
                  const std::string& folder = {}, std::optional<bool> chosenCalculatorInput = std::nullopt,
                  std::optional<bool> chosenToolsBeyondCentre = std::nullopt);

// inferStock on G-code text, parsed here and read as checkJob reads it
// (lengths without a decimal point: point_reading.h, `chosenCalculatorInput`
// being the file's own choice).
StockInference inferStockFromText(std::string_view gcode, int firstLine, const MachineSetup& setup,
                                  const RunOptions& options, std::optional<bool> chosenCalculatorInput = std::nullopt);

}  // namespace klueng::core::machine

#pragma once
// Tools from the program in the GUI (core/machine/tool_inference.h): the
// background check also decides the job's tools, so the checker's E305, the
// run and Tool Select all see the same setup.
//
// Public API
//   checkWithTools(text, firstLine, options, setup, overrides, stations)
//        parse + inferTools + check (T words against the amended table); runs off the GUI thread
//   loadToolOverrides(path) / saveToolOverrides(path, list)
//        the stations the user set for one program file (QSettings "Klueng"/"klueng", per file)
//   sameTools(a, b)    whether two setups have the same tool table, offsets, tool side and
//                      reading of lengths without a decimal point
#include <QString>
#include <optional>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/machine/tool_inference.h"
#include "klueng/core/units.h"

namespace klueng::gui {

struct JobToolsResult {
  std::vector<core::Diagnostic> diagnostics;
  core::machine::ToolInference inference;
  // Another dialect that accepts the whole program (the current one refuses it).
  std::optional<core::gcode::Dialect> fit;
  int fitBlocks = 0;
  core::DisplayUnits units = core::DisplayUnits::Mm;  // the program's (its G20/G21, else the power-on units)
};

JobToolsResult checkWithTools(const QString& text, int firstLine, core::gcode::CheckOptions options,
                              const core::machine::MachineSetup& setup,
                              const std::vector<core::machine::StationOverride>& overrides, int stations,
                              const QString& folder = {}, std::optional<bool> calculatorInput = std::nullopt,
                              std::optional<bool> toolsBeyondCentre = std::nullopt);

std::vector<core::machine::StationOverride> loadToolOverrides(const QString& filePath);
void saveToolOverrides(const QString& filePath, const std::vector<core::machine::StationOverride>& overrides);

bool sameTools(const core::machine::MachineSetup& a, const core::machine::MachineSetup& b);

// Hands the pages a finished check or compile freed back to the system, off the
// GUI thread: the worker threads' malloc arenas keep them otherwise, and a
// 2,000,000-line program's parse leaves hundreds of MB resident (issue 29 item 8).
void releaseFreedMemory();

}  // namespace klueng::gui

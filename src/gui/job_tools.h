#pragma once
// Tools from the program in the GUI (core/infer/tool_inference.h): the
// background check's Job (core/job/job.h) also decides the job's tools, so the
// checker's E305, the run and Tool Select all see the same setup.
//
// Public API
//   loadToolOverrides(path) / saveToolOverrides(path, list)
//        the stations the user set for one program file (QSettings "Klueng"/"klueng", per file)
//   sameTools(a, b)    whether two setups have the same tool table, offsets, tool side and
//                      reading of lengths without a decimal point
#include <QString>
#include <optional>
#include <vector>

#include "klueng/core/infer/tool_inference.h"

namespace klueng::gui {

std::vector<core::machine::StationOverride> loadToolOverrides(const QString& filePath);
void saveToolOverrides(const QString& filePath, const std::vector<core::machine::StationOverride>& overrides);

bool sameTools(const core::machine::MachineSetup& a, const core::machine::MachineSetup& b);

// Hands the pages a finished check or compile freed back to the system, off the
// GUI thread: the worker threads' malloc arenas keep them otherwise, and a
// 2,000,000-line program's parse leaves hundreds of MB resident (issue 29 item 8).
void releaseFreedMemory();

}  // namespace klueng::gui

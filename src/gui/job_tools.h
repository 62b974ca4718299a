#pragma once
// Tools from the program in the GUI (core/machine/tool_inference.h): the
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

#include "klueng/core/machine/tool_inference.h"

namespace klueng::gui {

std::vector<core::machine::StationOverride> loadToolOverrides(const QString& filePath);
void saveToolOverrides(const QString& filePath, const std::vector<core::machine::StationOverride>& overrides);

bool sameTools(const core::machine::MachineSetup& a, const core::machine::MachineSetup& b);

}  // namespace klueng::gui

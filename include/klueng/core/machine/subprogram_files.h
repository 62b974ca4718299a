#pragma once
// Subprogram files (issue 9): the folder of a program is the control's memory.
// A program that calls O1000 (M98 P1000, G65 P1000, G66 P1000) which is not an
// O block of its own file gets the file O1000.nc (or 1000.nc, O1000, O1000.txt,
// zero-padded O0100.nc for P100, any case) from that folder appended to it:
// its blocks and expressions go after the program's own, with Block::file and
// SourceRange::file set to its index in Program::files. Files called by those
// files are appended too (at most kMaxSubprogramFiles). A missing file is not
// reported here: the checker reports the call (E404) with its line and column.
#include <string>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/program.h"

namespace klueng::core::machine {

inline constexpr int kMaxSubprogramFiles = 200;

// Returns the diagnostics of reading the appended files (their F-codes and
// lexical errors carry the file's index in range.file).
std::vector<Diagnostic> attachSubprogramFiles(gcode::Program& program, const std::string& folder,
                                              gcode::Dialect dialect);

// The path of the file a diagnostic belongs to: `mainPath` for file 0.
std::string diagnosticFile(const gcode::Program& program, const Diagnostic& d, const std::string& mainPath);

}  // namespace klueng::core::machine

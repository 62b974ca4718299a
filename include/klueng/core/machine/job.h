#pragma once
// One compiled job (issue 12, first step): a program file plus a machine setup
// plus options -> the parsed program with its subprogram files, every
// diagnostic of the check (sorted), and, when there is no error, the timeline.
// The GUI's run and the printed drawing ask this instead of parsing G-code.
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/timeline.h"

namespace klueng::core::machine {

struct JobOptions {
  RunOptions run;
  std::string folder;  // where subprogram files come from (empty = none)
};

struct CompiledJob {
  gcode::Program program;
  std::vector<Diagnostic> diagnostics;  // the check, the subprogram files, the stock size; sorted
  std::optional<Timeline> timeline;     // only when nothing is an error
  bool hasErrors() const { return core::hasErrors(diagnostics); }
};

// The stations whose bitmap (tools.cfg line or library tool) names an existing
// file: the T words the check accepts (E305). The one meaning for the editor,
// a run, the CLI and the reports.
std::vector<int> toolsWithBitmap(const MachineSetup& setup);

CompiledJob compileJob(const io::ProgramFile& file, const MachineSetup& setup, const JobOptions& options);

}  // namespace klueng::core::machine

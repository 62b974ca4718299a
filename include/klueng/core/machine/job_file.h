#pragma once
// One program file made ready to run, in one call (issue 12): read once,
// parsed once (with the subprogram files it calls from its folder), the tools
// it asks for, the grammar check against those tools, the dialect that fits
// when this one refuses it, and the stock resolved (--stock, the header, Job
// details, or inferred). The CLI's check and simulate use only this; the
// timeline is then machine::interpret(*job.program, job.setup, run).
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/tool_inference.h"

namespace klueng::core::machine {

struct JobFileRequest {
  RunOptions run;                          // dialect and power-on units (the check uses them too)
  io::JobHeader defaultsForPlain;          // text fields of a file without a header
  std::optional<io::JobHeader> stock;      // a stock given for this run (--stock): wins over the file's
  std::vector<StationOverride> overrides;  // stations set by the user (--tool)
  // Lengths without a decimal point (--decimal-point): wins over the file's
  // own choice, its numbers and the machine (machine/point_reading.h).
  std::optional<bool> calculatorInput;
  int stations = 0;                        // highest T station (the dialect's limit, else the turret)
  // False when no tool table was read: no library choices, and T words are not checked.
  bool toolTable = true;
};

struct JobFile {
  std::string path;
  std::optional<io::ProgramFile> file;    // the header holds the resolved stock
  std::optional<gcode::Program> program;  // subprogram files appended (Program::files)
  MachineSetup setup;                     // the setup with the program's tools and its
                                          // reading of lengths without a point (machine.calculatorInput)
  std::vector<Diagnostic> diagnostics;    // file, subprogram files and checker; sorted by file, line, column
  std::vector<Diagnostic> toolNotes;      // I401-I410: which library tool each station got
  std::vector<Diagnostic> stockNotes;     // I150-I157: where the stock came from
  bool unreadable = false;                // the program file itself could not be read
  bool hasErrors() const { return core::hasErrors(diagnostics); }
  // The file a diagnostic belongs to: the program or one of its subprogram files.
  std::string fileOf(const Diagnostic& d) const;
};

JobFile loadJobFile(const std::string& path, const MachineSetup& setup, const JobFileRequest& request,
                    const io::ToolLibrary& library);

}  // namespace klueng::core::machine

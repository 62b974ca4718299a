#pragma once
// Runs a checked Program into a Timeline (SPEC 6-10).
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/timeline.h"

namespace klueng::core::machine {

struct RunOptions {
  gcode::Dialect dialect = gcode::Dialect::Fanuc;
  bool optionalStop = false;   // M01 stops when on
  bool blockSkip = false;      // '/' blocks skipped when on
  bool stopAtM00 = false;      // false: a headless run records the stop and continues
};

struct MachineSetup {
  io::MachineConfig machine;
  io::OffsetTable offsets;
  io::ToolTable tools;
};

Timeline interpret(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options = {});

}  // namespace klueng::core::machine

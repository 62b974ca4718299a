#pragma once
// How one job reads lengths written without a decimal point (issue 26 item 6;
// gcode/decimal_point.h has the two readings). In order:
//   1. the user's choice for this file (Job details, --decimal-point);
//   2. a plain program (no Klueng header: a file from the shop): its own
//      numbers (G71 U1250 only makes sense in increments, X30 only whole),
//      with a note saying which word decided;
//   3. the machine's setting (machine.cfg calculator_input), which also breaks
//      a plain program's ties.
// Words whose other reading is clearly what the author meant get W110/W111.
#include <optional>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/program.h"

namespace klueng::core::machine {

struct PointReading {
  bool calculatorInput = true;
  bool fromProgram = false;             // the plain program's numbers decided it
  std::vector<Diagnostic> diagnostics;  // I103/I104 when they did; W110/W111
};

// Decides, and rescales `program`'s pointless lengths in place when they are
// least input increments.
PointReading readDecimalPoints(gcode::Program& program, bool plainProgram, std::optional<bool> chosen,
                               bool machineCalculatorInput, gcode::InputUnits powerOnUnits, gcode::Dialect dialect);

}  // namespace klueng::core::machine

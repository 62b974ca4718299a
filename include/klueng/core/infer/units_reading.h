#pragma once
// The units a plain program speaks when it says none (issue 38 item 8): a shop's inch program
// without G20 (`G71 U.1 R.02`, `G96 S500`, `X1.2345`) read on a machine that powers on in mm
// cuts a part 25.4 times too small. When the user gave no units and the program has no G20/G21,
// its own numbers decide, and only when they clearly do; a note names the words that did.
#include <optional>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/program.h"

namespace klueng::core::machine {

struct UnitsReading {
  gcode::InputUnits units;
  Diagnostic note;  // I107: the units and the words that decided them
};

// nullopt: the machine's power-on units stand (the program names its units, or its numbers do
// not clearly speak the other unit).
std::optional<UnitsReading> readPowerOnUnits(const gcode::Program& program, gcode::Dialect dialect,
                                             gcode::InputUnits machinePowerOn);

}  // namespace klueng::core::machine

#pragma once
// More decimals than the least input increment (SPEC 13): where the profile
// says RoundWithWarning, the control computes with the value rounded to the
// increment of the units in force (the checker reports the warning).
// TODO: switch to gcode::roundToIncrement (gcode/word_format.h) once it lands.
#include <optional>

#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/program.h"

namespace klueng::core::machine {

// `value` rounded half away from zero to `decimals` decimals.
double roundToDecimals(double value, int decimals);

// A copy of `program` with the axis words X Z U W I K R rounded to the least
// increment (profile decimals, mm or inch as G20/G21 say, from `powerOnUnits`
// on); nullopt when the profile keeps extra decimals an error or nothing
// needs rounding (the caller then runs `program` itself).
std::optional<gcode::Program> roundToIncrements(const gcode::Program& program, const gcode::MachineProfile& profile,
                                                gcode::InputUnits powerOnUnits);

}  // namespace klueng::core::machine

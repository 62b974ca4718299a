#pragma once
// Word formats of a machine profile (SPEC 4, 13): the least input increment
// and how a value with more decimals is read. The checker warns (W103) where
// the profile rounds; the interpreter calls roundToIncrement() so the run uses
// the value the control would use.
#include <string>

#include "klueng/core/gcode/machine_profile.h"

namespace klueng::core::gcode {

// Digits after the decimal point of the least input increment (3 for mm, 4 for inch).
int incrementDecimals(const MachineProfile& profile, InputUnits units);

// value rounded to the least input increment, half away from zero
// (X0.42928932 -> 0.429 in mm, 0.4293 in inch).
double roundToIncrement(double value, const MachineProfile& profile, InputUnits units);

// value with exactly `decimals` digits after the point ("0.429", "-9999.999").
std::string formatFixed(double value, int decimals);

}  // namespace klueng::core::gcode

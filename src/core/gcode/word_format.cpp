// Least input increments and rounding (SPEC 4, 13; docs/dialects.md).
#include "klueng/core/gcode/word_format.h"

#include <cmath>
#include <cstdio>

namespace klueng::core::gcode {

int incrementDecimals(const MachineProfile& profile, InputUnits units) {
  return units == InputUnits::Inch ? profile.decimalsInch : profile.decimalsMm;
}

double roundToIncrement(double value, const MachineProfile& profile, InputUnits units) {
  const double scale = std::pow(10.0, incrementDecimals(profile, units));
  // std::round rounds half away from zero; the small nudge keeps 0.0005 (read
  // as 0.000499999...) rounding up as it does on paper.
  const double scaled = value * scale;
  return std::round(scaled + std::copysign(1e-9, scaled)) / scale;
}

std::string formatFixed(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  std::string s = buf;
  if (s.size() > 1 && s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);  // no "-0.000"
  return s;
}

}  // namespace klueng::core::gcode

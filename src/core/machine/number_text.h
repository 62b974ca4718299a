#pragma once
// A length or time as the run's alarms write it: three decimals, never "-0.000".
#include <fmt/format.h>

#include <cmath>
#include <string>

namespace klueng::core::machine::detail {

inline std::string num(double v) {
  if (std::abs(v) < 0.0005) v = 0.0;  // no "-0.000"
  return fmt::format("{:.3f}", v);
}

}  // namespace klueng::core::machine::detail

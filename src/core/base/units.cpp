// The one display conversion of lengths (see units.h).
#include "klueng/core/units.h"

#include <fmt/format.h>

#include <cmath>

namespace klueng::core {

namespace {

// Fixed decimals, never "-0.000" (a value that rounds to zero has no sign).
std::string fixed(double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string trimmed(double v, int decimals) {
  std::string s = fixed(v, decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s;
}

}  // namespace

std::string UnitFormat::position(double mm) const { return fixed(value(mm), decimals()); }

std::string UnitFormat::size(double mm, int mmDecimals) const {
  return inch() ? fixed(value(mm), 3) : trimmed(mm, mmDecimals);
}

std::string UnitFormat::feed(double mmFeed, bool perRev) const {
  if (perRev) return fixed(value(mmFeed), inch() ? 4 : 3);
  return fixed(value(mmFeed), inch() ? 2 : 1);
}

std::string UnitFormat::withUnit(double mm, Lang lang) const { return position(mm) + " " + unitName(lang); }

std::string UnitFormat::unitName(Lang lang) const {
  if (lang == Lang::Th) return inch() ? "นิ้ว" : "มม.";
  return inch() ? "in" : "mm";
}

std::string UnitFormat::feedUnit(bool perRev, Lang lang) const {
  const bool th = lang == Lang::Th;
  return unitName(lang) + (perRev ? (th ? "/รอบ" : "/rev") : (th ? "/นาที" : "/min"));
}

const char* unitArgText(const std::string& arg, Lang lang) {
  const bool th = lang == Lang::Th;
  if (arg == kUnitArgMm) return th ? "มม." : "mm";
  if (arg == kUnitArgInch) return th ? "นิ้ว" : "in";
  return nullptr;
}

}  // namespace klueng::core

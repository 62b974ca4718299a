#pragma once
// Lengths shown in millimetres or inches (issue 28 item 4). The core keeps
// millimetres everywhere; which unit a screen, a report or the CLI shows is a
// display choice, and this is the one place that converts and rounds for it.
// Decimals follow a Haas/Fanuc control's display: positions 3 decimals in mm,
// 4 in inches; drawing sizes trimmed in mm ("30", "28.16"), 3 decimals in
// inches ("1.750", as an inch drawing writes them).
//
//   const UnitFormat u(DisplayUnits::Inch);
//   u.position(44.45)           -> "1.7500"
//   u.size(44.45)               -> "1.750"
//   u.feed(0.2032, true)        -> "0.0080"   (in/rev; feedUnit() says which)
//   u.withUnit(0.53, Lang::Th)  -> "0.0209 นิ้ว"
#include <cstdint>
#include <string>

#include "klueng/core/messages.h"

namespace klueng::core {

enum class DisplayUnits : std::uint8_t { Mm, Inch };

inline constexpr double kMmPerInch = 25.4;

// A diagnostic argument that formatMessage writes as the unit's name in the
// message's language ("mm"/"มม.", "in"/"นิ้ว"): the catalog's texts stay
// language-neutral data while the number's unit follows the display choice.
inline constexpr const char* kUnitArgMm = "\x1Funit:mm";
inline constexpr const char* kUnitArgInch = "\x1Funit:in";

class UnitFormat {
 public:
  constexpr UnitFormat() = default;  // millimetres
  constexpr explicit UnitFormat(DisplayUnits units) : units_(units) {}
  constexpr DisplayUnits units() const { return units_; }
  constexpr bool inch() const { return units_ == DisplayUnits::Inch; }
  bool operator==(const UnitFormat&) const = default;

  // mm -> the shown unit's number, and back.
  double value(double mm) const { return inch() ? mm / kMmPerInch : mm; }
  double toMm(double shown) const { return inch() ? shown * kMmPerInch : shown; }
  // Decimals of a position or a measured length (3 mm, 4 inch).
  int decimals() const { return inch() ? 4 : 3; }

  // A coordinate or a measured length: "-12.500" / "-0.4921" (never "-0.000").
  std::string position(double mm) const;
  // A drawing's size: "30", "28.16" in mm (at most `mmDecimals`, zeros dropped); "1.750" in inches.
  std::string size(double mm, int mmDecimals = 2) const;
  // A feed as programmed, stored in mm/rev or mm/min: "0.250" / "0.0080" per rev,
  // "120.0" / "4.72" per minute.
  std::string feed(double mmFeed, bool perRev) const;
  // A number with its unit name: "0.530 mm" / "0.0209 in" ("มม." / "นิ้ว" in Thai).
  std::string withUnit(double mm, Lang lang) const;
  // "mm"/"มม.", "in"/"นิ้ว"; a feed's: "mm/rev"/"มม./รอบ", "in/rev"/"นิ้ว/รอบ", "mm/min"/"มม./นาที", "in/min"/"นิ้ว/นาที".
  std::string unitName(Lang lang) const;
  std::string feedUnit(bool perRev, Lang lang) const;
  // The diagnostic argument naming this unit (kUnitArgMm / kUnitArgInch).
  const char* unitArg() const { return inch() ? kUnitArgInch : kUnitArgMm; }
  // After a size in the texts of features: "" in mm (a drawing in mm writes none), "″" in inches.
  const char* sizeMark() const { return inch() ? "\u2033" : ""; }

 private:
  DisplayUnits units_ = DisplayUnits::Mm;
};

// The unit an argument made by unitArg() names in `lang`; nullptr for any other text.
const char* unitArgText(const std::string& arg, Lang lang);

}  // namespace klueng::core

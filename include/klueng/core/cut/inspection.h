#pragma once
// Inspection against the teacher's drawing (issue 28, item 2): each toleranced
// diameter and length of the drawing measured on the cut part, with its
// limits and whether it is in tolerance. A teacher grades against a drawing,
// not a reference program; class_grading.h uses it for a whole class.
//
//   const auto report = inspectPart(partFeatures(stock), drawing);  // one row per dimension
//
// Rounding rule: the measured value and both limits are rounded to 0.001 mm
// (half away from zero) and compared as whole microns, so a value exactly at a
// limit is in. Diameters are exact (the radial model, fitted to ~0.001 mm);
// lengths are read between faces, resolved to the stock's column width.
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/cut/part_features.h"
#include "klueng/core/messages.h"

namespace klueng::core::cut {

// Limit deviations from the nominal size in mm (upper >= lower), as the drawing writes them.
struct Tolerance {
  double upper = 0.0;
  double lower = 0.0;
  std::string text;  // "h7", "±0.05", "+0.02/-0.01", "ISO 2768-m"; empty: none given
  bool given() const { return !text.empty(); }
  bool operator==(const Tolerance&) const = default;
};

enum class DimensionKind { Diameter, Length };

// One toleranced dimension of the drawing, where the drawing has it.
struct DrawnDimension {
  DimensionKind kind = DimensionKind::Diameter;
  FeatureSide side = FeatureSide::Outside;
  double nominal = 0.0;  // mm: a diameter, or a length along Z
  Tolerance tolerance;
  // A diameter: the Z span of its cylinder (clear of its edge break). A length:
  // the Z of its right and left ends (shoulders or the part's ends).
  double zRight = 0.0;
  double zLeft = 0.0;
};

enum class Verdict { In, Out, Missing };

struct InspectedDimension {
  DrawnDimension drawn;
  std::optional<double> measured;  // mm, rounded to 0.001; none when the feature is not on the part
  Verdict verdict = Verdict::Missing;
  double lowerLimit() const;  // nominal + lower deviation, rounded to 0.001
  double upperLimit() const;
  bool in() const { return verdict == Verdict::In; }
};

inline constexpr double kMeasureStep = 0.001;  // mm: what the inspection reads to
double roundToMicron(double mm);

// Each drawn dimension measured on the part: a diameter on the cylinder(s) of
// that side across its span (the one furthest from the middle of the
// tolerance zone when the span is cut as several); a length between the faces
// nearest its two ends (within half its length, at most 5 mm). Not found:
// Missing, which is out.
std::vector<InspectedDimension> inspectPart(const PartFeatures& part, const std::vector<DrawnDimension>& drawing);

// "Ø25", "Ø20 bore", "L20 (Z0/Z-20)"; Thai in Thai.
std::string dimensionLabel(const DrawnDimension& d, Lang lang);
// "h7 (0/-0.021)", "±0.05", "+0.02/-0.01".
std::string toleranceLabel(const Tolerance& t);
// "in", "out", "missing" / "ผ่าน", "ไม่ผ่าน", "ไม่มี".
std::string verdictName(Verdict v, Lang lang);

}  // namespace klueng::core::cut

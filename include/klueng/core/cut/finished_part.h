#pragma once
// The finished part measured from the stock (SPEC 11): profile, diameters,
// step lengths, volume, CSV and SVG export. Diameters are exact (radial model);
// Z positions are resolved to the stock's column width.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "klueng/core/cut/stock.h"
#include "klueng/core/geometry.h"

namespace klueng::core::cut {

struct ProfileRow {
  double z = 0.0;              // mm
  double outerDiameter = 0.0;  // 0 where nothing is left
  double innerDiameter = 0.0;  // bore diameter, 0 when solid
};

class FinishedPart {
 public:
  // Keeps a reference: `stock` must outlive the part and not change meanwhile.
  explicit FinishedPart(const Stock& stock);

  // One row per stock column (at its centre), plus rows at the part's left and
  // right faces (column edges) repeating the end columns' values.
  const std::vector<ProfileRow>& rows() const { return rows_; }
  bool empty() const { return first_ > last_; }
  double rightFaceZ() const;  // right edge of the rightmost column with material
  double leftFaceZ() const;
  // Interpolated linearly between column centres; nullopt outside the part or
  // where nothing is left.
  std::optional<double> outerDiameterAt(double z) const;
  std::optional<double> innerDiameterAt(double z) const;
  // Z extent [zMin, zMax] (column edges) of the stretch around z whose outer diameter
  // stays within `tolerance` of the diameter at z.
  std::pair<double, double> stepExtent(double z, double tolerance = 0.005) const;
  double stepLength(double z, double tolerance = 0.005) const;
  double maxDiameter() const;
  double length() const { return empty() ? 0.0 : rightFaceZ() - leftFaceZ(); }
  double volume() const { return volume_; }

  // (z, radius) polylines from the left end to the right face, with vertical
  // steps between columns; the outer one starts and ends on the centre line.
  std::vector<Vec2> outerProfile() const;
  std::vector<Vec2> innerProfile() const;  // empty when the part is solid

  std::string toCsv() const;  // header "z,x_outer,x_inner": mm always (G20 too), diameters, "%.4f"
  std::string toSvg() const;  // both halves, mm units, X up
  std::string toDxf() const;  // AutoCAD R12 DXF: LINE entities of both halves (layer PART) and the bore (BORE), mm

 private:
  const Stock* stock_;
  std::vector<ProfileRow> rows_;
  int first_ = 0;  // first / last column with material
  int last_ = -1;
  double volume_ = 0.0;
};

}  // namespace klueng::core::cut

#pragma once
// The finished part as a draughtsman reads it (issue 10, item 1): the cut
// stock's outside and inside profiles split into faces, cylinders, tapers,
// chamfers, arcs, grooves and threads, each with its sizes. One function used
// by the GUI's dimensions panel, the drawing sheet and the CLI.
//
// Diameters, radii and angles come from fits to the exact radial values
// (to ~0.001 mm); Z positions where two fitted curves meet (a chamfer and a
// cylinder, an arc and its tangent line) are exact, those of faces are
// resolved to the stock's column width.
#include <string>
#include <vector>

#include "klueng/core/cut/stock.h"
#include "klueng/core/geometry.h"
#include "klueng/core/messages.h"
#include "klueng/core/units.h"

namespace klueng::core::cut {

enum class FeatureKind { Face, Cylinder, Taper, Chamfer, Arc, Groove, Thread };
enum class FeatureSide { Outside, Inside };

struct PartFeature {
  FeatureKind kind = FeatureKind::Cylinder;
  FeatureSide side = FeatureSide::Outside;
  double zLeft = 0.0;  // extent along Z, zLeft <= zRight (a face: zLeft == zRight)
  double zRight = 0.0;
  double diameterLeft = 0.0;   // Ø of the profile at zLeft / zRight (a face: the
  double diameterRight = 0.0;  // larger and the smaller Ø, left = larger)
  // Cylinder, groove (its bottom), thread (major): the Ø.
  double diameter = 0.0;
  // Arc: radius, centre (z, radius) and whether material lies inside the circle
  // (a rounded corner) or outside it (a fillet in an inside corner).
  double radius = 0.0;
  Vec2 centre = Vec2::Zero();
  bool convex = false;
  // Chamfer, taper: angle to the axis in degrees; a chamfer's axial and radial
  // legs measured to the sharp corners it replaces (C3 = 3 × 3 at 45°).
  double angle = 0.0;
  double axialLength = 0.0;
  double radialHeight = 0.0;
  // Groove: width along Z and depth (radius) below the lower shoulder.
  double width = 0.0;
  double depth = 0.0;
  // Thread: pitch and minor Ø (diameter = major Ø).
  double pitch = 0.0;
  double minorDiameter = 0.0;

  double length() const { return zRight - zLeft; }
  bool isFortyFiveChamfer() const;  // a chamfer at 45° ± 0.5°: written "C<size>"
  // A concave arc no larger than a nose radius (1.6 mm): the tool's print in an
  // inside corner, not a radius the drawing gives.
  bool isNoseFillet() const;
  // The profile's radius at z within [zLeft, zRight] (arcs on their circle; a
  // groove at its bottom).
  double radiusAt(double z) const;
};

struct PartFeatures {
  std::vector<PartFeature> outside;  // from the right face (Z0 side) to the left end
  std::vector<PartFeature> inside;   // bores, the same order; empty on a solid part
  double zLeft = 0.0;                // the part's ends (column edges)
  double zRight = 0.0;
  bool empty() const { return outside.empty(); }
  double overallLength() const { return zRight - zLeft; }
  // The faces' Z from right to left, outside and inside merged (for chained
  // step dimensions), both ends included.
  std::vector<double> shoulderZ() const;
};

// Reads the cut stock. An empty stock (nothing left) gives no features.
PartFeatures partFeatures(const Stock& stock);

// "cylinder", "ทรงกระบอก", ...
std::string featureKindName(FeatureKind kind, Lang lang);
// A draughtsman's label of the feature: "Ø30", "C3", "R2", "M30×1.5",
// "15°", "groove 3 × Ø26" (Thai in Thai). In inches (issue 28 item 4):
// "Ø1.750″", "0.050″ × 45°", "R0.125″", "0.750″-16 TPI".
std::string featureLabel(const PartFeature& f, Lang lang);
std::string featureLabel(const PartFeature& f, Lang lang, const UnitFormat& units);
// One line with the place: "Cylinder Ø30, Z-3 to Z-20, length 17";
// in inches "Cylinder Ø1.7500″, Z-0.1000 to Z-1.0000, length 0.9000″".
std::string describeFeature(const PartFeature& f, Lang lang);
std::string describeFeature(const PartFeature& f, Lang lang, const UnitFormat& units);

}  // namespace klueng::core::cut

#pragma once
// A part design from a DXF drawing (issue 14): the upper half of a turned
// part's section as lines, arcs and polylines on one layer, read with dxflib.
//
//   const auto design = importDxf(text, "shaft.dxf");          // F184-F194 name the drawing's X Y
//   const auto program = generateProgram(*design.value, ...);
//
// The drawing's X runs along the spindle axis, its Y away from it; the right
// end of the outline is the part's face (Z0). The axis is a horizontal centre
// line (linetype or layer CENTER/CENTRE/AXIS), or else the outline's lowest
// Y. Horizontal lines become cylinders, sloped lines tapers, arcs arc steps;
// a 45° line or a 90° convex arc between a face and a cylinder becomes that
// cylinder's chamfer or round, a face down-across-up of one width a groove,
// and a second outline below the first the bore. The bar is the next 5 mm
// above the largest diameter (the hole 2 mm under the bore), long enough to
// hold the part outside the jaws.
#include <string>
#include <vector>

#include "klueng/core/design/part_design.h"
#include "klueng/core/io/result.h"

namespace klueng::core::design {

struct DxfImportOptions {
  std::string layer;        // empty: the only layer with lines and arcs
  double chuckGrip = 15.0;  // mm the jaws hold, for the bar's length
  std::string material = "steel";
};

io::ReadResult<PartDesign> importDxf(const std::string& text, const std::string& fileName,
                                     const DxfImportOptions& options = {});

// The layers that hold lines, arcs or polylines (for picking one), sorted.
std::vector<std::string> dxfOutlineLayers(const std::string& text);

}  // namespace klueng::core::design

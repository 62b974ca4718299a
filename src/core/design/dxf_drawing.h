#pragma once
// The entities of a DXF drawing that a turned profile is made of, read with
// dxflib (internal to core/design).
#include <string>
#include <vector>

#include "klueng/core/geometry.h"

namespace klueng::core::design::detail {

// A line or an arc in the drawing's X Y, from a to b.
struct DxfSegment {
  Vec2 a, b;
  bool arc = false;
  Vec2 centre;
  double radius = 0.0;
  bool ccw = true;          // an arc's sense from a to b
  bool centreLine = false;  // drawn as the axis (linetype or layer CENTER/CENTRE/AXIS)
  std::string layer;
};

struct DxfOddEntity {
  std::string kind;  // "spline", "ellipse", ...
  std::string layer;
  Vec2 at;
};

struct DxfDrawing {
  bool parsed = false;
  std::string why;      // when not parsed (English)
  std::string whyThai;  // the same in Thai
  int insunits = 0;     // $INSUNITS: 0 unitless, 1 in, 4 mm, ...
  std::vector<DxfSegment> segments;
  std::vector<DxfOddEntity> odd;
};

DxfDrawing readDxfDrawing(const std::string& text);

}  // namespace klueng::core::design::detail

#pragma once
// Intersections of the carriers of two segments, used to trim or extend offset
// paths at corners: a line is taken as its whole infinite line, an arc as its
// full circle.
#include <array>

#include "klueng/core/comp/segment.h"

namespace klueng::core::comp {

struct CarrierHits {
  int count = 0;                 // 0, 1 or 2
  std::array<Vec2, 2> points{};  // valid up to count
};

// Curves that miss each other by less than `touch` (mm) count as touching and
// give their one nearest point, so tangent offsets still meet.
// Parallel lines and concentric circles give no point. Zero-length lines give none.
CarrierHits intersectCarriers(const Segment& a, const Segment& b, double touch = 1e-9);

}  // namespace klueng::core::comp

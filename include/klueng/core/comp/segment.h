#pragma once
// A straight or circular piece of path in the (z, x_radius) plane.
#include <cstdint>

#include "klueng/core/geometry.h"

namespace klueng::core {

struct Segment {
  // (Points first, flags last: 64 bytes, not 80; a timeline holds one per move.)
  enum class Kind : std::uint8_t { Line, Arc };
  Vec2 start = Vec2::Zero();
  Vec2 end = Vec2::Zero();
  Vec2 centre = Vec2::Zero();  // arcs only, absolute
  Kind kind = Kind::Line;
  bool ccw = false;  // arcs: counter-clockwise in the X-up drawing (G03)

  static Segment line(const Vec2& a, const Vec2& b) { return {a, b, Vec2::Zero(), Kind::Line, false}; }
  static Segment arc(const Vec2& a, const Vec2& b, const Vec2& c, bool ccw) { return {a, b, c, Kind::Arc, ccw}; }
  bool isArc() const { return kind == Kind::Arc; }
  double radius() const { return (start - centre).norm(); }
  double length() const;                     // path length (arc length for arcs)
  Vec2 pointAt(double s) const;              // s in [0,1] of the path length
  Vec2 startTangent() const;                 // unit direction of travel at the start
  Vec2 endTangent() const;                   // unit direction of travel at the end
  double sweep() const;                      // arcs: swept angle in radians, > 0
  Segment translated(const Vec2& by) const;  // the same piece moved by `by`
};

// Shortest distance from p to the piece (its end points included). For an arc
// this is | |p - centre| - radius | when p lies in the arc's angular range,
// else the distance to the nearer end point.
double distanceTo(const Segment& s, const Vec2& p);

}  // namespace klueng::core

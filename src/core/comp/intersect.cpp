#include "klueng/core/comp/intersect.h"

#include <cmath>

namespace klueng::core::comp {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

CarrierHits lineLine(const Segment& a, const Segment& b) {
  CarrierHits hits;
  const Vec2 u = a.end - a.start;
  const Vec2 v = b.end - b.start;
  const double denom = cross(u, v);
  if (std::abs(denom) <= 1e-12 * u.norm() * v.norm()) return hits;  // parallel (or a zero-length line)
  const double t = cross(b.start - a.start, v) / denom;
  hits.points[hits.count++] = a.start + t * u;
  return hits;
}

CarrierHits lineCircle(const Segment& line, const Vec2& centre, double r, double touch) {
  CarrierHits hits;
  const Vec2 d = line.end - line.start;
  const double len = d.norm();
  if (len == 0.0) return hits;
  const Vec2 u = d / len;
  const Vec2 w = line.start - centre;
  const double b = w.dot(u);
  const Vec2 foot = line.start - b * u;  // nearest point of the line to the centre
  const double h = (foot - centre).norm();
  if (h > r + touch) return hits;
  if (h >= r) {  // touching (within `touch`)
    hits.points[hits.count++] = foot;
    return hits;
  }
  const double half = std::sqrt(r * r - h * h);
  hits.points[hits.count++] = foot - half * u;
  hits.points[hits.count++] = foot + half * u;
  return hits;
}

CarrierHits circleCircle(const Vec2& c1, double r1, const Vec2& c2, double r2, double touch) {
  CarrierHits hits;
  const Vec2 d = c2 - c1;
  const double dist = d.norm();
  if (dist <= 1e-12) return hits;  // concentric
  if (dist > r1 + r2 + touch || dist < std::abs(r1 - r2) - touch) return hits;
  const Vec2 u = d / dist;
  const double along = (dist * dist + r1 * r1 - r2 * r2) / (2 * dist);
  const double h2 = r1 * r1 - along * along;
  const Vec2 base = c1 + along * u;
  if (h2 <= 0.0) {  // touching
    hits.points[hits.count++] = base;
    return hits;
  }
  const double h = std::sqrt(h2);
  const Vec2 perp(-u.y(), u.x());
  hits.points[hits.count++] = base + h * perp;
  hits.points[hits.count++] = base - h * perp;
  return hits;
}

}  // namespace

CarrierHits intersectCarriers(const Segment& a, const Segment& b, double touch) {
  if (!a.isArc() && !b.isArc()) return lineLine(a, b);
  if (!a.isArc()) return lineCircle(a, b.centre, b.radius(), touch);
  if (!b.isArc()) return lineCircle(b, a.centre, a.radius(), touch);
  return circleCircle(a.centre, a.radius(), b.centre, b.radius(), touch);
}

}  // namespace klueng::core::comp

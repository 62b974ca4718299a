#include "klueng/core/comp/segment.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace klueng::core {

double Segment::sweep() const {
  if (!isArc()) return 0.0;
  const Vec2 a = start - centre;
  const Vec2 b = end - centre;
  double ang = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));  // ccw angle a->b in (-pi, pi]
  if (ccw) {
    if (ang <= 1e-12) ang += 2 * std::numbers::pi;
  } else {
    ang = -ang;
    if (ang <= 1e-12) ang += 2 * std::numbers::pi;
  }
  return ang;
}

double Segment::length() const { return isArc() ? radius() * sweep() : (end - start).norm(); }

Vec2 Segment::pointAt(double s) const {
  if (!isArc()) return start + s * (end - start);
  const Vec2 a = start - centre;
  const double ang = (ccw ? 1.0 : -1.0) * sweep() * s;
  const double c = std::cos(ang), sn = std::sin(ang);
  return centre + Vec2(c * a.x() - sn * a.y(), sn * a.x() + c * a.y());
}

static Vec2 perpendicular(const Vec2& v, bool ccw) {
  // Tangent of a circle at radius vector v: rotate +90 deg for ccw travel.
  return ccw ? Vec2(-v.y(), v.x()) : Vec2(v.y(), -v.x());
}

Vec2 Segment::startTangent() const {
  if (!isArc()) {
    const Vec2 d = end - start;
    const double n = d.norm();
    return n > 0 ? Vec2(d / n) : Vec2(Vec2::Zero());
  }
  return perpendicular(start - centre, ccw).normalized();
}

Vec2 Segment::endTangent() const {
  if (!isArc()) return startTangent();
  return perpendicular(end - centre, ccw).normalized();
}

Segment Segment::translated(const Vec2& by) const {
  Segment s = *this;
  s.start += by;
  s.end += by;
  if (isArc()) s.centre += by;
  return s;
}

double distanceTo(const Segment& s, const Vec2& p) {
  if (!s.isArc()) {
    const Vec2 d = s.end - s.start;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - s.start).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (p - (s.start + t * d)).norm();
  }
  const Vec2 a = s.start - s.centre;
  const Vec2 v = p - s.centre;
  const double r = a.norm();
  if (v.norm() == 0.0) return r;  // every point of the arc is r away from its centre
  // Angle from the start radius to p, measured in the direction of travel, in [0, 2pi).
  double ang = std::atan2(a.x() * v.y() - a.y() * v.x(), a.dot(v));
  if (!s.ccw) ang = -ang;
  if (ang < 0) ang += 2 * std::numbers::pi;
  if (ang <= s.sweep()) return std::abs(v.norm() - r);
  return std::min((p - s.start).norm(), (p - s.end).norm());
}

}  // namespace klueng::core

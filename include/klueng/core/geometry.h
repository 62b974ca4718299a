#pragma once
// 2-D lathe geometry with Eigen. A point is (z, x) with x a RADIUS in mm:
// the core computes in radius; only words, traces and the UI speak diameters.
#include <Eigen/Core>

namespace klueng::core {

using Vec2 = Eigen::Vector2d;  // (z, x_radius)

inline Vec2 zx(double z, double xRadius) { return Vec2(z, xRadius); }
inline double zOf(const Vec2& p) { return p.x(); }
inline double xOf(const Vec2& p) { return p.y(); }  // radius
inline double diameterOf(const Vec2& p) { return 2.0 * p.y(); }

}  // namespace klueng::core

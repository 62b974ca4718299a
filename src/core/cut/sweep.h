#pragma once
// Column-wise sweeps of tool primitives (internal to the cut module).
// A column grid samples Z at column centres zStart + (i + 0.5) * dz; each sweep
// calls f(i, lo, hi) with the radial interval the swept primitive covers at
// column i's centre. Convex primitives give one interval per column.
//
// A sweep given a MaterialCull leaves out columns whose material lies wholly at
// or below the primitive's lowest radius there (f would find nothing to remove
// or touch), a block of stock columns at a time: a pass over a surface already
// cut visits only the columns at its shoulder (issue 29 item 14). The columns
// it does visit come in the same order with the same values as without it.
#include <algorithm>
#include <cmath>
#include <limits>

#include "klueng/core/cut/stock.h"
#include "klueng/core/cut/tool_shape.h"
#include "klueng/core/geometry.h"

namespace klueng::core::cut::detail {

struct Grid {
  double zStart = 0.0;
  double dz = 0.05;
  int count = 0;
  double centre(int i) const { return zStart + (i + 0.5) * dz; }
  // Columns with centres in [z0, z1].
  void range(double z0, double z1, int& first, int& last) const {
    if (!std::isfinite(z0) || !std::isfinite(z1)) {
      first = 0;
      last = -1;
      return;
    }
    const double f0 = std::ceil((z0 - zStart) / dz - 0.5);
    const double f1 = std::floor((z1 - zStart) / dz - 0.5);
    first = static_cast<int>(std::clamp(f0, 0.0, static_cast<double>(count)));
    last = static_cast<int>(std::clamp(f1, -1.0, static_cast<double>(count) - 1));
  }
};

// Visit every column (a grid that is not the stock's, e.g. the chuck check's).
struct NoCull {};
// Skip what lies below the sweep. The grid must be the stock's columns, and f must
// do nothing where lo >= the column's outer radius (Stock::remove, Stock::overlap).
struct MaterialCull {
  const Stock* stock;
};

// True when f would do nothing at column i for an interval starting at lo (its material lies
// wholly at or below lo): a sweep need not work out the interval's top there. Never without a cull.
inline bool passesOver(const NoCull&, int, double) { return false; }
inline bool passesOver(const MaterialCull& cull, int i, double lo) { return lo >= cull.stock->outerRadius(i); }

template <typename Bound, typename Body>
void visitColumns(const NoCull&, int first, int last, Bound&&, Body&& body) {
  for (int i = first; i <= last; ++i) body(i);
}

// bound(p, q): at most the lo that body gives any column of p..q. The columns
// from i to the end of i's super-block (or block), when its largest outer radius
// is not above the bound there, are skipped at once.
template <typename Bound, typename Body>
void visitColumns(const MaterialCull& cull, int first, int last, Bound&& bound, Body&& body) {
  const Stock& s = *cull.stock;
  constexpr int kBlock = Stock::kBlock, kSuper = Stock::kSuper;
  for (int i = first; i <= last;) {
    const int superEnd = std::min(last, i / kSuper * kSuper + kSuper - 1);
    if (s.superMaxOuter(i / kSuper) <= bound(i, superEnd)) {
      i = superEnd + 1;
      continue;
    }
    for (; i <= superEnd;) {
      const int end = std::min(superEnd, i / kBlock * kBlock + kBlock - 1);
      if (!(s.blockMaxOuter(i / kBlock) <= bound(i, end)))
        for (int k = i; k <= end; ++k) body(k);
      i = end + 1;
    }
  }
}

// Lowest radius of a primitive (local z extent [z0, z1], lowest point `bottom`
// above its reference point) whose reference point moves along a -> b, over the
// columns p..q. With `exact`, the sweep's own lo is bottom + a.y() to the bit on
// a move along Z (a.y() == b.y()), so a pass over the surface it or its twin cut
// is skipped; otherwise rounding may differ and a margin keeps the bound below.
inline double lineBound(const Grid& g, int p, int q, const Vec2& a, const Vec2& b, double z0, double z1, double bottom,
                        bool exact, bool alongX) {
  const double yLo = std::min(a.y(), b.y());
  const double margin = 1e-9 * (1.0 + std::abs(a.y()) + std::abs(b.y()) + std::abs(bottom));
  if (alongX) return exact ? yLo + bottom : yLo + bottom - margin;  // the sweep's own branch for dz ~ 0
  if (exact && a.y() == b.y()) return a.y() + bottom;
  const double dz = b.x() - a.x(), dx = b.y() - a.y();
  double s0 = (g.centre(p) - z1 - a.x()) / dz, s1 = (g.centre(q) - z0 - a.x()) / dz;
  if (s0 > s1) std::swap(s0, s1);
  s0 = std::max(s0, 0.0);
  s1 = std::min(s1, 1.0);
  if (!(s0 <= s1)) return yLo + bottom - margin;
  return std::min(a.y() + s0 * dx, a.y() + s1 * dx) + bottom - margin;
}

// Box (local, relative to the controlled point) swept with the controlled point
// moving along the line a -> b.
template <typename F, typename Cull = NoCull>
void sweepBoxLine(const Grid& g, const Vec2& a, const Vec2& b, const Box& box, F&& f, const Cull& cull = {}) {
  const double dz = b.x() - a.x();
  int first, last;
  g.range(std::min(a.x(), b.x()) + box.z0, std::max(a.x(), b.x()) + box.z1, first, last);
  if (first > last) return;
  const bool alongX = std::abs(dz) < 1e-12;
  auto bound = [&](int p, int q) { return lineBound(g, p, q, a, b, box.z0, box.z1, box.x0, true, alongX); };
  if (alongX) {
    const double lo = std::min(a.y(), b.y()) + box.x0, hi = std::max(a.y(), b.y()) + box.x1;
    visitColumns(cull, first, last, bound, [&](int i) { f(i, lo, hi); });
    return;
  }
  const double dx = b.y() - a.y();
  visitColumns(cull, first, last, bound, [&](int i) {
    const double z = g.centre(i);
    double s0 = (z - box.z1 - a.x()) / dz, s1 = (z - box.z0 - a.x()) / dz;
    if (s0 > s1) std::swap(s0, s1);
    s0 = std::max(s0, 0.0);
    s1 = std::min(s1, 1.0);
    if (s0 > s1) return;
    const double x0 = a.y() + s0 * dx, x1 = a.y() + s1 * dx;
    f(i, std::min(x0, x1) + box.x0, std::max(x0, x1) + box.x1);
  });
}

// Trapezoid (local) swept along the line a -> b. x(s) + bottom(z - z(s)) is
// linear in s, so the extremes over the s-range sit at its ends.
template <typename F, typename Cull = NoCull>
void sweepTrapezoidLine(const Grid& g, const Vec2& a, const Vec2& b, const Trapezoid& t, F&& f, const Cull& cull = {}) {
  const double dz = b.x() - a.x();
  int first, last;
  g.range(std::min(a.x(), b.x()) + t.z0, std::max(a.x(), b.x()) + t.z1, first, last);
  if (first > last) return;
  const bool alongX = std::abs(dz) < 1e-12;
  // A flat bottom is interpolated to itself exactly; a sloped one may round below its ends.
  const bool flat = t.bottom0 == t.bottom1;
  auto bound = [&](int p, int q) {
    return lineBound(g, p, q, a, b, t.z0, t.z1, std::min(t.bottom0, t.bottom1), flat, alongX);
  };
  if (alongX) {
    const double xLo = std::min(a.y(), b.y()), xHi = std::max(a.y(), b.y());
    visitColumns(cull, first, last, bound, [&](int i) {
      const double u = g.centre(i) - a.x();
      f(i, xLo + t.bottomAt(u), xHi + t.topAt(u));
    });
    return;
  }
  const double dx = b.y() - a.y();
  // A box's flat bottom (top) needs no interpolation: bottomAt adds (bottom1 - bottom0) * q = +-0
  // to bottom0, which changes no x + bottom0 to the bit unless both are 0 (then the sign of
  // the 0 may differ).
  const bool flatBottom = t.bottom0 == t.bottom1 && std::isfinite(t.bottom0);
  const bool flatTop = t.top0 == t.top1 && std::isfinite(t.top0);
  visitColumns(cull, first, last, bound, [&](int i) {
    const double z = g.centre(i);
    double s0 = (z - t.z1 - a.x()) / dz, s1 = (z - t.z0 - a.x()) / dz;
    if (s0 > s1) std::swap(s0, s1);
    s0 = std::max(s0, 0.0);
    s1 = std::min(s1, 1.0);
    if (s0 > s1) return;
    const double xa = a.y() + s0 * dx, xb = a.y() + s1 * dx;
    const double ua = z - (a.x() + s0 * dz), ub = z - (a.x() + s1 * dz);
    const double lo = flatBottom && (t.bottom0 != 0.0 || (xa != 0.0 && xb != 0.0))
                          ? std::min(xa + t.bottom0, xb + t.bottom0)
                          : std::min(xa + t.bottomAt(ua), xb + t.bottomAt(ub));
    if (passesOver(cull, i, lo)) return;
    const double hi = flatTop && (t.top0 != 0.0 || (xa != 0.0 && xb != 0.0))
                          ? std::max(xa + t.top0, xb + t.top0)
                          : std::max(xa + t.topAt(ua), xb + t.topAt(ub));
    f(i, lo, hi);
  });
}

// Disc of radius r whose centre moves along the line a -> b (a capsule).
template <typename F, typename Cull = NoCull>
void sweepDiscLine(const Grid& g, Vec2 a, Vec2 b, double r, F&& f, const Cull& cull = {}) {
  if (a.x() > b.x()) std::swap(a, b);
  int first, last;
  g.range(a.x() - r, b.x() + r, first, last);
  if (first > last) return;
  const double r2 = r * r;
  auto half = [r2](double d) { return std::sqrt(std::max(0.0, r2 - d * d)); };
  const double len = (b - a).norm();
  const bool alongX = b.x() - a.x() < 1e-9 * std::max(1.0, len) || len < 1e-12;
  // lo is a centre's y less at most r (half() never exceeds r, and along Z the
  // tangent is y - r to the bit), so the bound is exact on a pass along Z.
  auto bound = [&](int p, int q) { return lineBound(g, p, q, a, b, -r, r, -r, true, alongX); };
  if (alongX) {
    const double lo = std::min(a.y(), b.y()), hi = std::max(a.y(), b.y());
    const double zc = (a.x() + b.x()) / 2;
    visitColumns(cull, first, last, bound, [&](int i) {
      const double h = half(g.centre(i) - zc);
      if (!passesOver(cull, i, lo - h)) f(i, lo - h, hi + h);
    });
    return;
  }
  const Vec2 d = (b - a) / len;
  const Vec2 down(d.y() * r, -d.x() * r);                         // normal with negative x, length r
  const double tLoA = a.x() + down.x(), tLoB = b.x() + down.x();  // lower tangent points' z
  const double tHiA = a.x() - down.x(), tHiB = b.x() - down.x();  // upper tangent points' z
  const double slope = (b.y() - a.y()) / (b.x() - a.x());
  visitColumns(cull, first, last, bound, [&](int i) {
    const double z = g.centre(i);
    double lo, hi;
    if (z < tLoA)
      lo = a.y() - half(z - a.x());
    else if (z > tLoB)
      lo = b.y() - half(z - b.x());
    else
      lo = a.y() + down.y() + (z - tLoA) * slope;
    if (passesOver(cull, i, lo)) return;  // (where it trails the surface the move before left)
    if (z < tHiA)
      hi = a.y() + half(z - a.x());
    else if (z > tHiB)
      hi = b.y() + half(z - b.x());
    else
      hi = a.y() - down.y() + (z - tHiA) * slope;
    if (hi >= lo) f(i, lo, hi);
  });
}

}  // namespace klueng::core::cut::detail

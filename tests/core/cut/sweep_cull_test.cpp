// The sweeps' MaterialCull (issue 29 item 14): a culled sweep visits every column
// where the primitive reaches below the material, with the same values in the same
// order as a full sweep, and leaves out only columns it could do nothing to.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "../../../src/core/cut/sweep.h"
#include "klueng/core/cut/stock.h"

namespace klueng::core::cut {
namespace {

using detail::Grid;
using detail::MaterialCull;
using Visit = std::tuple<int, double, double>;

Grid gridOf(const Stock& s) { return Grid{-s.length(), s.resolution(), s.columnCount()}; }

enum class Kind { Disc, Box, FlatTrapezoid, SlopedTrapezoid };

// Runs one primitive of `kind` along a -> b over the stock's grid, culled or not.
template <typename Cull>
std::vector<Visit> sweep(Kind kind, const Stock& s, const Vec2& a, const Vec2& b, const Cull& cull) {
  std::vector<Visit> out;
  auto f = [&out](int i, double lo, double hi) { out.emplace_back(i, lo, hi); };
  const Grid g = gridOf(s);
  switch (kind) {
    case Kind::Disc: detail::sweepDiscLine(g, a, b, 0.8, f, cull); break;
    case Kind::Box: detail::sweepBoxLine(g, a, b, Box{0.0, 3.0, 0.5, 12.0}, f, cull); break;
    case Kind::FlatTrapezoid:
      detail::sweepTrapezoidLine(g, a, b, Trapezoid{0.8, 9.0, 0.5, 0.5, 1.0, 1.0}, f, cull);
      break;
    case Kind::SlopedTrapezoid:
      detail::sweepTrapezoidLine(g, a, b, Trapezoid{0.0, 6.0, 3.0, 0.2, 8.0, 4.0}, f, cull);
      break;
  }
  return out;
}

bool sameBits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

// What the full sweep gives where it reaches below the material must be what the
// culled one gives, to the bit and in order; it may give more only where it cannot act.
void expectCullKeepsEveryReach(Kind kind, const Stock& s, const Vec2& a, const Vec2& b, const std::string& what) {
  const std::vector<Visit> all = sweep(kind, s, a, b, detail::NoCull{});
  const std::vector<Visit> culled = sweep(kind, s, a, b, MaterialCull{&s});
  std::vector<Visit> reaching;
  for (const Visit& v : all)
    if (std::get<1>(v) < s.outerRadius(std::get<0>(v))) reaching.push_back(v);
  std::size_t k = 0;
  for (const Visit& v : culled) {
    // Every culled visit is one of the full sweep's, in the same order.
    while (k < all.size() && std::get<0>(all[k]) != std::get<0>(v)) {
      ASSERT_FALSE(std::get<1>(all[k]) < s.outerRadius(std::get<0>(all[k])))
          << what << ": column " << std::get<0>(all[k]) << " reaches the material but was skipped";
      ++k;
    }
    ASSERT_LT(k, all.size()) << what << ": column " << std::get<0>(v) << " was not in the full sweep";
    EXPECT_TRUE(sameBits(std::get<1>(all[k]), std::get<1>(v)) && sameBits(std::get<2>(all[k]), std::get<2>(v)))
        << what << ": column " << std::get<0>(v);
    ++k;
  }
  for (; k < all.size(); ++k)
    ASSERT_FALSE(std::get<1>(all[k]) < s.outerRadius(std::get<0>(all[k])))
        << what << ": column " << std::get<0>(all[k]) << " reaches the material but was skipped";
  EXPECT_LE(reaching.size(), culled.size()) << what;
}

TEST(SweepCull, VisitsEveryColumnThePrimitiveReachesOnRandomStock) {
  std::mt19937 rng(29014);
  std::uniform_real_distribution<double> z(-130.0, 10.0), x(0.0, 35.0), unit(0.0, 1.0);
  for (int round = 0; round < 40; ++round) {
    Stock s(60.0, 120.0);
    // A rough surface: grooves, steps and undercuts (several intervals a column).
    for (int k = 0; k < 30; ++k) {
      const int i0 = static_cast<int>(unit(rng) * s.columnCount());
      const int n = 1 + static_cast<int>(unit(rng) * 400);
      const double lo = x(rng), hi = lo + 1.0 + unit(rng) * 20.0;
      for (int i = i0; i < std::min(s.columnCount(), i0 + n); ++i) s.remove(i, lo, hi);
    }
    for (int m = 0; m < 40; ++m) {
      Vec2 a(z(rng), x(rng)), b(z(rng), x(rng));
      if (m % 4 == 1) b.y() = a.y();  // along Z, the exact bound's case
      if (m % 4 == 2) b.x() = a.x();  // along X
      for (Kind kind : {Kind::Disc, Kind::Box, Kind::FlatTrapezoid, Kind::SlopedTrapezoid})
        expectCullKeepsEveryReach(kind, s, a, b,
                                  "round " + std::to_string(round) + " move " + std::to_string(m) + " kind " +
                                      std::to_string(static_cast<int>(kind)));
    }
  }
}

// The point of the cull: a pass along Z over the surface a twin pass has just cut
// visits no column of it, only the uncut shoulder beyond.
TEST(SweepCull, ASecondPassAlongZVisitsOnlyTheShoulder) {
  // Heights at which each primitive turns the Ø60 bar's outside down (no groove under it).
  for (auto [kind, y] :
       {std::pair{Kind::Disc, 29.37}, std::pair{Kind::Box, 24.37}, std::pair{Kind::FlatTrapezoid, 29.27}}) {
    Stock s(60.0, 120.0);
    const Vec2 a(1.3, y), b(-100.0, y);
    auto remove = [&s](int i, double lo, double hi) { s.remove(i, lo, hi); };
    const Grid g = gridOf(s);
    switch (kind) {
      case Kind::Disc: detail::sweepDiscLine(g, a, b, 0.8, remove); break;
      case Kind::Box: detail::sweepBoxLine(g, a, b, Box{0.0, 3.0, 0.5, 12.0}, remove); break;
      default: detail::sweepTrapezoidLine(g, a, b, Trapezoid{0.8, 9.0, 0.5, 0.5, 1.0, 1.0}, remove); break;
    }
    const std::vector<Visit> all = sweep(kind, s, a, b, detail::NoCull{});
    const std::vector<Visit> culled = sweep(kind, s, a, b, MaterialCull{&s});
    ASSERT_GT(all.size(), 1900u);
    ASSERT_LT(s.outerRadius(s.columnAt(-50.0)), 30.0) << static_cast<int>(kind);
    // At most the block of 32 columns at the shoulder (Z -100.8 .. -99.2) is visited.
    for (const Visit& v : culled) EXPECT_LT(s.zCentre(std::get<0>(v)), -99.2) << static_cast<int>(kind);
    EXPECT_LE(culled.size(), static_cast<std::size_t>(Stock::kBlock)) << static_cast<int>(kind);
  }
}

// A box's flat bottom and top skip Trapezoid::bottomAt / topAt: what the sweep gives must be
// what the interpolating formula gives, to the bit, also where a side or the path is 0 or -0
// (there the sign of a zero could differ).
TEST(SweepFlatEdge, GivesWhatTheInterpolatingFormulaGivesToTheBit) {
  // The formula every trapezoid used before the flat sides' short cut (sweepTrapezoidLine, not along X).
  auto formula = [](const Grid& g, const Vec2& a, const Vec2& b, const Trapezoid& t) {
    std::vector<Visit> out;
    const double dz = b.x() - a.x(), dx = b.y() - a.y();
    int first, last;
    g.range(std::min(a.x(), b.x()) + t.z0, std::max(a.x(), b.x()) + t.z1, first, last);
    for (int i = first; i <= last; ++i) {
      const double z = g.centre(i);
      double s0 = (z - t.z1 - a.x()) / dz, s1 = (z - t.z0 - a.x()) / dz;
      if (s0 > s1) std::swap(s0, s1);
      s0 = std::max(s0, 0.0);
      s1 = std::min(s1, 1.0);
      if (s0 > s1) continue;
      const double xa = a.y() + s0 * dx, xb = a.y() + s1 * dx;
      const double ua = z - (a.x() + s0 * dz), ub = z - (a.x() + s1 * dz);
      out.emplace_back(i, std::min(xa + t.bottomAt(ua), xb + t.bottomAt(ub)),
                       std::max(xa + t.topAt(ua), xb + t.topAt(ub)));
    }
    return out;
  };
  const Stock s(50.0, 100.0);
  const Grid g = gridOf(s);
  // The outside-turning tool's lowest box beside its R0.8 nose (tip 3), and boxes whose bottom
  // or top is 0 or -0.
  const Trapezoid edges[] = {Trapezoid::of(Box{0.8, 3.5, 0.0, 0.5}), Trapezoid::of(Box{0.75, 3.5, -0.0, 0.5}),
                             Trapezoid::of(Box{-2.0, 1.0, -0.5, 0.0}), Trapezoid::of(Box{-2.0, 1.0, -0.5, -0.0}),
                             Trapezoid::of(Box{0.0, 9.0, 0.5, 1.0})};
  // Moves of the yardstick program (a 0.086 mm step of the wave, radius in mm), a facing cut
  // to the centre line and beyond, a long slope; then passes along -0 whose box edge z0 = 0.75
  // starts exactly at a column centre: there the path's radius at the edge's end is -0, the
  // case where a bottom of -0 added without the formula could give -0 for its +0.
  std::vector<std::pair<Vec2, Vec2>> moves = {{Vec2(-0.742, 24.893), Vec2(-0.828, 24.8925)},
                                              {Vec2(-30.742, 24.8955), Vec2(-30.828, 24.896)},
                                              {Vec2(-5.5, 5.0), Vec2(-6.3, 0.0)},
                                              {Vec2(-5.5, 5.0), Vec2(-6.3, -0.0)},
                                              {Vec2(0.5, 0.0), Vec2(-40.0, -0.0)},
                                              {Vec2(0.5, -0.0), Vec2(-40.0, 0.0)},
                                              {Vec2(-10.0, 2.0), Vec2(-60.0, -3.0)}};
  for (int i = 1000; i < 1064; ++i) {
    const double z = g.centre(i) - 0.75;  // (exact: the same binade)
    moves.emplace_back(Vec2(z, -0.0), Vec2(z - 5.0, -0.0));
  }
  for (const Trapezoid& t : edges)
    for (const auto& [a, b] : moves) {
      std::vector<Visit> swept;
      detail::sweepTrapezoidLine(g, a, b, t, [&](int i, double lo, double hi) { swept.emplace_back(i, lo, hi); });
      const std::vector<Visit> expected = formula(g, a, b, t);
      ASSERT_EQ(swept.size(), expected.size());
      ASSERT_FALSE(swept.empty());
      for (std::size_t k = 0; k < swept.size(); ++k) {
        EXPECT_EQ(std::get<0>(swept[k]), std::get<0>(expected[k]));
        EXPECT_TRUE(sameBits(std::get<1>(swept[k]), std::get<1>(expected[k])) &&
                    sameBits(std::get<2>(swept[k]), std::get<2>(expected[k])))
            << "box bottom " << t.bottom0 << " top " << t.top0 << ", move to Z" << b.x() << ", column "
            << std::get<0>(swept[k]) << ": " << std::get<1>(swept[k]) << " against " << std::get<1>(expected[k]);
      }
    }
}

}  // namespace
}  // namespace klueng::core::cut

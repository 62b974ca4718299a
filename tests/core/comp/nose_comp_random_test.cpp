// Random stretches (fixed seed): whatever the input, the kernel returns
// finite, connected pieces in move order, or stops cleanly at an interference.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "comp_test_support.h"
#include "klueng/core/comp/nose_comp.h"

namespace klueng::core::comp {
namespace {

std::vector<Segment> randomStretch(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Segment> moves;
  Vec2 at(unit(rng) * 40 - 20, unit(rng) * 30);
  for (int i = 0; i < count; ++i) {
    const double pick = unit(rng);
    const bool edge = i == 0 || i == count - 1;  // start-up and cancel are straight
    if (pick < 0.08) {
      moves.push_back(Segment::line(at, at));  // repeated point
    } else if (pick < 0.12) {
      const Vec2 to = at + Vec2(1e-11, -1e-11);
      moves.push_back(Segment::line(at, to));
      at = to;
    } else if (pick < 0.55 || edge) {
      const double ang = unit(rng) * 2 * std::numbers::pi;
      const Vec2 to = at + (0.1 + unit(rng) * 8) * Vec2(std::cos(ang), std::sin(ang));
      moves.push_back(Segment::line(at, to));
      at = to;
    } else {
      const double r = 0.05 + unit(rng) * 6;
      const double ang = unit(rng) * 2 * std::numbers::pi;
      const Vec2 centre = at - r * Vec2(std::cos(ang), std::sin(ang));
      const bool ccw = unit(rng) < 0.5;
      const double sweep = (ccw ? 1 : -1) * (0.05 + unit(rng) * 3);
      const Vec2 to = centre + r * Vec2(std::cos(ang + sweep), std::sin(ang + sweep));
      moves.push_back(Segment::arc(at, to, centre, ccw));
      at = to;
    }
  }
  return moves;
}

TEST(RandomStretches, AlwaysFiniteConnectedAndInOrder) {
  std::mt19937 rng(20261122);
  int interfered = 0;
  for (int run = 0; run < 3000; ++run) {
    const auto moves = randomStretch(rng, 2 + run % 12);
    const Side side = run % 2 ? Side::Left : Side::Right;
    const double radius = 0.1 + (run % 7) * 0.3;
    const CompOutput out = compensate(CompInput{moves, side, radius, run % 10, run % 3 != 0});
    SCOPED_TRACE(::testing::Message() << "run " << run);
    const int covered = out.interference ? out.interference->source : static_cast<int>(moves.size());
    if (out.interference) ++interfered;
    testing::expectWellFormed(out, covered);
    if (::testing::Test::HasFailure()) return;
  }
  // The random paths are rough enough that some must interfere, and most must not.
  EXPECT_GT(interfered, 100);
  EXPECT_LT(interfered, 2900);
}

}  // namespace
}  // namespace klueng::core::comp

#pragma once
// Helpers shared by the nose-compensation tests: building programmed paths,
// distances to a path of lines/arcs, and continuity checks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "klueng/core/comp/nose_comp.h"
#include "klueng/core/comp/segment.h"
#include "klueng/core/geometry.h"

namespace klueng::core::comp::testing {

inline constexpr double kDeg = std::numbers::pi / 180.0;

// Programmed moves in (z, x radius), chained from one point to the next.
class PathBuilder {
 public:
  explicit PathBuilder(double z, double x) : at_(z, x) {}
  PathBuilder& lineTo(double z, double x) {
    moves_.push_back(Segment::line(at_, Vec2(z, x)));
    at_ = Vec2(z, x);
    return *this;
  }
  // G02 (cw = true) or G03 to (z, x) around the absolute centre (cz, cx).
  PathBuilder& arcTo(double z, double x, double cz, double cx, bool cw) {
    moves_.push_back(Segment::arc(at_, Vec2(z, x), Vec2(cz, cx), !cw));
    at_ = Vec2(z, x);
    return *this;
  }
  std::vector<Segment> build() const { return moves_; }

 private:
  Vec2 at_;
  std::vector<Segment> moves_;
};

inline double distanceToPath(const Vec2& p, std::span<const Segment> path) {
  double best = INFINITY;
  for (const Segment& s : path) best = std::min(best, distanceTo(s, p));
  return best;
}

inline std::vector<Segment> centrePath(const CompOutput& out) {
  std::vector<Segment> path;
  for (const CompPiece& p : out.pieces) path.push_back(p.path);
  return path;
}

inline std::vector<Segment> piecesOf(const CompOutput& out, int source) {
  std::vector<Segment> path;
  for (const CompPiece& p : out.pieces)
    if (p.source == source) path.push_back(p.path);
  return path;
}

inline bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

// Pieces join end to start, carry non-decreasing source indices and every
// input move up to `movesCovered` has at least one piece.
inline void expectWellFormed(const CompOutput& out, int movesCovered) {
  int expectedSource = 0;
  for (std::size_t k = 0; k < out.pieces.size(); ++k) {
    const CompPiece& p = out.pieces[k];
    EXPECT_TRUE(finite(p.path.start) && finite(p.path.end)) << "piece " << k;
    if (p.path.isArc()) {
      EXPECT_TRUE(finite(p.path.centre)) << "piece " << k;
    }
    EXPECT_TRUE(p.source == expectedSource || p.source == expectedSource + 1)
        << "piece " << k << " source " << p.source << " after " << expectedSource;
    expectedSource = std::max(expectedSource, p.source);
    if (k > 0) {
      EXPECT_LT((out.pieces[k - 1].path.end - p.path.start).norm(), 1e-6) << "gap before piece " << k;
    }
  }
  EXPECT_EQ(out.pieces.empty() ? -1 : out.pieces.back().source, movesCovered - 1);
}

#define EXPECT_VEC_NEAR(actual, expected, tol)           \
  do {                                                   \
    const ::klueng::core::Vec2 a_ = (actual);            \
    const ::klueng::core::Vec2 e_ = (expected);          \
    EXPECT_NEAR(a_.x(), e_.x(), tol) << "z of " #actual; \
    EXPECT_NEAR(a_.y(), e_.y(), tol) << "x of " #actual; \
  } while (0)

}  // namespace klueng::core::comp::testing

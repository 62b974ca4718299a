#pragma once
// Fitting one profile run (column centres z, radii r) with lines and arcs, and
// finding threads in it: the numeric half of part_features.cpp.
#include <vector>

#include "klueng/core/geometry.h"

namespace klueng::core::cut::fit {

// A fitted piece of a smooth run: points [first, last] of the run.
struct Piece {
  bool arc = false;
  int first = 0;
  int last = 0;
  double a = 0.0, b = 0.0;     // line: r = a + b·z
  Vec2 centre = Vec2::Zero();  // arc
  double radius = 0.0;
  bool upper = false;  // arc: the profile is the circle's upper half (r above the centre)
  double zLeft = 0.0;  // resolved extent (set by resolveJoins or the caller)
  double zRight = 0.0;
  double at(double z) const;  // r on the carrier (an arc clamps z into its circle)
};

// Splits points [first, last] of (z, r) into lines and arcs that pass within
// `tolerance` (mm, radial) of every point. Faces are the caller's business:
// the run must be smooth (no jumps).
std::vector<Piece> fitRun(const std::vector<double>& z, const std::vector<double>& r, int first, int last,
                          double tolerance);

// Sets zRight of each piece and zLeft of the next to where they meet (line
// intersections, tangent points, else the closest approach between them);
// the outer ends get `zStart` / `zEnd`.
void resolveJoins(std::vector<Piece>& pieces, const std::vector<double>& z, double zStart, double zEnd);

struct ThreadRun {
  int first = 0;  // points of the run covered by the teeth
  int last = 0;
  double pitch = 0.0;
  double crest = 0.0;  // radii
  double root = 0.0;
};

// Stretches of at least three equally spaced valleys with sloping flanks.
std::vector<ThreadRun> findThreads(const std::vector<double>& z, const std::vector<double>& r, int first, int last,
                                   double columnWidth);

}  // namespace klueng::core::cut::fit

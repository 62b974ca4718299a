#pragma once
// Tool nose radius compensation kernel (SPEC 9): pure geometry, no modal state.
//
// Input: the programmed moves of one compensated stretch, in order:
//   [0]      the start-up move (the G41/G42 block's G00/G01), from the nose
//            position before it (already the controlled point = programmed point)
//   [1..n-2] the contour (lines and arcs)
//   [n-1]    the cancel move (the G40 block's G00/G01) if `endsWithCancel`;
//            otherwise the stretch ends in compensation (e.g. the program ends)
// Output: the NOSE-CENTRE path, one or more pieces per input move (bridging
// arcs around convex corners are attached to the move that follows the corner,
// as a real control does), each tagged with the index of its input move.
// The controlled point (what the trace shows) is centre + R * tipVector(tip).
#include <optional>
#include <span>
#include <vector>

#include "klueng/core/comp/segment.h"

namespace klueng::core::comp {

enum class Side { Left = 1, Right = -1 };  // G41 = +1 (IsNoseComp), G42 = -1

struct CompInput {
  std::span<const Segment> moves;
  Side side = Side::Right;
  double radius = 0.0;       // nose radius R (> 0; R == 0 means: path unchanged)
  int tip = 3;               // imaginary tip 0..9
  bool endsWithCancel = true;
  // Without compensation the imaginary tip follows the program, so the nose
  // centre before start-up and after cancel is programmed - R * tipVector.
};

struct CompPiece {
  Segment path;       // nose-centre path
  int source = 0;     // index into CompInput::moves
};

struct Interference {
  int source = 0;     // index of the move where the nose cannot follow
  enum class Kind { ArcSmallerThanRadius, PathReversal } kind = Kind::PathReversal;
};

struct CompOutput {
  std::vector<CompPiece> pieces;
  std::optional<Interference> interference;  // set => pieces valid up to that move
};

CompOutput compensate(const CompInput& in);

// Offset of one segment by d to the left (d > 0) or right (d < 0) of travel;
// nullopt if an arc would collapse (radius - d <= 0 on its concave side).
std::optional<Segment> offsetSegment(const Segment& s, double d);

}  // namespace klueng::core::comp

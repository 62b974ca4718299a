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
//
// Rules (Fanuc 0i-TF type A; docs/nose-compensation.md):
//   start-up: from the uncompensated centre of its start to its end point offset
//             by R perpendicular to the START direction of the next move;
//   corners:  concave -> both offsets trimmed at their intersection; convex
//             turn <= 90 deg -> both extended to the intersection of their
//             carriers (lines always; with arcs when it lies past the ends and
//             within 2R of the corner); any other convex corner gets a bridging
//             arc of radius R around the programmed corner point; tangent
//             continuation adds nothing;
//   cancel:   from where the previous piece ended (offset perpendicular to the
//             END direction of the previous move) to the uncompensated centre
//             of its end point.
// Every move before an interference yields at least one piece; a zero-length
// move (or a piece trimmed to nothing) yields a zero-length line. R <= 0 leaves
// the path unchanged. A lone move with endsWithCancel is start-up and cancel at
// once: uncompensated centre to uncompensated centre.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/comp/segment.h"

namespace klueng::core::comp {

enum class Side { Left = 1, Right = -1 };  // G41 = +1 (IsNoseComp), G42 = -1

struct CompInput {
  std::span<const Segment> moves;
  Side side = Side::Right;
  double radius = 0.0;  // nose radius R (> 0; R == 0 means: path unchanged)
  int tip = 3;          // imaginary tip 0..9
  bool endsWithCancel = true;
  // Without compensation the imaginary tip follows the program, so the nose
  // centre before start-up and after cancel is programmed - R * tipVector.
};

struct CompPiece {
  Segment path;    // nose-centre path
  int source = 0;  // index into CompInput::moves
};

struct Interference {
  int source = 0;  // index of the move where the nose cannot follow
  enum class Kind {
    ArcSmallerThanRadius,  // concave arc radius < R (A201)
    PathReversal,          // the offset piece would run against its programmed direction (A202)
    ArcInStartUpOrCancel,  // start-up or cancel move is an arc: only G00/G01 allowed (A203)
  } kind = Kind::PathReversal;
};

struct CompOutput {
  std::vector<CompPiece> pieces;
  std::optional<Interference> interference;  // set => pieces valid up to that move
};

CompOutput compensate(const CompInput& in);

// The alarm code (A2xx, messages_comp.cpp) of an interference, and the
// Diagnostic::args its text expects: A201 {0} = arc radius, {1} = nose radius;
// A202 {0} = nose radius; A203 none. Radii in mm, at most 3 decimals.
std::string_view interferenceCode(Interference::Kind kind);
std::vector<std::string> interferenceArgs(const Interference& i, const CompInput& in);

// Direction from the nose centre to the imaginary tool tip for tip 0..9
// (SPEC 9 grid, +X up, +Z right). Components are -1, 0 or +1 (not normalised:
// the tip is the corner of the square around the nose). Tips 0 and 9 give (0,0).
Vec2 tipVector(int tip);

// Without compensation (G40) the imaginary tip follows the program: the nose
// centre is programmed - R * tipVector(tip).
Vec2 uncompensatedCentre(const Vec2& programmed, double radius, int tip);
Segment uncompensatedCentrePath(const Segment& programmed, double radius, int tip);
// The controlled point (imaginary tip, what the trace shows) of a nose centre.
Vec2 controlledPoint(const Vec2& centre, double radius, int tip);
Segment controlledPath(const Segment& centrePath, double radius, int tip);

// Offset of one segment by d to the left (d > 0) or right (d < 0) of travel;
// nullopt if an arc would collapse (radius - d <= 0 on its concave side).
std::optional<Segment> offsetSegment(const Segment& s, double d);

}  // namespace klueng::core::comp

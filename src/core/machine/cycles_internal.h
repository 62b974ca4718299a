#pragma once
// Shared machinery of the cycle expansions (cycles.cpp: Fanuc two-block forms,
// cycles_haas.cpp: Haas one-block forms, drilling.cpp: G81-G83). Not a public API.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "machine/cycles.h"

namespace klueng::core::machine::cycles::detail {

using A = gcode::CodeAction;  // the cycles switch on what a code does, not its number

using gcode::Block;
using gcode::Word;

inline constexpr double kEps = 1e-6;
inline constexpr double kArcTolerance = 0.01;  // mm, as the interpreter's arcs
inline constexpr double kMaxPasses = 10000;    // more passes than this is a typing slip, not a program
// A cycle's whole expansion (moves, not passes: pecks x positions, passes x
// profile length) is bounded too, checked before anything is allocated.
inline constexpr double kMaxCycleMoves = 200000;

// Moves of a peck cycle (G74/G75): per position, pecks of 2 moves and a
// retract and a step. `drill` along the pecks, `width` across, `peck`, `step`.
inline double peckCycleMoves(double drill, double peck, double width, double step) {
  const double pecks = peck > kEps ? std::ceil(drill / peck) : 1.0;
  const double positions = step > kEps ? std::floor(width / step) + 1.0 : 1.0;
  return positions * (2.0 * pecks + 3.0);
}

inline std::string num(double v) {
  if (std::abs(v) < 0.0005) v = 0.0;
  return fmt::format("{:.3f}", v);
}

inline double sign(double v) { return v > kEps ? 1.0 : v < -kEps ? -1.0 : 0.0; }

inline Step rapid(const Vec2& a, const Vec2& b) { return Step{StepKind::Rapid, Segment::line(a, b), 0.0, 0.0, {}, {}}; }
inline Step feedLine(const Vec2& a, const Vec2& b) {
  return Step{StepKind::Feed, Segment::line(a, b), 0.0, 0.0, {}, {}};
}
inline Step thread(const Vec2& a, const Vec2& b, double lead) {
  return Step{StepKind::Thread, Segment::line(a, b), lead, 0.0, {}, {}};
}

// One thread pass from s1 to s2 (then out to s3) at `lead`; with a chamfer,
// the last `chamfer` of Z is pulled out at 45 degrees, still threading
// (Fanuc G76 r, Haas Settings 95/96). sx: the direction towards the crest.
inline void threadPass(std::vector<Step>& steps, const Vec2& s1, const Vec2& s2, const Vec2& s3, double chamfer,
                       double sx, double lead) {
  const double length = std::abs(s2.x() - s1.x());
  chamfer = std::min(chamfer, length);
  if (chamfer > kEps) {
    const Vec2 c0 = s1 + (s2 - s1) * ((length - chamfer) / length);
    const Vec2 c1(s2.x(), c0.y() + sx * chamfer);
    steps.push_back(thread(s1, c0, lead));
    steps.push_back(thread(c0, c1, lead));
    steps.push_back(rapid(c1, s3));
  } else {
    steps.push_back(thread(s1, s2, lead));
    steps.push_back(rapid(s2, s3));
  }
}

// The passes of a multi-pass thread (Fanuc G76, Haas G76): for each depth, a
// rapid in along the flank (one-flank infeed: each pass starts depth·flank
// further along; flank = tan(angle/2), 0 for straight infeed), the thread pass
// to `target` with its pull-out chamfer, and back to the start `a`. height:
// thread height; taper: radius difference, start minus end.
template <typename Depths>
void threadInfeed(std::vector<Step>& steps, const Vec2& a, const Vec2& target, double height, double taper,
                  double flank, const Depths& depths, double chamfer, double lead) {
  const double sx = sign(a.y() - target.y());  // towards the crest (outside: +1)
  const double sz = sign(target.x() - a.x());
  for (const double depth : depths) {
    const double xPass = target.y() + sx * (height - depth);
    const Vec2 s0(a.x() + sz * depth * flank, a.y());
    const Vec2 s1(s0.x(), xPass + taper);
    const Vec2 s2(target.x(), xPass);
    const Vec2 s3(target.x(), a.y());
    if ((s0 - a).norm() > kEps) steps.push_back(rapid(a, s0));
    steps.push_back(rapid(s0, s1));
    threadPass(steps, s1, s2, s3, chamfer, sx, lead);
    steps.push_back(rapid(s3, a));
  }
}

inline CycleAlarm alarmAt(const char* code, const Word* w, const Block& b, std::vector<std::string> args) {
  return CycleAlarm{code, w ? w->range : SourceRange{b.line, 1, 0}, std::move(args)};
}

// P/Q of G74-G76 without a decimal point are in the least input increment
// (0.001 mm, 0.0001 inch); with one they are lengths.
inline double increment(const Word& w, double unit) {
  if (w.hasDecimalPoint) return w.value * unit;
  return w.value * (unit > 1.0 ? 0.0001 * unit : 0.001);
}

inline bool hasAxis(const Block& b) { return b.has('X') || b.has('Z') || b.has('U') || b.has('W'); }

// Target of an X/Z/U/W block from `from`, as the interpreter's axisTarget.
inline Vec2 axisTarget(const Block& b, const Vec2& from, const Vec2& offset, double unit) {
  Vec2 p = from;
  if (const Word* w = b.find('X')) p.y() = w->value * unit / 2.0 + offset.y();
  if (const Word* w = b.find('U')) p.y() += w->value * unit / 2.0;
  if (const Word* w = b.find('Z')) p.x() = w->value * unit + offset.x();
  if (const Word* w = b.find('W')) p.x() += w->value * unit;
  return p;
}

// Mirror (z, x) -> (x, z): G72 and G75 are G71 and G74 with the axes swapped.
// A mirror reverses the sense of rotation.
inline Vec2 swapped(const Vec2& p) { return Vec2(p.y(), p.x()); }
inline Segment swapped(const Segment& s) {
  if (s.isArc()) return Segment::arc(swapped(s.start), swapped(s.end), swapped(s.centre), !s.ccw);
  return Segment::line(swapped(s.start), swapped(s.end));
}
inline void swapAll(std::vector<Step>& steps) {
  for (Step& s : steps) s.path = swapped(s.path);
}

// Reads N(P)..N(Q) through the interpreter (CycleInput::readProfile).
std::optional<CycleAlarm> readProfile(const CycleInput& in, const Block& cycle, bool withFeed, Profile& out);
// Keeps only the moves (roughing cycles ignore G40-G42 inside the profile).
void movesOnly(Profile& p);

// G71 (swap = false) / G72 (swap = true) roughing: passes
// `depth` apart down to the profile offset by `allowance` + `roughAllowance`,
// each retracted by `retract` at 45 degrees, then one pass along the profile
// offset by `allowance`. Type I: the profile moves one way in both axes. Type II
// (X and Z both in the first profile block): one way along the passes, pockets
// allowed (roughPockets). `firstMayMoveAlong`: the first block may move along
// the passes without being type II.
std::optional<CycleAlarm> stockRemoval(const CycleInput& in, Profile& profile, double depth, double retract,
                                       const Vec2& allowance, bool swap, std::vector<Step>& out,
                                       const Vec2& roughAllowance = Vec2::Zero(), bool firstMayMoveAlong = false);

// Type II roughing (cycles_pockets.cpp), in stockRemoval's frame: the passes of a
// profile `roughed` that moves one way along them but dips into pockets. Each
// level cuts every stretch where the profile lies beyond it; a pocket is
// entered over the ridge at the start's height and down its cleared column.
// Appends to `steps` from `pos` and leaves `pos` where the tool ends.
std::optional<CycleAlarm> roughPockets(const std::string& g, const SourceRange& where, const Vec2& start,
                                       const std::vector<Step>& roughed, double depth, double retract, double sa,
                                       double sb, bool infeedRapid, std::vector<Step>& steps, Vec2& pos);
// The piece never moves back along the passes (direction sa).
bool movesOneWayAlong(const Segment& s, double sa);

// G74 peck cycle in the frame where pecks run along the first coordinate
// (G75: swap before and after): pecks of `peck` with `retract` back between
// them, `shiftStep` between the rows, then back to the start.
std::vector<Step> pecks(const Vec2& start, const Vec2& target, double peck, double shiftStep, double retract);

// The cycle block as the interpreter runs it (macro values evaluated).
inline const Block& cycleBlock(const CycleInput& in) {
  return in.block ? *in.block : in.program->blocks[static_cast<std::size_t>(in.blockIndex)];
}

inline std::string gName(const CycleInput& in, const gcode::CodeInfo& code) {
  return in.gWord ? "G" + in.gWord->number : fmt::format("G{}", code.number);
}

}  // namespace klueng::core::machine::cycles::detail

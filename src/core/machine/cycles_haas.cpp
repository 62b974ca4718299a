// Haas one-block multiple repetitive cycles (Haas NGC lathe operator's manual,
// "G-codes"; readings in docs/haas-cycles.md), expanded with the machinery of
// the Fanuc forms: the same profile reader, roughing, pecks and thread passes.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "machine/cycles_internal.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine::cycles {

using namespace detail;

namespace {

// A length word in mm (value in program units), or `fallback` (mm) without it.
double length(const Block& b, char letter, double unit, double fallback) {
  const Word* w = b.find(letter);
  return w ? w->value * unit : fallback;
}

// A machine setting in mm for the units in force (Haas keeps one value per unit).
double setting(double inchValue, double mmValue, double unit) { return unit > 1.0 ? inchValue * unit : mmValue; }

// Depths (radius, from the crest) of the G76 passes: D, then D·√n ("cutting
// amount constant", P1/P2) or n·D ("cutting depth constant", P3/P4), each at
// least `minCut` deeper than the one before, up to height - finish; then one
// pass at the full height when a finish allowance is set (Setting 86).
std::vector<double> haasThreadDepths(double height, double first, double minCut, double finish, bool constantDepth) {
  std::vector<double> depths;
  const double rough = height - finish;
  double prev = 0.0;
  for (int n = 1; rough > kEps && prev < rough - kEps && n <= kMaxPasses; ++n) {
    double next = constantDepth ? n * first : first * std::sqrt(static_cast<double>(n));
    if (next - prev < minCut) next = prev + minCut;
    next = std::min(next, rough);
    depths.push_back(next);
    prev = next;
  }
  if (finish > kEps || depths.empty()) depths.push_back(height);
  return depths;
}

Expansion roughing(const gcode::CodeInfo& code, const CycleInput& in, const Block& b) {
  const gcode::CodeAction g = code.action;
  Expansion e;
  const double u = in.unit;
  const std::string name = gName(in, code);
  const gcode::CycleSettings& s = in.profile->cycles;
  const double depth = length(b, 'D', u, setting(s.roughDepthInch, s.roughDepthMm, u));
  if (depth <= 0.0) {
    const Word* d = b.find('D');
    e.alarm = alarmAt(codes::kCycleNeedsPositive, d ? d : in.gWord, b, {name, "D"});
    return e;
  }
  Profile p;
  if (auto a = readProfile(in, b, false, p)) {
    e.alarm = a;
    return e;
  }
  // U/W: finish allowance (U diameter); I/K: rough pass allowance (I radius).
  const Vec2 finish(length(b, 'W', u, 0.0), length(b, 'U', u, 0.0) / 2.0);
  const Vec2 rough(length(b, 'K', u, 0.0), length(b, 'I', u, 0.0));
  const double retract = setting(s.roughRetractInch, s.roughRetractMm, u);
  if (auto a = stockRemoval(in, p, depth, retract, finish, g == A::FaceRoughing, e.steps, rough, true)) {
    e.alarm = a;
    return e;
  }
  if (p.ns > in.blockIndex) e.resumeAfter = p.nf;
  return e;
}

Expansion grooving(const gcode::CodeInfo& code, const CycleInput& in, const Block& b) {
  const gcode::CodeAction g = code.action;
  Expansion e;
  const double u = in.unit;
  const gcode::CycleSettings& s = in.profile->cycles;
  const Vec2 target = axisTarget(b, in.start, in.offset, u);
  const Word* iw = b.find('I');
  const Word* kw = b.find('K');
  const double i = iw ? std::abs(increment(*iw, u)) : 0.0;            // radius: X step (G74) or X peck (G75)
  const double k = kw ? std::abs(increment(*kw, u)) : 0.0;            // Z peck (G74) or Z step (G75)
  const double retract = setting(s.peckClearInch, s.peckClearMm, u);  // Setting 22
  const double drillDepth = std::abs(g == A::FacePecking ? zOf(target) - zOf(in.start) : xOf(target) - xOf(in.start));
  const double peck = g == A::FacePecking ? k : i;
  if (peck > kEps && drillDepth / peck > kMaxPasses) {
    e.alarm = alarmAt(codes::kTooManyPasses, g == A::FacePecking ? kw : iw, b,
                      {gName(in, code), fmt::format("{:.0f}", std::ceil(drillDepth / peck)), num(peck)});
    return e;
  }
  const double width = std::abs(g == A::FacePecking ? xOf(target) - xOf(in.start) : zOf(target) - zOf(in.start));
  const double moves = peckCycleMoves(drillDepth, peck, width, g == A::FacePecking ? i : k);
  if (moves > kMaxCycleMoves) {
    e.alarm = alarmAt(codes::kTooManyCycleMoves, in.gWord, b,
                      {gName(in, code), fmt::format("{:.0f}", moves), fmt::format("{:.0f}", kMaxCycleMoves)});
    return e;
  }
  if (g == A::FacePecking) {
    e.steps = pecks(in.start, target, k, i, retract);
  } else {
    e.steps = pecks(swapped(in.start), swapped(target), i, k, retract);
    swapAll(e.steps);
  }
  return e;
}

Expansion threading(const gcode::CodeInfo& code, const CycleInput& in, const Block& b) {
  Expansion e;
  const double u = in.unit;
  const std::string name = gName(in, code);
  const gcode::CycleSettings& s = in.profile->cycles;
  const Vec2 target = axisTarget(b, in.start, in.offset, u);
  const double height = length(b, 'K', u, 0.0);
  const double first = length(b, 'D', u, 0.0);
  if (height <= 0.0) {
    const Word* k = b.find('K');
    e.alarm = alarmAt(codes::kCycleNeedsPositive, k ? k : in.gWord, b, {name, "K"});
    return e;
  }
  if (first <= 0.0) {
    const Word* d = b.find('D');
    e.alarm = alarmAt(codes::kCycleNeedsPositive, d ? d : in.gWord, b, {name, "D"});
    return e;
  }
  const int method = b.has('P') ? b.find('P')->code() : 1;  // P1..P4, default P1
  const bool doubleEdge = method == 2 || method == 4;
  const bool constantDepth = method == 3 || method == 4;
  const double angle = b.has('A') ? b.find('A')->value : 0.0;  // tool nose angle, degrees
  const double taper = length(b, 'I', u, 0.0);                 // radius, start minus end
  const double minCut = setting(s.threadMinCutInch, s.threadMinCutMm, u);
  const double finish = setting(s.threadFinishInch, s.threadFinishMm, u);
  if (constantDepth && height / first > kMaxPasses) {
    e.alarm = alarmAt(codes::kTooManyPasses, b.find('D'), b,
                      {name, fmt::format("{:.0f}", std::ceil(height / first)), num(first)});
    return e;
  }
  const double flank = doubleEdge ? 0.0 : std::tan(angle / 2.0 * std::numbers::pi / 180.0);
  const double leads = in.threadChamfer ? s.threadChamferLeads : 0.0;  // M23/M24, Settings 95/96
  threadInfeed(e.steps, in.start, target, height, taper, flank,
               haasThreadDepths(height, first, minCut, finish, constantDepth), leads * in.feed, in.feed);
  return e;
}

}  // namespace

Expansion expandOneBlock(const gcode::CodeInfo& code, const CycleInput& in) {
  const Block& b = cycleBlock(in);
  switch (code.action) {
    case A::Finishing: {
      // G70 P Q is the same block in both forms.
      CycleMemory unused;
      return expand(code, in, unused);
    }
    case A::TurnRoughing:
    case A::FaceRoughing: return roughing(code, in, b);
    case A::PatternRepeating: {
      // D = number of passes, I/K = total relief (I radius): the Fanuc pattern
      // repeat with these values in its memory.
      const Word* d = b.find('D');
      CycleMemory m;
      m.g73Count = d ? static_cast<int>(std::lround(d->value)) : 0;
      m.g73ReliefX = length(b, 'I', in.unit, 0.0);
      m.g73ReliefZ = length(b, 'K', in.unit, 0.0);
      if (m.g73Count < 1) {
        Expansion e;
        e.alarm = alarmAt(codes::kCycleNeedsPositive, d ? d : in.gWord, b, {gName(in, code), "D"});
        return e;
      }
      return expand(code, in, m);
    }
    case A::FacePecking:
    case A::Grooving: return grooving(code, in, b);
    case A::ThreadCutting: return threading(code, in, b);
    default: return {};
  }
}

}  // namespace klueng::core::machine::cycles

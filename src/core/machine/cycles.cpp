// Fanuc 0i-TF lathe canned cycles expanded into simple moves (see cycles.h).
#include "machine/cycles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "machine/cycles_internal.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine::cycles {

using namespace detail;

std::vector<double> threadDepths(double k, double d1, double dmin, double d, int m) {
  std::vector<double> depths;
  const double rough = k - d;
  double prev = 0.0;
  for (int n = 1; rough > kEps && prev < rough - kEps; ++n) {
    double next = d1 * std::sqrt(static_cast<double>(n));
    if (next - prev < dmin) next = prev + dmin;
    next = std::min(next, rough);
    depths.push_back(next);
    prev = next;
    if (n > 10000) break;  // d1 and dmin both ~0 are refused before; a safety net
  }
  for (int i = 0; i < std::max(1, m); ++i) depths.push_back(k);
  return depths;
}

std::vector<Step> singleCycle(gcode::CodeAction g, const Vec2& start, const Vec2& target, double taper, double lead) {
  std::vector<Step> s;
  if (g == A::BoxFacing) {
    // Rapid in Z to the face (taper: Z at the start of the cut), face to X, back along Z, rapid out.
    const Vec2 p1(target.x() + taper, start.y());
    const Vec2 p3(start.x(), target.y());
    s.push_back(rapid(start, p1));
    s.push_back(feedLine(p1, target));
    s.push_back(feedLine(target, p3));
    s.push_back(rapid(p3, start));
    return s;
  }
  const Vec2 p1(start.x(), target.y() + taper);
  const Vec2 p3(target.x(), start.y());
  s.push_back(rapid(start, p1));
  if (g == A::BoxThreading) {
    s.push_back(thread(p1, target, lead));
    s.push_back(rapid(target, p3));
  } else {
    s.push_back(feedLine(p1, target));
    s.push_back(feedLine(target, p3));
  }
  s.push_back(rapid(p3, start));
  return s;
}

namespace {

// The length a word of the cycle block gives, else `fallback` (already in mm).
double cycleWordOr(const Block& b, char letter, double fallback, double unit) {
  const Word* w = b.find(letter);
  return w ? w->value * unit : fallback;
}

// The first block of a two-block cycle (G71 U R, G73 U W R, G74/G75 R, G76 P Q R): its values are
// remembered for the cycle's second block; nothing moves.
Expansion rememberCycleSettings(gcode::CodeAction g, const CycleInput& in, const Block& b, const std::string& name,
                                CycleMemory& memory) {
  Expansion e;
  const double u = in.unit;
  switch (g) {
    case A::TurnRoughing:
    case A::FaceRoughing: {
      const char depthLetter = g == A::TurnRoughing ? 'U' : 'W';
      const Word* dw = b.find(depthLetter);
      if (!dw || dw->value <= 0.0)
        e.alarm = alarmAt(codes::kCycleNeedsPositive, dw ? dw : in.gWord, b, {name, std::string(1, depthLetter)});
      else if (g == A::TurnRoughing)
        memory.g71Depth = dw->value * u, memory.g71Retract = cycleWordOr(b, 'R', memory.g71Retract, u);
      else
        memory.g72Depth = dw->value * u, memory.g72Retract = cycleWordOr(b, 'R', memory.g72Retract, u);
      break;
    }
    case A::PatternRepeating:
      memory.g73ReliefX = cycleWordOr(b, 'U', memory.g73ReliefX, u);
      memory.g73ReliefZ = cycleWordOr(b, 'W', memory.g73ReliefZ, u);
      if (const Word* r = b.find('R')) memory.g73Count = static_cast<int>(std::lround(r->value));
      break;
    case A::FacePecking: memory.g74Retract = cycleWordOr(b, 'R', memory.g74Retract, u); break;
    case A::Grooving: memory.g75Retract = cycleWordOr(b, 'R', memory.g75Retract, u); break;
    case A::ThreadCutting:
      if (const Word* p = b.find('P')) {
        const int mra = p->code();
        memory.g76Finishing = mra / 10000;
        memory.g76Chamfer = (mra / 100) % 100;
        memory.g76Angle = mra % 100;
      }
      if (const Word* q = b.find('Q')) memory.g76MinDepth = increment(*q, u);
      memory.g76Allowance = cycleWordOr(b, 'R', memory.g76Allowance, u);
      break;
    case A::Finishing: e.alarm = alarmAt(codes::kCycleNeedsPAndQ, in.gWord, b, {name}); break;
    default: break;
  }
  return e;
}

// G70: the P-Q shape as written, then back to the start.
Expansion expandFinishing(const CycleInput& in, const Block& b) {
  Expansion e;
  Profile p;
  if (auto a = readProfile(in, b, true, p)) {
    e.alarm = a;
    return e;
  }
  e.steps = p.moves;
  Vec2 end = in.start;
  for (const Step& s : p.moves)
    if (s.kind != StepKind::Compensation) end = s.path.end;
  e.steps.push_back(rapid(end, in.start));
  return e;
}

// G71 / G72: the stock removed in passes along Z (X for G72), the shape left with its allowance.
Expansion expandRoughing(gcode::CodeAction g, const CycleInput& in, const Block& b, const std::string& name,
                         const CycleMemory& memory) {
  Expansion e;
  const double depth = g == A::TurnRoughing ? memory.g71Depth : memory.g72Depth;
  if (depth <= 0.0) {
    e.alarm = alarmAt(codes::kCycleNeedsPositive, in.gWord, b, {name, g == A::TurnRoughing ? "U" : "W"});
    return e;
  }
  Profile p;
  if (auto a = readProfile(in, b, false, p)) {
    e.alarm = a;
    return e;
  }
  const Vec2 allowance(cycleWordOr(b, 'W', 0.0, in.unit), cycleWordOr(b, 'U', 0.0, in.unit) / 2.0);
  if (auto a = stockRemoval(in, p, depth, g == A::TurnRoughing ? memory.g71Retract : memory.g72Retract, allowance,
                            g == A::FaceRoughing, e.steps)) {
    e.alarm = a;
    return e;
  }
  if (p.ns > in.blockIndex) e.resumeAfter = p.nf;
  return e;
}

// G73: the shape again and again, each pass closer by the relief's share.
Expansion expandPatternRepeating(const CycleInput& in, const Block& b, const std::string& name,
                                 const CycleMemory& memory) {
  Expansion e;
  if (memory.g73Count > kMaxPasses) {
    e.alarm = alarmAt(codes::kTooManyPasses, in.gWord, b, {name, std::to_string(memory.g73Count), "R"});
    return e;
  }
  if (memory.g73Count < 1) {
    e.alarm = alarmAt(codes::kCycleNeedsPositive, in.gWord, b, {name, "R"});
    return e;
  }
  Profile p;
  if (auto a = readProfile(in, b, false, p)) {
    e.alarm = a;
    return e;
  }
  movesOnly(p);
  const double moves = static_cast<double>(memory.g73Count) * static_cast<double>(p.moves.size() + 1);
  if (moves > kMaxCycleMoves) {
    e.alarm = alarmAt(codes::kTooManyCycleMoves, in.gWord, b,
                      {name, fmt::format("{:.0f}", moves), fmt::format("{:.0f}", kMaxCycleMoves)});
    return e;
  }
  const Vec2 allowance(cycleWordOr(b, 'W', 0.0, in.unit), cycleWordOr(b, 'U', 0.0, in.unit) / 2.0);
  const Vec2 relief(memory.g73ReliefZ, memory.g73ReliefX);
  const int d = memory.g73Count;
  Vec2 pos = in.start;
  for (int j = 0; j < d; ++j) {
    // Pass j: the profile moved by the allowance plus the part of the relief still left.
    const double frac = d > 1 ? static_cast<double>(d - 1 - j) / (d - 1) : 0.0;
    const Vec2 shift = allowance + frac * relief;
    const Step& first = p.moves.front();
    const Vec2 a1 = first.path.end + shift;
    e.steps.push_back(first.kind == StepKind::Rapid ? rapid(pos, a1) : feedLine(pos, a1));
    for (std::size_t i = 1; i < p.moves.size(); ++i) {
      Step s = p.moves[i];
      s.path = s.path.translated(shift);
      s.feed = 0.0;
      s.where = {};
      e.steps.push_back(s);
    }
    pos = p.moves.back().path.end + shift;
    e.steps.push_back(rapid(pos, in.start));
    pos = in.start;
  }
  if (p.ns > in.blockIndex) e.resumeAfter = p.nf;
  return e;
}

// G74 / G75: pecks along Z (G74) or X (G75), stepping across by P (G74) or Q (G75).
Expansion expandPecking(gcode::CodeAction g, const CycleInput& in, const Block& b, const std::string& name,
                        const CycleMemory& memory) {
  Expansion e;
  const double u = in.unit;
  const Vec2 target = axisTarget(b, in.start, in.offset, u);
  const Word* pw = b.find('P');
  const Word* qw = b.find('Q');
  const double across = pw ? increment(*pw, u) : 0.0;  // Δi: X step (G74) or X peck (G75)
  const double along = qw ? increment(*qw, u) : 0.0;   // Δk: Z peck (G74) or Z step (G75)
  const double drill = std::abs(g == A::FacePecking ? zOf(target) - zOf(in.start) : xOf(target) - xOf(in.start));
  const double peck = g == A::FacePecking ? along : across;
  if (peck > kEps && drill / peck > kMaxPasses) {
    e.alarm = alarmAt(codes::kTooManyPasses, g == A::FacePecking ? qw : pw, b,
                      {name, fmt::format("{:.0f}", std::ceil(drill / peck)), num(peck)});
    return e;
  }
  const double width = std::abs(g == A::FacePecking ? xOf(target) - xOf(in.start) : zOf(target) - zOf(in.start));
  const double moves = peckCycleMoves(drill, peck, width, std::abs(g == A::FacePecking ? across : along));
  if (moves > kMaxCycleMoves) {
    e.alarm = alarmAt(codes::kTooManyCycleMoves, in.gWord, b,
                      {name, fmt::format("{:.0f}", moves), fmt::format("{:.0f}", kMaxCycleMoves)});
    return e;
  }
  if (g == A::FacePecking) {
    e.steps = pecks(in.start, target, along, across, memory.g74Retract);
  } else {
    e.steps = pecks(swapped(in.start), swapped(target), across, along, memory.g75Retract);
    swapAll(e.steps);
  }
  return e;
}

// G76's second block: the thread in passes of less and less depth, then the pull-out.
Expansion expandThreading(const CycleInput& in, const Block& b, const std::string& name, const CycleMemory& memory) {
  Expansion e;
  const double u = in.unit;
  const Vec2 target = axisTarget(b, in.start, in.offset, u);
  const Word* pw = b.find('P');
  const Word* qw = b.find('Q');
  const double height = pw ? increment(*pw, u) : 0.0;
  const double first = qw ? increment(*qw, u) : 0.0;
  if (height <= 0.0) {
    e.alarm = alarmAt(codes::kCycleNeedsPositive, pw ? pw : in.gWord, b, {name, "P"});
    return e;
  }
  if (first <= 0.0 && memory.g76MinDepth <= 0.0) {
    e.alarm = alarmAt(codes::kCycleNeedsPositive, qw ? qw : in.gWord, b, {name, "Q"});
    return e;
  }
  const double taper = cycleWordOr(b, 'R', 0.0, u);  // R(i): radius difference, start minus end
  const double flank = std::tan(memory.g76Angle / 2.0 * std::numbers::pi / 180.0);
  const auto depths = threadDepths(height, first, memory.g76MinDepth, memory.g76Allowance, memory.g76Finishing);
  // Pull-out at 45 degrees over the last r/10 leads, still threading.
  threadInfeed(e.steps, in.start, target, height, taper, flank, depths, memory.g76Chamfer / 10.0 * in.feed, in.feed);
  return e;
}

}  // namespace

Expansion expand(const gcode::CodeInfo& code, const CycleInput& in, CycleMemory& memory) {
  const gcode::CodeAction g = code.action;
  const Block& b = cycleBlock(in);
  const std::string name = gName(in, code);
  const bool secondBlock =
      (g == A::Finishing || g == A::TurnRoughing || g == A::FaceRoughing || g == A::PatternRepeating)
          ? (b.has('P') || b.has('Q'))
          : hasAxis(b);
  if (!secondBlock) return rememberCycleSettings(g, in, b, name, memory);
  switch (g) {
    case A::Finishing: return expandFinishing(in, b);
    case A::TurnRoughing:
    case A::FaceRoughing: return expandRoughing(g, in, b, name, memory);
    case A::PatternRepeating: return expandPatternRepeating(in, b, name, memory);
    case A::FacePecking:
    case A::Grooving: return expandPecking(g, in, b, name, memory);
    case A::ThreadCutting: return expandThreading(in, b, name, memory);
    default: return Expansion{};
  }
}

}  // namespace klueng::core::machine::cycles
// Drilling cycles on the spindle axis, G81/G82/G83, Fanuc 0i-TF and Haas
// (docs/haas-cycles.md, "Drilling"). The dialects differ in what R means
// (MachineProfile::cycles.drillR), the unit of P (dwellP) and the peck
// clearance (cycles.peckClear*); the moves are the same.
#include <algorithm>
#include <cmath>

#include "machine/cycles_internal.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine::cycles {

using namespace detail;

double dwellSeconds(const gcode::Word& p, gcode::DwellPUnit rule) {
  if (rule == gcode::DwellPUnit::SecondsWithPointElseMs && p.hasDecimalPoint) return std::max(0.0, p.value);
  return std::max(0.0, p.value / 1000.0);
}

std::optional<CycleAlarm> readDrillWords(const gcode::CodeInfo& code, const CycleInput& in, bool fresh, DrillWords& w) {
  const gcode::CodeAction g = code.action;
  const Block& b = cycleBlock(in);
  const gcode::MachineProfile& profile = *in.profile;
  const double u = in.unit;
  const bool inch = u > 1.0;
  const std::string name = gName(in, code);
  w.g = g;  // the kind of hole, kept for the next positions
  if (fresh) {
    // A new cycle: only what this block says (R at the initial level unless given).
    w.rPlane = in.start.x();
    w.peck = w.firstPeck = w.reduce = w.minPeck = w.dwell = 0.0;
    w.repeats = 1;
    w.hole = in.start;
    w.initialLevel = in.start.x();
  }
  w.returnToRPoint = in.returnToRPoint;  // the return level in force at each hole
  w.clearance = inch ? profile.cycles.peckClearInch * u : profile.cycles.peckClearMm;
  if (!b.has('Z') && !b.has('W') && fresh) return alarmAt(codes::kCycleNeedsPositive, in.gWord, b, {name, "Z"});
  const bool plane = profile.cycles.drillR == gcode::DrillR::Plane;
  if (const Word* r = b.find('R')) {
    // Fanuc: the distance from the initial level to the R point; Haas: the R plane's Z.
    w.rPlane = plane ? r->value * u + in.offset.x() : in.start.x() + r->value * u;
  }
  // The hole: X (U) its position on the initial level, Z its bottom; W counts
  // from the R point (Fanuc) or from the initial level (Haas).
  const double bottom = w.hole.x();
  w.hole = axisTarget(b, Vec2(bottom, w.hole.y()), in.offset, u);
  if (const Word* wz = b.find('W')) w.hole.x() = (plane ? in.start.x() : w.rPlane) + wz->value * u;
  if (const Word* q = b.find('Q')) w.peck = std::abs(increment(*q, u));
  if (g == A::PeckDrilling) {
    // Haas G83 I J K: first peck, reduction per peck, least peck (Fanuc has no I J
    // in this cycle; its K is the repeat count).
    if (const Word* i = b.find('I')) w.firstPeck = std::abs(i->value * u);
    if (const Word* j = b.find('J')) w.reduce = std::abs(j->value * u);
    if (profile.cycles.drillR == gcode::DrillR::Plane)
      if (const Word* k = b.find('K')) w.minPeck = std::abs(k->value * u);
  }
  if (const Word* p = b.find('P')) w.dwell = g == A::Drilling ? 0.0 : dwellSeconds(*p, profile.dwellP);
  const Word* repeat = profile.cycles.drillR == gcode::DrillR::Plane ? b.find('L') : b.find('K');
  if (repeat) w.repeats = std::max(0, static_cast<int>(std::lround(repeat->value)));
  if (g == A::PeckDrilling && w.firstPeck <= 0.0 && w.peck > kEps) {
    const double depth = std::abs(w.hole.x() - w.rPlane);
    if (depth / w.peck > kMaxPasses) {
      const Word* q = b.find('Q');
      return alarmAt(codes::kTooManyPasses, q ? q : in.gWord, b,
                     {name, fmt::format("{:.0f}", std::ceil(depth / w.peck)), num(w.peck)});
    }
  }
  // The whole cycle is bounded (repeats x pecks, three moves a peck) before
  // anything is allocated: K3500 over 4,800 pecks of 0.01 mm is 50 million moves.
  const double depth = std::abs(w.hole.x() - w.rPlane);
  double pecks = 1.0;
  if (g == A::PeckDrilling && (w.peck > kEps || w.firstPeck > kEps)) {
    const double least = w.firstPeck > kEps ? (w.reduce > 0.0 ? std::max(w.minPeck, kEps * 10) : w.firstPeck) : w.peck;
    pecks = std::min(kMaxPasses, std::ceil(depth / least));
  }
  const double moves = static_cast<double>(w.repeats) * (3.0 * pecks + 3.0);
  if (moves > kMaxCycleMoves)
    return alarmAt(codes::kTooManyCycleMoves, repeat ? repeat : in.gWord, b,
                   {name, fmt::format("{:.0f}", moves), fmt::format("{:.0f}", kMaxCycleMoves)});
  return std::nullopt;
}

std::vector<Step> drill(const DrillWords& w, const Vec2& start) {
  std::vector<Step> steps;
  const double bottom = w.hole.x();
  const double sz = sign(bottom - w.rPlane);  // into the hole (-1 drilling from the right face)
  const double depth = std::abs(bottom - w.rPlane);
  // Peck depths from the R point: Q each (Haas I, then less by J, never under K).
  std::vector<double> levels;
  if (w.g == A::PeckDrilling && (w.peck > kEps || w.firstPeck > kEps)) {
    double done = 0.0;
    double peck = w.firstPeck > kEps ? w.firstPeck : w.peck;
    while (done < depth - kEps && levels.size() < static_cast<std::size_t>(kMaxPasses)) {
      done = std::min(depth, done + peck);
      levels.push_back(done);
      if (w.firstPeck > kEps) peck = std::max(peck - w.reduce, w.minPeck > kEps ? w.minPeck : kEps * 10);
    }
  } else {
    levels.push_back(depth);
  }
  Vec2 pos = start;
  // Over the hole at the level the tool is at: the initial level, or the R point
  // after a hole under G99 (systems B and C).
  const Vec2 overHole(start.x(), w.hole.y());
  const Vec2 initial(w.initialLevel, w.hole.y());
  const Vec2 rPoint(w.rPlane, w.hole.y());
  auto rapidTo = [&](const Vec2& p) {
    if ((p - pos).norm() > kEps) steps.push_back(rapid(pos, p));
    pos = p;
  };
  for (int n = 0; n < w.repeats; ++n) {
    if (n == 0) rapidTo(overHole);  // a repeat starts where the last one returned
    rapidTo(rPoint);
    double reached = 0.0;
    for (std::size_t i = 0; i < levels.size(); ++i) {
      if (i > 0) {
        // Back to the R point to clear the chips, then rapid down to the
        // clearance above the last peck and feed on.
        rapidTo(rPoint);
        rapidTo(Vec2(w.rPlane + sz * std::max(0.0, reached - w.clearance), w.hole.y()));
      }
      const Vec2 to(w.rPlane + sz * levels[i], w.hole.y());
      steps.push_back(feedLine(pos, to));
      pos = to;
      reached = levels[i];
    }
    if (w.dwell > 0.0) {
      Step d;
      d.kind = StepKind::Dwell;
      d.path = Segment::line(pos, pos);
      d.seconds = w.dwell;
      steps.push_back(d);
    }
    // Back to the initial level (G-code system A, Haas, G98 of systems B and C), or
    // only to the R point under G99 of systems B and C: the next hole starts from there.
    rapidTo(w.returnToRPoint ? rPoint : initial);
  }
  return steps;
}

}  // namespace klueng::core::machine::cycles

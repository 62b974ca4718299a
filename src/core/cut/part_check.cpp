#include "klueng/core/cut/part_check.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::cut {

namespace {

// The ideal run's shapes live under offsets shifted by this (a ToolLibrary key
// no offset table reaches), so one library holds both kinds of tool.
constexpr int kIdealOffset = 100000;

// The part of t on one side of the line x = limit (below it, or above it).
// Where t's far line crosses the limit the strip ends there: a sliver never
// runs on along the rest of the trapezoid.
Trapezoid clipX(const Trapezoid& t, double limit, bool keepBelow) {
  const double near0 = keepBelow ? t.bottom0 : t.top0, near1 = keepBelow ? t.bottom1 : t.top1;
  const auto inside = [&](double v) { return keepBelow ? v < limit : v > limit; };
  if (!inside(near0) && !inside(near1)) return Trapezoid{t.z0, t.z0, 0, 0, 0, 0};  // nothing left
  double z0 = t.z0, z1 = t.z1;
  if (inside(near0) != inside(near1)) {
    const double zc = t.z0 + (limit - near0) / (near1 - near0) * (t.z1 - t.z0);
    (inside(near0) ? z1 : z0) = zc;
  }
  Trapezoid c{z0, z1, t.bottomAt(z0), t.bottomAt(z1), t.topAt(z0), t.topAt(z1)};
  if (keepBelow) {
    c.top0 = std::min(c.top0, limit);
    c.top1 = std::min(c.top1, limit);
    c.bottom0 = std::min(c.bottom0, c.top0);
    c.bottom1 = std::min(c.bottom1, c.top1);
  } else {
    c.bottom0 = std::max(c.bottom0, limit);
    c.bottom1 = std::max(c.bottom1, limit);
    c.top0 = std::max(c.top0, c.bottom0);
    c.top1 = std::max(c.top1, c.bottom1);
  }
  return c;
}

Trapezoid clipZ(const Trapezoid& t, double limit, bool keepLeft) {
  Trapezoid c = t;
  const double z = std::clamp(limit, t.z0, t.z1);
  if (keepLeft) {
    c.z1 = z;
    c.bottom1 = t.bottomAt(z);
    c.top1 = t.topAt(z);
  } else {
    c.z0 = z;
    c.bottom0 = t.bottomAt(z);
    c.top0 = t.topAt(z);
  }
  return c;
}

bool hasArea(const Trapezoid& t) {
  return t.z1 > t.z0 && (t.top0 > t.bottom0 || t.top1 > t.bottom1);
}

// Moves whose form is the tool's own: threading passes, drilling on the axis.
bool keepsWholeTool(const machine::Move& m) {
  if (m.kind == machine::MoveKind::Thread) return true;
  return std::abs(m.path.start.y()) < 1e-6 && std::abs(m.path.end.y()) < 1e-6;
}

struct Finding {
  DefectKind kind;
  FeatureSide side;
  int column;
  double depth;
  double described;  // radius of the described surface
  int cause = -1;    // move index
};

}  // namespace

ToolShape idealToolShape(const ToolShape& real, double strip) {
  ToolShape s = real;
  s.cutting.clear();
  s.holder.clear();
  const double r = real.noseRadius;
  const Vec2 c = real.noseCentre;
  Box edge{c.x() - r, c.x() + r, c.y() - r, c.y() + r};
  for (const Trapezoid& t : real.cutting) {
    const Box b = t.bounds();
    edge.z0 = std::min(edge.z0, b.z0);
    edge.z1 = std::max(edge.z1, b.z1);
    edge.x0 = std::min(edge.x0, b.x0);
    edge.x1 = std::max(edge.x1, b.x1);
  }
  const Vec2 tip = tipVector(real.tip);
  // The body behind the nose (away from the part): the real tool's edge above
  // the nose's centre within the nose's width, and all of it beyond the nose's
  // top — a roughing pass never leaves a shell above its path in the described
  // part. (So a trailing edge gouges only where it runs below the nose's top.)
  for (const Trapezoid& t : real.cutting) {
    if (tip.y() != 0.0) {
      const Trapezoid band = clipZ(clipZ(t, c.x() - r, false), c.x() + r, true);
      if (hasArea(band)) s.cutting.push_back(clipX(band, c.y(), tip.y() > 0.0));
      s.cutting.push_back(clipX(t, c.y() - tip.y() * r, tip.y() > 0.0));
    } else if (tip.x() != 0.0) {
      const Trapezoid band = clipX(clipX(t, c.y() - r, false), c.y() + r, true);
      if (hasArea(band)) s.cutting.push_back(clipZ(band, c.x(), tip.x() > 0.0));
      s.cutting.push_back(clipZ(t, c.x() - tip.x() * r, tip.x() > 0.0));
    }
  }
  for (const Trapezoid& t : real.cutting) {
    if (tip.y() < 0.0) s.cutting.push_back(clipX(t, edge.x0 + strip, true));
    if (tip.y() > 0.0) s.cutting.push_back(clipX(t, edge.x1 - strip, false));
    if (tip.x() < 0.0) s.cutting.push_back(clipZ(t, edge.z0 + strip, true));
    if (tip.x() > 0.0) s.cutting.push_back(clipZ(t, edge.z1 - strip, false));
  }
  std::erase_if(s.cutting, [](const Trapezoid& t) { return !hasArea(t); });
  s.bounds = Box{c.x() - r, c.x() + r, c.y() - r, c.y() + r};
  for (const Trapezoid& t : s.cutting) {
    const Box b = t.bounds();
    s.bounds.z0 = std::min(s.bounds.z0, b.z0);
    s.bounds.z1 = std::max(s.bounds.z1, b.z1);
    s.bounds.x0 = std::min(s.bounds.x0, b.x0);
    s.bounds.x1 = std::max(s.bounds.x1, b.x1);
  }
  return s;
}

double PartCheck::largestGouge() const {
  double m = 0.0;
  for (const PartDefect& d : defects)
    if (d.kind == DefectKind::Gouge) m = std::max(m, d.depth);
  return m;
}

double PartCheck::largestLeftover() const {
  double m = 0.0;
  for (const PartDefect& d : defects)
    if (d.kind == DefectKind::Leftover) m = std::max(m, d.depth);
  return m;
}

PartCheck checkPart(const machine::Timeline& timeline, const CutSetup& setup, const PartCheckOptions& options) {
  return checkPart(timeline, setup, ToolLibrary(setup.tools, setup.offsets), options);
}

PartCheck checkPart(const machine::Timeline& timeline, const CutSetup& setup, const ToolLibrary& tools,
                    const PartCheckOptions& options) {
  PartCheck out;
  CutOptions cutOptions;
  cutOptions.resolution = options.resolution;
  cutOptions.checkpointBudgetBytes = 0;  // forward only

  CutSimulator real(timeline, setup, tools, cutOptions);
  real.runToEnd();
  out.stoppedBy = real.stoppingAlarm();
  const double end = real.endTime();

  // The same moves with the ideal tools (no holder: nothing to collide).
  machine::Timeline idealTimeline = timeline;
  ToolLibrary idealTools = tools;
  std::set<std::pair<int, int>> made;
  for (machine::Move& m : idealTimeline.moves) {
    if (m.tool <= 0 || keepsWholeTool(m)) continue;
    const ToolShape* shape = idealTools.get(m.tool, m.offset);
    if (!shape) continue;
    if (made.insert({m.tool, m.offset}).second) idealTools.set(m.tool, m.offset + kIdealOffset, idealToolShape(*shape));
    m.offset += kIdealOffset;
  }
  CutOptions idealOptions = cutOptions;
  idealOptions.detectCollisions = false;
  CutSimulator ideal(idealTimeline, setup, idealTools, idealOptions);
  ideal.advanceTo(end);

  out.cut = real.stock();
  const Stock& a = real.stock();
  const Stock& b = ideal.stock();
  out.nothingCut = b.removedVolume() <= 0.0 && a.removedVolume() <= 0.0;
  std::vector<Finding> findings;
  for (int i = 0; i < a.columnCount(); ++i) {
    const double ro = a.outerRadius(i), io = b.outerRadius(i);
    if (io - ro > options.gougeTolerance) findings.push_back({DefectKind::Gouge, FeatureSide::Outside, i, io - ro, io});
    if (ro - io > options.leftoverTolerance)
      findings.push_back({DefectKind::Leftover, FeatureSide::Outside, i, ro - io, io});
    if (ro <= 0.0 || io <= 0.0) continue;  // no bore where nothing is left
    const double ri = a.innerRadius(i), ii = b.innerRadius(i);
    if (ri - ii > options.gougeTolerance) findings.push_back({DefectKind::Gouge, FeatureSide::Inside, i, ri - ii, ii});
    if (ii - ri > options.leftoverTolerance)
      findings.push_back({DefectKind::Leftover, FeatureSide::Inside, i, ii - ri, ii});
  }
  if (findings.empty()) return out;

  // Which block did it: replay both runs move by move; a gouge belongs to the
  // real move after which the column first went below the described part, a
  // leftover to the ideal move after which the described part went below what stayed.
  CutSimulator realReplay(timeline, setup, tools, cutOptions);
  CutSimulator idealReplay(idealTimeline, setup, idealTools, idealOptions);
  std::size_t pending = findings.size();
  for (std::size_t k = 0; k < timeline.moves.size() && pending > 0; ++k) {
    const machine::Move& m = timeline.moves[k];
    if (m.tStart >= end) break;
    const double t = std::min(m.tEnd, end);
    realReplay.advanceTo(t);
    idealReplay.advanceTo(t);
    if (m.kind == machine::MoveKind::Dwell) continue;
    for (Finding& f : findings) {
      if (f.cause >= 0) continue;
      const Stock& s = f.kind == DefectKind::Gouge ? realReplay.stock() : idealReplay.stock();
      const Stock& other = f.kind == DefectKind::Gouge ? b : a;  // the final described / real surface
      const bool outside = f.side == FeatureSide::Outside;
      const double now = outside ? s.outerRadius(f.column) : s.innerRadius(f.column);
      const double mark = outside ? other.outerRadius(f.column) : other.innerRadius(f.column);
      const double tol = f.kind == DefectKind::Gouge ? options.gougeTolerance : options.leftoverTolerance;
      if (outside ? now < mark - tol : now > mark + tol) {
        f.cause = static_cast<int>(k);
        --pending;
      }
    }
  }

  // Runs of neighbouring columns with the same kind, side and cause are one defect.
  std::sort(findings.begin(), findings.end(), [](const Finding& x, const Finding& y) {
    if (x.kind != y.kind) return x.kind < y.kind;
    if (x.side != y.side) return x.side < y.side;
    return x.column < y.column;
  });
  for (std::size_t k = 0; k < findings.size();) {
    std::size_t e = k;
    while (e + 1 < findings.size() && findings[e + 1].kind == findings[k].kind &&
           findings[e + 1].side == findings[k].side && findings[e + 1].column == findings[e].column + 1 &&
           findings[e + 1].cause == findings[k].cause)
      ++e;
    PartDefect d;
    d.kind = findings[k].kind;
    d.side = findings[k].side;
    d.zLeft = a.zLeft(findings[k].column);
    d.zRight = a.zRight(findings[e].column);
    for (std::size_t m = k; m <= e; ++m) {
      if (findings[m].depth <= d.depth) continue;
      d.depth = findings[m].depth;
      d.z = a.zCentre(findings[m].column);
      d.diameter = 2.0 * findings[m].described;
    }
    if (findings[k].cause >= 0) {
      d.line = timeline.moves[static_cast<std::size_t>(findings[k].cause)].line;
      d.file = timeline.moves[static_cast<std::size_t>(findings[k].cause)].file;
    }
    out.defects.push_back(d);
    k = e + 1;
  }
  std::sort(out.defects.begin(), out.defects.end(),
            [](const PartDefect& x, const PartDefect& y) { return x.zRight > y.zRight; });
  return out;
}

std::vector<Diagnostic> partCheckDiagnostics(const PartCheck& check, const UnitFormat& units) {
  std::vector<Diagnostic> out;
  const auto f3 = [&](double v) { return units.position(v); };
  for (const PartDefect& d : check.defects) {
    Diagnostic g;
    g.severity = Severity::Warning;
    g.code = d.kind == DefectKind::Gouge ? (d.side == FeatureSide::Outside ? codes::kPartGouge : codes::kBoreGouge)
                                         : (d.side == FeatureSide::Outside ? codes::kPartLeftover
                                                                           : codes::kBoreLeftover);
    g.range.line = d.line;
    g.range.column = d.line > 0 ? 1 : 0;
    g.range.file = d.file;
    g.args = {f3(d.depth), f3(d.zRight), f3(d.zLeft), f3(d.z), f3(d.diameter), units.unitArg()};
    out.push_back(g);
  }
  if (check.stoppedBy) {
    Diagnostic n;
    n.severity = Severity::Note;
    n.code = codes::kPartCheckStopped;
    n.range = check.stoppedBy->range;
    n.args = {check.stoppedBy->code};
    out.push_back(n);
  }
  if (check.nothingCut) {
    Diagnostic n;
    n.severity = Severity::Note;
    n.code = codes::kPartCheckNothingCut;
    out.push_back(n);
  }
  return out;
}

}  // namespace klueng::core::cut

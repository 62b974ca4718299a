#include "klueng/core/cut/part_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "klueng/core/comp/nose_comp.h"
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

bool hasArea(const Trapezoid& t) { return t.z1 > t.z0 && (t.top0 > t.bottom0 || t.top1 > t.bottom1); }

// Moves whose form is the tool's own: threading passes, drilling on the axis.
bool onAxis(const machine::Move& m) { return std::abs(m.path.start.y()) < 1e-6 && std::abs(m.path.end.y()) < 1e-6; }

bool keepsWholeTool(const machine::Move& m) { return m.kind == machine::MoveKind::Thread || onAxis(m); }

struct Finding {
  DefectKind kind;
  FeatureSide side;
  int column;
  double depth;
  double described;   // radius of the described surface
  int cause = -1;     // move index
  int pathMove = -1;  // a gouge below the programmed path: the programmed move that lies there
};

// The programmed path over one column: the lowest (outside) or highest (inside)
// radius a feed move's path has at the column's centre.
struct ProgrammedColumn {
  double radius = 0.0;
  int move = -1;         // into the programmed timeline; -1: no path over the column
  double nose = 0.0;     // that move's nose radius
  bool contour = false;  // a contour, not a tool's form (threading passes are the form)
  // A face or a retreat the path makes in the column: the contour's wall, up to
  // its top (outside) or down to its bottom (inside); NaN when none.
  double wall = std::numeric_limits<double>::quiet_NaN();
};

// The radius a path has at z, if it runs over z: the lower (outside) or upper
// (inside) of an arc's two points there.
std::optional<double> radiusAt(const Segment& s, double z, bool outside) {
  const double z0 = std::min(s.start.x(), s.end.x()), z1 = std::max(s.start.x(), s.end.x());
  if (!s.isArc()) {
    if (!(z > z0 && z < z1)) return std::nullopt;
    return s.start.y() + (z - s.start.x()) / (s.end.x() - s.start.x()) * (s.end.y() - s.start.y());
  }
  const double r = s.radius(), dz = z - s.centre.x();
  if (std::abs(dz) >= r) return std::nullopt;
  const double h = std::sqrt(r * r - dz * dz);
  std::optional<double> best;
  for (const double x : {s.centre.y() - h, s.centre.y() + h}) {
    if (distanceTo(s, Vec2(z, x)) > 1e-6) continue;
    if (!best || (outside ? x < *best : x > *best)) best = x;
  }
  return best;
}

// Below the centre line (a face past the centre, a tool working beyond it) the
// path's radius is not the part's.
bool beyondCentre(const machine::Move& m) { return m.path.start.y() < 0.0 || m.path.end.y() < 0.0; }

// The programmed path over each column of `part` (the real cut) on one side: a
// feed move's side is its tool's (by the tip), else the outside when the move's
// middle lies nearer the part's outside than its bore. Drilling on the axis is
// the drill's form, not a contour.
std::vector<ProgrammedColumn> programmedColumns(const machine::Timeline& programmed, const Stock& part,
                                                ToolLibrary& shapes, double end, bool outside) {
  std::vector<ProgrammedColumn> out(static_cast<std::size_t>(part.columnCount()));
  const double dz = part.columnWidth();
  for (std::size_t k = 0; k < programmed.moves.size(); ++k) {
    const machine::Move& m = programmed.moves[k];
    if (m.tStart >= end) break;  // `end`: where an alarm stopped the real run (its times are near the real ones)
    if (m.tool <= 0 || onAxis(m) || beyondCentre(m)) continue;
    if (m.kind != machine::MoveKind::Line && m.kind != machine::MoveKind::Arc && m.kind != machine::MoveKind::Thread)
      continue;
    const Vec2 mid = m.path.pointAt(0.5);
    const int c = part.columnAt(mid.x());
    if (c < 0 || c >= part.columnCount()) continue;
    // The side: the tip's (3, 4, 8 cut outside; 1, 2, 6 in a bore), else where the move ends up.
    const ToolShape* shape = shapes.get(m.tool, m.offset);
    const double tipX = shape ? comp::tipVector(shape->tip).y() : 0.0;
    const double outer = part.outerRadius(c);
    const bool outsideMove = tipX != 0.0 ? tipX < 0.0 : outer <= 0.0 || mid.y() >= (outer + part.innerRadius(c)) / 2.0;
    if (outsideMove != outside) continue;
    const double z0 = std::min(m.path.start.x(), m.path.end.x()), z1 = std::max(m.path.start.x(), m.path.end.x());
    if (z1 - z0 < dz) {  // a face or a retreat: a wall of the contour, over no column's width
      ProgrammedColumn& p = out[static_cast<std::size_t>(c)];
      const double extreme =
          outside ? std::max(m.path.start.y(), m.path.end.y()) : std::min(m.path.start.y(), m.path.end.y());
      if (m.kind != machine::MoveKind::Thread &&
          (std::isnan(p.wall) || (outside ? extreme > p.wall : extreme < p.wall)))
        p.wall = extreme;
      continue;
    }
    int first = 0, last = -1;
    part.columnRange(z0, z1, first, last);
    for (int i = first; i <= last; ++i) {
      const std::optional<double> r = radiusAt(m.path, part.zCentre(i), outside);
      if (!r) continue;
      ProgrammedColumn& p = out[static_cast<std::size_t>(i)];
      if (p.move >= 0 && (outside ? *r >= p.radius : *r <= p.radius)) continue;
      p = {*r, static_cast<int>(k), shape ? shape->noseRadius : 0.0, m.kind != machine::MoveKind::Thread};
    }
  }
  return out;
}

// What a round nose can reach: the described surface where the programmed
// path is a contour is that path (or the ideal cut where that is lower), less
// what no nose of the tool's radius reaches — the fillet in a concave corner.
// Computed as the opening of the air by a disk: a column's surface is the
// lowest point of any disk of radius r that fits in the air over it (outside;
// mirrored for a bore). Columns are taken whole: a disk clears a column's
// nearest edge, and reaches a column at its nearest edge.
struct Reach {
  std::vector<double> described;  // NaN: no contour over the column
  double at(std::size_t k, double ideal) const { return std::isnan(described[k]) ? ideal : described[k]; }
};

std::vector<double> opening(const std::vector<double>& surface, double dz, double r) {
  const int n = static_cast<int>(surface.size());
  if (r <= 0.0 || n == 0) return surface;
  const int reach = static_cast<int>(std::ceil(r / dz)) + 1;
  const auto rise = [&](int di) {
    const double d = std::max(0.0, std::abs(di) * dz - dz / 2.0);
    return d >= r ? -1.0 : std::sqrt(r * r - d * d);
  };
  const auto at = [](auto& v, int i) -> auto& { return v[static_cast<std::size_t>(i)]; };
  // The lowest centre of a disk over column c that clears every column it spans ...
  std::vector<double> centre(static_cast<std::size_t>(n), -std::numeric_limits<double>::infinity());
  for (int c = 0; c < n; ++c)
    for (int j = std::max(0, c - reach); j <= std::min(n - 1, c + reach); ++j)
      if (const double h = rise(j - c); h >= 0.0) at(centre, c) = std::max(at(centre, c), at(surface, j) + h);
  // ... and the lowest point of any such disk over column i.
  std::vector<double> out(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  for (int i = 0; i < n; ++i)
    for (int c = std::max(0, i - reach); c <= std::min(n - 1, i + reach); ++c)
      if (const double h = rise(i - c); h >= 0.0) at(out, i) = std::min(at(out, i), at(centre, c) - h);
  for (int i = 0; i < n; ++i) at(out, i) = std::max(at(out, i), at(surface, i));
  return out;
}

Reach noseReach(const std::vector<double>& ideal, const std::vector<ProgrammedColumn>& path, double dz, bool outside) {
  const std::size_t n = ideal.size();
  Reach out{std::vector<double>(n, std::numeric_limits<double>::quiet_NaN())};
  // Outside the air is above the surface; a bore's air is below it: mirror it.
  const double sign = outside ? 1.0 : -1.0;
  std::vector<double> surface(n);
  std::set<double> noses;
  for (std::size_t k = 0; k < n; ++k) {
    surface[k] = sign * ideal[k];
    if (path[k].move >= 0 && path[k].contour) {
      surface[k] = std::min(surface[k], sign * path[k].radius);
      noses.insert(path[k].nose);
    }
    // The contour's own walls stand where a later cut took them away (a parting
    // cut beside a shoulder's fillet): the nose met them when it cut there.
    if (!std::isnan(path[k].wall)) surface[k] = std::max(surface[k], sign * path[k].wall);
  }
  for (const double r : noses) {
    const std::vector<double> open = opening(surface, dz, r);
    for (std::size_t k = 0; k < n; ++k)
      if (path[k].move >= 0 && path[k].contour && path[k].nose == r) out.described[k] = sign * open[k];
  }
  return out;
}

// Whether a real move's path runs over z (not a plunge beside it).
bool runsOver(const machine::Move& m, double z) {
  const double z0 = std::min(m.path.start.x(), m.path.end.x()), z1 = std::max(m.path.start.x(), m.path.end.x());
  return z > z0 && z < z1;
}

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
  const Vec2 tip = comp::tipVector(real.tip);
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

machine::Timeline programmedPath(const gcode::Program& program, const machine::MachineSetup& setup,
                                 machine::RunOptions options, const machine::Timeline& run) {
  const bool compensated =
      std::any_of(run.moves.begin(), run.moves.end(), [](const machine::Move& m) { return m.compensated; });
  if (!compensated) return run;
  options.noseCompensation = false;
  options.persistentVariables = nullptr;  // one program run must not write #500-#999 twice
  return machine::interpret(program, setup, options);
}

namespace {

// A leftover against the programmed path belongs to the block whose path lies there.
bool foundFromPath(const Finding& f) { return f.kind == DefectKind::Leftover && f.pathMove >= 0; }

// The same moves with the ideal tools (no holder: nothing to collide).
struct IdealRun {
  machine::Timeline timeline;
  ToolLibrary tools;
};

IdealRun idealRunOf(const machine::Timeline& timeline, const ToolLibrary& tools) {
  IdealRun ideal{timeline, tools};
  std::set<std::pair<int, int>> made;
  for (machine::Move& m : ideal.timeline.moves) {
    if (m.tool <= 0 || keepsWholeTool(m)) continue;
    const ToolShape* shape = ideal.tools.get(m.tool, m.offset);
    if (!shape) continue;
    if (made.insert({m.tool, m.offset}).second)
      ideal.tools.set(m.tool, m.offset + kIdealOffset, idealToolShape(*shape));
    m.offset += kIdealOffset;
  }
  return ideal;
}

struct ProgrammedPaths {
  std::vector<ProgrammedColumn> outside;
  std::vector<ProgrammedColumn> inside;
};

// The programmed path (where the run got to) per column, outside and inside.
ProgrammedPaths programmedPathColumns(const machine::Timeline& programmed, const Stock& a, const ToolLibrary& tools,
                                      double pathEnd) {
  ToolLibrary shapes = tools;
  ProgrammedPaths path{programmedColumns(programmed, a, shapes, pathEnd, true),
                       programmedColumns(programmed, a, shapes, pathEnd, false)};
  // The programmed path judges a column the real cut left as one ring or bar (or
  // nothing): an island left inside (a drill's cone beside a bore's end) is no surface of it.
  for (int i = 0; i < a.columnCount(); ++i)
    if (a.column(i).size() > 1) {
      path.outside[static_cast<std::size_t>(i)] = ProgrammedColumn{};
      path.inside[static_cast<std::size_t>(i)] = ProgrammedColumn{};
    }
  return path;
}

// Each column where the real cut `a` went below the described part `b` or the
// programmed path (a gouge), or left more than the tool's nose could reach (a leftover).
std::vector<Finding> findDefectColumns(const Stock& a, const Stock& b, const ProgrammedPaths& path,
                                       const PartCheckOptions& options) {
  std::vector<Finding> findings;
  const int n = a.columnCount();
  const std::vector<ProgrammedColumn>& pathOut = path.outside;
  const std::vector<ProgrammedColumn>& pathIn = path.inside;
  std::vector<double> idealOut(static_cast<std::size_t>(n)), idealIn(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    idealOut[static_cast<std::size_t>(i)] = b.outerRadius(i);
    idealIn[static_cast<std::size_t>(i)] = b.outerRadius(i) > 0.0 ? b.innerRadius(i) : 0.0;
  }
  const Reach reachOut = noseReach(idealOut, pathOut, a.columnWidth(), true);
  const Reach reachIn = noseReach(idealIn, pathIn, a.columnWidth(), false);
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double ro = a.outerRadius(i), io = b.outerRadius(i);
    if (io - ro > options.gougeTolerance)
      findings.push_back({DefectKind::Gouge, FeatureSide::Outside, i, io - ro, io});
    else if (pathOut[k].move >= 0 && pathOut[k].radius - ro > options.gougeTolerance)
      findings.push_back(
          {DefectKind::Gouge, FeatureSide::Outside, i, pathOut[k].radius - ro, pathOut[k].radius, -1, pathOut[k].move});
    const double describedOut = reachOut.at(k, io);
    if (ro - describedOut > options.leftoverTolerance)
      findings.push_back({DefectKind::Leftover, FeatureSide::Outside, i, ro - describedOut, describedOut, -1,
                          std::isnan(reachOut.described[k]) ? -1 : pathOut[k].move});
    if (ro <= 0.0 || io <= 0.0) continue;  // no bore where nothing is left
    const double ri = a.innerRadius(i), ii = b.innerRadius(i);
    if (ri - ii > options.gougeTolerance)
      findings.push_back({DefectKind::Gouge, FeatureSide::Inside, i, ri - ii, ii});
    else if (pathIn[k].move >= 0 && ri - pathIn[k].radius > options.gougeTolerance)
      findings.push_back(
          {DefectKind::Gouge, FeatureSide::Inside, i, ri - pathIn[k].radius, pathIn[k].radius, -1, pathIn[k].move});
    const double describedIn = reachIn.at(k, ii);
    if (describedIn - ri > options.leftoverTolerance)
      findings.push_back({DefectKind::Leftover, FeatureSide::Inside, i, describedIn - ri, describedIn, -1,
                          std::isnan(reachIn.described[k]) ? -1 : pathIn[k].move});
  }
  return findings;
}

// Which block did it: replay the runs move by move. A gouge belongs to the
// real move after which the column first went below the described part; one
// below the programmed path counts only when that move's own programmed path
// runs over the column (a grooving blade's width beside its plunge is the
// tool's, not a gouge). A leftover belongs to the ideal move after which the
// described part went below what stayed.
void findDefectCauses(std::vector<Finding>& findings, CutSimulator& realReplay, CutSimulator& idealReplay,
                      const machine::Timeline& timeline, const Stock& a, double end, const PartCheckOptions& options) {
  std::size_t pending = findings.size();
  for (const Finding& f : findings) pending -= foundFromPath(f) ? 1 : 0;
  for (std::size_t k = 0; k < timeline.moves.size() && pending > 0; ++k) {
    const machine::Move& m = timeline.moves[k];
    if (m.tStart >= end) break;
    const double t = std::min(m.tEnd, end);
    realReplay.advanceTo(t);
    idealReplay.advanceTo(t);
    if (m.kind == machine::MoveKind::Dwell) continue;
    for (Finding& f : findings) {
      if (f.cause >= 0 || foundFromPath(f)) continue;
      const bool outside = f.side == FeatureSide::Outside;
      const Stock& s = f.kind == DefectKind::Gouge ? realReplay.stock() : idealReplay.stock();
      const double now = outside ? s.outerRadius(f.column) : s.innerRadius(f.column);
      double mark = 0.0;
      if (f.kind == DefectKind::Gouge) {
        mark = f.described;
      } else {
        mark = outside ? a.outerRadius(f.column) : a.innerRadius(f.column);
      }
      const double tol = f.kind == DefectKind::Gouge ? options.gougeTolerance : options.leftoverTolerance;
      if (outside ? now < mark - tol : now > mark + tol) {
        f.cause = static_cast<int>(k);
        --pending;
      }
    }
  }
}

// A gouge below the programmed path that its own move did not make over the
// column is the tool's form (a blade's width, a parting cut): not a defect.
void dropToolFormGouges(std::vector<Finding>& findings, const machine::Timeline& timeline, const Stock& a) {
  std::erase_if(findings, [&](const Finding& f) {
    if (f.pathMove < 0 || f.kind != DefectKind::Gouge) return false;
    if (f.cause < 0) return true;
    const machine::Move& cause = timeline.moves[static_cast<std::size_t>(f.cause)];
    return !runsOver(cause, a.zCentre(f.column));
  });
}

// Runs of neighbouring columns with the same kind, side and cause are one defect;
// the defects from the right end of the part to the left.
std::vector<PartDefect> defectsFromFindings(std::vector<Finding>& findings, const Stock& a,
                                            const machine::Timeline& timeline, const machine::Timeline& programmed) {
  std::vector<PartDefect> defects;
  std::sort(findings.begin(), findings.end(), [](const Finding& x, const Finding& y) {
    if (x.kind != y.kind) return x.kind < y.kind;
    if (x.side != y.side) return x.side < y.side;
    return x.column < y.column;
  });
  for (std::size_t k = 0; k < findings.size();) {
    std::size_t e = k;
    while (e + 1 < findings.size() && findings[e + 1].kind == findings[k].kind &&
           findings[e + 1].side == findings[k].side && findings[e + 1].column == findings[e].column + 1 &&
           findings[e + 1].cause == findings[k].cause && foundFromPath(findings[e + 1]) == foundFromPath(findings[k]) &&
           (!foundFromPath(findings[k]) || findings[e + 1].pathMove == findings[k].pathMove))
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
    if (foundFromPath(findings[k])) {
      d.line = programmed.moves[static_cast<std::size_t>(findings[k].pathMove)].line;
      d.file = programmed.moves[static_cast<std::size_t>(findings[k].pathMove)].file;
    } else if (findings[k].cause >= 0) {
      d.line = timeline.moves[static_cast<std::size_t>(findings[k].cause)].line;
      d.file = timeline.moves[static_cast<std::size_t>(findings[k].cause)].file;
    }
    defects.push_back(d);
    k = e + 1;
  }
  std::sort(defects.begin(), defects.end(),
            [](const PartDefect& x, const PartDefect& y) { return x.zRight > y.zRight; });
  return defects;
}

}  // namespace

PartCheck checkPart(const machine::Timeline& run, const machine::Timeline& programmed, const CutSetup& setup,
                    const PartCheckOptions& options) {
  return checkPart(run, programmed, setup, ToolLibrary(setup.tools, setup.offsets), options);
}

PartCheck checkPart(const machine::Timeline& timeline, const machine::Timeline& programmed, const CutSetup& setup,
                    const ToolLibrary& tools, const PartCheckOptions& options) {
  PartCheck out;
  CutOptions cutOptions;
  cutOptions.resolution = options.resolution;
  cutOptions.checkpointBudgetBytes = 0;  // forward only

  CutSimulator real(timeline, setup, tools, cutOptions);
  real.runToEnd();
  out.stoppedBy = real.stoppingAlarm();
  const double end = real.endTime();

  IdealRun idealRun = idealRunOf(timeline, tools);
  CutOptions idealOptions = cutOptions;
  idealOptions.detectCollisions = false;
  CutSimulator ideal(idealRun.timeline, setup, idealRun.tools, idealOptions);
  ideal.advanceTo(end);

  out.cut = real.stock();
  const Stock& a = real.stock();
  const Stock& b = ideal.stock();
  out.nothingCut = b.removedVolume() <= 0.0 && a.removedVolume() <= 0.0;

  const double pathEnd = out.stoppedBy ? end : std::numeric_limits<double>::infinity();
  std::vector<Finding> findings =
      findDefectColumns(a, b, programmedPathColumns(programmed, a, tools, pathEnd), options);
  if (findings.empty()) return out;

  CutSimulator realReplay(timeline, setup, tools, cutOptions);
  CutSimulator idealReplay(idealRun.timeline, setup, idealRun.tools, idealOptions);
  findDefectCauses(findings, realReplay, idealReplay, timeline, a, end, options);
  dropToolFormGouges(findings, timeline, a);
  if (findings.empty()) return out;

  out.defects = defectsFromFindings(findings, a, timeline, programmed);
  return out;
}

std::vector<Diagnostic> partCheckDiagnostics(const PartCheck& check, const UnitFormat& units) {
  std::vector<Diagnostic> out;
  const auto f3 = [&](double v) { return units.position(v); };
  for (const PartDefect& d : check.defects) {
    Diagnostic g;
    g.severity = Severity::Warning;
    g.code = d.kind == DefectKind::Gouge
                 ? (d.side == FeatureSide::Outside ? codes::kPartGouge : codes::kBoreGouge)
                 : (d.side == FeatureSide::Outside ? codes::kPartLeftover : codes::kBoreLeftover);
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

#include "klueng/core/cut/cut_simulator.h"

#include <algorithm>
#include <limits>
#include <cmath>
#include <functional>
#include <span>
#include <numbers>

#include <fmt/format.h>

#include "sweep.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::cut {

using machine::Move;
using machine::MoveKind;

namespace {

constexpr double kNoseChordTolerance = 0.0002;  // mm: nose sweeps along arcs are this close to exact
constexpr double kBoxChordTolerance = 0.0002;   // mm: bitmap edges next to the nose touch the surface too

using Pieces = std::vector<std::pair<Vec2, Vec2>>;

// Controlled-point pieces of the sub-path [s0, s1] of a move: straight pieces
// (arcs as chords within `tolerance`), or for G32 the stamp positions (a == b).
// Into `out` (cleared first): a run reuses one buffer, not two fresh ones a move.
void piecesOf(const Move& m, double s0, double s1, double tolerance, double resolution, Pieces& out) {
  out.clear();
  const Segment& p = m.path;
  // A lead finer than two stock columns cannot show teeth: sweep it as a groove
  // (and keep a fine-lead G32 from stamping the tool millions of times).
  if (m.kind == MoveKind::Thread && m.lead >= 2.0 * resolution) {
    const double dz = std::abs(p.end.x() - p.start.x());
    const double span = dz > 1e-9 ? dz : p.length();
    if (m.lead <= 0.0 || span <= 1e-12) {
      if (s0 == 0.0) out.emplace_back(p.start, p.start);
      if (s1 >= 1.0 && span > 1e-12) out.emplace_back(p.end, p.end);
      return;
    }
    const double step = m.lead / span;  // path parameter per revolution
    const long kFirst = s0 == 0.0 ? 0 : static_cast<long>(std::floor(s0 / step)) + 1;
    for (long k = kFirst;; ++k) {
      const double s = k * step;
      if (s > s1 || s > 1.0) break;
      if (s > s0 || k == 0) out.emplace_back(p.pointAt(s), p.pointAt(s));
    }
    if (s1 >= 1.0) out.emplace_back(p.end, p.end);  // the tool stands here before it retracts
    return;
  }
  if (!p.isArc()) {
    out.emplace_back(p.pointAt(s0), p.pointAt(s1));
    return;
  }
  const double rho = p.radius();
  const double sweep = p.sweep() * (s1 - s0);
  double maxStep = std::numbers::pi / 8;
  if (rho > tolerance) maxStep = std::min(maxStep, 2.0 * std::acos(1.0 - tolerance / rho));
  // At most 100k chords: even a 1 m radius half circle is within 0.0002 mm.
  const int n = static_cast<int>(std::clamp(std::ceil(sweep / maxStep), 1.0, 100000.0));
  // Rotate the radius vector step by step: one sincos per arc, not per chord.
  const double step = (p.ccw ? 1.0 : -1.0) * sweep / n;
  const double c = std::cos(step), sn = std::sin(step);
  const Vec2 first = p.pointAt(s0), last = p.pointAt(s1);
  Vec2 v = first - p.centre;
  Vec2 prev = first;
  out.reserve(static_cast<std::size_t>(n));
  for (int k = 1; k <= n; ++k) {
    v = Vec2(c * v.x() - sn * v.y(), sn * v.x() + c * v.y());
    const Vec2 next = k == n ? last : Vec2(p.centre + v);
    out.emplace_back(prev, next);
    prev = next;
  }
}

Pieces piecesOf(const Move& m, double s0, double s1, double tolerance, double resolution) {
  Pieces out;
  piecesOf(m, s0, s1, tolerance, resolution, out);
  return out;
}

// Bounding box of the controlled point's sub-path [s0, s1] (arcs: exact, from
// the axis-extreme points inside the sweep), grown by the local box `local`.
Box pathBounds(const Move& m, double s0, double s1, const Box& local) {
  const Segment& p = m.path;
  const Vec2 a = p.pointAt(s0), b = p.pointAt(s1);
  Box box{std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()), std::max(a.y(), b.y())};
  if (p.isArc() && m.kind != MoveKind::Thread) {
    const double rho = p.radius();
    const Vec2 from = a - p.centre;
    const double start = std::atan2(from.y(), from.x());
    const double sweep = p.sweep() * (s1 - s0);
    const double dir = p.ccw ? 1.0 : -1.0;
    for (int q = 0; q < 4; ++q) {
      const double angle = q * std::numbers::pi / 2;
      // Angle travelled from the start to this extreme point, in [0, 2pi).
      double travelled = dir * (angle - start);
      travelled = std::fmod(travelled, 2 * std::numbers::pi);
      if (travelled < 0) travelled += 2 * std::numbers::pi;
      if (travelled > sweep) continue;
      const Vec2 e = p.centre + rho * Vec2(std::cos(angle), std::sin(angle));
      box.z0 = std::min(box.z0, e.x());
      box.z1 = std::max(box.z1, e.x());
      box.x0 = std::min(box.x0, e.y());
      box.x1 = std::max(box.x1, e.y());
    }
  }
  return Box{box.z0 + local.z0, box.z1 + local.z1, box.x0 + local.x0, box.x1 + local.x1};
}

// A feed that ends (or starts) this close to the centre line, in radius, may have cut a part off.
constexpr double kCutOffReachMm = 1.0;

Diagnostic makeAlarm(const char* code, const Move& m, const Vec2& where) {
  Diagnostic d;
  d.severity = Severity::Alarm;
  d.code = code;
  d.range = SourceRange{m.line, 1, 0};
  d.args = {fmt::format("{:.3f}", where.x() + 0.0), fmt::format("{:.3f}", 2.0 * where.y() + 0.0)};
  return d;
}

enum class Hit { None, Rapid, SpindleStopped, Holder, Chuck };

}  // namespace

CutSetup CutSetup::from(const io::JobHeader& header, const machine::MachineSetup& setup) {
  CutSetup s;
  s.stockDiameter = header.diameterMm();
  s.stockLength = header.lengthMm();
  s.stockBore = header.boreMm();
  s.machine = setup.machine;
  s.tools = setup.tools;
  s.offsets = setup.offsets;
  return s;
}

ToolLibrary::ToolLibrary(io::ToolTable tools, io::OffsetTable offsets)
    : tools_(std::move(tools)), offsets_(std::move(offsets)) {}

const ToolShape* ToolLibrary::get(int tool, int offset) {
  if (tool < 1 || tool > io::kToolCount) return nullptr;
  const auto key = std::make_pair(tool, offset);
  auto it = cache_.find(key);
  if (it == cache_.end()) {
    std::optional<ToolShape> shape;
    const std::string path = tools_.bitmapPath(tool);
    if (!path.empty()) {
      // Offset 00 (T0100) cancels the offset's shift, not the insert: the same
      // tool is drawn with its station's own row, as after T0101.
      const int row = offset >= 1 ? offset : tool;
      const io::Offset o = row >= 1 && row <= io::kOffsetCount ? offsets_.at(row) : io::Offset{};
      io::ReadResult<ToolShape> r = loadToolShape(path, o.r, o.tip, tools_.pixelsPerMmOf(tool));
      // One report per bitmap file, not one per offset it is used with.
      bool known = false;
      for (const auto& [k, v] : cache_) known = known || (k.first == tool);
      if (!known) diagnostics_.insert(diagnostics_.end(), r.diagnostics.begin(), r.diagnostics.end());
      if (r.ok()) shape = std::move(r.value);
    }
    it = cache_.emplace(key, std::move(shape)).first;
  }
  return it->second ? &*it->second : nullptr;
}

void ToolLibrary::set(int tool, int offset, ToolShape shape) { cache_[{tool, offset}] = std::move(shape); }

CutSimulator::CutSimulator(const machine::Timeline& timeline, const CutSetup& setup, const CutOptions& options)
    : CutSimulator(timeline, setup, ToolLibrary(setup.tools, setup.offsets), options) {}

CutSimulator::CutSimulator(const machine::Timeline& timeline, const CutSetup& setup, ToolLibrary tools,
                           const CutOptions& options)
    : timeline_(&timeline), setup_(setup), options_(options), tools_(std::move(tools)) {
  reset();
  // Spread the checkpoints over the whole run within the memory budget: about
  // 64 bytes a stock column (its interval, the vector holding it, its radius).
  const std::size_t stockBytes = 64u * static_cast<std::size_t>(std::max(1, stock_.columnCount())) + 256u;
  const std::size_t most = std::clamp<std::size_t>(options_.checkpointBudgetBytes / stockBytes, 1, 4096);
  checkpointEvery_ = options_.checkpointBudgetBytes == 0
                         ? std::numeric_limits<std::size_t>::max()  // no way back wanted (a batch run)
                         : std::max<std::size_t>(64, timeline_->moves.size() / most + 1);
}

void CutSimulator::reset() {
  warnings_.clear();
  warnedGuess_.fill(false);
  stock_ = Stock(setup_.stockDiameter, setup_.stockLength, options_.resolution, setup_.stockBore);
  chuck_ = Chuck{};
  chuck_.stockLength = setup_.stockLength;
  chuck_.stockRadius = setup_.stockDiameter / 2.0;
  chuck_.grip = std::clamp(setup_.machine.chuckGrip, 0.0, setup_.stockLength);
  chuck_.jawHeight = std::max(0.0, setup_.machine.chuckJawHeight);
  chuck_.spindleBoreRadius = std::max(0.0, setup_.machine.spindleBore / 2.0);
  time_ = 0.0;
  nextMove_ = 0;
  nextMoveDone_ = 0.0;
  alarm_.reset();
  alarmTime_ = 0.0;
  alarmPosition_ = Vec2::Zero();
}

double CutSimulator::endTime() const { return alarm_ ? alarmTime_ : timeline_->cycleTime(); }

bool CutSimulator::finished() const { return alarm_.has_value() || nextMove_ >= timeline_->moves.size(); }

std::optional<Diagnostic> CutSimulator::stoppingAlarm() const {
  if (alarm_) return alarm_;
  return timeline_->alarm;
}

void CutSimulator::runToEnd() { advanceTo(timeline_->cycleTime()); }

const CutCheckpoint* CutSimulator::checkpointBefore(double t) const {
  auto it = std::upper_bound(checkpoints_.begin(), checkpoints_.end(), t,
                             [](double v, const CutCheckpoint& c) { return v < c.time; });
  return it == checkpoints_.begin() ? nullptr : &*std::prev(it);
}

std::size_t CutSimulator::movesToCut(double t) const {
  std::size_t from = nextMove_;
  if (t < time_) {
    const CutCheckpoint* c = checkpointBefore(t);
    from = c ? c->nextMove : 0;
  }
  const int target = timeline_->moveAt(t);
  std::size_t to = target < 0 ? 0 : static_cast<std::size_t>(target) + 1;
  // A move that starts exactly at t is not cut yet.
  if (target >= 0 && t <= timeline_->moves[static_cast<std::size_t>(target)].tStart) --to;
  return to > from ? to - from : 0;
}

void CutSimulator::keepCheckpoint() {
  if (nextMove_ == 0 || nextMove_ % checkpointEvery_ != 0) return;
  if (!checkpoints_.empty() && checkpoints_.back().nextMove >= nextMove_) return;  // kept on an earlier pass
  checkpoints_.push_back({nextMove_, timeline_->moves[nextMove_ - 1].tEnd, stock_});
}

void CutSimulator::advanceTo(double t) {
  if (t < time_) {
    // Back: the nearest stock kept at or before t (every checkpoint lies before any alarm).
    const CutCheckpoint* c = checkpointBefore(t);
    if (!c) {
      reset();
    } else {
      stock_ = c->stock;
      nextMove_ = c->nextMove;
      nextMoveDone_ = 0.0;
      time_ = c->time;
      alarm_.reset();
    }
  }
  const auto& moves = timeline_->moves;
  while (!alarm_ && nextMove_ < moves.size()) {
    const Move& m = moves[nextMove_];
    if (t < m.tStart) break;
    const double s = t >= m.tEnd ? 1.0 : m.fractionAt(t);
    if (s > nextMoveDone_ || s >= 1.0) {
      cutMove(nextMove_, s);
    }
    if (alarm_) break;
    if (s >= 1.0) {
      ++nextMove_;
      nextMoveDone_ = 0.0;
      keepCheckpoint();
    } else {
      nextMoveDone_ = s;
      break;
    }
  }
  time_ = alarm_ ? std::min(t, alarmTime_) : t;
}

Vec2 CutSimulator::toolPosition() const {
  if (alarm_ && time_ >= alarmTime_) return alarmPosition_;
  return timeline_->positionAt(time_);
}

int CutSimulator::currentMove() const { return timeline_->moveAt(time_); }

const ToolShape* CutSimulator::currentTool() const {
  const int i = currentMove();
  if (i < 0) return nullptr;
  const Move& m = timeline_->moves[static_cast<std::size_t>(i)];
  return tools_.get(m.tool, m.offset);
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Bounds of the holder boxes or of the cutting trapezoids in the tool's own
// coordinates (z0 > z1 when there are none).
Box partBounds(const ToolShape& t, bool holder) {
  double z0 = kInf, z1 = -kInf, x0 = kInf, x1 = -kInf;
  auto grow = [&](const Box& b) {
    z0 = std::min(z0, b.z0);
    z1 = std::max(z1, b.z1);
    x0 = std::min(x0, b.x0);
    x1 = std::max(x1, b.x1);
  };
  if (holder) {
    for (const Box& box : t.holder) grow(box);
  } else {
    for (const Trapezoid& edge : t.cutting) grow(edge.bounds());
  }
  return Box{z0, z1, x0, x1};
}

CutSimulator::ToolBounds boundsOf(const ToolShape& t, int tool, int offset) {
  CutSimulator::ToolBounds b{tool, offset, partBounds(t, false), partBounds(t, true), {}, false};
  b.edges.reserve(t.cutting.size());
  for (const Trapezoid& edge : t.cutting) b.edges.push_back(edge.bounds());
  const double r = t.noseRadius;
  const Box nose{t.noseCentre.x() - r, t.noseCentre.x() + r, t.noseCentre.y() - r, t.noseCentre.y() + r};
  auto inside = [&](const Box& p) {  // (an empty part, z0 = inf, is inside anything)
    return t.bounds.z0 <= p.z0 && p.z1 <= t.bounds.z1 && t.bounds.x0 <= p.x0 && p.x1 <= t.bounds.x1;
  };
  b.boundsHoldAll = inside(b.edge) && inside(b.holder) && (r <= 0.0 || inside(nose));
  return b;
}

// What one move's sweep does to the stock and chuck.
struct SweepContext {
  Stock* stock;
  const Chuck* chuck;
  const ToolShape* tool = nullptr;
  double tolerance;
  detail::Grid grid;
  Box edgeBounds, holderBounds;    // partBounds of the tool
  std::span<const Box> edgeBoxes;  // the bounds of each of its cutting trapezoids
  // No material under the whole tool's sweep of this move lies above this radius (the
  // move's first look at the stock): a primitive starting at or above it needs no look.
  double materialCeiling = std::numeric_limits<double>::infinity();

  void use(const ToolShape* t, const Box& edge, const Box& holder, std::span<const Box> edges) {
    tool = t;
    edgeBounds = edge;
    holderBounds = holder;
    edgeBoxes = edges;
  }
};

// True if any swept primitive overlaps the box (z0..z1, x0..x1) by more than tolerance.
template <typename Primitive>
bool hitsBox(const SweepContext& c, const Box& target, Primitive&& sweepOn) {
  if (target.z1 <= target.z0 || target.x1 <= target.x0) return false;
  const double dz = c.grid.dz;
  detail::Grid g{target.z0, dz, std::max(1, static_cast<int>(std::ceil((target.z1 - target.z0) / dz)))};
  g.dz = (target.z1 - target.z0) / g.count;
  bool hit = false;
  sweepOn(g, [&](int, double lo, double hi) {
    if (std::min(hi, target.x1) - std::max(lo, target.x0) > c.tolerance) hit = true;
  });
  return hit;
}

bool boxesOverlap(const Box& a, const Box& b) { return a.z0 < b.z1 && b.z0 < a.z1 && a.x0 < b.x1 && b.x0 < a.x1; }

Box sweptBounds(const std::vector<std::pair<Vec2, Vec2>>& pieces, const Box& local) {
  Box b{1e300, -1e300, 1e300, -1e300};
  for (const auto& [a, e] : pieces) {
    b.z0 = std::min({b.z0, a.x() + local.z0, e.x() + local.z0});
    b.z1 = std::max({b.z1, a.x() + local.z1, e.x() + local.z1});
    b.x0 = std::min({b.x0, a.y() + local.x0, e.y() + local.x0});
    b.x1 = std::max({b.x1, a.y() + local.x1, e.y() + local.x1});
  }
  return b;
}

// Runs f(i, lo, hi) over every column interval of the cutting edge (or of the
// holder) swept along the pieces, skipping primitives that stay above all material
// and, with MaterialCull, columns whose material the primitive stays above.
template <typename F, typename Cull>
void sweepIntervals(const SweepContext& c, const std::vector<std::pair<Vec2, Vec2>>& nosePieces,
                    const std::vector<std::pair<Vec2, Vec2>>& boxPieces, bool holder, F&& f, const Cull& cull) {
  const ToolShape& t = *c.tool;
  const bool nose = !holder && t.noseRadius > 0.0;
  auto sweptBox = [](const Vec2& a, const Vec2& b, const Box& box) {
    return Box{std::min(a.x(), b.x()) + box.z0, std::max(a.x(), b.x()) + box.z1, std::min(a.y(), b.y()) + box.x0,
               std::max(a.y(), b.y()) + box.x1};
  };
  // Whether any material under the swept box reaches above its bottom (x0 < the largest outer
  // radius there): the answer of the maximum, found at the first column or block above.
  auto materialAbove = [&](const Box& swept) {
    int first, last;
    c.stock->columnRange(swept.z0, swept.z1, first, last);
    return first <= last && c.stock->maxOuterAbove(first, last, swept.x0);
  };
  const Box part = holder ? c.holderBounds : c.edgeBounds;
  // Two looks, the second only when the first cannot tell: the move's ceiling (free), then
  // the material under this primitive's sweep.
  auto above = [&](const Box& swept) { return swept.x0 >= c.materialCeiling || !materialAbove(swept); };
  // (Inside a Stock::Batch, a removing f leaves maxima to settle: settled after each
  // primitive, so the next one is culled by exact maxima, as without the batch.)
  if (nose) {
    const double r = t.noseRadius;
    for (const auto& [a, b] : nosePieces) {
      const Vec2 ca = a + t.noseCentre, cb = b + t.noseCentre;
      if (above(sweptBox(ca, cb, Box{-r, r, -r, r}))) continue;
      detail::sweepDiscLine(c.grid, ca, cb, r, f, cull);
      c.stock->settle();
    }
  }
  // A piece along which even the part's lowest point stays at or above the ceiling passes
  // every box of the part (box.x0 >= part.x0): the boxes need no look of their own.
  auto partAbove = [&](const Vec2& a, const Vec2& b) { return std::min(a.y(), b.y()) + part.x0 >= c.materialCeiling; };
  if (holder) {
    for (const Box& box : t.holder)
      for (const auto& [a, b] : boxPieces)
        if (!partAbove(a, b) && !above(sweptBox(a, b, box))) {
          detail::sweepBoxLine(c.grid, a, b, box, f, cull);
          c.stock->settle();
        }
    return;
  }
  for (std::size_t k = 0; k < t.cutting.size(); ++k) {
    const Box& box = c.edgeBoxes[k];
    for (const auto& [a, b] : boxPieces)
      if (!partAbove(a, b) && !above(sweptBox(a, b, box))) {
        detail::sweepTrapezoidLine(c.grid, a, b, t.cutting[k], f, cull);
        c.stock->settle();
      }
  }
}

// f must do nothing where lo is at or above the column's outer radius (Stock::remove,
// Stock::overlap > a tolerance >= 0), unless allColumns: then every column comes.
template <typename F>
void forEachInterval(const SweepContext& c, const std::vector<std::pair<Vec2, Vec2>>& nosePieces,
                     const std::vector<std::pair<Vec2, Vec2>>& boxPieces, bool holder, F&& f, bool allColumns = false) {
  if (allColumns)
    sweepIntervals(c, nosePieces, boxPieces, holder, f, detail::NoCull{});
  else
    sweepIntervals(c, nosePieces, boxPieces, holder, f, detail::MaterialCull{c.stock});
}

// Columns whose centres lie outside (zMin, zMax) are not counted: a rapid
// retract may shave the sliver a tool's flank leaves beside a shoulder.
bool overlapsStock(const SweepContext& c, const std::vector<std::pair<Vec2, Vec2>>& nosePieces,
                   const std::vector<std::pair<Vec2, Vec2>>& boxPieces, bool holder,
                   double zMin = -std::numeric_limits<double>::infinity(),
                   double zMax = std::numeric_limits<double>::infinity()) {
  bool hit = false;
  // (A tolerance below 0 would call an overlap of nothing a hit: every column then.)
  forEachInterval(
      c, nosePieces, boxPieces, holder,
      [&](int i, double lo, double hi) {
        if (hit) return;
        const double z = c.stock->zCentre(i);
        if (z > zMin && z < zMax && c.stock->overlap(i, lo, hi) > c.tolerance) hit = true;
      },
      !(c.tolerance >= 0.0));
  return hit;
}

// How far the holder swept along the pieces reaches into the stock (mm, radial): what a
// guessed tool's edge would need to reach further.
double holderDepth(const SweepContext& c, const std::vector<std::pair<Vec2, Vec2>>& nosePieces,
                   const std::vector<std::pair<Vec2, Vec2>>& boxPieces, double zMin, double zMax) {
  double deepest = 0.0;
  forEachInterval(c, nosePieces, boxPieces, true, [&](int i, double lo, double hi) {
    const double z = c.stock->zCentre(i);
    if (z > zMin && z < zMax) deepest = std::max(deepest, c.stock->overlap(i, lo, hi));
  });
  return deepest;
}

bool hitsChuck(const SweepContext& c, const std::vector<std::pair<Vec2, Vec2>>& nosePieces,
               const std::vector<std::pair<Vec2, Vec2>>& boxPieces) {
  const Chuck& k = *c.chuck;
  const Box targets[] = {{k.jawZMin(), k.jawZMax(), k.jawXMin(), k.jawXMax()},
                         {k.bodyZMin(), k.bodyZMax(), k.bodyXMin(), k.bodyXMax()}};
  const ToolShape& t = *c.tool;
  for (const Box& target : targets) {
    if (!boxesOverlap(sweptBounds(boxPieces, t.bounds), target)) continue;
    // (Pieces by reference, not structured bindings: clang 14, the fuzz preset's
    // compiler, cannot capture those in a lambda.)
    for (const Box& box : t.holder)
      for (const auto& piece : boxPieces)
        if (hitsBox(c, target, [&](const detail::Grid& g, auto&& f) {
              detail::sweepBoxLine(g, piece.first, piece.second, box, f);
            }))
          return true;
    for (const Trapezoid& edge : t.cutting)
      for (const auto& piece : boxPieces)
        if (hitsBox(c, target, [&](const detail::Grid& g, auto&& f) {
              detail::sweepTrapezoidLine(g, piece.first, piece.second, edge, f);
            }))
          return true;
    if (t.noseRadius > 0.0)
      for (const auto& piece : nosePieces)
        if (hitsBox(c, target, [&](const detail::Grid& g, auto&& f) {
              detail::sweepDiscLine(g, piece.first + t.noseCentre, piece.second + t.noseCentre, t.noseRadius, f);
            }))
          return true;
  }
  return false;
}

}  // namespace

// How deep a guessed tool's edge may brush the stock in a rapid before it is the program's fault.
constexpr double kGuessGrazeMm = 0.2;

bool CutSimulator::excuseGuess(const char* warning, const Move& m, const Vec2& where,
                               const std::function<double()>& depth) {
  if (!setup_.tools.isGuess(m.tool)) return false;
  bool& warned = warnedGuess_[static_cast<std::size_t>(m.tool - 1)];
  if (!warned) {
    Diagnostic d = makeAlarm(warning, m, where);
    d.severity = Severity::Warning;
    const std::string id = setup_.tools.libraryId(m.tool);
    const std::string& line = setup_.tools.bitmap[static_cast<std::size_t>(m.tool - 1)];
    d.args.insert(d.args.begin(),
                  {fmt::format("{:02}", m.tool), id.empty() ? line.substr(line.find_last_of('/') + 1) : id});
    if (depth) d.args.push_back(fmt::format("{:.3f}", depth()));
    warnings_.push_back(std::move(d));
    warned = true;
  }
  return true;
}

void CutSimulator::cutMove(std::size_t index, double sEnd) {
  Move mirrored;
  const bool beyond = setup_.machine.toolsBeyondCentre;
  if (beyond) mirrored = mirroredAcrossCentre(timeline_->moves[index]);
  const Move& m = beyond ? mirrored : timeline_->moves[index];
  if (m.kind == MoveKind::Dwell) return;
  // A bar puller or bar stop cuts nothing and touches nothing: it grips or stops the bar with the
  // spindle stopped. (Where it drags the bar is the machine's own M codes: not modelled, so the
  // part it leaves stays in view.)
  if (setup_.tools.isBarHolder(m.tool)) return;
  const Segment& path = m.path;
  if (!path.start.allFinite() || !path.end.allFinite() || (path.isArc() && !path.centre.allFinite())) return;
  const ToolShape* tool = tools_.get(m.tool, m.offset);
  if (!tool) {
    // A tool whose bitmap is refused stops the run where it is first used.
    if (m.tool >= 1 && hasErrors(tools_.diagnostics())) {
      for (const Diagnostic& d : tools_.diagnostics())
        if (d.severity == Severity::Error && !alarm_) alarm_ = d;
      if (alarm_) {
        alarm_->range = SourceRange{m.line, 1, 0};
        alarmPosition_ = m.path.start;
        alarmTime_ = m.tStart;
      }
    }
    return;
  }
  const double s0 = nextMoveDone_;
  SweepContext ctx{&stock_,
                   &chuck_,
                   nullptr,
                   options_.collisionTolerance,
                   detail::Grid{-stock_.length(), stock_.resolution(), stock_.columnCount()},
                   Box{},
                   Box{},
                   {}};

  const double dz = stock_.resolution();
  auto nose = [&](double a, double b) { return piecesOf(m, a, b, kNoseChordTolerance, dz); };
  auto boxes = [&](double a, double b) { return piecesOf(m, a, b, kBoxChordTolerance, dz); };

  // Smallest s in (s0, sEnd] at which test(s0, s) holds (test(s0, sEnd) is known to hold).
  auto earliest = [&](auto&& test) {
    double lo = s0, hi = sEnd;
    for (int k = 0; k < 40 && hi - lo > 1e-9; ++k) {
      const double mid = (lo + hi) / 2;
      if (test(mid))
        hi = mid;
      else
        lo = mid;
    }
    return hi;
  };
  auto raise = [&](const char* code, double s) {
    const Vec2 at = timeline_->moves[index].path.pointAt(s);  // as programmed (beyond the centre too)
    alarm_ = makeAlarm(code, m, at);
    alarmPosition_ = at;
    alarmTime_ = m.timeAt(s);
  };

  // Quick rejection: the whole tool stays above every bit of material it passes
  // and away from the chuck (most moves of a long program are in air).
  const Box swept = pathBounds(m, s0, sEnd, tool->bounds);
  int first, last;
  stock_.columnRange(swept.z0, swept.z1, first, last);
  const double ceiling = first <= last ? stock_.maxOuterRadius(first, last) : -kInf;
  const bool nearStock = swept.x0 < ceiling;
  const Box jaws{chuck_.jawZMin(), chuck_.jawZMax(), chuck_.jawXMin(), chuck_.jawXMax()};
  const Box body{chuck_.bodyZMin(), chuck_.bodyZMax(), chuck_.bodyXMin(), chuck_.bodyXMax()};
  const bool nearChuck = options_.detectCollisions && (boxesOverlap(swept, jaws) || boxesOverlap(swept, body));
  if (!nearStock && !nearChuck) return;
  if (toolBounds_.tool != m.tool || toolBounds_.offset != m.offset) toolBounds_ = boundsOf(*tool, m.tool, m.offset);
  ctx.use(tool, toolBounds_.edge, toolBounds_.holder, toolBounds_.edges);
  if (toolBounds_.boundsHoldAll) ctx.materialCeiling = ceiling;  // (a shape made by hand may not)

  piecesOf(m, s0, sEnd, kNoseChordTolerance, dz, nosePieces_);
  piecesOf(m, s0, sEnd, kBoxChordTolerance, dz, boxPieces_);
  const Pieces& nosePieces = nosePieces_;
  const Pieces& boxPieces = boxPieces_;

  // A guessed tool's holder may touch the chuck (a warning); its edge may not.
  std::optional<ToolShape> edgeOnly;
  SweepContext edgeCtx = ctx;
  if (nearChuck && setup_.tools.isGuess(m.tool)) {
    edgeOnly = *tool;
    edgeOnly->holder.clear();
    edgeCtx.use(&*edgeOnly, ctx.edgeBounds, partBounds(*edgeOnly, true), ctx.edgeBoxes);
    if (hitsChuck(ctx, nosePieces, boxPieces) && !hitsChuck(edgeCtx, nosePieces, boxPieces)) {
      const double s = earliest([&](double e) { return hitsChuck(ctx, nose(s0, e), boxes(s0, e)); });
      excuseGuess(codes::kGuessHitsChuck, m, timeline_->moves[index].path.pointAt(s));
      ctx.use(edgeCtx.tool, edgeCtx.edgeBounds, edgeCtx.holderBounds,
              edgeCtx.edgeBoxes);  // the rest of the move as its edge alone: no second word on the chuck
    }
  }
  if (nearChuck && hitsChuck(ctx, nosePieces, boxPieces)) {
    const double s = earliest([&](double e) { return hitsChuck(ctx, nose(s0, e), boxes(s0, e)); });
    // Cut what the tool removed on its way in, then stop at the crash.
    const auto inNose = nose(s0, s);
    const auto inBoxes = boxes(s0, s);
    if (nearStock && m.kind != MoveKind::Rapid && m.spindle != machine::SpindleDir::Stopped) {
      const Stock::Batch batch(stock_);
      forEachInterval(ctx, inNose, inBoxes, false, [&](int i, double lo, double hi) { stock_.remove(i, lo, hi); });
    }
    raise(codes::kToolHitsChuck, s);
    return;
  }
  if (!nearStock) return;

  const bool cutting = m.kind != MoveKind::Rapid && m.spindle != machine::SpindleDir::Stopped;
  if (!cutting) {
    if (!options_.detectCollisions) return;
    // Rapids and a stopped spindle must not touch the material, except for
    // grazing: a sliver within rapidFlankAllowance of the tool's left or right
    // side, as when G00 X retracts straight up beside a shoulder just turned.
    const double zMin = swept.z0 + options_.rapidFlankAllowance;
    const double zMax = swept.z1 - options_.rapidFlankAllowance;
    auto touches = [&](const auto& n, const auto& b, bool holder) {
      return overlapsStock(ctx, n, b, holder, zMin, zMax);
    };
    if (touches(nosePieces, boxPieces, false) || touches(nosePieces, boxPieces, true)) {
      const double s = earliest([&](double e) {
        const auto n = nose(s0, e);
        const auto b = boxes(s0, e);
        return touches(n, b, false) || touches(n, b, true);
      });
      const auto n = nose(s0, s);
      const auto b = boxes(s0, s);
      const bool edge = touches(n, b, false);
      if (!edge && excuseGuess(codes::kGuessHitsStock, m, timeline_->moves[index].path.pointAt(s),
                               [&] { return holderDepth(ctx, nosePieces, boxPieces, zMin, zMax); }))
        return;
      // A guessed tool's edge brushing the stock by a sliver (its flank beside a shoulder, the
      // shape of the shop's real insert unknown): a warning; a rapid that goes in deeper is the program's.
      if (edge && m.kind == MoveKind::Rapid && setup_.tools.isGuess(m.tool)) {
        SweepContext loose = ctx;
        loose.tolerance = std::max(ctx.tolerance, kGuessGrazeMm);
        if (!overlapsStock(loose, nosePieces, boxPieces, false, zMin, zMax) &&
            excuseGuess(codes::kGuessEdgeBrushesStock, m, timeline_->moves[index].path.pointAt(s)))
          return;
      }
      raise(m.kind == MoveKind::Rapid ? codes::kRapidIntoStock
                                      : (edge ? codes::kCutWithSpindleStopped : codes::kHolderHitsStock),
            s);
    }
    return;
  }

  {
    const Stock::Batch batch(stock_);
    forEachInterval(ctx, nosePieces, boxPieces, false, [&](int i, double lo, double hi) { stock_.remove(i, lo, hi); });
  }
  // A cut that reaches the centre line may have cut a part off: it drops into the catcher.
  if (sEnd >= 1.0 && std::min(std::abs(m.path.start[1]), std::abs(m.path.end[1])) < kCutOffReachMm &&
      std::abs(m.path.end[1] - m.path.start[1]) >= std::abs(m.path.end[0] - m.path.start[0]))
    stock_.catchCutOffPart();
  // A holder whose lowest point along the whole move stays above the ceiling (the material's highest
  // radius in these columns before this move cut) meets no material: no sweep of it needed.
  const bool holderAbove =
      toolBounds_.boundsHoldAll && ctx.tolerance >= 0.0 && pathBounds(m, s0, sEnd, toolBounds_.holder).x0 >= ceiling;
  if (options_.detectCollisions && !tool->holder.empty() && !holderAbove &&
      overlapsStock(ctx, nosePieces, boxPieces, true)) {
    const double s = earliest([&](double e) { return overlapsStock(ctx, nose(s0, e), boxes(s0, e), true); });
    const double everywhere = std::numeric_limits<double>::infinity();
    if (excuseGuess(codes::kGuessHitsStock, m, timeline_->moves[index].path.pointAt(s),
                    [&] { return holderDepth(ctx, nosePieces, boxPieces, -everywhere, everywhere); }))
      return;
    raise(codes::kHolderHitsStock, s);
  }
}

}  // namespace klueng::core::cut

// G71/G72 type II roughing: a profile that moves one way along the passes but
// dips into pockets (Fanuc 0i-TF: X and Z in the first profile block; Haas:
// a P block with X and Z). Frame as in stockRemoval: x along the passes, y
// across them (swapped for G72).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "machine/cycles_internal.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine::cycles::detail {

namespace {

// Where a piece meets y = level, as fractions of its length (tangent points too:
// the caller looks at each part between them).
std::vector<double> levelBreaks(const Segment& s, double level) {
  std::vector<double> ts;
  if (!s.isArc()) {
    const double y0 = s.start.y(), y1 = s.end.y();
    if (std::abs(y1 - y0) > 1e-12) {
      const double t = (level - y0) / (y1 - y0);
      if (t > 0.0 && t < 1.0) ts.push_back(t);
    }
    return ts;
  }
  const double r = s.radius();
  const double dy = level - s.centre.y();
  if (std::abs(dy) > r) return ts;
  const double dx = std::sqrt(std::max(0.0, r * r - dy * dy));
  const Vec2 rel0 = s.start - s.centre;
  const double phi0 = std::atan2(rel0.y(), rel0.x());
  const double sweep = s.sweep();
  for (const double x : {s.centre.x() - dx, s.centre.x() + dx}) {
    double u = (s.ccw ? 1.0 : -1.0) * (std::atan2(dy, x - s.centre.x()) - phi0);
    u = std::fmod(u, 2.0 * std::numbers::pi);
    if (u < 0) u += 2.0 * std::numbers::pi;
    if (u > 0.0 && u < sweep) ts.push_back(u / sweep);
  }
  std::sort(ts.begin(), ts.end());
  return ts;
}

struct Span {
  double from = 0.0, to = 0.0;  // along the passes
  bool fromStart = false;       // begins at the start point's x (the free end)
};

// The stretches along the passes where the contour lies at or beyond `level`
// (sb: the side of the stock), i.e. where a pass at this level cuts.
std::vector<Span> spansAt(const std::vector<Step>& contour, double startX, double level, double sb) {
  const auto cuts = [&](const Vec2& p) { return (level - p.y()) * sb >= -1e-9; };
  std::vector<Span> spans;
  bool open = cuts(contour.front().path.start);
  Span span{startX, startX, true};
  for (const Step& s : contour) {
    std::vector<double> ts = levelBreaks(s.path, level);
    ts.insert(ts.begin(), 0.0);
    ts.push_back(1.0);
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
      if (ts[i + 1] - ts[i] < 1e-12) continue;
      const bool in = cuts(s.path.pointAt((ts[i] + ts[i + 1]) / 2.0));
      if (in == open) continue;
      const double x = s.path.pointAt(ts[i]).x();
      if (in) {
        span = Span{x, x, false};
      } else {
        span.to = x;
        spans.push_back(span);
      }
      open = in;
    }
  }
  if (open) {
    span.to = contour.back().path.end.x();
    spans.push_back(span);
  }
  return spans;
}

}  // namespace

bool movesOneWayAlong(const Segment& s, double sa) {
  const int n = s.isArc() ? 32 : 1;
  Vec2 prev = s.start;
  for (int i = 1; i <= n; ++i) {
    const Vec2 p = s.pointAt(static_cast<double>(i) / n);
    if ((p.x() - prev.x()) * sa < -1e-4) return false;
    prev = p;
  }
  return true;
}

std::optional<CycleAlarm> roughPockets(const std::string& g, const SourceRange& where, const Vec2& start,
                                       const std::vector<Step>& roughed, double depth, double retract, double sa,
                                       double sb, bool infeedRapid, std::vector<Step>& steps, Vec2& pos) {
  // The deepest point of the contour: the last level is above it.
  double deepest = roughed.front().path.start.y() * sb;
  for (const Step& s : roughed) {
    const int n = s.path.isArc() ? 64 : 1;
    for (int i = 0; i <= n; ++i) deepest = std::min(deepest, s.path.pointAt(static_cast<double>(i) / n).y() * sb);
  }
  // Levels strictly above the deepest point, as type I stops above A'.
  const double levels = std::max(0.0, std::ceil((start.y() * sb - deepest) / depth - 1e-9) - 1.0);
  if (!(levels <= kMaxPasses))  // (NaN-safe: the int loops below must have a bound)
    return CycleAlarm{codes::kTooManyPasses, where, {g, fmt::format("{:.0f}", levels), num(depth)}};
  // Every level looks at every piece: bound that work, then the moves themselves.
  if (levels * static_cast<double>(roughed.size()) > 20.0 * kMaxCycleMoves)
    return CycleAlarm{codes::kTooManyCycleMoves,
                      where,
                      {g, fmt::format("{:.0f}", levels * static_cast<double>(roughed.size())),
                       fmt::format("{:.0f}", kMaxCycleMoves)}};
  // Each level's stretches, read once; kept only while the moves they make stay within the bound.
  std::vector<std::vector<Span>> spansOf;
  double moves = 0.0;
  for (int k = 1; k <= static_cast<int>(levels); ++k) {
    std::vector<Span> spans = spansAt(roughed, start.x(), start.y() - sb * k * depth, sb);
    moves += 7.0 * static_cast<double>(spans.size());
    if (moves <= kMaxCycleMoves) spansOf.push_back(std::move(spans));
  }
  if (moves > kMaxCycleMoves)
    return CycleAlarm{
        codes::kTooManyCycleMoves, where, {g, fmt::format("{:.0f}", moves), fmt::format("{:.0f}", kMaxCycleMoves)}};

  const auto to = [&](const Vec2& p, bool feed) {
    if ((p - pos).norm() <= kEps) return;
    steps.push_back(feed ? feedLine(pos, p) : rapid(pos, p));
    pos = p;
  };
  for (int k = 1; k <= static_cast<int>(levels); ++k) {
    const double level = start.y() - sb * k * depth;
    // Above the previous level the pocket's column is already clear.
    const double clear = level + sb * (depth + retract);
    for (const Span& span : spansOf[static_cast<std::size_t>(k - 1)]) {
      if ((span.to - span.from) * sa < -kEps) continue;
      if (span.fromStart) {
        to(Vec2(start.x(), level), !infeedRapid);
      } else {
        // Over the ridge at the start's height, down the cleared column, then feed into the pocket.
        to(Vec2(pos.x(), start.y()), false);
        to(Vec2(span.from, start.y()), false);
        to(Vec2(span.from, (clear - start.y()) * sb > 0.0 ? start.y() : clear), false);
        to(Vec2(span.from, level), true);
      }
      to(Vec2(span.to, level), true);
      // 45-degree retract (no further back than the span's start), then out.
      const double back = std::min(retract, std::abs(span.to - span.from));
      to(Vec2(span.to - sa * back, level + sb * retract), false);
      if (span.fromStart) {
        to(Vec2(start.x(), pos.y()), false);
      } else {
        to(Vec2(pos.x(), start.y()), false);
      }
    }
    if (std::abs(pos.x() - start.x()) > kEps) {
      to(Vec2(pos.x(), start.y()), false);
      to(start, false);
    }
  }
  return std::nullopt;
}

}  // namespace klueng::core::machine::cycles::detail

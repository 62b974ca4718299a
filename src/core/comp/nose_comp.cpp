#include "klueng/core/comp/nose_comp.h"

#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "klueng/core/comp/intersect.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::comp {

namespace {

constexpr double kPointLength = 1e-9;  // a move shorter than this has no direction (mm)
constexpr double kTangentSin = 1e-6;   // |sin(turn)| below this: no corner at all
constexpr double kSnap = 1e-6;         // end points closer than this are one point (mm)
constexpr double kReversal = 1e-6;     // a trimmed piece shorter than minus this runs backwards (mm)
constexpr double kArcAsLine = 1e-7;    // arcs shorter than this are emitted as straight lines (mm)

Vec2 leftNormal(const Vec2& d) { return Vec2(-d.y(), d.x()); }
double crossZ(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Signed path length along the carrier of `s` from `from` to `x` (both on it),
// positive in the direction of travel; arcs in (-pi r, pi r].
double along(const Segment& s, const Vec2& from, const Vec2& x) {
  if (!s.isArc()) return (x - from).dot(s.startTangent());
  const Vec2 a = from - s.centre;
  const Vec2 b = x - s.centre;
  double ang = std::atan2(crossZ(a, b), a.dot(b));
  if (!s.ccw) ang = -ang;
  return ang * s.radius();
}

enum class WorkKind {
  Curve,  // an offset line or arc
  Point,  // concave arc of radius == R: the nose centre stands at the arc centre
  Skip,   // zero-length move: no direction, takes no part in corners
};

// One contour move on its way to becoming output pieces.
struct Work {
  int source = 0;
  WorkKind kind = WorkKind::Curve;
  Segment offset;             // untrimmed offset
  Vec2 start = Vec2::Zero();  // after trimming / extending at the corners
  Vec2 end = Vec2::Zero();
  double startShift = 0.0;        // path length the start moved forward
  double endShift = 0.0;          // path length the end moved forward
  std::optional<Segment> bridge;  // convex-corner arc that precedes this piece

  double trimmedLength() const { return offset.length() + endShift - startShift; }

  Segment piece() const {
    if (kind != WorkKind::Curve || !offset.isArc() || trimmedLength() < kArcAsLine) return Segment::line(start, end);
    return Segment::arc(start, end, offset.centre, offset.ccw);
  }
};

class Compensator {
 public:
  explicit Compensator(const CompInput& in)
      : in_(in), n_(static_cast<int>(in.moves.size())), d_(static_cast<int>(in.side) * in.radius) {}

  CompOutput run();

 private:
  void fail(int source, Interference::Kind kind) {
    if (source < stopAt_) {
      stopAt_ = source;
      stopKind_ = kind;
    }
  }
  void emit(const Segment& s, int source) { out_.pieces.push_back({s, source}); }
  CompOutput finish() {
    if (stopAt_ < n_) out_.interference = Interference{stopAt_, stopKind_};
    return std::move(out_);
  }
  void buildWorks(int contourEnd);
  bool corner(Work& a, Work& b);
  Vec2 startUpEnd() const;

  const CompInput& in_;
  const int n_;
  const double d_;  // signed offset: > 0 left of travel (G41)
  std::vector<Work> works_;
  CompOutput out_;
  int stopAt_ = std::numeric_limits<int>::max();
  Interference::Kind stopKind_ = Interference::Kind::PathReversal;
};

void Compensator::buildWorks(int contourEnd) {
  works_.reserve(static_cast<std::size_t>(contourEnd));
  for (int i = 1; i < contourEnd; ++i) {
    const Segment& m = in_.moves[i];
    Work w;
    w.source = i;
    if (m.length() < kPointLength) {
      w.kind = WorkKind::Skip;
      works_.push_back(w);
      continue;
    }
    if (m.isArc()) {
      // Left of a ccw arc is its inside: the offset radius shrinks by d there.
      const double offsetRadius = m.radius() - (m.ccw ? d_ : -d_);
      if (offsetRadius < -kSnap) {
        fail(i, Interference::Kind::ArcSmallerThanRadius);
        return;
      }
      if (offsetRadius < kSnap) {
        w.kind = WorkKind::Point;
        w.offset = Segment::line(m.centre, m.centre);
        w.start = w.end = m.centre;
        works_.push_back(w);
        continue;
      }
    }
    const auto offset = offsetSegment(m, d_);
    if (!offset) {  // an inexact arc end point nearer the centre than R
      fail(i, Interference::Kind::ArcSmallerThanRadius);
      return;
    }
    w.offset = *offset;
    w.start = w.offset.start;
    w.end = w.offset.end;
    works_.push_back(w);
  }
}

// Joins a and b (consecutive contour moves with a direction) at their corner.
// Returns false after recording an interference.
bool Compensator::corner(Work& a, Work& b) {
  const Vec2 corner = in_.moves[b.source].start;
  if (a.kind == WorkKind::Point || b.kind == WorkKind::Point) {
    // The neighbour's offset must run into the arc centre (tangent entry/exit).
    const Work& point = a.kind == WorkKind::Point ? a : b;
    const Vec2 other = a.kind == WorkKind::Point ? b.start : a.end;
    if ((other - point.start).norm() > kSnap) {
      fail(point.source, Interference::Kind::ArcSmallerThanRadius);
      return false;
    }
    (a.kind == WorkKind::Point ? b.start : a.end) = point.start;
    return true;
  }
  const Vec2 t1 = in_.moves[a.source].endTangent();
  const Vec2 t2 = in_.moves[b.source].startTangent();
  const double turnSin = crossZ(t1, t2);  // > 0: the path turns left
  const double turnCos = t1.dot(t2);
  if (std::abs(turnSin) < kTangentSin && turnCos > 0) {
    b.start = a.end;  // tangent continuation: the offsets already meet
    return true;
  }
  const bool concave = d_ * turnSin > 0 && std::abs(turnSin) >= kTangentSin;
  const double radius = std::abs(d_);

  // The carrier intersection needing the least trimming or extension.
  const CarrierHits hits = intersectCarriers(a.offset, b.offset, kSnap);
  int best = -1;
  double bestScore = std::numeric_limits<double>::max();
  double bestEnd = 0.0, bestStart = 0.0;
  for (int k = 0; k < hits.count; ++k) {
    const double endShift = along(a.offset, a.offset.end, hits.points[k]);
    const double startShift = along(b.offset, b.offset.start, hits.points[k]);
    const double score = std::abs(endShift) + std::abs(startShift);
    if (score < bestScore) {
      best = k;
      bestScore = score;
      bestEnd = endShift;
      bestStart = startShift;
    }
  }
  auto meetAt = [&](const Vec2& x) {
    a.endShift = bestEnd;
    a.end = x;
    b.startShift = bestStart;
    b.start = x;
  };

  if (concave) {
    if (best < 0) {  // the offsets never meet: the nose cannot get into this corner
      fail(b.source, Interference::Kind::PathReversal);
      return false;
    }
    meetAt(hits.points[best]);
    return true;
  }
  // Convex: extend to the intersection for turns up to 90 degrees (Fanuc),
  // when the carriers meet just past the ends, else go round the corner.
  const double turn = std::atan2(std::abs(turnSin), turnCos);
  if (turn <= std::numbers::pi / 2 + 1e-9 && best >= 0 && bestEnd >= -kSnap && bestStart <= kSnap &&
      (hits.points[best] - corner).norm() <= 2 * radius) {
    meetAt(hits.points[best]);
    return true;
  }
  // Around the corner the nose turns the way the path turns: ccw iff the tool is on the right.
  b.bridge = Segment::arc(a.end, b.start, corner, d_ < 0);
  return true;
}

// Fanuc type A: offset perpendicular to the start of the next move with a direction.
Vec2 Compensator::startUpEnd() const {
  for (const Work& w : works_)
    if (w.kind != WorkKind::Skip) return w.start;  // identical to the formula below, exactly joined
  Vec2 dir = in_.moves[0].startTangent();
  for (int i = 1; i < n_; ++i) {
    if (in_.moves[i].length() >= kPointLength) {
      dir = in_.moves[i].startTangent();
      break;
    }
  }
  return in_.moves[0].end + d_ * leftNormal(dir);
}

CompOutput Compensator::run() {
  if (n_ == 0) return finish();
  const auto& moves = in_.moves;
  const bool cancel = in_.endsWithCancel && n_ >= 2;
  if (moves[0].isArc()) fail(0, Interference::Kind::ArcInStartUpOrCancel);
  if (cancel && moves[n_ - 1].isArc()) fail(n_ - 1, Interference::Kind::ArcInStartUpOrCancel);

  if (in_.radius <= 0.0) {  // a sharp tool: the centre is the programmed path
    for (int i = 0; i < n_ && i < stopAt_; ++i) emit(moves[i], i);
    return finish();
  }
  const double r = in_.radius;
  const int tip = in_.tip;
  if (stopAt_ == 0) return finish();
  if (n_ == 1 && in_.endsWithCancel) {
    emit(Segment::line(uncompensatedCentre(moves[0].start, r, tip), uncompensatedCentre(moves[0].end, r, tip)), 0);
    return finish();
  }

  const int contourEnd = cancel ? n_ - 1 : n_;
  buildWorks(contourEnd);

  // Corners between consecutive moves that have a direction.
  Work* previous = nullptr;
  for (Work& w : works_) {
    if (w.kind == WorkKind::Skip) continue;
    if (previous && !corner(*previous, w)) break;
    previous = &w;
  }
  for (const Work& w : works_) {
    if (w.source >= stopAt_) break;
    if (w.kind == WorkKind::Curve && w.trimmedLength() < -kReversal) {
      fail(w.source, Interference::Kind::PathReversal);
      break;
    }
  }

  out_.pieces.reserve(works_.size() + 2);
  Vec2 cursor = startUpEnd();
  emit(Segment::line(uncompensatedCentre(moves[0].start, r, tip), cursor), 0);
  for (const Work& w : works_) {
    if (w.source >= stopAt_) break;
    if (w.bridge) emit(*w.bridge, w.source);
    if (w.kind == WorkKind::Skip) {
      emit(Segment::line(cursor, cursor), w.source);
      continue;
    }
    emit(w.piece(), w.source);
    cursor = w.end;
  }
  if (cancel && stopAt_ >= n_) {
    emit(Segment::line(cursor, uncompensatedCentre(moves[n_ - 1].end, r, tip)), n_ - 1);
  }
  return finish();
}

std::string mm(double v) {
  std::string s = fmt::format("{:.3f}", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

CompOutput compensate(const CompInput& in) { return Compensator(in).run(); }

std::optional<Segment> offsetSegment(const Segment& s, double d) {
  if (!s.isArc()) {
    const Vec2 shift = d * leftNormal(s.startTangent());  // zero for a zero-length line
    return Segment::line(s.start + shift, s.end + shift);
  }
  const double change = s.ccw ? -d : d;  // radius change: left of a ccw arc is its inside
  auto moved = [&](const Vec2& p) -> std::optional<Vec2> {
    const Vec2 v = p - s.centre;
    const double r = v.norm();
    if (r == 0.0 || r + change <= 0.0) return std::nullopt;
    return Vec2(s.centre + v * ((r + change) / r));
  };
  const auto start = moved(s.start);
  const auto end = moved(s.end);
  if (!start || !end) return std::nullopt;
  return Segment::arc(*start, *end, s.centre, s.ccw);
}

std::string_view interferenceCode(Interference::Kind kind) {
  switch (kind) {
    case Interference::Kind::ArcSmallerThanRadius: return codes::kConcaveArcTooSmall;
    case Interference::Kind::PathReversal: return codes::kNoseDoesNotFit;
    case Interference::Kind::ArcInStartUpOrCancel: return codes::kCompStartOrCancelOnArc;
  }
  return codes::kNoseDoesNotFit;
}

std::vector<std::string> interferenceArgs(const Interference& i, const CompInput& in) {
  switch (i.kind) {
    case Interference::Kind::ArcSmallerThanRadius: {
      const bool valid = i.source >= 0 && i.source < static_cast<int>(in.moves.size());
      return {mm(valid ? in.moves[i.source].radius() : 0.0), mm(in.radius)};
    }
    case Interference::Kind::PathReversal: return {mm(in.radius)};
    case Interference::Kind::ArcInStartUpOrCancel: return {};
  }
  return {};
}

Vec2 tipVector(int tip) {
  //  2 6 1
  //  7 0 5      (+X up, +Z right); vector is (dz, dx)
  //  3 8 4
  switch (tip) {
    case 1: return Vec2(1, 1);
    case 2: return Vec2(-1, 1);
    case 3: return Vec2(-1, -1);
    case 4: return Vec2(1, -1);
    case 5: return Vec2(1, 0);
    case 6: return Vec2(0, 1);
    case 7: return Vec2(-1, 0);
    case 8: return Vec2(0, -1);
    default: return Vec2(0, 0);
  }
}

Vec2 uncompensatedCentre(const Vec2& programmed, double radius, int tip) {
  return programmed - radius * tipVector(tip);
}

Segment uncompensatedCentrePath(const Segment& programmed, double radius, int tip) {
  return programmed.translated(-radius * tipVector(tip));
}

Vec2 controlledPoint(const Vec2& centre, double radius, int tip) { return centre + radius * tipVector(tip); }

Segment controlledPath(const Segment& centrePath, double radius, int tip) {
  return centrePath.translated(radius * tipVector(tip));
}

}  // namespace klueng::core::comp

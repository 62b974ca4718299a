// Chamfer and corner R on G01 (Fanuc 0i-TF manual, "Chamfering and corner R"
// and "Direct drawing dimension programming"): `G01 X.. Z.. ,C c` cuts a
// chamfer whose ends lie c from the virtual corner along both moves; `,R r`
// rounds the corner with an arc of radius r tangent to both; `,A a` gives a
// G01 by its angle from the +Z axis (counter-clockwise) and one end coordinate.
// The corner needs the next block's move, so the G01 is held until then.
#include <numbers>

#include "machine/interpreter_impl.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine::detail {

namespace {

Vec2 unitVector(const Vec2& v) {
  const double n = v.norm();
  return n > 1e-12 ? Vec2(v / n) : Vec2(Vec2::Zero());
}

// The direction a segment leaves its start / arrives at its end.
Vec2 startDirection(const Segment& s) {
  if (!s.isArc()) return unitVector(s.end - s.start);
  const Vec2 r = s.start - s.centre;
  const Vec2 t = s.ccw ? Vec2(-r.y(), r.x()) : Vec2(r.y(), -r.x());
  return unitVector(t);
}

// The point of `s` at distance d from its start along the path (an arc: by chord, as the control measures it).
std::optional<Vec2> pointFromStart(const Segment& s, double d) {
  if (!s.isArc()) {
    const double len = (s.end - s.start).norm();
    if (d > len + 1e-9) return std::nullopt;
    return Vec2(s.start + unitVector(s.end - s.start) * d);
  }
  const double r = s.radius();
  if (d > 2.0 * r) return std::nullopt;
  const double angle = 2.0 * std::asin(std::min(1.0, d / (2.0 * r)));
  if (angle > s.sweep() + 1e-9) return std::nullopt;
  const Vec2 a = s.start - s.centre;
  const double phi = std::atan2(a.y(), a.x()) + (s.ccw ? angle : -angle);
  return Vec2(s.centre + r * Vec2(std::cos(phi), std::sin(phi)));
}

Segment withStart(const Segment& s, const Vec2& start) {
  return s.isArc() ? Segment::arc(start, s.end, s.centre, s.ccw) : Segment::line(start, s.end);
}

}  // namespace

bool Interpreter::holdCorner(const Segment& path, const Word* where) {
  // Two corners in a row: the one before ends where this G01 starts.
  Segment first = path;
  if (corner_.active && corner_.blockIndex != blockIndex_) {
    Vec2 start;
    if (!cutHeldCorner(path, start, where)) return false;
    first = Segment::line(start, path.end);
  }
  const Word* c = chamferWord();
  const Word* r = commaWord('R');
  const Word* w = c ? c : r;
  if (!pathWithinTravel(first, where)) return false;
  corner_ = PendingCorner{};
  corner_.active = true;
  corner_.kind = c ? 'C' : 'R';
  corner_.size = std::abs(w->value) * unit();
  corner_.where = w->range;
  corner_.text = w->comma ? "," + w->text() : w->text();
  corner_.blockIndex = blockIndex_;
  corner_.first.kind = MoveKind::Line;
  corner_.first.path = first;
  fillCall(corner_.first, where);
  moved(first.end);  // the program goes on from the virtual corner
  return true;
}

bool Interpreter::cornerNeedsMove() {
  corner_.active = false;
  sink_->alarm(Diagnostic{Severity::Alarm, codes::kCornerNeedsNextMove, corner_.where, {corner_.text}});
  return false;
}

bool Interpreter::feedMoveAfterCorner(MoveKind kind, const Segment& path, const Word* where) {
  if (!corner_.active || corner_.blockIndex == blockIndex_) return feedMove(kind, path, where);
  Vec2 start;
  if (!cutHeldCorner(path, start, where)) return false;
  if ((path.end - start).norm() <= 1e-9) {
    moved(path.end);
    return true;
  }
  return feedMove(kind, withStart(path, start), where);
}

// The move after a held G01: cut the held G01 short, then the chamfer or the
// corner arc; `start` is where `path` goes on from.
bool Interpreter::cutHeldCorner(const Segment& path, Vec2& start, const Word* where) {
  PendingCorner held = corner_;
  corner_.active = false;
  const Segment& first = held.first.path;
  const Vec2 corner = first.end;
  const double len1 = (first.end - first.start).norm();
  const Vec2 d1 = unitVector(first.end - first.start);
  const Vec2 d2 = startDirection(path);
  const auto alarm = [&](const char* code) {
    sink_->alarm(Diagnostic{Severity::Alarm, code, held.where, {held.text}});
    return false;
  };
  const auto tooLong = [&]() { return alarm(codes::kCornerLongerThanMove); };
  Vec2 p1, p2;
  std::optional<Segment> round;
  if (held.kind == 'C') {
    if (held.size > len1 + 1e-9) return tooLong();
    p1 = corner - d1 * held.size;
    const auto q = pointFromStart(path, held.size);
    if (!q) return tooLong();
    p2 = *q;
  } else {
    // A tangent arc of radius r between two lines: its ends lie r * tan(theta/2)
    // from the corner, theta the turn between the two directions.
    // Corner R into an arc: the control rounds it too; the simulation needs the two lines.
    if (path.isArc()) return alarm(codes::kAngleUnreachable);
    const double cross = d1.x() * d2.y() - d1.y() * d2.x();
    const double dot = std::clamp(d1.dot(d2), -1.0, 1.0);
    const double theta = std::acos(dot);
    if (std::abs(cross) < 1e-12) {  // straight on: no corner to round
      start = corner;
      pos_ = first.start;
      return feedMove(MoveKind::Line, first, where);
    }
    const double t = held.size * std::tan(theta / 2.0);
    const double len2 = (path.end - path.start).norm();
    if (t > len1 + 1e-9 || t > len2 + 1e-9) return tooLong();
    p1 = corner - d1 * t;
    p2 = corner + d2 * t;
    const bool ccw = cross > 0.0;
    const Vec2 normal = ccw ? Vec2(-d1.y(), d1.x()) : Vec2(d1.y(), -d1.x());
    round = Segment::arc(p1, p2, p1 + normal * held.size, ccw);
  }
  // The held G01 up to the corner piece (nothing when the piece takes all of it).
  pos_ = first.start;
  MotionCall m = held.first;
  if ((p1 - first.start).norm() > 1e-9) {
    m.path = Segment::line(first.start, p1);
    sink_->motion(m);
  }
  // The corner piece belongs to the block that asked for it.
  MotionCall piece = held.first;
  piece.kind = round ? MoveKind::Arc : MoveKind::Line;
  piece.path = round ? *round : Segment::line(p1, p2);
  if (!pathWithinTravel(piece.path, where)) return false;
  sink_->motion(piece);
  moved(p2);
  start = p2;
  return true;
}

// ,A: the missing end coordinate of a G01 from its angle to the +Z axis.
bool Interpreter::angleTarget(Vec2& target, const Word* where) {
  const Word* a = commaWord('A');
  if (!a) return true;
  const double angle = a->value * std::numbers::pi / 180.0;
  const Vec2 dir(std::cos(angle), std::sin(angle));  // (z, x radius)
  const bool x = movesX(), z = movesZ();
  const auto unreachable = [&]() { return raise(codes::kAngleUnreachable, a, {"," + a->text()}); };
  if (x && !z) {
    if (std::abs(dir.y()) < 1e-9) return unreachable();
    const double t = (xOf(target) - xOf(pos_)) / dir.y();
    target = Vec2(zOf(pos_) + t * dir.x(), xOf(target));
  } else if (z && !x) {
    if (std::abs(dir.x()) < 1e-9) return unreachable();
    const double t = (zOf(target) - zOf(pos_)) / dir.x();
    target = Vec2(zOf(target), xOf(pos_) + t * dir.y());
  } else if (!x && !z) {
    return unreachable();
  }
  (void)where;
  return true;
}

}  // namespace klueng::core::machine::detail

// Chamfer and corner R on G01 (Fanuc 0i-TF manual, "Chamfering and corner R"):
// `G01 X.. Z.. ,C c` cuts a chamfer whose ends lie c from the virtual corner
// along both moves; `,R r` rounds the corner with an arc of radius r tangent
// to both. The corner needs the next block's move, so the G01 waits here.
#include "machine/corner_stage.h"

#include <algorithm>
#include <cmath>

#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine::detail {

namespace {

Vec2 cornerUnitVector(const Vec2& v) {
  const double n = v.norm();
  return n > 1e-12 ? Vec2(v / n) : Vec2(Vec2::Zero());
}

// The direction a segment leaves its start.
Vec2 cornerStartDirection(const Segment& s) {
  if (!s.isArc()) return cornerUnitVector(s.end - s.start);
  const Vec2 r = s.start - s.centre;
  const Vec2 t = s.ccw ? Vec2(-r.y(), r.x()) : Vec2(r.y(), -r.x());
  return cornerUnitVector(t);
}

// The point of `s` at distance d from its start along the path (an arc: by chord, as the control measures it).
std::optional<Vec2> cornerPointFromStart(const Segment& s, double d) {
  if (!s.isArc()) {
    const double len = (s.end - s.start).norm();
    if (d > len + 1e-9) return std::nullopt;
    return Vec2(s.start + cornerUnitVector(s.end - s.start) * d);
  }
  const double r = s.radius();
  if (d > 2.0 * r) return std::nullopt;
  const double angle = 2.0 * std::asin(std::min(1.0, d / (2.0 * r)));
  if (angle > s.sweep() + 1e-9) return std::nullopt;
  const Vec2 a = s.start - s.centre;
  const double phi = std::atan2(a.y(), a.x()) + (s.ccw ? angle : -angle);
  return Vec2(s.centre + r * Vec2(std::cos(phi), std::sin(phi)));
}

Segment cornerWithStart(const Segment& s, const Vec2& start) {
  return s.isArc() ? Segment::arc(start, s.end, s.centre, s.ccw) : Segment::line(start, s.end);
}

}  // namespace

bool CornerStage::alarmAt(const Held& held, const char* code) {
  next_.alarm(Diagnostic{Severity::Alarm, code, held.request.where, {held.request.text}});
  return false;
}

bool CornerStage::refuse() {
  const Held held = *held_;
  held_.reset();
  return alarmAt(held, codes::kCornerNeedsNextMove);
}

CornerStage::Cut CornerStage::hold(const MotionCall& toCorner, const CornerRequest& request) {
  // Two corners in a row: the one before ends where this G01 starts.
  Cut done;
  MotionCall first = toCorner;
  if (heldBefore(toCorner.blockIndex)) {
    done = cut(toCorner);
    if (!done.ok) return done;
    first.path = Segment::line(*done.pieceEnd, toCorner.path.end);
  }
  if (!travel_(first.path, toCorner.where)) {
    done.ok = false;
    return done;
  }
  held_ = Held{first, request};
  return done;
}

CornerStage::Cut CornerStage::follow(const MotionCall& m) {
  Cut done = cut(m);
  if (!done.ok) return done;
  const Vec2 start = *done.pieceEnd;
  if ((m.path.end - start).norm() <= 1e-9) return done;  // the corner piece took all of the move
  MotionCall rest = m;
  rest.path = cornerWithStart(m.path, start);
  if (!travel_(rest.path, m.where)) {
    done.ok = false;
    return done;
  }
  next_.motion(rest);
  return done;
}

// The move after a held G01: the held G01 cut short, then the chamfer or the
// corner arc.
CornerStage::Cut CornerStage::cut(const MotionCall& m) {
  const Held held = *held_;
  held_.reset();
  Cut done;
  done.ok = false;
  const Segment& path = m.path;
  const Segment& first = held.first.path;
  const Vec2 corner = first.end;
  const double size = held.request.size;
  const double len1 = (first.end - first.start).norm();
  const Vec2 d1 = cornerUnitVector(first.end - first.start);
  const Vec2 d2 = cornerStartDirection(path);
  const auto tooLong = [&]() {
    alarmAt(held, codes::kCornerLongerThanMove);
    return done;
  };
  Vec2 p1, p2;
  std::optional<Segment> round;
  if (held.request.kind == 'C') {
    if (size > len1 + 1e-9) return tooLong();
    p1 = corner - d1 * size;
    const auto q = cornerPointFromStart(path, size);
    if (!q) return tooLong();
    p2 = *q;
  } else {
    // A tangent arc of radius r between two lines: its ends lie r * tan(theta/2)
    // from the corner, theta the turn between the two directions.
    // Corner R into an arc: the control rounds it too; the simulation needs the two lines.
    if (path.isArc()) {
      alarmAt(held, codes::kAngleUnreachable);
      return done;
    }
    const double cross = d1.x() * d2.y() - d1.y() * d2.x();
    const double dot = std::clamp(d1.dot(d2), -1.0, 1.0);
    const double theta = std::acos(dot);
    if (std::abs(cross) < 1e-12) {  // straight on: no corner to round; the held G01 goes as the next block's
      done.restart = first.start;
      if (!travel_(first, m.where)) return done;
      MotionCall whole = m;
      whole.kind = MoveKind::Line;
      whole.path = first;
      next_.motion(whole);
      done.ok = true;
      done.pieceEnd = first.end;
      return done;
    }
    const double t = size * std::tan(theta / 2.0);
    const double len2 = (path.end - path.start).norm();
    if (t > len1 + 1e-9 || t > len2 + 1e-9) return tooLong();
    p1 = corner - d1 * t;
    p2 = corner + d2 * t;
    const bool ccw = cross > 0.0;
    const Vec2 normal = ccw ? Vec2(-d1.y(), d1.x()) : Vec2(d1.y(), -d1.x());
    round = Segment::arc(p1, p2, p1 + normal * size, ccw);
  }
  // The held G01 up to the corner piece (nothing when the piece takes all of it).
  done.restart = first.start;
  if ((p1 - first.start).norm() > 1e-9) {
    MotionCall shortened = held.first;
    shortened.path = Segment::line(first.start, p1);
    next_.motion(shortened);
  }
  // The corner piece belongs to the block that asked for it.
  MotionCall piece = held.first;
  piece.kind = round ? MoveKind::Arc : MoveKind::Line;
  piece.path = round ? *round : Segment::line(p1, p2);
  if (!travel_(piece.path, m.where)) return done;
  next_.motion(piece);
  done.ok = true;
  done.pieceEnd = p2;
  return done;
}

}  // namespace klueng::core::machine::detail

#include "render/path_painter.h"

#include <QPen>
#include <cmath>
#include <numbers>

#include "render/lathe_painters.h"

namespace klueng::render {

void appendSegment(QPainterPath& path, const core::Segment& segment, bool moveToStart) {
  if (moveToStart) path.moveTo(toScene(segment.start));
  if (!segment.isArc()) {
    path.lineTo(toScene(segment.end));
    return;
  }
  // Qt's arcs (Bezier pieces) are exact enough at any zoom and cheap for long trails.
  // Scene y is -X, so the drawing's counter-clockwise is the screen's counter-clockwise too.
  const double r = segment.radius();
  const core::Vec2 d = segment.start - segment.centre;
  const double startDeg = std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
  const double sweepDeg = segment.sweep() * 180.0 / std::numbers::pi * (segment.ccw ? 1.0 : -1.0);
  const QPointF c = toScene(segment.centre);
  if (!moveToStart && path.currentPosition() != toScene(segment.start)) path.lineTo(toScene(segment.start));
  path.arcTo(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r), startDeg, sweepDeg);
}

core::Segment partialSegment(const core::Segment& segment, double s) {
  core::Segment part = segment;
  part.end = segment.pointAt(std::clamp(s, 0.0, 1.0));
  return part;
}

void PathTrail::clear() {
  feed_ = QPainterPath();
  rapid_ = QPainterPath();
  lastFeedEnd_ = lastRapidEnd_ = core::Vec2(1e300, 1e300);
}

void PathTrail::append(const core::machine::Move& move) {
  using core::machine::MoveKind;
  if (move.kind == MoveKind::Dwell) return;
  const bool rapid = move.kind == MoveKind::Rapid;
  QPainterPath& path = rapid ? rapid_ : feed_;
  core::Vec2& last = rapid ? lastRapidEnd_ : lastFeedEnd_;
  const bool continues = (last - move.path.start).norm() < 1e-9;
  appendSegment(path, move.path, !continues);
  last = move.path.end;
}

QRectF PathTrail::boundingRect() const { return feed_.boundingRect().united(rapid_.boundingRect()); }

void PathTrail::paint(QPainter& painter) const { paintPaths(painter, feed_, rapid_); }

void PathTrail::paintPaths(QPainter& painter, const QPainterPath& feed, const QPainterPath& rapid) {
  painter.save();
  painter.setBrush(Qt::NoBrush);
  QPen rapidPen(palette().rapidPath, 1.0, Qt::DashLine);
  rapidPen.setCosmetic(true);
  painter.setPen(rapidPen);
  painter.drawPath(rapid);
  // Width 1 cosmetic pens take the raster engine's fast stroker (long trails stay quick).
  QPen feedPen(palette().feedPath, 1.0, Qt::SolidLine);
  feedPen.setCosmetic(true);
  painter.setPen(feedPen);
  painter.drawPath(feed);
  painter.restore();
}

}  // namespace klueng::render

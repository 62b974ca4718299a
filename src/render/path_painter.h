#pragma once
// Tool path trail: rapids dashed, feeds solid (SPEC 10, issue 5).
//
// Public API
//   PathTrail  built incrementally from Timeline moves: append(move) or
//              appendPartial(move, upToTime); paint(painter) draws both pens.
//   appendMovePath(QPainterPath&, Segment)  a Segment (line or arc) in scene units.
#include <QPainter>
#include <QPainterPath>

#include "klueng/core/machine/timeline.h"

namespace klueng::render {

void appendSegment(QPainterPath& path, const core::Segment& segment, bool moveToStart);
// Part of a segment from its start to fraction s in [0,1] of its length.
core::Segment partialSegment(const core::Segment& segment, double s);

class PathTrail {
 public:
  void clear();
  void append(const core::machine::Move& move);
  const QPainterPath& feedPath() const { return feed_; }
  const QPainterPath& rapidPath() const { return rapid_; }
  QRectF boundingRect() const;
  void paint(QPainter& painter) const;
  static void paintPaths(QPainter& painter, const QPainterPath& feed, const QPainterPath& rapid);

 private:
  QPainterPath feed_;
  QPainterPath rapid_;
  core::Vec2 lastFeedEnd_{1e300, 1e300};
  core::Vec2 lastRapidEnd_{1e300, 1e300};
};

}  // namespace klueng::render

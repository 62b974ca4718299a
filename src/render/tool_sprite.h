#pragma once
// A tool bitmap ready to draw: white pixels transparent, at its own
// resolution (2 pixels per mm for the seed's bitmaps, SPEC 11; a library tool's own), with its controlled point for an
// imaginary-tip number.
//
// Public API
//   ToolSprite::fromShape(shape)      from the core's cut::ToolShape (its bitmap and the
//                                     core's controlled point) -- what the view draws
//   ToolSprite::fromImage(rgb, tip)   any bitmap (also one the core refuses as a tool);
//                                     the controlled point by the same SPEC 11 rule
//   image()            ARGB32 image, white made transparent
//   controlledPointPx()  the controlled point in image pixel coordinates (may lie on
//                      a pixel edge: the corner of the cutting-edge bounding box)
//   paint(painter, controlledPointScene)  draws the tool, in scene millimetres, so
//                      that its controlled point sits at that scene point
//   sceneRect(controlledPointScene)       the rectangle paint() covers
//   pixelsPerMm()      the bitmap's resolution (seedPixelsPerMm == 2 unless given)
#include <QImage>
#include <QPainter>
#include <QPointF>
#include <QRectF>
#include <QString>

#include "klueng/core/cut/tool_shape.h"
#include "klueng/core/io/image.h"

namespace klueng::render {

class ToolSprite {
 public:
  static constexpr double seedPixelsPerMm = 2.0;

  ToolSprite() = default;
  static ToolSprite fromImage(const core::io::RgbImage& rgb, int tip, double pixelsPerMm = seedPixelsPerMm);
  static ToolSprite fromShape(const core::cut::ToolShape& shape);

  bool isNull() const { return image_.isNull(); }
  const QImage& image() const { return image_; }
  QPointF controlledPointPx() const { return controlPx_; }
  int tip() const { return tip_; }
  double pixelsPerMm() const { return ppm_; }
  // Cutting-edge pixels' bounding box in pixel coordinates (empty if the bitmap has none).
  QRect cuttingEdgeBox() const { return edgeBox_; }

  QRectF sceneRect(const QPointF& controlledPointScene) const;
  void paint(QPainter& painter, const QPointF& controlledPointScene) const;

 private:
  QImage image_;
  QPointF controlPx_;
  QRect edgeBox_;
  int tip_ = 0;
  double ppm_ = seedPixelsPerMm;
};

// The controlled point of a bitmap for a tip (pixel coordinates, y down): the
// corner / edge middle / centre of the cutting-edge bounding box in the tip's
// direction (SPEC 11). Uses the core's definition when it is available.
QPointF controlledPointForTip(const QRect& cuttingEdgeBox, int tip);

// A small picture of the imaginary tip number: nose circle, tip cross, arrow (Offset dialog).
QImage tipPicture(int tip, int sizePx);

}  // namespace klueng::render

#pragma once
// What the Part panel (issue 10) lays over the output screen: the part check's
// gouges (red) and leftovers (yellow), the compensation comparison's other
// part (magenta outline) and its differences (orange), the selected feature
// (a thick blue line on its profile), and the measure tool's line with its
// ΔZ, ΔØ, distance and angle. Scene units: mm, scene y = -X radius; every
// mark is drawn on both halves.
#include <QColor>
#include <QGraphicsItem>
#include <QPainterPath>
#include <QString>
#include <optional>
#include <vector>

#include "klueng/core/cut/stock.h"
#include "klueng/core/units.h"

namespace klueng::gui {

struct PartOverlay {
  struct Band {
    double zLeft = 0.0, zRight = 0.0;  // mm
    double r0 = 0.0, r1 = 0.0;         // radii it spans
    QColor colour;
  };
  std::vector<Band> bands;
  QPainterPath otherOutline;  // upper half, scene units (comparison)
  QPainterPath highlight;     // upper half, scene units (selected feature)
  bool empty() const { return bands.empty() && otherOutline.isEmpty() && highlight.isEmpty(); }
};

class PartOverlayItem : public QGraphicsItem {
 public:
  PartOverlayItem();
  void setOverlay(const PartOverlay& overlay);
  const PartOverlay& overlay() const { return overlay_; }
  QRectF boundingRect() const override { return bounds_; }
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

 private:
  PartOverlay overlay_;
  QRectF bounds_;
};

// The measure tool's two points (scene) and what lies between them.
class MeasureItem : public QGraphicsItem {
 public:
  MeasureItem();
  void setPoints(const QPointF& a, const std::optional<QPointF>& b);
  // "ΔZ 20.000  ΔØ 10.000  d 22.361  ∠ 26.57°" (empty before the second point).
  // In the unit shown (View ▸ Units shown): 3 decimals in mm, 4 in inches.
  static QString reading(const QPointF& a, const QPointF& b, const core::UnitFormat& units = core::UnitFormat{});
  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

 private:
  QPointF a_;
  std::optional<QPointF> b_;
};

// The scene point snapped to the stock's outside or bore profile (within
// `tolerance` mm of it) and to a face (a step of the profile) within the same
// distance along Z; unchanged when nothing is that near.
QPointF snapToStock(const core::cut::Stock& stock, const QPointF& scenePos, double tolerance);

}  // namespace klueng::gui

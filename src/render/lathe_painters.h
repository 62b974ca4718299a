#pragma once
// QPainter code for the lathe drawing, shared by the output screen, Print
// Drawing and PNG export (no widgets here).
//
// Public API
//   Scene coordinates are millimetres with Z to the right and X (radius) UP:
//     render::toScene(Vec2(z, r)) == QPointF(z, -r)   (Qt's y grows downward)
//   StockShape       material left in the stock (upper half, scene units): a fill
//                    path (column runs of the core's dexel Stock) and its exact
//                    outline; drawn mirrored about the centre line.
//   stockShapeFromStock(stock)  from core::cut::Stock (what the core has cut)
//   paintStock()     fills the section (both halves) and the centre line.
//   paintChuck()     the core's cut::Chuck (jaws gripping the stock's left end, the
//                    body behind it), both halves -- the same boxes the crash check uses.
//   paintCentreLine()  dash-dot axis line over a Z range.
//   stockShapeFromBlank()  the rectangle of an uncut bar (diameter, length).
//   Colours: render::palette() (one place, so screen and print agree).
#include <QColor>
#include <QPainter>
#include <QPainterPath>
#include <QPointF>
#include <QPolygonF>
#include <QRectF>
#include <vector>

#include "klueng/core/cut/stock.h"
#include "klueng/core/geometry.h"

namespace klueng::render {

inline QPointF toScene(const core::Vec2& zx) { return QPointF(zx.x(), -zx.y()); }
inline QPointF toScene(double z, double radius) { return QPointF(z, -radius); }
inline core::Vec2 fromScene(const QPointF& p) { return core::Vec2(p.x(), -p.y()); }

struct Palette {
  QColor background{250, 250, 247};
  QColor stockFill{176, 190, 204};
  QColor stockEdge{60, 72, 88};
  QColor removedFill{235, 235, 230};  // outline of the blank, to show what was cut
  QColor centreLine{200, 40, 40};
  QColor chuckFill{90, 90, 96};
  QColor chuckEdge{30, 30, 34};
  QColor feedPath{0, 110, 200};
  QColor rapidPath{220, 120, 0};
  QColor controlledPoint{220, 0, 0};
};
const Palette& palette();

// Material in the upper half plane, in scene units (z, -radius), see toScene.
struct StockShape {
  QPainterPath fill;     // union of rectangles: runs of equal columns x material intervals
  QPainterPath outline;  // the boundary of `fill` (no seams between runs)
  QRectF blank;          // the uncut bar's upper half (a tube's: radii bore/2 .. diameter/2)
  bool isEmpty() const { return fill.isEmpty(); }
  QRectF boundingRect() const;  // both halves
  // Is the point (z, radius) material?  (Tests compare this with the core's part.)
  bool containsMaterial(double z, double radius) const;
};

StockShape stockShapeFromBlank(double diameterMm, double lengthMm, double boreMm = 0.0);  // bore > 0: a tube
StockShape stockShapeFromStock(const core::cut::Stock& stock);

// Fills both halves of the stock section; `cosmetic` pens stay 1 px at any zoom.
void paintStock(QPainter& painter, const StockShape& stock, bool showBlankOutline = true);
void paintCentreLine(QPainter& painter, double zFrom, double zTo);
void paintChuck(QPainter& painter, const core::cut::Chuck& chuck);
QRectF chuckRect(const core::cut::Chuck& chuck);  // both halves, scene units
// The controlled point's cross: arms of halfLength, pen width in the painter's units.
void paintMarker(QPainter& painter, const QPointF& at, double halfLength, double penWidth);
core::cut::Chuck chuckFor(double stockDiameterMm, double stockLengthMm, double gripMm, double jawHeightMm,
                          double spindleBoreMm = 40.0);

}  // namespace klueng::render

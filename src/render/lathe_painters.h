#pragma once
// QPainter code for the lathe drawing, shared by the output screen, Print
// Drawing and PNG export (no widgets here).
//
// Public API
//   Scene coordinates are millimetres with Z to the right and X (radius) UP:
//     render::toScene(Vec2(z, r)) == QPointF(z, -r)   (Qt's y grows downward)
//   StockShape       material left in the stock: closed (z, radius) polygons
//                    in the upper half (radius >= 0); drawn mirrored about the
//                    centre line so the whole section shows.
//   paintStock()     fills the section (both halves) and the centre line.
//   paintChuck()     the jaws gripping the stock's left end (machine.cfg's
//                    chuckGrip / chuckJawHeight), both halves.
//   paintCentreLine()  dash-dot axis line over a Z range.
//   stockShapeFromBlank()  the rectangle of an uncut bar (diameter, length).
//   Colours: render::palette() (one place, so screen and print agree).
#include <QColor>
#include <QPainter>
#include <QPointF>
#include <QPolygonF>
#include <QRectF>
#include <vector>

#include "klueng/core/geometry.h"

namespace klueng::render {

inline QPointF toScene(const core::Vec2& zx) { return QPointF(zx.x(), -zx.y()); }
inline QPointF toScene(double z, double radius) { return QPointF(z, -radius); }
inline core::Vec2 fromScene(const QPointF& p) { return core::Vec2(p.x(), -p.y()); }

struct Palette {
  QColor background{250, 250, 247};
  QColor stockFill{176, 190, 204};
  QColor stockEdge{60, 72, 88};
  QColor removedFill{235, 235, 230};   // outline of the blank, to show what was cut
  QColor centreLine{200, 40, 40};
  QColor chuckFill{90, 90, 96};
  QColor chuckEdge{30, 30, 34};
  QColor feedPath{0, 110, 200};
  QColor rapidPath{220, 120, 0};
  QColor controlledPoint{220, 0, 0};
};
const Palette& palette();

// Material in the upper half plane as closed polygons of (z, radius) points.
struct StockShape {
  std::vector<QPolygonF> polygons;   // each in scene units (z, -radius), see toScene
  QRectF blank;                      // the uncut bar's upper half, in scene units
  bool isEmpty() const { return polygons.empty(); }
  QRectF boundingRect() const;       // both halves
};

StockShape stockShapeFromBlank(double diameterMm, double lengthMm);

// Fills both halves of the stock section; `cosmetic` pens stay 1 px at any zoom.
void paintStock(QPainter& painter, const StockShape& stock, bool showBlankOutline = true);
void paintCentreLine(QPainter& painter, double zFrom, double zTo);
// Jaws at z in [-length - 5, -length + grip], outside radius diameter/2 .. + jawHeight.
void paintChuck(QPainter& painter, double stockDiameterMm, double stockLengthMm, double gripMm,
                double jawHeightMm);
QRectF chuckRect(double stockDiameterMm, double stockLengthMm, double gripMm, double jawHeightMm);

}  // namespace klueng::render

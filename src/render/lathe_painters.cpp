#include "render/lathe_painters.h"

#include <QPainterPath>
#include <QPen>
#include <algorithm>
#include <span>

namespace klueng::render {

const Palette& palette() {
  static const Palette p;
  return p;
}

QRectF StockShape::boundingRect() const {
  QRectF r = blank.united(fill.boundingRect());
  // Mirror about the centre line: the lower half spans the same radii downward.
  const QRectF mirrored(r.left(), -r.bottom(), r.width(), r.height());
  return r.united(mirrored);
}

bool StockShape::containsMaterial(double z, double radius) const { return fill.contains(toScene(z, radius)); }

StockShape stockShapeFromBlank(double diameterMm, double lengthMm, double boreMm) {
  StockShape s;
  const double r = diameterMm / 2.0;
  const double b = boreMm > 0.0 && boreMm < diameterMm ? boreMm / 2.0 : 0.0;
  s.blank = QRectF(QPointF(-lengthMm, -r), QPointF(0.0, -b));  // a tube leaves its bore empty
  s.fill.addRect(s.blank);
  s.outline.addRect(s.blank);
  return s;
}

namespace {

using Intervals = std::span<const core::cut::Interval>;

bool sameIntervals(Intervals a, Intervals b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].lo != b[i].lo || a[i].hi != b[i].hi) return false;
  return true;
}

// Vertical outline pieces at z between two neighbouring runs: where exactly one
// side has material (the symmetric difference of their radial coverage).
void addSeam(QPainterPath& outline, double z, Intervals left, Intervals right) {
  std::vector<double> cuts;
  for (Intervals side : {left, right})
    for (const auto& iv : side) {
      cuts.push_back(iv.lo);
      cuts.push_back(iv.hi);
    }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  auto covered = [](Intervals side, double r) {
    for (const auto& iv : side)
      if (r > iv.lo && r < iv.hi) return true;
    return false;
  };
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double mid = (cuts[i] + cuts[i + 1]) / 2.0;
    if (covered(left, mid) != covered(right, mid)) {
      outline.moveTo(toScene(z, cuts[i]));
      outline.lineTo(toScene(z, cuts[i + 1]));
    }
  }
}

}  // namespace

StockShape stockShapeFromStock(const core::cut::Stock& stock) {
  StockShape s;
  const double r = stock.diameter() / 2.0;
  s.blank = QRectF(QPointF(-stock.length(), -r), QPointF(0.0, -stock.bore() / 2.0));  // the uncut ring of a tube
  const int n = stock.columnCount();
  const double dz = stock.resolution();
  Intervals previous;
  int runStart = 0;
  // Equal neighbouring columns merge into one rectangle per interval.
  auto closeRun = [&](int endColumn /* exclusive */) {
    if (endColumn <= runStart) return;
    const double z0 = stock.zLeft(runStart);
    const double z1 = stock.zLeft(runStart) + (endColumn - runStart) * dz;
    for (const auto& iv : previous) {
      s.fill.addRect(QRectF(QPointF(z0, -iv.hi), QPointF(z1, -iv.lo)));
      s.outline.moveTo(toScene(z0, iv.hi));
      s.outline.lineTo(toScene(z1, iv.hi));
      if (iv.lo > 0.0) {
        s.outline.moveTo(toScene(z0, iv.lo));
        s.outline.lineTo(toScene(z1, iv.lo));
      }
    }
  };
  for (int i = 0; i < n; ++i) {
    const Intervals col = stock.column(i);
    if (i == 0) {
      addSeam(s.outline, stock.zLeft(0), {}, col);
      previous = col;
      continue;
    }
    if (sameIntervals(col, previous)) continue;
    closeRun(i);
    addSeam(s.outline, stock.zLeft(i), previous, col);
    previous = col;
    runStart = i;
  }
  if (n > 0) {
    closeRun(n);
    addSeam(s.outline, stock.zLeft(runStart) + (n - runStart) * dz, previous, {});
  }
  return s;
}

namespace {

QPen cosmeticPen(const QColor& c, qreal width, Qt::PenStyle style = Qt::SolidLine) {
  QPen pen(c, width, style);
  pen.setCosmetic(true);
  return pen;
}

}  // namespace

void paintStock(QPainter& painter, const StockShape& stock, bool showBlankOutline) {
  const Palette& pal = palette();
  painter.save();
  if (showBlankOutline && !stock.blank.isEmpty()) {
    // What was removed stays visible as a faint outline of the bar.
    const QRectF lower(stock.blank.left(), -stock.blank.bottom(), stock.blank.width(), stock.blank.height());
    painter.setPen(cosmeticPen(pal.stockEdge.lighter(220), 1.0, Qt::DotLine));
    painter.setBrush(pal.removedFill);
    painter.drawRect(stock.blank);
    painter.drawRect(lower);
  }
  for (int half = 0; half < 2; ++half) {
    if (half == 1) painter.scale(1.0, -1.0);  // the lower half: the section mirrored about the axis
    painter.setPen(Qt::NoPen);
    painter.setBrush(pal.stockFill);
    painter.drawPath(stock.fill);
    painter.setPen(cosmeticPen(pal.stockEdge, 1.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(stock.outline);
  }
  painter.restore();
  if (!stock.blank.isEmpty()) paintCentreLine(painter, stock.blank.left() - 10.0, stock.blank.right() + 10.0);
}

void paintCentreLine(QPainter& painter, double zFrom, double zTo) {
  painter.save();
  painter.setPen(cosmeticPen(palette().centreLine, 1.0, Qt::DashDotLine));
  painter.drawLine(QPointF(zFrom, 0.0), QPointF(zTo, 0.0));
  painter.restore();
}

core::cut::Chuck chuckFor(double stockDiameterMm, double stockLengthMm, double gripMm, double jawHeightMm,
                          double spindleBoreMm) {
  core::cut::Chuck c;
  c.spindleBoreRadius = std::max(0.0, spindleBoreMm / 2.0);
  c.stockLength = stockLengthMm;
  c.stockRadius = stockDiameterMm / 2.0;
  c.grip = gripMm;
  c.jawHeight = jawHeightMm;
  return c;
}

QRectF chuckRect(const core::cut::Chuck& c) {
  const double top = std::max(c.jawXMax(), c.bodyXMax());
  return QRectF(QPointF(c.bodyZMin(), -top), QPointF(c.jawZMax(), top));
}

void paintChuck(QPainter& painter, const core::cut::Chuck& c) {
  const Palette& pal = palette();
  painter.save();
  painter.setPen(cosmeticPen(pal.chuckEdge, 1.0));
  for (double sign : {1.0, -1.0}) {
    // Jaw: the box the crash check uses, gripping the bar's left end.
    painter.setBrush(pal.chuckFill);
    painter.drawRect(
        QRectF(QPointF(c.jawZMin(), -sign * c.jawXMin()), QPointF(c.jawZMax(), -sign * c.jawXMax())).normalized());
  }
  // The chuck body behind the bar's end: a ring around the spindle bore.
  painter.setBrush(pal.chuckFill.darker(130));
  for (double sign : {1.0, -1.0})
    painter.drawRect(
        QRectF(QPointF(c.bodyZMin(), sign * c.bodyXMin()), QPointF(c.bodyZMax(), sign * c.bodyXMax())).normalized());
  painter.restore();
}

void paintMarker(QPainter& painter, const QPointF& at, double halfLength, double penWidth) {
  painter.setPen(QPen(palette().controlledPoint, penWidth));
  painter.drawLine(at - QPointF(halfLength, 0), at + QPointF(halfLength, 0));
  painter.drawLine(at - QPointF(0, halfLength), at + QPointF(0, halfLength));
}

}  // namespace klueng::render

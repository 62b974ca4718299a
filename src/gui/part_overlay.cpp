#include "gui/part_overlay.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>
#include <QTransform>
#include <cmath>

namespace klueng::gui {

namespace {
// Both halves: the upper one as given, its mirror about the centre line.
QPainterPath mirrored(const QPainterPath& upper) {
  QPainterPath both = upper;
  both.addPath(QTransform::fromScale(1.0, -1.0).map(upper));
  return both;
}
}  // namespace

PartOverlayItem::PartOverlayItem() { setZValue(5); }

void PartOverlayItem::setOverlay(const PartOverlay& overlay) {
  prepareGeometryChange();
  overlay_ = overlay;
  QRectF r = mirrored(overlay_.otherOutline).boundingRect().united(mirrored(overlay_.highlight).boundingRect());
  for (const PartOverlay::Band& b : overlay_.bands) {
    const double top = std::max(b.r0, b.r1);
    r = r.united(QRectF(b.zLeft, -top, b.zRight - b.zLeft, 2.0 * top));
  }
  bounds_ = r.adjusted(-2, -2, 2, 2);
  update();
}

void PartOverlayItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  painter->save();
  painter->setRenderHint(QPainter::Antialiasing);
  for (const PartOverlay::Band& b : overlay_.bands) {
    QColor fill = b.colour;
    fill.setAlpha(170);
    const double lo = std::min(b.r0, b.r1), hi = std::max(b.r0, b.r1);
    // At least a few pixels wide and tall, so a 0.05 mm gouge is seen at any zoom.
    const double px = 1.0 / std::max(1e-6, painter->worldTransform().m11());
    const double w = std::max(b.zRight - b.zLeft, 4.0 * px), h = std::max(hi - lo, 4.0 * px);
    const double z = (b.zLeft + b.zRight - w) / 2.0;
    painter->setPen(QPen(b.colour.darker(150), 0));
    painter->setBrush(fill);
    painter->drawRect(QRectF(z, -lo - h, w, h));
    painter->drawRect(QRectF(z, lo, w, h));
  }
  painter->setBrush(Qt::NoBrush);
  if (!overlay_.otherOutline.isEmpty()) {
    QPen pen(QColor(200, 0, 160), 2);
    pen.setCosmetic(true);
    pen.setStyle(Qt::DashLine);
    painter->setPen(pen);
    painter->drawPath(mirrored(overlay_.otherOutline));
  }
  if (!overlay_.highlight.isEmpty()) {
    QPen pen(QColor(0, 110, 230), 4);
    pen.setCosmetic(true);
    pen.setCapStyle(Qt::RoundCap);
    painter->setPen(pen);
    painter->drawPath(mirrored(overlay_.highlight));
  }
  painter->restore();
}

MeasureItem::MeasureItem() { setZValue(6); }

void MeasureItem::setPoints(const QPointF& a, const std::optional<QPointF>& b) {
  prepareGeometryChange();
  a_ = a;
  b_ = b;
  update();
}

QString MeasureItem::reading(const QPointF& a, const QPointF& b, const core::UnitFormat& units) {
  // Scene y is -radius: ΔØ is twice the radial difference.
  const double dz = b.x() - a.x(), dr = -(b.y() - a.y());
  const double angle = std::atan2(dr, dz) * 180.0 / M_PI;
  const auto length = [&units](double mm) { return QString::fromStdString(units.position(mm)); };
  return QStringLiteral("ΔZ %1   ΔØ %2   d %3   ∠ %4°")
      .arg(length(dz), length(2.0 * dr), length(std::hypot(dz, dr)))
      .arg(angle, 0, 'f', 2);
}

QRectF MeasureItem::boundingRect() const {
  const QPointF b = b_.value_or(a_);
  return QRectF(a_, b).normalized().adjusted(-200, -200, 200, 200);
}

void MeasureItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  painter->save();
  painter->setRenderHint(QPainter::Antialiasing);
  QPen pen(QColor(0, 140, 60), 2);
  pen.setCosmetic(true);
  painter->setPen(pen);
  const double px = 1.0 / std::max(1e-6, painter->worldTransform().m11());
  for (const QPointF& p : {a_, b_.value_or(a_)}) painter->drawEllipse(p, 3.0 * px, 3.0 * px);
  if (b_) painter->drawLine(a_, *b_);
  painter->restore();
}

QPointF snapToStock(const core::cut::Stock& stock, const QPointF& scenePos, double tolerance) {
  const double z = scenePos.x(), r = std::abs(scenePos.y());
  const double side = scenePos.y() < 0.0 ? -1.0 : 1.0;
  const int i = stock.columnAt(z);
  if (i < 0) return scenePos;
  QPointF out = scenePos;
  // Radially: the outside, or the bore, nearest.
  double best = tolerance;
  for (const double edge : {stock.outerRadius(i), stock.innerRadius(i)}) {
    if (edge > 0.0 && std::abs(edge - r) <= best) {
      best = std::abs(edge - r);
      out.setY(side * edge);
    }
  }
  // Along Z: the nearest step of the outside within reach.
  const int reach = static_cast<int>(std::ceil(tolerance / stock.resolution()));
  double bestZ = tolerance;
  for (int k = std::max(0, i - reach); k < std::min(stock.columnCount() - 1, i + reach); ++k) {
    if (std::abs(stock.outerRadius(k + 1) - stock.outerRadius(k)) < 0.1) continue;
    const double edgeZ = stock.zRight(k);
    const double lo = std::min(stock.outerRadius(k), stock.outerRadius(k + 1));
    const double hi = std::max(stock.outerRadius(k), stock.outerRadius(k + 1));
    if (r < lo - tolerance || r > hi + tolerance || std::abs(edgeZ - z) > bestZ) continue;
    bestZ = std::abs(edgeZ - z);
    out.setX(edgeZ);
  }
  return out;
}

}  // namespace klueng::gui

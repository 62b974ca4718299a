#include "gui/output_items.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>

namespace klueng::gui {

namespace {
QRectF mirrored(const QRectF& r) { return QRectF(r.left(), -r.bottom(), r.width(), r.height()); }
}  // namespace

QRectF segmentRect(const core::Segment& s) {
  QRectF r = QRectF(render::toScene(s.start), render::toScene(s.end)).normalized();
  if (s.isArc()) {
    // Conservative: the whole circle (cheap, and arcs are short).
    const double radius = s.radius();
    r = r.united(QRectF(render::toScene(s.centre) - QPointF(radius, radius), QSizeF(2 * radius, 2 * radius)));
  }
  return r.adjusted(-0.5, -0.5, 0.5, 0.5);
}

// ---------------------------------------------------------------- StockItem

StockItem::StockItem() { setZValue(0); }

void StockItem::setShape(const render::StockShape& shape) {
  const QRectF b = shape.boundingRect().adjusted(-12, -1, 12, 1);  // + the centre line overhang
  if (b != bounds_) {
    prepareGeometryChange();
    bounds_ = b;
  }
  shape_ = shape;
}

void StockItem::updateRegion(const QRectF& upperRect) {
  update(upperRect);
  update(mirrored(upperRect));
}

void StockItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  render::paintStock(*painter, shape_);
}

// ---------------------------------------------------------------- ChuckItem

void ChuckItem::setChuck(const core::cut::Chuck& chuck) {
  prepareGeometryChange();
  chuck_ = chuck;
}

QRectF ChuckItem::boundingRect() const { return render::chuckRect(chuck_).adjusted(-1, -1, 1, 1); }

void ChuckItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  render::paintChuck(*painter, chuck_);
}

// ---------------------------------------------------------------- ToolItem

ToolItem::ToolItem() { setZValue(3); }

void ToolItem::setSprite(const render::ToolSprite& sprite, const void* identity) {
  prepareGeometryChange();
  sprite_ = sprite;
  identity_ = identity;
}

QRectF ToolItem::boundingRect() const {
  return sprite_.isNull() ? QRectF() : sprite_.sceneRect(QPointF(0, 0)).adjusted(-0.5, -0.5, 0.5, 0.5);
}

void ToolItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  sprite_.paint(*painter, QPointF(0, 0));
}

// ---------------------------------------------------------------- MarkerItem

MarkerItem::MarkerItem() {
  setFlag(ItemIgnoresTransformations);
  setZValue(4);
}

void MarkerItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  render::paintMarker(*painter, QPointF(0, 0), 5.0, 1.5);  // device pixels: the item ignores the zoom
}

// ---------------------------------------------------------------- TrailItem

void TrailItem::append(const core::machine::Move& move, bool repaint) {
  trail_.append(move);
  ++moves_;
  if (repaint && move.kind != core::machine::MoveKind::Dwell) update(segmentRect(move.path));
}

void TrailItem::setPartial(const core::machine::Move* move, double fraction) {
  const QRectF old = partialFeed_.boundingRect().united(partialRapid_.boundingRect());
  partialFeed_ = QPainterPath();
  partialRapid_ = QPainterPath();
  if (move && move->kind != core::machine::MoveKind::Dwell && fraction > 0) {
    QPainterPath& path = move->kind == core::machine::MoveKind::Rapid ? partialRapid_ : partialFeed_;
    render::appendSegment(path, render::partialSegment(move->path, fraction), true);
  }
  const QRectF now = partialFeed_.boundingRect().united(partialRapid_.boundingRect());
  if (!old.isNull()) update(old.adjusted(-0.5, -0.5, 0.5, 0.5));
  if (!now.isNull()) update(now.adjusted(-0.5, -0.5, 0.5, 0.5));
}

void TrailItem::clear() {
  trail_.clear();
  partialFeed_ = partialRapid_ = QPainterPath();
  moves_ = 0;
  update();
}

void TrailItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  trail_.paint(*painter);
  render::PathTrail::paintPaths(*painter, partialFeed_, partialRapid_);
}

}  // namespace klueng::gui

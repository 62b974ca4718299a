#pragma once
// Thin scene items of the output screen; the drawing itself is render/'s code.
// Scene units are millimetres, scene y = -X radius (render::toScene).
#include <QGraphicsItem>
#include <QPainterPath>
#include <vector>

#include "klueng/core/machine/timeline.h"
#include "render/lathe_painters.h"
#include "render/path_painter.h"
#include "render/tool_sprite.h"

namespace klueng::gui {

// The stock section, both halves. Its bounding rect is the blank's, fixed, so a
// cut only repaints the region the tool swept (updateRegion()).
// Scene rectangle covering a segment (arcs: their whole circle), with half a mm to spare.
QRectF segmentRect(const core::Segment& segment);

class StockItem : public QGraphicsItem {
 public:
  StockItem();
  void setShape(const render::StockShape& shape);
  const render::StockShape& stockShape() const { return shape_; }
  // Repaints a scene rect of the upper half and its mirror image.
  void updateRegion(const QRectF& upperRect);
  QRectF boundingRect() const override { return bounds_; }
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

 private:
  render::StockShape shape_;
  QRectF bounds_;
};

class ChuckItem : public QGraphicsItem {
 public:
  void setChuck(const core::cut::Chuck& chuck);
  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

 private:
  core::cut::Chuck chuck_;
};

// The tool bitmap; the item's position is the controlled point.
class ToolItem : public QGraphicsItem {
 public:
  ToolItem();
  void setSprite(const render::ToolSprite& sprite, const void* identity);
  const void* identity() const { return identity_; }
  const render::ToolSprite& sprite() const { return sprite_; }
  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

 private:
  render::ToolSprite sprite_;
  const void* identity_ = nullptr;
};

// The controlled-point marker: a small cross that keeps its pixel size at any zoom.
class MarkerItem : public QGraphicsItem {
 public:
  MarkerItem();
  QRectF boundingRect() const override { return {-6, -6, 12, 12}; }
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;
};

// One piece of the tool path trail. Completed chunks never change; the live one
// grows and repaints only what was added (its bounding rect is fixed).
class TrailItem : public QGraphicsItem {
 public:
  explicit TrailItem(const QRectF& bounds) : bounds_(bounds) {}
  // repaint = false when many moves come at once (the caller repaints the item once).
  void append(const core::machine::Move& move, bool repaint = true);
  void setPartial(const core::machine::Move* move, double fraction);
  int moveCount() const { return moves_; }
  void clear();
  QRectF boundingRect() const override { return bounds_; }
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

 private:
  render::PathTrail trail_;
  QPainterPath partialFeed_;
  QPainterPath partialRapid_;
  QRectF bounds_;
  int moves_ = 0;
};

}  // namespace klueng::gui

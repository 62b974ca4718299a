#pragma once
// The operator panel's picture, drawn by the screen's painters (render/) from the panel's Control.
#include <QPainter>
#include <QWidget>
#include <map>

#include "klueng/core/control/control.h"
#include "klueng/core/cut/tool_shape.h"
#include "render/lathe_painters.h"
#include "render/tool_sprite.h"

namespace klueng::gui {

// The bar at the tool: the panel's own cut (the run's painters), the chuck and
// the tool at the turret, whole or in close-up (a handwheel click shows).
class TouchView : public QWidget {
 public:
  explicit TouchView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("operatorTouchView"));
    setMinimumHeight(90);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
  }
  void setControl(const core::control::Control* c) {
    control_ = c;
    sprites_.clear();
    movesSeen_ = static_cast<std::size_t>(-1);
    update();
  }
  int zoom = 0;  // 0 = the bar and the tool, 1 = 40 mm around the tip, 2 = 8 mm (a handwheel click shows)
  QSize sizeHint() const override { return {320, 110}; }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    p.fillRect(rect(), render::palette().background);
    if (!control_) return;
    const core::control::AxisValues tip = control_->tip();
    const QPointF tipScene = render::toScene(tip.z, tip.x / 2.0);
    const core::cut::Chuck& chuck = control_->chuck();
    QRectF world;
    if (zoom > 0) {
      const double w = zoom == 1 ? 40.0 : 8.0;
      world = QRectF(tipScene - QPointF(w / 2, w / 4), QSizeF(w, w / 2));
    } else {
      world = QRectF(QPointF(chuck.bodyZMin(), -(chuck.bodyXMax() + 5.0)), QPointF(15.0, 5.0));
      world = world.united(QRectF(tipScene - QPointF(15.0, 15.0), QSizeF(30.0, 30.0)));
    }
    const double s = std::min(width() / world.width(), height() / world.height());
    p.setRenderHint(QPainter::Antialiasing);
    p.translate(width() / 2.0, height() / 2.0);
    p.scale(s, s);
    p.translate(-world.center());
    if (movesSeen_ != control_->moves().moves.size()) {
      shape_ = render::stockShapeFromStock(control_->stock());
      movesSeen_ = control_->moves().moves.size();
    }
    render::paintChuck(p, chuck);
    render::paintStock(p, shape_);
    const int station = control_->station();
    auto it = sprites_.find(station);
    if (it == sprites_.end()) {
      core::cut::ToolLibrary lib(control_->setup().tools, control_->setup().offsets);
      const core::cut::ToolShape* shape = lib.get(station, station);
      it = sprites_.emplace(station, shape ? render::ToolSprite::fromShape(*shape) : render::ToolSprite()).first;
    }
    if (!it->second.isNull()) it->second.paint(p, tipScene);
    render::paintMarker(p, tipScene, 6.0 / s, 1.5 / s);
    p.resetTransform();
    p.setPen(palette().color(QPalette::WindowText));
    // A scale bar: how far a click goes.
    const double barMm = zoom == 2 ? 1.0 : 10.0;
    const double barPx = barMm * s;
    p.drawLine(QPointF(8, height() - 8), QPointF(8 + barPx, height() - 8));
    const QString label = QStringLiteral("%1 mm").arg(barMm);
    const QRectF box(10 + barPx, height() - 4 - fontMetrics().ascent(), fontMetrics().horizontalAdvance(label) + 4,
                     fontMetrics().height());
    p.fillRect(box, QColor(255, 255, 255, 200));
    p.drawText(QPointF(12 + barPx, height() - 4), label);
  }

 private:
  const core::control::Control* control_ = nullptr;
  render::StockShape shape_;
  std::size_t movesSeen_ = static_cast<std::size_t>(-1);
  std::map<int, render::ToolSprite> sprites_;
};

}  // namespace klueng::gui

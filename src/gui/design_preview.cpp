#include "gui/design_preview.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>

#include "render/lathe_painters.h"

namespace klueng::gui {

DesignPreview::DesignPreview(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("designPreview"));
  setAttribute(Qt::WA_OpaquePaintEvent);
}

void DesignPreview::show(const core::design::PartDesign& design, std::shared_ptr<const core::cut::Stock> cut) {
  design_ = design;
  outline_ = core::design::partOutline(design);
  cut_ = std::move(cut);
  update();
}

void DesignPreview::setHighlight(double zRight, double zLeft) {
  highlightRight_ = zRight;
  highlightLeft_ = zLeft;
  update();
}

void DesignPreview::setMessage(const QString& text) {
  message_ = text;
  update();
}

void DesignPreview::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  p.fillRect(rect(), render::palette().background);
  const double length = std::max(design_.stockLength, design_.length());
  const double radius = std::max(design_.stockDiameter, 1.0) / 2.0;
  if (length <= 0.0) return;
  // Scene units: (z, -radius), both halves, a margin around; the bar's right part fills the width.
  const double shown = std::min(length, design_.length() + std::max(10.0, 0.2 * design_.length()));
  const QRectF scene(-shown - 3.0, -radius - 4.0, shown + 9.0, 2.0 * radius + 8.0);
  const double scale = std::min((width() - 16) / scene.width(), (height() - 16) / scene.height());
  if (scale <= 0.0) return;
  p.save();
  p.translate(width() / 2.0, height() / 2.0);
  p.scale(scale, scale);
  p.translate(-scene.center());
  p.setClipRect(scene);
  if (highlightLeft_ < highlightRight_) {
    const QRectF band(highlightLeft_, -radius - 4.0, highlightRight_ - highlightLeft_, 2.0 * radius + 8.0);
    p.fillRect(band, QColor(255, 214, 140, 120));
  }
  const render::StockShape shape =
      cut_ ? render::stockShapeFromStock(*cut_)
           : render::stockShapeFromBlank(design_.stockDiameter, design_.stockLength, design_.stockBore);
  render::paintStock(p, shape, true);
  render::paintCentreLine(p, -shown - 3.0, 6.0);
  // The drawing: blue over the upper half, thin over the lower.
  const auto path = [](const std::vector<core::Vec2>& points, double sign) {
    QPainterPath path;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const QPointF at(points[k].x(), -sign * points[k].y());
      if (k == 0)
        path.moveTo(at);
      else
        path.lineTo(at);
    }
    return path;
  };
  for (const double sign : {1.0, -1.0}) {
    QPen pen(QColor(0, 90, 220), sign > 0 ? 2.0 : 1.0);
    pen.setCosmetic(true);
    p.setPen(pen);
    p.setBrush(Qt::NoBrush);
    p.drawPath(path(outline_.outside, sign));
    if (!outline_.bore.empty()) p.drawPath(path(outline_.bore, sign));
    // The left end: down from the outside to the bore (or the axis).
    if (!outline_.outside.empty()) {
      const core::Vec2 end = outline_.outside.back();
      const double low = outline_.bore.empty() ? 0.0 : outline_.bore.back().y();
      p.drawLine(QPointF(end.x(), -sign * end.y()), QPointF(end.x(), -sign * low));
      const double face = outline_.bore.empty() ? 0.0 : outline_.bore.front().y();
      p.drawLine(QPointF(0.0, -sign * outline_.outside.front().y()), QPointF(0.0, -sign * face));
    }
  }
  // Threads: short strokes at the pitch over the thread's length.
  QPen thread(QColor(0, 90, 220), 1.0);
  thread.setCosmetic(true);
  p.setPen(thread);
  for (const core::design::ThreadMark& t : outline_.threads)
    for (double z = t.zRight; z > t.zLeft + 1e-9 && t.pitch > 0.05; z -= t.pitch)
      for (const double sign : {1.0, -1.0})
        p.drawLine(QPointF(z, -sign * t.major), QPointF(z - t.pitch / 2.0, -sign * t.minor));
  p.restore();
  if (!message_.isEmpty()) {
    p.setPen(QColor(150, 30, 30));
    p.drawText(rect().adjusted(10, 8, -10, -8), Qt::AlignTop | Qt::AlignLeft | Qt::TextWordWrap, message_);
  }
}

}  // namespace klueng::gui

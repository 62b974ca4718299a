#include "render/tool_sprite.h"

#include <QPainterPath>
#include <QPen>
#include <cmath>

#include "klueng/core/comp/nose_comp.h"
#include "klueng/core/geometry.h"
#include "render/lathe_painters.h"

namespace klueng::render {

namespace {
constexpr std::uint32_t kHolder = 0x000000;
constexpr std::uint32_t kEmpty = 0xFFFFFF;
}  // namespace

QPointF controlledPointForTip(const QRect& box, int tip) {
  if (box.isEmpty()) return {};
  const core::Vec2 dir = core::comp::tipVector(tip);  // (dz, dx), +X up
  // Pixel edges: left() .. right()+1 across, top() .. bottom()+1 down (image y grows downward).
  const double left = box.left();
  const double right = box.right() + 1.0;
  const double top = box.top();
  const double bottom = box.bottom() + 1.0;
  const double x = dir.x() < 0 ? left : dir.x() > 0 ? right : (left + right) / 2.0;
  const double y = dir.y() > 0 ? top : dir.y() < 0 ? bottom : (top + bottom) / 2.0;
  return {x, y};
}

ToolSprite ToolSprite::fromImage(const core::io::RgbImage& rgb, int tip, double pixelsPerMm) {
  ToolSprite s;
  s.tip_ = tip;
  s.ppm_ = pixelsPerMm > 0.0 ? pixelsPerMm : seedPixelsPerMm;
  if (rgb.width <= 0 || rgb.height <= 0) return s;
  s.image_ = QImage(rgb.width, rgb.height, QImage::Format_ARGB32);
  int minX = rgb.width, minY = rgb.height, maxX = -1, maxY = -1;
  for (int y = 0; y < rgb.height; ++y) {
    auto* line = reinterpret_cast<QRgb*>(s.image_.scanLine(y));
    for (int x = 0; x < rgb.width; ++x) {
      const std::uint32_t c = rgb.at(x, y) & 0xFFFFFF;
      if (c == kEmpty) {
        line[x] = qRgba(0, 0, 0, 0);
        continue;
      }
      line[x] = qRgb(static_cast<int>((c >> 16) & 0xFF), static_cast<int>((c >> 8) & 0xFF), static_cast<int>(c & 0xFF));
      if (c != kHolder) {
        minX = std::min(minX, x);
        maxX = std::max(maxX, x);
        minY = std::min(minY, y);
        maxY = std::max(maxY, y);
      }
    }
  }
  if (maxX >= 0) s.edgeBox_ = QRect(QPoint(minX, minY), QPoint(maxX, maxY));
  s.controlPx_ = controlledPointForTip(s.edgeBox_, tip);
  return s;
}

ToolSprite ToolSprite::fromShape(const core::cut::ToolShape& shape) {
  ToolSprite s = fromImage(shape.image, shape.tip, shape.pixelsPerMm);
  s.controlPx_ = QPointF(shape.controlPixelX, shape.controlPixelY);
  return s;
}

QRectF ToolSprite::sceneRect(const QPointF& cp) const {
  const QPointF topLeft = cp - controlPx_ / ppm_;
  return {topLeft, QSizeF(image_.width() / ppm_, image_.height() / ppm_)};
}

void ToolSprite::paint(QPainter& painter, const QPointF& cp) const {
  if (image_.isNull()) return;
  painter.save();
  painter.setRenderHint(QPainter::SmoothPixmapTransform, false);
  painter.drawImage(sceneRect(cp), image_);
  painter.restore();
}

QImage tipPicture(int tip, int sizePx) {
  QImage img(sizePx, sizePx, QImage::Format_ARGB32_Premultiplied);
  img.fill(Qt::transparent);
  QPainter p(&img);
  p.setRenderHint(QPainter::Antialiasing);
  const double c = sizePx / 2.0;
  const double r = sizePx * 0.22;
  // The square of the imaginary tip grid around the nose, the nose circle, the tip point.
  p.setPen(QPen(QColor(150, 150, 150), 1.0, Qt::DotLine));
  p.drawRect(QRectF(c - r, c - r, 2 * r, 2 * r));
  p.setPen(QPen(QColor(40, 40, 40), 1.2));
  p.setBrush(QColor(200, 210, 225));
  p.drawEllipse(QPointF(c, c), r, r);
  const core::Vec2 dir = core::comp::tipVector(tip);
  const QPointF tipPt(c + dir.x() * r, c - dir.y() * r);
  p.setPen(QPen(palette().controlledPoint, 1.6));
  if (dir.norm() > 0) p.drawLine(QPointF(c, c), tipPt);
  const double k = std::max(2.0, sizePx * 0.08);
  p.drawLine(tipPt - QPointF(k, k), tipPt + QPointF(k, k));
  p.drawLine(tipPt - QPointF(k, -k), tipPt + QPointF(k, -k));
  return img;
}

}  // namespace klueng::render

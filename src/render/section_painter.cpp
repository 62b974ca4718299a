#include "render/section_painter.h"

#include <QBuffer>
#include <QPainter>
#include <algorithm>
#include <cmath>

#include "render/lathe_painters.h"
#include "render/path_painter.h"
#include "render/tool_sprite.h"

namespace klueng::render {

QImage renderSectionPicture(const SectionPicture& picture) {
  if (!picture.stock || picture.maxWidth < 1 || picture.maxHeight < 1) return {};
  const core::cut::Stock& stock = *picture.stock;
  const StockShape shape = stockShapeFromStock(stock);
  PathTrail trail;
  if (picture.path)
    for (const core::machine::Move& m : picture.path->moves) {
      if (m.tStart >= picture.pathUntil) break;
      trail.append(m);
    }
  ToolSprite sprite = picture.tool ? ToolSprite::fromShape(*picture.tool) : ToolSprite();
  const QPointF toolAt = toScene(picture.toolPosition);

  // The bar (both halves), the chuck and the tool, with a 3 mm margin; the path is
  // clipped to them (a rapid from the reference point would shrink the part to a dot).
  QRectF scene = shape.boundingRect().united(stockShapeFromBlank(stock.diameter(), stock.length()).boundingRect());
  if (picture.chuck) scene = scene.united(chuckRect(*picture.chuck));
  if (!sprite.isNull()) scene = scene.united(sprite.sceneRect(toolAt));
  scene = scene.adjusted(-3, -3, 3, 3);
  const double scale =
      std::clamp(std::min(picture.maxWidth / scene.width(), picture.maxHeight / scene.height()), 0.05, 200.0);
  const QSize size(std::max(1, static_cast<int>(std::ceil(scene.width() * scale))),
                   std::max(1, static_cast<int>(std::ceil(scene.height() * scale))));
  QImage image(size, QImage::Format_RGB32);
  image.fill(palette().background);
  QPainter p(&image);
  p.setRenderHint(QPainter::Antialiasing);
  p.scale(scale, scale);
  p.translate(-scene.topLeft());
  paintStock(p, shape);
  if (picture.chuck) paintChuck(p, *picture.chuck);
  paintCentreLine(p, scene.left(), scene.right());
  trail.paint(p);
  if (!sprite.isNull()) sprite.paint(p, toolAt);
  paintMarker(p, toolAt, 5.0 / scale, 1.5 / scale);  // the screen's 5-pixel cross
  p.end();
  return image;
}

QByteArray sectionPicturePng(const SectionPicture& picture) {
  const QImage image = renderSectionPicture(picture);
  if (image.isNull()) return {};
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  if (!image.save(&buffer, "PNG")) return {};
  return bytes;
}

}  // namespace klueng::render

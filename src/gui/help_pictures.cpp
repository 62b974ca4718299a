#include "gui/help_pictures.h"

#include <QCoreApplication>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>

#include "klueng/core/comp/nose_comp.h"
#include "klueng/core/geometry.h"
#include "klueng/core/help/help.h"

namespace klueng::gui {

QImage tipNumbersPicture() {
  const int cell = 90, size = 3 * cell;
  QImage img(size + 20, size + 44, QImage::Format_RGB32);
  img.fill(Qt::white);
  QPainter p(&img);
  p.setRenderHint(QPainter::Antialiasing);
  const double r = 18.0;
  for (int tip = 0; tip <= 8; ++tip) {
    const core::Vec2 v = core::comp::tipVector(tip);  // (dz, dx): +Z right, +X up
    const QPointF centre(10 + cell * (1.5 + v.x()), 10 + cell * (1.5 - v.y()));
    p.setPen(QPen(QColor(90, 90, 90), 1.5));
    p.setBrush(QColor(235, 235, 235));
    p.drawEllipse(centre, r, r);
    // The imaginary tip: where the tangents of the nose along X and Z meet.
    const QPointF tipPoint(centre.x() + r * v.x(), centre.y() - r * v.y());
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(200, 0, 0));
    p.drawEllipse(tipPoint, 4.0, 4.0);
    p.setPen(Qt::black);
    p.setFont(QFont(QStringLiteral("Loma"), 11, QFont::Bold));
    const QString label = tip == 0 ? QStringLiteral("0, 9") : QString::number(tip);
    p.drawText(QRectF(centre.x() - cell / 2.0, centre.y() + r + 2, cell, 20), Qt::AlignHCenter | Qt::AlignTop, label);
  }
  p.setFont(QFont(QStringLiteral("Loma"), 10));
  p.drawText(QRectF(10, size + 14, size, 24), Qt::AlignLeft | Qt::AlignVCenter,
             QCoreApplication::translate("klueng::gui::HelpContents", "+X up, +Z right; red dot = imaginary tip"));
  return img;
}

QImage examplePathPicture(char letter, int number, core::gcode::Dialect dialect) {
  std::vector<bool> rapid;
  const std::vector<core::Segment> path = core::machine::workedExamplePath(letter, number, dialect, &rapid);
  // The window: the bar's right half (Z -60..8, radius 0..30), 7 px per mm.
  const double zMin = -60.0, zMax = 8.0, rMax = 30.0, scale = 7.0;
  QImage img(static_cast<int>((zMax - zMin) * scale), static_cast<int>(rMax * scale) + 10, QImage::Format_RGB32);
  img.fill(Qt::white);
  QPainter p(&img);
  p.setRenderHint(QPainter::Antialiasing);
  auto at = [&](const core::Vec2& v) {
    return QPointF((core::zOf(v) - zMin) * scale, (rMax - core::xOf(v)) * scale + 5);
  };
  p.setPen(Qt::NoPen);
  p.setBrush(QColor(215, 222, 232));
  p.drawRect(QRectF(at(core::zx(-100.0, 25.0)), at(core::zx(0.0, 0.0))));  // the bar, Ø50
  p.setPen(QPen(QColor(120, 120, 120), 1, Qt::DashDotLine));
  p.drawLine(at(core::zx(zMin, 0.0)), at(core::zx(zMax, 0.0)));  // centre line
  for (std::size_t i = 0; i < path.size(); ++i) {
    p.setPen(rapid[i] ? QPen(QColor(40, 90, 200), 1, Qt::DashLine) : QPen(QColor(200, 0, 0), 1.6));
    QPainterPath line(at(path[i].start));
    for (int k = 1; k <= 16; ++k) line.lineTo(at(path[i].pointAt(k / 16.0)));
    p.drawPath(line);
  }
  return img;
}

}  // namespace klueng::gui

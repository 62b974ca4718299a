#include "gui/output_ruler.h"

#include <QGraphicsView>
#include <QPainter>
#include <cmath>

namespace klueng::gui {

OutputRuler::OutputRuler(Axis axis, QGraphicsView* view, QWidget* parent) : QWidget(parent), axis_(axis), view_(view) {
  QFont f = font();
  f.setPointSizeF(std::max(6.5, f.pointSizeF() * 0.8));
  setFont(f);
  setAttribute(Qt::WA_OpaquePaintEvent);
}

double OutputRuler::tickStep(double pixelsPerMm, double minPixels) {
  const double raw = minPixels / std::max(pixelsPerMm, 1e-9);
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= raw) return m * decade;
  return 10.0 * decade;
}

void OutputRuler::setUnits(const core::UnitFormat& units) {
  if (units_ == units) return;
  units_ = units;
  update();
}

std::vector<OutputRuler::Tick> OutputRuler::ticks() const {
  std::vector<Tick> out;
  const QTransform t = view_->viewportTransform();
  const double scale = axis_ == Axis::Z ? std::abs(t.m11()) : std::abs(t.m22());
  if (scale <= 0) return out;
  // X is shown as a diameter: one scene mm of radius is 2 mm of X. In inches a
  // unit is 25.4 scene mm: ticks fall on round inches, not on converted mm.
  const double mmPerUnit = units_.toMm(1.0);
  const double unitPixels = (axis_ == Axis::Z ? scale : scale / 2.0) * mmPerUnit;
  const double major = tickStep(unitPixels, axis_ == Axis::Z ? 70.0 : 40.0);
  const double minor = major / (std::fmod(major / std::pow(10.0, std::floor(std::log10(major))), 2.0) == 0 ? 4.0 : 5.0);
  const int length = axis_ == Axis::Z ? width() : height();
  // Ruler pixel p -> value: Z = scene x; X diameter = -2 * scene y.
  auto valueAt = [&](double p) {
    const QPointF scene = t.inverted().map(axis_ == Axis::Z ? QPointF(p, 0) : QPointF(0, p));
    return (axis_ == Axis::Z ? scene.x() : -2.0 * scene.y()) / mmPerUnit;
  };
  auto pixelOf = [&](double v) {
    const double mm = v * mmPerUnit;
    const QPointF vp = t.map(axis_ == Axis::Z ? QPointF(mm, 0) : QPointF(0, -mm / 2.0));
    return axis_ == Axis::Z ? vp.x() : vp.y();
  };
  double a = valueAt(0), b = valueAt(length);
  if (a > b) std::swap(a, b);
  for (double v = std::floor(a / minor) * minor; v <= b + minor * 0.5; v += minor) {
    const bool isMajor = std::abs(std::remainder(v, major)) < minor * 0.01;
    out.push_back({pixelOf(v), std::abs(v) < minor * 1e-6 ? 0.0 : v, isMajor});
  }
  return out;
}

QStringList OutputRuler::visibleLabels() const {
  QStringList labels;
  for (const Tick& t : ticks())
    if (t.major) labels << QString::number(t.value, 'g', 6);
  return labels;
}

void OutputRuler::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), QColor(236, 236, 232));
  p.setPen(QColor(120, 120, 120));
  if (axis_ == Axis::Z)
    p.drawLine(0, height() - 1, width(), height() - 1);
  else
    p.drawLine(width() - 1, 0, width() - 1, height());
  p.setPen(QColor(40, 40, 40));
  const QFontMetrics fm = fontMetrics();
  for (const Tick& t : ticks()) {
    const int len = t.major ? 9 : 4;
    if (axis_ == Axis::Z) {
      p.drawLine(QPointF(t.pos, height() - len), QPointF(t.pos, height()));
      if (t.major) p.drawText(QPointF(t.pos + 2, fm.ascent() + 1), QString::number(t.value, 'g', 6));
    } else {
      p.drawLine(QPointF(width() - len, t.pos), QPointF(width(), t.pos));
      if (t.major) {
        p.save();
        p.translate(fm.ascent() + 1, t.pos - 2);
        p.rotate(-90);
        p.drawText(QPointF(0, 0), QString::number(t.value, 'g', 6));
        p.restore();
      }
    }
  }
}

}  // namespace klueng::gui

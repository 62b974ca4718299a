#pragma once
// A ruler along the output view's top (Z) or left edge (X, diameter), in mm or
// inches (View ▸ Units shown), following the view's zoom and pan.
#include <QWidget>

#include "klueng/core/units.h"

class QGraphicsView;

namespace klueng::gui {

class OutputRuler : public QWidget {
  Q_OBJECT
 public:
  enum class Axis { Z, X };
  OutputRuler(Axis axis, QGraphicsView* view, QWidget* parent);
  // The ticks' step in mm for a zoom (1, 2, 5 x 10^n, at least minPixels apart).
  static double tickStep(double pixelsPerMm, double minPixels);
  // Tick labels currently drawn (tests: the rulers follow zoom and pan).
  QStringList visibleLabels() const;
  // Ticks at round numbers of this unit (the scene stays in mm).
  void setUnits(const core::UnitFormat& units);

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  struct Tick {
    double pos;    // pixels along the ruler
    double value;  // Z or diameter X, in units_
    bool major;
  };
  std::vector<Tick> ticks() const;
  Axis axis_;
  core::UnitFormat units_;
  QGraphicsView* view_;
};

}  // namespace klueng::gui

#pragma once
// A ruler along the output view's top (Z, mm) or left edge (X, diameter mm),
// following the view's zoom and pan.
#include <QWidget>

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

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  struct Tick {
    double pos;   // pixels along the ruler
    double value; // mm (Z) or diameter (X)
    bool major;
  };
  std::vector<Tick> ticks() const;
  Axis axis_;
  QGraphicsView* view_;
};

}  // namespace klueng::gui

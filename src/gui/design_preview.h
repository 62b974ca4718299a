#pragma once
// The part designer's drawing preview (issue 14): the part as the generated
// program cut it (the section, both halves, as the output screen draws stock),
// the drawing's outline over its upper half in blue, the bar's outline, the
// centre line, and the selected feature's Z band.
#include <QWidget>
#include <memory>

#include "klueng/core/cut/stock.h"
#include "klueng/core/design/part_design.h"

namespace klueng::gui {

class DesignPreview : public QWidget {
  Q_OBJECT
 public:
  explicit DesignPreview(QWidget* parent = nullptr);
  // The drawing and the bar; `cut` may be null (nothing cut: the drawing alone).
  void show(const core::design::PartDesign& design, std::shared_ptr<const core::cut::Stock> cut);
  void setHighlight(double zRight, double zLeft);  // zRight < zLeft: none
  void setMessage(const QString& text);            // over the picture when nothing was cut
  QSize sizeHint() const override { return {560, 300}; }
  QSize minimumSizeHint() const override { return {280, 160}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  core::design::PartDesign design_;
  core::design::PartOutline outline_;
  std::shared_ptr<const core::cut::Stock> cut_;
  double highlightRight_ = 0.0, highlightLeft_ = 1.0;
  QString message_;
};

}  // namespace klueng::gui

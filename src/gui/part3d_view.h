#pragma once
// The 3D view dock (issue 10, item 5): the stock as it is being cut, shaded,
// a quarter cut away (render/part3d_painter). Drag = orbit, right or middle
// drag = pan, wheel = zoom, double-click = the starting view. It follows the
// run controller like the 2-D output screen, beside it or tabbed with it.
#include <QDockWidget>
#include <QPointer>
#include <QWidget>
#include <memory>

#include "render/part3d_painter.h"

namespace klueng::gui {

class RunController;

class Part3DWidget : public QWidget {
  Q_OBJECT
 public:
  explicit Part3DWidget(QWidget* parent = nullptr);
  void setRunController(RunController* controller);
  // Shows this part instead of a run's (the part designer's cut part).
  void setStock(std::shared_ptr<const core::cut::Stock> stock);
  render::Camera3D& camera() { return camera_; }
  int lastQuadCount() const { return quads_; }
  qint64 paintCount() const { return paints_; }
  QSize sizeHint() const override { return {420, 300}; }

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  QPointer<RunController> controller_;
  render::Camera3D camera_;
  QPoint last_;
  int quads_ = 0;
  qint64 paints_ = 0;
  std::shared_ptr<const core::cut::Stock> shown_;
  std::unique_ptr<core::cut::Stock> blank_;  // before the first run: the bar from the job header
  double blankKey_ = -1.0;
};

class Part3DDock : public QDockWidget {
  Q_OBJECT
 public:
  explicit Part3DDock(QWidget* parent = nullptr);
  Part3DWidget* view() const { return view_; }
  void retranslateUi();

 protected:
  void changeEvent(QEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  Part3DWidget* view_ = nullptr;
};

}  // namespace klueng::gui

#include "gui/part3d_view.h"

#include <QEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <cmath>

#include "gui/run_controller.h"
#include "render/lathe_painters.h"

namespace klueng::gui {

namespace {

using core::Vec2;

// The tool's shapes in work units (z, radius) at its controlled point.
void toolPolygons(const core::cut::ToolShape& tool, const Vec2& at, render::Scene3D& scene) {
  for (const core::cut::Trapezoid& t : tool.cutting)
    scene.toolCutting.push_back(
        {at + Vec2(t.z0, t.bottom0), at + Vec2(t.z1, t.bottom1), at + Vec2(t.z1, t.top1), at + Vec2(t.z0, t.top0)});
  for (const core::cut::Box& b : tool.holder)
    scene.toolHolder.push_back(
        {at + Vec2(b.z0, b.x0), at + Vec2(b.z1, b.x0), at + Vec2(b.z1, b.x1), at + Vec2(b.z0, b.x1)});
  if (tool.noseRadius > 0.0) {
    std::vector<Vec2> nose;
    for (int k = 0; k < 16; ++k) {
      const double a = k * 2.0 * M_PI / 16.0;
      nose.push_back(at + tool.noseCentre + tool.noseRadius * Vec2(std::cos(a), std::sin(a)));
    }
    scene.toolCutting.push_back(nose);
  }
}

}  // namespace

Part3DWidget::Part3DWidget(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("part3dView"));
  setMinimumSize(200, 150);
  setAttribute(Qt::WA_OpaquePaintEvent);
  setCursor(Qt::OpenHandCursor);
}

void Part3DWidget::setRunController(RunController* controller) {
  if (controller_) disconnect(controller_, nullptr, this, nullptr);
  controller_ = controller;
  if (!controller_) return;
  connect(controller_, &RunController::frameAdvanced, this, qOverload<>(&QWidget::update));
  connect(controller_, &RunController::programReset, this, qOverload<>(&QWidget::update));
}

void Part3DWidget::setStock(std::shared_ptr<const core::cut::Stock> stock) {
  shown_ = std::move(stock);
  update();
}

void Part3DWidget::paintEvent(QPaintEvent*) {
  ++paints_;
  QPainter p(this);
  p.fillRect(rect(), render::palette().background);
  render::Scene3D scene;
  const core::cut::CutSimulator* sim = controller_ && !controller_->isBusy() ? controller_->cutSimulator() : nullptr;
  if (shown_) {
    scene.stock = shown_.get();
  } else if (sim) {
    scene.stock = &sim->stock();
    scene.chuck = &sim->chuck();
    if (const core::cut::ToolShape* tool = sim->currentTool()) toolPolygons(*tool, sim->toolPosition(), scene);
  } else if (controller_) {
    // Not run yet: the bar the job header describes.
    const core::io::JobHeader& h = controller_->jobHeader();
    const double key = h.diameterMm() * 1e6 + h.lengthMm() + h.boreMm() * 1e-3;
    if (h.diameterMm() > 0.0 && h.lengthMm() > 0.0 && key != blankKey_) {
      blank_ =
          std::make_unique<core::cut::Stock>(h.diameterMm(), h.lengthMm(), core::cut::kDefaultResolution, h.boreMm());
      blankKey_ = key;
    }
    scene.stock = blank_.get();
  }
  quads_ = render::paintPart3D(p, QRectF(rect()), scene, camera_);
}

void Part3DWidget::mousePressEvent(QMouseEvent* event) {
  last_ = event->position().toPoint();
  setCursor(Qt::ClosedHandCursor);
}

void Part3DWidget::mouseMoveEvent(QMouseEvent* event) {
  const QPoint at = event->position().toPoint();
  const QPoint d = at - last_;
  last_ = at;
  if (event->buttons() & Qt::LeftButton) {
    camera_.yaw += d.x() * 0.4;
    camera_.pitch = std::clamp(camera_.pitch + d.y() * 0.4, -89.0, 89.0);
  } else if (event->buttons() & (Qt::RightButton | Qt::MiddleButton)) {
    camera_.pan += QPointF(d);
  } else {
    return;
  }
  update();
}

void Part3DWidget::mouseDoubleClickEvent(QMouseEvent*) {
  camera_ = render::Camera3D{};
  update();
}

void Part3DWidget::wheelEvent(QWheelEvent* event) {
  camera_.zoom = std::clamp(camera_.zoom * std::pow(1.0015, event->angleDelta().y()), 0.2, 40.0);
  update();
  event->accept();
}

Part3DDock::Part3DDock(QWidget* parent) : QDockWidget(parent) {
  setObjectName(QStringLiteral("view3dDock"));
  view_ = new Part3DWidget(this);
  setWidget(view_);
  retranslateUi();
}

void Part3DDock::retranslateUi() {
  setWindowTitle(tr("3D view"));
  view_->setToolTip(tr("Drag to turn, right-drag to move, wheel to zoom, double-click for the first view"));
}

void Part3DDock::changeEvent(QEvent* event) {
  QDockWidget::changeEvent(event);
  if (event->type() == QEvent::LanguageChange) retranslateUi();
}

void Part3DDock::showEvent(QShowEvent* event) {
  retranslateUi();  // a dock hidden when the language changed shows the new one
  QDockWidget::showEvent(event);
}

}  // namespace klueng::gui

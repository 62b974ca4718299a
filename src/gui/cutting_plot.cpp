#include "gui/cutting_plot.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>

#include "gui/run_controller.h"

namespace klueng::gui {

CuttingPlot::CuttingPlot(RunController* runner, QWidget* parent) : QWidget(parent), runner_(runner) {
  setObjectName(QStringLiteral("cuttingPlot"));
  setMinimumHeight(60);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  hide();
  connect(runner_, &RunController::statusChanged, this, [this] {
    if (isVisible()) update();
  });
}

void CuttingPlot::setData(std::shared_ptr<const core::cut::CuttingData> data, double cycleTime, double spindlePowerKw,
                          bool inch) {
  data_ = std::move(data);
  cycleTime_ = cycleTime;
  spindlePowerKw_ = spindlePowerKw;
  inch_ = inch;
  setVisible(data_ && !data_->cuts.empty() && cycleTime_ > 0.0);
  update();
}

void CuttingPlot::paintEvent(QPaintEvent*) {
  if (!data_ || data_->cuts.empty() || cycleTime_ <= 0.0) return;
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  p.fillRect(rect(), QColor(250, 250, 246));
  const QRectF area = QRectF(rect()).adjusted(4, 16, -4, -4);
  double maxPower = spindlePowerKw_, maxVc = 0.0;
  for (const core::cut::CutNumbers& c : data_->cuts) {
    maxPower = std::max(maxPower, c.power);
    maxVc = std::max(maxVc, c.vc);
  }
  maxPower = maxPower > 0.0 ? maxPower * 1.1 : 1.0;
  maxVc = maxVc > 0.0 ? maxVc * 1.1 : 1.0;
  const auto x = [&](double t) { return area.left() + area.width() * std::clamp(t / cycleTime_, 0.0, 1.0); };
  const auto yOf = [&](double v, double top) { return area.bottom() - area.height() * std::clamp(v / top, 0.0, 1.0); };
  // Each cut as a step over its time: power (blue) and Vc (green).
  QPainterPath power, vc;
  for (const core::cut::CutNumbers& c : data_->cuts) {
    power.moveTo(x(c.tStart), yOf(c.power, maxPower));
    power.lineTo(x(c.tEnd), yOf(c.power, maxPower));
    vc.moveTo(x(c.tStart), yOf(c.vc, maxVc));
    vc.lineTo(x(c.tEnd), yOf(c.vc, maxVc));
  }
  p.setPen(QPen(QColor(30, 150, 60), 1.5));
  p.drawPath(vc);
  p.setPen(QPen(QColor(20, 80, 200), 2.0));
  p.drawPath(power);
  if (spindlePowerKw_ > 0.0) {
    p.setPen(QPen(QColor(200, 0, 0), 1.0, Qt::DashLine));
    const double y = yOf(spindlePowerKw_, maxPower);
    p.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
  }
  // The run's time.
  p.setPen(QPen(QColor(60, 60, 60), 1.0));
  const double cursor = x(runner_->currentTime());
  p.drawLine(QPointF(cursor, area.top()), QPointF(cursor, area.bottom()));
  // The legend, in the UI language.
  QString legend = tr("power (kW, max %1)").arg(maxPower / 1.1, 0, 'f', 2);
  if (spindlePowerKw_ > 0.0) legend += tr(", spindle %1 kW").arg(spindlePowerKw_, 0, 'f', 1);
  const double vcShown = inch_ ? maxVc / 1.1 / 0.3048 : maxVc / 1.1;
  legend +=
      QStringLiteral("  ·  ") + (inch_ ? tr("Vc (ft/min, max %1)") : tr("Vc (m/min, max %1)")).arg(vcShown, 0, 'f', 0);
  p.setPen(QColor(40, 40, 40));
  QFont f = font();
  f.setPointSizeF(f.pointSizeF() * 0.85);
  p.setFont(f);
  p.drawText(QRectF(rect()).adjusted(6, 1, -6, 0), Qt::AlignLeft | Qt::AlignTop, legend);
}

}  // namespace klueng::gui

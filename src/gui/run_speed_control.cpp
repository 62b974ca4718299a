#include "gui/run_speed_control.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <cmath>

#include "gui/run_controller.h"

namespace klueng::gui {

const std::vector<double>& RunSpeedControl::steps() {
  static const std::vector<double> s{0.1, 0.25, 0.5,  1.0,   2.0,
                                     5.0, 10.0, 25.0, 100.0, RunController::kAsFastAsPossible};
  return s;
}

RunSpeedControl::RunSpeedControl(QWidget* parent) : QWidget(parent) {
  caption_ = new QLabel(this);
  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setRange(0, static_cast<int>(steps().size()) - 1);
  slider_->setPageStep(1);
  slider_->setTickPosition(QSlider::TicksBelow);
  slider_->setMinimumWidth(120);
  value_ = new QLabel(this);
  value_->setMinimumWidth(value_->fontMetrics().horizontalAdvance(QStringLiteral("100×")) + 30);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 0, 4, 0);
  layout->addWidget(caption_);
  layout->addWidget(slider_, 1);
  layout->addWidget(value_);
  connect(slider_, &QSlider::valueChanged, this, [this] {
    retranslate();
    emit speedChanged(speed());
  });
  setSpeed(1.0);
  retranslate();
}

void RunSpeedControl::setRunController(RunController* controller) {
  if (!controller) return;
  setSpeed(controller->speed());
  connect(this, &RunSpeedControl::speedChanged, controller, &RunController::setSpeed);
}

double RunSpeedControl::speed() const { return steps()[static_cast<std::size_t>(slider_->value())]; }

void RunSpeedControl::setSpeed(double factor) {
  int best = 0;
  for (int i = 0; i < static_cast<int>(steps().size()); ++i) {
    const double s = steps()[static_cast<std::size_t>(i)];
    if (s == factor) {
      best = i;
      break;
    }
    if (s != RunController::kAsFastAsPossible &&
        std::abs(std::log(s / std::max(factor, 1e-6))) <
            std::abs(std::log(steps()[static_cast<std::size_t>(best)] / std::max(factor, 1e-6))))
      best = i;
  }
  slider_->setValue(best);
}

void RunSpeedControl::retranslate() {
  caption_->setText(tr("Speed"));
  const double s = speed();
  value_->setText(s == RunController::kAsFastAsPossible ? tr("fastest") : tr("%1×").arg(s));
  const QString tip =
      tr("Animation speed: 1× is real machine time; slower is slow motion; "
         "\"fastest\" cuts to the next stop at once");
  slider_->setToolTip(tip);
  value_->setToolTip(tip);
}

void RunSpeedControl::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

}  // namespace klueng::gui

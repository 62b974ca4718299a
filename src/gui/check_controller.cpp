#include "gui/check_controller.h"

#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

namespace klueng::gui {

CheckController::CheckController(QObject* parent, std::function<QString()> text, std::function<Request()> request)
    : QObject(parent), text_(std::move(text)), request_(std::move(request)), timer_(new QTimer(this)) {
  timer_->setSingleShot(true);
  timer_->setInterval(300);  // debounce: check once typing pauses
  connect(timer_, &QTimer::timeout, this, [this] { checkText(text_()); });
  connect(&watcher_, &QFutureWatcherBase::finished, this, &CheckController::onFinished);
}

CheckController::~CheckController() { watcher_.waitForFinished(); }

void CheckController::schedule() { timer_->start(); }

bool CheckController::isScheduled() const { return timer_->isActive(); }

bool CheckController::isBusy() const { return inFlight_ || pending_ || timer_->isActive(); }

void CheckController::checkNow() {
  timer_->stop();
  checkText(text_());
}

void CheckController::checkText(const QString& text) {
  timer_->stop();
  if (watcher_.isRunning()) {  // one check at a time; the newest text goes next
    pending_ = true;
    return;
  }
  pending_ = false;
  inFlight_ = true;
  const Request r = request_();
  watcher_.setFuture(QtConcurrent::run(checkWithTools, text, r.firstLine, r.options, r.setup, r.overrides, r.stations,
                                       r.folder, r.calculatorInput, r.toolsBeyondCentre));
  emit started();
}

void CheckController::onFinished() {
  inFlight_ = false;
  if (pending_ || timer_->isActive()) {
    // The text changed while checking: this result is out of date.
    if (pending_) checkNow();
    else releaseFreedMemory();
    return;
  }
  emit finished(watcher_.result());
  releaseFreedMemory();  // the check's parse and recorded run are gone now
}

}  // namespace klueng::gui

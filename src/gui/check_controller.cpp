#include "gui/check_controller.h"
#include "gui/job_tools.h"

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
  Request r = request_();
  watcher_.setFuture(QtConcurrent::run([r = std::move(r), text]() mutable {
    if (!r.file) r.file.emplace();
    r.file->gcode = text.toStdString();
    return core::job::makeJob(std::move(r));
  }));
  emit started();
}

void CheckController::onFinished() {
  inFlight_ = false;
  if (pending_ || timer_->isActive()) {
    // The text changed while checking: this result is out of date.
    if (pending_)
      checkNow();
    else
      releaseFreedMemory();
    return;
  }
  // The window keeps the Job (JobDocument frees a replaced one off the GUI thread); the
  // watcher's reference goes when the next check starts, while the window still holds it.
  emit finished(watcher_.result());
  releaseFreedMemory();  // the check's parse and recorded run are gone now
}

}  // namespace klueng::gui

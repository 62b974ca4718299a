#pragma once
// The editor's check while typing (SPEC 12, issue 12): debounced, one check
// at a time off the GUI thread, the newest text next; a result that is out of
// date when it arrives is dropped. The window says what to check (Request)
// and shows what comes back: one core::job::Job, made on a worker thread.
#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <functional>
#include <memory>

#include "klueng/core/job/job.h"

class QTimer;

namespace klueng::gui {

class CheckController : public QObject {
  Q_OBJECT
 public:
  // Everything a check needs besides the text, taken when it starts: the
  // job's inputs, its `file` holding the header (the text goes in off the GUI thread).
  using Request = core::job::JobInput;
  using JobPtr = std::shared_ptr<const core::job::Job>;

  CheckController(QObject* parent, std::function<QString()> text, std::function<Request()> request);
  ~CheckController() override;

  void schedule();                      // after typing pauses (300 ms)
  void checkNow();                      // the current text, at once (still off the GUI thread)
  void checkText(const QString& text);  // this text (just loaded), at once
  bool isBusy() const;                  // a check scheduled, running or waiting to run
  bool isScheduled() const;

 signals:
  void started();
  void finished(const klueng::gui::CheckController::JobPtr& job);

 private:
  void onFinished();

  std::function<QString()> text_;
  std::function<Request()> request_;
  QTimer* timer_;
  QFutureWatcher<JobPtr> watcher_;
  bool pending_ = false;   // the text changed while checking
  bool inFlight_ = false;  // covers the gap between the future finishing and its slot
};

}  // namespace klueng::gui

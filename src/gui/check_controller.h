#pragma once
// The editor's check while typing (SPEC 12, issue 12): debounced, one check
// at a time off the GUI thread, the newest text next; a result that is out of
// date when it arrives is dropped. The window says what to check (Request)
// and shows what comes back.
#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <functional>
#include <optional>

#include "gui/job_tools.h"

class QTimer;

namespace klueng::gui {

class CheckController : public QObject {
  Q_OBJECT
 public:
  // Everything a check needs besides the text, taken when it starts.
  struct Request {
    int firstLine = 1;
    core::gcode::CheckOptions options;
    core::machine::MachineSetup setup;
    std::vector<core::machine::StationOverride> overrides;
    int stations = 0;  // the highest T station (the dialect's limit, else the turret)
    QString folder;    // subprogram files; empty for an untitled program
    std::optional<bool> calculatorInput;  // the file's reading of lengths without a point (Job details)
    std::optional<bool> toolsBeyondCentre;  // the file's tool side (Job details)
  };

  CheckController(QObject* parent, std::function<QString()> text, std::function<Request()> request);
  ~CheckController() override;

  void schedule();                   // after typing pauses (300 ms)
  void checkNow();                   // the current text, at once (still off the GUI thread)
  void checkText(const QString& text);  // this text (just loaded), at once
  bool isBusy() const;               // a check scheduled, running or waiting to run
  bool isScheduled() const;

 signals:
  void started();
  void finished(const JobToolsResult& result);

 private:
  void onFinished();

  std::function<QString()> text_;
  std::function<Request()> request_;
  QTimer* timer_;
  QFutureWatcher<JobToolsResult> watcher_;
  bool pending_ = false;   // the text changed while checking
  bool inFlight_ = false;  // covers the gap between the future finishing and its slot
};

}  // namespace klueng::gui

#pragma once
// Plays the core's Timeline (and the core's cut) for the GUI: Go, Step, Pause,
// Stop, Step Back, Run to line, breakpoints, speed. Holds no machining logic:
// the core checks, interprets and cuts; this class only maps wall-clock time
// to machine time and stops where the user asked.
//
// Public API (F1 wires these into the main window)
//   setProgram(file, displayName)   the document's current text (call before each run; the same
//                                   program again keeps the run; a new one is made lazily on the next run)
//   setMachineSetup(setup)          tools.cfg / offset.cfg / machine.cfg (after the dialogs)
//   setDialect(d), setOptionalStop(on), setBlockSkip(on)   switches (SPEC 10)
//   setBreakpoints(QSet<int> fileLines)                      editor margin breakpoints
//   setSpeed(factor)  machine seconds per wall second; kAsFastAsPossible (0) = no animation
//   go() step() pause() stop() stepBack() runToLine(fileLine)   the Run menu (slots)
//   state(), currentTime(), currentLine(), status(), timeline(), stockShape()
//   Breakpoints stop BEFORE the block on that line runs; Go/Step from there runs it.
//   M00, M01 (switch on) and M02/M30 pause after their block; alarms stop the run.
//   The Optional Stop switch acts at once, also during a run; Block Skip and the
//   dialect apply from the next run (they change the path).
// Signals
//   stateChanged(RunState)                 enable/disable the Run actions
//   checkFailed(QList<core::Diagnostic>)   the program has errors; the run did not start
//   alarmRaised(core::Diagnostic)          run stopped on an alarm (line in d.range.line);
//                                          formatMessage(d, Language::coreLang()) for the text
//   executingLineChanged(int fileLine)     highlight this line (0 = none)
//   statusChanged(RunStatus)               status bar fields and lamps
//   frameAdvanced()                        the output view should repaint (pose/stock changed)
//   programReset()                         new timeline / stock: rebuild the scene
//   busyChanged(bool)                      background work (check/interpret/cut to end) running
#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QList>
#include <QMetaType>
#include <QObject>
#include <QSet>
#include <QString>
#include <QTimer>
#include <functional>
#include <memory>
#include <optional>

#include "klueng/core/control/control.h"
#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/timeline.h"
#include "render/lathe_painters.h"

namespace klueng::core::job {
class Job;
}

namespace klueng::gui {

enum class RunState {
  Idle,       // nothing run yet, or stopped (reset)
  Preparing,  // checking + interpreting in the background
  Running,    // Go: animating
  Stepping,   // Step: animating one block
  Paused,     // waiting after a step, a pause, a breakpoint, M00/M01
  Finished,   // reached the program's end
  Alarm,      // stopped on an alarm
};

// Everything the status bar and the lamps show (SPEC 12).
struct RunStatus {
  core::Vec2 position = core::Vec2::Zero();  // controlled point, work coords (z, radius)
  double feedMmPerMin = 0.0;                 // actual feed of the active move (0 when idle)
  double programmedFeed = 0.0;               // F as programmed
  core::machine::FeedMode feedMode = core::machine::FeedMode::PerRev;
  double rpm = 0.0;
  core::machine::MachineState machine;  // tool, offset, lamps ...
  double time = 0.0;                    // machine seconds since the start
  double cycleTime = 0.0;
  std::vector<core::machine::ToolTime> toolTimes;  // the cycle time per tool
  int line = 0;                                    // file line of the block (0 = none)
  bool feedHold = false;                           // FEED HOLD: the axes stand, the spindle turns on
  core::Vec2 moveEnd = core::Vec2::Zero();         // where the move under way ends (= position between moves)
};

class RunController : public QObject {
  Q_OBJECT
 public:
  static constexpr double kAsFastAsPossible = 0.0;

  explicit RunController(QObject* parent = nullptr);
  ~RunController() override;

  void setProgram(const core::io::ProgramFile& file, const QString& displayName = {});
  // The folder subprogram files (O1000.nc ...) are read from: the program's own (empty = none).
  void setProgramFolder(const QString& folder);
  // Where the window's last check is asked for when a run is prepared: a check of the same text,
  // read alike, lends the run its parsed program (core::job::JobInput::sameText), so a long
  // program is not parsed a second time beside the editor's check (issue 42 item 3).
  void setLastCheck(std::function<std::shared_ptr<const core::job::Job>()> lastCheck);
  // The files of the running program: [0] the program itself (""), then its subprogram files.
  const std::vector<std::string>& programFiles() const { return files_; }
  // Program::files index of the block being executed (0 = the program in the editor).
  int currentFile() const { return currentFile_; }
  void setMachineSetup(const core::machine::MachineSetup& setup);
  const core::machine::MachineSetup& machineSetup() const { return setup_; }
  // The tools the run cuts with: machineSetup() with a guessed tool that touched replaced
  // by another of its kind that fits, and the notes saying which (cut/guess_fit.h).
  const core::machine::MachineSetup& cutSetup() const { return cutSetup_; }
  const std::vector<core::Diagnostic>& guessNotes() const { return guessNotes_; }
  void setDialect(core::gcode::Dialect dialect);
  // Units before any G20/G21; nullopt = the dialect's (Haas: inch).
  void setPowerOnUnits(std::optional<core::gcode::InputUnits> units);
  void setOptionalStop(bool on);
  bool optionalStop() const { return options_.optionalStop; }
  void setBlockSkip(bool on);
  bool blockSkip() const { return options_.blockSkip; }
  void setBreakpoints(const QSet<int>& fileLines);
  QSet<int> breakpoints() const { return breakpoints_; }
  void setSpeed(double factor);
  double speed() const { return speed_; }
  // The operator panel's overrides (issue 31): each move plays at the length they give it
  // (control::OverrideClock), relative to the speed above; they act at once, also during a run.
  void setOverrides(const core::control::Overrides& overrides, bool dryRun = false, double dryRunFeed = 1000.0);
  const core::control::Overrides& overrides() const { return overrides_; }
  // FEED HOLD (issue 31): the axes decelerate and stop within kFeedHoldSeconds of machine time (a
  // thread pass and a dwell first run to their end, as the controls do), the spindle keeps turning;
  // go() (CYCLE START) resumes. Returns false when no run was moving.
  bool feedHold();
  bool isFeedHeld() const { return held_; }
  // SINGLE BLOCK (the operator panel's switch): on during a run, the run stops at the end of the
  // block it is in; while on, go() runs one block at a time.
  void setSingleBlock(bool on);
  bool singleBlock() const { return singleBlock_; }
  static constexpr double kFeedHoldSeconds = 0.2;
  // One frame of the playback clock: `seconds` of machine time at the overrides (the frame
  // timer passes wall time × speed; tests drive it directly).
  void advancePlayback(double seconds);

  RunState state() const { return state_; }
  bool isBusy() const { return busy_; }
  double currentTime() const { return time_; }
  int currentLine() const { return currentLine_; }
  RunStatus status() const;
  // The timeline being played (nullptr before the first run).
  const core::machine::Timeline* timeline() const { return timeline_.get(); }
  // The same, shared: a worker thread reading it keeps it alive (the explain bar's cutting data).
  std::shared_ptr<const core::machine::Timeline> sharedTimeline() const { return timeline_; }
  const core::io::JobHeader& jobHeader() const { return file_.header; }
  // The stock as the core's cut has left it at currentTime().
  render::StockShape stockShape() const;
  // Index of the snapshot of the block being executed or last finished (-1 = none).
  int currentSnapshot() const { return snapshotIndex_; }
  // The snapshot of the block the arrow marks: running, or next to run (-1 none).
  int markedSnapshot() const { return markedSnapshot_; }
  // Frames drawn since the last reset (for the frame-rate probe).
  qint64 frameCount() const { return frames_; }

 public slots:
  void go();
  void step();      // one block (Step Into: also into a subprogram or macro)
  void stepOver();  // one block of this call level: a call runs whole
  void stepOut();   // on to the block after the call of this level
  void pause();
  void stop();
  void stepBack();
  void runToLine(int fileLine);
  // Blocks until any background preparation/cut finished (tests, batch export).
  void waitForIdle();

 signals:
  void stateChanged(klueng::gui::RunState state);
  void checkFailed(const QList<klueng::core::Diagnostic>& diagnostics);
  void alarmRaised(const klueng::core::Diagnostic& alarm);
  void executingLineChanged(int fileLine);            // a line of the program in the editor (0 = elsewhere)
  void executingFileLineChanged(int file, int line);  // any file of the program (programFiles())
  void statusChanged(const klueng::gui::RunStatus& status);
  void frameAdvanced();
  void programReset();
  void busyChanged(bool busy);

 public:
  // The machine-time step a slow-motion frame may take so that the tool moves at most
  // `mm` (one display pixel; the view sets it from its zoom). 0 = no limit.
  void setMaxStepMm(double mm) { maxStepMm_ = mm; }
  // The core's cut simulator (nullptr before the first run). Do not use while isBusy().
  const core::cut::CutSimulator* cutSimulator() const { return cut_.get(); }
  // Tool shape at the current time, nullptr when no tool / no bitmap.
  const core::cut::ToolShape* currentToolShape() const;

 private:
  enum class Pending { None, Go, Step, StepOver, StepOut, RunToLine };
  struct Prepared {
    std::shared_ptr<const core::machine::Timeline> timeline;  // the job's own (it keeps the job alive)
    std::vector<std::string> files;                           // Program::files
    QList<core::Diagnostic> errors;
    // Guessed tools that touched, replaced by others of their kind that fit (issue 26).
    std::optional<core::machine::MachineSetup> fitted;
    std::vector<core::Diagnostic> guessNotes;  // I413/I414
  };

  void prepareAndThen(Pending what);
  void onPrepared();
  void startPending(Pending what);
  void startRun(bool stepOnly);
  void tick();
  void advanceTo(double t);
  void finishStop();
  void setState(RunState s);
  void setBusy(bool b);
  void resetPlayback();
  void invalidate();
  void updateLine();
  void emitStatus();
  void runInBackground(double target);
  void onBackgroundDone();

  core::io::ProgramFile file_;
  QString displayName_;
  QString folder_;  // subprogram files come from here
  std::function<std::shared_ptr<const core::job::Job>()> lastCheck_;
  std::vector<std::string> files_;  // Program::files of the prepared run
  Pending stepKind_ = Pending::Step;
  core::machine::MachineSetup setup_;
  core::machine::MachineSetup cutSetup_;      // setup_ with the replaced guesses: what the cut uses
  std::vector<core::Diagnostic> guessNotes_;  // which guesses were replaced (I413/I414)
  core::machine::RunOptions options_;
  QSet<int> breakpoints_;
  double speed_ = 1.0;
  double maxStepMm_ = 0.0;
  core::control::Overrides overrides_;
  bool dryRun_ = false;
  double dryRunFeed_ = 1000.0;
  core::control::OverrideClock clock_;  // of timeline_ at overrides_ (rebuilt when either changes)
  bool holding_ = false;                // FEED HOLD pressed: decelerating
  double holdLeft_ = 0.0;               // machine seconds of the deceleration left
  bool held_ = false;                   // FEED HOLD: stopped, CYCLE START resumes
  bool singleBlock_ = false;            // SINGLE BLOCK: go() runs one block
  bool stale_ = true;

  std::shared_ptr<const core::machine::Timeline> timeline_;
  std::vector<core::machine::ToolTime> toolTimes_;  // of timeline_, worked out once
  std::unique_ptr<core::cut::CutSimulator> cut_;
  mutable render::StockShape stockShape_;
  mutable double stockShapeVolume_ = -1.0;
  RunState state_ = RunState::Idle;
  bool busy_ = false;
  bool preparing_ = false;  // prepareWatcher_ has a job not handled yet
  bool cutting_ = false;    // backgroundWatcher_ has a job not handled yet
  Pending pending_ = Pending::None;
  int runToLine_ = 0;
  double time_ = 0.0;
  double targetTime_ = 0.0;  // where the current Go/Step pauses
  int targetSnapshot_ = -1;  // snapshots done when targetTime_ is reached
  bool targetIsEnd_ = false;
  bool targetBeforeNext_ = false;  // the target stops before a block (breakpoint, run to line)
  int snapshotIndex_ = -1;         // last completed block's snapshot
  int markedSnapshot_ = -1;        // the arrow's block (updateLine)
  int currentLine_ = 0;
  int currentFile_ = 0;
  qint64 frames_ = 0;
  std::optional<core::Diagnostic> reportedAlarm_;

  QTimer frameTimer_;
  QElapsedTimer wallClock_;
  qint64 lastTickNs_ = 0;
  QFutureWatcher<std::shared_ptr<Prepared>> prepareWatcher_;
  QFutureWatcher<void> backgroundWatcher_;
};

QString runStateName(RunState s);

}  // namespace klueng::gui

Q_DECLARE_METATYPE(klueng::gui::RunStatus)
Q_DECLARE_METATYPE(klueng::core::Diagnostic)
Q_DECLARE_METATYPE(klueng::gui::RunState)

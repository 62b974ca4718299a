#include "gui/run_controller.h"

#include "gui/job_tools.h"

#include <set>

#include "klueng/core/machine/playback.h"

#include <QThread>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cmath>

#include "klueng/core/cut/guess_fit.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/machine/flow_view.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/subprogram_files.h"

namespace klueng::gui {

namespace machine = core::machine;

namespace {
constexpr double kEps = 1e-9;
constexpr int kFrameIntervalMs = 15;
constexpr double kMaxFrameSeconds = 0.1;  // a stalled frame never jumps further than this
}  // namespace

QString runStateName(RunState s) {
  switch (s) {
    case RunState::Idle: return QStringLiteral("Idle");
    case RunState::Preparing: return QStringLiteral("Preparing");
    case RunState::Running: return QStringLiteral("Running");
    case RunState::Stepping: return QStringLiteral("Stepping");
    case RunState::Paused: return QStringLiteral("Paused");
    case RunState::Finished: return QStringLiteral("Finished");
    case RunState::Alarm: return QStringLiteral("Alarm");
  }
  return {};
}

RunController::RunController(QObject* parent) : QObject(parent) {
  qRegisterMetaType<klueng::gui::RunStatus>();
  qRegisterMetaType<klueng::core::Diagnostic>();
  qRegisterMetaType<klueng::gui::RunState>();
  frameTimer_.setTimerType(Qt::PreciseTimer);
  frameTimer_.setInterval(kFrameIntervalMs);
  connect(&frameTimer_, &QTimer::timeout, this, &RunController::tick);
  connect(&prepareWatcher_, &QFutureWatcher<std::shared_ptr<Prepared>>::finished, this, &RunController::onPrepared);
  connect(&backgroundWatcher_, &QFutureWatcher<void>::finished, this, &RunController::onBackgroundDone);
  wallClock_.start();
}

RunController::~RunController() { waitForIdle(); }

// ---------------------------------------------------------------- inputs

namespace {
// What a run of the file reads: its text and line numbers, the bar, and the
// file's choices of decimal point reading and tool side (not its title fields).
bool runControllerSameProgram(const core::io::ProgramFile& a, const core::io::ProgramFile& b) {
  const core::io::JobHeader& x = a.header;
  const core::io::JobHeader& y = b.header;
  return a.gcodeFirstLine == b.gcodeFirstLine && a.plainGcode == b.plainGcode && x.diameter == y.diameter &&
         x.diameterUnit == y.diameterUnit && x.length == y.length && x.lengthUnit == y.lengthUnit && x.bore == y.bore &&
         x.calculatorInput == y.calculatorInput && x.toolsBeyondCentre == y.toolsBeyondCentre && a.gcode == b.gcode;
}
}  // namespace

void RunController::setProgram(const core::io::ProgramFile& file, const QString& displayName) {
  // The same program again changes nothing: a paused or finished run stays as it is.
  if (displayName == displayName_ && runControllerSameProgram(file, file_)) return;
  file_ = file;
  displayName_ = displayName;
  invalidate();
}

void RunController::setProgramFolder(const QString& folder) {
  if (folder == folder_) return;
  folder_ = folder;
  invalidate();
}

void RunController::setLastCheck(std::function<std::shared_ptr<const core::job::Job>()> lastCheck) {
  lastCheck_ = std::move(lastCheck);
}

void RunController::setMachineSetup(const machine::MachineSetup& setup) {
  setup_ = setup;
  cutSetup_ = setup;  // until the next run fits its guesses
  guessNotes_.clear();
  invalidate();
}

void RunController::setDialect(core::gcode::Dialect dialect) {
  if (options_.dialect == dialect) return;
  options_.dialect = dialect;
  invalidate();
}

void RunController::setPowerOnUnits(std::optional<core::gcode::InputUnits> units) {
  if (options_.powerOnUnits == units) return;
  options_.powerOnUnits = units;
  invalidate();
}

void RunController::setOptionalStop(bool on) {
  if (options_.optionalStop == on) return;
  // No new timeline needed: every M01 is recorded as a stop and the switch is read
  // when the run reaches it (startRun), so it acts at once, as on the machine.
  options_.optionalStop = on;
  if (state_ == RunState::Running && timeline_) {
    frameTimer_.stop();
    startRun(false);
  }
  emitStatus();
}

void RunController::setBlockSkip(bool on) {
  if (options_.blockSkip == on) return;
  options_.blockSkip = on;
  invalidate();
}

void RunController::setBreakpoints(const QSet<int>& fileLines) { breakpoints_ = fileLines; }

void RunController::setSpeed(double factor) {
  speed_ = std::max(0.0, factor);
  // Switching to "as fast as possible" during a run finishes the rest in the background.
  if (speed_ == kAsFastAsPossible && frameTimer_.isActive()) {
    frameTimer_.stop();
    runInBackground(targetTime_);
  }
}

void RunController::setOverrides(const core::control::Overrides& overrides, bool dryRun, double dryRunFeed) {
  overrides_ = overrides;
  dryRun_ = dryRun;
  dryRunFeed_ = dryRunFeed;
  clock_ = {};  // rebuilt on the next frame
  emitStatus();
}

bool RunController::feedHold() {
  if (state_ != RunState::Running && state_ != RunState::Stepping) return false;
  if (busy_ || !frameTimer_.isActive()) {
    pause();  // a run in the background has no axes to slow down
    held_ = true;
    emitStatus();
    return true;
  }
  holding_ = true;
  holdLeft_ = kFeedHoldSeconds;
  return true;
}

void RunController::setSingleBlock(bool on) {
  singleBlock_ = on;
  if (!on || state_ != RunState::Running || busy_ || !timeline_ || !cut_) return;
  // Switched on while the program runs: it stops at the end of the block it is in.
  stepKind_ = Pending::Step;
  startRun(true);
}

// A changed input applies to the next run; a run in progress keeps its timeline.
void RunController::invalidate() {
  stale_ = true;
  if (busy_ || state_ == RunState::Running || state_ == RunState::Stepping || state_ == RunState::Paused) return;
  frameTimer_.stop();
  cut_.reset();
  timeline_.reset();
  clock_ = {};
  stockShapeVolume_ = -1.0;
  time_ = 0.0;
  snapshotIndex_ = -1;
  currentLine_ = 0;
  currentFile_ = 0;
  reportedAlarm_.reset();
  setState(RunState::Idle);
  emit executingLineChanged(0);
  emit programReset();
  emitStatus();
}

// ---------------------------------------------------------------- queries

const core::cut::ToolShape* RunController::currentToolShape() const {
  if (!cut_ || busy_) return nullptr;
  return const_cast<core::cut::CutSimulator*>(cut_.get())->currentTool();
}

render::StockShape RunController::stockShape() const {
  if (!cut_) {
    return render::stockShapeFromBlank(file_.header.diameterMm(), file_.header.lengthMm(), file_.header.boreMm());
  }
  if (busy_) return stockShape_;  // the worker owns the simulator: show the last shape
  const double volume = cut_->stock().volume();
  if (volume != stockShapeVolume_) {
    stockShape_ = render::stockShapeFromStock(cut_->stock());
    stockShapeVolume_ = volume;
  }
  return stockShape_;
}

RunStatus RunController::status() const {
  RunStatus s;
  s.time = time_;
  s.line = currentLine_;
  s.machine.optionalStopSwitch = options_.optionalStop;
  s.position = core::zx(setup_.machine.startZ, setup_.machine.startX / 2.0);
  if (!timeline_) return s;
  s.cycleTime = timeline_->cycleTime();
  s.toolTimes = toolTimes_;
  const machine::Pose pose = machine::poseAt(*timeline_, snapshotIndex_, time_);
  if (!timeline_->moves.empty()) s.position = pose.position;
  s.moveEnd = s.position;
  if (const int i = timeline_->moveAt(time_); i >= 0) {
    const machine::Move& m = timeline_->moves[static_cast<std::size_t>(i)];
    if (time_ >= m.tStart && time_ < m.tEnd) s.moveEnd = m.path.end;
  }
  if (pose.hasState) {
    s.machine = pose.machine;
    s.programmedFeed = pose.programmedFeed;
    s.feedMode = pose.feedMode;
  }
  s.rpm = pose.rpm * overrides_.spindle / 100.0;
  // The feed the overrides make (the clock is the timeline's until the first frame builds it).
  s.feedMmPerMin =
      pose.feedMmPerMin * (clock_.timeline() == timeline_.get() ? clock_.rate(timeline_->moveAt(time_)) : 1.0);
  // Held: the axes stand, the spindle turns on.
  s.feedHold = held_;
  if (held_) s.feedMmPerMin = 0.0;
  s.machine.optionalStopSwitch = options_.optionalStop;
  if (cut_ && !busy_ && cut_->alarm()) s.position = const_cast<core::cut::CutSimulator*>(cut_.get())->toolPosition();
  return s;
}

// ---------------------------------------------------------------- commands

void RunController::go() {
  held_ = holding_ = false;  // CYCLE START after a FEED HOLD resumes
  prepareAndThen(singleBlock_ ? Pending::Step : Pending::Go);
}

void RunController::step() {
  held_ = holding_ = false;
  prepareAndThen(Pending::Step);
}
void RunController::stepOver() { prepareAndThen(Pending::StepOver); }
void RunController::stepOut() { prepareAndThen(Pending::StepOut); }

void RunController::runToLine(int fileLine) {
  runToLine_ = fileLine;
  prepareAndThen(Pending::RunToLine);
}

void RunController::pause() {
  if (state_ != RunState::Running && state_ != RunState::Stepping) return;
  if (busy_) {
    pending_ = Pending::None;  // the background cut cannot be interrupted; it pauses when done
    targetIsEnd_ = false;
    return;
  }
  frameTimer_.stop();
  setState(RunState::Paused);
  updateLine();
  emitStatus();
}

void RunController::stop() {
  frameTimer_.stop();
  held_ = holding_ = false;
  if (busy_) waitForIdle();
  pending_ = Pending::None;
  resetPlayback();
  setState(RunState::Idle);
  if (stale_) invalidate();
}

void RunController::stepBack() {
  if (busy_ || !timeline_ || !cut_) return;
  frameTimer_.stop();
  const machine::StopTarget back = machine::stepBackStop(*timeline_, snapshotIndex_, time_);
  const int target = back.snapshot;
  const double t = back.time;
  reportedAlarm_.reset();
  targetSnapshot_ = target;
  targetTime_ = t;
  targetIsEnd_ = false;
  snapshotIndex_ = target;
  // Going back restores the nearest stock checkpoint and re-cuts from there;
  // only a long re-cut (the first pass had no checkpoints yet) runs in the background.
  if (cut_->movesToCut(t) > 2000) {
    pending_ = Pending::None;
    setState(RunState::Paused);
    runInBackground(t);
    return;
  }
  cut_->advanceTo(t);
  time_ = t;
  setState(RunState::Paused);
  updateLine();
  emitStatus();
  emit frameAdvanced();
}

namespace {
// QFuture::waitForFinished runs a pool task that has not started on the waiting
// thread itself: the Job, its run and the cut would then be made on the GUI thread.
// This waits for the worker instead.
void runControllerAwaitWorker(const QFutureWatcherBase& watcher) {
  while (!watcher.isFinished()) QThread::msleep(1);
}
}  // namespace

void RunController::waitForIdle() {
  // Preparing may chain into a background cut ("as fast as possible"): wait for both.
  while (preparing_ || cutting_) {
    if (preparing_) {
      runControllerAwaitWorker(prepareWatcher_);
      onPrepared();
    }
    if (cutting_) {
      runControllerAwaitWorker(backgroundWatcher_);
      onBackgroundDone();
    }
  }
}

// ---------------------------------------------------------------- preparation

void RunController::prepareAndThen(Pending what) {
  if (busy_) return;
  const bool fresh = state_ == RunState::Idle || state_ == RunState::Finished || state_ == RunState::Alarm;
  if (timeline_ && !(stale_ && fresh)) {
    startPending(what);
    return;
  }
  pending_ = what;
  preparing_ = true;
  setBusy(true);
  setState(RunState::Preparing);
  auto file = file_;
  auto setup = setup_;
  auto options = options_;
  const std::string folder = folder_.toStdString();
  options.optionalStop = true;  // record every M01; the switch decides while playing
  std::shared_ptr<const core::job::Job> checked = lastCheck_ ? lastCheck_() : nullptr;
  prepareWatcher_.setFuture(QtConcurrent::run([file, setup, options, folder, checked = std::move(checked)]() mutable {
    auto result = std::make_shared<Prepared>();
    core::job::JobInput input;
    input.file = file;
    input.setup = setup;  // the job's tools, as the last check decided them
    input.inferTools = false;
    input.run = options;
    input.folder = folder;
    input.sameText = std::move(checked);  // shared while the run is made; the window keeps its own
    const std::shared_ptr<const core::job::Job> job = core::job::makeJob(std::move(input));
    if (job->program()) result->files = job->program()->files;
    if (job->hasErrors() || !job->timeline()) {
      for (const auto& d : job->diagnostics()) result->errors.push_back(d);
      return result;
    }
    // The job's timeline, not a copy, held on its own: the job's program (its blocks and
    // words) goes when this returns, the run keeps only what it plays.
    result->timeline = job->sharedTimeline();
    // A guessed tool that touches gives way to another of its kind that fits: one whole cut
    // here (more only when a guess touched), so the run draws the tool that fits.
    if (std::any_of(setup.tools.guessed.begin(), setup.tools.guessed.end(), [](bool g) { return g; })) {
      core::cut::CutOptions cutOptions;
      cutOptions.checkpointBudgetBytes = 0;  // only its verdict is kept
      core::cut::GuessFit fit =
          core::cut::fitGuessedTools(*result->timeline, file.header, setup, core::io::shippedToolLibrary(), cutOptions);
      if (!fit.notes.empty()) result->fitted = std::move(fit.setup);
      result->guessNotes = std::move(fit.notes);
    }
    return result;
  }));
}

void RunController::onPrepared() {
  if (!preparing_) return;
  prepareWatcher_.waitForFinished();
  preparing_ = false;
  std::shared_ptr<Prepared> result = prepareWatcher_.result();
  prepareWatcher_.setFuture(QFuture<std::shared_ptr<Prepared>>());
  releaseFreedMemory();  // the compiled program (its words) is gone; the timeline stays
  setBusy(false);
  const Pending what = pending_;
  pending_ = Pending::None;
  if (!result->errors.isEmpty()) {
    setState(RunState::Idle);
    emit checkFailed(result->errors);
    return;
  }
  timeline_ = result->timeline;
  clock_ = {};  // a new timeline may sit where the old one was: its rates are rebuilt
  toolTimes_ = timeline_ ? timeline_->timeByTool() : std::vector<core::machine::ToolTime>{};
  files_ = result->files;
  cutSetup_ = result->fitted ? *result->fitted : setup_;
  guessNotes_ = result->guessNotes;
  cut_ = std::make_unique<core::cut::CutSimulator>(*timeline_, core::cut::CutSetup::from(file_.header, cutSetup_));
  stale_ = false;
  resetPlayback();
  startPending(what);
}

void RunController::resetPlayback() {
  if (cut_) cut_->reset();
  time_ = 0.0;
  snapshotIndex_ = -1;
  currentLine_ = 0;
  currentFile_ = 0;
  frames_ = 0;
  reportedAlarm_.reset();
  stockShapeVolume_ = -1.0;
  emit executingLineChanged(0);
  emit programReset();
  emitStatus();
}

void RunController::startPending(Pending what) {
  if (what == Pending::None) {
    setState(RunState::Idle);
    return;
  }
  if (state_ == RunState::Finished || state_ == RunState::Alarm) resetPlayback();
  stepKind_ = what;
  startRun(what == Pending::Step || what == Pending::StepOver || what == Pending::StepOut);
  if (what != Pending::RunToLine) runToLine_ = 0;
}

// ---------------------------------------------------------------- playing

void RunController::startRun(bool stepOnly) {
  machine::StopRequest request;
  request.command = !stepOnly                        ? machine::RunCommand::Go
                    : stepKind_ == Pending::StepOver ? machine::RunCommand::StepOver
                    : stepKind_ == Pending::StepOut  ? machine::RunCommand::StepOut
                                                     : machine::RunCommand::Step;
  request.done = snapshotIndex_;
  request.endTime = cut_->endTime();
  request.optionalStop = options_.optionalStop;
  const std::set<int> breakpoints(breakpoints_.begin(), breakpoints_.end());
  request.breakpoints = &breakpoints;
  request.runToLine = runToLine_;
  const machine::StopTarget stop = machine::nextStop(*timeline_, request);
  targetSnapshot_ = stop.snapshot;
  targetTime_ = stop.time;
  targetIsEnd_ = stop.isEnd;
  targetBeforeNext_ = stop.beforeNext;
  setState(stepOnly ? RunState::Stepping : RunState::Running);
  if (speed_ == kAsFastAsPossible) {
    runInBackground(targetTime_);
    return;
  }
  if (targetTime_ <= time_ + kEps) {
    finishStop();
    return;
  }
  lastTickNs_ = wallClock_.nsecsElapsed();
  frameTimer_.start();
}

void RunController::tick() {
  const qint64 now = wallClock_.nsecsElapsed();
  const double wall = std::min(kMaxFrameSeconds, (now - lastTickNs_) * 1e-9);
  lastTickNs_ = now;
  advancePlayback(wall * speed_);
}

void RunController::advancePlayback(double seconds) {
  if (!timeline_ || !cut_ || busy_ || (state_ != RunState::Running && state_ != RunState::Stepping)) return;
  if (clock_.timeline() != timeline_.get())
    clock_ = core::control::OverrideClock(*timeline_, overrides_, setup_.machine, dryRun_, dryRunFeed_);
  bool stopHere = false;
  if (holding_) {
    // FEED HOLD: the speed falls to nothing over kFeedHoldSeconds (the mean of the ramp over
    // this frame). A thread pass is not stopped half-way and a dwell's timer runs on (Haas NGC
    // operator's manual, Override Usage): the hold waits for their end.
    const int i = timeline_->moveAt(time_);
    const machine::MoveKind kind =
        i >= 0 ? timeline_->moves[static_cast<std::size_t>(i)].kind : machine::MoveKind::Rapid;
    const bool runsOn = i >= 0 && time_ >= timeline_->moves[static_cast<std::size_t>(i)].tStart &&
                        (kind == machine::MoveKind::Thread || kind == machine::MoveKind::Dwell);
    if (!runsOn) {
      const double used = std::min(seconds, holdLeft_);
      const double mean = (holdLeft_ - used / 2.0) / kFeedHoldSeconds;
      holdLeft_ -= used;
      seconds = used * mean;
      stopHere = holdLeft_ <= kEps;
    }
  }
  double t = clock_.advance(time_, seconds);
  if (speed_ < 1.0 && maxStepMm_ > 0.0)
    t = time_ + machine::limitTravel(*timeline_, time_, std::max(0.0, t - time_), maxStepMm_);
  advanceTo(std::min(t, targetTime_));
  ++frames_;
  if (cut_->alarm() || time_ >= targetTime_ - kEps) {
    holding_ = false;
    finishStop();
    return;
  }
  if (stopHere) {
    holding_ = false;
    held_ = true;
    frameTimer_.stop();
    setState(RunState::Paused);
    updateLine();
    emitStatus();
  }
}

void RunController::advanceTo(double t) {
  cut_->advanceTo(t);
  time_ = cut_->time();
  const auto& snaps = timeline_->snapshots;
  while (snapshotIndex_ + 1 <= targetSnapshot_ &&
         snaps[static_cast<std::size_t>(snapshotIndex_ + 1)].time <= time_ + kEps &&
         !(cut_->alarm() && snaps[static_cast<std::size_t>(snapshotIndex_ + 1)].line >= cut_->alarm()->range.line))
    ++snapshotIndex_;
  updateLine();
  emitStatus();
  emit frameAdvanced();
}

void RunController::finishStop() {
  frameTimer_.stop();
  if (const auto alarm = cut_->alarm()) {
    time_ = cut_->time();
  } else {
    time_ = targetTime_;
    snapshotIndex_ = std::max(snapshotIndex_, targetSnapshot_);
  }
  const std::optional<core::Diagnostic> alarm =
      cut_->alarm() ? cut_->alarm() : (targetIsEnd_ ? cut_->stoppingAlarm() : std::nullopt);
  if (alarm) {
    setState(RunState::Alarm);
    currentLine_ = alarm->range.line;
    currentFile_ = alarm->range.file;
    emit executingFileLineChanged(currentFile_, currentLine_);
    emit executingLineChanged(currentFile_ == 0 ? currentLine_ : 0);
    emitStatus();
    emit frameAdvanced();
    if (!reportedAlarm_) {
      reportedAlarm_ = alarm;
      emit alarmRaised(*alarm);
    }
    return;
  }
  setState(targetIsEnd_ ? RunState::Finished : RunState::Paused);
  updateLine();
  emitStatus();
  emit frameAdvanced();
}

void RunController::runInBackground(double target) {
  cutting_ = true;
  setBusy(true);
  core::cut::CutSimulator* sim = cut_.get();
  backgroundWatcher_.setFuture(QtConcurrent::run([sim, target] { sim->advanceTo(target); }));
}

void RunController::onBackgroundDone() {
  if (!cutting_) return;
  backgroundWatcher_.waitForFinished();
  cutting_ = false;
  backgroundWatcher_.setFuture(QFuture<void>());
  setBusy(false);
  if (state_ == RunState::Paused && !cut_->alarm()) {  // a step back's re-cut
    time_ = cut_->time();
    updateLine();
    emitStatus();
    emit frameAdvanced();
    return;
  }
  time_ = cut_->time();
  finishStop();
}

void RunController::updateLine() {
  int line = 0;
  int file = 0;
  if (timeline_) {
    const auto& snaps = timeline_->snapshots;
    const int count = static_cast<int>(snaps.size());
    // One meaning for the arrow (issue 11, SPEC 10 "the block being executed"):
    // the block running, else the last block that ran — after a Step and at a
    // breakpoint alike (a breakpoint stops before its block: the arrow is on the
    // block before it, the breakpoint's dot on the one that runs next).
    const bool moving = state_ == RunState::Running || state_ == RunState::Stepping;
    int k = moving ? snapshotIndex_ + 1 : snapshotIndex_;
    if (state_ == RunState::Paused && snapshotIndex_ >= 0 &&
        time_ > snaps[static_cast<std::size_t>(snapshotIndex_)].time + kEps)
      k = snapshotIndex_ + 1;  // paused in the middle of a block: that block is running
    if (k >= count) k = count - 1;
    markedSnapshot_ = k;
    if (k >= 0) {
      line = snaps[static_cast<std::size_t>(k)].line;
      file = snaps[static_cast<std::size_t>(k)].file;
    }
  }
  if (line != currentLine_ || file != currentFile_) {
    currentLine_ = line;
    currentFile_ = file;
    emit executingFileLineChanged(file, line);
    emit executingLineChanged(file == 0 ? line : 0);
  }
}

void RunController::emitStatus() { emit statusChanged(status()); }

void RunController::setState(RunState s) {
  if (state_ == s) return;
  state_ = s;
  emit stateChanged(s);
}

void RunController::setBusy(bool b) {
  if (busy_ == b) return;
  busy_ = b;
  emit busyChanged(b);
}

}  // namespace klueng::gui

#include "gui/operator_panel.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDial>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFontDatabase>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPlainTextEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QShortcut>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "gui/language.h"
#include "gui/operator_touch_view.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/job/class_grading.h"
#include "klueng/core/job/job.h"
#include "klueng/core/messages.h"
#include "render/lathe_painters.h"
#include "render/tool_sprite.h"

namespace klueng::gui {

namespace ctl = core::control;

namespace {

QString panelMm(double v) { return QString::number(std::abs(v) < 0.0005 ? 0.0 : v, 'f', 3); }

QString panelMinSec(double s) {
  if (!std::isfinite(s)) return QStringLiteral("∞");
  const int m = static_cast<int>(s / 60.0);
  return QStringLiteral("%1:%2").arg(m).arg(s - m * 60.0, 4, 'f', 1, QLatin1Char('0'));
}

bool panelSameOffsets(const core::io::OffsetTable& a, const core::io::OffsetTable& b) {
  for (int n = 1; n <= core::io::kOffsetCount; ++n) {
    const auto &p = a.at(n), &q = b.at(n);
    if (p.x != q.x || p.z != q.z || p.r != q.r || p.tip != q.tip) return false;
  }
  return true;
}

}  // namespace

OperatorPanel::OperatorPanel(QWidget* parent, std::function<Source()> source)
    : QDockWidget(parent), source_(std::move(source)) {
  setObjectName(QStringLiteral("operatorPanelDock"));
  build();
  retranslateUi();
}

OperatorPanel::~OperatorPanel() = default;

void OperatorPanel::changeEvent(QEvent* event) {
  QDockWidget::changeEvent(event);
  if (event->type() == QEvent::LanguageChange) retranslateUi();
}

void OperatorPanel::showEvent(QShowEvent* event) {
  QDockWidget::showEvent(event);
  if (!control_) {
    powerOn();
  } else {
    updateCycleTime();
    refresh();  // a run went on while the panel was hidden
  }
}

void OperatorPanel::powerOn() {
  Source s = source_();
  // The offsets the panel gave the run are not offset.cfg: power on starts from the file's again.
  if (emitted_ && panelSameOffsets(s.setup.offsets, lastEmitted_))
    s.setup.offsets = fileOffsets_;
  else
    fileOffsets_ = s.setup.offsets;
  control_ = std::make_unique<ctl::Control>(s.setup, s.stock, s.dialect);
  // A program running (or held) as the panel powers on: the machine is in MEM, running it.
  if (runner_ && runner_->state() != RunState::Idle && runner_->state() != RunState::Finished &&
      runner_->state() != RunState::Alarm)
    control_->setMode(ctl::Mode::Memory);
  view_->setControl(control_.get());
  const int stations = std::min(s.setup.machine.turretStations, core::io::kMaxStations);
  offsets_->setRowCount(stations);
  QStringList rows;
  for (int n = 1; n <= stations; ++n) rows << QStringLiteral("%1").arg(n, 2, 10, QLatin1Char('0'));
  offsets_->setVerticalHeaderLabels(rows);
  setOffsetRow(1);
  modes_->button(static_cast<int>(control_->mode()))->setChecked(true);
  sWord_->setValue(static_cast<int>(control_->spindleSpeed()));
  feedOv_->setCurrentIndex(feedOv_->findData(100));
  rapidOv_->setCurrentIndex(rapidOv_->findData(100));
  spindleOv_->setCurrentIndex(spindleOv_->findData(100));
  for (QToolButton* sw : switches_) sw->setChecked(false);
  // The teacher's job file may ask for the setup exercise: (OFFSETS: UNKNOWN) at its head.
  if (core::io::offsetsUnknownIn(s.programFile.gcode) > 0) control_->forgetGeometry();
  {
    const QSignalBlocker quiet(exercise_);
    exercise_->setChecked(control_->exercise());
  }
  coolant_->setChecked(false);
  handleStep_->button(0)->setChecked(true);
  handleAxis_->button(1)->setChecked(true);
  shown_.reset();
  message_->clear();
  micReading_->clear();
  applyLayoutLabels();
  emitOffsets();
  emitOverrides();
  refresh();
  updateCycleTime();
}

int OperatorPanel::offsetRow() const { return std::max(0, offsets_->currentRow()) + 1; }

void OperatorPanel::setOffsetRow(int row) {
  if (row >= 1 && row <= offsets_->rowCount()) offsets_->selectRow(row - 1);
}

void OperatorPanel::pressMode(ctl::Mode mode) {
  if (!control_) return;
  control_->setMode(mode);
  chips_ = false;
  modes_->button(static_cast<int>(mode))->setChecked(true);
  if (mode == ctl::Mode::Mdi) tabs_->setCurrentIndex(2);
  refresh();
}

void OperatorPanel::pressJog(ctl::Axis axis, int direction) {
  if (!control_) return;
  if (control_->mode() == ctl::Mode::ZeroReturn) {
    if (direction > 0) afterMotion(control_->zeroReturn(axis));
    return;
  }
  // One tick of a held key: 0.1 s at the jog feed or the rapid rate (times the overrides).
  const core::io::MachineConfig& m = control_->setup().machine;
  const bool rapid = rapid_->isChecked();
  const int ro = control_->overrides().rapid;
  const double rate =
      rapid ? (ro <= 0 ? ctl::kRapidF0Rate : (axis == ctl::Axis::X ? 2.0 * m.rapidX : m.rapidZ) * ro / 100.0)
            : control_->jogFeed * control_->overrides().feed / 100.0 * (axis == ctl::Axis::X ? 2.0 : 1.0);
  afterMotion(control_->jog(axis, direction * rate / 600.0, rapid));
}

void OperatorPanel::turnHandle(int clicks) {
  if (!control_) return;
  afterMotion(control_->handle(clicks));
}

void OperatorPanel::afterMotion(const ctl::MotionResult& r) {
  chips_ = r.cut;
  showMessage(r.stop);
  view_->update();
  refresh();
}

std::optional<ctl::MeasureInput> OperatorPanel::readOffsetInput(std::optional<ctl::Axis> only) {
  auto parsed = ctl::parseMeasureInput(input_->text().toStdString());
  if (parsed && (!only || parsed->axis == *only)) return parsed;
  showMessage(
      core::Diagnostic{core::Severity::Error, core::codes::kNotMeasureInput, {}, {input_->text().toStdString()}});
  return std::nullopt;
}

void OperatorPanel::pressMeasure() {
  if (!control_) return;
  const auto parsed = readOffsetInput();
  if (!parsed) return;
  showMessage(control_->measure(offsetRow(), parsed->axis, parsed->value));
  input_->clear();
  emitOffsets();
  refresh();
}

void OperatorPanel::setExercise(bool on) {
  if (!control_ || on == control_->exercise()) return;
  if (on) {
    control_->forgetGeometry();
    emitOffsets();
    refresh();
  } else {
    powerOn();
  }
}

void OperatorPanel::pressInputWear() {
  if (!control_) return;
  const auto parsed = readOffsetInput();
  if (!parsed) return;
  ctl::OffsetRow& r = control_->row(offsetRow());
  (parsed->axis == ctl::Axis::X ? r.wear.x : r.wear.z) += parsed->value;
  input_->clear();
  showMessage(std::nullopt);
  emitOffsets();
  refresh();
}

void OperatorPanel::pressMeasureShift() {
  if (!control_) return;
  const auto parsed = readOffsetInput(ctl::Axis::Z);
  if (!parsed) return;
  showMessage(control_->measureWorkShift(parsed->value));
  input_->clear();
  emitOffsets();
  refresh();
}

void OperatorPanel::pressMicrometer() {
  if (!control_) return;
  micReading_->setText(QStringLiteral("Ø%1").arg(panelMm(control_->micrometer(micZ_->value()))));
}

void OperatorPanel::pressCycleStart() {
  if (!control_) return;
  switch (control_->mode()) {
    case ctl::Mode::Mdi: {
      const double removed = control_->stock().removedVolume();
      const std::vector<core::Diagnostic> ds = control_->runMdi(mdi_->toPlainText().toStdString());
      chips_ = control_->stock().removedVolume() > removed;
      showAll(ds);
      if (!core::hasErrors(ds)) mdi_->clear();
      view_->update();
      refresh();
      return;
    }
    case ctl::Mode::Memory: {
      std::vector<int> used;
      if (control_->exercise()) {
        // The tools of the program as it is now (the last run may be of older text, or none yet).
        const Source s = source_();
        core::job::JobInput input;
        input.file = s.programFile;
        input.setup = control_->runSetup();
        input.inferTools = false;
        input.folder = std::string();
        input.run.dialect = s.dialect;
        const std::shared_ptr<const core::job::Job> job = core::job::makeJob(std::move(input));
        std::set<int> tools;
        if (const core::machine::Timeline* t = job->timeline())
          for (const core::machine::Move& m : t->moves)
            if (m.tool > 0) tools.insert(m.tool);
        used.assign(tools.begin(), tools.end());
      }
      const auto refusal = control_->cycleStartRefusal(used);
      // The exercise: how far the entered offsets are from the true ones.
      showMessage(refusal ? refusal : control_->exercise() ? control_->compareTouchOff(used) : std::nullopt);
      if (!refusal && control_->exercise()) saveTouchOff();
      if (!refusal) emit cycleStartRequested(control_->singleBlock);
      return;
    }
    default:
      showMessage(core::Diagnostic{core::Severity::Note, core::codes::kKeyNotInMode, {}, {"CYCLE START", "MEM / MDI"}});
  }
}

void OperatorPanel::saveTouchOff() {
  // The student's touch-off, beside the program, for klueng-cli class and Grade a class.
  const QString program = source_().programPath;
  if (program.isEmpty()) {
    touchOffSaved_.clear();
    return;
  }
  const std::string path = core::job::touchOffFilePath(program.toStdString());
  std::string error;
  const bool ok =
      core::io::writeTextFileAtomic(path, core::io::formatOffsetTable(control_->runSetup().offsets), &error);
  touchOffSaved_ = ok ? QString::fromStdString(path) : QString();
  const QString name = QString::fromStdString(std::filesystem::path(path).filename().string());
  note_ = ok ? tr("Touch-off saved for grading: %1").arg(name)
             : tr("Touch-off not saved (%1): %2").arg(name, QString::fromStdString(error));
  showMessage(shown_);
}

void OperatorPanel::pressFeedHold() {
  if (!control_) return;
  emit feedHoldRequested();
}

void OperatorPanel::showFeedHold(bool held) {
  showMessage(std::nullopt);
  note_ = held ? tr("FEED HOLD: the axes stop, the spindle keeps turning; CYCLE START in MEM resumes")
               : tr("FEED HOLD: no program is moving");
  showMessage(shown_);
}

void OperatorPanel::emitOverrides() {
  if (control_) emit overridesChanged(control_->overrides(), control_->dryRun, control_->jogFeed);
}

void OperatorPanel::pressReset() {
  if (!control_) return;
  control_->reset();
  showMessage(std::nullopt);
  // RESET ends the program the machine runs, whichever key started it.
  if (runUnderWay_) emit resetRequested();
  refresh();
}

QString OperatorPanel::text(const core::Diagnostic& d) const {
  return QString::fromStdString(core::formatMessage(d, Language::coreLang(), core::Surface::Gui));
}

void OperatorPanel::showMessage(const std::optional<core::Diagnostic>& d) {
  if (&d != &shown_) {
    mdiPlace_ = {0, 0};  // a new message: not about an MDI line unless showAll says so
    note_.clear();
  }
  shown_ = d;
  if (!d) {
    message_->setStyleSheet(QString());
    message_->setText(note_);
    return;
  }
  const bool bad = core::isError(d->severity);
  const bool warn = d->severity == core::Severity::Warning;
  message_->setStyleSheet(bad    ? QStringLiteral("color: #b00000; font-weight: bold;")
                          : warn ? QStringLiteral("color: #8a5a00;")
                                 : QString());
  QString line = QString::fromStdString(d->code) + QStringLiteral(" ") + text(*d);
  if (mdiPlace_.first > 0) line += tr(" (MDI line %1, column %2)").arg(mdiPlace_.first).arg(mdiPlace_.second);
  if (!note_.isEmpty()) line += QLatin1Char('\n') + note_;
  message_->setText(line);
}

void OperatorPanel::showAll(const std::vector<core::Diagnostic>& ds) {
  if (ds.empty()) {
    showMessage(std::nullopt);
    return;
  }
  // The worst one first, with its line in the MDI text.
  const core::Diagnostic* worst = &ds.front();
  for (const core::Diagnostic& d : ds)
    if (core::isError(d.severity) && !core::isError(worst->severity)) worst = &d;
  showMessage(*worst);
  mdiPlace_ = worst->range.line > 0 ? std::make_pair(worst->range.line, worst->range.column) : std::make_pair(0, 0);
  showMessage(shown_);
}

void OperatorPanel::emitOffsets() {
  if (!control_) return;
  lastEmitted_ = control_->runSetup().offsets;
  emitted_ = true;
  emit offsetsChanged(lastEmitted_);
}

void OperatorPanel::refresh() {
  showPositions();
  if (!control_) return;
  showState();
  if (shown_) showMessage(shown_);  // its words in the language now shown
  showOffsetRows();
}

void OperatorPanel::showPositions() {
  if (!control_) {
    for (auto& r : pos_)
      for (QLabel* l : r) l->setText(QStringLiteral("-"));
    return;
  }
  const ctl::Control& c = *control_;
  ctl::AxisValues v[4] = {c.absolutePosition(), c.relativePosition(), c.machinePosition(), c.distanceToGo()};
  if (showsRun()) {
    // The run's controlled point (work coordinates, X a radius) as the control shows it, and the
    // turret where the run's offset row puts it: machine = work + geometry + wear + work shift.
    const ctl::AxisValues work{2.0 * run_.position.y(), run_.position.x()};
    const int n = run_.machine.offset > 0 ? run_.machine.offset
                  : run_.machine.tool > 0 ? run_.machine.tool
                                          : c.station();
    ctl::AxisValues offset;
    if (n >= 1 && n <= core::io::kOffsetCount) {
      const ctl::OffsetRow& r = c.row(n);
      offset = {r.geometry.x + r.wear.x, r.geometry.z + r.wear.z};
    }
    const ctl::AxisValues machine{work.x + offset.x + c.workShift().x, work.z + offset.z + c.workShift().z};
    v[0] = work;
    v[1] = {v[1].x + machine.x - v[2].x, v[1].z + machine.z - v[2].z};
    v[2] = machine;
    v[3] = {2.0 * (run_.moveEnd.y() - run_.position.y()), run_.moveEnd.x() - run_.position.x()};
  }
  for (int k = 0; k < 4; ++k) {
    pos_[0][k]->setText(panelMm(v[k].x));
    pos_[1][k]->setText(panelMm(v[k].z));
  }
  // Not yet referenced: the machine column says so, as the lamps of a real panel do.
  for (int r = 0; r < 2; ++r) {
    const bool ref = c.referenced(r == 0 ? ctl::Axis::X : ctl::Axis::Z);
    pos_[r][2]->setStyleSheet(ref ? QString() : QStringLiteral("color: #b00000;"));
    pos_[r][2]->setToolTip(ref ? QString() : tr("Not returned to the reference point yet"));
  }
}

void OperatorPanel::showState() {
  const ctl::Control& c = *control_;
  const bool run = showsRun();
  const core::machine::SpindleDir spindle = run ? run_.machine.spindle : c.spindle();
  const char* dir = spindle == core::machine::SpindleDir::Cw    ? "CW"
                    : spindle == core::machine::SpindleDir::Ccw ? "CCW"
                                                                : "STOP";
  // The mode as its key says it (Fanuc JOG, Haas HAND JOG).
  QString state = QStringLiteral("%1  T%2  S%3 %4  %5%6")
                      .arg(modes_->button(static_cast<int>(c.mode()))->text())
                      .arg(run ? run_.machine.tool : c.station(), 2, 10, QLatin1Char('0'))
                      .arg(run ? run_.rpm : c.actualRpm(), 0, 'f', 0)
                      .arg(QString::fromLatin1(dir))
                      .arg(c.alarm() ? QStringLiteral("ALM ") : QString())
                      .arg((run ? run_.machine.coolant : c.coolant) ? QStringLiteral("COOL") : QString());
  // The run's feed (mm/min, at the overrides), and the axes standing in FEED HOLD.
  if (run) state += QStringLiteral("  F%1").arg(run_.feedMmPerMin, 0, 'f', 0);
  if (run && run_.feedHold) state += QStringLiteral("  HOLD");
  // Chips: the last key took material off, the sign a touch-off waits for.
  if (chips_ && !run) state += QStringLiteral("  ") + tr("CHIPS");
  state_->setText(state);
  state_->setStyleSheet(c.alarm()        ? QStringLiteral("color: #b00000; font-weight: bold;")
                        : chips_ && !run ? QStringLiteral("color: #a05000; font-weight: bold;")
                                         : QString());
}

void OperatorPanel::showOffsetRows() {
  const ctl::Control& c = *control_;
  for (int n = 1; n <= offsets_->rowCount(); ++n) {
    const ctl::OffsetRow& r = c.row(n);
    const QString cells[4] = {panelMm(r.geometry.x), panelMm(r.geometry.z), panelMm(r.wear.x), panelMm(r.wear.z)};
    for (int k = 0; k < 4; ++k) {
      QTableWidgetItem* item = offsets_->item(n - 1, k);
      if (!item) {
        item = new QTableWidgetItem;
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        offsets_->setItem(n - 1, k, item);
      }
      item->setText(cells[k]);
    }
  }
  shift_->setText(QStringLiteral("SHIFT Z %1").arg(panelMm(c.workShift().z)));
}

// ---------------------------------------------------------------- the one run

void OperatorPanel::followRun(const RunController* runner) {
  runner_ = runner;
  connect(runner, &RunController::stateChanged, this, &OperatorPanel::followRunState);
  connect(runner, &RunController::statusChanged, this, [this](const RunStatus& status) {
    run_ = status;
    if (showsRun() && isVisible()) {
      showPositions();
      showState();
    }
  });
  followRunState(runner->state());
}

bool OperatorPanel::showsRun() const { return runUnderWay_ && control_ && control_->mode() == ctl::Mode::Memory; }

void OperatorPanel::followRunState(RunState state) {
  const bool underWay = state != RunState::Idle;
  // A run that starts puts the machine in MEM, whichever key started it.
  const bool starts = underWay && !runUnderWay_;
  runUnderWay_ = underWay;
  run_ = runner_->status();
  if (starts && control_ && control_->mode() != ctl::Mode::Memory)
    pressMode(ctl::Mode::Memory);
  else
    refresh();
}

void OperatorPanel::updateCycleTime() {
  if (!control_) return;
  const ctl::Control& c = *control_;
  // The program's cycle time as these overrides would make it.
  const Source s = source_();
  if (s.program && !s.program->moves.empty()) {
    const double base = s.program->cycleTime();
    const double now =
        ctl::withOverrides(*s.program, c.overrides(), c.setup().machine, c.dryRun, c.jogFeed).cycleTime();
    cycleTime_->setText(
        tr("Cycle time at these overrides: %1 (at 100 %: %2)").arg(panelMinSec(now), panelMinSec(base)));
  } else {
    cycleTime_->setText(tr("Run the program once to see its cycle time at these overrides."));
  }
}

}  // namespace klueng::gui

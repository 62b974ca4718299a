#include "gui/explain_bar.h"

#include <QEvent>
#include <QTextBlock>
#include <QtConcurrent/QtConcurrentRun>

#include "gui/code_editor.h"
#include "gui/language.h"
#include "gui/run_controller.h"
#include "klueng/core/help/explain.h"
#include "klueng/core/machine/program_units.h"
#include "klueng/core/messages.h"

namespace klueng::gui {

ExplainBar::ExplainBar(RunController* runner, CodeEditor* editor, QWidget* parent)
    : QLabel(parent), runner_(runner), editor_(editor) {
  setObjectName(QStringLiteral("explainBar"));
  setWordWrap(true);
  setTextFormat(Qt::PlainText);
  setTextInteractionFlags(Qt::TextSelectableByMouse);
  setMargin(4);
  setAutoFillBackground(true);
  QPalette p = palette();
  p.setColor(QPalette::Window, QColor(232, 244, 232));
  p.setColor(QPalette::WindowText, QColor(20, 60, 20));
  setPalette(p);
  hide();
  // Queued: the editor moves its arrow on the same signals first.
  connect(runner_, &RunController::executingLineChanged, this, &ExplainBar::refresh, Qt::QueuedConnection);
  connect(runner_, &RunController::stateChanged, this, &ExplainBar::refresh, Qt::QueuedConnection);
  connect(&watcher_, &QFutureWatcherBase::finished, this, [this] {
    data_ = watcher_.result();
    const std::shared_ptr<const core::machine::Timeline> timeline = dataFor_.lock();
    emit cuttingDataReady(data_, timeline ? timeline->cycleTime() : 0.0, runner_->cutSetup().machine.spindlePowerKw,
                          dataUnits_ == core::DisplayUnits::Inch);
    refresh();
  });
}

void ExplainBar::measureRun() {
  std::shared_ptr<const core::machine::Timeline> timeline = runner_->sharedTimeline();
  if (!timeline || timeline == dataFor_.lock() || watcher_.isRunning()) return;
  dataFor_ = timeline;
  data_.reset();
  emit cuttingDataReady(nullptr, 0.0, 0.0, false);  // the last run's plot goes
  // A very long run's numbers (about 190 bytes a cut) would cost the window more memory than the
  // run itself (issue 29 item 8's goal): klueng-cli simulate --cutting-data measures those.
  if (timeline->moves.size() > kCuttingDataMoveLimit) return;
  const core::io::JobHeader header = runner_->jobHeader();
  const core::machine::MachineSetup setup = runner_->cutSetup();
  core::cut::CuttingDataOptions options =
      core::cut::cuttingDataOptions(header.material, setup.tools, setup.machine, core::cut::shippedMaterials());
  options.units = core::machine::programUnits(*timeline, core::gcode::InputUnits::Millimetre);
  options.finishMarks = finishMarks_;
  dataUnits_ = options.units;
  watcher_.setFuture(QtConcurrent::run([timeline, header, setup, options] {
    return std::shared_ptr<const core::cut::CuttingData>(std::make_shared<core::cut::CuttingData>(
        core::cut::measureCuts(*timeline, core::cut::CutSetup::from(header, setup), options)));
  }));
}

QString ExplainBar::cuttingDataLine(int fileLine) const {
  if (!data_) return {};
  const std::optional<core::cut::CutNumbers> c = data_->ofLine(0, fileLine);
  if (!c) return {};
  const bool inch = dataUnits_ == core::DisplayUnits::Inch;
  const double perUnit = inch ? 1.0 / core::kMmPerInch : 1.0;
  const QString unit = inch ? tr("in") : tr("mm");
  const QString vc = inch ? QString::number(c->vc / 0.3048, 'f', 0) + QStringLiteral(" ") + tr("ft/min")
                          : QString::number(c->vc, 'f', 0) + QStringLiteral(" ") + tr("m/min");
  QString text = tr("Cutting data: Vc %1, f %2 %3/rev, ap %4 %3")
                     .arg(vc, QString::number(c->feed * perUnit, 'f', inch ? 4 : 3), unit,
                          QString::number(c->depth * perUnit, 'f', inch ? 3 : 2));
  if (c->rz && c->ra)
    text += tr(", Rz %1 µm, Ra %2 µm").arg(QString::number(*c->rz, 'f', 1), QString::number(*c->ra, 'f', 1));
  if (c->power > 0.0)
    text +=
        tr(", power %1 kW, torque %2 N·m").arg(QString::number(c->power, 'f', 2), QString::number(c->torque, 'f', 1));
  for (const core::Diagnostic& w : data_->warnings)
    if (w.range.file == 0 && w.range.line == fileLine) {
      text += QStringLiteral("\n⚠ ") +
              QString::fromStdString(core::formatMessage(w, Language::coreLang(), core::Surface::Gui));
      break;
    }
  return text;
}

QString ExplainBar::explainLine(int fileLine) const {
  const QTextBlock line = editor_->document()->findBlockByNumber(editor_->editorLineFromFileLine(fileLine));
  if (!line.isValid()) return {};
  const std::string text = line.text().toStdString();
  // The state it left the last time it ran (up to where the run stands).
  const core::machine::StateSnapshot* after = nullptr;
  if (const core::machine::Timeline* t = runner_->timeline()) {
    for (int k = runner_->currentSnapshot(); k >= 0 && !after; --k) {
      const core::machine::StateSnapshot& s = t->snapshots[static_cast<std::size_t>(k)];
      if (s.file == 0 && s.line == fileLine) after = &s;
    }
  }
  QString what = QString::fromStdString(
      core::machine::explainLineText(text, fileLine, after, editor_->dialect(), Language::coreLang(),
                                     !runner_->machineSetup().machine.calculatorInput));
  if (const QString cut = cuttingDataLine(fileLine); !what.isEmpty() && !cut.isEmpty())
    what += QStringLiteral("\n") + cut;
  return what;
}

void ExplainBar::refresh() {
  const RunState state = runner_->state();
  const int line = editor_->executingFileLine();
  const core::machine::Timeline* t = runner_->timeline();
  if (t && state != RunState::Idle) measureRun();
  const int k = runner_->markedSnapshot();
  if (state == RunState::Idle || state == RunState::Running || line <= 0 || !t || k < 0 ||
      k >= static_cast<int>(t->snapshots.size()) || t->snapshots[static_cast<std::size_t>(k)].line != line) {
    const QString text =
        state == RunState::Idle || state == RunState::Running || line <= 0 ? QString() : explainLine(line);
    setText(text);
    setVisible(!text.isEmpty());
    return;
  }
  // The arrow's block, with the state it leaves (the whole run is known ahead).
  const QTextBlock b = editor_->document()->findBlockByNumber(editor_->editorLineFromFileLine(line));
  std::string what = core::machine::explainLineText(
      b.text().toStdString(), line, &t->snapshots[static_cast<std::size_t>(k)], editor_->dialect(),
      Language::coreLang(), !runner_->machineSetup().machine.calculatorInput);
  if (what.empty()) {
    hide();
    return;
  }
  // Paused inside a cycle: which pass.
  const int move = t->moveAt(runner_->currentTime());
  const core::machine::StateSnapshot& snap = t->snapshots[static_cast<std::size_t>(k)];
  if (move >= 0 && runner_->currentTime() < snap.time - 1e-9 &&
      t->moves[static_cast<std::size_t>(move)].blockIndex == snap.blockIndex)
    if (const std::string pass = core::machine::explainPass(*t, move, Language::coreLang()); !pass.empty())
      what += "; " + pass;
  QString text = QString::fromStdString(what);
  if (const QString cut = cuttingDataLine(line); !cut.isEmpty()) text += QStringLiteral("\n") + cut;
  setText(text);
  show();
}

void ExplainBar::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange && isVisible()) refresh();
  QLabel::changeEvent(event);
}

}  // namespace klueng::gui

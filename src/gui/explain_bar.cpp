#include "gui/explain_bar.h"

#include <QEvent>
#include <QTextBlock>

#include "gui/code_editor.h"
#include "gui/language.h"
#include "gui/run_controller.h"
#include "klueng/core/help/explain.h"

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
  return QString::fromStdString(core::machine::explainLineText(text, fileLine, after, editor_->dialect(),
                                                               Language::coreLang(),
                                                               !runner_->machineSetup().machine.calculatorInput));
}

void ExplainBar::refresh() {
  const RunState state = runner_->state();
  const int line = editor_->executingFileLine();
  const core::machine::Timeline* t = runner_->timeline();
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
  setText(QString::fromStdString(what));
  show();
}

void ExplainBar::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange && isVisible()) refresh();
  QLabel::changeEvent(event);
}

}  // namespace klueng::gui

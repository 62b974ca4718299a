#include "gui/flow_panel.h"

#include <QEvent>
#include <QFile>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QSplitter>
#include <QTextBlock>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "gui/run_controller.h"
#include "klueng/core/gcode/macro.h"
#include "klueng/core/machine/flow_view.h"

namespace klueng::gui {

namespace machine = core::machine;

namespace {

QString programName(int number) {
  return number > 0 ? QStringLiteral("O%1").arg(number, 4, 10, QLatin1Char('0')) : QString();
}

QString valueText(const machine::WatchedVariable& v) {
  if (v.vacant) return FlowPanel::tr("vacant");
  return QString::fromStdString(core::gcode::macroNumberText(v.value));
}

}  // namespace

FlowPanel::FlowPanel(QWidget* parent) : QDockWidget(parent) {
  setObjectName(QStringLiteral("flowPanel"));
  auto* body = new QWidget(this);
  auto* layout = new QVBoxLayout(body);
  layout->setContentsMargins(2, 2, 2, 2);
  auto* split = new QSplitter(Qt::Horizontal, body);
  split->setChildrenCollapsible(false);

  stack_ = new QTreeWidget(split);
  stack_->setObjectName(QStringLiteral("callStack"));
  stack_->setColumnCount(2);
  stack_->setRootIsDecorated(false);
  stack_->setAlternatingRowColors(true);
  stack_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);

  variables_ = new QTreeWidget(split);
  variables_->setObjectName(QStringLiteral("variableWatch"));
  variables_->setColumnCount(2);
  variables_->setRootIsDecorated(false);
  variables_->setAlternatingRowColors(true);
  variables_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);

  auto* sourceBox = new QWidget(split);
  auto* sourceLayout = new QVBoxLayout(sourceBox);
  sourceLayout->setContentsMargins(0, 0, 0, 0);
  sourceTitle_ = new QLabel(sourceBox);
  sourceTitle_->setObjectName(QStringLiteral("subprogramTitle"));
  source_ = new QPlainTextEdit(sourceBox);
  source_->setObjectName(QStringLiteral("subprogramSource"));
  source_->setReadOnly(true);
  source_->setLineWrapMode(QPlainTextEdit::NoWrap);
  QFont mono(QStringLiteral("Monospace"));
  mono.setStyleHint(QFont::TypeWriter);
  source_->setFont(mono);
  sourceLayout->addWidget(sourceTitle_);
  sourceLayout->addWidget(source_, 1);
  sourceBox->hide();  // only while a block of a subprogram file runs

  split->setStretchFactor(0, 2);
  split->setStretchFactor(1, 2);
  split->setStretchFactor(2, 3);
  layout->addWidget(split);
  setWidget(body);

  connect(stack_, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
    const int file = item->data(0, Qt::UserRole).toInt();
    const int line = item->data(0, Qt::UserRole + 1).toInt();
    if (line > 0) emit callerActivated(file, line);
  });
  retranslateUi();
}

void FlowPanel::follow(RunController* runner) {
  runner_ = runner;
  const auto refresh = [this] {
    const machine::Timeline* t = runner_->timeline();
    const int snap = runner_->currentSnapshot();
    if (snap == shownSnapshot_ && t == timeline_) return;  // frames within one block change nothing here
    const int previous = shownSnapshot_ >= -1 && t == timeline_ ? shownSnapshot_ : -1;
    shownSnapshot_ = snap;
    if (t && !raisedForRun_ && (t->flow.stacks.size() > 1 || !t->flow.writes.empty())) {
      raisedForRun_ = true;
      show();
      raise();
    }
    showStep(t, snap, previous, runner_->programFiles(), runner_->currentFile(), runner_->currentLine());
  };
  connect(runner, &RunController::frameAdvanced, this, refresh);
  connect(runner, &RunController::executingFileLineChanged, this, refresh);
  connect(runner, &RunController::programReset, this, [this, refresh] {
    raisedForRun_ = false;
    shownSnapshot_ = -2;
    refresh();
  });
}

void FlowPanel::retranslateUi() {
  setWindowTitle(tr("Program flow"));
  stack_->setHeaderLabels({tr("Call stack"), tr("Called from")});
  variables_->setHeaderLabels({tr("Variable"), tr("Value")});
  if (timeline_) showStep(timeline_, snapshot_, previous_, files_, file_, line_);
}

void FlowPanel::changeEvent(QEvent* event) {
  QDockWidget::changeEvent(event);
  if (event->type() == QEvent::LanguageChange) retranslateUi();
}

void FlowPanel::clear() {
  timeline_ = nullptr;
  snapshot_ = previous_ = -1;
  stack_->clear();
  variables_->clear();
  source_->parentWidget()->hide();
}

void FlowPanel::showStep(const machine::Timeline* timeline, int snapshot, int previous,
                         const std::vector<std::string>& files, int file, int line) {
  timeline_ = timeline;
  snapshot_ = snapshot;
  previous_ = previous;
  files_ = files;
  file_ = file;
  line_ = line;
  stack_->clear();
  variables_->clear();
  if (!timeline || snapshot < 0 || snapshot >= static_cast<int>(timeline->snapshots.size())) {
    source_->parentWidget()->hide();
    return;
  }
  const machine::StateSnapshot& s = timeline->snapshots[static_cast<std::size_t>(snapshot)];
  const auto& stacks = timeline->flow.stacks;
  if (s.callStack >= 0 && s.callStack < static_cast<int>(stacks.size())) {
    const auto& frames = stacks[static_cast<std::size_t>(s.callStack)];
    // Innermost first, as debuggers list it.
    for (auto it = frames.rbegin(); it != frames.rend(); ++it) {
      const machine::CallFrame& f = *it;
      QString what;
      switch (f.kind) {
        case machine::CallFrame::Kind::Main: what = tr("main program"); break;
        case machine::CallFrame::Kind::Subprogram: what = tr("subprogram (M98)"); break;
        case machine::CallFrame::Kind::Local: what = tr("local subprogram (M97)"); break;
        case machine::CallFrame::Kind::Macro: what = tr("macro (G65)"); break;
        case machine::CallFrame::Kind::ModalMacro: what = tr("modal macro (G66)"); break;
      }
      QString name = programName(f.program);
      name = name.isEmpty() ? what : QStringLiteral("%1 — %2").arg(name, what);
      if (f.repeats > 1) name += QLatin1Char(' ') + tr("(pass %1 of %2)").arg(f.repeat).arg(f.repeats);
      auto* item = new QTreeWidgetItem(stack_);
      item->setText(0, name);
      if (f.callLine > 0) {
        QString where = tr("line %1").arg(f.callLine);
        if (f.callFile > 0 && f.callFile < static_cast<int>(files.size()))
          where = QStringLiteral("%1: %2").arg(
              QFileInfo(QString::fromStdString(files[static_cast<std::size_t>(f.callFile)])).fileName(), where);
        item->setText(1, where);
        item->setData(0, Qt::UserRole, f.callFile);
        item->setData(0, Qt::UserRole + 1, f.callLine);
      }
      if (it == frames.rbegin()) {
        QFont bold = item->font(0);
        bold.setBold(true);
        item->setFont(0, bold);
      }
    }
  }
  for (const machine::WatchedVariable& v : machine::variablesAt(*timeline, snapshot, previous)) {
    auto* item = new QTreeWidgetItem(variables_);
    item->setText(0, QStringLiteral("#%1").arg(v.number));
    item->setText(1, valueText(v));
    if (v.changed) {
      for (int c = 0; c < 2; ++c) {
        QFont bold = item->font(c);
        bold.setBold(true);
        item->setFont(c, bold);
        item->setForeground(c, QColor(0xb0, 0x30, 0x00));
      }
      item->setData(0, Qt::UserRole, true);  // changed by the last step (tests read it)
    }
  }
  showSource(files, file, line);
}

void FlowPanel::showSource(const std::vector<std::string>& files, int file, int line) {
  QWidget* box = source_->parentWidget();
  if (file <= 0 || file >= static_cast<int>(files.size())) {
    box->hide();
    return;
  }
  const std::string& path = files[static_cast<std::size_t>(file)];
  if (path != sourcePath_) {
    const QString qpath = QString::fromStdString(path);
    auto it = cache_.find(qpath);
    if (it == cache_.end()) {
      QFile f(qpath);
      QString text;
      if (f.open(QIODevice::ReadOnly)) text = QString::fromUtf8(f.read(4 * 1024 * 1024));
      it = cache_.insert(qpath, text);
    }
    source_->setPlainText(*it);
    sourcePath_ = path;
  }
  sourceTitle_->setText(tr("Running in %1, line %2").arg(QFileInfo(QString::fromStdString(path)).fileName()).arg(line));
  box->show();
  const QTextBlock b = source_->document()->findBlockByNumber(line - 1);
  if (b.isValid()) {
    QTextEdit::ExtraSelection sel;
    sel.format.setBackground(QColor(0xff, 0xe8, 0x90));
    sel.format.setProperty(QTextFormat::FullWidthSelection, true);
    sel.cursor = QTextCursor(b);
    source_->setExtraSelections({sel});
    source_->setTextCursor(QTextCursor(b));
    source_->centerCursor();
  }
}

}  // namespace klueng::gui

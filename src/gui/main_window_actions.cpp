// The main window's commands (issue 12): the action table's actions wired to
// their slots, the docks, retranslation, and the choices the menus make
// (dialect, power-on units, animation speed).
#include <QActionGroup>
#include <QAction>
#include <QDir>
#include <QMenu>
#include <QRegularExpression>
#include <QStatusBar>
#include <QToolBar>
#include <QTextDocument>
#include <QTimer>
#include <QTreeWidget>
#include <QUndoGroup>
#include <QUndoStack>
#include <QVBoxLayout>

#include "gui/banner.h"
#include "gui/action_table.h"
#include "gui/class_grade_dialog.h"
#include "gui/code_editor.h"
#include "gui/document.h"
#include "gui/diagnostics_panel.h"
#include "gui/document_manager.h"
#include "gui/flow_panel.h"
#include "gui/help_contents.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/header_strip.h"
#include "gui/part3d_view.h"
#include "gui/operator_panel.h"
#include "gui/part_panel.h"
#include "gui/output_view.h"
#include "gui/run_speed_control.h"
#include "gui/settings.h"
#include "gui/status_panel.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/io/tool_config.h"

namespace klueng::gui {

namespace {

// The Dialect menu's action of a machine ("actionDialectHaas", "actionMachine_romi-gl240m").
QString dialectActionName(core::gcode::Dialect d) {
  switch (d) {
    case core::gcode::Dialect::Fanuc: return QStringLiteral("actionDialectFanuc");
    case core::gcode::Dialect::Haas: return QStringLiteral("actionDialectHaas");
    case core::gcode::Dialect::Classic: return QStringLiteral("actionDialectClassic");
  }
  const std::string_view id = core::gcode::machineProfile(d).id;
  return QStringLiteral("actionMachine_") + QString::fromUtf8(id.data(), static_cast<qsizetype>(id.size()));
}

// Animation speeds: machine seconds per wall second; 0 = as fast as possible.
// The same stops as the tool bar's speed slider.
const std::vector<double>& speeds() { return RunSpeedControl::steps(); }
int speedCount() { return static_cast<int>(speeds().size()); }

}  // namespace

// ---------------------------------------------------------------- actions

QAction* MainWindow::action(const QString& objectName) const { return actions_->action(objectName); }

template <class Slot>
void MainWindow::on(const char* actionName, Slot&& slot) {
  connect(action(QString::fromLatin1(actionName)), &QAction::triggered, this, std::forward<Slot>(slot));
}

void MainWindow::createActions() {
  // The table makes every action, menu and tool bar (action_table.cpp); here each gets its slot.
  actions_ = new ActionTable(this, speedCount());
  actions_->add(QStringLiteral("diagnosticsDock"), diagnostics_->toggleViewAction());
  actions_->add(QStringLiteral("flowDock"), flow_->toggleViewAction());
  actions_->add(QStringLiteral("partDock"), part_->toggleViewAction());
  actions_->add(QStringLiteral("view3dDock"), view3d_->toggleViewAction());
  actions_->add(QStringLiteral("operatorPanelDock"), operatorPanel_->toggleViewAction());
  operatorPanel_->toggleViewAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_M));
  connectOperatorPanel();
  actions_->buildToolBars();
  actions_->buildMenus();
  connect(actions_->menu(QStringLiteral("menuRecent")), &QMenu::aboutToShow, this,
          [this] { docs_->fillRecentMenu(actions_->menu(QStringLiteral("menuRecent"))); });
  connectFileActions();
  connectEditActions();
  connectRunActions();
  createSpeedControl();
  connectSetupActions();
  connectViewAndHelpActions();
}

// The operator panel's buttons act on the window's run (issue 40 item 2).
void MainWindow::connectOperatorPanel() {
  connect(operatorPanel_, &OperatorPanel::cycleStartRequested, this, [this](bool singleBlock) {
    action(singleBlock ? QStringLiteral("actionStep") : QStringLiteral("actionGo"))->trigger();
  });
  connect(operatorPanel_, &OperatorPanel::overridesChanged, runner_, &RunController::setOverrides);
  connect(operatorPanel_, &OperatorPanel::feedHoldRequested, this,
          [this] { operatorPanel_->showFeedHold(runner_->feedHold()); });
  // One run (issue 40 item 2): the panel shows the runner's run, its RESET stops it as Stop does.
  operatorPanel_->followRun(runner_);
  connect(operatorPanel_, &OperatorPanel::resetRequested, this,
          [this] { action(QStringLiteral("actionStop"))->trigger(); });
  connect(operatorPanel_, &OperatorPanel::singleBlockChanged, runner_, &RunController::setSingleBlock);
  connect(operatorPanel_, &OperatorPanel::switchesChanged, this, [this](bool optionalStop, bool blockSkip) {
    action(QStringLiteral("actionOptionalStop"))->setChecked(optionalStop);
    action(QStringLiteral("actionBlockSkip"))->setChecked(blockSkip);
  });
}

void MainWindow::connectFileActions() {
  on("actionNew", [this] { newFile(); });
  on("actionOpen", [this] { open(); });
  on("actionSave", [this] { save(); });
  on("actionSaveAs", [this] { saveAs(); });
  on("actionJobDetails", [this] { showJobDetails(); });
  on("actionPrintCode", [this] { printCode(); });
  on("actionPrint", [this] { printCodeNow(); });
  on("actionPrintDrawing", [this] { printDrawing(); });
  on("actionPrintPreview", [this] { printPreview(); });
  on("actionExportPdf", [this] { exportPdf(); });
  on("actionGradeClass", [this] {
    // Graded against offset.cfg as it is on disk: the operator panel's touch-off (the exercise's
    // entries) is this window's run, not the class's true offsets (issue 31 item 5).
    core::machine::MachineSetup setup = jobDoc_.setup();
    const auto shipped =
        core::io::readOffsetTable(QDir(configDir_).filePath(QStringLiteral("offset.cfg")).toStdString());
    if (shipped.value) setup.offsets = *shipped.value;
    auto* dialog = new ClassGradeDialog(setup, jobDoc_.dialect(), document_->filePath(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &ClassGradeDialog::openProgram, this, [this](const QString& path) { openFile(path); });
    dialog->show();
  });
  on("actionPartDesigner", [this] { showPartDesigner(); });
  on("actionExit", [this] { close(); });
}

// Edit: one Undo / Redo for the document's edits, text and setup alike (issue 30 item 2):
// the group follows the active document's stack; the rest are the editor's own commands.
void MainWindow::connectEditActions() {
  on("actionUndo", [this] { undoGroup_->undo(); });
  on("actionRedo", [this] { undoGroup_->redo(); });
  on("actionCut", [this] { editor_->cut(); });
  on("actionCopy", [this] { editor_->copy(); });
  on("actionPaste", [this] { editor_->paste(); });
  on("actionDelete", [this] { editor_->textCursor().removeSelectedText(); });
  on("actionSelectAll", [this] { editor_->selectAll(); });
  for (const char* n : {"actionCut", "actionCopy", "actionDelete"}) action(QString::fromLatin1(n))->setEnabled(false);
  for (const char* n : {"actionCut", "actionCopy", "actionDelete"})
    connect(editor_, &QPlainTextEdit::copyAvailable, action(QString::fromLatin1(n)), &QAction::setEnabled);
  connectUndoActions();
  on("actionFind", [this] { showFind(); });
  on("actionReplace", [this] { showFind(); });
  on("actionGoToLine", [this] { goToLine(); });
}

// Undo and Redo name the step they would take, and are off while a run animates the text.
void MainWindow::connectUndoActions() {
  QAction* undo = action(QStringLiteral("actionUndo"));
  QAction* redo = action(QStringLiteral("actionRedo"));
  editor_->setUndoActions(undo, redo);  // its keys and context menu go through the stack too
  updateUndo_ = [this, undo, redo] {
    // Not while a run animates the text it was given (the editor is read-only then too).
    const bool idle = !runner_ || ActionTable::enabledIn(EnabledWhen::NotRunning, runner_->state());
    undo->setEnabled(idle && undoGroup_->canUndo());
    redo->setEnabled(idle && undoGroup_->canRedo());
    // The step it would undo, named: "Undo Tool Select", "Redo Typing".
    undo->setText(undoGroup_->canUndo() ? tr("&Undo %1").arg(undoGroup_->undoText()) : tr("&Undo"));
    redo->setText(undoGroup_->canRedo() ? tr("&Redo %1").arg(undoGroup_->redoText()) : tr("&Redo"));
    // The tip without the mnemonic, the Thai "(U)" form included: "Undo Typing".
    static const QRegularExpression mnemonic(QStringLiteral(R"(\s*\(&.\)|&)"));
    undo->setStatusTip(undo->text().remove(mnemonic));
    redo->setStatusTip(redo->text().remove(mnemonic));
    for (QAction* a : {undo, redo})
      a->setToolTip(QStringLiteral("%1 (%2)").arg(a->statusTip(), a->shortcut().toString(QKeySequence::NativeText)));
  };
  connect(undoGroup_, &QUndoGroup::indexChanged, this, [this] { updateUndo_(); });
  connect(undoGroup_, &QUndoGroup::activeStackChanged, this, [this] { updateUndo_(); });
  connect(undoGroup_, &QUndoGroup::canUndoChanged, this, [this] { updateUndo_(); });
  connect(undoGroup_, &QUndoGroup::canRedoChanged, this, [this] { updateUndo_(); });
  connect(runner_, &RunController::stateChanged, this, [this] { updateUndo_(); });
  updateUndo_();
}

// Run: the runner gets the editor's text first.
void MainWindow::connectRunActions() {
  const auto run = [this](void (RunController::*command)()) {
    return [this, command] {
      syncRunner();
      hideBanner();
      (runner_->*command)();
    };
  };
  on("actionGo", run(&RunController::go));
  on("actionStep", run(&RunController::stepOver));    // F10: one block of this level
  on("actionStepInto", run(&RunController::step));    // F11: into calls
  on("actionStepOut", run(&RunController::stepOut));  // Shift+F11: out of one
  on("actionPause", [this] { runner_->pause(); });
  on("actionStop", [this] {
    runner_->stop();
    editor_->setExecutingLine(0);
  });
  on("actionStepBack", [this] { runner_->stepBack(); });
  on("actionRunToCursor", [this] { runToCursor(); });
  on("actionToggleBreakpoint", [this] { toggleBreakpoint(); });
  QAction* optStop = action(QStringLiteral("actionOptionalStop"));
  optStop->setChecked(settings_->optionalStop());
  connect(optStop, &QAction::toggled, this, [this](bool checked) {
    runner_->setOptionalStop(checked);
    statusLamps_->setOptionalStopSwitch(checked);
    settings_->setOptionalStop(checked);
  });
  QAction* skip = action(QStringLiteral("actionBlockSkip"));
  skip->setChecked(settings_->blockSkip());
  connect(skip, &QAction::toggled, this, [this](bool checked) {
    runner_->setBlockSkip(checked);
    settings_->setBlockSkip(checked);
  });
}

// Run > Speed and the run tool bar's slider: the same choice.
void MainWindow::createSpeedControl() {
  for (int i = 0; i < speedCount(); ++i)
    connect(action(QStringLiteral("actionSpeed%1").arg(i)), &QAction::triggered, this, [this, i] { setSpeedIndex(i); });
  speedControl_ = new RunSpeedControl(this);
  speedControl_->setObjectName(QStringLiteral("speedControl"));
  speedControl_->setRunController(runner_);
  // The slider and the Run > Speed menu show the same choice.
  connect(speedControl_, &RunSpeedControl::speedChanged, this, [this](double factor) {
    for (int i = 0; i < speedCount(); ++i)
      if (speeds()[static_cast<std::size_t>(i)] == factor)
        action(QStringLiteral("actionSpeed%1").arg(i))->setChecked(true);
  });
  QToolBar* runBar = actions_->toolBar(QStringLiteral("runToolBar"));
  runBar->addSeparator();
  runBar->addWidget(speedControl_);
  setSpeedIndex(static_cast<int>(std::find(speeds().begin(), speeds().end(), 1.0) - speeds().begin()));
}

// Tool setting: the tables, the machine (dialect), the power-on and the shown units.
void MainWindow::connectSetupActions() {
  on("actionToolSelect", [this] { showToolSelect(); });
  on("actionOffsetDefine", [this] { showOffsetDefine(); });
  for (const core::gcode::Dialect d :
       {core::gcode::Dialect::Fanuc, core::gcode::Dialect::Haas, core::gcode::Dialect::Classic}) {
    QAction* a = action(dialectActionName(d));
    a->setChecked(d == jobDoc_.dialect());
    connect(a, &QAction::triggered, this, [this, d] { setDialect(d); });
  }
  const std::pair<const char*, std::optional<core::gcode::InputUnits>> unitChoices[] = {
      {"actionUnitsMachine", std::nullopt},
      {"actionUnitsMm", core::gcode::InputUnits::Millimetre},
      {"actionUnitsInch", core::gcode::InputUnits::Inch}};
  for (const auto& [name, units] : unitChoices) {
    QAction* a = action(QString::fromLatin1(name));
    a->setChecked(units == jobDoc_.powerOnUnits());
    const auto u = units;
    connect(a, &QAction::triggered, this, [this, u] { setPowerOnUnits(u); });
  }

  const std::pair<const char*, std::optional<core::DisplayUnits>> shownChoices[] = {
      {"actionShowUnitsAuto", std::nullopt},
      {"actionShowUnitsMm", core::DisplayUnits::Mm},
      {"actionShowUnitsInch", core::DisplayUnits::Inch}};
  for (const auto& [name, units] : shownChoices) {
    QAction* a = action(QString::fromLatin1(name));
    a->setChecked(units == shownUnits_);
    const auto u = units;
    connect(a, &QAction::triggered, this, [this, u] { setShownUnits(u); });
  }
}

// View and Help.
void MainWindow::connectViewAndHelpActions() {
  on("actionFitView", [this] { output_->fitToView(); });
  on("actionZoomIn", [this] { output_->zoomIn(); });
  on("actionZoomOut", [this] { output_->zoomOut(); });
  for (const char* n : {"actionShowPath", "actionShowStatusBar", "actionShowLamps"})
    action(QString::fromLatin1(n))->setChecked(true);
  connect(action(QStringLiteral("actionShowPath")), &QAction::toggled, output_, &OutputView::setShowPath);
  connect(action(QStringLiteral("actionShowStatusBar")), &QAction::toggled, statusBar(), &QWidget::setVisible);
  connect(action(QStringLiteral("actionShowLamps")), &QAction::toggled, statusLamps_, &QWidget::setVisible);
  on("actionContents", [this] { showHelpContents(); });
  on("actionToggleLanguage", [this] { toggleLanguage(); });
  on("actionAbout", [this] { showAbout(); });
}

void MainWindow::createDocks() {
  diagnostics_ = new DiagnosticsPanel(this);
  addDockWidget(Qt::BottomDockWidgetArea, diagnostics_);
  flow_ = new FlowPanel(this);
  addDockWidget(Qt::BottomDockWidgetArea, flow_);
  tabifyDockWidget(diagnostics_, flow_);
  diagnostics_->raise();
  flow_->follow(runner_);
  connect(flow_, &FlowPanel::callerActivated, this, [this](int file, int line) {
    if (file == 0) editor_->goToFileLine(line, 1);
  });
  // Issue 10: the part's features, the part check and the compensation comparison.
  part_ = new PartPanel(this, [this] {
    PartPanel::Source source;
    source.program = currentProgramFile();
    source.setup = jobDoc_.tools().setup;
    source.run.dialect = jobDoc_.dialect();
    source.run.powerOnUnits = jobDoc_.powerOnUnits();
    source.folder = programFolder().toStdString();
    return source;
  });
  addDockWidget(Qt::BottomDockWidgetArea, part_);
  tabifyDockWidget(flow_, part_);
  diagnostics_->raise();
  // Issue 28 item 8: the bottom docks share one height, enough for the
  // diagnostics but 3 rows of the Part list at 768 px. When the Part tab first
  // shows in a session, the docks grow to show 6 rows of it; a height the user
  // sets after that stays.
  connect(part_, &QDockWidget::visibilityChanged, this, [this](bool visible) {
    if (!visible || partDockGrown_ || part_->isFloating()) return;
    partDockGrown_ = true;
    QTimer::singleShot(0, this, [this] {
      QTreeWidget* list = part_->list();
      const int row =
          std::max(list->fontMetrics().height() + 6, list->topLevelItemCount() > 0 ? list->sizeHintForRow(0) : 0);
      const int need = part_->height() - list->viewport()->height() + 6 * row;
      if (part_->height() < need) resizeDocks({part_}, {need}, Qt::Vertical);
    });
  });
  // Issue 11: what lines 1-6 are, above the editor (a click edits them).
  auto* header = new HeaderStrip(editor_->parentWidget());
  if (auto* pane = qobject_cast<QVBoxLayout*>(editor_->parentWidget()->layout()))
    pane->insertWidget(pane->indexOf(editor_), header);
  const auto showHeader = [this, header] { header->showHeader(document_->header(), document_->isPlainGcode()); };
  connect(document_, &Document::headerChanged, header, showHeader);
  connect(docs_, &DocumentManager::cleared, header, showHeader);
  connect(docs_, &DocumentManager::loaded, header, showHeader);
  connect(header, &HeaderStrip::activated, this, &MainWindow::showJobDetails);
  showHeader();
  // Issue 10: the 3D view, on the right beside the editor and the output screen; hidden at first.
  view3d_ = new Part3DDock(this);
  addDockWidget(Qt::RightDockWidgetArea, view3d_);
  view3d_->view()->setRunController(runner_);
  view3d_->hide();
  // Issue 31: the operator panel beside the output screen; its touch-off gives the run its offset rows.
  operatorPanel_ = new OperatorPanel(this, [this] {
    return OperatorPanel::Source{jobDoc_.tools().setup, document_->header(),  jobDoc_.dialect(),
                                 runner_->timeline(),   currentProgramFile(), document_->filePath()};
  });
  addDockWidget(Qt::RightDockWidgetArea, operatorPanel_);
  // The right-hand docks (the panel, the 3D view) run down to the status bar, beside the bottom
  // docks: on a 1366 x 768 screen the panel's keys then fit down to the last row (issue 40 item 4).
  setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
  operatorPanel_->hide();
  connect(operatorPanel_, &OperatorPanel::offsetsChanged, this, [this](const core::io::OffsetTable& offsets) {
    // The control's offset rows, for the run only: not offset.cfg (power on starts from the
    // setup's again), so no edit to undo or save. The run takes them at once; the next check's Job too.
    core::machine::MachineSetup run = jobDoc_.tools().setup;
    run.offsets = offsets;
    jobDoc_.setOffsets(offsets);
    runner_->setMachineSetup(run);
    checkNow();
  });
  connect(part_, &PartPanel::overlayChanged, output_, &OutputView::setPartOverlay);
  // Real edits only: re-colouring by the highlighter changes no characters.
  connect(editor_->document(), &QTextDocument::contentsChange, part_, [this](int, int removed, int added) {
    if (removed != 0 || added != 0) part_->invalidate();
  });
  connect(document_, &Document::headerChanged, part_, &PartPanel::invalidate);
  connect(part_, &PartPanel::lineActivated, this, [this](int line) { editor_->goToFileLine(line, 1); });
  connect(part_, &PartPanel::measuringToggled, output_, &OutputView::setMeasuring);
  connect(output_, &OutputView::measured, this, [this](const QString& reading) { statusBar()->showMessage(reading); });
  connect(output_, &OutputView::cursorPositionChanged, this, [this](double xDiameter, double z) {
    if (!output_->isMeasuring() || statusBar()->currentMessage().isEmpty())
      statusBar()->showMessage(tr("Z %1   Ø %2   %3")
                                   .arg(QString::fromStdString(displayUnits().position(z)),
                                        QString::fromStdString(displayUnits().position(xDiameter)),
                                        displayUnits().inch() ? tr("in") : tr("mm")),
                               3000);
  });
}

void MainWindow::updateMachineMenu() {
  QMenu* menu = actions_->menu(QStringLiteral("menuDialect"));
  QAction* fanuc = action(QStringLiteral("actionDialectFanuc"));
  if (!menu || !fanuc) return;
  // After the shipped three, before the separator of the power-on units.
  QAction* before = action(QStringLiteral("actionUnitsMachine"));
  const QList<QAction*> items = menu->actions();
  const qsizetype at = items.indexOf(before);
  if (at > 0 && items[at - 1]->isSeparator()) before = items[at - 1];
  const bool thai = Language::coreLang() == core::Lang::Th;
  for (const core::gcode::MachineProfile* p : core::gcode::machineProfiles()) {
    if (static_cast<int>(p->dialect) < 3) continue;
    const QString name = dialectActionName(p->dialect);
    QAction* a = action(name);
    if (!a) {
      a = new QAction(this);
      a->setObjectName(name);
      a->setCheckable(true);
      if (fanuc->actionGroup()) fanuc->actionGroup()->addAction(a);
      menu->insertAction(before, a);
      actions_->add(name, a);
      const core::gcode::Dialect d = p->dialect;
      connect(a, &QAction::triggered, this, [this, d] { setDialect(d); });
    }
    const std::string_view text = thai ? p->nameTh : p->nameEn;
    a->setText(QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size())));
    a->setChecked(p->dialect == jobDoc_.dialect());
  }
}

void MainWindow::retranslateUi() {
  // The status bar may show an action's tip (the mouse over its button or menu item, as over
  // Toggle Language when it is clicked): it says it again in the new language.
  QAction* tipShown = nullptr;
  if (const QString shown = statusBar()->currentMessage(); !shown.isEmpty())
    for (QAction* a : findChildren<QAction*>())
      if (a->statusTip() == shown) {
        tipShown = a;
        break;
      }
  actions_->retranslate();
  if (tipShown) statusBar()->showMessage(tipShown->statusTip());
  updateMachineMenu();
  updateUndo_();  // Undo / Redo name the step in the new language
  updateTitle();
  updateStockLabel();
  // The banner says what it said, in the new language.
  if (bannerMaker_ && !banner_->text().isEmpty()) banner_->showMessage(bannerMaker_(), bannerError_);
}

void MainWindow::changeEvent(QEvent* event) {
  QMainWindow::changeEvent(event);
  if (event->type() == QEvent::LanguageChange && actions_) retranslateUi();
}

void MainWindow::toggleLanguage() {
  Language::instance()->toggle();
  settings_->setLanguage(Language::instance()->language());
}

void MainWindow::setDialect(core::gcode::Dialect d) {
  settings_->setDialect(d);
  useMachineForThisProgram(d);
}

void MainWindow::takeMachineOffer(core::gcode::Dialect d) {
  jobDoc_.undoStack()->beginMacro(tr("Use the offered machine"));
  nameMachineInProgram(std::string(core::gcode::machineProfile(d).id));
  jobDoc_.undoStack()->endMacro();
  useMachineForThisProgram(d);
}

void MainWindow::useMachineForThisProgram(core::gcode::Dialect d) {
  const bool machineKeys =
      !core::gcode::machineProfile(d).file.empty() || !core::gcode::machineProfile(jobDoc_.dialect()).file.empty();
  jobDoc_.setDialect(d);
  // A machine file's machine.cfg keys (rapids, travel ...) are part of the setup: read it again with them.
  if (machineKeys && !configDir_.isEmpty()) loadMachineSetup();
  editor_->setDialect(d);
  runner_->setDialect(d);
  action(dialectActionName(d))->setChecked(true);
  if (help_) help_->setDialect(d);
  if (operatorPanel_ && operatorPanel_->control()) operatorPanel_->powerOn();  // another machine, its own control
  // The same plain text may approach the part elsewhere in another dialect (units, cycle forms):
  // the next check's Job says where (off the GUI thread).
  restockOnNextCheck_ = true;
  checkNow();
}

void MainWindow::setShownUnits(std::optional<core::DisplayUnits> units) {
  shownUnits_ = units;
  settings_->setShownUnits(units);
  action(!units                               ? QStringLiteral("actionShowUnitsAuto")
         : *units == core::DisplayUnits::Inch ? QStringLiteral("actionShowUnitsInch")
                                              : QStringLiteral("actionShowUnitsMm"))
      ->setChecked(true);
  applyDisplayUnits();
}

void MainWindow::setPowerOnUnits(std::optional<core::gcode::InputUnits> units) {
  jobDoc_.setPowerOnUnits(units);
  settings_->setPowerOnUnits(units);
  runner_->setPowerOnUnits(units);
  action(!units                                    ? QStringLiteral("actionUnitsMachine")
         : *units == core::gcode::InputUnits::Inch ? QStringLiteral("actionUnitsInch")
                                                   : QStringLiteral("actionUnitsMm"))
      ->setChecked(true);      // the group unchecks the others
  restockOnNextCheck_ = true;  // inch or mm changes the approach: the next check's Job says the bar
  checkNow();
}

void MainWindow::setSpeedIndex(int index) {
  index = std::clamp(index, 0, speedCount() - 1);
  const double factor = speeds()[static_cast<std::size_t>(index)];
  speedControl_->setSpeed(factor);
  runner_->setSpeed(factor);
  action(QStringLiteral("actionSpeed%1").arg(index))->setChecked(true);
}

}  // namespace klueng::gui

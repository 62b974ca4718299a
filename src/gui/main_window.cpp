#include "gui/main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QProgressBar>
#include <QScreen>
#include <QSplitter>
#include <QTextCursor>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <QUndoGroup>
#include <QUndoStack>
#include <QtConcurrent/QtConcurrentRun>

#include "gui/about_dialog.h"
#include "gui/action_table.h"
#include "gui/banner.h"
#include "gui/code_editor.h"
#include "gui/diagnostics_panel.h"
#include "gui/cutting_plot.h"
#include "gui/explain_bar.h"
#include "render/report_sheets.h"
#include "gui/dialect_offer_bar.h"
#include "gui/first_steps_bar.h"
#include "klueng/core/io/tool_config.h"
#include "gui/document_manager.h"
#include "gui/file_save.h"
#include "gui/find_dialog.h"
#include "gui/flow_panel.h"
#include "gui/help_contents.h"
#include "gui/job_details_dialog.h"
#include "gui/language.h"
#include "gui/offset_define_dialog.h"
#include "gui/output_view.h"
#include "gui/part_designer.h"
#include "gui/recovery_bar.h"
#include "gui/report_controller.h"
#include "gui/run_speed_control.h"
#include "gui/setup_strip.h"
#include "gui/settings.h"
#include "gui/setup_commands.h"
#include "gui/setup_save.h"
#include "gui/job_tools.h"
#include "klueng/core/io/tool_library.h"
#include "gui/part_panel.h"
#include "gui/status_panel.h"
#include "gui/tool_select_dialog.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/macro.h"
#include "klueng/core/machine/flow_view.h"
#include "klueng/core/machine/machine_files.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/messages.h"

namespace klueng::gui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), settings_(std::make_unique<Settings>()) {
  takeSettings();
  createEditorAndRunner();
  createDocumentControllers();
  createCentralArea();
  createStatusBar();
  createChecker();
  createUndoGroup();
  createDocks();
  createActions();
  connectDocuments();
  connectEditing();
  connectRunner();
  startUp();
}

// The machine, units and switches the user last chose.
void MainWindow::takeSettings() {
  setObjectName(QStringLiteral("mainWindow"));
  setWindowIcon(QIcon(QStringLiteral(":/icons/klueng.svg")));
  jobDoc_.setDialect(settings_->dialect());
  jobDoc_.setPowerOnUnits(settings_->powerOnUnits());
  shownUnits_ = settings_->shownUnits();
  programUnits_ =
      core::gcode::powerOnUnitsOf(jobDoc_.dialect(), jobDoc_.powerOnUnits()) == core::gcode::InputUnits::Inch
          ? core::DisplayUnits::Inch
          : core::DisplayUnits::Mm;  // until the first check says the program's
}

void MainWindow::createEditorAndRunner() {
  editor_ = new CodeEditor(this);
  editor_->setObjectName(QStringLiteral("codeEditor"));
  editor_->setDialect(jobDoc_.dialect());

  runner_ = new RunController(this);
  runner_->setLastCheck([this] { return jobDoc_.job(); });
  runner_->setDialect(jobDoc_.dialect());
  runner_->setPowerOnUnits(jobDoc_.powerOnUnits());
  runner_->setOptionalStop(settings_->optionalStop());
  runner_->setBlockSkip(settings_->blockSkip());
}

// The open program, its loading and saving, and the reports and prints made of it.
void MainWindow::createDocumentControllers() {
  docs_ = new DocumentManager(this, editor_, settings_.get());
  document_ = docs_->document();
  reports_ = new ReportController(this, [this] {
    ReportController::Source source;
    source.program = currentProgramFile();
    source.displayName = document_->displayName();
    source.filePath = document_->filePath();
    source.setup = jobDoc_.tools().setup;
    source.dialect = jobDoc_.dialect();
    source.units = displayUnits();
    source.design = document_->design();
    return source;
  });
  connect(reports_, &ReportController::message, statusBar(), &QStatusBar::showMessage);
}

// The editor on the left (with its bars), the output screen on the right.
void MainWindow::createCentralArea() {
  output_ = new OutputView(this);
  output_->setObjectName(QStringLiteral("outputView"));
  output_->setRunController(runner_);
  QWidget* editorPane = createEditorPane();
  QWidget* outputPane = createOutputPane();
  splitter_ = new QSplitter(Qt::Horizontal, this);
  splitter_->setObjectName(QStringLiteral("mainSplitter"));
  splitter_->addWidget(editorPane);
  splitter_->addWidget(outputPane);
  splitter_->setStretchFactor(0, 2);
  splitter_->setStretchFactor(1, 3);
  splitter_->setChildrenCollapsible(false);
  setCentralWidget(splitter_);
}

// The editor with the bars above it (alarms, first steps, recovery, the machine offer) and below it.
QWidget* MainWindow::createEditorPane() {
  // Banner above the editor: alarms and refused runs, in the UI language.
  banner_ = new Banner(this);
  auto* pane = new QWidget(this);
  auto* editorLayout = new QVBoxLayout(pane);
  editorLayout->setContentsMargins(0, 0, 0, 0);
  editorLayout->setSpacing(0);
  editorLayout->addWidget(banner_);
  firstSteps_ = new FirstStepsBar(this);
  editorLayout->addWidget(firstSteps_);
  recoveryBar_ = new RecoveryBar(this);
  editorLayout->addWidget(recoveryBar_);
  dialectOffer_ = new DialectOfferBar(this);
  connect(dialectOffer_, &DialectOfferBar::switchRequested, this, &MainWindow::takeMachineOffer);
  editorLayout->addWidget(dialectOffer_);
  editorLayout->addWidget(editor_, 1);
  explainBar_ = new ExplainBar(runner_, editor_, this);
  editorLayout->addWidget(explainBar_);
  editor_->setLineExplainer([this](int fileLine) { return explainBar_->explainLine(fileLine); });
  return pane;
}

// The output screen with the setup strip above it and the lamps below.
QWidget* MainWindow::createOutputPane() {
  statusLamps_ = new StatusLamps(this);
  statusLamps_->setObjectName(QStringLiteral("statusLamps"));
  statusLamps_->setOptionalStopSwitch(settings_->optionalStop());
  auto* pane = new QWidget(this);
  auto* outputLayout = new QVBoxLayout(pane);
  outputLayout->setContentsMargins(0, 0, 0, 0);
  outputLayout->setSpacing(2);
  // SPEC 2 (ext), issue 26: where the stock came from and, for a plain file, the
  // tools guessed from the program, before a run; a click changes one.
  setupStrip_ = new SetupStrip(pane);
  connect(setupStrip_, &SetupStrip::stockActivated, this, &MainWindow::showJobDetails);
  connect(setupStrip_, &SetupStrip::stationActivated, this, &MainWindow::showToolSelectFor);
  connect(setupStrip_, &SetupStrip::pointReadingActivated, this, &MainWindow::showJobDetails);
  connect(setupStrip_, &SetupStrip::toolSideActivated, this, &MainWindow::showJobDetails);
  outputLayout->addWidget(setupStrip_);
  outputLayout->addWidget(output_, 1);
  // Spindle power and Vc over the cycle time (issue 39), from the explain bar's cutting data.
  cuttingPlot_ = new CuttingPlot(runner_, pane);
  connect(explainBar_, &ExplainBar::cuttingDataReady, cuttingPlot_, &CuttingPlot::setData);
  outputLayout->addWidget(cuttingPlot_);
  outputLayout->addWidget(statusLamps_);
  return pane;
}

void MainWindow::createStatusBar() {
  statusFields_ = new StatusFields(this);
  statusFields_->setObjectName(QStringLiteral("statusFields"));
  statusBar()->addWidget(statusFields_, 1);
  // The busy bar sits at the right end of the menu bar, which has room in
  // both languages: in the status bar it took 140 px the fields need at 1366 px.
  busyBar_ = new QProgressBar(this);
  busyBar_->setObjectName(QStringLiteral("busyBar"));
  busyBar_->setRange(0, 0);
  busyBar_->setFixedWidth(120);
  busyBar_->setMaximumHeight(menuBar()->fontMetrics().height());
  busyBar_->setTextVisible(false);
  busyBar_->hide();
  menuBar()->setCornerWidget(busyBar_, Qt::TopRightCorner);
}

void MainWindow::createChecker() {
  checker_ = new CheckController(
      this, [this] { return editor_->toPlainText(); }, [this] { return checkRequest(); });
  connect(checker_, &CheckController::started, this,
          [this] { QTimer::singleShot(300, this, &MainWindow::showBusyIndicator); });
  connect(checker_, &CheckController::finished, this, &MainWindow::onCheckFinished);
}

void MainWindow::createUndoGroup() {
  // One Edit > Undo for the text and the setup (issue 30 item 2): the editor's undo steps
  // go onto the document's stack as commands (setup_commands.h), beside the setup edits.
  undoGroup_ = new QUndoGroup(this);
  undoGroup_->addStack(jobDoc_.undoStack());
  undoGroup_->setActiveStack(jobDoc_.undoStack());
  auto pushingText = std::make_shared<bool>(false);
  connect(editor_->document(), &QTextDocument::undoCommandAdded, this, [this, pushingText] {
    if (docs_->isFillingEditor()) return;
    *pushingText = true;
    jobDoc_.undoStack()->push(new TextEditCommand(editor_));
    *pushingText = false;
    editor_->setNewUndoStep(false);  // typing goes on into this step
  });
  // Any other move of the stack (a setup edit, an undo, a redo): the next typing is a new step.
  connect(jobDoc_.undoStack(), &QUndoStack::indexChanged, this, [this, pushingText] {
    if (!*pushingText) editor_->setNewUndoStep(true);
  });
}

// The program's edits: the check, the stock drawn, the breakpoints, a diagnostic's line.
void MainWindow::connectEditing() {
  // Only real edits re-check; the highlighter's re-colouring changes no characters.
  connect(editor_->document(), &QTextDocument::contentsChange, this, [this](int, int removed, int added) {
    if ((removed == 0 && added == 0) || docs_->isFillingEditor()) return;
    // What the last run said (its alarm, its end, its notices) was about the old text.
    if (!banner_->text().isEmpty() && (bannerKind_ == BannerKind::Alarm || bannerKind_ == BannerKind::RunEnded))
      hideBanner();
    // A run stopped by an alarm points at a block of the old text: the runner
    // takes the new text, which leaves nothing of that run (arrow, cut, time).
    if (runner_->state() == RunState::Alarm) syncRunner();
    if (!runDiagnostics_.empty()) {
      runDiagnostics_.clear();
      showDiagnostics();
    }
    checker_->schedule();
  });
  connect(document_, &Document::headerChanged, this, [this] {
    updateStockLabel();
    // Draw the new stock at once; the runner re-reads the whole program before a run.
    if (runner_->state() == RunState::Idle && !runner_->isBusy()) {
      core::io::ProgramFile stockOnly;
      stockOnly.header = document_->header();
      runner_->setProgram(stockOnly, document_->displayName());
    }
  });
  connect(editor_, &CodeEditor::breakpointsChanged, this, [this] {
    const QList<int> lines = editor_->breakpointFileLines();
    runner_->setBreakpoints(QSet<int>(lines.begin(), lines.end()));
  });
  connect(diagnostics_, &DiagnosticsPanel::diagnosticActivated, this, [this](int line, int column) {
    if (line >= editor_->firstFileLine())
      editor_->goToFileLine(line, column);
    else if (line >= 1 && !document_->isPlainGcode())
      showJobDetails();  // a header line
  });
}

// What the run shows: the executing line, the words' values, the status bar and lamps, alarms.
void MainWindow::connectRunner() {
  connect(runner_, &RunController::executingLineChanged, editor_, &CodeEditor::setExecutingLine);
  editor_->setWordValueLookup([this](int fileLine, int column) -> QString {
    const core::machine::Timeline* t = runner_->timeline();
    if (!t || runner_->currentSnapshot() < 0) return {};
    const auto v = core::machine::wordValueAt(*t, runner_->currentSnapshot(), 0, fileLine, column);
    if (!v) return {};
    return v->vacant ? tr("vacant (the address was left out)")
                     : QString::fromStdString(core::gcode::macroNumberText(v->value));
  });
  connect(runner_, &RunController::statusChanged, statusFields_, &StatusFields::setStatus);
  connect(runner_, &RunController::statusChanged, statusLamps_, &StatusLamps::setStatus);
  connect(runner_, &RunController::stateChanged, this, &MainWindow::onRunStateChanged);
  connect(runner_, &RunController::alarmRaised, this, &MainWindow::onAlarm);
  connect(runner_, &RunController::checkFailed, this, &MainWindow::onCheckFailed);
  connect(runner_, &RunController::busyChanged, this, [this](bool busy) {
    if (busy)
      QTimer::singleShot(300, this, &MainWindow::showBusyIndicator);
    else if (!isBusy())
      busyBar_->hide();
  });
}

// The setup files, the language, the layout, an empty program; unsaved work to recover; first steps.
void MainWindow::startUp() {
  loadMachineSetup();
  Language::instance()->setLanguage(settings_->language());
  retranslateUi();
  restoreLayout();
  newFile();
  onRunStateChanged(RunState::Idle);
  // Unsaved work a crash, a kill or a power cut left behind (issue 13).
  recoveryBar_->offer(docs_->recovery().orphans());
  // A first start (no file ever opened): what to do first, the samples one
  // click away (issue 28 item 8). Gone once a program is in the editor.
  connect(firstSteps_, &FirstStepsBar::openRequested, this, [this](const QString& path) { openFile(path); });
  connect(firstSteps_, &FirstStepsBar::browseRequested, docs_, &DocumentManager::open);
  connect(docs_, &DocumentManager::loaded, firstSteps_, &QWidget::hide);
  if (settings_->recentFiles().isEmpty() && recoveryBar_->pending().isEmpty())
    firstSteps_->offer(QString::fromStdString(core::io::samplesDir()));
}

MainWindow::~MainWindow() {
  // The stack goes with jobDoc_, before the group and the actions: nothing may call back.
  undoGroup_->disconnect(this);
  jobDoc_.undoStack()->disconnect(this);
  jobDoc_.undoStack()->clear();
}

// ---------------------------------------------------------------- documents

void MainWindow::connectDocuments() {
  connect(docs_, &DocumentManager::modificationChanged, this, &MainWindow::updateTitle);
  connect(docs_, &DocumentManager::aboutToReplace, this, [this] {
    runner_->stop();
    hideBanner();
    output_->clearMeasurement();  // measured on the old file's part
    statusBar()->clearMessage();  // and its reading
    // Diagnostics belong to their file (issue 11): none of the old file's
    // errors or alarms may underline a line of the new one.
    runDiagnostics_.clear();
    lastDiagnostics_.clear();
    showDiagnostics();
  });
  docs_->setSetupHooks({[this] { return jobDoc_.isSetupModified(); },
                        [this](const QString& programPath) { return saveSetup(programPath); },
                        [this] {
                          RecoverySetup r;
                          r.present = true;
                          r.dir = configDir_;
                          r.tools = QByteArray::fromStdString(core::io::formatToolTable(jobDoc_.setup().tools));
                          r.offsets = QByteArray::fromStdString(core::io::formatOffsetTable(jobDoc_.setup().offsets));
                          for (const auto& o : jobDoc_.overrides())
                            r.overrides << QStringLiteral("%1=%2").arg(o.station).arg(
                                QString::fromStdString(o.libraryId));
                          return r;
                        },
                        [this](const RecoverySetup& r) {
                          // As the tables were in memory: unsaved, against the files on disk.
                          const std::string dir = r.dir.isEmpty() ? configDir_.toStdString() : r.dir.toStdString();
                          SetupEdit e = jobDoc_.edit();
                          if (auto t = core::io::parseToolTable(r.tools.toStdString(), dir, "tools.cfg",
                                                                jobDoc_.setup().machine.turretStations);
                              t.value)
                            e.tools = *t.value;
                          if (auto o = core::io::parseOffsetTable(r.offsets.toStdString(), "offset.cfg"); o.value)
                            e.offsets = *o.value;
                          e.overrides.clear();
                          for (const QString& item : r.overrides) {
                            core::machine::StationOverride o;
                            std::string error;
                            if (core::machine::parseStationOverride(item.toStdString(), core::io::kMaxStations,
                                                                    core::io::shippedToolLibrary(), o, error))
                              e.overrides.push_back(o);
                          }
                          applySetupEdit(e);
                        },
                        [this] {
                          // Every file the run reads besides the program itself: the setup, the tool
                          // pictures, the library, the machines, the subprogram files (F126, issue 42).
                          std::vector<std::string> inputs = setupInputs(jobDoc_.setup());
                          if (const auto& job = jobDoc_.job(); job && job->program())
                            for (std::size_t k = 1; k < job->program()->files.size(); ++k)
                              inputs.push_back(job->program()->files[k]);
                          return inputs;
                        }});
  connect(docs_, &DocumentManager::cleared, this, [this] {
    jobDoc_.undoStack()->clear();  // one undo history per document
    revertSetup();
    updateTitle();
    checkNow();
  });
  connect(docs_, &DocumentManager::busyChanged, this, [this] {
    if (docs_->isLoading())
      QTimer::singleShot(300, this, &MainWindow::showBusyIndicator);
    else if (!isBusy() && !runner_->isBusy())
      busyBar_->hide();
  });
  connect(docs_, &DocumentManager::loadFailed, this, &MainWindow::loadFailed);
  connect(docs_, &DocumentManager::loaded, this, [this](const QString& path, const QString& text) {
    jobDoc_.undoStack()->clear();
    revertSetup();
    jobDoc_.setSavedOverrides(loadToolOverrides(path));
    updateTitle();
    // A program that names its machine at its head ((MACHINE: id), issue 27) selects it, for
    // itself; one that names none is read on the menu's machine (an earlier file's is not kept).
    core::gcode::Dialect named{};
    if (!core::gcode::parseDialectId(document_->header().machine, named)) named = settings_->dialect();
    if (named != jobDoc_.dialect()) useMachineForThisProgram(named);
    // The bar as the check reads the program (its units, a comment naming the bar): the first
    // check's Job says it, as after a change of machine or units.
    restockOnNextCheck_ = true;
    checker_->checkText(text);  // the text just loaded: no need to read it back from the editor
    emit fileLoaded(path);
  });
  connect(recoveryBar_, &RecoveryBar::restoreRequested, docs_, &DocumentManager::restoreRecovery);
  connect(recoveryBar_, &RecoveryBar::discardRequested, this,
          [this](const RecoveryCopy& copy) { docs_->recovery().remove(copy.id); });
  connect(docs_, &DocumentManager::autosaveFailed, this,
          [this](const QString& error) { statusBar()->showMessage(tr("Autosave failed: %1").arg(error), 5000); });
  // Losing the focus (another program, a locked screen) writes the copy at once.
  connect(qApp, &QGuiApplication::applicationStateChanged, this, [this](Qt::ApplicationState state) {
    if (state != Qt::ApplicationActive) docs_->autosave();
  });
  connect(docs_, &DocumentManager::saved, this, [this](const QString& path) {
    updateTitle();
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)), 3000);
  });
}

void MainWindow::newFile() { docs_->newFile(); }
void MainWindow::open() { docs_->open(); }
bool MainWindow::openFile(const QString& path) { return docs_->openFile(path); }
bool MainWindow::save() { return docs_->save(); }
bool MainWindow::saveAs() { return docs_->saveAs(); }
bool MainWindow::saveFile(const QString& path) { return docs_->saveFile(path); }
void MainWindow::printCode() { reports_->printCode(); }
void MainWindow::printCodeNow() { reports_->printCodeNow(); }
void MainWindow::printDrawing() { reports_->printDrawing(); }
void MainWindow::printPreview() { reports_->printPreview(); }
bool MainWindow::exportPdf(const QString& path) { return reports_->exportPdf(path); }

void MainWindow::updateTitle() {
  if (!document_ || !editor_) return;
  setWindowTitle(tr("Klueng : %1[*]").arg(document_->displayName()));
  setWindowModified(docs_->isModified());
}

void MainWindow::showBusyIndicator() {
  if (isBusy() || runner_->isBusy()) busyBar_->show();
}

bool MainWindow::isBusy() const {
  // The flags cover the gap between a future finishing and its slot running.
  return docs_->isLoading() || checker_->isBusy();
}

// ---------------------------------------------------------------- layout

void MainWindow::restoreLayout() {
  // Never larger than the screen: a classroom's 1366 x 768 leaves about 1366 x 740 for a window.
  // (The title bar is not part of the window's size: keep 40 px for it.)
  QRect screenArea = screen() ? screen()->availableGeometry() : QRect(0, 0, 1280, 840);
  screenArea.setHeight(screenArea.height() - 40);
  const QSize fit(std::min(1280, screenArea.width()), std::min(800, screenArea.height()));
  resize(fit);
  // A remembered geometry is the user's (Qt moves it onto the screen if it is off it).
  if (!restoreGeometry(settings_->windowGeometry())) resize(fit);
  if (!restoreState(settings_->windowState())) resizeDocks({diagnostics_}, {150}, Qt::Vertical);
  if (!splitter_->restoreState(settings_->splitterState())) splitter_->setSizes({520, 760});
}

void MainWindow::saveLayout() {
  settings_->setWindowGeometry(saveGeometry());
  settings_->setWindowState(saveState());
  settings_->setSplitterState(splitter_->saveState());
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!docs_->maybeSave()) {
    event->ignore();
    return;
  }
  docs_->discardRecovery();  // saved or discarded: nothing to recover
  runner_->stop();
  saveLayout();
  event->accept();
}

// ---------------------------------------------------------------- checking

void MainWindow::checkNow() { checker_->checkNow(); }

core::io::ProgramFile MainWindow::currentProgramFile() const {
  core::io::ProgramFile f;
  f.header = document_->header();
  f.plainGcode = document_->isPlainGcode();
  f.gcodeFirstLine = document_->gcodeFirstLine();
  f.gcode = editor_->toPlainText().toStdString();
  return f;
}

CheckController::Request MainWindow::checkRequest() const {
  core::io::ProgramFile file;  // the header and line numbering; the text goes in off the GUI thread
  file.header = document_->header();
  file.plainGcode = document_->isPlainGcode();
  file.gcodeFirstLine = document_->gcodeFirstLine();
  CheckController::Request r = jobDoc_.checkInput(std::move(file), programFolder().toStdString());
  // A program made in the Part Designer: its roughness marks judge the finishing feeds (W332, issue 39).
  if (document_->design()) r.finishMarks = core::design::finishMarks(*document_->design());
  return r;
}

void MainWindow::onCheckFinished(const CheckController::JobPtr& job) {
  const std::vector<core::Diagnostic> found = job->programFileDiagnostics();
  lastDiagnostics_ = document_->fileDiagnostics();
  // A header size the file reading already reported is said once.
  for (const core::Diagnostic& d : found)
    if (std::none_of(lastDiagnostics_.begin(), lastDiagnostics_.end(), [&](const core::Diagnostic& f) {
          return f.code == d.code && f.range.line == d.range.line && f.range.file == d.range.file;
        }))
      lastDiagnostics_.push_back(d);
  if (job->fit())
    dialectOffer_->offer(*job->fit(), job->fitBlocks());
  else
    dialectOffer_->clear();
  // The job's tools: library choices for the stations the program uses (a note per choice in Tool Select).
  const bool toolsChanged = !sameTools(job->tools().setup, jobDoc_.tools().setup);
  jobDoc_.setJob(job);
  explainBar_->setFinishMarks(job->input().finishMarks);
  // Which word decided how lengths without a decimal point are read (point_reading.h), for the strip.
  pointNote_.reset();
  for (const core::Diagnostic& d : found)
    if (d.code == core::codes::kLengthsInIncrements || d.code == core::codes::kLengthsWhole) pointNote_ = d;
  if (toolsChanged) runner_->setMachineSetup(jobDoc_.tools().setup);
  // After a dialect or units change, a plain file's inferred bar is the one this Job resolved.
  if (restockOnNextCheck_ && job->file()) {
    restockOnNextCheck_ = false;
    document_->takeInferredStock(job->file()->header, job->stockNotes());
  }
  updateStockLabel();            // the setup strip lists the tools just decided
  programUnits_ = job->units();  // a G20 program speaks inches on View ▸ Units shown ▸ Auto
  applyDisplayUnits();
  std::stable_sort(lastDiagnostics_.begin(), lastDiagnostics_.end(), [](const auto& a, const auto& b) {
    return a.range.line != b.range.line ? a.range.line < b.range.line : a.range.column < b.range.column;
  });
  showDiagnostics();
  // "Fix the errors first" goes when the errors are fixed.
  if (bannerKind_ == BannerKind::Refused && !banner_->text().isEmpty() &&
      std::none_of(lastDiagnostics_.begin(), lastDiagnostics_.end(),
                   [](const core::Diagnostic& d) { return core::isError(d.severity); }))
    hideBanner();
  if (!isBusy() && !runner_->isBusy()) busyBar_->hide();
  emit checkFinished();
}

void MainWindow::applyDisplayUnits() {
  const core::UnitFormat units = displayUnits();
  statusFields_->setUnits(units);
  output_->setUnits(units);
  part_->setUnits(units);
}

void MainWindow::showDiagnostics() {
  std::vector<core::Diagnostic> all = lastDiagnostics_;
  all.insert(all.end(), runDiagnostics_.begin(), runDiagnostics_.end());
  editor_->setDiagnostics(all);
  diagnostics_->setDiagnostics(std::move(all));
}

// ---------------------------------------------------------------- running

void MainWindow::loadMachineSetup(const QString& dir, bool keepEdits) {
  // A save into the per-user folder tells us where; otherwise the core decides.
  if (!dir.isEmpty()) configDirOverride_ = dir;
  const core::machine::LoadedSetup loaded = core::machine::loadMachineSetup(configDirOverride_.toStdString());
  configDir_ = QString::fromStdString(loaded.dir);
  const bool edited = keepEdits && jobDoc_.isSetupModified();
  const SetupEdit edits = jobDoc_.edit();
  jobDoc_.setSetup(loaded.setup, loaded.toolsWithBitmap());  // the next check decides the job's tools
  if (edited) jobDoc_.applyEdit(edits);                      // still in memory, still unsaved
  // A setup file the reader refused is said at once, file and line, above the editor.
  const bool problems =
      std::any_of(loaded.diagnostics.begin(), loaded.diagnostics.end(),
                  [](const core::machine::SetupDiagnostic& d) { return core::isError(d.diagnostic.severity); });
  if (problems)
    showBanner(
        BannerKind::Setup,
        [diagnostics = loaded.diagnostics] {
          QStringList lines{tr("The machine setup has errors:")};
          for (const core::machine::SetupDiagnostic& d : diagnostics)
            if (core::isError(d.diagnostic.severity))
              lines << QStringLiteral("%1:%2: %3")
                           .arg(QDir::toNativeSeparators(QString::fromStdString(d.file)))
                           .arg(d.diagnostic.range.line)
                           .arg(QString::fromStdString(
                               core::formatMessage(d.diagnostic, Language::coreLang(), core::Surface::Gui)));
          return lines.join(QLatin1Char('\n'));
        },
        false);
  // The machines folders may name the remembered machine only now; its machine.cfg keys join the setup.
  updateMachineMenu();
  if (const core::gcode::Dialect remembered = settings_->dialect(); remembered != jobDoc_.dialect())
    setDialect(remembered);
  jobDoc_.setMachine(
      core::machine::withMachineKeys(jobDoc_.setup().machine, core::gcode::machineProfile(jobDoc_.dialect())));
  runner_->setMachineSetup(jobDoc_.setup());
  if (designer_) designer_->setMachineSetup(jobDoc_.setup());
}

QString MainWindow::programFolder() const {
  return document_->filePath().isEmpty() ? QString() : QFileInfo(document_->filePath()).absolutePath();
}

void MainWindow::syncRunner() {
  if (checker_->isScheduled()) checkNow();
  // The runner compares: an unchanged program keeps its run, a changed one makes a new Job.
  const QList<int> lines = editor_->breakpointFileLines();
  runner_->setBreakpoints(QSet<int>(lines.begin(), lines.end()));
  runner_->setProgram(currentProgramFile(), document_->displayName());
  // The program's folder is the control's memory: subprogram files (O1000.nc) come from there.
  runner_->setProgramFolder(programFolder());
}

void MainWindow::runToCursor() {
  syncRunner();
  hideBanner();
  runner_->runToLine(editor_->cursorFileLine());
}

void MainWindow::toggleBreakpoint() { editor_->toggleBreakpoint(editor_->cursorFileLine()); }

void MainWindow::onRunStateChanged(RunState state) {
  actions_->applyRunState(state);
  const bool running = !ActionTable::enabledIn(EnabledWhen::NotRunning, state);
  // The text being run must not change under the animation.
  editor_->setReadOnly(running);
  if (state == RunState::Idle) editor_->setExecutingLine(0);
  // The Part marks (the comparison's outline, gouges) fit the finished part,
  // not a bar being cut again: hidden while a run is under way.
  output_->setPartOverlayHidden(state != RunState::Idle && state != RunState::Finished);
  if (state == RunState::Running || state == RunState::Stepping || state == RunState::Preparing) {
    if (!runDiagnostics_.empty()) {
      runDiagnostics_.clear();
      showDiagnostics();
    }
  }
  // Issue 11: the end of a run says so, with the cycle time the core computed.
  // A program with no block to run (an empty editor, only comments) ran nothing.
  if (state == RunState::Finished && runner_->timeline() && !runner_->timeline()->alarm) {
    if (runner_->timeline()->snapshots.empty())
      showBanner(
          BannerKind::RunEnded,
          [] {
            return tr(
                "There is nothing to run: the program has no blocks. Type the program in the editor or open a file.");
          },
          false);
    else
      showBanner(
          BannerKind::RunEnded,
          [seconds = runner_->timeline()->cycleTime()] {
            return tr("The program ended. Cycle time: %1.").arg(formatDuration(seconds));
          },
          false);
  }
  // The run's notices (a vacant address left out, M99 in the main program, a
  // #3006 stop message) up to where it stands, for lines of this file.
  if ((state == RunState::Paused || state == RunState::Finished) && runner_->timeline()) {
    const core::machine::Timeline& t = *runner_->timeline();
    const int upTo =
        runner_->currentSnapshot() < 0 ? -1 : t.snapshots[static_cast<std::size_t>(runner_->currentSnapshot())].line;
    bool added = false;
    std::vector<core::Diagnostic> found = t.flow.notices;
    // A guessed tool's holder touching the stock or chuck (W324/W325): the run went on, the list says so.
    // A guess replaced by another of its kind that fits (I413/I414), on the block where the first touched.
    if (const core::cut::CutSimulator* cut = runner_->isBusy() ? nullptr : runner_->cutSimulator()) {
      found.insert(found.end(), runner_->guessNotes().begin(), runner_->guessNotes().end());
      found.insert(found.end(), cut->warnings().begin(), cut->warnings().end());
    }
    for (const core::Diagnostic& n : found) {
      if (n.range.file != 0 || (state == RunState::Paused && n.range.line > upTo)) continue;
      const bool seen = std::any_of(runDiagnostics_.begin(), runDiagnostics_.end(),
                                    [&n](const core::Diagnostic& d) { return d.code == n.code && d.range == n.range; });
      if (!seen) {
        runDiagnostics_.push_back(n);
        added = true;
      }
    }
    if (added) showDiagnostics();
  }
}

QString MainWindow::formatDuration(double seconds) {
  // As the program sheet says it, in the UI language.
  return render::durationText(
      seconds, Language::coreLang() == core::Lang::Th ? render::ReportLanguage::Thai : render::ReportLanguage::English);
}

void MainWindow::onAlarm(const core::Diagnostic& alarm) {
  runDiagnostics_ = {alarm};
  showDiagnostics();
  editor_->setExecutingLine(alarm.range.line);
  showBanner(
      BannerKind::Alarm,
      [alarm] {
        return tr("Alarm %1 on line %2: %3")
            .arg(QString::fromStdString(alarm.code))
            .arg(alarm.range.line)
            .arg(QString::fromStdString(core::formatMessage(alarm, Language::coreLang(), core::Surface::Gui)));
      },
      true);
}

void MainWindow::onCheckFailed(const QList<core::Diagnostic>& diags) {
  int errors = 0;
  for (const auto& d : diags) errors += core::isError(d.severity);
  showBanner(
      BannerKind::Refused,
      [errors] {
        return tr("The program has %n error(s); fix them before running. Click an error below to go to it.", nullptr,
                  errors);
      },
      true);
  diagnostics_->show();
  diagnostics_->raise();
  // Go to the first error in the editor's own file (a subprogram file's are E412 on its call).
  for (const auto& d : diags)
    if (d.range.file == 0) {
      editor_->goToFileLine(d.range.line, d.range.column);
      break;
    }
}

void MainWindow::showBanner(BannerKind kind, std::function<QString()> text, bool error) {
  bannerKind_ = kind;
  bannerMaker_ = std::move(text);
  bannerError_ = error;
  banner_->showMessage(bannerMaker_(), error);
}

void MainWindow::hideBanner() {
  bannerMaker_ = nullptr;
  banner_->dismiss();
}

void MainWindow::updateStockLabel() {
  if (!setupStrip_ || !document_) return;
  const core::io::StockSource source = document_->header().stockSource;
  setupStrip_->showSetup(document_->stockNotes(),
                         source == core::io::StockSource::Inferred || source == core::io::StockSource::Default,
                         document_->isPlainGcode(), jobDoc_.tools(),
                         {document_->header().calculatorInput, pointNote_, document_->header().toolsBeyondCentre});
}

QString MainWindow::stockSourceText() const { return setupStrip_ ? setupStrip_->stockText() : QString(); }

QString MainWindow::bannerText() const { return banner_->text(); }

// ---------------------------------------------------------------- dialogs

void MainWindow::showJobDetails() {
  // The machine is the one the program names now, in the editor (issue 27).
  const std::string text = editor_->toPlainText().toStdString();
  const std::optional<core::io::NamedMachine> named = core::io::machineNamedIn(text);
  core::io::JobHeader h = document_->header();
  h.machine = named ? named->id : std::string();
  JobDetailsDialog dlg(h, this);
  if (dlg.exec() != QDialog::Accepted) return;
  const core::io::JobHeader chosen = dlg.header();
  // The header and the head line naming the machine are one step of Edit > Undo.
  jobDoc_.undoStack()->beginMacro(tr("Job Details"));
  setJobDetails(chosen);
  // A name no loaded machine has shows as "not named": kept unless another machine is picked.
  core::gcode::Dialect d{};
  const std::string shown = core::gcode::parseDialectId(h.machine, d) ? h.machine : std::string();
  if (chosen.machine != shown) nameMachineInProgram(chosen.machine);
  jobDoc_.undoStack()->endMacro();
  if (core::gcode::parseDialectId(chosen.machine, d) && d != jobDoc_.dialect()) useMachineForThisProgram(d);
}

void MainWindow::nameMachineInProgram(const std::string& id) {
  {
    const std::string text = editor_->toPlainText().toStdString();
    // One edit of the changed lines only (undone with Ctrl+Z): the program's head names the machine.
    const QString before = editor_->toPlainText();
    const QString after = QString::fromStdString(core::io::withMachineNamed(text, id));
    qsizetype head = 0;
    while (head < before.size() && head < after.size() && before[head] == after[head]) ++head;
    qsizetype tail = 0;
    while (tail < before.size() - head && tail < after.size() - head &&
           before[before.size() - 1 - tail] == after[after.size() - 1 - tail])
      ++tail;
    QTextCursor edit(editor_->document());
    edit.setPosition(static_cast<int>(head));
    edit.setPosition(static_cast<int>(before.size() - tail), QTextCursor::KeepAnchor);
    edit.insertText(after.mid(head, after.size() - head - tail));
  }
}

void MainWindow::showFind() {
  if (!findDialog_) findDialog_ = new FindDialog(editor_, this);
  const QString selected = editor_->textCursor().selectedText();
  if (!selected.isEmpty() && !selected.contains(QChar::ParagraphSeparator)) findDialog_->setFindText(selected);
  findDialog_->show();
  findDialog_->raise();
  findDialog_->activateWindow();
}

void MainWindow::goToLine() {
  const int first = editor_->firstFileLine();
  const int last = first + editor_->blockCount() - 1;
  bool ok = false;
  const int line = QInputDialog::getInt(this, tr("Go to Line"), tr("Line (%1-%2):").arg(first).arg(last),
                                        editor_->cursorFileLine(), first, last, 1, &ok);
  if (ok) editor_->goToFileLine(line);
}

void MainWindow::showToolSelect() { showToolSelectFor(0); }

void MainWindow::showToolSelectFor(int station) {
  // The dialog edits the tables the document holds; its OK is one undo step, nothing is written.
  ToolSelectDialog dlg(jobDoc_.setup().tools, jobDoc_.setup().offsets, configDir_, this);
  dlg.setProgramTools(jobDoc_.tools(), jobDoc_.overrides());
  if (station > 0) dlg.setCurrentTool(station);
  if (dlg.exec() != QDialog::Accepted) return;
  SetupEdit after = jobDoc_.edit();
  if (dlg.toolsChanged()) after.tools = dlg.toolTable();
  after.overrides = dlg.jobOverrides();
  pushSetupEdit(tr("Tool Select"), after);
}

void MainWindow::showOffsetDefine() {
  OffsetDefineDialog dlg(jobDoc_.setup().offsets, this);
  if (dlg.exec() != QDialog::Accepted) return;
  SetupEdit after = jobDoc_.edit();
  after.offsets = dlg.offsetTable();
  pushSetupEdit(tr("Offset Define"), after);
}

void MainWindow::pushSetupEdit(const QString& text, const SetupEdit& after) {
  const SetupEdit before = jobDoc_.edit();
  if (before.sameAs(after)) return;  // OK on an unchanged dialog is no step
  jobDoc_.undoStack()->push(
      new SetupCommand(text, before, after, [this](const SetupEdit& edit) { applySetupEdit(edit); }));
}

void MainWindow::applySetupEdit(const SetupEdit& edit) {
  // A run takes the new offsets at once with the tools the program was given; the next
  // check's Job decides the tools again (empty offset rows may take a library tool's nose).
  const bool sameTools = core::io::formatToolTable(edit.tools) == core::io::formatToolTable(jobDoc_.setup().tools);
  core::machine::MachineSetup run = jobDoc_.tools().setup;
  jobDoc_.applyEdit(edit);
  if (sameTools)
    run.offsets = jobDoc_.runSetup().offsets;
  else
    run = jobDoc_.runSetup();
  runner_->setMachineSetup(run);
  if (designer_) designer_->setMachineSetup(jobDoc_.setup());
  docs_->setupChanged();  // the title's '*', the autosave
  updateStockLabel();
  checkNow();
}

bool MainWindow::saveSetup(const QString& programPath) {
  SetupToSave what;
  what.dir = configDir_;
  what.tools = &jobDoc_.setup().tools;
  what.offsets = &jobDoc_.setup().offsets;
  what.toolsEdited = jobDoc_.toolsModified();
  what.offsetsEdited = jobDoc_.offsetsModified();
  const QString written = saveSetupFiles(this, what);
  if (written.isEmpty()) return false;
  if (!programPath.isEmpty()) saveToolOverrides(programPath, jobDoc_.overrides());
  if (QDir(written) != QDir(configDir_)) {
    // The per-user folder is the setup now: read from there, the edits being in it.
    loadMachineSetup(written, false);
    runner_->setMachineSetup(jobDoc_.setup());
    checkNow();
  }
  // Stations set for an untitled program wait for its file (Save As) to be remembered.
  jobDoc_.markSetupSaved(!programPath.isEmpty());
  return true;
}

void MainWindow::revertSetup() {
  if (jobDoc_.toolsModified() || jobDoc_.offsetsModified()) {
    loadMachineSetup({}, false);
    runner_->setMachineSetup(jobDoc_.setup());
  }
  jobDoc_.setSavedOverrides({});  // the next program's own, when it has any
}

void MainWindow::showHelpContents() {
  if (!help_) help_ = new HelpContents(this);
  help_->setDialect(jobDoc_.dialect());
  const std::optional<std::pair<char, int>> code = editor_->codeAtCursor();  // F1 on G71 opens G71
  help_->showCode(code ? code->first : 'G', code ? code->second : -1);
}

void MainWindow::showAbout() {
  AboutDialog dlg(this);
  dlg.exec();
}

}  // namespace klueng::gui

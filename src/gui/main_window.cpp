#include "gui/main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPageSize>
#include <QPdfWriter>
#include <QPrintDialog>
#include <QPrintPreviewDialog>
#include <QPrinter>
#include <QPrinterInfo>
#include <QPushButton>
#include <QScreen>
#include <QSplitter>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "gui/about_dialog.h"
#include "gui/code_editor.h"
#include "gui/diagnostics_panel.h"
#include "gui/dialect_offer_bar.h"
#include "gui/find_dialog.h"
#include "gui/flow_panel.h"
#include "klueng/core/gcode/macro.h"
#include "klueng/core/machine/flow_view.h"
#include "gui/help_contents.h"
#include "gui/job_details_dialog.h"
#include "gui/language.h"
#include "gui/offset_define_dialog.h"
#include "gui/output_view.h"
#include "gui/run_speed_control.h"
#include "gui/settings.h"
#include "gui/status_panel.h"
#include "gui/tool_select_dialog.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/messages.h"

namespace klueng::gui {

namespace {

// The Dialect menu's action of a machine profile ("actionDialectHaas").
QString dialectActionName(core::gcode::Dialect d) {
  switch (d) {
    case core::gcode::Dialect::Fanuc: return QStringLiteral("actionDialectFanuc");
    case core::gcode::Dialect::Haas: return QStringLiteral("actionDialectHaas");
    case core::gcode::Dialect::Classic: return QStringLiteral("actionDialectClassic");
  }
  return QStringLiteral("actionDialectFanuc");
}

// Animation speeds: machine seconds per wall second; 0 = as fast as possible.
// The same stops as the tool bar's speed slider.
const std::vector<double>& speeds() { return RunSpeedControl::steps(); }
int speedCount() { return static_cast<int>(speeds().size()); }

QString speedText(int i) {
  const double v = speeds()[static_cast<std::size_t>(i)];
  if (v == RunController::kAsFastAsPossible) return MainWindow::tr("As fast as possible");
  if (v == 1.0) return MainWindow::tr("1× (real time)");
  return MainWindow::tr("%1×").arg(QLocale().toString(v));
}

// Runs on a worker thread: the UTF-8 conversion happens there too.
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), settings_(std::make_unique<Settings>()) {
  setObjectName(QStringLiteral("mainWindow"));
  setWindowIcon(QIcon(QStringLiteral(":/icons/klueng.svg")));
  dialect_ = settings_->dialect();
  powerOnUnits_ = settings_->powerOnUnits();
  document_ = new Document(this);

  editor_ = new CodeEditor(this);
  editor_->setObjectName(QStringLiteral("codeEditor"));
  editor_->setDialect(dialect_);

  runner_ = new RunController(this);
  runner_->setDialect(dialect_);
  runner_->setPowerOnUnits(powerOnUnits_);
  runner_->setOptionalStop(settings_->optionalStop());
  runner_->setBlockSkip(settings_->blockSkip());

  output_ = new OutputView(this);
  output_->setObjectName(QStringLiteral("outputView"));
  output_->setRunController(runner_);

  // Banner above the editor: alarms and refused runs, in the UI language.
  banner_ = new QWidget(this);
  banner_->setObjectName(QStringLiteral("banner"));
  bannerLabel_ = new QLabel(banner_);
  bannerLabel_->setWordWrap(true);
  bannerLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* bannerClose = new QToolButton(banner_);
  bannerClose->setIcon(QIcon(QStringLiteral(":/icons/close.svg")));
  bannerClose->setAutoRaise(true);
  connect(bannerClose, &QToolButton::clicked, this, &MainWindow::hideBanner);
  auto* bannerLayout = new QHBoxLayout(banner_);
  bannerLayout->setContentsMargins(8, 4, 4, 4);
  bannerLayout->addWidget(bannerLabel_, 1);
  bannerLayout->addWidget(bannerClose, 0, Qt::AlignTop);
  banner_->setAutoFillBackground(true);
  banner_->hide();

  auto* editorPane = new QWidget(this);
  auto* editorLayout = new QVBoxLayout(editorPane);
  editorLayout->setContentsMargins(0, 0, 0, 0);
  editorLayout->setSpacing(0);
  editorLayout->addWidget(banner_);
  dialectOffer_ = new DialectOfferBar(this);
  connect(dialectOffer_, &DialectOfferBar::switchRequested, this, &MainWindow::setDialect);
  editorLayout->addWidget(dialectOffer_);
  editorLayout->addWidget(editor_, 1);

  statusLamps_ = new StatusLamps(this);
  statusLamps_->setObjectName(QStringLiteral("statusLamps"));
  statusLamps_->setOptionalStopSwitch(settings_->optionalStop());
  auto* outputPane = new QWidget(this);
  auto* outputLayout = new QVBoxLayout(outputPane);
  outputLayout->setContentsMargins(0, 0, 0, 0);
  outputLayout->setSpacing(2);
  // SPEC 2 (ext): the user is always told where the stock came from.
  stockLabel_ = new QLabel(outputPane);
  stockLabel_->setObjectName(QStringLiteral("stockSource"));
  stockLabel_->setWordWrap(true);
  stockLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  stockLabel_->setContentsMargins(6, 2, 6, 2);
  outputLayout->addWidget(stockLabel_);
  outputLayout->addWidget(output_, 1);
  outputLayout->addWidget(statusLamps_);

  splitter_ = new QSplitter(Qt::Horizontal, this);
  splitter_->setObjectName(QStringLiteral("mainSplitter"));
  splitter_->addWidget(editorPane);
  splitter_->addWidget(outputPane);
  splitter_->setStretchFactor(0, 2);
  splitter_->setStretchFactor(1, 3);
  splitter_->setChildrenCollapsible(false);
  setCentralWidget(splitter_);

  statusFields_ = new StatusFields(this);
  statusFields_->setObjectName(QStringLiteral("statusFields"));
  statusBar()->addWidget(statusFields_, 1);
  busyBar_ = new QProgressBar(this);
  busyBar_->setRange(0, 0);
  busyBar_->setMaximumWidth(140);
  busyBar_->hide();
  statusBar()->addPermanentWidget(busyBar_);

  watcher_ = new QFileSystemWatcher(this);
  connect(watcher_, &QFileSystemWatcher::fileChanged, this, &MainWindow::onFileChangedOnDisk);
  diskChangeTimer_ = new QTimer(this);
  diskChangeTimer_->setSingleShot(true);
  diskChangeTimer_->setInterval(250);

  checkTimer_ = new QTimer(this);
  checkTimer_->setSingleShot(true);
  checkTimer_->setInterval(300);  // debounce: check once typing pauses
  connect(checkTimer_, &QTimer::timeout, this, &MainWindow::startCheck);
  connect(&checkWatcher_, &QFutureWatcherBase::finished, this, &MainWindow::onCheckFinished);
  connect(&loadWatcher_, &QFutureWatcherBase::finished, this, &MainWindow::onLoadFinished);

  createActions();
  createMenus();
  createToolBars();
  createDocks();

  // Only real edits re-check; the highlighter's re-colouring changes no characters.
  connect(editor_->document(), &QTextDocument::contentsChange, this, [this](int, int removed, int added) {
    if ((removed == 0 && added == 0) || fillingEditor_) return;
    runnerStale_ = true;
    scheduleCheck();
  });
  connect(editor_->document(), &QTextDocument::modificationChanged, this, &MainWindow::updateTitle);
  connect(document_, &Document::headerChanged, this, [this] {
    runnerStale_ = true;
    updateTitle();
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
    if (line >= editor_->firstFileLine()) editor_->goToFileLine(line, column);
    else if (line >= 1 && !document_->isPlainGcode()) showJobDetails();  // a header line
  });

  connect(runner_, &RunController::executingLineChanged, editor_, &CodeEditor::setExecutingLine);
  editor_->setWordValueLookup([this](int fileLine, int column) -> QString {
    const core::machine::Timeline* t = runner_->timeline();
    if (!t || runner_->currentSnapshot() < 0) return {};
    const auto v = core::machine::wordValueAt(*t, runner_->currentSnapshot(), 0, fileLine, column);
    if (!v) return {};
    return v->vacant ? tr("vacant (the address was left out)") : QString::fromStdString(core::gcode::macroNumberText(v->value));
  });
  connect(runner_, &RunController::statusChanged, statusFields_, &StatusFields::setStatus);
  connect(runner_, &RunController::statusChanged, statusLamps_, &StatusLamps::setStatus);
  connect(runner_, &RunController::stateChanged, this, &MainWindow::onRunStateChanged);
  connect(runner_, &RunController::alarmRaised, this, &MainWindow::onAlarm);
  connect(runner_, &RunController::checkFailed, this, &MainWindow::onCheckFailed);
  connect(runner_, &RunController::busyChanged, this, [this](bool busy) {
    if (busy) QTimer::singleShot(300, this, &MainWindow::showBusyIndicator);
    else if (!isBusy()) busyBar_->hide();
  });

  loadMachineSetup();
  Language::instance()->setLanguage(settings_->language());
  retranslateUi();
  restoreLayout();
  newFile();
  onRunStateChanged(RunState::Idle);
}

MainWindow::~MainWindow() {
  loadWatcher_.waitForFinished();
  checkWatcher_.waitForFinished();
}

// ---------------------------------------------------------------- actions

QAction* MainWindow::action(const QString& objectName) const { return actions_.value(objectName, nullptr); }

void MainWindow::createActions() {
  auto make = [this](const char* name, const char* icon, QKeySequence key = {}) {
    auto* a = new QAction(this);
    a->setObjectName(QString::fromLatin1(name));
    if (icon) a->setIcon(QIcon(QStringLiteral(":/icons/%1.svg").arg(QString::fromLatin1(icon))));
    if (!key.isEmpty()) a->setShortcut(key);
    actions_.insert(a->objectName(), a);
    return a;
  };
  // File
  connect(make("actionNew", "new", QKeySequence::New), &QAction::triggered, this, &MainWindow::newFile);
  connect(make("actionOpen", "open", QKeySequence::Open), &QAction::triggered, this, &MainWindow::open);
  connect(make("actionSave", "save", QKeySequence::Save), &QAction::triggered, this, &MainWindow::save);
  connect(make("actionSaveAs", "save-as", QKeySequence(QStringLiteral("Ctrl+Shift+S"))), &QAction::triggered, this,
          &MainWindow::saveAs);
  connect(make("actionJobDetails", "job", QKeySequence(QStringLiteral("Ctrl+J"))), &QAction::triggered, this,
          &MainWindow::showJobDetails);
  connect(make("actionPrintCode", "print", QKeySequence::Print), &QAction::triggered, this, &MainWindow::printCode);
  connect(make("actionPrint", "print"), &QAction::triggered, this, &MainWindow::printCodeNow);
  connect(make("actionPrintDrawing", "print-drawing", QKeySequence(QStringLiteral("Ctrl+Shift+P"))), &QAction::triggered,
          this, &MainWindow::printDrawing);
  connect(make("actionPrintPreview", "print-preview"), &QAction::triggered, this, &MainWindow::printPreview);
  connect(make("actionExportPdf", "export-pdf"), &QAction::triggered, this, [this] { exportPdf(); });
  auto* quit = make("actionExit", "exit", QKeySequence(QStringLiteral("Ctrl+Q")));
  quit->setMenuRole(QAction::QuitRole);
  connect(quit, &QAction::triggered, this, &QWidget::close);

  // Edit
  auto* undo = make("actionUndo", "undo", QKeySequence::Undo);
  auto* redo = make("actionRedo", "redo", QKeySequence::Redo);
  auto* cut = make("actionCut", "cut", QKeySequence::Cut);
  auto* copy = make("actionCopy", "copy", QKeySequence::Copy);
  auto* paste = make("actionPaste", "paste", QKeySequence::Paste);
  auto* del = make("actionDelete", "delete", QKeySequence::Delete);
  auto* selectAll = make("actionSelectAll", nullptr, QKeySequence::SelectAll);
  // Editor-local keys (Delete, Ctrl+C ...) keep working inside the editor; the
  // actions take the shortcut only when another widget has the focus.
  for (QAction* a : {undo, redo, cut, copy, paste, del, selectAll}) a->setShortcutContext(Qt::WidgetShortcut);
  connect(undo, &QAction::triggered, editor_, &QPlainTextEdit::undo);
  connect(redo, &QAction::triggered, editor_, &QPlainTextEdit::redo);
  connect(cut, &QAction::triggered, editor_, &QPlainTextEdit::cut);
  connect(copy, &QAction::triggered, editor_, &QPlainTextEdit::copy);
  connect(paste, &QAction::triggered, editor_, &QPlainTextEdit::paste);
  connect(del, &QAction::triggered, editor_, [this] { editor_->textCursor().removeSelectedText(); });
  connect(selectAll, &QAction::triggered, editor_, &QPlainTextEdit::selectAll);
  undo->setEnabled(false);
  redo->setEnabled(false);
  cut->setEnabled(false);
  copy->setEnabled(false);
  del->setEnabled(false);
  connect(editor_, &QPlainTextEdit::undoAvailable, undo, &QAction::setEnabled);
  connect(editor_, &QPlainTextEdit::redoAvailable, redo, &QAction::setEnabled);
  for (QAction* a : {cut, copy, del}) connect(editor_, &QPlainTextEdit::copyAvailable, a, &QAction::setEnabled);
  connect(make("actionFind", "find", QKeySequence::Find), &QAction::triggered, this, &MainWindow::showFind);
  connect(make("actionReplace", nullptr, QKeySequence(QStringLiteral("Ctrl+H"))), &QAction::triggered, this,
          &MainWindow::showFind);
  connect(make("actionGoToLine", "goto", QKeySequence(QStringLiteral("Ctrl+G"))), &QAction::triggered, this,
          &MainWindow::goToLine);

  // Run
  connect(make("actionGo", "go", QKeySequence(Qt::Key_F5)), &QAction::triggered, this, [this] {
    syncRunner();
    hideBanner();
    runner_->go();
  });
  // F10 Step (over): one block of this level; F11 into calls; Shift+F11 out of one.
  connect(make("actionStep", "step", QKeySequence(Qt::Key_F10)), &QAction::triggered, this, [this] {
    syncRunner();
    hideBanner();
    runner_->stepOver();
  });
  connect(make("actionStepInto", "step", QKeySequence(Qt::Key_F11)), &QAction::triggered, this, [this] {
    syncRunner();
    hideBanner();
    runner_->step();
  });
  connect(make("actionStepOut", "step", QKeySequence(QStringLiteral("Shift+F11"))), &QAction::triggered, this, [this] {
    syncRunner();
    hideBanner();
    runner_->stepOut();
  });
  connect(make("actionPause", "pause", QKeySequence(Qt::Key_F6)), &QAction::triggered, runner_, &RunController::pause);
  connect(make("actionStop", "stop", QKeySequence(QStringLiteral("Shift+F5"))), &QAction::triggered, this, [this] {
    runner_->stop();
    editor_->setExecutingLine(0);
  });
  connect(make("actionStepBack", "step-back", QKeySequence(QStringLiteral("Shift+F10"))), &QAction::triggered,
          runner_, &RunController::stepBack);
  connect(make("actionRunToCursor", "run-to-cursor", QKeySequence(QStringLiteral("Ctrl+F10"))), &QAction::triggered,
          this, &MainWindow::runToCursor);
  connect(make("actionToggleBreakpoint", "breakpoint", QKeySequence(Qt::Key_F9)), &QAction::triggered, this,
          &MainWindow::toggleBreakpoint);
  auto* optStop = make("actionOptionalStop", "optional-stop", QKeySequence(QStringLiteral("Ctrl+M")));
  optStop->setCheckable(true);
  optStop->setChecked(settings_->optionalStop());
  connect(optStop, &QAction::toggled, this, [this](bool on) {
    runner_->setOptionalStop(on);
    statusLamps_->setOptionalStopSwitch(on);
    settings_->setOptionalStop(on);
  });
  auto* skip = make("actionBlockSkip", "block-skip", QKeySequence(QStringLiteral("Ctrl+/")));
  skip->setCheckable(true);
  skip->setChecked(settings_->blockSkip());
  connect(skip, &QAction::toggled, this, [this](bool on) {
    runner_->setBlockSkip(on);
    settings_->setBlockSkip(on);
  });
  speedGroup_ = new QActionGroup(this);
  for (int i = 0; i < speedCount(); ++i) {
    auto* a = make(QStringLiteral("actionSpeed%1").arg(i).toLatin1().constData(), nullptr);
    a->setCheckable(true);
    a->setData(i);
    speedGroup_->addAction(a);
    connect(a, &QAction::triggered, this, [this, i] { setSpeedIndex(i); });
  }

  // Tool setting
  connect(make("actionToolSelect", "tool", QKeySequence(QStringLiteral("Ctrl+T"))), &QAction::triggered, this,
          &MainWindow::showToolSelect);
  connect(make("actionOffsetDefine", "offset", QKeySequence(QStringLiteral("Ctrl+Shift+O"))), &QAction::triggered,
          this, &MainWindow::showOffsetDefine);
  dialectGroup_ = new QActionGroup(this);
  for (const core::gcode::MachineProfile& profile : core::gcode::machineProfiles()) {
    QAction* a = make(dialectActionName(profile.dialect).toLatin1().constData(), nullptr);
    a->setCheckable(true);
    a->setChecked(profile.dialect == dialect_);
    dialectGroup_->addAction(a);
    const core::gcode::Dialect d = profile.dialect;
    connect(a, &QAction::triggered, this, [this, d] { setDialect(d); });
  }
  unitsGroup_ = new QActionGroup(this);
  const std::pair<const char*, std::optional<core::gcode::InputUnits>> unitChoices[] = {
      {"actionUnitsMachine", std::nullopt},
      {"actionUnitsMm", core::gcode::InputUnits::Millimetre},
      {"actionUnitsInch", core::gcode::InputUnits::Inch}};
  for (const auto& [name, units] : unitChoices) {
    QAction* a = make(name, nullptr);
    a->setCheckable(true);
    a->setChecked(units == powerOnUnits_);
    unitsGroup_->addAction(a);
    const auto u = units;
    connect(a, &QAction::triggered, this, [this, u] { setPowerOnUnits(u); });
  }

  // View
  connect(make("actionFitView", "fit", QKeySequence(QStringLiteral("Ctrl+0"))), &QAction::triggered, output_,
          &OutputView::fitToView);
  connect(make("actionZoomIn", "zoom-in", QKeySequence::ZoomIn), &QAction::triggered, output_, &OutputView::zoomIn);
  connect(make("actionZoomOut", "zoom-out", QKeySequence::ZoomOut), &QAction::triggered, output_,
          &OutputView::zoomOut);
  auto* showPath = make("actionShowPath", nullptr);
  showPath->setCheckable(true);
  showPath->setChecked(true);
  connect(showPath, &QAction::toggled, output_, &OutputView::setShowPath);
  auto* showStatus = make("actionShowStatusBar", nullptr);
  showStatus->setCheckable(true);
  showStatus->setChecked(true);
  connect(showStatus, &QAction::toggled, statusBar(), &QWidget::setVisible);
  auto* showLamps = make("actionShowLamps", nullptr);
  showLamps->setCheckable(true);
  showLamps->setChecked(true);
  connect(showLamps, &QAction::toggled, statusLamps_, &QWidget::setVisible);

  // Help
  connect(make("actionContents", "contents", QKeySequence::HelpContents), &QAction::triggered, this,
          &MainWindow::showHelpContents);
  connect(make("actionToggleLanguage", "language", QKeySequence(QStringLiteral("Ctrl+Shift+L"))), &QAction::triggered,
          this, &MainWindow::toggleLanguage);
  auto* about = make("actionAbout", "klueng");
  about->setMenuRole(QAction::AboutRole);
  connect(about, &QAction::triggered, this, &MainWindow::showAbout);

}

void MainWindow::createMenus() {
  fileMenu_ = menuBar()->addMenu(QString());
  fileMenu_->setObjectName(QStringLiteral("menuFile"));
  fileMenu_->addAction(action(QStringLiteral("actionNew")));
  fileMenu_->addAction(action(QStringLiteral("actionOpen")));
  recentMenu_ = fileMenu_->addMenu(QString());
  recentMenu_->setObjectName(QStringLiteral("menuRecent"));
  connect(recentMenu_, &QMenu::aboutToShow, this, &MainWindow::updateRecentMenu);
  fileMenu_->addAction(action(QStringLiteral("actionSave")));
  fileMenu_->addAction(action(QStringLiteral("actionSaveAs")));
  fileMenu_->addSeparator();
  fileMenu_->addAction(action(QStringLiteral("actionJobDetails")));
  fileMenu_->addSeparator();
  fileMenu_->addAction(action(QStringLiteral("actionPrintCode")));
  fileMenu_->addAction(action(QStringLiteral("actionPrintDrawing")));
  fileMenu_->addAction(action(QStringLiteral("actionPrintPreview")));
  fileMenu_->addAction(action(QStringLiteral("actionExportPdf")));
  fileMenu_->addSeparator();
  fileMenu_->addAction(action(QStringLiteral("actionExit")));

  editMenu_ = menuBar()->addMenu(QString());
  editMenu_->setObjectName(QStringLiteral("menuEdit"));
  for (const char* n : std::initializer_list<const char*>{"actionUndo", "actionRedo", nullptr, "actionCut", "actionCopy", "actionPaste", "actionDelete",
                        "actionSelectAll", nullptr, "actionFind", "actionReplace", "actionGoToLine"}) {
    if (n) editMenu_->addAction(action(QString::fromLatin1(n)));
    else editMenu_->addSeparator();
  }

  runMenu_ = menuBar()->addMenu(QString());
  runMenu_->setObjectName(QStringLiteral("menuRun"));
  for (const char* n : std::initializer_list<const char*>{"actionGo", "actionStep", "actionStepInto", "actionStepOut",
                        "actionPause", "actionStop", nullptr, "actionStepBack",
                        "actionRunToCursor", "actionToggleBreakpoint", nullptr, "actionOptionalStop",
                        "actionBlockSkip"}) {
    if (n) runMenu_->addAction(action(QString::fromLatin1(n)));
    else runMenu_->addSeparator();
  }
  speedMenu_ = runMenu_->addMenu(QString());
  speedMenu_->setObjectName(QStringLiteral("menuSpeed"));
  speedMenu_->addActions(speedGroup_->actions());

  toolMenu_ = menuBar()->addMenu(QString());
  toolMenu_->setObjectName(QStringLiteral("menuToolSetting"));
  toolMenu_->addAction(action(QStringLiteral("actionToolSelect")));
  toolMenu_->addAction(action(QStringLiteral("actionOffsetDefine")));
  toolMenu_->addAction(action(QStringLiteral("actionOptionalStop")));
  toolMenu_->addSeparator();
  dialectMenu_ = toolMenu_->addMenu(QString());
  dialectMenu_->setObjectName(QStringLiteral("menuDialect"));
  dialectMenu_->addActions(dialectGroup_->actions());
  dialectMenu_->addSeparator();
  dialectMenu_->addActions(unitsGroup_->actions());

  viewMenu_ = menuBar()->addMenu(QString());
  viewMenu_->setObjectName(QStringLiteral("menuView"));

  helpMenu_ = menuBar()->addMenu(QString());
  helpMenu_->setObjectName(QStringLiteral("menuHelp"));
  helpMenu_->addAction(action(QStringLiteral("actionContents")));
  helpMenu_->addAction(action(QStringLiteral("actionToggleLanguage")));
  helpMenu_->addSeparator();
  helpMenu_->addAction(action(QStringLiteral("actionAbout")));
}

void MainWindow::createToolBars() {
  auto bar = [this](const char* name) {
    QToolBar* t = addToolBar(QString());
    t->setObjectName(QString::fromLatin1(name));
    t->setIconSize(QSize(24, 24));
    return t;
  };
  fileToolBar_ = bar("fileToolBar");
  for (const char* n : {"actionNew", "actionOpen", "actionSave", "actionPrint"}) fileToolBar_->addAction(action(QString::fromLatin1(n)));
  editToolBar_ = bar("editToolBar");
  for (const char* n : std::initializer_list<const char*>{"actionUndo", "actionCut", "actionCopy", "actionPaste", "actionDelete", "actionFind"})
    editToolBar_->addAction(action(QString::fromLatin1(n)));
  runToolBar_ = bar("runToolBar");
  for (const char* n : {"actionGo", "actionStep", "actionPause", "actionStop", "actionStepBack", "actionRunToCursor"})
    runToolBar_->addAction(action(QString::fromLatin1(n)));
  speedControl_ = new RunSpeedControl(this);
  speedControl_->setObjectName(QStringLiteral("speedControl"));
  speedControl_->setRunController(runner_);
  // The slider and the Run > Speed menu show the same choice.
  connect(speedControl_, &RunSpeedControl::speedChanged, this, [this](double factor) {
    for (int i = 0; i < speedCount(); ++i)
      if (speeds()[static_cast<std::size_t>(i)] == factor) action(QStringLiteral("actionSpeed%1").arg(i))->setChecked(true);
  });
  runToolBar_->addSeparator();
  runToolBar_->addWidget(speedControl_);
  helpToolBar_ = bar("helpToolBar");
  helpToolBar_->addAction(action(QStringLiteral("actionContents")));
  helpToolBar_->addAction(action(QStringLiteral("actionToggleLanguage")));
  setSpeedIndex(static_cast<int>(std::find(speeds().begin(), speeds().end(), 1.0) - speeds().begin()));
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
  for (QToolBar* t : {fileToolBar_, editToolBar_, runToolBar_, helpToolBar_}) viewMenu_->addAction(t->toggleViewAction());
  viewMenu_->addAction(action(QStringLiteral("actionShowStatusBar")));
  viewMenu_->addAction(action(QStringLiteral("actionShowLamps")));
  viewMenu_->addAction(diagnostics_->toggleViewAction());
  viewMenu_->addAction(flow_->toggleViewAction());
  viewMenu_->addSeparator();
  viewMenu_->addAction(action(QStringLiteral("actionShowPath")));
  viewMenu_->addAction(action(QStringLiteral("actionFitView")));
  viewMenu_->addAction(action(QStringLiteral("actionZoomIn")));
  viewMenu_->addAction(action(QStringLiteral("actionZoomOut")));
}

void MainWindow::retranslateUi() {
  auto set = [this](const char* name, const QString& text, const QString& tip = {}) {
    QAction* a = action(QString::fromLatin1(name));
    a->setText(text);
    QString t = tip.isEmpty() ? QString(text).remove(QLatin1Char('&')) : tip;
    if (!a->shortcut().isEmpty()) t += QStringLiteral(" (%1)").arg(a->shortcut().toString(QKeySequence::NativeText));
    a->setToolTip(t);
    a->setStatusTip(tip.isEmpty() ? QString(text).remove(QLatin1Char('&')) : tip);
  };
  fileMenu_->setTitle(tr("&File"));
  recentMenu_->setTitle(tr("&Recent Files"));
  editMenu_->setTitle(tr("&Edit"));
  runMenu_->setTitle(tr("&Run"));
  speedMenu_->setTitle(tr("S&peed"));
  toolMenu_->setTitle(tr("&Tool setting"));
  dialectMenu_->setTitle(tr("G-code &dialect"));
  viewMenu_->setTitle(tr("&View"));
  helpMenu_->setTitle(tr("&Help"));

  set("actionNew", tr("&New"), tr("Start a new program"));
  set("actionOpen", tr("&Open..."), tr("Open a program file"));
  set("actionSave", tr("&Save"), tr("Save the program"));
  set("actionSaveAs", tr("Save &As..."), tr("Save the program under a new name"));
  set("actionJobDetails", tr("&Job details..."), tr("Project, part, material, stock size and programmer"));
  set("actionPrintCode", tr("&Print Code..."), tr("Print the program sheet: job details and the numbered program"));
  set("actionPrint", tr("Print"), tr("Print the program sheet at once on the default printer"));
  set("actionPrintDrawing", tr("Print &Drawing..."), tr("Print the finished part to scale with its title block"));
  set("actionPrintPreview", tr("Print Pre&view..."), tr("Preview the program sheet and the drawing sheet"));
  set("actionExportPdf", tr("&Export PDF..."), tr("Save the program sheet and the drawing sheet as a PDF file"));
  set("actionExit", tr("E&xit"));
  set("actionUndo", tr("&Undo"));
  set("actionRedo", tr("&Redo"));
  set("actionCut", tr("Cu&t"));
  set("actionCopy", tr("&Copy"));
  set("actionPaste", tr("&Paste"));
  set("actionDelete", tr("&Delete"));
  set("actionSelectAll", tr("Select &All"));
  set("actionFind", tr("&Find..."), tr("Find text in the program"));
  set("actionReplace", tr("R&eplace..."), tr("Find and replace text"));
  set("actionGoToLine", tr("&Go to Line..."));
  set("actionGo", tr("&Go"), tr("Run the program continuously"));
  set("actionStep", tr("&Step"), tr("Run one block, then wait (a subprogram or macro call runs whole)"));
  set("actionStepInto", tr("Step &Into"), tr("Run one block, into a subprogram or macro it calls"));
  set("actionStepOut", tr("Step O&ut"), tr("Run to the end of this subprogram or macro"));
  set("actionPause", tr("&Pause"), tr("Stop after the current step; Go or Step resumes"));
  set("actionStop", tr("S&top"), tr("Abort the run and reset"));
  set("actionStepBack", tr("Step &Back"), tr("Go back one block"));
  set("actionRunToCursor", tr("Run to &Cursor"), tr("Run up to the block at the cursor"));
  set("actionToggleBreakpoint", tr("Toggle &Breakpoint"), tr("Stop the run before this line"));
  set("actionOptionalStop", tr("&Optional Stop"), tr("M01 stops the run when this switch is on"));
  set("actionBlockSkip", tr("Block S&kip"), tr("Blocks starting with / are skipped when this switch is on"));
  set("actionToolSelect", tr("Tool &Select..."), tr("Choose the bitmap of each tool 01-08"));
  set("actionOffsetDefine", tr("Offset &Define..."), tr("Edit the 16 tool offsets"));
  set("actionDialectFanuc", tr("&Fanuc 0i-TF"));
  set("actionDialectHaas", tr("&Haas ST lathe (NGC)"));
  set("actionDialectClassic", tr("&Rook classic (1999 rules)"));
  set("actionUnitsMachine", tr("Power-on units as the &machine (Haas: inch)"));
  set("actionUnitsMm", tr("&Power-on units: millimetres"));
  set("actionUnitsInch", tr("Power-on units: &inches"));
  set("actionFitView", tr("&Fit to View"));
  set("actionZoomIn", tr("Zoom &In"));
  set("actionZoomOut", tr("Zoom &Out"));
  set("actionShowPath", tr("Show Tool &Path"));
  set("actionShowStatusBar", tr("&Status Bar"));
  set("actionShowLamps", tr("Status &Lamps"));
  set("actionContents", tr("&Contents"), tr("Help for self-learners: every G and M code with an example"));
  set("actionToggleLanguage", tr("Toggle &Language (ไทย/English)"), tr("Switch between Thai and English"));
  set("actionAbout", tr("&About Klueng"));
  for (int i = 0; i < speedCount(); ++i) action(QStringLiteral("actionSpeed%1").arg(i))->setText(speedText(i));
  fileToolBar_->setWindowTitle(tr("File tool bar"));
  editToolBar_->setWindowTitle(tr("Edit tool bar"));
  runToolBar_->setWindowTitle(tr("Run tool bar"));
  helpToolBar_->setWindowTitle(tr("Help tool bar"));
  updateTitle();
  updateStockLabel();
}

void MainWindow::changeEvent(QEvent* event) {
  QMainWindow::changeEvent(event);
  if (event->type() == QEvent::LanguageChange && fileMenu_) {
    retranslateUi();
    if (!runDiagnostics_.empty()) onAlarm(runDiagnostics_.front());
  }
}

void MainWindow::toggleLanguage() {
  Language::instance()->toggle();
  settings_->setLanguage(Language::instance()->language());
}

void MainWindow::setDialect(core::gcode::Dialect d) {
  dialect_ = d;
  settings_->setDialect(d);
  editor_->setDialect(d);
  runner_->setDialect(d);
  action(dialectActionName(d))->setChecked(true);
  if (help_) help_->setDialect(d);
  // The same plain text may approach the part elsewhere in another dialect (units, cycle forms).
  core::machine::RunOptions run;
  run.dialect = d;
  run.powerOnUnits = powerOnUnits_;
  document_->reinferStock(editor_->toPlainText(), runner_->machineSetup(), run);
  runnerStale_ = true;
  checkNow();
}

void MainWindow::setPowerOnUnits(std::optional<core::gcode::InputUnits> units) {
  powerOnUnits_ = units;
  settings_->setPowerOnUnits(units);
  runner_->setPowerOnUnits(units);
  for (QAction* a : unitsGroup_->actions()) {
    const QString name = a->objectName();
    a->setChecked(name == (!units                                      ? QStringLiteral("actionUnitsMachine")
                           : *units == core::gcode::InputUnits::Inch ? QStringLiteral("actionUnitsInch")
                                                                     : QStringLiteral("actionUnitsMm")));
  }
  core::machine::RunOptions run;
  run.dialect = dialect_;
  run.powerOnUnits = units;
  document_->reinferStock(editor_->toPlainText(), runner_->machineSetup(), run);
  runnerStale_ = true;
  checkNow();
}

void MainWindow::setSpeedIndex(int index) {
  index = std::clamp(index, 0, speedCount() - 1);
  const double factor = speeds()[static_cast<std::size_t>(index)];
  speedControl_->setSpeed(factor);
  runner_->setSpeed(factor);
  action(QStringLiteral("actionSpeed%1").arg(index))->setChecked(true);
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
  if (!maybeSave()) {
    event->ignore();
    return;
  }
  runner_->stop();
  saveLayout();
  event->accept();
}

// ---------------------------------------------------------------- files

bool MainWindow::isModified() const {
  return editor_->document()->isModified() || document_->isHeaderModified();
}

void MainWindow::updateTitle() {
  if (!document_ || !editor_) return;
  setWindowTitle(tr("Klueng : %1[*]").arg(document_->displayName()));
  setWindowModified(isModified());
}

bool MainWindow::maybeSave() {
  if (!isModified()) return true;
  QMessageBox box(this);
  box.setObjectName(QStringLiteral("unsavedChangesBox"));
  box.setIcon(QMessageBox::Warning);
  box.setWindowTitle(tr("Unsaved changes"));
  box.setText(tr("The program \"%1\" has been changed.").arg(document_->displayName()));
  box.setInformativeText(tr("Do you want to save your changes?"));
  QPushButton* saveButton = box.addButton(tr("&Save"), QMessageBox::AcceptRole);
  QPushButton* discardButton = box.addButton(tr("&Discard"), QMessageBox::DestructiveRole);
  QPushButton* cancelButton = box.addButton(tr("Cancel"), QMessageBox::RejectRole);
  saveButton->setObjectName(QStringLiteral("saveButton"));
  discardButton->setObjectName(QStringLiteral("discardButton"));
  cancelButton->setObjectName(QStringLiteral("cancelButton"));
  box.setDefaultButton(saveButton);
  box.setEscapeButton(cancelButton);
  box.exec();
  if (box.clickedButton() == saveButton) return save();
  return box.clickedButton() == discardButton;
}

void MainWindow::newFile() {
  if (!maybeSave()) return;
  runner_->stop();
  if (!document_->filePath().isEmpty()) watcher_->removePath(document_->filePath());
  ++fillGeneration_;  // drop the rest of a file still going into the editor
  pendingText_.clear();
  fillingEditor_ = false;
  loadInFlight_ = loadWatcher_.isRunning();
  editor_->setUndoRedoEnabled(true);
  editor_->setReadOnly(false);
  document_->reset(settings_->lastJobHeader());
  editor_->setFirstFileLine(document_->gcodeFirstLine());
  editor_->clearBreakpoints();
  editor_->setPlainText(QString());
  editor_->document()->setModified(false);
  hideBanner();
  runnerStale_ = true;
  updateTitle();
  checkNow();
}

void MainWindow::open() {
  if (!maybeSave()) return;
  QString dir = settings_->lastDirectory();
  if (dir.isEmpty()) dir = QDir::homePath();
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Open program"), dir, tr("Lathe programs (*.txt *.nc *.tap *.cnc *.gc);;All files (*)"));
  if (!path.isEmpty()) startLoad(path);
}

bool MainWindow::openFile(const QString& path) {
  if (!maybeSave()) return false;
  startLoad(path);
  return true;
}

void MainWindow::startLoad(const QString& path) {
  if (loadWatcher_.isRunning()) loadWatcher_.waitForFinished();
  loadingPath_ = path;
  loadInFlight_ = true;
  // A plain file's stock: its own Job details, else inferred; never the last file's.
  const core::io::JobHeader defaults = settings_->lastJobHeader();
  const std::optional<core::io::JobHeader> details = settings_->jobDetailsFor(path);
  const core::machine::MachineSetup setup = runner_->machineSetup();
  core::machine::RunOptions run;
  run.dialect = dialect_;
  run.powerOnUnits = powerOnUnits_;
  loadWatcher_.setFuture(QtConcurrent::run([path, defaults, details, setup, run] {
    return Document::load(path, defaults, details, setup, run);
  }));
  QTimer::singleShot(300, this, &MainWindow::showBusyIndicator);
}

void MainWindow::showBusyIndicator() {
  if (isBusy() || runner_->isBusy()) busyBar_->show();
}

bool MainWindow::isBusy() const {
  // The flags cover the gap between a future finishing and its slot running.
  return loadInFlight_ || checkInFlight_ || checkTimer_->isActive() || checkPending_;
}

void MainWindow::onLoadFinished() {
  const LoadedProgram loaded = loadWatcher_.result();
  loadInFlight_ = false;
  if (!loaded.ok) {
    busyBar_->hide();
    QStringList lines;
    for (const auto& d : loaded.diagnostics)
      lines << QString::fromStdString(core::formatMessage(d, Language::coreLang()));
    QMessageBox::warning(this, tr("Cannot open the program"),
                         tr("\"%1\" could not be read.").arg(QDir::toNativeSeparators(loaded.path)) +
                             (lines.isEmpty() ? QString() : QStringLiteral("\n\n") + lines.join(QLatin1Char('\n'))));
    settings_->removeRecentFile(loaded.path);
    emit loadFailed(loaded.path);
    return;
  }
  runner_->stop();
  if (!document_->filePath().isEmpty()) watcher_->removePath(document_->filePath());
  document_->adopt(loaded);
  editor_->setFirstFileLine(document_->gcodeFirstLine());
  editor_->clearBreakpoints();
  editor_->setExecutingLine(0);
  editor_->setDiagnostics({});
  hideBanner();
  // The text goes into the editor a few thousand lines per event-loop pass, so
  // colouring a 100,000-line program never freezes the window.
  loadInFlight_ = true;
  fillingEditor_ = true;
  editor_->setReadOnly(true);
  editor_->setUndoRedoEnabled(false);
  editor_->clear();
  pendingText_ = loaded.gcode;
  pendingOffset_ = 0;
  ++fillGeneration_;
  appendNextChunk();
}

void MainWindow::appendNextChunk() {
  constexpr int kChunkLines = 1500;
  const qsizetype size = pendingText_.size();
  qsizetype end = pendingOffset_;
  for (int n = 0; n < kChunkLines && end < size; ++n) {
    const qsizetype nl = pendingText_.indexOf(QLatin1Char('\n'), end);
    end = nl < 0 ? size : nl + 1;
  }
  QTextCursor c(editor_->document());
  c.movePosition(QTextCursor::End);
  c.insertText(pendingText_.mid(pendingOffset_, end - pendingOffset_));
  pendingOffset_ = end;
  if (pendingOffset_ < size) {
    QTimer::singleShot(0, this, [this, generation = fillGeneration_] {
      if (generation == fillGeneration_) appendNextChunk();  // else a newer file took over
    });
    return;
  }
  QTimer::singleShot(0, this, [this, generation = fillGeneration_] {
    if (generation == fillGeneration_) finishLoad();
  });
}

void MainWindow::finishLoad() {
  const QString loadedText = std::exchange(pendingText_, QString());
  fillingEditor_ = false;
  loadInFlight_ = false;
  editor_->setUndoRedoEnabled(true);
  editor_->setReadOnly(false);
  editor_->document()->setModified(false);
  editor_->moveCursor(QTextCursor::Start);
  const QString path = document_->filePath();
  settings_->addRecentFile(path);
  settings_->setLastDirectory(QFileInfo(path).absolutePath());
  if (!document_->isPlainGcode()) settings_->setLastJobHeader(document_->header());
  toolOverrides_ = loadToolOverrides(path);
  watchFile(path);
  runnerStale_ = true;
  updateTitle();
  checkTimer_->stop();
  startCheckOn(loadedText);  // the text just loaded: no need to read it back from the editor
  emit fileLoaded(path);
}

bool MainWindow::save() {
  if (document_->isUntitled()) return saveAs();
  return saveFile(document_->filePath());
}

bool MainWindow::saveAs() {
  QString suggestion = document_->filePath();
  if (suggestion.isEmpty()) {
    const QString dir = settings_->lastDirectory().isEmpty() ? QDir::homePath() : settings_->lastDirectory();
    suggestion = QDir(dir).filePath(document_->displayName());
  }
  const QString path = QFileDialog::getSaveFileName(this, tr("Save program as"), suggestion,
                                                    tr("Lathe programs (*.txt *.nc);;All files (*)"));
  if (path.isEmpty()) return false;
  return saveFile(path);
}

bool MainWindow::saveFile(const QString& path) {
  // A line too long to edit was left out of the editor: writing over the file would delete it.
  if (const int omitted = document_->firstOmittedLine();
      omitted > 0 && QFileInfo(path).absoluteFilePath() == QFileInfo(document_->filePath()).absoluteFilePath()) {
    QMessageBox::warning(this, tr("Cannot save over this file"),
                         tr("Line %1 of \"%2\" is too long to edit, so it is not in the editor. Saving over the file "
                            "would delete it: use Save As to write your version to another file.")
                             .arg(omitted)
                             .arg(document_->displayName()));
    return false;
  }
  // A file still going into the editor is saved whole: put the rest in first.
  if (fillingEditor_) {
    QTextCursor c(editor_->document());
    c.movePosition(QTextCursor::End);
    c.insertText(pendingText_.mid(pendingOffset_));
    pendingOffset_ = pendingText_.size();
    ++fillGeneration_;  // the queued chunks and finishLoad() of this fill are void now
    finishLoad();
  }
  QString error;
  const QString old = document_->filePath();
  if (!old.isEmpty()) watcher_->removePath(old);
  if (!document_->save(path, editor_->toPlainText(), &error)) {
    if (!old.isEmpty()) watcher_->addPath(old);
    QMessageBox::critical(this, tr("Cannot save the program"),
                          tr("\"%1\" could not be written:\n%2").arg(QDir::toNativeSeparators(path), error));
    return false;
  }
  editor_->document()->setModified(false);
  settings_->addRecentFile(document_->filePath());
  settings_->setLastDirectory(QFileInfo(document_->filePath()).absolutePath());
  if (!document_->isPlainGcode()) settings_->setLastJobHeader(document_->header());
  watchFile(document_->filePath());
  updateTitle();
  statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(document_->filePath())), 3000);
  return true;
}

void MainWindow::watchFile(const QString& path) {
  // An atomic save replaces the file; watch the new one.
  if (!watcher_->files().contains(path)) watcher_->addPath(path);
}

void MainWindow::onFileChangedOnDisk(const QString& path) {
  if (path != document_->filePath()) return;
  // Editors often write in several steps: wait until the file settles.
  diskChangeTimer_->disconnect();
  connect(diskChangeTimer_, &QTimer::timeout, this, [this, path] {
    if (path != document_->filePath()) return;
    if (!QFileInfo::exists(path)) return;  // deleted or mid-rename; a later change re-triggers
    watchFile(path);
    QMessageBox box(this);
    box.setObjectName(QStringLiteral("fileChangedBox"));
    box.setIcon(QMessageBox::Question);
    box.setWindowTitle(tr("File changed on disk"));
    box.setText(tr("\"%1\" was changed by another program.").arg(document_->displayName()));
    box.setInformativeText(isModified() ? tr("Reload it and lose your changes here?") : tr("Reload it?"));
    QPushButton* reload = box.addButton(tr("&Reload"), QMessageBox::AcceptRole);
    QPushButton* keep = box.addButton(tr("&Keep mine"), QMessageBox::RejectRole);
    reload->setObjectName(QStringLiteral("reloadButton"));
    keep->setObjectName(QStringLiteral("keepButton"));
    box.exec();
    if (box.clickedButton() == reload) startLoad(path);
  });
  diskChangeTimer_->start();
}

void MainWindow::updateRecentMenu() {
  recentMenu_->clear();
  const QStringList files = settings_->recentFiles();
  for (int i = 0; i < files.size(); ++i) {
    QAction* a = recentMenu_->addAction(
        QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(files[i]).fileName().replace(QLatin1Char('&'), QStringLiteral("&&"))));
    a->setToolTip(QDir::toNativeSeparators(files[i]));
    a->setStatusTip(QDir::toNativeSeparators(files[i]));
    const QString path = files[i];
    connect(a, &QAction::triggered, this, [this, path] { openFile(path); });
  }
  if (files.isEmpty()) recentMenu_->addAction(tr("(none)"))->setEnabled(false);
}

// ---------------------------------------------------------------- checking

void MainWindow::scheduleCheck() { checkTimer_->start(); }

void MainWindow::checkNow() {
  checkTimer_->stop();
  startCheck();
}

core::io::ProgramFile MainWindow::currentProgramFile() const {
  core::io::ProgramFile f;
  f.header = document_->header();
  f.plainGcode = document_->isPlainGcode();
  f.gcodeFirstLine = document_->gcodeFirstLine();
  f.gcode = editor_->toPlainText().toStdString();
  return f;
}

void MainWindow::startCheck() { startCheckOn(editor_->toPlainText()); }

void MainWindow::startCheckOn(const QString& text) {
  if (checkWatcher_.isRunning()) {  // one check at a time; the newest text goes next
    checkPending_ = true;
    return;
  }
  checkPending_ = false;
  core::gcode::CheckOptions options;
  options.dialect = dialect_;
  options.powerOnUnits = powerOnUnits_;
  options.toolsWithBitmap = toolsWithBitmap_;
  ++checkGeneration_;
  checkInFlight_ = true;
  const int profileLimit = core::gcode::machineProfile(dialect_).maxToolStation;
  const int stations = profileLimit > 0 ? std::min(profileLimit, setup_.tools.stations) : setup_.tools.stations;
  options.turretStations = setup_.tools.stations;
  const QString folder =
      document_->filePath().isEmpty() ? QString() : QFileInfo(document_->filePath()).absolutePath();
  checkWatcher_.setFuture(QtConcurrent::run(checkWithTools, text, document_->gcodeFirstLine(), options, setup_,
                                            toolOverrides_, stations, folder));
  QTimer::singleShot(300, this, &MainWindow::showBusyIndicator);
}

void MainWindow::onCheckFinished() {
  checkInFlight_ = false;
  if (checkPending_ || checkTimer_->isActive()) {
    // The text changed while checking: this result is out of date.
    if (checkPending_) startCheck();
    return;
  }
  appliedGeneration_ = checkGeneration_;
  lastDiagnostics_ = document_->fileDiagnostics();
  const JobToolsResult result = checkWatcher_.result();
  const auto& found = result.diagnostics;
  lastDiagnostics_.insert(lastDiagnostics_.end(), found.begin(), found.end());
  if (result.fit) dialectOffer_->offer(*result.fit, result.fitBlocks);
  else dialectOffer_->clear();
  // The job's tools: library choices for the stations the program uses (a note per choice in Tool Select).
  const bool toolsChanged = !sameTools(result.inference.setup, toolInference_.setup);
  toolInference_ = result.inference;
  if (toolsChanged) runner_->setMachineSetup(toolInference_.setup);
  std::stable_sort(lastDiagnostics_.begin(), lastDiagnostics_.end(), [](const auto& a, const auto& b) {
    return a.range.line != b.range.line ? a.range.line < b.range.line : a.range.column < b.range.column;
  });
  showDiagnostics();
  if (!isBusy() && !runner_->isBusy()) busyBar_->hide();
  emit checkFinished();
}

void MainWindow::showDiagnostics() {
  std::vector<core::Diagnostic> all = lastDiagnostics_;
  all.insert(all.end(), runDiagnostics_.begin(), runDiagnostics_.end());
  editor_->setDiagnostics(all);
  diagnostics_->setDiagnostics(std::move(all));
}

// ---------------------------------------------------------------- running

void MainWindow::loadMachineSetup(const QString& dir) {
  // A dialog that wrote a per-user copy tells us where; otherwise the core decides.
  configDir_ = dir.isEmpty() ? QString::fromStdString(core::io::findConfigDir(configDirOverride_.toStdString())) : dir;
  if (!dir.isEmpty()) configDirOverride_ = dir;
  const QDir folder(configDir_);
  QStringList problems;
  auto note = [&problems](const std::vector<core::Diagnostic>& diags) {
    for (const auto& d : diags)
      if (core::isError(d.severity))
        problems << QString::fromStdString(core::formatMessage(d, Language::coreLang()));
  };
  // machine.cfg first: its turret size bounds the tool table.
  const QString machinePath = folder.filePath(QStringLiteral("machine.cfg"));
  if (QFileInfo::exists(machinePath)) {
    auto machine = core::io::readMachineConfig(machinePath.toStdString());
    note(machine.diagnostics);
    if (machine.value) setup_.machine = *machine.value;
  }
  auto tools = core::io::readToolTable(folder.filePath(QStringLiteral("tools.cfg")).toStdString(),
                                       setup_.machine.turretStations);
  note(tools.diagnostics);
  if (tools.value) {
    setup_.tools = *tools.value;
    std::vector<int> withBitmap;
    for (int t = 1; t <= core::io::kToolCount; ++t)
      if (!setup_.tools.bitmap[static_cast<std::size_t>(t - 1)].empty()) withBitmap.push_back(t);
    toolsWithBitmap_ = withBitmap;
  } else {
    toolsWithBitmap_.reset();
  }
  auto offsets = core::io::readOffsetTable(folder.filePath(QStringLiteral("offset.cfg")).toStdString());
  note(offsets.diagnostics);
  if (offsets.value) setup_.offsets = *offsets.value;
  setupProblems_ = problems.join(QLatin1Char('\n'));
  runner_->setMachineSetup(setup_);
  toolInference_ = {};  // the next check decides the job's tools from the new tables
  toolInference_.setup = setup_;
}

void MainWindow::syncRunner() {
  if (checkTimer_->isActive()) checkNow();
  if (!runnerStale_) return;
  const QList<int> lines = editor_->breakpointFileLines();
  runner_->setBreakpoints(QSet<int>(lines.begin(), lines.end()));
  runner_->setProgram(currentProgramFile(), document_->displayName());
  // The program's folder is the control's memory: subprogram files (O1000.nc) come from there.
  runner_->setProgramFolder(document_->filePath().isEmpty() ? QString() : QFileInfo(document_->filePath()).absolutePath());
  runnerStale_ = false;
}

void MainWindow::runToCursor() {
  syncRunner();
  hideBanner();
  runner_->runToLine(editor_->cursorFileLine());
}

void MainWindow::toggleBreakpoint() { editor_->toggleBreakpoint(editor_->cursorFileLine()); }

void MainWindow::onRunStateChanged(RunState state) {
  const bool running = state == RunState::Running || state == RunState::Stepping || state == RunState::Preparing;
  const bool active = running || state == RunState::Paused;
  action(QStringLiteral("actionGo"))->setEnabled(!running || state == RunState::Stepping);
  action(QStringLiteral("actionStep"))->setEnabled(!running || state == RunState::Running);
  action(QStringLiteral("actionStepInto"))->setEnabled(!running || state == RunState::Running);
  action(QStringLiteral("actionStepOut"))->setEnabled(!running || state == RunState::Running);
  action(QStringLiteral("actionPause"))->setEnabled(running);
  action(QStringLiteral("actionStop"))->setEnabled(active || state == RunState::Finished || state == RunState::Alarm);
  action(QStringLiteral("actionStepBack"))->setEnabled(!running && state != RunState::Idle);
  // The text being run must not change under the animation.
  editor_->setReadOnly(running);
  for (const char* n : {"actionNew", "actionOpen", "actionToolSelect", "actionOffsetDefine", "actionJobDetails"})
    action(QString::fromLatin1(n))->setEnabled(!running);
  if (state == RunState::Idle) editor_->setExecutingLine(0);
  if (state == RunState::Running || state == RunState::Stepping || state == RunState::Preparing) {
    if (!runDiagnostics_.empty()) {
      runDiagnostics_.clear();
      showDiagnostics();
    }
  }
  // The run's notices (a vacant address left out, M99 in the main program, a
  // #3006 stop message) up to where it stands, for lines of this file.
  if ((state == RunState::Paused || state == RunState::Finished) && runner_->timeline()) {
    const core::machine::Timeline& t = *runner_->timeline();
    const int upTo = runner_->currentSnapshot() < 0 ? -1 : t.snapshots[static_cast<std::size_t>(runner_->currentSnapshot())].line;
    bool added = false;
    for (const core::Diagnostic& n : t.flow.notices) {
      if (n.range.file != 0 || (state == RunState::Paused && n.range.line > upTo)) continue;
      const bool seen = std::any_of(runDiagnostics_.begin(), runDiagnostics_.end(), [&n](const core::Diagnostic& d) {
        return d.code == n.code && d.range == n.range;
      });
      if (!seen) {
        runDiagnostics_.push_back(n);
        added = true;
      }
    }
    if (added) showDiagnostics();
  }
}

void MainWindow::onAlarm(const core::Diagnostic& alarm) {
  runDiagnostics_ = {alarm};
  showDiagnostics();
  editor_->setExecutingLine(alarm.range.line);
  showBanner(tr("Alarm %1 on line %2: %3")
                 .arg(QString::fromStdString(alarm.code))
                 .arg(alarm.range.line)
                 .arg(QString::fromStdString(core::formatMessage(alarm, Language::coreLang()))),
             true);
}

void MainWindow::onCheckFailed(const QList<core::Diagnostic>& diags) {
  int errors = 0;
  for (const auto& d : diags) errors += core::isError(d.severity);
  showBanner(tr("The program has %n error(s); fix them before running. Click an error below to go to it.", nullptr,
                errors),
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

void MainWindow::showBanner(const QString& text, bool error) {
  QPalette p = banner_->palette();
  p.setColor(QPalette::Window, error ? QColor(0xfd, 0xe2, 0xe2) : QColor(0xfd, 0xf4, 0xd0));
  p.setColor(QPalette::WindowText, error ? QColor(0x80, 0x10, 0x10) : QColor(0x60, 0x48, 0x00));
  banner_->setPalette(p);
  bannerLabel_->setText(text);
  banner_->show();
}

void MainWindow::hideBanner() {
  banner_->hide();
  bannerLabel_->clear();
}

void MainWindow::updateStockLabel() {
  if (!stockLabel_ || !document_) return;
  QStringList notes;
  for (const core::Diagnostic& d : document_->stockNotes())
    notes << QString::fromStdString(core::formatMessage(d, Language::coreLang()));
  QString first = notes.isEmpty() ? QString() : notes.front();
  if (!first.isEmpty()) first[0] = first[0].toUpper();  // "Stock Ø50 x 80 mm inferred from ..."
  stockLabel_->setText(first);
  stockLabel_->setToolTip(notes.join(QLatin1Char('\n')));
  stockLabel_->setVisible(!notes.isEmpty());
}

QString MainWindow::stockSourceText() const { return stockLabel_ ? stockLabel_->text() : QString(); }

QString MainWindow::bannerText() const { return banner_->isVisible() ? bannerLabel_->text() : QString(); }

// ---------------------------------------------------------------- dialogs

// ---------------------------------------------------------------- reports

render::ReportData MainWindow::reportData(bool withPart) const {
  const render::ReportLanguage lang =
      Language::instance()->isThai() ? render::ReportLanguage::Thai : render::ReportLanguage::English;
  render::ReportData data;
  data.program = currentProgramFile();
  data.fileName = document_->displayName();
  data.date = QDate::currentDate();
  if (withPart) {
    QApplication::setOverrideCursor(Qt::WaitCursor);
    data.part = render::finishedPart(data.program, toolInference_.setup, dialect_, lang, &data.partNote);
    QApplication::restoreOverrideCursor();
  }
  return data;
}

void MainWindow::paintReports(QPainter& painter, QPagedPaintDevice& device, const render::ReportData& data, bool code,
                              bool drawing) {
  const render::ReportLanguage lang =
      Language::instance()->isThai() ? render::ReportLanguage::Thai : render::ReportLanguage::English;
  if (code) render::paintProgramSheet(painter, device, data, lang);
  if (code && drawing) {
    // A shaft is long: the drawing goes on a landscape page (takes effect on the next page);
    // the device keeps its own orientation for the next job.
    const QPageLayout::Orientation before = device.pageLayout().orientation();
    device.setPageOrientation(QPageLayout::Landscape);
    device.newPage();
    render::paintDrawingSheet(painter, device, data, lang);
    device.setPageOrientation(before);
    return;
  }
  if (drawing) render::paintDrawingSheet(painter, device, data, lang);
}

namespace {
void preparePrinter(QPrinter& printer, const QString& title) {
  printer.setDocName(title);
  printer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
}
}  // namespace

void MainWindow::printCode() {
  QPrinter printer(QPrinter::HighResolution);
  preparePrinter(printer, document_->displayName());
  QPrintDialog dialog(&printer, this);
  dialog.setWindowTitle(tr("Print Code"));
  if (dialog.exec() != QDialog::Accepted) return;
  const render::ReportData data = reportData(false);
  QPainter painter(&printer);
  paintReports(painter, printer, data, true, false);
}

void MainWindow::printCodeNow() {
  const QPrinterInfo info = QPrinterInfo::defaultPrinter();
  if (info.isNull()) {
    statusBar()->showMessage(tr("No printer is set up: use File > Export PDF to save the sheet."), 5000);
    return;
  }
  QPrinter printer(info, QPrinter::HighResolution);
  preparePrinter(printer, document_->displayName());
  const render::ReportData data = reportData(false);
  QPainter painter(&printer);
  paintReports(painter, printer, data, true, false);
  statusBar()->showMessage(tr("Program sheet sent to %1").arg(info.printerName()), 3000);
}

void MainWindow::printDrawing() {
  QPrinter printer(QPrinter::HighResolution);
  preparePrinter(printer, document_->displayName());
  printer.setPageOrientation(QPageLayout::Landscape);   // a shaft is long: landscape fits it larger
  QPrintDialog dialog(&printer, this);
  dialog.setWindowTitle(tr("Print Drawing"));
  if (dialog.exec() != QDialog::Accepted) return;
  const render::ReportData data = reportData(true);
  QPainter painter(&printer);
  paintReports(painter, printer, data, false, true);
}

void MainWindow::printPreview() {
  QPrinter printer(QPrinter::HighResolution);
  preparePrinter(printer, document_->displayName());
  const render::ReportData data = reportData(true);
  QPrintPreviewDialog dialog(&printer, this);
  dialog.setWindowTitle(tr("Print Preview"));
  connect(&dialog, &QPrintPreviewDialog::paintRequested, this, [this, &data](QPrinter* p) {
    QPainter painter(p);
    paintReports(painter, *p, data, true, true);
  });
  dialog.exec();
}

bool MainWindow::exportPdf(const QString& path) {
  QString target = path;
  if (target.isEmpty()) {
    const QFileInfo source(document_->isUntitled() ? document_->displayName() : document_->filePath());
    target = QFileDialog::getSaveFileName(this, tr("Export PDF"),
                                          source.dir().filePath(source.completeBaseName() + QStringLiteral(".pdf")),
                                          tr("PDF files (*.pdf)"));
    if (target.isEmpty()) return false;
  }
  const render::ReportData data = reportData(true);
  QPdfWriter writer(target);
  writer.setTitle(document_->displayName());
  writer.setCreator(render::kluengVersion());
  writer.setResolution(600);
  writer.setPageSize(QPageSize(QPageSize::A4));
  writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
  QPainter painter;
  if (!painter.begin(&writer)) {
    QMessageBox::warning(this, tr("Export PDF"), tr("Cannot write %1").arg(QDir::toNativeSeparators(target)));
    return false;
  }
  paintReports(painter, writer, data, true, true);
  painter.end();
  statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(target)), 3000);
  return true;
}

void MainWindow::showJobDetails() {
  JobDetailsDialog dlg(document_->header(), this);
  if (dlg.exec() != QDialog::Accepted) return;
  document_->setHeader(dlg.header());
  if (!document_->isPlainGcode()) settings_->setLastJobHeader(dlg.header());
  else if (!document_->isUntitled()) settings_->setJobDetailsFor(document_->filePath(), dlg.header());
  checkNow();
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

void MainWindow::showToolSelect() {
  ToolSelectDialog dlg(configDir_, this);
  dlg.setProgramTools(toolInference_, toolOverrides_);
  if (dlg.exec() != QDialog::Accepted) return;
  toolOverrides_ = dlg.jobOverrides();
  saveToolOverrides(document_->filePath(), toolOverrides_);
  loadMachineSetup(dlg.savedConfigDir());
  runnerStale_ = true;
  checkNow();
}

void MainWindow::showOffsetDefine() {
  OffsetDefineDialog dlg(configDir_, this);
  if (dlg.exec() != QDialog::Accepted) return;
  loadMachineSetup(dlg.savedConfigDir());
  runnerStale_ = true;
  checkNow();  // empty offset rows may take a library tool's nose radius and tip
}

void MainWindow::showHelpContents() {
  if (!help_) {
    help_ = new HelpContents(this);
    help_->setDialect(dialect_);
  }
  help_->show();
  help_->raise();
  help_->activateWindow();
}

void MainWindow::showAbout() {
  AboutDialog dlg(this);
  dlg.exec();
}

}  // namespace klueng::gui

#include "gui/action_table.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QLocale>
#include <QMainWindow>
#include <QMenuBar>
#include <QToolBar>

#include "gui/run_speed_control.h"

namespace klueng::gui {

namespace {

// The texts keep the main window's translation context: one catalogue for the window.
#define KLUENG_TR(text) QT_TRANSLATE_NOOP("klueng::gui::MainWindow", text)
constexpr const char* kContext = "klueng::gui::MainWindow";

QString translated(const char* text) { return text ? QCoreApplication::translate(kContext, text) : QString(); }

struct ActionSpec {
  const char* name;
  const char* icon;  // :/icons/<icon>.svg, or none
  QKeySequence::StandardKey standardKey;
  const char* keys;  // portable text when there is no standard key
  const char* text;
  const char* tip;  // status and tool tip; the text without '&' when none
  EnabledWhen enabledWhen = EnabledWhen::Always;
  bool checkable = false;
  bool editorLocal = false;  // the editor's own key handles it while it has the focus
};

constexpr auto kNoKey = QKeySequence::UnknownKey;

const ActionSpec kActions[] = {
    // File
    {"actionNew", "new", QKeySequence::New, nullptr, KLUENG_TR("&New"), KLUENG_TR("Start a new program"),
     EnabledWhen::NotRunning},
    {"actionOpen", "open", QKeySequence::Open, nullptr, KLUENG_TR("&Open..."), KLUENG_TR("Open a program file"),
     EnabledWhen::NotRunning},
    {"actionSave", "save", QKeySequence::Save, nullptr, KLUENG_TR("&Save"), KLUENG_TR("Save the program")},
    {"actionSaveAs", "save-as", kNoKey, "Ctrl+Shift+S", KLUENG_TR("Save &As..."),
     KLUENG_TR("Save the program under a new name")},
    {"actionJobDetails", "job", kNoKey, "Ctrl+J", KLUENG_TR("&Job details..."),
     KLUENG_TR("Project, part, material, stock size and programmer"), EnabledWhen::NotRunning},
    {"actionPrintCode", "print", QKeySequence::Print, nullptr, KLUENG_TR("&Print Code..."),
     KLUENG_TR("Print the program sheet: job details and the numbered program")},
    {"actionPrint", "print", kNoKey, nullptr, KLUENG_TR("Print"),
     KLUENG_TR("Print the program sheet at once on the default printer")},
    {"actionPrintDrawing", "print-drawing", kNoKey, "Ctrl+Shift+P", KLUENG_TR("Print &Drawing..."),
     KLUENG_TR("Print the finished part to scale with its title block")},
    {"actionPrintPreview", "print-preview", kNoKey, nullptr, KLUENG_TR("Print Pre&view..."),
     KLUENG_TR("Preview the program sheet and the drawing sheet")},
    {"actionExportPdf", "export-pdf", kNoKey, nullptr, KLUENG_TR("&Export PDF..."),
     KLUENG_TR("Save the program sheet and the drawing sheet as a PDF file")},
    {"actionGradeClass", "job", kNoKey, nullptr, KLUENG_TR("&Grade a class..."),
     KLUENG_TR("Grade every program in a folder against a reference program"), EnabledWhen::NotRunning},
    {"actionPartDesigner", "job", kNoKey, "Ctrl+Shift+D", KLUENG_TR("Part &Designer..."),
     KLUENG_TR("Draw a turned part and get its program, checked by cutting it"), EnabledWhen::NotRunning},
    {"actionExit", "exit", kNoKey, "Ctrl+Q", KLUENG_TR("E&xit"), nullptr},
    // Edit
    // One Undo / Redo for the text and the setup (issue 30 item 2): window-wide keys, the
    // editor passes Ctrl+Z / Ctrl+Y on to them; the window names and enables them.
    {"actionUndo", "undo", QKeySequence::Undo, nullptr, KLUENG_TR("&Undo"), nullptr},
    {"actionRedo", "redo", QKeySequence::Redo, nullptr, KLUENG_TR("&Redo"), nullptr},
    {"actionCut", "cut", QKeySequence::Cut, nullptr, KLUENG_TR("Cu&t"), nullptr, EnabledWhen::Always, false, true},
    {"actionCopy", "copy", QKeySequence::Copy, nullptr, KLUENG_TR("&Copy"), nullptr, EnabledWhen::Always, false, true},
    {"actionPaste", "paste", QKeySequence::Paste, nullptr, KLUENG_TR("&Paste"), nullptr, EnabledWhen::Always, false,
     true},
    {"actionDelete", "delete", QKeySequence::Delete, nullptr, KLUENG_TR("&Delete"), nullptr, EnabledWhen::Always, false,
     true},
    {"actionSelectAll", nullptr, QKeySequence::SelectAll, nullptr, KLUENG_TR("Select &All"), nullptr,
     EnabledWhen::Always, false, true},
    {"actionFind", "find", QKeySequence::Find, nullptr, KLUENG_TR("&Find..."), KLUENG_TR("Find text in the program")},
    {"actionReplace", nullptr, kNoKey, "Ctrl+H", KLUENG_TR("R&eplace..."), KLUENG_TR("Find and replace text")},
    {"actionGoToLine", "goto", kNoKey, "Ctrl+G", KLUENG_TR("&Go to Line..."), nullptr},
    // Run
    {"actionGo", "go", kNoKey, "F5", KLUENG_TR("&Go"), KLUENG_TR("Run the program continuously"), EnabledWhen::CanGo},
    {"actionStep", "step", kNoKey, "F10", KLUENG_TR("&Step"),
     KLUENG_TR("Run one block, then wait (a subprogram or macro call runs whole)"), EnabledWhen::CanStep},
    {"actionStepInto", "step", kNoKey, "F11", KLUENG_TR("Step &Into"),
     KLUENG_TR("Run one block, into a subprogram or macro it calls"), EnabledWhen::CanStep},
    {"actionStepOut", "step", kNoKey, "Shift+F11", KLUENG_TR("Step O&ut"),
     KLUENG_TR("Run to the end of this subprogram or macro"), EnabledWhen::CanStep},
    {"actionPause", "pause", kNoKey, "F6", KLUENG_TR("&Pause"),
     KLUENG_TR("Stop after the current step; Go or Step resumes"), EnabledWhen::Running},
    {"actionStop", "stop", kNoKey, "Shift+F5", KLUENG_TR("S&top"), KLUENG_TR("Abort the run and reset"),
     EnabledWhen::Started},
    {"actionStepBack", "step-back", kNoKey, "Shift+F10", KLUENG_TR("Step &Back"), KLUENG_TR("Go back one block"),
     EnabledWhen::StoppedMidRun},
    {"actionRunToCursor", "run-to-cursor", kNoKey, "Ctrl+F10", KLUENG_TR("Run to &Cursor"),
     KLUENG_TR("Run up to the block at the cursor")},
    {"actionToggleBreakpoint", "breakpoint", kNoKey, "F9", KLUENG_TR("Toggle &Breakpoint"),
     KLUENG_TR("Stop the run before this line")},
    {"actionOptionalStop", "optional-stop", kNoKey, "Ctrl+M", KLUENG_TR("&Optional Stop"),
     KLUENG_TR("M01 stops the run when this switch is on"), EnabledWhen::Always, true},
    {"actionBlockSkip", "block-skip", kNoKey, "Ctrl+/", KLUENG_TR("Block S&kip"),
     KLUENG_TR("Blocks starting with / are skipped when this switch is on"), EnabledWhen::Always, true},
    // Tool setting
    {"actionToolSelect", "tool", kNoKey, "Ctrl+T", KLUENG_TR("Tool &Select..."),
     KLUENG_TR("Choose the bitmap of each tool 01-08"), EnabledWhen::NotRunning},
    {"actionOffsetDefine", "offset", kNoKey, "Ctrl+Shift+O", KLUENG_TR("Offset &Define..."),
     KLUENG_TR("Edit the 16 tool offsets"), EnabledWhen::NotRunning},
    {"actionDialectFanuc", nullptr, kNoKey, nullptr, KLUENG_TR("&Fanuc 0i-TF"), nullptr, EnabledWhen::Always, true},
    {"actionDialectHaas", nullptr, kNoKey, nullptr, KLUENG_TR("&Haas ST lathe (NGC)"), nullptr, EnabledWhen::Always,
     true},
    {"actionDialectClassic", nullptr, kNoKey, nullptr, KLUENG_TR("&Rook classic (1999 rules)"), nullptr,
     EnabledWhen::Always, true},
    {"actionUnitsMachine", nullptr, kNoKey, nullptr, KLUENG_TR("Power-on units as the &machine (Haas: inch)"), nullptr,
     EnabledWhen::Always, true},
    {"actionUnitsMm", nullptr, kNoKey, nullptr, KLUENG_TR("&Power-on units: millimetres"), nullptr, EnabledWhen::Always,
     true},
    {"actionUnitsInch", nullptr, kNoKey, nullptr, KLUENG_TR("Power-on units: &inches"), nullptr, EnabledWhen::Always,
     true},
    // View
    {"actionFitView", "fit", kNoKey, "Ctrl+0", KLUENG_TR("&Fit to View"), nullptr},
    {"actionZoomIn", "zoom-in", QKeySequence::ZoomIn, nullptr, KLUENG_TR("Zoom &In"), nullptr},
    {"actionZoomOut", "zoom-out", QKeySequence::ZoomOut, nullptr, KLUENG_TR("Zoom &Out"), nullptr},
    {"actionShowPath", nullptr, kNoKey, nullptr, KLUENG_TR("Show Tool &Path"), nullptr, EnabledWhen::Always, true},
    {"actionShowStatusBar", nullptr, kNoKey, nullptr, KLUENG_TR("&Status Bar"), nullptr, EnabledWhen::Always, true},
    {"actionShowLamps", nullptr, kNoKey, nullptr, KLUENG_TR("Status &Lamps"), nullptr, EnabledWhen::Always, true},
    {"actionShowUnitsAuto", nullptr, kNoKey, nullptr, KLUENG_TR("&Auto: the program's units (G20 inch, G21 mm)"),
     KLUENG_TR("Positions, feeds, rulers, features and the drawing in the units the program is written in"),
     EnabledWhen::Always, true},
    {"actionShowUnitsMm", nullptr, kNoKey, nullptr, KLUENG_TR("&Millimetres"), nullptr, EnabledWhen::Always, true},
    {"actionShowUnitsInch", nullptr, kNoKey, nullptr, KLUENG_TR("&Inches"), nullptr, EnabledWhen::Always, true},
    // Help
    {"actionContents", "contents", QKeySequence::HelpContents, nullptr, KLUENG_TR("&Contents"),
     KLUENG_TR("Help for self-learners: every G and M code with an example")},
    {"actionToggleLanguage", "language", kNoKey, "Ctrl+Shift+L", KLUENG_TR("Toggle &Language (ไทย/English)"),
     KLUENG_TR("Switch between Thai and English")},
    {"actionAbout", "klueng", kNoKey, nullptr, KLUENG_TR("&About Klueng"), nullptr},
};

// Items: action names, "|" a separator, "menuX" a submenu, "actionSpeed*" the speed actions,
// anything else a name given to add() (tool bar and dock toggles).
struct MenuSpec {
  const char* name;
  const char* title;
  const char* items;
};

const MenuSpec kMenus[] = {
    {"menuFile", KLUENG_TR("&File"),
     "actionNew actionOpen menuRecent actionSave actionSaveAs | actionJobDetails | actionPrintCode actionPrintDrawing "
     "actionPrintPreview actionExportPdf | actionPartDesigner actionGradeClass | actionExit"},
    {"menuRecent", KLUENG_TR("&Recent Files"), ""},
    {"menuEdit", KLUENG_TR("&Edit"),
     "actionUndo actionRedo | actionCut actionCopy actionPaste actionDelete "
     "actionSelectAll | actionFind actionReplace "
     "actionGoToLine"},
    {"menuRun", KLUENG_TR("&Run"),
     "actionGo actionStep actionStepInto actionStepOut actionPause actionStop | actionStepBack actionRunToCursor "
     "actionToggleBreakpoint | actionOptionalStop actionBlockSkip menuSpeed"},
    {"menuSpeed", KLUENG_TR("S&peed"), "actionSpeed*"},
    {"menuToolSetting", KLUENG_TR("&Tool setting"),
     "actionToolSelect actionOffsetDefine actionOptionalStop | menuDialect"},
    {"menuDialect", KLUENG_TR("G-code &dialect"),
     "actionDialectFanuc actionDialectHaas actionDialectClassic | actionUnitsMachine actionUnitsMm actionUnitsInch"},
    {"menuView", KLUENG_TR("&View"),
     "fileToolBar editToolBar runToolBar helpToolBar actionShowStatusBar actionShowLamps diagnosticsDock flowDock "
     "partDock view3dDock operatorPanelDock | "
     "actionShowPath actionFitView actionZoomIn actionZoomOut | menuShowUnits"},
    {"menuShowUnits", KLUENG_TR("&Units Shown"), "actionShowUnitsAuto actionShowUnitsMm actionShowUnitsInch"},
    {"menuHelp", KLUENG_TR("&Help"), "actionContents actionToggleLanguage | actionAbout"},
};
// Only these are on the menu bar; the others are submenus.
const char* const kMenuBar[] = {"menuFile", "menuEdit", "menuRun", "menuToolSetting", "menuView", "menuHelp"};

const MenuSpec kToolBars[] = {
    {"fileToolBar", KLUENG_TR("File tool bar"), "actionNew actionOpen actionSave actionPrint"},
    {"editToolBar", KLUENG_TR("Edit tool bar"), "actionUndo actionCut actionCopy actionPaste actionDelete actionFind"},
    {"runToolBar", KLUENG_TR("Run tool bar"),
     "actionGo actionStep actionPause actionStop actionStepBack actionRunToCursor"},
    {"helpToolBar", KLUENG_TR("Help tool bar"), "actionContents actionToggleLanguage"},
};

QStringList itemsOf(const char* items) {
  return QString::fromLatin1(items).split(QLatin1Char(' '), Qt::SkipEmptyParts);
}

QString speedText(double v) {
  if (v == RunController::kAsFastAsPossible) return translated(KLUENG_TR("As fast as possible"));
  if (v == 1.0) return translated(KLUENG_TR("1× (real time)"));
  return translated(KLUENG_TR("%1×")).arg(QLocale().toString(v));
}

#undef KLUENG_TR

}  // namespace

ActionTable::ActionTable(QMainWindow* window, int speedCount) : QObject(window), window_(window) {
  for (const ActionSpec& spec : kActions) {
    auto* a = new QAction(window);
    a->setObjectName(QString::fromLatin1(spec.name));
    if (spec.icon) a->setIcon(QIcon(QStringLiteral(":/icons/%1.svg").arg(QString::fromLatin1(spec.icon))));
    if (spec.standardKey != kNoKey)
      a->setShortcut(QKeySequence(spec.standardKey));
    else if (spec.keys)
      a->setShortcut(QKeySequence(QString::fromLatin1(spec.keys)));
    a->setCheckable(spec.checkable);
    if (spec.editorLocal) a->setShortcutContext(Qt::WidgetShortcut);
    actions_.insert(a->objectName(), a);
  }
  action(QStringLiteral("actionExit"))->setMenuRole(QAction::QuitRole);
  action(QStringLiteral("actionAbout"))->setMenuRole(QAction::AboutRole);
  auto* speeds = new QActionGroup(this);
  for (int i = 0; i < speedCount; ++i) {
    auto* a = new QAction(window);
    a->setObjectName(QStringLiteral("actionSpeed%1").arg(i));
    a->setCheckable(true);
    a->setData(i);
    speeds->addAction(a);
    actions_.insert(a->objectName(), a);
  }
  // Exclusive choices: one dialect, one power-on unit, one unit shown.
  for (const char* group : {"actionDialect", "actionUnits", "actionShowUnits"}) {
    auto* g = new QActionGroup(this);
    for (const ActionSpec& spec : kActions)
      if (QString::fromLatin1(spec.name).startsWith(QLatin1String(group)))
        g->addAction(action(QString::fromLatin1(spec.name)));
  }
}

void ActionTable::add(const QString& name, QAction* a) { actions_.insert(name, a); }

void ActionTable::buildToolBars() {
  for (const MenuSpec& spec : kToolBars) {
    QToolBar* bar = window_->addToolBar(QString());
    bar->setObjectName(QString::fromLatin1(spec.name));
    bar->setIconSize(QSize(24, 24));
    for (const QString& item : itemsOf(spec.items)) bar->addAction(action(item));
    toolBars_.insert(bar->objectName(), bar);
    add(bar->objectName(), bar->toggleViewAction());
  }
}

void ActionTable::buildMenus() {
  for (const MenuSpec& spec : kMenus) {
    auto* m = new QMenu(window_->menuBar());
    m->setObjectName(QString::fromLatin1(spec.name));
    menus_.insert(m->objectName(), m);
  }
  for (const MenuSpec& spec : kMenus) {
    QMenu* m = menu(QString::fromLatin1(spec.name));
    for (const QString& item : itemsOf(spec.items)) {
      if (item == QLatin1String("|"))
        m->addSeparator();
      else if (QMenu* sub = menu(item))
        m->addMenu(sub);
      else if (item.endsWith(QLatin1Char('*'))) {
        for (int i = 0; QAction* a = action(item.chopped(1) + QString::number(i)); ++i) m->addAction(a);
      } else if (QAction* a = action(item))
        m->addAction(a);
    }
  }
  for (const char* name : kMenuBar) window_->menuBar()->addMenu(menu(QString::fromLatin1(name)));
}

void ActionTable::retranslate() {
  for (const ActionSpec& spec : kActions) {
    QAction* a = action(QString::fromLatin1(spec.name));
    const QString text = translated(spec.text);
    const QString tip = spec.tip ? translated(spec.tip) : QString(text).remove(QLatin1Char('&'));
    a->setText(text);
    a->setStatusTip(tip);
    a->setToolTip(a->shortcut().isEmpty()
                      ? tip
                      : QStringLiteral("%1 (%2)").arg(tip, a->shortcut().toString(QKeySequence::NativeText)));
  }
  const std::vector<double>& steps = RunSpeedControl::steps();
  for (std::size_t i = 0; i < steps.size(); ++i)
    if (QAction* a = action(QStringLiteral("actionSpeed%1").arg(i))) a->setText(speedText(steps[i]));
  for (const MenuSpec& spec : kMenus)
    if (QMenu* m = menu(QString::fromLatin1(spec.name))) m->setTitle(translated(spec.title));
  for (const MenuSpec& spec : kToolBars)
    if (QToolBar* t = toolBar(QString::fromLatin1(spec.name))) t->setWindowTitle(translated(spec.title));
}

bool ActionTable::enabledIn(EnabledWhen when, RunState state) {
  const bool running = state == RunState::Running || state == RunState::Stepping || state == RunState::Preparing;
  switch (when) {
    case EnabledWhen::Always: return true;
    case EnabledWhen::NotRunning: return !running;
    case EnabledWhen::CanGo: return !running || state == RunState::Stepping;
    case EnabledWhen::CanStep: return !running || state == RunState::Running;
    case EnabledWhen::Running: return running;
    case EnabledWhen::Started: return state != RunState::Idle;
    case EnabledWhen::StoppedMidRun: return !running && state != RunState::Idle;
  }
  return true;
}

void ActionTable::applyRunState(RunState state) {
  for (const ActionSpec& spec : kActions)
    if (spec.enabledWhen != EnabledWhen::Always)
      action(QString::fromLatin1(spec.name))->setEnabled(enabledIn(spec.enabledWhen, state));
}

}  // namespace klueng::gui

#pragma once
// The main window (SPEC 12): title "Klueng : <file>", menus File / Edit / Run /
// Tool setting / View / Help, the tool bar, the G-code editor | output screen
// splitter, the diagnostics dock, status fields and lamps. It wires the
// editor, the document and the checker to F2's run controller, output view,
// status widgets and dialogs; it holds no machining logic.
#include <QFutureWatcher>
#include <QHash>
#include <QMainWindow>
#include <QPointer>
#include <functional>
#include <memory>
#include <optional>

#include "gui/check_controller.h"
#include "gui/job_document.h"
#include "gui/job_tools.h"
#include "gui/document.h"
#include "gui/run_controller.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/units.h"

class QAction;
class QActionGroup;
class QComboBox;
class QFileSystemWatcher;
class QLabel;
class QMenu;
class QProgressBar;
class QSplitter;
class QTimer;
class QToolBar;
class QToolButton;
class QUndoGroup;
class QUndoStack;

namespace klueng::gui {

class CodeEditor;
class DiagnosticsPanel;
class DialectOfferBar;
class FindDialog;
class PartDesignerDialog;
class HelpContents;
class RunSpeedControl;
class OutputView;
class Settings;
class StatusFields;
class StatusLamps;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Opens a file in the background (after the unsaved-changes prompt). Returns
  // false when the user cancelled; fileLoaded / loadFailed follow otherwise.
  bool openFile(const QString& path);
  // Saves to `path` atomically; false (with a message box) on failure.
  bool saveFile(const QString& path);

  CodeEditor* editor() const { return editor_; }
  DiagnosticsPanel* diagnosticsPanel() const { return diagnostics_; }
  Document* document() const { return document_; }
  class DocumentManager* documentManager() const {
    return docs_;
  }
  class RecoveryBar* recoveryBar() const {
    return recoveryBar_;
  }
  class FirstStepsBar* firstSteps() const {
    return firstSteps_;
  }
  // The document's edits, text and setup, in the order made (Edit > Undo / Redo).
  QUndoStack* undoStack() const { return jobDoc_.undoStack(); }
  // The tool and offset tables and this program's stations as held in memory (saved by File > Save).
  const JobDocument& jobDocument() const { return jobDoc_; }
  RunController* runController() const { return runner_; }
  class FlowPanel* flowPanel() const {
    return flow_;
  }
  class PartPanel* partPanel() const {
    return part_;
  }
  class OperatorPanel* operatorPanel() const {
    return operatorPanel_;
  }
  class Part3DDock* view3dDock() const {
    return view3d_;
  }
  OutputView* outputView() const { return output_; }
  StatusFields* statusFields() const { return statusFields_; }
  class ExplainBar* explainBar() const {
    return explainBar_;
  }
  StatusLamps* statusLamps() const { return statusLamps_; }
  QSplitter* splitter() const { return splitter_; }
  // The banner above the editor (alarms, "fix the errors first"); empty when hidden.
  QString bannerText() const;
  // A cycle time as people say it: "3 min 12.4 s" / "3 นาที 12.4 วินาที".
  static QString formatDuration(double seconds);
  // Where the open program's stock came from (header, Job details, inferred ...).
  QString stockSourceText() const;
  // Stock and tools above the output screen (issue 26).
  class SetupStrip* setupStrip() const {
    return setupStrip_;
  }
  // Actions by object name ("actionGo", "actionSave", ...), for tests.
  QAction* action(const QString& objectName) const;

  // True while a file loads or a check runs in the background.
  bool isBusy() const;
  // Diagnostics of the last finished check (checker + file header).
  const std::vector<core::Diagnostic>& diagnostics() const { return lastDiagnostics_; }
  core::gcode::Dialect dialect() const { return jobDoc_.dialect(); }
  // The machine chosen in the menu: every program that names none is checked on it (remembered).
  void setDialect(core::gcode::Dialect d);
  // The machine of the program in the editor only (its `(MACHINE: id)` line, an offer taken):
  // not remembered, so the next file opened is read on the menu's machine again (issue 38 item 8).
  void useMachineForThisProgram(core::gcode::Dialect d);
  // The offer bar's switch: the program's head names the machine (one undo step), and it is used.
  void takeMachineOffer(core::gcode::Dialect d);
  // Units before any G20/G21 (Dialect menu; remembered): nullopt = the dialect's.
  void setPowerOnUnits(std::optional<core::gcode::InputUnits> units);
  // The unit lengths are shown in (View ▸ Units shown; remembered): nullopt = Auto,
  // the program's own (its G20/G21, else the power-on units). Issue 28 item 4.
  void setShownUnits(std::optional<core::DisplayUnits> units);
  core::UnitFormat displayUnits() const { return core::UnitFormat(shownUnits_.value_or(programUnits_)); }
  QString configDir() const { return configDir_; }

 public slots:
  void newFile();
  void open();
  bool save();
  bool saveAs();
  void showJobDetails();
  void setJobDetails(const core::io::JobHeader& header);  // as the dialog's OK does: undoable
  // Writes or rewrites the program's `(MACHINE: id)` head line ("" takes it out): one edit of the changed lines.
  void nameMachineInProgram(const std::string& id);
  void showPartDesigner();
  // Reports (SPEC 12): the program sheet and the drawing sheet, in the UI's language.
  void printCode();     // File > Print Code: printer dialog
  void printCodeNow();  // tool bar Print: the default printer, no dialog
  void printDrawing();
  void printPreview();                       // both sheets
  bool exportPdf(const QString& path = {});  // both sheets; asks for a path when empty
  void showFind();
  void goToLine();
  void toggleBreakpoint();
  void runToCursor();
  void showToolSelect();
  void showToolSelectFor(int station);  // Tool Select on that station (0: as it opens)
  void showOffsetDefine();
  void showHelpContents();
  void showAbout();
  void toggleLanguage();
  // Check the editor's text now (still off the GUI thread).
  void checkNow();

 signals:
  void fileLoaded(const QString& path);
  void loadFailed(const QString& path);
  void checkFinished();

 protected:
  void closeEvent(QCloseEvent* event) override;
  void changeEvent(QEvent* event) override;

 private:
  // The constructor's steps, in order.
  void takeSettings();
  void createEditorAndRunner();
  void createDocumentControllers();
  void createCentralArea();
  QWidget* createEditorPane();
  QWidget* createOutputPane();
  void createStatusBar();
  void createChecker();
  void createUndoGroup();
  void createActions();  // its steps:
  void connectOperatorPanel();
  void connectFileActions();
  void connectEditActions();
  void connectUndoActions();
  void connectRunActions();
  void createSpeedControl();
  void connectSetupActions();
  void connectViewAndHelpActions();
  // The named action's triggered() runs `slot`.
  template <class Slot>
  void on(const char* actionName, Slot&& slot);
  void createDocks();
  void connectDocuments();
  void connectEditing();
  void connectRunner();
  void startUp();
  void retranslateUi();
  void restoreLayout();
  void saveLayout();

  void updateTitle();
  void showBusyIndicator();

  CheckController::Request checkRequest() const;
  void onCheckFinished(const CheckController::JobPtr& job);
  void showDiagnostics();

  // Reads the setup folder; unsaved edits of the tool and offset tables stay (a dialect's
  // machine keys change, not the user's edits) unless `keepEdits` is false.
  void loadMachineSetup(const QString& dir = {}, bool keepEdits = true);
  // The machines past the three shipped dialects (romi-gl240m, the user's own
  // machines folders) in the dialect menu, named in the UI language (issue 27).
  void updateMachineMenu();
  // A setup dialog's result as one undo command on the document's stack (none when nothing changed).
  void pushSetupEdit(const QString& text, const SetupEdit& after);
  // What the command does and undoes: the in-memory setup, and every reader of it told.
  void applySetupEdit(const SetupEdit& edit);
  // File > Save's part for the setup: the edited files, the stations set for `programPath`.
  bool saveSetup(const QString& programPath);
  // The edits are dropped (a new or another program after Discard): the setup as on disk.
  void revertSetup();
  // The open file's folder (subprogram files come from there); empty when untitled.
  QString programFolder() const;
  // Hand the editor's current text to the run controller (before a run).
  void syncRunner();
  core::io::ProgramFile currentProgramFile() const;
  void onRunStateChanged(RunState state);
  void onAlarm(const core::Diagnostic& alarm);
  void onCheckFailed(const QList<core::Diagnostic>& diags);
  // What the banner says, made again in the current language on a language
  // switch; an edit of the program takes away what a run said about the old text.
  enum class BannerKind { Setup, RunEnded, Alarm, Refused };
  void showBanner(BannerKind kind, std::function<QString()> text, bool error);
  void hideBanner();
  void updateStockLabel();
  void setSpeedIndex(int index);

  std::unique_ptr<Settings> settings_;
  class DocumentManager* docs_ = nullptr;
  Document* document_ = nullptr;  // docs_'s
  class ReportController* reports_ = nullptr;
  class ActionTable* actions_ = nullptr;
  CodeEditor* editor_ = nullptr;
  DiagnosticsPanel* diagnostics_ = nullptr;
  class FlowPanel* flow_ = nullptr;
  class PartPanel* part_ = nullptr;
  class Part3DDock* view3d_ = nullptr;
  class OperatorPanel* operatorPanel_ = nullptr;  // issue 31: the machine's control, hidden at first
  RunController* runner_ = nullptr;
  OutputView* output_ = nullptr;
  StatusFields* statusFields_ = nullptr;
  StatusLamps* statusLamps_ = nullptr;
  QSplitter* splitter_ = nullptr;
  class Banner* banner_ = nullptr;
  BannerKind bannerKind_ = BannerKind::Setup;
  std::function<QString()> bannerMaker_;  // the banner's text in the current language
  bool bannerError_ = false;
  bool partDockGrown_ = false;  // the Part dock made tall enough for its list once this session
  class ExplainBar* explainBar_ = nullptr;
  class CuttingPlot* cuttingPlot_ = nullptr;
  DialectOfferBar* dialectOffer_ = nullptr;
  class RecoveryBar* recoveryBar_ = nullptr;
  class FirstStepsBar* firstSteps_ = nullptr;
  class SetupStrip* setupStrip_ = nullptr;  // stock and tools above the output screen
  QProgressBar* busyBar_ = nullptr;
  QPointer<FindDialog> findDialog_;
  QPointer<PartDesignerDialog> designer_;
  QPointer<HelpContents> help_;
  CheckController* checker_ = nullptr;
  class QUndoGroup* undoGroup_ = nullptr;  // Edit > Undo / Redo follow the active document's stack
  std::function<void()> updateUndo_;       // enables and names Edit > Undo / Redo

  RunSpeedControl* speedControl_ = nullptr;

  std::vector<core::Diagnostic> lastDiagnostics_;
  std::vector<core::Diagnostic> runDiagnostics_;  // the last alarm / refused run

  std::optional<core::DisplayUnits> shownUnits_;              // View ▸ Units shown; nullopt: Auto
  core::DisplayUnits programUnits_ = core::DisplayUnits::Mm;  // the last check's: what Auto shows
  void applyDisplayUnits();
  QString configDir_;
  QString configDirOverride_;  // where the dialogs last saved the .cfg files
  // The job's inputs (setup, dialect, units, the stations set for this file) and its last Job.
  JobDocument jobDoc_;
  bool restockOnNextCheck_ = false;            // the dialect or units changed: the next Job says the bar
  std::optional<core::Diagnostic> pointNote_;  // the last check's I103/I104, for the setup strip
};

}  // namespace klueng::gui

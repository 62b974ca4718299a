#pragma once
// The Operator panel dock (issue 31): the machine's control as a student meets
// it before the first cycle start — mode keys, jog and handwheel, spindle,
// overrides, switches, cycle start / feed hold / reset, the position page, the
// offset page with MEASURE, and MDI. Everything it does is core::control::Control's;
// the panel shows the model, forwards keys and draws the bar at the tool
// (render/ painters). Key labels are the control's own English (Fanuc 0i-TF or
// Haas, after the selected machine); tooltips explain them via tr().
#include <QDockWidget>
#include <QPointer>
#include <functional>
#include <memory>

#include "gui/run_controller.h"
#include "klueng/core/control/control.h"

class QButtonGroup;
class QCheckBox;
class QComboBox;
class QDial;
class QDoubleSpinBox;
class QGridLayout;
class QHBoxLayout;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QSpinBox;
class QTableWidget;
class QTabWidget;
class QToolButton;
class QVBoxLayout;

namespace klueng::gui {

class TouchView;

class OperatorPanel : public QDockWidget {
  Q_OBJECT
 public:
  struct Source {
    core::machine::MachineSetup setup;
    core::io::JobHeader stock;
    core::gcode::Dialect dialect = core::gcode::Dialect::Fanuc;
    const core::machine::Timeline* program = nullptr;  // the job's last run, if any: its cycle time
    core::io::ProgramFile programFile;                 // the program as it is now: the tools the exercise asks for
    QString programPath;  // its file, if saved: the exercise's offsets go beside it (job::touchOffFilePath)
  };
  OperatorPanel(QWidget* parent, std::function<Source()> source);
  ~OperatorPanel() override;

  // POWER ON: a new machine from the job (the bar, the tools, offset.cfg as wear).
  void powerOn();
  core::control::Control* control() const { return control_.get(); }
  // The offset page's row under the cursor (1-based).
  int offsetRow() const;
  void setOffsetRow(int row);
  // The keys, as a click would press them (tests drive these).
  void pressMode(core::control::Mode mode);
  void pressJog(core::control::Axis axis, int direction);  // one jog tick (a held key repeats it)
  void turnHandle(int clicks);
  void pressMeasure();        // the offset page's input + MEASURE
  void pressInputWear();      // the input + +INPUT: added to the selected row's wear
  void pressMeasureShift();   // "Z0" + SHIFT MEASURE: the work shift Z
  void pressMicrometer();     // the bar's diameter at the micrometer's Z
  void setExercise(bool on);  // the exercise: every geometry offset unknown (off: power on again)
  void pressCycleStart();
  void pressReset();
  void pressFeedHold();
  // What FEED HOLD did to the run: `held` = a run was moving and now stands.
  void showFeedHold(bool held);
  // The one run (issue 40 item 2): whichever key started it (Go on the tool bar, or MEM +
  // CYCLE START here), the panel is the machine that runs it. While a run is under way (not
  // reset) and the mode is MEM, the mode, the positions, the spindle and the feed on the panel
  // are the run's; RESET stops it (resetRequested) and SINGLE BLOCK acts on it.
  void followRun(const RunController* runner);
  bool showsRun() const;
  QLineEdit* offsetInput() const { return input_; }
  QPlainTextEdit* mdiText() const { return mdi_; }
  QLabel* messageLabel() const { return message_; }
  QLabel* cycleTimeLabel() const { return cycleTime_; }
  QTableWidget* offsetTable() const { return offsets_; }
  // Where the exercise's touch-off was last saved (empty: not saved).
  QString touchOffSaved() const { return touchOffSaved_; }
  void retranslateUi();

 signals:
  // The offset rows a run should use (geometry + wear + work shift against the true tools).
  void offsetsChanged(const klueng::core::io::OffsetTable& offsets);
  // MEM + CYCLE START with nothing refusing it: run the job's program (one block under single block).
  void cycleStartRequested(bool singleBlock);
  // The OPT STOP and BLOCK SKIP keys pressed: the run's own switches follow them.
  void switchesChanged(bool optionalStop, bool blockSkip);
  // The override knobs or DRY RUN changed (also at power-on): the run plays at them.
  void overridesChanged(const klueng::core::control::Overrides& overrides, bool dryRun, double dryRunFeed);
  // FEED HOLD pressed: the run should stop its axes (showFeedHold says whether one was moving).
  void feedHoldRequested();
  // RESET pressed while a run is under way: the run stops (as the tool bar's Stop).
  void resetRequested();
  // The SINGLE BLOCK switch: the run stops after each block.
  void singleBlockChanged(bool on);

 protected:
  void changeEvent(QEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  // The panel's face (operator_panel_build.cpp), in the order build() lays it out.
  void build();
  void addTitleRow(QVBoxLayout* v);
  void addPositionPage(QVBoxLayout* v);
  void addMessageLine(QVBoxLayout* v);
  QWidget* buildKeysPage();
  void addModeKeys(QGridLayout* g);
  void addJogKeys(QGridLayout* g, int row);
  void addHandwheel(QGridLayout* g, int row);
  void addSpindleKeys(QGridLayout* g, int row);
  void addSpindleSpeedAndCoolant(QGridLayout* g, int row);
  void addOverrideKnobs(QGridLayout* g, int row);
  void addSwitches(QGridLayout* g, int row);
  QHBoxLayout* buildCycleKeys();
  QWidget* buildOffsetPage();
  QWidget* buildMdiPage();
  void addShortcuts();
  void putInScrollArea(QWidget* body);
  void applyLayoutLabels();
  void refresh();  // every page from the model
  void showPositions();
  void showState();
  void showOffsetRows();
  void followRunState(RunState state);
  void updateCycleTime();  // the job's cycle time at the overrides (the program may be long: not on every key)
  void showMessage(const std::optional<core::Diagnostic>& d);
  void showAll(const std::vector<core::Diagnostic>& ds);
  void afterMotion(const core::control::MotionResult& r);
  // The offset page's input read ("X49.6", "Z0"; only that axis when given), or E608 said.
  std::optional<core::control::MeasureInput> readOffsetInput(std::optional<core::control::Axis> only = std::nullopt);
  void emitOffsets();
  void emitOverrides();
  void saveTouchOff();
  QString text(const core::Diagnostic& d) const;

  std::function<Source()> source_;
  const RunController* runner_ = nullptr;
  bool runUnderWay_ = false;  // the runner's run is not reset: MEM shows it
  RunStatus run_;             // the run's last status
  std::unique_ptr<core::control::Control> control_;
  const core::machine::Timeline* program_ = nullptr;
  core::io::OffsetTable fileOffsets_;  // offset.cfg as first read: the wear at power-on
  core::io::OffsetTable lastEmitted_;
  bool emitted_ = false;
  bool chips_ = false;  // the last motion key cut the bar
  QString touchOffSaved_;
  QString note_;  // a line under the message (where the touch-off was saved)
  std::optional<core::Diagnostic> shown_;
  std::pair<int, int> mdiPlace_{0, 0};  // line, column in the MDI text of the message shown

  QLabel* title_ = nullptr;
  QLabel* message_ = nullptr;
  TouchView* view_ = nullptr;
  QToolButton* zoom_ = nullptr;
  QLabel* posHeads_[4] = {};
  QLabel* pos_[2][4] = {};
  QLabel* state_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  QButtonGroup* modes_ = nullptr;
  QToolButton* jogKeys_[4] = {};
  QToolButton* rapid_ = nullptr;
  QButtonGroup* handleAxis_ = nullptr;
  QButtonGroup* handleStep_ = nullptr;
  QDial* dial_ = nullptr;
  int dialValue_ = 0;
  QToolButton* spindleKeys_[3] = {};
  QSpinBox* sWord_ = nullptr;
  QToolButton* coolant_ = nullptr;
  QComboBox* feedOv_ = nullptr;
  QComboBox* rapidOv_ = nullptr;
  QComboBox* spindleOv_ = nullptr;
  QToolButton* switches_[4] = {};
  QToolButton* cycleStart_ = nullptr;
  QToolButton* feedHold_ = nullptr;
  QToolButton* reset_ = nullptr;
  QToolButton* powerOn_ = nullptr;
  QLabel* cycleTime_ = nullptr;
  QTableWidget* offsets_ = nullptr;
  QLineEdit* input_ = nullptr;
  QToolButton* measure_ = nullptr;
  QToolButton* inputWear_ = nullptr;
  QToolButton* measureShift_ = nullptr;
  QLabel* shift_ = nullptr;
  QDoubleSpinBox* micZ_ = nullptr;
  QToolButton* micButton_ = nullptr;
  QLabel* micReading_ = nullptr;
  QPlainTextEdit* mdi_ = nullptr;
  QLabel* mdiHint_ = nullptr;
  QCheckBox* exercise_ = nullptr;
  QLabel* labels_[8] = {};
};

}  // namespace klueng::gui

// The Operator panel dock (issue 31) in the real main window, driven headless:
// the refused cycle start before the zero return, the zero return keys, a
// handwheel touch-off typed into the offset page that reaches the run's setup,
// an MDI block, and the cycle time the overrides give.
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QScrollArea>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <cmath>

#include "fresh_user_folders.h"
#include "gui/class_grade_dialog.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/operator_panel.h"
#include "gui/output_view.h"
#include "gui/resources.h"
#include "gui/run_controller.h"
#include "gui/status_panel.h"
#include "gui_test_runner.h"
#include "window_test_support.h"
#include "klueng/core/control/control.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/job/class_grading.h"
#include "klueng/core/machine/setup_files.h"

using namespace klueng;
namespace ctl = klueng::core::control;

namespace {

QString minSec(double s) {
  const int m = static_cast<int>(s / 60.0);
  return QStringLiteral("%1:%2").arg(m).arg(s - m * 60.0, 4, 'f', 1, QLatin1Char('0'));
}

// A teacher's job: Ø50 x 100 bar, turn Ø40 over 30 mm with T0101; the head asks for the exercise.
const char* kExerciseJob =
    "Setup exercise\nShaft\nAluminium\n150\n1100\nTeacher\n(OFFSETS: UNKNOWN)\n"
    "G21 G99\nT0101\nG97 S800 M03\nG00 X52 Z2\nX40\nG01 Z-30 F0.2\nG00 X52\nZ2\nM30\n";

void writeText(const QString& path, const QByteArray& text) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  f.write(text);
}

}  // namespace

class OperatorPanelTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { klueng::test::startInEnglish(); }

  void touchOffMdiAndOverridesFromThePanel() {
    gui::MainWindow w;
    QVERIFY(klueng::test::showSample(w));
    auto* runner = w.findChild<gui::RunController*>();
    runner->setSpeed(gui::RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QVERIFY(QTest::qWaitFor([runner] { return runner->state() == gui::RunState::Finished; }, 30000));
    runner->waitForIdle();
    QVERIFY(runner->timeline());

    // View ▸ Operator panel: a dock beside the output screen, hidden at first.
    gui::OperatorPanel* panel = w.operatorPanel();
    QVERIFY(panel && !panel->isVisible());
    QAction* toggle = w.action(QStringLiteral("operatorPanelDock"));
    QVERIFY(toggle);
    toggle->trigger();
    QVERIFY(panel->isVisible());
    QVERIFY(panel->control());
    auto* output = w.findChild<gui::OutputView*>();
    QVERIFY(QTest::qWaitFor([&] { return panel->width() > 0 && output->width() > 0; }));
    QVERIFY2(panel->width() <= 460, qPrintable(QString::number(panel->width())));
    QVERIFY(output->isVisible() && output->width() >= 300);
    QCOMPARE(panel->findChild<QLabel*>(QStringLiteral("operatorTitle"))->text(), QStringLiteral("FANUC Series 0i-TF"));

    // Power on: MEM + CYCLE START is refused with the control's alarm.
    QSignalSpy started(panel, &gui::OperatorPanel::cycleStartRequested);
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorModeMem")), Qt::LeftButton);
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorCycleStart")), Qt::LeftButton);
    QVERIFY2(panel->messageLabel()->text().startsWith(QStringLiteral("A601 PS0224 ZERO RETURN NOT FINISHED")),
             qPrintable(panel->messageLabel()->text()));
    QCOMPARE(started.count(), 0);

    // ZRN and the +X / +Z keys.
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorModeZrn")), Qt::LeftButton);
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorJogPlusX")), Qt::LeftButton);
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorJogPlusZ")), Qt::LeftButton);
    ctl::Control* c = panel->control();
    QVERIFY(c->referenced(ctl::Axis::X) && c->referenced(ctl::Axis::Z));
    QCOMPARE(panel->findChild<QLabel*>(QStringLiteral("operatorPosX2"))->text(), QStringLiteral("0.000"));

    // The tip 0.1 mm off the face at Ø40 (jogged in the model: holding a key is many ticks),
    // spindle on, then the handwheel ×1 until the first chip.
    c->setMode(ctl::Mode::Jog);
    c->jog(ctl::Axis::Z, 0.1 - c->tip().z, true);
    c->jog(ctl::Axis::X, 40.0 - c->tip().x, true);
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorSpindleCw")), Qt::LeftButton);
    QCOMPARE(c->spindle(), core::machine::SpindleDir::Cw);
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorModeHandle")), Qt::LeftButton);
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorHandleZ")), Qt::LeftButton);
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorHandleStep0")), Qt::LeftButton);
    const double removed = c->stock().removedVolume();
    int clicks = 0;
    while (c->stock().removedVolume() == removed && clicks < 200) {
      panel->turnHandle(-1);
      ++clicks;
    }
    QCOMPARE(clicks, 101);

    // The offset page: row 01, "Z0" + MEASURE.
    QSignalSpy offsets(panel, &gui::OperatorPanel::offsetsChanged);
    panel->setOffsetRow(1);
    panel->offsetInput()->setText(QStringLiteral("Z0"));
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorMeasure")), Qt::LeftButton);
    QCOMPARE(offsets.count(), 1);
    QCOMPARE(panel->offsetTable()->item(0, 1)->text(), QString::number(c->machinePosition().z, 'f', 3));
    // The run's setup has the click's depth in row 01's Z.
    QVERIFY(std::abs(runner->machineSetup().offsets.at(1).z - (-0.001)) < 1e-9);
    QVERIFY(std::abs(runner->machineSetup().offsets.at(1).x) < 1e-9);
    // A typing slip is said, not taken.
    panel->offsetInput()->setText(QStringLiteral("49.6"));
    panel->pressMeasure();
    QVERIFY(panel->messageLabel()->text().startsWith(QStringLiteral("E608")));
    QCOMPARE(offsets.count(), 1);

    // MDI: one block, run with the checker, interpreter and cut.
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorModeMdi")), Qt::LeftButton);
    panel->mdiText()->setPlainText(QStringLiteral("G00 X60 Z5"));
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorCycleStart")), Qt::LeftButton);
    QVERIFY2(panel->messageLabel()->text().isEmpty(), qPrintable(panel->messageLabel()->text()));
    QCOMPARE(panel->findChild<QLabel*>(QStringLiteral("operatorPosX0"))->text(), QStringLiteral("60.000"));
    QCOMPARE(panel->findChild<QLabel*>(QStringLiteral("operatorPosZ0"))->text(), QStringLiteral("5.000"));
    QVERIFY(panel->mdiText()->toPlainText().isEmpty());
    panel->mdiText()->setPlainText(QStringLiteral("G01 X40 Q"));
    panel->pressCycleStart();
    QVERIFY2(panel->messageLabel()->text().contains(QStringLiteral("MDI line 1")),
             qPrintable(panel->messageLabel()->text()));

    // New offsets drop the last run (it was made with the old ones): run again with the touch-off's.
    QVERIFY(!runner->timeline());
    QVERIFY(panel->cycleTimeLabel()->text().startsWith(QStringLiteral("Run the program once")));
    w.action(QStringLiteral("actionGo"))->trigger();
    QVERIFY(QTest::qWaitFor([runner] { return runner->state() == gui::RunState::Finished; }, 30000));
    runner->waitForIdle();
    QVERIFY(runner->timeline());

    // Overrides: feed 50 %, rapid 25 %, spindle 120 % — the cycle time as the control makes it.
    const core::machine::Timeline& t = *runner->timeline();
    panel->findChild<QComboBox*>(QStringLiteral("operatorFeedOverride"))->setCurrentIndex(5);
    panel->findChild<QComboBox*>(QStringLiteral("operatorRapidOverride"))->setCurrentIndex(1);
    panel->findChild<QComboBox*>(QStringLiteral("operatorSpindleOverride"))->setCurrentIndex(7);
    ctl::Overrides o;
    o.feed = 50;
    o.rapid = 25;
    o.spindle = 120;
    const double slow = ctl::withOverrides(t, o, c->setup().machine).cycleTime();
    QVERIFY(slow > t.cycleTime() * 1.5);
    QCOMPARE(
        panel->cycleTimeLabel()->text(),
        QStringLiteral("Cycle time at these overrides: %1 (at 100 %: %2)").arg(minSec(slow), minSec(t.cycleTime())));

    // Referenced and no alarm: MEM + CYCLE START runs the job's program.
    panel->pressReset();
    panel->pressMode(ctl::Mode::Memory);
    panel->pressCycleStart();
    QCOMPARE(started.count(), 1);
    QCOMPARE(started.last().first().toBool(), false);
    QVERIFY(QTest::qWaitFor([runner] { return runner->state() == gui::RunState::Finished; }, 30000));
    // OPT STOP and BLOCK SKIP are the run's switches; SINGLE BLOCK makes cycle start one block.
    QVERIFY(!w.action(QStringLiteral("actionOptionalStop"))->isChecked());
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorOptStop")), Qt::LeftButton);
    QVERIFY(w.action(QStringLiteral("actionOptionalStop"))->isChecked());
    QVERIFY(c->optionalStop);
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorOptStop")), Qt::LeftButton);
    QVERIFY(!w.action(QStringLiteral("actionOptionalStop"))->isChecked());
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorSingleBlock")), Qt::LeftButton);
    panel->pressCycleStart();
    QCOMPARE(started.count(), 2);
    QCOMPARE(started.last().first().toBool(), true);

    // Thai: the dock's words and the tips follow the language; the keys stay the control's.
    gui::Language::instance()->setLanguage(QStringLiteral("th"));
    QTRY_COMPARE(panel->windowTitle(), QStringLiteral("แผงควบคุมเครื่อง"));
    QCOMPARE(panel->findChild<QToolButton*>(QStringLiteral("operatorCycleStart"))->text(),
             QStringLiteral("CYCLE START"));
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
  }

  // Issue 40 item 2: one run, two faces. Go on the tool bar runs the program on the panel's
  // machine: MEM, the moving positions, the spindle; FEED HOLD holds it, RESET ends it, SINGLE
  // BLOCK stops it after the block it is in; the tool bar's Pause acts on a run the panel started.
  void theToolBarsRunIsThePanelsRun() {
    gui::MainWindow w;
    QVERIFY(klueng::test::showSample(w));
    auto* runner = w.findChild<gui::RunController*>();
    gui::OperatorPanel* panel = w.operatorPanel();
    w.action(QStringLiteral("operatorPanelDock"))->trigger();
    QVERIFY(panel->isVisible() && panel->control());
    QVERIFY(panel->control()->mode() != ctl::Mode::Memory);
    QVERIFY(!panel->showsRun());
    // At 1366 x 728 (a 768 px screen less its task bar) the last row of keys is in sight, in both
    // languages: the panel runs down beside the bottom docks (issue 40 item 4).
    const auto lastRowInSight = [panel] {
      auto* scroll = panel->findChild<QScrollArea*>();
      QWidget* last = panel->findChild<QToolButton*>(QStringLiteral("operatorDryRun"));
      const QPoint bottom = last->mapTo(scroll->viewport(), QPoint(0, last->height()));
      return last->isVisible() && bottom.y() <= scroll->viewport()->height();
    };
    QTRY_VERIFY(lastRowInSight());
    gui::Language::instance()->setLanguage(QStringLiteral("th"));
    QTRY_VERIFY(lastRowInSight());
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
    const auto label = [panel](const char* name) { return panel->findChild<QLabel*>(QLatin1String(name))->text(); };
    QVERIFY2(!label("operatorState").startsWith(QStringLiteral("MEM")), qPrintable(label("operatorState")));

    // The frame timer barely moves the run: the test drives its clock.
    runner->setSpeed(1e-6);
    w.action(QStringLiteral("actionGo"))->trigger();
    QVERIFY(QTest::qWaitFor([runner] { return runner->state() == gui::RunState::Running; }, 30000));
    runner->setMaxStepMm(0.0);  // no slow-motion pixel limit: each step of the clock is whole
    QCOMPARE(panel->control()->mode(), ctl::Mode::Memory);
    QVERIFY(panel->findChild<QToolButton*>(QStringLiteral("operatorModeMem"))->isChecked());
    QVERIFY(panel->showsRun());
    // On until the spindle turns and the tool moves.
    for (int i = 0; i < 20000 && (runner->status().rpm <= 0.0 || runner->status().feedMmPerMin <= 0.0); ++i)
      runner->advancePlayback(0.25);
    QVERIFY(runner->status().rpm > 0.0);
    const QString state = label("operatorState");
    QVERIFY2(state.startsWith(QStringLiteral("MEM")), qPrintable(state));
    QVERIFY2(state.contains(QStringLiteral("S%1 CW").arg(runner->status().rpm, 0, 'f', 0)), qPrintable(state));
    QVERIFY2(!state.contains(QStringLiteral("S0 STOP")), qPrintable(state));
    // The work position is the run's controlled point (X a diameter); the machine and
    // distance-to-go columns move with it.
    const auto shown = [&] {
      QStringList l;
      for (const char* axis : {"X", "Z"})
        for (int c = 0; c < 4; ++c)
          l << panel->findChild<QLabel*>(QStringLiteral("operatorPos%1%2").arg(QLatin1String(axis)).arg(c))->text();
      return l;
    };
    const core::Vec2 p = runner->status().position;
    QCOMPARE(label("operatorPosX0"), QString::number(2.0 * p.y(), 'f', 3));
    QCOMPARE(label("operatorPosZ0"), QString::number(p.x(), 'f', 3));
    const QStringList before = shown();
    runner->advancePlayback(0.5);
    const QStringList after = shown();
    QVERIFY(before[0] != after[0] || before[4] != after[4]);                              // work X or Z
    QVERIFY(before[2] != after[2] || before[6] != after[6]);                              // machine X or Z
    QVERIFY(after[3] != QStringLiteral("0.000") || after[7] != QStringLiteral("0.000"));  // distance to go

    // FEED HOLD on the panel: the axes decelerate and stand, the run waits.
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorFeedHold")), Qt::LeftButton);
    for (int i = 0; i < 20 && runner->state() == gui::RunState::Running; ++i) runner->advancePlayback(0.05);
    QCOMPARE(runner->state(), gui::RunState::Paused);
    QVERIFY(runner->isFeedHeld());
    QVERIFY2(label("operatorState").contains(QStringLiteral("HOLD")), qPrintable(label("operatorState")));
    const QStringList held = shown();
    runner->advancePlayback(1.0);
    QCOMPARE(shown(), held);
    // RESET on the panel ends the run; the panel is its own machine again.
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorReset")), Qt::LeftButton);
    QCOMPARE(runner->state(), gui::RunState::Idle);
    QVERIFY(!panel->showsRun());
    QCOMPARE(label("operatorPosX2"), QString::number(panel->control()->machinePosition().x, 'f', 3));

    // SINGLE BLOCK switched on during a run: it stops at the end of the block it is in.
    w.action(QStringLiteral("actionGo"))->trigger();
    QVERIFY(QTest::qWaitFor([runner] { return runner->state() == gui::RunState::Running; }, 30000));
    runner->advancePlayback(1.0);
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorSingleBlock")), Qt::LeftButton);
    QCOMPARE(runner->state(), gui::RunState::Stepping);
    for (int i = 0; i < 20000 && runner->state() == gui::RunState::Stepping; ++i) runner->advancePlayback(0.05);
    QCOMPARE(runner->state(), gui::RunState::Paused);
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorSingleBlock")), Qt::LeftButton);
    QVERIFY(!runner->singleBlock());
    w.action(QStringLiteral("actionStop"))->trigger();
    // A run MEM + CYCLE START started (after the zero return): the tool bar's Pause and Stop act on it.
    panel->pressMode(ctl::Mode::ZeroReturn);
    panel->pressJog(ctl::Axis::X, 1);
    panel->pressJog(ctl::Axis::Z, 1);
    panel->pressMode(ctl::Mode::Memory);
    QSignalSpy started(panel, &gui::OperatorPanel::cycleStartRequested);
    QTest::mouseClick(panel->findChild<QToolButton*>(QStringLiteral("operatorCycleStart")), Qt::LeftButton);
    QCOMPARE(started.count(), 1);
    QVERIFY(QTest::qWaitFor([runner] { return runner->state() == gui::RunState::Running; }, 30000));
    w.action(QStringLiteral("actionPause"))->trigger();
    QCOMPARE(runner->state(), gui::RunState::Paused);
    QVERIFY(panel->showsRun());
    w.action(QStringLiteral("actionStop"))->trigger();
    QCOMPARE(runner->state(), gui::RunState::Idle);
    QVERIFY(!panel->showsRun());
  }

  void haasLayout() {
    gui::MainWindow w;
    w.resize(1366, 728);
    w.show();
    w.action(QStringLiteral("actionDialectHaas"))->trigger();
    w.action(QStringLiteral("operatorPanelDock"))->trigger();
    gui::OperatorPanel* panel = w.operatorPanel();
    panel->powerOn();
    QCOMPARE(panel->control()->layout(), ctl::Layout::Haas);
    QCOMPARE(panel->findChild<QLabel*>(QStringLiteral("operatorTitle"))->text(), QStringLiteral("HAAS"));
    QCOMPARE(panel->findChild<QToolButton*>(QStringLiteral("operatorModeZrn"))->text(), QStringLiteral("ZERO RET"));
    QCOMPARE(panel->findChild<QToolButton*>(QStringLiteral("operatorSpindleCw"))->text(), QStringLiteral("FWD"));
    // Haas rapid override keys: 5 / 25 / 50 / 100 %, no F0; the slowest one reaches the run.
    auto* rapid = panel->findChild<QComboBox*>(QStringLiteral("operatorRapidOverride"));
    QCOMPARE(rapid->itemText(0), QStringLiteral("R 5%"));
    QCOMPARE(rapid->count(), 4);
    rapid->setCurrentIndex(0);
    QCOMPARE(panel->control()->overrides().rapid, 5);
    QCOMPARE(w.findChild<gui::RunController*>()->overrides().rapid, 5);
    panel->pressMode(ctl::Mode::Memory);
    panel->pressCycleStart();
    QVERIFY2(panel->messageLabel()->text().startsWith(QStringLiteral("A601 ZERO RETURN REQUIRED")),
             qPrintable(panel->messageLabel()->text()));
    QCOMPARE(panel->findChild<QLabel*>(QStringLiteral("operatorState"))->text().left(8), QStringLiteral("MEM  T01"));
    // The exercise: sample 01's T0101 must be touched off before cycle start.
    QVERIFY(w.openFile(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt")));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    panel->powerOn();
    panel->findChild<QCheckBox*>(QStringLiteral("operatorExercise"))->setChecked(true);
    QVERIFY(panel->control()->exercise());
    QCOMPARE(panel->offsetTable()->item(0, 1)->text(), QStringLiteral("0.000"));
    panel->pressMode(ctl::Mode::ZeroReturn);
    panel->pressJog(ctl::Axis::X, 1);
    panel->pressJog(ctl::Axis::Z, 1);
    QSignalSpy started(panel, &gui::OperatorPanel::cycleStartRequested);
    panel->pressMode(ctl::Mode::Memory);
    panel->pressCycleStart();
    QVERIFY2(panel->messageLabel()->text().startsWith(QStringLiteral("A609")),
             qPrintable(panel->messageLabel()->text()));
    QVERIFY(panel->messageLabel()->text().contains(QStringLiteral("T01 (X and Z)")));
    QCOMPARE(started.count(), 0);
    // Another machine: the panel powers on as its control.
    w.action(QStringLiteral("actionDialectFanuc"))->trigger();
    QCOMPARE(panel->control()->layout(), ctl::Layout::Fanuc);
    QCOMPARE(panel->findChild<QLabel*>(QStringLiteral("operatorTitle"))->text(), QStringLiteral("FANUC Series 0i-TF"));
    QCOMPARE(panel->findChild<QToolButton*>(QStringLiteral("operatorModeZrn"))->text(), QStringLiteral("ZRN"));
    QCOMPARE(rapid->itemText(0), QStringLiteral("R F0"));
  }

  // Issue 31 item 5 and the review: the job file's (OFFSETS: UNKNOWN) powers the panel on in the
  // exercise; the touch-off is saved beside the program at cycle start and Grade a class shows it;
  // FEED HOLD stops the run's axes with the spindle turning; the overrides reach the run.
  void theJobFilesExerciseIsTouchedOffHeldAndGraded() {
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("class")));
    const QString program = dir.filePath(QStringLiteral("class/somchai.nc"));
    writeText(program, kExerciseJob);
    writeText(dir.filePath(QStringLiteral("reference.nc")),
              QByteArray(kExerciseJob).replace("(OFFSETS: UNKNOWN)\n", ""));
    gui::MainWindow w;
    QVERIFY(klueng::test::showSample(w));
    QVERIFY(w.openFile(program));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    auto* runner = w.findChild<gui::RunController*>();
    w.action(QStringLiteral("operatorPanelDock"))->trigger();
    gui::OperatorPanel* panel = w.operatorPanel();
    QVERIFY(panel->isVisible());
    ctl::Control* c = panel->control();
    QVERIFY(c->exercise());
    QVERIFY(panel->findChild<QCheckBox*>(QStringLiteral("operatorExercise"))->isChecked());
    QCOMPARE(panel->offsetTable()->item(0, 1)->text(), QStringLiteral("0.000"));
    panel->pressMode(ctl::Mode::ZeroReturn);
    panel->pressJog(ctl::Axis::X, 1);
    panel->pressJog(ctl::Axis::Z, 1);
    QSignalSpy started(panel, &gui::OperatorPanel::cycleStartRequested);
    panel->pressMode(ctl::Mode::Memory);
    panel->pressCycleStart();
    QVERIFY2(panel->messageLabel()->text().startsWith(QStringLiteral("A609 the offsets are unknown: touch off T01")),
             qPrintable(panel->messageLabel()->text()));
    QCOMPARE(started.count(), 0);
    QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("class/somchai.offset.cfg"))));

    // Touch off T01: the face with the handwheel, Z0 + MEASURE; a skimmed Ø, X + MEASURE.
    c->setSpindleSpeed(800.0);
    c->setSpindle(core::machine::SpindleDir::Cw);
    panel->pressMode(ctl::Mode::Jog);
    QVERIFY(!c->jog(ctl::Axis::Z, 0.1 - c->tip().z, true).stop);
    QVERIFY(!c->jog(ctl::Axis::X, 40.0 - c->tip().x, true).stop);
    panel->pressMode(ctl::Mode::Handle);
    c->setHandleAxis(ctl::Axis::Z);
    int clicks = 0;
    while (clicks < 200 && !c->handle(-1).cut) ++clicks;
    QCOMPARE(clicks, 100);  // from Z+0.100: the 101st click takes the first chip
    panel->setOffsetRow(1);
    panel->offsetInput()->setText(QStringLiteral("Z0"));
    panel->pressMeasure();
    panel->pressMode(ctl::Mode::Jog);
    QVERIFY(!c->jog(ctl::Axis::Z, 2.0 - c->tip().z, true).stop);
    QVERIFY(!c->jog(ctl::Axis::X, 49.0 - c->tip().x, false).stop);
    QVERIFY(c->jog(ctl::Axis::Z, -12.0, false).cut);
    QVERIFY(!c->jog(ctl::Axis::Z, 14.0, false).stop);
    c->setSpindle(core::machine::SpindleDir::Stopped);
    QCOMPARE(c->micrometer(-5.0), 49.0);
    panel->offsetInput()->setText(QStringLiteral("X49.000"));
    panel->pressMeasure();

    // Cycle start: accepted, compared, saved beside the program; the run starts.
    // Real time (no one-pixel slow-motion rule): frames only advance while the test waits on the
    // event loop; between waits the test drives the run's clock itself.
    runner->setSpeed(1.0);
    panel->pressMode(ctl::Mode::Memory);
    panel->pressCycleStart();
    QCOMPARE(started.count(), 1);
    const QString saved = dir.filePath(QStringLiteral("class/somchai.offset.cfg"));
    QCOMPARE(panel->touchOffSaved(), saved);
    QVERIFY2(panel->messageLabel()->text().contains(QStringLiteral("Touch-off saved for grading: somchai.offset.cfg")),
             qPrintable(panel->messageLabel()->text()));
    QFile file(saved);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const auto table = core::io::parseOffsetTable(file.readAll().toStdString(), "somchai.offset.cfg");
    QVERIFY(table.value);
    QCOMPARE(table.value->at(1).x, 0.0);
    QCOMPARE(table.value->at(1).z, -0.001);
    QVERIFY(QTest::qWaitFor([runner] { return runner->state() == gui::RunState::Running; }, 30000));

    // The feed override knob reaches the run's clock.
    auto* feedOv = panel->findChild<QComboBox*>(QStringLiteral("operatorFeedOverride"));
    feedOv->setCurrentIndex(feedOv->findData(50));
    QCOMPARE(runner->overrides().feed, 50);
    // Into the first feed move (G01 Z-30 F0.2 at 800 rpm, 12 s with its ramps): 5 s of the clock at 50 % is 2.5 s.
    const core::machine::Timeline* tl = runner->timeline();
    int feed = -1;
    for (int i = 0; i < static_cast<int>(tl->moves.size()) && feed < 0; ++i)
      if (tl->moves[static_cast<std::size_t>(i)].kind == core::machine::MoveKind::Line) feed = i;
    QVERIFY(feed >= 0);
    const core::machine::Move& f = tl->moves[static_cast<std::size_t>(feed)];
    runner->advancePlayback(f.tStart - runner->currentTime());  // rapids at 100 %: their own time
    QVERIFY(std::abs(runner->currentTime() - f.tStart) < 1e-6);
    runner->advancePlayback(5.0);
    QVERIFY(std::abs(runner->currentTime() - (f.tStart + 2.5)) < 1e-6);

    // FEED HOLD: the axes slow to a stop within 0.2 s (0.05 s of the move at 50 %), the spindle turns on.
    panel->findChild<QToolButton*>(QStringLiteral("operatorFeedHold"))->click();
    const double held = runner->currentTime();
    runner->advancePlayback(1.0);
    QCOMPARE(runner->state(), gui::RunState::Paused);
    QVERIFY(runner->isFeedHeld());
    QVERIFY2(std::abs(runner->currentTime() - held - 0.05) < 1e-6,
             qPrintable(QString::number(runner->currentTime() - held)));
    QVERIFY(runner->status().feedHold);
    auto* fields = w.findChild<gui::StatusFields*>();
    QVERIFY(fields);
    QCOMPARE(fields->fieldText(gui::StatusFields::Field::Feed), QStringLiteral("FEED HOLD"));
    QCOMPARE(fields->fieldText(gui::StatusFields::Field::Spindle), QStringLiteral("800 rpm"));
    QCOMPARE(runner->status().feedMmPerMin, 0.0);
    QVERIFY(runner->status().rpm > 799.0);
    QVERIFY2(panel->messageLabel()->text().contains(QStringLiteral("FEED HOLD: the axes stop")),
             qPrintable(panel->messageLabel()->text()));
    const double stood = runner->currentTime();
    runner->advancePlayback(10.0);
    QCOMPARE(runner->currentTime(), stood);
    // CYCLE START resumes where it stood.
    panel->pressCycleStart();
    QCOMPARE(started.count(), 2);
    QCOMPARE(runner->state(), gui::RunState::Running);
    QVERIFY(!runner->isFeedHeld());
    runner->advancePlayback(1.0);
    QVERIFY(std::abs(runner->currentTime() - stood - 0.5) < 1e-6);
    runner->stop();

    // File > Grade a class: the touch-off line beside the part's grade, against offset.cfg's true rows
    // (not the exercise's entries this window's run has).
    w.action(QStringLiteral("actionGradeClass"))->trigger();
    auto* dialog = w.findChild<gui::ClassGradeDialog*>();
    QVERIFY(dialog);
    QVERIFY(dialog->table()->isColumnHidden(dialog->table()->columnCount() - 1));
    dialog->setFolder(dir.filePath(QStringLiteral("class")));
    dialog->setReference(dir.filePath(QStringLiteral("reference.nc")));
    QSignalSpy done(dialog, &gui::ClassGradeDialog::finished);
    dialog->grade();
    QTRY_COMPARE_WITH_TIMEOUT(done.count(), 1, 30000);
    QCOMPARE(dialog->table()->rowCount(), 1);
    const int touchColumn = dialog->table()->columnCount() - 1;
    QVERIFY(!dialog->table()->isColumnHidden(touchColumn));
    QCOMPARE(dialog->table()->horizontalHeaderItem(touchColumn)->text(), QStringLiteral("Touch-off"));
    QCOMPARE(dialog->table()->item(0, touchColumn)->text(),
             QStringLiteral("T01 touched off at X0.000 Z-0.001, true X0.000 Z0.000: within 0.050 mm"));
    QCOMPARE(dialog->table()->item(0, 1)->text(), QStringLiteral("pass"));
    dialog->close();
  }
};

KLUENG_GUI_TEST(OperatorPanelTest)
#include "operator_panel_test.moc"

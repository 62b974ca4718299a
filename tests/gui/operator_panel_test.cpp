// The Operator panel dock (issue 31) in the real main window, driven headless:
// the refused cycle start before the zero return, the zero return keys, a
// handwheel touch-off typed into the offset page that reaches the run's setup,
// an MDI block, and the cycle time the overrides give.
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <QToolButton>
#include <cmath>

#include "fresh_user_folders.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/operator_panel.h"
#include "gui/output_view.h"
#include "gui/resources.h"
#include "gui/run_controller.h"
#include "gui_test_runner.h"
#include "window_test_support.h"
#include "klueng/core/control/control.h"

using namespace klueng;
namespace ctl = klueng::core::control;

namespace {

QString minSec(double s) {
  const int m = static_cast<int>(s / 60.0);
  return QStringLiteral("%1:%2").arg(m).arg(s - m * 60.0, 4, 'f', 1, QLatin1Char('0'));
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
  }
};

KLUENG_GUI_TEST(OperatorPanelTest)
#include "operator_panel_test.moc"

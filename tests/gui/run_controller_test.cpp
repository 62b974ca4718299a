// The run controller and the output screen against the core (offscreen QTest):
// stepping, going to the end, pause / stop / step back / breakpoints, alarms,
// a program with errors, the slow-motion one-pixel rule.
#include <cmath>

#include <QLabel>
#include <QApplication>
#include <QSignalSpy>
#include <QTest>

#include "gui_test_runner.h"
#include "gui/output_items.h"
#include "gui/output_ruler.h"
#include "gui/output_view.h"
#include "gui/run_controller.h"
#include "gui/status_panel.h"
#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/finished_part.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"

#include "gui_test_support.h"

using namespace klueng;
using namespace klueng::gui;

namespace {

std::string sample(const char* name) { return std::string(KLUENG_SAMPLES_DIR "/") + name; }

using gui_test::loadSetup;

core::io::ProgramFile loadProgram(const char* name) {
  auto r = core::io::readProgramFile(sample(name));
  return *r.value;
}

// The same run as the GUI's, headless through the core alone.
core::machine::Timeline coreTimeline(const core::io::ProgramFile& f, const core::machine::MachineSetup& setup) {
  return core::machine::interpret(core::gcode::parse(f.gcode, f.gcodeFirstLine), setup, {});
}

int fileLineOf(const char* sampleName, const char* blockStart) {
  const auto f = loadProgram(sampleName);
  const auto program = core::gcode::parse(f.gcode, f.gcodeFirstLine);
  for (const auto& b : program.blocks)
    if (const auto* n = b.find('N'); n && ("N" + n->number) == blockStart) return b.line;
  return -1;
}

struct Rig {
  RunController controller;
  OutputView view;
  StatusFields fields;
  StatusLamps lamps;
  core::machine::MachineSetup setup = loadSetup();
  explicit Rig(const char* program, double speed = RunController::kAsFastAsPossible) {
    controller.setMachineSetup(setup);
    controller.setProgram(loadProgram(program), QString::fromLatin1(program));
    controller.setSpeed(speed);
    view.resize(1280, 800);
    view.setRunController(&controller);
    QObject::connect(&controller, &RunController::statusChanged, &fields, &StatusFields::setStatus);
    QObject::connect(&controller, &RunController::statusChanged, &lamps, &StatusLamps::setStatus);
    view.show();
  }
  void waitIdle() {
    QVERIFY(QTest::qWaitFor([this] { return !controller.isBusy(); }, 60000));
  }
};

}  // namespace

class RunControllerTest : public QObject {
  Q_OBJECT
 private slots:
  void stepFiveBlocksMatchesTheTimeline() {
    Rig rig("01-step-shaft.txt");
    const auto tl = coreTimeline(loadProgram("01-step-shaft.txt"), rig.setup);
    QVERIFY(tl.snapshots.size() > 8);
    for (int i = 0; i < 5; ++i) {
      rig.controller.step();
      rig.waitIdle();
      QCOMPARE(rig.controller.state(), RunState::Paused);
      QCOMPARE(rig.controller.currentSnapshot(), i);
    }
    const auto& snap = tl.snapshots[4];
    const core::Vec2 p = snap.machine.position;
    QCOMPARE(rig.controller.currentTime(), snap.time);
    QCOMPARE(rig.fields.fieldText(StatusFields::Field::ToolX), QString::number(core::diameterOf(p), 'f', 3));
    QCOMPARE(rig.fields.fieldText(StatusFields::Field::ToolZ), QString::number(core::zOf(p), 'f', 3));
    QCOMPARE(rig.fields.fieldText(StatusFields::Field::Tool), QStringLiteral("T0101"));
    QCOMPARE(rig.fields.fieldText(StatusFields::Field::NoseRadius), QStringLiteral("0.800"));
    QCOMPARE(rig.fields.fieldText(StatusFields::Field::Tip), QStringLiteral("3"));
    // Machine time: elapsed to this block / the whole program, as a clock.
    QCOMPARE(rig.fields.fieldText(StatusFields::Field::Time),
             StatusFields::formatClock(snap.time) + QStringLiteral(" / ") + StatusFields::formatClock(tl.cycleTime()));
    QVERIFY(tl.cycleTime() > 60.0);
    QVERIFY(rig.fields.fieldText(StatusFields::Field::Time)
                .endsWith(QStringLiteral("%1:%2")
                              .arg(static_cast<int>(tl.cycleTime() / 60))
                              .arg(std::fmod(tl.cycleTime(), 60.0), 4, 'f', 1, QLatin1Char('0'))));
    // Per tool on hover: sample 01 cuts with T01 only.
    QVERIFY(rig.fields.findChildren<QLabel*>().size() > 0);
    bool perTool = false;
    for (QLabel* l : rig.fields.findChildren<QLabel*>())
      perTool |=
          l->toolTip().contains(QStringLiteral("T01: ") + StatusFields::formatClock(tl.timeByTool().front().seconds));
    QVERIFY(perTool);
    QCOMPARE(StatusFields::formatClock(7.46), QStringLiteral("0:07.5"));
    QCOMPARE(StatusFields::formatClock(754.0), QStringLiteral("12:34.0"));
    QCOMPARE(StatusFields::formatClock(59.96), QStringLiteral("1:00.0"));
    QVERIFY(qAbs(rig.view.toolItemPos().x() - core::zOf(p)) < 1e-9);
    QVERIFY(qAbs(rig.view.toolItemPos().y() + core::xOf(p)) < 1e-9);
    QCOMPARE(rig.controller.currentLine(), snap.line);
    // O0001 N10 N15 N20 N30 have run; the spindle starts with the next block, N40 ... M03.
    QVERIFY(!rig.lamps.lamp(StatusLamps::Lamp::Spindle)->isOn());
    rig.controller.step();
    rig.waitIdle();
    QVERIFY(tl.snapshots[5].machine.spindle == core::machine::SpindleDir::Cw);
    QVERIFY(rig.lamps.lamp(StatusLamps::Lamp::Spindle)->isOn());
    QVERIFY(!rig.lamps.lamp(StatusLamps::Lamp::Coolant)->isOn());
    QVERIFY(rig.fields.fieldText(StatusFields::Field::Spindle)
                .startsWith(QString::number(tl.snapshots[5].machine.rpm, 'f', 0)));
    // The tool bitmap is drawn with its controlled point on the tool position.
    QVERIFY(rig.view.toolVisible());
  }

  void animatedStepReachesTheSameBlockEnd() {
    Rig rig("01-step-shaft.txt", 20.0);
    const auto tl = coreTimeline(loadProgram("01-step-shaft.txt"), rig.setup);
    QSignalSpy lines(&rig.controller, &RunController::executingLineChanged);
    // The first six blocks take no time; the seventh is the rapid from Z300 (N50).
    for (int i = 0; i < 8; ++i) {
      rig.controller.step();
      QVERIFY(QTest::qWaitFor([&] { return rig.controller.state() == RunState::Paused; }, 20000));
    }
    QCOMPARE(rig.controller.currentSnapshot(), 7);
    QCOMPARE(rig.controller.currentTime(), tl.snapshots[7].time);
    QVERIFY(tl.snapshots[7].time > 1.0);
    QVERIFY(lines.count() >= 5);
    QVERIFY(rig.controller.frameCount() > 0);
  }

  void goToTheEndLeavesTheCoresFinishedPart() {
    Rig rig("01-step-shaft.txt");
    QSignalSpy alarms(&rig.controller, &RunController::alarmRaised);
    rig.controller.go();
    rig.waitIdle();
    QCOMPARE(rig.controller.state(), RunState::Finished);
    QCOMPARE(alarms.count(), 0);

    const core::io::ProgramFile file = loadProgram("01-step-shaft.txt");
    const auto tl = coreTimeline(file, rig.setup);
    QCOMPARE(rig.controller.currentTime(), tl.cycleTime());
    core::cut::CutSimulator sim(tl, core::cut::CutSetup::from(file.header, rig.setup));
    sim.runToEnd();
    const core::cut::FinishedPart part(sim.stock());
    const render::StockShape& drawn = rig.view.stockItem()->stockShape();
    int checked = 0;
    for (const auto& row : part.rows()) {
      if (row.z <= part.leftFaceZ() + 0.1 || row.z >= part.rightFaceZ() - 0.1) continue;
      const double r = row.outerDiameter / 2.0;
      QVERIFY2(drawn.containsMaterial(row.z, r - 0.01), qPrintable(QStringLiteral("z %1 r %2").arg(row.z).arg(r)));
      QVERIFY2(!drawn.containsMaterial(row.z, r + 0.01), qPrintable(QStringLiteral("z %1 r %2").arg(row.z).arg(r)));
      ++checked;
    }
    QVERIFY(checked > 500);
    // The finished shaft: Ø30 at Z-10, Ø40 at Z-30, Ø46 at Z-50 (the program's contour).
    QVERIFY(drawn.containsMaterial(-10.0, 14.99) && !drawn.containsMaterial(-10.0, 15.01));
    QVERIFY(drawn.containsMaterial(-30.0, 19.99) && !drawn.containsMaterial(-30.0, 20.01));
    QVERIFY(drawn.containsMaterial(-50.0, 22.99) && !drawn.containsMaterial(-50.0, 23.01));
  }

  void pauseHoldsAndStopResets() {
    Rig rig("01-step-shaft.txt", 5.0);
    rig.controller.go();
    QVERIFY(QTest::qWaitFor([&] { return rig.controller.state() == RunState::Running; }, 20000));
    QTest::qWait(300);
    rig.controller.pause();
    QCOMPARE(rig.controller.state(), RunState::Paused);
    const double t = rig.controller.currentTime();
    QVERIFY(t > 0.0);
    QTest::qWait(200);
    QCOMPARE(rig.controller.currentTime(), t);
    // Go resumes from where it paused.
    rig.controller.go();
    QTest::qWait(200);
    QVERIFY(rig.controller.currentTime() > t);
    rig.controller.stop();
    QCOMPARE(rig.controller.state(), RunState::Idle);
    QCOMPARE(rig.controller.currentTime(), 0.0);
    QCOMPARE(rig.controller.currentLine(), 0);
    // Stop resets the stock to the uncut bar.
    const render::StockShape& drawn = rig.view.stockItem()->stockShape();
    QVERIFY(drawn.containsMaterial(-1.0, 24.99));
  }

  void breakpointStopsBeforeItsBlockAndStepBackReturns() {
    Rig rig("01-step-shaft.txt");
    const auto tl = coreTimeline(loadProgram("01-step-shaft.txt"), rig.setup);
    const int n100 = fileLineOf("01-step-shaft.txt", "N100");
    QVERIFY(n100 > 0);
    rig.controller.setBreakpoints({n100});
    rig.controller.go();
    rig.waitIdle();
    QCOMPARE(rig.controller.state(), RunState::Paused);
    const int k = rig.controller.currentSnapshot();
    QCOMPARE(tl.snapshots[static_cast<std::size_t>(k + 1)].line, n100);
    // One meaning for the arrow (issue 11): the last block that ran, as after a Step;
    // the breakpoint's own block has not run yet.
    QCOMPARE(rig.controller.currentLine(), tl.snapshots[static_cast<std::size_t>(k)].line);
    QCOMPARE(rig.controller.currentLine(), n100 - 1);
    QCOMPARE(rig.controller.currentTime(), tl.snapshots[static_cast<std::size_t>(k)].time);
    // N100 has not cut yet: the bar is still Ø54 faced... untouched at Z-30.
    QVERIFY(rig.view.stockItem()->stockShape().containsMaterial(-30.0, 24.9));

    // Go again runs through the breakpoint's block to the end.
    rig.controller.go();
    rig.waitIdle();
    QCOMPARE(rig.controller.state(), RunState::Finished);

    // Step back twice from the end: the state of two blocks earlier.
    const int last = rig.controller.currentSnapshot();
    rig.controller.stepBack();
    rig.waitIdle();
    rig.controller.stepBack();
    rig.waitIdle();
    QCOMPARE(rig.controller.currentSnapshot(), last - 2);
    const auto& snap = tl.snapshots[static_cast<std::size_t>(last - 2)];
    QCOMPARE(rig.controller.currentTime(), snap.time);
    QVERIFY((rig.controller.status().position - snap.machine.position).norm() < 1e-9);
    QVERIFY(qAbs(rig.view.toolItemPos().x() - core::zOf(snap.machine.position)) < 1e-9);
  }

  void runToLineStopsBeforeThatLine() {
    Rig rig("01-step-shaft.txt");
    const int n330 = fileLineOf("01-step-shaft.txt", "N330");
    rig.controller.runToLine(n330);
    rig.waitIdle();
    QCOMPARE(rig.controller.state(), RunState::Paused);
    // Stopped before N330: the arrow is on the last block that ran, N320.
    QCOMPARE(rig.controller.currentLine(), fileLineOf("01-step-shaft.txt", "N320"));
    QCOMPARE(rig.controller.currentLine(), n330 - 1);
  }

  void alarmStopsOnItsBlock() {
    Rig rig("05-runtime-alarms.txt");
    QSignalSpy alarms(&rig.controller, &RunController::alarmRaised);
    rig.controller.go();
    rig.waitIdle();
    QCOMPARE(rig.controller.state(), RunState::Alarm);
    QCOMPARE(alarms.count(), 1);
    const auto alarm = alarms.first().first().value<core::Diagnostic>();
    const int n40 = fileLineOf("05-runtime-alarms.txt", "N40");
    QCOMPARE(alarm.range.line, n40);
    QCOMPARE(rig.controller.currentLine(), n40);
    QVERIFY(alarm.severity == core::Severity::Alarm);
  }

  void programWithErrorsDoesNotStart() {
    RunController controller;
    controller.setMachineSetup(loadSetup());
    auto file = loadProgram("01-step-shaft.txt");
    file.gcode = "N10 G01 X20 X30 F0.2\nN20 G999\n";
    controller.setProgram(file);
    QSignalSpy failed(&controller, &RunController::checkFailed);
    controller.go();
    controller.waitForIdle();
    QCOMPARE(failed.count(), 1);
    const auto diags = failed.first().first().value<QList<core::Diagnostic>>();
    QVERIFY(diags.size() >= 2);
    QCOMPARE(diags.first().range.line, file.gcodeFirstLine);
    QCOMPARE(controller.state(), RunState::Idle);
    QVERIFY(controller.timeline() == nullptr);
  }

  void optionalStopSwitchActsAtOnce() {
    RunController controller;
    controller.setMachineSetup(loadSetup());
    auto file = loadProgram("01-step-shaft.txt");
    file.gcode = "N10 G00 X60. Z10.\nN20 M01\nN30 G00 X70. Z20.\nN40 M00\nN50 G00 X80. Z30.\nN60 M30\n";
    const int first = file.gcodeFirstLine;
    controller.setProgram(file);
    controller.setSpeed(RunController::kAsFastAsPossible);
    // Switch off: M01 is passed, M00 stops.
    controller.go();
    controller.waitForIdle();
    QCOMPARE(controller.state(), RunState::Paused);
    QCOMPARE(controller.currentLine(), first + 3);
    controller.go();
    controller.waitForIdle();
    QCOMPARE(controller.state(), RunState::Finished);
    // Switch on (no re-check needed): M01 stops too.
    controller.setOptionalStop(true);
    controller.go();
    controller.waitForIdle();
    QCOMPARE(controller.state(), RunState::Paused);
    QCOMPARE(controller.currentLine(), first + 1);
    QVERIFY(controller.status().machine.optionalStopSwitch);
    QCOMPARE(core::diameterOf(controller.status().position), 60.0);
  }

  void slowMotionMovesAtMostOnePixelPerFrame() {
    Rig rig("01-step-shaft.txt", 0.5);
    const double mmPerPixel = 1.0 / rig.view.pixelsPerMm();
    core::Vec2 last = rig.controller.status().position;
    double longest = 0.0;
    QObject::connect(&rig.controller, &RunController::frameAdvanced, [&] {
      const core::Vec2 p = rig.controller.status().position;
      longest = std::max(longest, (p - last).norm());
      last = p;
    });
    rig.controller.go();
    QTest::qWait(1500);  // the first rapid from Z300 (the fastest move of the program)
    rig.controller.pause();
    QVERIFY(rig.controller.currentTime() > 0.0);
    QVERIFY2(longest <= mmPerPixel * 1.0001, qPrintable(QStringLiteral("%1 > %2").arg(longest).arg(mmPerPixel)));
  }

  void rulersFollowZoom() {
    Rig rig("01-step-shaft.txt");
    const QStringList before = rig.view.findChildren<OutputRuler*>().first()->visibleLabels();
    rig.view.zoomIn();
    rig.view.zoomIn();
    rig.view.zoomIn();
    const QStringList after = rig.view.findChildren<OutputRuler*>().first()->visibleLabels();
    QVERIFY(!before.isEmpty() && !after.isEmpty());
    QVERIFY(before != after);
    QCOMPARE(OutputRuler::tickStep(3.0, 70.0), 50.0);
    QCOMPARE(OutputRuler::tickStep(10.0, 70.0), 10.0);
    QCOMPARE(OutputRuler::tickStep(0.5, 70.0), 200.0);
  }
};

KLUENG_GUI_TEST(RunControllerTest)
#include "run_controller_test.moc"

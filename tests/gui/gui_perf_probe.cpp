// klueng_gui_perf_probe [PROGRAM]: measures the output screen (not a unit test;
// run it by hand, figures go to stdout):
//  1. frames per second of the 1280x800 output view while sample 01 cuts at 1x,
//  2. "as fast as possible" on PROGRAM (default: a generated 100,000-block program)
//     against the core's own headless time (parse + check + interpret + cut to the end),
//  3. the longest event-loop stall during both (a 1 ms QTimer probe).
#include <QApplication>
#include <QElapsedTimer>
#include <QTest>
#include <QTimer>
#include <cstdio>

#include "../../bench/program_generator.h"
#include "gui/output_view.h"
#include "gui/part3d_view.h"
#include "gui/run_controller.h"
#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"

#include "gui_test_support.h"

using namespace klueng;
using namespace klueng::gui;

namespace {

using gui_test::loadSetup;

// The longest gap between two 1 ms timer ticks = the longest the event loop was blocked.
class StallProbe : public QObject {
 public:
  StallProbe() {
    timer_.setTimerType(Qt::PreciseTimer);
    timer_.setInterval(1);
    connect(&timer_, &QTimer::timeout, this, [this] {
      const qint64 now = clock_.nsecsElapsed();
      if (last_ > 0) longest_ = std::max(longest_, now - last_);
      last_ = now;
    });
  }
  void start() {
    longest_ = 0;
    last_ = 0;
    clock_.start();
    timer_.start();
  }
  double stop() {
    timer_.stop();
    return longest_ / 1e6;
  }

 private:
  QTimer timer_;
  QElapsedTimer clock_;
  qint64 last_ = 0;
  qint64 longest_ = 0;
};

// Sample 01 fast to its roughing pass N100 (cutting starts there), then at 1x.
void toRoughingPass(RunController& controller, const core::machine::MachineSetup& setup) {
  controller.setMachineSetup(setup);
  controller.setProgram(*core::io::readProgramFile(KLUENG_SAMPLES_DIR "/01-step-shaft.txt").value);
  controller.setSpeed(RunController::kAsFastAsPossible);
  controller.setBreakpoints({18});  // file line of N100 G01 Z-59.8
  controller.go();
  controller.waitForIdle();
  controller.setBreakpoints({});
  controller.setSpeed(1.0);
}

struct Run {
  double seconds;
  double stall;  // ms
};

// Five seconds of Go at 1x, timed, with the longest UI stall.
Run goFiveSeconds(RunController& controller, StallProbe& probe) {
  probe.start();
  QElapsedTimer wall;
  wall.start();
  controller.go();
  QTest::qWait(5000);
  const double seconds = wall.nsecsElapsed() / 1e9;
  const double stall = probe.stop();
  controller.pause();
  return {seconds, stall};
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  const auto setup = loadSetup();
  StallProbe probe;

  // 1. Frame rate at 1x while cutting sample 01.
  {
    RunController controller;
    OutputView view;
    view.resize(1280, 800);
    view.setRunController(&controller);
    view.show();
    (void)QTest::qWaitForWindowExposed(&view);
    toRoughingPass(controller, setup);
    const double volume0 = controller.cutSimulator()->removedVolume();
    const qint64 paints0 = view.paintCount();
    const qint64 frames0 = controller.frameCount();
    const auto [seconds, stall] = goFiveSeconds(controller, probe);
    const double cut = controller.cutSimulator()->removedVolume() - volume0;
    std::printf(
        "1x sample 01, 1280x800: %.1f frames/s drawn (%.1f animation steps/s), %.0f mm^3 cut in %.2f s, "
        "longest stall %.1f ms\n",
        (view.paintCount() - paints0) / seconds, (controller.frameCount() - frames0) / seconds, cut, seconds, stall);
  }

  // 1b. The same with the 3D view (issue 10) open beside the output screen, 640x600 each.
  {
    RunController controller;
    OutputView view;
    view.resize(640, 600);
    view.setRunController(&controller);
    view.show();
    Part3DWidget view3d;
    view3d.resize(640, 600);
    view3d.setRunController(&controller);
    view3d.show();
    (void)QTest::qWaitForWindowExposed(&view3d);
    toRoughingPass(controller, setup);
    const qint64 paints2d = view.paintCount(), paints3d = view3d.paintCount();
    const auto [seconds, stall] = goFiveSeconds(controller, probe);
    std::printf(
        "1x sample 01 with the 3D view: 2-D %.1f frames/s, 3D %.1f frames/s (%d quads), longest stall %.1f ms\n",
        (view.paintCount() - paints2d) / seconds, (view3d.paintCount() - paints3d) / seconds, view3d.lastQuadCount(),
        stall);
  }

  // 2. As fast as possible on a long program vs the core alone.
  {
    core::io::ProgramFile file;
    if (argc > 1) {
      file = *core::io::readProgramFile(argv[1]).value;
    } else {
      file = *core::io::parseProgramFile(bench::ProgramGenerator::generate(100000)).value;
    }
    QElapsedTimer t;
    t.start();
    const auto program = core::gcode::parse(file.gcode, file.gcodeFirstLine);
    core::gcode::CheckOptions options;
    const auto diags = core::gcode::check(program, options);
    const auto timeline = core::machine::interpret(program, setup, {});
    core::cut::CutSimulator sim(timeline, core::cut::CutSetup::from(file.header, setup));
    sim.runToEnd();
    const double headless = t.nsecsElapsed() / 1e9;
    std::printf("core headless: %zu blocks, %zu moves, %.3f s (alarm: %s)\n", program.blocks.size(),
                timeline.moves.size(), headless, sim.stoppingAlarm() ? sim.stoppingAlarm()->code.c_str() : "none");

    RunController controller;
    controller.setMachineSetup(setup);
    controller.setProgram(file);
    controller.setSpeed(RunController::kAsFastAsPossible);
    OutputView view;
    view.resize(1280, 800);
    view.setRunController(&controller);
    view.show();
    (void)QTest::qWaitForWindowExposed(&view);
    probe.start();
    t.restart();
    controller.go();
    (void)QTest::qWaitFor(
        [&] { return controller.state() == RunState::Finished || controller.state() == RunState::Alarm; }, 600000);
    view.repaint();  // the finished picture on screen
    const double gui = t.nsecsElapsed() / 1e9;
    const double stall = probe.stop();
    std::printf("GUI as fast as possible: %.3f s = %.2f x the core's time (state %s), longest stall %.1f ms\n", gui,
                gui / headless, qPrintable(runStateName(controller.state())), stall);
  }
  return 0;
}

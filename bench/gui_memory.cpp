// klueng-bench-gui-memory FILE: the window's memory on a big program (issue 29 item 8).
// Opens FILE in the real MainWindow, waits for the load and the editor's check,
// then runs the program to its end as fast as possible (Run > Speed fastest, Go)
// and quits. Prints the resident size after each stage and the peak (VmHWM), so
// bench/gui_memory.sh can set it against `klueng-cli simulate FILE`.
// Run it with QT_QPA_PLATFORM=offscreen (or under Xvfb) and a scratch XDG_CONFIG_HOME.
#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QTimer>
#include <cstdio>
#include <functional>

#include "gui/main_window.h"
#include "gui/resources.h"
#include "gui/run_controller.h"
#include "gui/run_speed_control.h"

namespace {

// "VmRSS" or "VmHWM" of this process in MB (Linux /proc), -1 when unknown.
double statusMb(const char* key) {
  QFile status(QStringLiteral("/proc/self/status"));
  if (!status.open(QIODevice::ReadOnly)) return -1.0;
  const QByteArray prefix = QByteArray(key) + ':';
  for (const QByteArray& line : status.readAll().split('\n'))
    if (line.startsWith(prefix)) return line.mid(prefix.size()).trimmed().split(' ').first().toDouble() / 1024.0;
  return -1.0;
}

void report(const char* stage, const QElapsedTimer& clock) {
  std::printf("%-10s %7.2f s  rss %7.1f MB  peak %7.1f MB\n", stage, clock.nsecsElapsed() * 1e-9, statusMb("VmRSS"),
              statusMb("VmHWM"));
  std::fflush(stdout);
}

// Calls `then` once `done` holds, polling the event loop every 50 ms.
void when(QObject* owner, std::function<bool()> done, std::function<void()> then) {
  auto* poll = new QTimer(owner);
  poll->setInterval(50);
  QObject::connect(poll, &QTimer::timeout, owner, [poll, done = std::move(done), then = std::move(then)] {
    if (!done()) return;
    poll->stop();
    poll->deleteLater();
    then();
  });
  poll->start();
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Klueng"));
  QApplication::setApplicationName(QStringLiteral("klueng"));
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s PROGRAM\n", argv[0]);
    return 2;
  }
  klueng::gui::initResources();
  QElapsedTimer clock;
  clock.start();
  report("start", clock);

  klueng::gui::MainWindow window;
  window.show();
  using klueng::gui::RunState;
  klueng::gui::RunController* runner = window.runController();
  if (!window.openFile(QFileInfo(QString::fromLocal8Bit(argv[1])).absoluteFilePath())) return 1;
  int exitCode = 0;
  bool loaded = false;
  QObject::connect(&window, &klueng::gui::MainWindow::fileLoaded, &window, [&loaded, &clock] {
    loaded = true;
    report("loaded", clock);
  });
  QObject::connect(&window, &klueng::gui::MainWindow::loadFailed, &window, [&exitCode] {
    std::fprintf(stderr, "the file did not load\n");
    exitCode = 1;
    QApplication::exit(1);
  });
  when(
      &window, [&] { return loaded && !window.isBusy(); },
      [&] {
        report("checked", clock);
        const auto& steps = klueng::gui::RunSpeedControl::steps();
        for (std::size_t i = 0; i < steps.size(); ++i)
          if (steps[i] == klueng::gui::RunController::kAsFastAsPossible)
            window.action(QStringLiteral("actionSpeed%1").arg(i))->trigger();
        window.action(QStringLiteral("actionGo"))->trigger();
        when(
            &window,
            [&] {
              const RunState s = runner->state();
              return !runner->isBusy() && (s == RunState::Finished || s == RunState::Alarm || s == RunState::Idle);
            },
            [&] {
              if (runner->state() != RunState::Finished) {
                std::fprintf(stderr, "the run did not finish (state %s)\n",
                             qPrintable(klueng::gui::runStateName(runner->state())));
                exitCode = 1;
              }
              // Let the window take in the finished run (path, part panel, repaints).
              QTimer::singleShot(1000, &window, [&] {
                report("ran", clock);
                QApplication::exit(exitCode);
              });
            });
      });
  QApplication::exec();
  report("end", clock);
  return exitCode;
}

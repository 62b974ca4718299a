// klueng_gui_edit_probe [PROGRAM] [EDITS]: one edit of a long program -> new
// diagnostics on screen, in the real main window (issue 12 goal: <= 60 ms on a
// 100,000-block program). Not a unit test; run it by hand, figures to stdout:
//   - per edit: the time from the check starting (the 300 ms typing pause has
//     passed) to the diagnostics panel showing the new list, median and worst;
//   - the longest the event loop was blocked meanwhile (a 1 ms timer probe).
// Each edit makes line 50,000 an error (X letter twice) or repairs it, so every
// check really has a different answer to show.
#include <QApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <vector>

#include "../../bench/program_generator.h"
#include "gui/code_editor.h"
#include "gui/diagnostics_panel.h"
#include "gui/main_window.h"
#include "gui/resources.h"

using namespace klueng;
using namespace klueng::gui;

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  initResources();
  QTemporaryDir dir;
  QString path = argc > 1 ? QString::fromLocal8Bit(argv[1]) : dir.filePath(QStringLiteral("long.nc"));
  if (argc <= 1) std::ofstream(path.toStdString()) << bench::ProgramGenerator::generate(100000);
  const int edits = argc > 2 ? std::atoi(argv[2]) : 21;

  MainWindow w;
  w.resize(1280, 728);
  w.show();
  (void)QTest::qWaitForWindowExposed(&w);
  QElapsedTimer t;
  t.start();
  w.openFile(path);
  (void)QTest::qWaitFor([&] { return !w.isBusy(); }, 120000);
  std::printf("opened %s: %d lines in the editor, %lld ms to idle, %d diagnostics\n", qPrintable(path),
              w.editor()->blockCount(), static_cast<long long>(t.elapsed()), static_cast<int>(w.diagnostics().size()));

  const int target = std::min(50000, w.editor()->blockCount() - 1);
  std::vector<double> times;
  double longestStall = 0;
  for (int i = 0; i < edits; ++i) {
    QTextCursor c(w.editor()->document()->findBlockByNumber(target));
    c.movePosition(QTextCursor::EndOfBlock);
    if (i % 2 == 0)
      c.insertText(QStringLiteral(" X1"));  // X twice: E-error
    else {
      c.movePosition(QTextCursor::Left, QTextCursor::KeepAnchor, 3);
      c.removeSelectedText();
    }
    const int before = w.diagnosticsPanel()->errorCount();
    QElapsedTimer stall;
    qint64 last = 0, longest = 0;
    QTimer probe;
    probe.setTimerType(Qt::PreciseTimer);
    probe.setInterval(1);
    QObject::connect(&probe, &QTimer::timeout, [&] {
      const qint64 now = stall.nsecsElapsed();
      if (last > 0) longest = std::max(longest, now - last);
      last = now;
    });
    bool done = false;
    auto conn = QObject::connect(&w, &MainWindow::checkFinished, [&] { done = true; });
    stall.start();
    probe.start();
    QElapsedTimer e;
    e.start();
    w.checkNow();  // as when the typing pause ends
    (void)QTest::qWaitFor([&] { return done; }, 60000);
    const double ms = e.nsecsElapsed() / 1e6;
    probe.stop();
    QObject::disconnect(conn);
    if (w.diagnosticsPanel()->errorCount() == before) std::printf("edit %d: the list did not change\n", i);
    times.push_back(ms);
    longestStall = std::max(longestStall, longest / 1e6);
  }
  std::sort(times.begin(), times.end());
  std::printf(
      "%d edits of line %d: edit -> new diagnostics on screen median %.1f ms, fastest %.1f ms, worst %.1f ms; "
      "longest event-loop stall %.1f ms\n",
      edits, target + 1, times[times.size() / 2], times.front(), times.back(), longestStall);
  return 0;
}

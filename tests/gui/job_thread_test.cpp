// Issue 30 item 1: nothing on the GUI thread compiles or cuts. The window's
// editor check, a run, the Part panel and the printed sheets each read a
// core::job::Job; the core counts the Jobs made and the timelines and cuts
// computed, and how many of those ran on the GUI thread (none may).
#include <QAction>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>
#include <thread>

#include "fresh_user_folders.h"
#include "gui/code_editor.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/part_panel.h"
#include "gui/resources.h"
#include "gui/run_controller.h"
#include "gui_test_runner.h"
#include "window_test_support.h"
#include "klueng/core/job/job.h"

using namespace klueng;

class JobThreadTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    klueng::test::startInEnglish();
    core::job::watchThread(std::this_thread::get_id());
  }
  void cleanupTestCase() { core::job::watchThread(std::thread::id()); }

  void checkRunPartAndReportsWorkOffTheGuiThread() {
    gui::MainWindow w;
    w.resize(1366, 728);
    w.show();
    const core::job::ComputeLog start = core::job::computeLog();
    QVERIFY(w.openFile(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt")));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    const core::job::ComputeLog opened = core::job::computeLog();
    QVERIFY(opened.jobs > start.jobs);  // the editor's check is a Job

    // An edit: the debounced check makes a new Job, on its worker.
    gui::CodeEditor* editor = w.findChild<gui::CodeEditor*>();
    QVERIFY(editor);
    QTextCursor c = editor->textCursor();
    c.movePosition(QTextCursor::End);
    c.insertText(QStringLiteral("\n"));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    const core::job::ComputeLog edited = core::job::computeLog();
    QVERIFY(edited.jobs > opened.jobs);

    // A run to the end: the Job's timeline, interpreted on the runner's worker.
    w.runController()->setSpeed(gui::RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(w.runController()->state(), gui::RunState::Finished, 30000);
    QVERIFY(w.runController()->timeline());
    const core::job::ComputeLog ran = core::job::computeLog();
    QVERIFY(ran.timelines > edited.timelines);

    // The Part panel: its Job, run and part check on a worker; the list filled on this thread.
    gui::PartPanel* part = w.partPanel();
    QVERIFY(part);
    part->analyse();
    QVERIFY(part->list()->topLevelItemCount() > 0);
    QVERIFY(part->list()->topLevelItem(0)->childCount() > 0);  // sample 01's features
    const core::job::ComputeLog analysed = core::job::computeLog();
    QVERIFY(analysed.timelines > ran.timelines);

    // Both sheets: the drawing's finished part is the Job's cut, made on a worker.
    QTemporaryDir dir;
    const QString pdf = dir.filePath(QStringLiteral("sheets.pdf"));
    QVERIFY(w.exportPdf(pdf));
    QVERIFY(QFileInfo(pdf).size() > 1000);
    const core::job::ComputeLog printed = core::job::computeLog();
    QVERIFY(printed.cuts > analysed.cuts);
    QVERIFY(printed.timelines > analysed.timelines);

    QCOMPARE(printed.onWatchedThread, start.onWatchedThread);  // none of it on the GUI thread
  }

  // Go again on the same program runs the same Job's timeline; an edit makes a new Job.
  void anUnchangedProgramKeepsItsRunAnEditMakesANewJob() {
    gui::MainWindow w;
    QVERIFY(klueng::test::showSample(w));
    gui::RunController* runner = w.runController();
    runner->setSpeed(gui::RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(runner->state(), gui::RunState::Finished, 30000);
    const core::machine::Timeline* first = runner->timeline();
    QVERIFY(first);
    const core::job::ComputeLog ran = core::job::computeLog();
    QVERIFY(!first->snapshots.empty());
    const int firstLine = first->snapshots.front().line;
    const double cycleTime = first->cycleTime();

    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(runner->state(), gui::RunState::Finished, 30000);
    QCOMPARE(runner->timeline(), first);
    QCOMPARE(core::job::computeLog().timelines, ran.timelines);

    // A comment line more: the same moves, but a new Job and its own timeline, one line further down.
    gui::CodeEditor* editor = w.findChild<gui::CodeEditor*>();
    QVERIFY(editor);
    QTextCursor c(editor->document());
    c.insertText(QStringLiteral("(ONE MORE LINE)\n"));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(runner->state(), gui::RunState::Finished, 30000);
    const core::machine::Timeline* second = runner->timeline();
    QVERIFY(second);
    QCOMPARE(core::job::computeLog().timelines, ran.timelines + 1);
    QVERIFY(!second->snapshots.empty());
    QCOMPARE(second->snapshots.front().line, firstLine + 1);
    QCOMPARE(second->cycleTime(), cycleTime);  // a comment moves nothing
  }
};

KLUENG_GUI_TEST(JobThreadTest)
#include "job_thread_test.moc"

// Stepping through subprograms and macros in the main window (issue 9): Step
// Into follows a call into a subprogram file beside the program, Step Over
// runs a call whole, Step Out returns; the call stack and the variable watch
// show the step, with the variables it changed highlighted.
#include <QAction>
#include <QFile>
#include <QLabel>
#include <QPlainTextEdit>
#include <QScreen>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTreeWidget>

#include "gui_test_runner.h"
#include "fresh_user_folders.h"
#include "gui/code_editor.h"
#include "gui/diagnostics_panel.h"
#include "gui/flow_panel.h"
#include "gui/main_window.h"
#include "gui/resources.h"
#include "gui/run_controller.h"

using namespace klueng::gui;

namespace {

void write(const QString& path, const QByteArray& text) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  f.write(text);
}

// Main program (Klueng header: stock 40 x 100), lines 7-..; O1000.nc beside it.
const QByteArray kMain =
    "Flow test\nGrooves\nAluminium\n140\n1100\nKlueng tests\n"
    "O0010 (TWO GROOVES)\n"  // 7
    "G21 G99 T0101\n"        // 8
    "G97 S800 M03\n"         // 9
    "G00 X44. Z-10.\n"       // 10
    "#100 = 36.\n"           // 11
    "M98 P1000 L2\n"         // 12
    "G00 X100. Z100.\n"      // 13
    "M30\n";                 // 14
const QByteArray kSub =
    "O1000 (GROOVE)\n"    // 1
    "#101 = #100 - 1.\n"  // 2
    "G01 X#101 F0.05\n"   // 3
    "G00 X44.\n"          // 4
    "W-10.\n"             // 5
    "M99\n";              // 6

}  // namespace

class FlowPanelTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    klueng::test::freshUserFolders();
    initResources();
  }

  // (First in this file: no layout has been saved yet.) A new window fits the
  // screen with room for its title bar (issue 11: 1366 x 768 classrooms).
  void aNewWindowFitsTheScreen() {
    MainWindow w;
    QScreen* s = w.screen();
    QVERIFY(s);
    const QRect area = s->availableGeometry();
    QVERIFY2(w.width() <= area.width() && w.height() <= area.height() - 40,
             qPrintable(
                 QStringLiteral("%1x%2 on %3x%4").arg(w.width()).arg(w.height()).arg(area.width()).arg(area.height())));
  }

  void steppingIntoAndOutOfASubprogramFile() {
    QTemporaryDir dir;
    const QString main = dir.filePath(QStringLiteral("grooves.nc"));
    write(main, kMain);
    write(dir.filePath(QStringLiteral("O1000.nc")), kSub);
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(main));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    // The editor's check reads O1000.nc from the folder too: no "program not found".
    QCOMPARE(w.diagnosticsPanel()->errorCount(), 0);
    RunController* run = w.runController();
    run->setSpeed(RunController::kAsFastAsPossible);
    auto stepAndWait = [&](const char* action) {
      w.action(QString::fromLatin1(action))->trigger();
      return QTest::qWaitFor(
          [run] {
            return run->state() == RunState::Paused || run->state() == RunState::Finished ||
                   run->state() == RunState::Alarm;
          },
          30000);
    };
    // Step Over (F10) up to the call: lines 7 .. 12, all in the main program.
    for (int line : {7, 8, 9, 10, 11}) {
      QVERIFY(stepAndWait("actionStep"));
      QCOMPARE(run->currentFile(), 0);
      QCOMPARE(run->currentLine(), line);
    }
    QVERIFY(stepAndWait("actionStep"));
    QCOMPARE(run->currentLine(), 12);
    // Step Into (F11): the first block of O1000.nc, one level down.
    QVERIFY(stepAndWait("actionStepInto"));
    QCOMPARE(run->currentFile(), 1);
    QCOMPARE(run->currentLine(), 1);
    QCOMPARE(w.editor()->executingFileLine(), 0);  // not a line of the editor's program
    FlowPanel* panel = w.flowPanel();
    QVERIFY(panel->isVisible());
    QCOMPARE(panel->callStack()->topLevelItemCount(), 2);
    QVERIFY(panel->callStack()->topLevelItem(0)->text(0).startsWith(QStringLiteral("O1000")));
    QVERIFY(panel->callStack()->topLevelItem(0)->text(0).contains(QStringLiteral("1 of 2")));
    QCOMPARE(panel->callStack()->topLevelItem(0)->text(1), QStringLiteral("line 12"));
    QVERIFY(panel->source()->isVisible());
    QVERIFY(panel->source()->toPlainText().startsWith(QStringLiteral("O1000 (GROOVE)")));
    QVERIFY(panel->sourceTitle()->text().contains(QStringLiteral("O1000.nc")));
    // #101 = #100 - 1.: the watch shows #100 = 36 and the new #101 = 35, highlighted.
    QVERIFY(stepAndWait("actionStepInto"));
    QCOMPARE(run->currentLine(), 2);
    QTreeWidget* vars = panel->variables();
    QCOMPARE(vars->topLevelItemCount(), 2);
    QCOMPARE(vars->topLevelItem(0)->text(0), QStringLiteral("#100"));
    QCOMPARE(vars->topLevelItem(0)->text(1), QStringLiteral("36"));
    QVERIFY(!vars->topLevelItem(0)->data(0, Qt::UserRole).toBool());
    QCOMPARE(vars->topLevelItem(1)->text(0), QStringLiteral("#101"));
    QCOMPARE(vars->topLevelItem(1)->text(1), QStringLiteral("35"));
    QVERIFY(vars->topLevelItem(1)->data(0, Qt::UserRole).toBool());
    QVERIFY(vars->topLevelItem(1)->font(0).bold());
    // Step Out (Shift+F11): both passes of the subprogram run, back at line 13.
    QVERIFY(stepAndWait("actionStepOut"));
    QCOMPARE(run->currentFile(), 0);
    QCOMPARE(run->currentLine(), 13);
    QCOMPARE(w.editor()->executingFileLine(), 13);
    QCOMPARE(panel->callStack()->topLevelItemCount(), 1);
    QVERIFY(!panel->source()->isVisible());
  }

  void anErrorInTheSubprogramFileIsShownOnTheCall() {
    QTemporaryDir dir;
    const QString main = dir.filePath(QStringLiteral("grooves.nc"));
    write(main, kMain);
    write(dir.filePath(QStringLiteral("O1000.nc")), "O1000\nG01 X36. Y1. F0.05\nM99\n");
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(main));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    QCOMPARE(w.diagnosticsPanel()->errorCount(), 1);
    const auto& d = w.diagnosticsPanel()->diagnostics().front();
    QCOMPARE(QString::fromStdString(d.code), QStringLiteral("E412"));
    QCOMPARE(d.range.line, 12);  // M98 P1000 L2: the P word
    QCOMPARE(d.range.column, 5);
    QCOMPARE(QString::fromStdString(d.args.at(0)), QStringLiteral("O1000.nc"));
    QCOMPARE(QString::fromStdString(d.args.at(3)), QStringLiteral("E201"));
  }

  void hoveringAnExpressionWordShowsItsLastValue() {
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    w.editor()->setPlainText(QStringLiteral("G21 G98\n#1 = 25.\nG00 X#1 Z10.\nM30\n"));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    RunController* run = w.runController();
    run->setSpeed(RunController::kAsFastAsPossible);
    const int xAt = w.editor()->document()->findBlockByNumber(2).position() + 4;  // the X of "G00 X#1"
    QVERIFY(!w.editor()->helpForPosition(xAt).contains(QStringLiteral("= 25")));  // not run yet
    w.action(QStringLiteral("actionGo"))->trigger();
    QVERIFY(QTest::qWaitFor([run] { return run->state() == RunState::Finished; }, 30000));
    const QString help = w.editor()->helpForPosition(xAt);
    QVERIFY2(help.contains(QStringLiteral("= 25 ")), qPrintable(help));
    QVERIFY(help.contains(QStringLiteral("X position")));
  }

  void stepOverRunsACallWhole() {
    QTemporaryDir dir;
    const QString main = dir.filePath(QStringLiteral("grooves.nc"));
    write(main, kMain);
    write(dir.filePath(QStringLiteral("1000.nc")), kSub);  // the number alone names the file too
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(main));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    RunController* run = w.runController();
    run->setSpeed(RunController::kAsFastAsPossible);
    for (int k = 0; k < 7; ++k) {
      w.action(QStringLiteral("actionStep"))->trigger();
      QVERIFY(QTest::qWaitFor([run] { return run->state() == RunState::Paused || run->state() == RunState::Finished; },
                              30000));
    }
    QCOMPARE(run->currentLine(), 13);  // the seventh step ran M98 P1000 L2 and both grooves
    QCOMPARE(run->currentFile(), 0);
    // Paused after G00 X100. Z100.; the subprogram's two passes ran inside the seventh step.
    QCOMPARE(run->status().position.x(), 100.0);
    QCOMPARE(run->status().position.y(), 50.0);
    const auto* t = run->timeline();
    QVERIFY(t);
    int grooves = 0;
    for (const auto& m : t->moves)
      if (m.file == 1 && m.kind == klueng::core::machine::MoveKind::Line) ++grooves;
    QCOMPARE(grooves, 2);
  }
};

KLUENG_GUI_TEST(FlowPanelTest)
#include "flow_panel_test.moc"

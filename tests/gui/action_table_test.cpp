// The main window's action table (issue 12): one table drives the menus, the
// tool bars, the texts and the run-state gates.
#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QTest>
#include <QToolBar>

#include "gui_test_runner.h"
#include "gui/action_table.h"
#include "gui/code_editor.h"
#include "gui/resources.h"
#include "gui/run_speed_control.h"

using namespace klueng::gui;

class ActionTableTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { initResources(); }

  void everyActionIsOnAMenuOrAToolBar() {
    QMainWindow window;
    ActionTable table(&window, static_cast<int>(RunSpeedControl::steps().size()));
    table.buildToolBars();
    table.buildMenus();
    table.retranslate();
    int count = 0;
    for (QAction* a : window.findChildren<QAction*>(QString(), Qt::FindDirectChildrenOnly)) {
      if (!a->objectName().startsWith(QStringLiteral("action"))) continue;
      ++count;
      bool shown = false;
      for (QObject* o : a->associatedObjects()) shown |= qobject_cast<QMenu*>(o) || qobject_cast<QToolBar*>(o);
      QVERIFY2(shown, qPrintable(a->objectName()));
      QVERIFY2(!a->text().isEmpty(), qPrintable(a->objectName()));
    }
    QVERIFY(count >= 50);
    // The menu bar in the order of SPEC 12, a submenu where the table puts it.
    QStringList titles;
    for (QAction* m : window.menuBar()->actions()) titles << m->text();
    QCOMPARE(titles, (QStringList{QStringLiteral("&File"), QStringLiteral("&Edit"), QStringLiteral("&Run"),
                                  QStringLiteral("&Tool setting"), QStringLiteral("&View"), QStringLiteral("&Help")}));
    const QList<QAction*> file = table.menu(QStringLiteral("menuFile"))->actions();
    QCOMPARE(file.at(2)->menu(), table.menu(QStringLiteral("menuRecent")));
    // The tool tip carries the shortcut.
    QCOMPARE(table.action(QStringLiteral("actionGo"))->toolTip(), QStringLiteral("Run the program continuously (F5)"));
  }

  void gatesFollowTheRunState() {
    using W = EnabledWhen;
    const struct {
      RunState state;
      bool go, step, pause, stop, back, open;
    } rows[] = {
        {RunState::Idle, true, true, false, false, false, true},
        {RunState::Preparing, false, false, true, true, false, false},
        {RunState::Running, false, true, true, true, false, false},
        {RunState::Stepping, true, false, true, true, false, false},
        {RunState::Paused, true, true, false, true, true, true},
        {RunState::Finished, true, true, false, true, true, true},
        {RunState::Alarm, true, true, false, true, true, true},
    };
    for (const auto& r : rows) {
      QCOMPARE(ActionTable::enabledIn(W::CanGo, r.state), r.go);
      QCOMPARE(ActionTable::enabledIn(W::CanStep, r.state), r.step);
      QCOMPARE(ActionTable::enabledIn(W::Running, r.state), r.pause);
      QCOMPARE(ActionTable::enabledIn(W::Started, r.state), r.stop);
      QCOMPARE(ActionTable::enabledIn(W::StoppedMidRun, r.state), r.back);
      QCOMPARE(ActionTable::enabledIn(W::NotRunning, r.state), r.open);
    }
    QMainWindow window;
    ActionTable table(&window, 3);
    table.applyRunState(RunState::Running);
    QVERIFY(!table.action(QStringLiteral("actionOpen"))->isEnabled());
    QVERIFY(table.action(QStringLiteral("actionPause"))->isEnabled());
    QVERIFY(table.action(QStringLiteral("actionSave"))->isEnabled());  // not gated
    table.applyRunState(RunState::Paused);
    QVERIFY(table.action(QStringLiteral("actionOpen"))->isEnabled());
    QVERIFY(table.action(QStringLiteral("actionStepBack"))->isEnabled());
  }
};

KLUENG_GUI_TEST(ActionTableTest)
#include "action_table_test.moc"

// klueng_gui_step_shot PROGRAM STEPS OUT.png [en|th]: the real main window at
// 1366 x 728 (a classroom screen less its taskbar), PROGRAM stepped STEPS blocks,
// saved as a picture to look at (status bar, Explain bar, tool). Not a unit test.
#include <QApplication>
#include <QTest>
#include <cstdio>
#include <cstdlib>

#include "gui/class_grade_dialog.h"
#include "gui/help_contents.h"
#include "gui/language.h"

#include <QLineEdit>
#include <QTextBrowser>
#include "gui/main_window.h"
#include "gui/operator_panel.h"
#include "gui/part3d_view.h"
#include "gui/part_designer.h"
#include "gui/part_panel.h"
#include <QPushButton>
#include <QTabWidget>
#include <QTableView>
#include "gui/design_model.h"
#include <QTreeWidget>
#include "gui/resources.h"
#include "gui/run_controller.h"
#include "gui/status_panel.h"

using namespace klueng::gui;

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  initResources();
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s PROGRAM STEPS OUT.png [en|th]\n", argv[0]);
    return 2;
  }
  MainWindow w;
  Language::instance()->setLanguage(QString::fromLatin1(argc > 4 ? argv[4] : "en"));
  w.resize(1366, 728);
  w.show();
  (void)QTest::qWaitForWindowExposed(&w);
  if (!w.openFile(QString::fromLocal8Bit(argv[1]))) return 1;
  if (!QTest::qWaitFor([&w] { return !w.isBusy(); }, 60000)) return 1;
  // "help:roughing": the help window searched for a word instead.
  if (QString::fromLocal8Bit(argv[2]).startsWith(QStringLiteral("help:"))) {
    w.action(QStringLiteral("actionContents"))->trigger();
    auto* help = w.findChild<HelpContents*>();
    if (!help) return 1;
    const QString word = QString::fromLocal8Bit(argv[2]).mid(5);
    if (word.startsWith(QLatin1Char('#'))) {
      help->browser()->scrollToAnchor(word.mid(1));  // "help:#ex-G71": a place on the page
    } else {
      help->searchField()->setText(word);
      QTest::keyClick(help->searchField(), Qt::Key_Return);
    }
    QTest::qWait(300);
    return help->grab().save(QString::fromLocal8Bit(argv[3])) ? 0 : 1;
  }
  // "part:N": the Part panel raised, the part checked with comparison N (0 none,
  // 1 without G41/G42, 2 sharp nose) and its first finding selected.
  if (QString::fromLocal8Bit(argv[2]).startsWith(QStringLiteral("part:"))) {
    auto* part = w.partPanel();
    part->setComparison(QString::fromLocal8Bit(argv[2]).mid(5).toInt());
    part->raise();
    part->analyse();
    if (part->list()->topLevelItemCount() > 0 && part->list()->topLevelItem(0)->childCount() > 3)
      part->list()->setCurrentItem(part->list()->topLevelItem(0)->child(3));
    QTest::qWait(200);
    return w.grab().save(QString::fromLocal8Bit(argv[3])) ? 0 : 1;
  }
  // "class:DIR": File > Grade a class on DIR against PROGRAM.
  if (QString::fromLocal8Bit(argv[2]).startsWith(QStringLiteral("class:"))) {
    w.action(QStringLiteral("actionGradeClass"))->trigger();
    auto* dialog = w.findChild<ClassGradeDialog*>();
    if (!dialog) return 1;
    dialog->setFolder(QString::fromLocal8Bit(argv[2]).mid(6));
    dialog->grade();
    if (!QTest::qWaitFor([dialog] { return !dialog->isGrading(); }, 60000)) return 1;
    QTest::qWait(300);
    return dialog->grab().save(QString::fromLocal8Bit(argv[3])) ? 0 : 1;
  }
  // "design:PART": File > Part designer with PART (JSON or DXF) opened, its first
  // feature selected; OUT.png the dialog, OUT-3d.png with its 3D tab.
  if (QString::fromLocal8Bit(argv[2]).startsWith(QStringLiteral("design:"))) {
    w.action(QStringLiteral("actionPartDesigner"))->trigger();
    auto* designer = w.findChild<PartDesignerDialog*>();
    if (!designer || !designer->openFile(QString::fromLocal8Bit(argv[2]).mid(7))) return 1;
    // The part's own bar (a tube for a bored part) into Job details, as the user's "Use this bar" does.
    if (auto* use = designer->findChild<QPushButton*>(QStringLiteral("designUseFileBar")); use && !use->isHidden())
      use->click();
    designer->table()->setCurrentIndex(designer->model()->index(0, 1));
    if (!QTest::qWaitFor([designer] { return !designer->isRunning() && designer->lastLoop(); }, 60000)) return 1;
    QTest::qWait(300);
    std::printf("%s\n", qPrintable(designer->verdict()));
    if (!designer->grab().save(QString::fromLocal8Bit(argv[3]))) return 1;
    designer->findChild<QTabWidget*>(QStringLiteral("designTabs"))->setCurrentIndex(1);
    QTest::qWait(200);
    QString out = QString::fromLocal8Bit(argv[3]);
    out.insert(out.lastIndexOf(QLatin1Char('.')), QStringLiteral("-3d"));
    return designer->grab().save(out) ? 0 : 1;
  }
  w.runController()->setSpeed(RunController::kAsFastAsPossible);
  // "3d:N": the 3D view shown beside the output screen, N blocks stepped (the window, then the 3D view alone
  // as OUT-3d.png).
  QString steps = QString::fromLocal8Bit(argv[2]);
  const bool view3d = steps.startsWith(QStringLiteral("3d:"));
  if (view3d) {
    steps = steps.mid(3);
    w.view3dDock()->show();
    w.resizeDocks({w.view3dDock()}, {560}, Qt::Horizontal);
  }
  // "panel:N": the Operator panel shown, N blocks stepped from the tool bar (the window, then the
  // panel alone as OUT-panel.png): the panel follows the run, its last row in sight.
  const bool panel = steps.startsWith(QStringLiteral("panel:"));
  if (panel) {
    steps = steps.mid(6);
    w.action(QStringLiteral("operatorPanelDock"))->trigger();
  }
  if (steps == QStringLiteral("end")) {  // run to the program's end
    w.action(QStringLiteral("actionGo"))->trigger();
    if (!QTest::qWaitFor([&w] { return w.runController()->state() == RunState::Finished; }, 60000)) return 1;
    w.runController()->waitForIdle();
  }
  for (int i = 0; i < steps.toInt(); ++i) {
    w.action(QStringLiteral("actionStep"))->trigger();
    if (!QTest::qWaitFor(
            [&w] {
              return w.runController()->state() == RunState::Paused || w.runController()->state() == RunState::Finished;
            },
            20000))
      return 1;
  }
  QTest::qWait(300);
  std::printf("status fields: %d px wanted, %d px shown\n", w.statusFields()->sizeHint().width(),
              w.statusFields()->width());
  if (panel) {
    QString out = QString::fromLocal8Bit(argv[3]);
    out.insert(out.lastIndexOf(QLatin1Char('.')), QStringLiteral("-panel"));
    if (!w.operatorPanel()->grab().save(out)) return 1;
  }
  if (view3d) {
    QString out = QString::fromLocal8Bit(argv[3]);
    out.insert(out.lastIndexOf(QLatin1Char('.')), QStringLiteral("-3d"));
    if (!w.view3dDock()->view()->grab().save(out)) return 1;
    std::printf("3d: %d quads\n", w.view3dDock()->view()->lastQuadCount());
  }
  return w.grab().save(QString::fromLocal8Bit(argv[3])) ? 0 : 1;
}

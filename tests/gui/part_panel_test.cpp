// The Part dock and the measure tool (issue 10, items 2-4) in the real main
// window: sample 01's features, its part check, the comparison without
// G41/G42 drawn over the section and put on its blocks, a feature marked on
// the output screen, and a measurement between two clicks.
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>
#include <QTreeWidget>

#include "gui_test_runner.h"
#include "window_test_support.h"
#include "fresh_user_folders.h"
#include "gui/code_editor.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/output_view.h"
#include "gui/part3d_view.h"
#include "gui/part_panel.h"
#include "gui/resources.h"
#include "gui/run_controller.h"

using namespace klueng;

namespace {

QStringList texts(QTreeWidgetItem* parent) {
  QStringList out;
  for (int i = 0; parent && i < parent->childCount(); ++i) out << parent->child(i)->text(0);
  return out;
}

QTreeWidgetItem* group(QTreeWidget* list, const QString& title) {
  for (int i = 0; i < list->topLevelItemCount(); ++i)
    if (list->topLevelItem(i)->text(0) == title) return list->topLevelItem(i);
  return nullptr;
}

}  // namespace

class PartPanelTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { klueng::test::startInEnglish(); }

  void sample01FeaturesCheckAndComparison() {
    gui::MainWindow w;
    QVERIFY(klueng::test::showSample(w));
    gui::PartPanel* part = w.partPanel();
    QVERIFY(part);
    auto* output = w.findChild<gui::OutputView*>();
    QVERIFY(output);
    part->setComparison(1);
    part->analyse();

    const QStringList features = texts(group(part->list(), QStringLiteral("Features")));
    QVERIFY2(features.contains(QStringLiteral("Cylinder Ø30, Z-3 to Z-19.2, length 16.2")),
             qPrintable(features.join(u'\n')));
    QVERIFY(features.contains(QStringLiteral("Chamfer C3 (3 × 45°), Ø24.469 to Ø30, Z-0.234 to Z-3")));
    QVERIFY(features.contains(QStringLiteral("Arc R2 round, centre Z-22 X36, Z-20 to Z-22")));
    QVERIFY(texts(group(part->list(), QStringLiteral("Part check"))).isEmpty());  // sample 01 is right
    QVERIFY(part->summary()->text().contains(QStringLiteral("no gouge, no leftover")));
    // Issue 39 item 3: each surface's roughness from the cut that left it. The Ø30 is finished on
    // line 44 (N360) at F0.1 with R0.8: Ra = 0.1^2 / (32 * 0.8) * 1000 = 0.39 um, Rz 1.56 um.
    QTreeWidgetItem* featureGroup = group(part->list(), QStringLiteral("Features"));
    QTreeWidgetItem* cylinder30 = nullptr;
    for (int i = 0; i < featureGroup->childCount(); ++i)
      if (featureGroup->child(i)->text(0) == QStringLiteral("Cylinder Ø30, Z-3 to Z-19.2, length 16.2"))
        cylinder30 = featureGroup->child(i);
    QVERIFY(cylinder30);
    QCOMPARE(part->list()->headerItem()->text(3), QStringLiteral("Ra (µm)"));
    QCOMPARE(cylinder30->text(3), QStringLiteral("0.39"));
    QCOMPARE(cylinder30->text(2), QStringLiteral("44"));
    QCOMPARE(cylinder30->toolTip(3), QStringLiteral("Ra 0.39 µm, Rz 1.6 µm: the theoretical roughness of line 44's cut "
                                                    "(feed 0.100 mm/rev, nose R0.8)"));

    QTreeWidgetItem* comp = group(part->list(), QStringLiteral("Compensation"));
    const QStringList differences = texts(comp);
    QVERIFY2(differences.contains(QStringLiteral("chamfer C3 N350: 0.33 mm short without compensation")),
             qPrintable(differences.join(u'\n')));
    QVERIFY(differences.contains(QStringLiteral("arc R2 N380: 0.33 mm short without compensation")));
    QVERIFY(!output->partOverlay().otherOutline.isEmpty());
    QVERIFY(output->partOverlay().bands.size() >= 3);

    // A difference goes to the block that cut that surface.
    auto* editor = w.findChild<gui::CodeEditor*>();
    QVERIFY(editor);
    for (int i = 0; i < comp->childCount(); ++i)
      if (comp->child(i)->text(0).startsWith(QStringLiteral("chamfer C3")))
        emit part->list()->itemActivated(comp->child(i), 0);
    QCOMPARE(editor->cursorFileLine(), 43);

    // Selecting a feature marks its profile on the output screen.
    QTreeWidgetItem* features_ = group(part->list(), QStringLiteral("Features"));
    part->list()->setCurrentItem(features_->child(3));
    QVERIFY(!output->partOverlay().highlight.isEmpty());
    QVERIFY(output->partOverlay().highlight.boundingRect().width() > 10.0);  // the Ø30 cylinder, 16.2 mm

    // Measure: two clicks on the Ø30 and Ø40 steps of the cut part read ΔZ and
    // ΔØ, snapped to the profile.
    auto* runner = w.findChild<gui::RunController*>();
    QVERIFY(runner);
    runner->setSpeed(gui::RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QVERIFY(QTest::qWaitFor([runner] { return runner->state() == gui::RunState::Finished; }, 30000));
    runner->waitForIdle();
    QVERIFY(runner->cutSimulator());
    output->fitToView();
    output->setMeasuring(true);
    QSignalSpy reading(output, &gui::OutputView::measured);
    const QPoint a = output->mapFromScene(QPointF(-10.0, -15.05));  // just off Ø30's edge, upper half
    const QPoint b = output->mapFromScene(QPointF(-30.0, -20.05));  // just off Ø40's edge
    QTest::mouseClick(output->viewport(), Qt::LeftButton, {}, a);
    QTest::mouseClick(output->viewport(), Qt::LeftButton, {}, b);
    QCOMPARE(reading.count(), 1);
    const QString text = reading.first().first().toString();
    QVERIFY2(text.contains(QStringLiteral("ΔØ 10.000")), qPrintable(text));  // Ø30 to Ø40, exactly
    output->setMeasuring(false);

    // An edit makes the list stale: it goes, and the marks on the output screen with it.
    editor->textCursor().insertText(QStringLiteral(" "));
    QCOMPARE(part->list()->topLevelItemCount(), 0);
    QVERIFY(output->partOverlay().empty());
    QVERIFY(part->summary()->text().contains(QStringLiteral("check the part again")));
  }

  // Issue 28 item 6: each view shows the current file and language, or nothing.
  // A measurement goes with its file; the comparison's outline is hidden while
  // a run cuts the bar again; a language switch says the Part list again.
  void noStaleMarks() {
    gui::MainWindow w;
    QVERIFY(klueng::test::showSample(w));
    gui::PartPanel* part = w.partPanel();
    auto* output = w.findChild<gui::OutputView*>();
    auto* runner = w.findChild<gui::RunController*>();
    part->setComparison(1);
    part->analyse();
    QVERIFY(output->isPartOverlayShown());
    QVERIFY(!output->partOverlay().otherOutline.isEmpty());

    // A re-run: the outline is not drawn over the bar being cut; back at the end.
    runner->setSpeed(1.0);
    w.action(QStringLiteral("actionGo"))->trigger();
    QVERIFY(QTest::qWaitFor([runner] { return runner->state() == gui::RunState::Running; }, 30000));
    QVERIFY(!output->isPartOverlayShown());
    runner->setSpeed(gui::RunController::kAsFastAsPossible);
    QVERIFY(QTest::qWaitFor([runner] { return runner->state() == gui::RunState::Finished; }, 60000));
    runner->waitForIdle();
    QVERIFY(output->isPartOverlayShown());

    // The Part list in Thai after the switch, and back.
    const QString cylinder = QStringLiteral("Cylinder Ø30, Z-3 to Z-19.2, length 16.2");
    QVERIFY(texts(group(part->list(), QStringLiteral("Features"))).contains(cylinder));
    gui::Language::instance()->setLanguage(QStringLiteral("th"));
    QCoreApplication::processEvents();
    const QStringList thai = texts(group(part->list(), QStringLiteral("รูปร่างชิ้นงาน")));
    QVERIFY2(thai.contains(QStringLiteral("ทรงกระบอก Ø30 Z-3 ถึง Z-19.2 ยาว 16.2")), qPrintable(thai.join(u'\n')));
    QVERIFY(!thai.join(u'\n').contains(QStringLiteral("Cylinder")));
    QVERIFY2(!part->summary()->text().contains(QStringLiteral("no gouge")), qPrintable(part->summary()->text()));
    // The comparison's choice is whole in Thai too ("เปรียบเทียบ: ไม่ชดเชยรัศมีจมูกมีด").
    auto* compare = part->findChild<QComboBox*>(QStringLiteral("compareCompensation"));
    part->raise();  // the dock's tab in front, laid out
    QTRY_VERIFY(compare->isVisible());
    QTest::qWait(50);
    QVERIFY2(compare->width() >= compare->fontMetrics().horizontalAdvance(compare->currentText()) + 24,
             qPrintable(QStringLiteral("%1: %2 px").arg(compare->currentText()).arg(compare->width())));
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
    QCoreApplication::processEvents();
    QVERIFY(texts(group(part->list(), QStringLiteral("Features"))).contains(cylinder));

    // Measure on sample 01's part, then open sample 02: no point of it is left.
    output->fitToView();
    output->setMeasuring(true);
    QTest::mouseClick(output->viewport(), Qt::LeftButton, {}, output->mapFromScene(QPointF(-10.0, -15.05)));
    QTest::mouseClick(output->viewport(), Qt::LeftButton, {}, output->mapFromScene(QPointF(-30.0, -20.05)));
    QVERIFY(output->hasMeasurement());
    QVERIFY(w.statusBar()->currentMessage().contains(QStringLiteral("ΔØ 10.000")));
    QVERIFY(w.openFile(QStringLiteral(KLUENG_SAMPLES_DIR "/02-thread.txt")));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    QVERIFY(!output->hasMeasurement());
    QCOMPARE(w.statusBar()->currentMessage(), QString());  // nor its reading
    QVERIFY(output->partOverlay().empty());
    output->setMeasuring(false);
  }

  // The 3D view: shown from the View menu, draws the bar before a run and the
  // cut part after it (thread teeth make many more faces), turns with a drag.
  void view3dFollowsTheRun() {
    gui::MainWindow w;
    w.resize(1366, 728);
    w.show();
    QVERIFY(w.openFile(QStringLiteral(KLUENG_SAMPLES_DIR "/02-thread.txt")));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    QAction* show = w.action(QStringLiteral("view3dDock"));
    QVERIFY(show);
    QVERIFY(!w.view3dDock()->isVisible());
    show->trigger();
    QVERIFY(w.view3dDock()->isVisible());
    gui::Part3DWidget* view = w.view3dDock()->view();
    view->repaint();
    const int barQuads = view->lastQuadCount();
    QVERIFY2(barQuads > 20, qPrintable(QString::number(barQuads)));
    auto* runner = w.findChild<gui::RunController*>();
    runner->setSpeed(gui::RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QVERIFY(QTest::qWaitFor([runner] { return runner->state() == gui::RunState::Finished; }, 30000));
    runner->waitForIdle();
    view->repaint();
    QVERIFY2(view->lastQuadCount() > 10 * barQuads, qPrintable(QString::number(view->lastQuadCount())));
    const double yaw = view->camera().yaw;
    QTest::mousePress(view, Qt::LeftButton, {}, QPoint(100, 100));
    QTest::mouseMove(view, QPoint(150, 100));
    QTest::mouseRelease(view, Qt::LeftButton, {}, QPoint(150, 100));
    QVERIFY(view->camera().yaw != yaw);
  }

  // Issue 28 item 8: at 1366 x 768 the Part list showed 3 rows; it shows 6.
  void thePartListShowsMoreThanThreeRowsAt768() {
    gui::MainWindow w;
    w.resize(1366, 768);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt")));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    gui::PartPanel* part = w.partPanel();
    part->show();
    part->raise();
    part->analyse();
    QTreeWidget* list = part->list();
    list->expandAll();
    const int row = list->sizeHintForRow(0);
    QVERIFY(row > 0);
    QTRY_VERIFY2(list->viewport()->height() >= 6 * row,
                 qPrintable(QStringLiteral("%1 px for rows of %2 px").arg(list->viewport()->height()).arg(row)));
    QVERIFY(w.editor()->height() > 150);  // the editor keeps its room
  }

  void thaiLabels() {
    gui::Language::instance()->setLanguage(QStringLiteral("th"));
    gui::MainWindow w;
    QCOMPARE(w.partPanel()->windowTitle(), QStringLiteral("ชิ้นงาน"));
    QCOMPARE(w.partPanel()->measureButton()->text(), QStringLiteral("วัดขนาด"));
    QCOMPARE(w.view3dDock()->windowTitle(), QStringLiteral("ภาพสามมิติ"));
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
  }
};

KLUENG_GUI_TEST(PartPanelTest)
#include "part_panel_test.moc"

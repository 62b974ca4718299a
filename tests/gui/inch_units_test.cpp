// Issue 28 item 4: a G20 program speaks inches on the screen — status bar,
// rulers, Part list and check — and View ▸ Units shown overrides it, remembered.
#include <QAction>
#include <QApplication>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "gui_test_runner.h"
#include <QTreeWidget>

#include <algorithm>

#include "fresh_user_folders.h"
#include "gui/code_editor.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/output_view.h"
#include "gui/part_panel.h"
#include "gui/resources.h"
#include "gui/run_controller.h"
#include "gui/settings.h"
#include "gui/status_panel.h"

using namespace klueng;
using namespace klueng::gui;

namespace {

// A Haas shop's inch shaft: Ø1.75 bar, faced, a 0.050″ × 45° chamfer, Ø1.500 to Z-1.0 with G42.
const char* const kInchShaft =
    "Inch shaft\nIN-01\n1018 steel\n01.75\n03\nKlueng tests\n"
    "O01000 (INCH SHAFT)\n"
    "G20 G40 G99 (INCH, FEED PER REV)\n"
    "T0101 (OD TURN)\n"
    "G50 S2000\n"
    "G96 S500 M03\n"
    "G00 X1.85 Z0.1 M08\n"
    "G01 Z0. F0.008\n"
    "X-0.063\n"
    "G00 Z0.1\n"
    "G00 G42 X1.3 Z0.05\n"
    "G01 X1.5 Z-0.05 F0.008\n"
    "Z-1.0\n"
    "X1.8\n"
    "G00 G40 X2.0 Z0.1\n"
    "M09\n"
    "M05\n"
    "M30\n";

bool waitIdle(MainWindow& w) {
  return QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000);
}

QStringList listChildren(QTreeWidget* list, const QString& title) {
  QStringList out;
  for (int i = 0; i < list->topLevelItemCount(); ++i)
    if (list->topLevelItem(i)->text(0) == title)
      for (int k = 0; k < list->topLevelItem(i)->childCount(); ++k) out << list->topLevelItem(i)->child(k)->text(0);
  return out;
}

std::pair<double, double> span(const QStringList& labels) {
  double lo = 1e9, hi = -1e9;
  for (const QString& l : labels) {
    lo = std::min(lo, l.toDouble());
    hi = std::max(hi, l.toDouble());
  }
  return {lo, hi};
}

}  // namespace

class InchUnitsTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    klueng::test::freshUserFolders();
    initResources();
    Language::instance()->setLanguage(QStringLiteral("en"));
  }

  void aG20ProgramSpeaksInchesAndTheViewSwitchOverridesIt() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("inch-shaft.txt"));
    {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(kInchShaft);
    }
    Settings().setShownUnits(std::nullopt);
    MainWindow w;
    w.resize(1366, 728);
    w.show();
    QVERIFY(w.openFile(path));
    QVERIFY(waitIdle(w));
    QVERIFY(w.displayUnits().inch());  // Auto: the program's G20
    QVERIFY(w.action(QStringLiteral("actionShowUnitsAuto"))->isChecked());

    w.runController()->setSpeed(RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(w.runController()->state(), RunState::Finished, 20000);
    QCoreApplication::processEvents();
    const StatusFields* f = w.statusFields();
    // G00 X2.0 Z0.1 last: the control's 4 decimals; F0.008 in/rev; offset 01's R0.8 mm nose.
    QCOMPARE(f->fieldText(StatusFields::Field::ToolX), QStringLiteral("2.0000"));
    QCOMPARE(f->fieldText(StatusFields::Field::ToolZ), QStringLiteral("0.1000"));
    QCOMPARE(f->fieldText(StatusFields::Field::Feed), QStringLiteral("0.0080 in/rev"));
    QCOMPARE(f->fieldText(StatusFields::Field::NoseRadius), QStringLiteral("0.0315"));

    auto* output = w.findChild<OutputView*>();
    QVERIFY(output);
    output->fitToView();
    QCoreApplication::processEvents();
    const QStringList inchZ = output->rulerLabels(true);
    QVERIFY2(inchZ.contains(QStringLiteral("-1")) || inchZ.contains(QStringLiteral("-2")),
             qPrintable(inchZ.join(u' ')));

    PartPanel* part = w.partPanel();
    part->analyse();
    const QStringList features = listChildren(part->list(), QStringLiteral("Features"));
    QVERIFY2(features.contains(QStringLiteral("Cylinder Ø1.5000″, Z-0.0500 to Z-0.9685, length 0.9185″")),
             qPrintable(features.join(u'\n')));
    QVERIFY2(listChildren(part->list(), QStringLiteral("Part check")).isEmpty(),
             qPrintable(listChildren(part->list(), QStringLiteral("Part check")).join(u'\n')));

    // View ▸ Units shown ▸ Millimetres: the same run, said in mm, and remembered.
    w.action(QStringLiteral("actionShowUnitsMm"))->trigger();
    QCOMPARE(f->fieldText(StatusFields::Field::ToolX), QStringLiteral("50.800"));
    QCOMPARE(f->fieldText(StatusFields::Field::ToolZ), QStringLiteral("2.540"));
    QCOMPARE(f->fieldText(StatusFields::Field::Feed), QStringLiteral("0.203 mm/rev"));
    QCOMPARE(f->fieldText(StatusFields::Field::NoseRadius), QStringLiteral("0.800"));
    QCOMPARE(Settings().shownUnits(), std::optional<core::DisplayUnits>(core::DisplayUnits::Mm));
    const QStringList mmFeatures = listChildren(part->list(), QStringLiteral("Features"));
    QVERIFY2(mmFeatures.contains(QStringLiteral("Cylinder Ø38.1, Z-1.27 to Z-24.6, length 23.33")),
             qPrintable(mmFeatures.join(u'\n')));
    // The rulers show the same stretch of Z, in mm now.
    const QStringList mmZ = output->rulerLabels(true);
    QVERIFY(inchZ.size() >= 2 && mmZ.size() >= 2);
    const auto [inLo, inHi] = span(inchZ);
    const auto [mmLo, mmHi] = span(mmZ);
    // Labels sit on round numbers of each unit: the ends agree within one major step.
    const double step = std::max((inHi - inLo) / (inchZ.size() - 1) * 25.4, (mmHi - mmLo) / (mmZ.size() - 1));
    QVERIFY2(std::abs(inLo * 25.4 - mmLo) <= step && std::abs(inHi * 25.4 - mmHi) <= step,
             qPrintable(QStringLiteral("%1..%2 in, %3..%4 mm").arg(inLo).arg(inHi).arg(mmLo).arg(mmHi)));

    // Back to Auto: inches again; a G21 program then speaks mm.
    w.action(QStringLiteral("actionShowUnitsAuto"))->trigger();
    QCOMPARE(f->fieldText(StatusFields::Field::ToolX), QStringLiteral("2.0000"));
    w.editor()->setPlainText(QStringLiteral("G21 G99\nT0101 G00 X60. Z5.\nM30\n"));
    QVERIFY(waitIdle(w));
    QTRY_VERIFY_WITH_TIMEOUT(!w.displayUnits().inch(), 10000);
  }
};

KLUENG_GUI_TEST(InchUnitsTest)
#include "inch_units_test.moc"

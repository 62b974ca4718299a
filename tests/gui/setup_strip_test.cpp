// Issue 26 (GUI): a plain program's setup is shown above the output screen
// before a run - each station's tool guessed from the program with its reason,
// the bar and why - and one click on a station opens Tool Select there.
#include <algorithm>

#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include "gui_test_runner.h"
#include "fresh_user_folders.h"
#include "gui/diagnostics_panel.h"
#include "gui/job_details_dialog.h"
#include "gui/run_controller.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/resources.h"
#include "gui/settings.h"
#include "gui/setup_strip.h"
#include "gui/tool_select_dialog.h"

using namespace klueng;
using namespace klueng::gui;

namespace {

// A Haas-style shop program: no job header, inches, T101 turning, T202 a G75 groove.
const char* kHaas =
    "%\n"
    "O30414 (PIN)\n"
    "G18 G40 G54 G80 G99\n"
    "T101 (TOOL 1)\n"
    "G96 S600 M03\n"
    "G00 X1.2 Z0.1\n"
    "G71 P40 Q55 U0 W0 D0.03 F0.008\n"
    "N40 G00 X0.875\n"
    "G01 Z0.\n"
    "Z-1.5\n"
    "N55 X1.0\n"
    "G00 X1.5 Z2.\n"
    "T202\n"
    "G97 S800 M03\n"
    "G00 X1.0\n"
    "Z-0.5\n"
    "G75 X0.7 Z-0.6 I0.05 K0.08 F0.002\n"
    "G00 X1.5\n"
    "M30\n"
    "%\n";

// A Fanuc inch program in shop habit: positions with points, the G71 depth and
// retract without (U1250 = 0.1250 in, R50 = 0.0050 in on a standard control).
const char* kFanucInch =
    "%\n"
    "O1234 (SLEEVE - 1.500 BAR)\n"
    "(T1 OD ROUGH 80DEG)\n"
    "G20 G40 G99\n"
    "G28 U0. W0.\n"
    "T0101\n"
    "G50 S2000\n"
    "G96 S500 M03\n"
    "G00 X1.6 Z.1 M08\n"
    "G71 U1250 R50\n"
    "G71 P100 Q200 U.02 W.005 F.010\n"
    "N100 G00 X.75\n"
    "G01 Z0. F.005\n"
    "X1. Z-.125\n"
    "Z-1.\n"
    "X1.3\n"
    "Z-1.75\n"
    "N200 X1.6\n"
    "G70 P100 Q200\n"
    "G28 U0. W0. M09\n"
    "M30\n"
    "%\n";

const core::Diagnostic* findCode(const std::vector<core::Diagnostic>& list, const char* code) {
  const auto it = std::find_if(list.begin(), list.end(), [code](const core::Diagnostic& d) { return d.code == code; });
  return it == list.end() ? nullptr : &*it;
}

bool openAndWait(MainWindow& w, const QString& path) {
  QSignalSpy loaded(&w, &MainWindow::fileLoaded);
  if (!w.openFile(path)) return false;
  return QTest::qWaitFor([&] { return loaded.count() > 0; }, 30000) &&
         QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000);
}

}  // namespace

class SetupStripTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    klueng::test::freshUserFolders();
    initResources();
  }
  void init() {
    QSettings(QStringLiteral("Klueng"), QStringLiteral("klueng")).clear();
    Language::instance()->setLanguage(QStringLiteral("en"));
  }

  void plainProgramShowsItsGuessedTools() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("O30414.nc"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(kHaas);
    f.close();

    MainWindow w;
    w.resize(1366, 740);
    w.show();
    QVERIFY(openAndWait(w, path));
    w.setDialect(core::gcode::Dialect::Haas);  // its D word (G71 D0.03) is Haas; the bar is inferred there
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    SetupStrip* strip = w.setupStrip();
    QVERIFY(strip);
    QTRY_VERIFY(strip->stations().contains(2));
    QVERIFY(strip->isVisible());
    QCOMPARE(strip->stations(), (QList<int>{1, 2}));
    QVERIFY2(strip->titleText().contains(QStringLiteral("guessed from the program")), qPrintable(strip->titleText()));
    // T02: the library's grooving tool, because of the G75 on line 17.
    const QString t2 = strip->stationText(2);
    QVERIFY2(t2.startsWith(QStringLiteral("T02  Grooving tool, 3 mm — ")), qPrintable(t2));
    QVERIFY2(t2.contains(QStringLiteral("grooving cycle G75 on line 17")), qPrintable(t2));
    QVERIFY(strip->stationLine(2)->toolTip().contains(QStringLiteral("T02 = grooving-3mm")));
    QVERIFY2(strip->stationText(1).startsWith(QStringLiteral("T01  ")), qPrintable(strip->stationText(1)));
    // The bar and why: the stock's note, clickable to Job details.
    QVERIFY2(w.stockSourceText().startsWith(QStringLiteral("Stock Ø")), qPrintable(w.stockSourceText()));
    QVERIFY2(w.stockSourceText().contains(QStringLiteral("inferred from")), qPrintable(w.stockSourceText()));
    QVERIFY(strip->sideText().isEmpty());  // the program stays at X > 0

    // One click on T02 opens Tool Select on station 2.
    int shownTool = 0;
    QTimer::singleShot(0, this, [&] {
      (void)QTest::qWaitFor(
          [] { return qobject_cast<ToolSelectDialog*>(QApplication::activeModalWidget()) != nullptr; }, 10000);
      if (auto* dlg = qobject_cast<ToolSelectDialog*>(QApplication::activeModalWidget())) {
        shownTool = dlg->currentTool();
        dlg->reject();
      }
    });
    QTest::mouseClick(strip->stationLine(2), Qt::LeftButton, {}, QPoint(10, 5));
    QCOMPARE(shownTool, 2);

    // One click on the bar opens Job details.
    bool jobDetails = false;
    QTimer::singleShot(0, this, [&] {
      (void)QTest::qWaitFor(
          [] { return qobject_cast<JobDetailsDialog*>(QApplication::activeModalWidget()) != nullptr; }, 10000);
      if (auto* dlg = qobject_cast<JobDetailsDialog*>(QApplication::activeModalWidget())) {
        jobDetails = true;
        dlg->reject();
      }
    });
    QTest::mouseClick(strip->findChild<SetupLine*>(QStringLiteral("stockSource")), Qt::LeftButton, {}, QPoint(10, 5));
    QVERIFY(jobDetails);

    // In Thai: the library tool's Thai name and the core's Thai note.
    Language::instance()->setLanguage(QStringLiteral("th"));
    QTRY_VERIFY(strip->stationText(2).contains(QStringLiteral("มีดกลึงร่อง 3 มม.")));
    QVERIFY2(strip->stationText(2).contains(QStringLiteral("G75")), qPrintable(strip->stationText(2)));
    QVERIFY2(strip->titleText().contains(QStringLiteral("เดาจาก")), qPrintable(strip->titleText()));
    Language::instance()->setLanguage(QStringLiteral("en"));
  }

  // A program that faces at X < 0: its tools are beyond the centre line (I412), said in the strip.
  void toolSideBeyondTheCentre() {
    MainWindow w;
    w.show();
    QVERIFY(
        openAndWait(w, QStringLiteral(KLUENG_SOURCE_DIR "/tests/real-style/programs/fanuc-11-face-beyond-centre.nc")));
    SetupStrip* strip = w.setupStrip();
    QTRY_VERIFY(!strip->sideText().isEmpty());
    QVERIFY2(strip->sideText().startsWith(QStringLiteral("Tools beyond the centre line, drawn mirrored: ")),
             qPrintable(strip->sideText()));
    QVERIFY2(strip->sideText().contains(QStringLiteral("X < 0")), qPrintable(strip->sideText()));
    QVERIFY(strip->titleText().contains(QStringLiteral("guessed from the program")));
    QVERIFY(strip->stations().contains(1));
  }

  void aStationSetForThisProgramIsRemembered() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("O30414.nc"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(kHaas);
    f.close();
    {
      MainWindow w;
      w.show();
      QVERIFY(openAndWait(w, path));
      QTRY_VERIFY(w.setupStrip()->stations().contains(2));
      QTimer::singleShot(0, this, [&] {
        (void)QTest::qWaitFor(
            [] { return qobject_cast<ToolSelectDialog*>(QApplication::activeModalWidget()) != nullptr; }, 10000);
        if (auto* dlg = qobject_cast<ToolSelectDialog*>(QApplication::activeModalWidget())) {
          dlg->setLibraryTool(2, QStringLiteral("parting-3mm"), true);  // "Only for this program"
          dlg->accept();
        }
      });
      QTest::mouseClick(w.setupStrip()->stationLine(2), Qt::LeftButton, {}, QPoint(10, 5));
      QTRY_VERIFY(w.setupStrip()->stationText(2).startsWith(QStringLiteral("T02  Parting (cut-off) tool, 3 mm — ")));
      QVERIFY(w.isWindowModified());  // an edit of this document, remembered when it is saved (issue 30 item 2)
      QVERIFY(w.save());
    }
    MainWindow again;
    again.show();
    QVERIFY(openAndWait(again, path));
    QTRY_VERIFY(again.setupStrip()->stations().contains(2));
    const QString t2 = again.setupStrip()->stationText(2);
    QVERIFY2(t2.startsWith(QStringLiteral("T02  Parting (cut-off) tool, 3 mm — ")), qPrintable(t2));
    QVERIFY2(t2.contains(QStringLiteral("set for this job")), qPrintable(t2));
  }

  // Issue 26 item 6: the strip says how lengths without a decimal point are
  // read and which word decided; Job details changes it for this file, the
  // check follows, and the choice comes back when the file is opened again.
  void decimalPointReadingShownAndChosen() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("O1234.nc"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(kFanucInch);
    f.close();
    const QString whole = QStringLiteral(
        "Lengths without a decimal point: whole millimetres/inches, as chosen in Job details (X30 = 30 mm)");
    {
      MainWindow w;
      w.resize(1366, 740);
      w.show();
      QVERIFY(openAndWait(w, path));
      SetupStrip* strip = w.setupStrip();
      QTRY_VERIFY(!strip->pointText().isEmpty());
      QCOMPARE(strip->pointText(), QStringLiteral("Lengths without a decimal point: least input increments — U1250 on "
                                                  "line 10 = 0.1250 in (as a standard Fanuc/Haas)"));
      auto* line = strip->findChild<SetupLine*>(QStringLiteral("setupDecimalPoint"));
      QVERIFY(line && line->isVisible());
      QVERIFY2(line->toolTip().startsWith(
                   QStringLiteral("Lengths without a decimal point are read in least input increments")),
               qPrintable(line->toolTip()));
      QVERIFY(strip->titleText().contains(QStringLiteral("guessed from the program")));
      QVERIFY(!findCode(w.diagnosticsPanel()->diagnostics(), "E110"));  // 0.1250 in is a fine depth
      QVERIFY(findCode(w.diagnosticsPanel()->diagnostics(), "I103"));

      // One click on the line opens Job details; choose whole there.
      int shownChoice = -2;
      QTimer::singleShot(0, this, [&] {
        (void)QTest::qWaitFor(
            [] { return qobject_cast<JobDetailsDialog*>(QApplication::activeModalWidget()) != nullptr; }, 10000);
        if (auto* dlg = qobject_cast<JobDetailsDialog*>(QApplication::activeModalWidget())) {
          auto* combo = dlg->findChild<QComboBox*>(QStringLiteral("decimalPoint"));
          if (!combo) return dlg->reject();
          shownChoice = combo->currentIndex();
          combo->setCurrentIndex(1);
          dlg->accept();
        }
      });
      QTest::mouseClick(line, Qt::LeftButton, {}, QPoint(10, 5));
      QCOMPARE(shownChoice, 0);  // "As the program's numbers show"

      // Read whole, the depth of cut is 1250 in: E110 on U1250, line 10.
      QTRY_VERIFY_WITH_TIMEOUT(findCode(w.diagnosticsPanel()->diagnostics(), "E110"), 20000);
      const core::Diagnostic* e110 = findCode(w.diagnosticsPanel()->diagnostics(), "E110");
      QCOMPARE(e110->range.line, 10);
      QCOMPARE(e110->range.column, 5);
      QVERIFY(!findCode(w.diagnosticsPanel()->diagnostics(), "I103"));
      QCOMPARE(strip->pointText(), whole);
      const std::optional<core::io::JobHeader> saved = Settings().jobDetailsFor(path);
      QVERIFY(saved && saved->calculatorInput);
      QCOMPARE(*saved->calculatorInput, true);

      // In Thai: the line is translated, the word and its line kept.
      Language::instance()->setLanguage(QStringLiteral("th"));
      QTRY_VERIFY(strip->pointText().contains(QStringLiteral("จุดทศนิยม")));
      Language::instance()->setLanguage(QStringLiteral("en"));
    }
    // Opened again: read whole from the start, the dialog shows the choice.
    MainWindow again;
    again.show();
    QVERIFY(openAndWait(again, path));
    QTRY_VERIFY_WITH_TIMEOUT(findCode(again.diagnosticsPanel()->diagnostics(), "E110"), 20000);
    QCOMPARE(findCode(again.diagnosticsPanel()->diagnostics(), "E110")->range.line, 10);
    QCOMPARE(again.setupStrip()->pointText(), whole);
    QVERIFY(again.document()->header().calculatorInput.value_or(false));
  }

  // A guessed tool's holder touching the bar (a groove 10 mm deep with the 3 mm
  // grooving blade guessed for T09): the parting blade, as wide and longer, is
  // cut with instead, and the list says so (I413) on its line (issue 26 item 4).
  void guessedToolsHolderIsAWarningInTheList() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("deep.nc"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(
        "%\nO0042 (DEEP GROOVE)\nG21 G40 G99\nT0909\nG97 S600 M03\nG00 X52. Z-20.\nG75 R0.5\n"
        "G75 X30. Z-20. P2000 F0.05\nG00 X60.\nM30\n%\n");
    f.close();
    MainWindow w;
    w.show();
    QVERIFY(openAndWait(w, path));
    w.runController()->setSpeed(RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(w.runController()->state(), RunState::Finished, 20000);
    const auto& list = w.diagnosticsPanel()->diagnostics();
    const auto it = std::find_if(list.begin(), list.end(), [](const core::Diagnostic& d) { return d.code == "I413"; });
    QVERIFY(it != list.end());
    QCOMPARE(it->range.line, 8);
    QCOMPARE(it->severity, core::Severity::Note);
    QCOMPARE(w.runController()->cutSetup().tools.libraryId(9), std::string("parting-3mm"));
  }
};

KLUENG_GUI_TEST(SetupStripTest)
#include "setup_strip_test.moc"

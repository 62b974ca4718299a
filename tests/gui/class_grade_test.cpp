// File > Grade a class against the teacher's drawing (issue 28, item 2): the
// dialog reads a part file with tolerances, grades the folder without a
// reference, shows each student's dimensions, saves the PDF the CLI's --pdf
// writes (read back with pdftotext), in English and Thai.
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QProcess>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include "gui_test_runner.h"

#include "gui/class_grade_dialog.h"
#include "gui/language.h"
#include "klueng/core/machine/setup_files.h"

using namespace klueng;
using namespace klueng::gui;

namespace {

QByteArray readAll(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void write(const QString& path, const QByteArray& text) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  f.write(text);
}

QString pdfText(const QString& pdf) {
  QProcess p;
  p.start(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), pdf, QStringLiteral("-")});
  p.waitForFinished(30000);
  return QString::fromUtf8(p.readAllStandardOutput());
}

const char* kDrawing = R"({
  "stock": { "diameter": 50, "length": 100 },
  "outside": [
    { "cylinder": 30, "length": 20, "chamfer": 3, "tolerance": "h7", "length_tolerance": 0.1 },
    { "cylinder": 40, "length": 20, "round": 2, "tolerance": "js6" },
    { "cylinder": 46, "length": 20, "chamfer": 1, "tolerance": [0, -0.05] }
  ]
})";

}  // namespace

class ClassGradeTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { Language::instance()->setLanguage(QStringLiteral("en")); }

  void gradesAgainstTheDrawingAndSavesThePdf() {
    QTemporaryDir dir;
    const QByteArray sample = readAll(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt"));
    QVERIFY(!sample.isEmpty());
    QDir(dir.path()).mkdir(QStringLiteral("class"));
    write(dir.filePath(QStringLiteral("class/anna.nc")), sample);
    write(dir.filePath(QStringLiteral("class/boon.nc")),
          QByteArray(sample).replace("N380 G03 X40. Z-22.", "N380 G03 X39.98 Z-22."));
    write(dir.filePath(QStringLiteral("class/chai.nc")),
          QByteArray(sample).replace("N410 X46. Z-41.\nN420 Z-60.", "N410 X45.95 Z-41.\nN420 Z-60."));
    write(dir.filePath(QStringLiteral("shaft.json")), kDrawing);

    const core::machine::MachineSetup setup = core::machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
    ClassGradeDialog dialog(setup, core::gcode::Dialect::Fanuc, QString());
    dialog.show();
    dialog.setFolder(dir.filePath(QStringLiteral("class")));
    dialog.setDrawing(dir.filePath(QStringLiteral("shaft.json")));
    QSignalSpy done(&dialog, &ClassGradeDialog::finished);
    dialog.grade();
    QTRY_COMPARE_WITH_TIMEOUT(done.count(), 1, 30000);
    QTableWidget* table = dialog.table();
    QCOMPARE(table->rowCount(), 3);
    QCOMPARE(table->item(0, 0)->text(), QStringLiteral("anna.nc"));
    QCOMPARE(table->item(0, 1)->text(), QStringLiteral("pass"));
    QCOMPARE(table->item(1, 1)->text(), QStringLiteral("fail"));
    QCOMPARE(table->item(1, 7)->text(), QStringLiteral("3 of 4 in tolerance"));
    QCOMPARE(table->item(2, 1)->text(), QStringLiteral("pass"));    // Ø46 exactly at its lower limit
    QVERIFY(table->isColumnHidden(5) && table->isColumnHidden(6));  // no reference: no leftover, no gouge
    QCOMPARE(dialog.summary()->text(), QStringLiteral("3 programs: 2 pass, 1 fail"));
    // The selected student's dimensions.
    QTableWidget* details = dialog.details();
    QVERIFY(details->isVisible());
    table->setCurrentCell(1, 0);
    QCOMPARE(details->rowCount(), 4);
    QCOMPARE(details->item(2, 0)->text(), QStringLiteral("Ø40"));
    QCOMPARE(details->item(2, 1)->text(), QStringLiteral("js6 (±0.008)"));
    QCOMPARE(details->item(2, 2)->text(), QStringLiteral("39.992 – 40.008"));
    QCOMPARE(details->item(2, 3)->text(), QStringLiteral("39.980"));
    QCOMPARE(details->item(2, 4)->text(), QStringLiteral("out of tolerance"));
    table->setCurrentCell(2, 0);
    QCOMPARE(details->item(3, 3)->text(), QStringLiteral("45.950"));
    QCOMPARE(details->item(3, 4)->text(), QStringLiteral("in tolerance"));

    // The CSV and the PDF, as the CLI writes them.
    QVERIFY(dialog.saveCsv(dir.filePath(QStringLiteral("grades.csv"))));
    QVERIFY(readAll(dir.filePath(QStringLiteral("grades.csv")))
                .contains("\nboon.nc,fail,0,,,77.8,,,,,,Ø40,40.000,js6 (±0.008),39.992,40.008,39.980,out\n"));
    QString why;
    QVERIFY2(dialog.savePdf(dir.filePath(QStringLiteral("grades.pdf")), &why), qPrintable(why));
    const QString en = pdfText(dir.filePath(QStringLiteral("grades.pdf")));
    for (const char* s : {"Against the drawing shaft.json (4 toleranced dimensions)", "Inspection against shaft.json",
                          "js6 (±0.008)", "39.980", "3 of 4 in", "In tolerance", "Cutting data"})
      QVERIFY2(en.contains(QString::fromUtf8(s)), s);
    // The drawing is not the PDF's name.
    QVERIFY(!dialog.savePdf(dir.filePath(QStringLiteral("shaft.json")), &why));
    QVERIFY(readAll(dir.filePath(QStringLiteral("shaft.json"))).startsWith("{"));

    // In Thai: the table, the dimensions and the PDF.
    Language::instance()->setLanguage(QStringLiteral("th"));
    QTRY_COMPARE(table->item(1, 1)->text(), QStringLiteral("ไม่ผ่าน"));
    QCOMPARE(dialog.summary()->text(), QStringLiteral("3 โปรแกรม: ผ่าน 2 ไม่ผ่าน 1"));
    table->setCurrentCell(1, 0);
    QCOMPARE(details->item(2, 4)->text(), QStringLiteral("นอกพิกัด"));
    QVERIFY2(dialog.savePdf(dir.filePath(QStringLiteral("th.pdf")), &why), qPrintable(why));
    const QString th = pdfText(dir.filePath(QStringLiteral("th.pdf")));
    QVERIFY2(th.contains(QStringLiteral("shaft.json")) && th.contains(QStringLiteral("39.992 – 40.008")),
             qPrintable(th));
    QVERIFY2(th.contains(QStringLiteral("แบบงาน")), qPrintable(th));
    Language::instance()->setLanguage(QStringLiteral("en"));
  }

  void aDrawingWithoutTolerancesSaysWhatToDo() {
    QTemporaryDir dir;
    QDir(dir.path()).mkdir(QStringLiteral("class"));
    write(dir.filePath(QStringLiteral("class/anna.nc")),
          readAll(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt")));
    write(dir.filePath(QStringLiteral("plain.json")),
          R"({ "stock": { "diameter": 50, "length": 100 }, "outside": [ { "cylinder": 30, "length": 20 } ] })");
    write(dir.filePath(QStringLiteral("broken.json")), "{ \"stock\": ");
    const core::machine::MachineSetup setup = core::machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
    ClassGradeDialog dialog(setup, core::gcode::Dialect::Fanuc, QString());
    dialog.setFolder(dir.filePath(QStringLiteral("class")));
    dialog.setDrawing(dir.filePath(QStringLiteral("plain.json")));
    dialog.grade();
    QVERIFY(!dialog.isGrading());
    QVERIFY2(dialog.summary()->text().contains(QStringLiteral("has no toleranced dimension")),
             qPrintable(dialog.summary()->text()));
    // A general tolerance (ISO 2768-m) gives the drawing's sizes their tolerances.
    dialog.setGeneralTolerance(QStringLiteral("m"));
    QSignalSpy done(&dialog, &ClassGradeDialog::finished);
    dialog.grade();
    QTRY_COMPARE_WITH_TIMEOUT(done.count(), 1, 30000);
    QCOMPARE(dialog.table()->item(0, 7)->text(), QStringLiteral("2 of 2 in tolerance"));
    // A file that is not JSON: its line and column.
    dialog.setDrawing(dir.filePath(QStringLiteral("broken.json")));
    dialog.grade();
    QVERIFY2(dialog.summary()->text().contains(QStringLiteral("F180")) ||
                 dialog.summary()->text().contains(QStringLiteral("line 1")),
             qPrintable(dialog.summary()->text()));
  }
};

KLUENG_GUI_TEST(ClassGradeTest)
#include "class_grade_test.moc"

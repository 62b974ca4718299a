// File > Part designer (issue 14) in the real main window: sample 01's part
// opened from its shipped design matches the drawing within 0.01 mm; an edit
// that makes an undercut says why and writes nothing, undo and redo walk it
// back and forth; a groove added from the Add menu; a tube's design asks for
// its own bar and gets it into Job details; Create program puts the program
// in the editor; the texts in Thai.
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QHeaderView>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QTableView>
#include <QPointer>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

#include "gui_test_runner.h"
#include "fresh_user_folders.h"
#include "gui/code_editor.h"
#include "gui/design_model.h"
#include "gui/document.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/part_designer.h"
#include "gui/resources.h"

using namespace klueng;

namespace {

bool waitLoop(gui::PartDesignerDialog* d) {
  return QTest::qWaitFor([d] { return !d->isRunning() && d->lastLoop(); }, 30000) &&
         QTest::qWaitFor([d] { return !d->isRunning(); }, 30000);
}

// One page of a PDF as text (poppler's pdftotext, as the report tests read them).
QString pdfPage(const QString& pdf, int page) {
  QProcess p;
  p.start(QStringLiteral("pdftotext"), {QStringLiteral("-f"), QString::number(page), QStringLiteral("-l"),
                                        QString::number(page), QStringLiteral("-raw"), pdf, QStringLiteral("-")});
  p.waitForFinished(30000);
  return QString::fromUtf8(p.readAllStandardOutput());
}

QStringList lines(QListWidget* list) {
  QStringList out;
  for (int i = 0; i < list->count(); ++i) out << list->item(i)->text();
  return out;
}

// Sample 01 open in the window, File > Part designer opened on it.
gui::PartDesignerDialog* openDesigner(gui::MainWindow& w) {
  w.resize(1366, 728);
  w.show();
  if (!w.openFile(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt")) ||
      !QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000))
    return nullptr;
  w.action(QStringLiteral("actionPartDesigner"))->trigger();
  return w.findChild<gui::PartDesignerDialog*>();
}

}  // namespace

class PartDesignerTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    klueng::test::freshUserFolders();
    gui::initResources();
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
  }

  void stepShaftMatchesEditsUndoAndCreateProgram() {
    gui::MainWindow w;
    auto* d = openDesigner(w);
    QVERIFY(d);
    QVERIFY(d->isVisible());
    // Sample 01's job: Ø50 x 100 aluminium, from Job details.
    QCOMPARE(d->design().stockDiameter, 50.0);
    QCOMPARE(d->findChild<QComboBox*>(QStringLiteral("designMaterial"))->currentData().toString(),
             QStringLiteral("aluminium"));
    QVERIFY(d->openFile(QStringLiteral(KLUENG_SOURCE_DIR "/resources/parts/step-shaft.json")));
    QVERIFY(waitLoop(d));
    QCOMPARE(d->model()->rowCount(), 3);
    QCOMPARE(d->model()->index(0, gui::DesignTableModel::Edge).data().toString(), QStringLiteral("C3"));
    QCOMPARE(d->model()->index(1, gui::DesignTableModel::Edge).data().toString(), QStringLiteral("R2"));
    QCOMPARE(d->model()->index(1, gui::DesignTableModel::Z).data().toString(), QStringLiteral("-20 … -40"));
    QCOMPARE(d->verdict(), QStringLiteral("The cut part matches the drawing within 0.01 mm."));
    QCOMPARE(lines(d->findings()), QStringList{d->verdict()});
    // Haas, the classic rules and the ROMI in G-code system B (issue 27) too.
    auto* dialect = d->findChild<QComboBox*>(QStringLiteral("designDialect"));
    QCOMPARE(dialect->itemText(3), QStringLiteral("ROMI GL 240M (system B)"));
    for (const int k : {1, 2, 3, 0}) {
      dialect->setCurrentIndex(k);
      QVERIFY(waitLoop(d));
      QVERIFY2(d->lastLoop()->matches(), qPrintable(dialect->currentText()));
    }
    // The bar is the same as the job's: nothing to offer.
    QVERIFY(d->findChild<QPushButton*>(QStringLiteral("designUseFileBar"))->isHidden());

    // Ø26 after Ø30: an undercut. Typed into the table.
    QVERIFY(
        d->model()->setData(d->model()->index(1, gui::DesignTableModel::Diameter), QStringLiteral("26"), Qt::EditRole));
    QVERIFY(waitLoop(d));
    QCOMPARE(d->design().outside[1].diameter, 26.0);
    QCOMPARE(d->verdict(), QStringLiteral("This part cannot be turned this way:"));
    QVERIFY2(lines(d->findings()).join(QLatin1Char('\n')).contains(QStringLiteral("E501  Step 2 (Ø26.) is thinner")),
             qPrintable(lines(d->findings()).join(QLatin1Char('\n'))));
    QVERIFY(!d->findChild<QPushButton*>(QStringLiteral("designCreateProgram"))->isEnabled());
    // Nonsense is refused by the cell: no change, no undo step.
    const int steps = d->undoStack()->count();
    QVERIFY(
        !d->model()->setData(d->model()->index(0, gui::DesignTableModel::Edge), QStringLiteral("X3"), Qt::EditRole));
    QVERIFY(
        !d->model()->setData(d->model()->index(0, gui::DesignTableModel::Length), QStringLiteral("-5"), Qt::EditRole));
    QCOMPARE(d->undoStack()->count(), steps);
    // Undo: Ø40 again and a match; redo: the undercut again.
    d->undoStack()->undo();
    QVERIFY(waitLoop(d));
    QCOMPARE(d->design().outside[1].diameter, 40.0);
    QVERIFY(d->lastLoop()->matches());
    d->undoStack()->redo();
    QVERIFY(waitLoop(d));
    QVERIFY(!d->lastLoop()->program);
    d->undoStack()->undo();
    QVERIFY(waitLoop(d));

    // A groove from the Add menu, then typed to 5 x Ø34 at Z-26 on Ø40.
    auto* add = d->findChild<QToolButton*>(QStringLiteral("designAdd"));
    QAction* groove = nullptr;
    for (QAction* a : add->menu()->actions())
      if (a->text() == QStringLiteral("Groove")) groove = a;
    QVERIFY(groove);
    groove->trigger();
    QCOMPARE(d->model()->rowCount(), 4);
    const int row = 3;
    QCOMPARE(d->model()->index(row, gui::DesignTableModel::Feature).data().toString(), QStringLiteral("Groove"));
    QVERIFY(d->model()->setData(d->model()->index(row, gui::DesignTableModel::Z), QStringLiteral("-26"), Qt::EditRole));
    QVERIFY(
        d->model()->setData(d->model()->index(row, gui::DesignTableModel::Length), QStringLiteral("5"), Qt::EditRole));
    QVERIFY(d->model()->setData(d->model()->index(row, gui::DesignTableModel::Diameter), QStringLiteral("34"),
                                Qt::EditRole));
    QVERIFY(waitLoop(d));
    QVERIFY2(d->lastLoop()->matches(), qPrintable(lines(d->findings()).join(QLatin1Char('\n'))));
    QCOMPARE(d->design().grooves.size(), std::size_t{1});

    // A machine with a slower spindle: the designer's next program clamps there.
    core::machine::MachineSetup slow = core::machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
    slow.machine.maxSpindleRpm = 2000.0;
    d->setMachineSetup(slow);
    QVERIFY(waitLoop(d));
    QVERIFY(QString::fromStdString(d->lastLoop()->program->text).contains(QStringLiteral("G50 S2000 ")));
    QVERIFY(d->lastLoop()->matches());
    // Part off: one undoable step, and still as drawn.
    auto* partOff = d->findChild<QCheckBox*>(QStringLiteral("designPartOff"));
    partOff->setChecked(true);
    QVERIFY(waitLoop(d));
    QVERIFY(d->design().partOff);
    QVERIFY(d->lastLoop()->matches());
    QVERIFY(QString::fromStdString(d->lastLoop()->program->text).contains(QStringLiteral("T0707")));
    d->undoStack()->undo();
    QVERIFY(waitLoop(d));
    QVERIFY(!partOff->isChecked());
    // Create program: a new, unsaved program in the editor, the job's words kept.
    QPushButton* create = d->findChild<QPushButton*>(QStringLiteral("designCreateProgram"));
    QVERIFY(create->isEnabled());
    create->click();
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    const QString program = w.editor()->toPlainText();
    QVERIFY2(program.contains(QStringLiteral("G71 P")), qPrintable(program.left(400)));
    QVERIFY(program.contains(QStringLiteral("T0404")));  // the grooving tool
    QVERIFY(w.document()->isUntitled());
    QVERIFY(w.isWindowModified());
    QCOMPARE(QString::fromStdString(w.document()->header().project), QStringLiteral("Step shaft exercise"));
    QCOMPARE(w.document()->header().diameterMm(), 50.0);
    w.editor()->document()->setModified(false);
    w.document()->restoreHeader({w.document()->header(), {}, false});
    d->close();
  }

  // Issue 28 item 8: closed and opened again in the same session, the designer still
  // holds the design as it was left (it used to start over from the job's bar).
  void reopenedItKeepsTheDesign() {
    gui::MainWindow w;
    auto* d = openDesigner(w);
    QVERIFY(d);
    core::design::PartDesign edited = d->design();
    QVERIFY(!edited.outside.empty());
    edited.outside.front().diameter -= 4.0;
    edited.name = "Reopen check";
    d->setDesign(edited, QStringLiteral("narrower"));
    QPointer<gui::PartDesignerDialog> closed(d);
    d->close();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);  // a dialog deleted on close is gone now
    QVERIFY(closed && !closed->isVisible());
    w.action(QStringLiteral("actionPartDesigner"))->trigger();
    auto* again = w.findChild<gui::PartDesignerDialog*>();
    QVERIFY(again && again->isVisible());
    QCOMPARE(again->design().outside.size(), edited.outside.size());
    QCOMPARE(again->design().outside.front().diameter, edited.outside.front().diameter);
    QCOMPARE(again->design().name, std::string("Reopen check"));
    again->close();
  }

  void aDxfDrawingOpensAsItsFeatures() {
    gui::MainWindow w;
    auto* d = openDesigner(w);
    QVERIFY(d);
    // A pin: Ø30 C2 spigot 25 long on Ø40, 55 in all, as LINE entities with the face at X100.
    QString dxf = QStringLiteral("0\nSECTION\n2\nENTITIES\n");
    const double pin[][4] = {{100, 0, 100, 13}, {100, 13, 98, 15}, {98, 15, 75, 15},
                             {75, 15, 75, 20},  {75, 20, 45, 20},  {45, 20, 45, 0}};
    for (const auto& l : pin)
      dxf +=
          QStringLiteral("0\nLINE\n8\nPART\n10\n%1\n20\n%2\n11\n%3\n21\n%4\n").arg(l[0]).arg(l[1]).arg(l[2]).arg(l[3]);
    dxf += QStringLiteral("0\nENDSEC\n0\nEOF\n");
    const QString path = QDir::temp().filePath(QStringLiteral("klueng-pin.dxf"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(dxf.toUtf8());
    f.close();
    QVERIFY(d->openFile(path));
    QVERIFY(waitLoop(d));
    QCOMPARE(d->model()->rowCount(), 2);
    QCOMPARE(d->model()->index(0, gui::DesignTableModel::Diameter).data().toString(), QStringLiteral("30"));
    QCOMPARE(d->model()->index(0, gui::DesignTableModel::Length).data().toString(), QStringLiteral("25"));
    QCOMPARE(d->model()->index(0, gui::DesignTableModel::Edge).data().toString(), QStringLiteral("C2"));
    QCOMPARE(d->model()->index(1, gui::DesignTableModel::Diameter).data().toString(), QStringLiteral("40"));
    QVERIFY2(d->lastLoop()->matches(), qPrintable(lines(d->findings()).join(QLatin1Char('\n'))));
    // Its bar (Ø45 x 75) differs from the job's: offered, not taken.
    QVERIFY(!d->findChild<QPushButton*>(QStringLiteral("designUseFileBar"))->isHidden());
    QCOMPARE(w.document()->header().diameterMm(), 50.0);
    QFile::remove(path);
  }

  void aTubesDesignGetsItsBarAndTheTextsAreThai() {
    gui::MainWindow w;
    auto* d = openDesigner(w);
    QVERIFY(d);
    QVERIFY(d->openFile(QStringLiteral(KLUENG_SOURCE_DIR "/resources/parts/threaded-bush.json")));
    QVERIFY(waitLoop(d));
    // The job's bar is solid: it is drilled Ø10 first, then bored, and matches too.
    QVERIFY2(d->lastLoop()->matches(), qPrintable(lines(d->findings()).join(QLatin1Char('\n'))));
    QVERIFY(QString::fromStdString(d->lastLoop()->program->text).contains(QStringLiteral("T0606")));
    auto* use = d->findChild<QPushButton*>(QStringLiteral("designUseFileBar"));
    QVERIFY(!use->isHidden());
    use->click();  // into Job details (undoable there), and back into the designer
    QVERIFY(waitLoop(d));
    QCOMPARE(w.document()->header().boreMm(), 16.0);
    QCOMPARE(w.document()->header().lengthMm(), 80.0);
    QVERIFY2(d->lastLoop()->matches(), qPrintable(lines(d->findings()).join(QLatin1Char('\n'))));
    QVERIFY(!QString::fromStdString(d->lastLoop()->program->text).contains(QStringLiteral("T0606")));  // a tube
    // Thai.
    gui::Language::instance()->setLanguage(QStringLiteral("th"));
    QApplication::processEvents();  // the LanguageChange events are posted
    QVERIFY(waitLoop(d));
    QCOMPARE(d->windowTitle(), QStringLiteral("ออกแบบชิ้นงาน"));
    QCOMPARE(d->model()->headerData(0, Qt::Horizontal, Qt::DisplayRole).toString(), QStringLiteral("รูปร่าง"));
    QCOMPARE(d->model()->index(2, gui::DesignTableModel::Feature).data().toString(), QStringLiteral("รูคว้าน"));
    QCOMPARE(lines(d->findings()).value(0), QStringLiteral("ชิ้นงานที่กลึงได้ตรงตามแบบภายใน 0.01 มม."));
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
    // A broken part file: its reasons listed, the design kept.
    const QString broken = QDir::temp().filePath(QStringLiteral("klueng-broken-part.json"));
    QFile f(broken);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{ \"stock\": { \"diameter\": 50,\n \"length\" 80 } }");
    f.close();
    const std::size_t before = d->design().outside.size();
    QVERIFY(!d->openFile(broken));
    QVERIFY(lines(d->findings()).join(QLatin1Char('\n')).contains(QStringLiteral("F180")));
    QCOMPARE(d->design().outside.size(), before);
    QFile::remove(broken);
    w.document()->restoreHeader({w.document()->header(), {}, false});
    w.editor()->document()->setModified(false);
  }

  // Issue 28 item 3: a program made with Create program prints its drawing with the
  // design's own tolerance and finish mark (as `print --design` does); another
  // program opened afterwards prints none of them.
  void theCreatedProgramsDrawingCarriesTheDesignsMarks() {
    gui::MainWindow w;
    auto* d = openDesigner(w);
    QVERIFY(d);
    QVERIFY(d->openFile(QStringLiteral(KLUENG_SOURCE_DIR "/resources/parts/step-shaft.json")));
    QVERIFY(waitLoop(d));
    core::design::PartDesign marked = d->design();
    marked.outside.at(1).tolerance = {0.0, -0.025, "h7"};  // the Ø40 seat
    marked.outside.at(0).roughness = 1.6;                  // the Ø30 spigot
    d->setDesign(marked, QStringLiteral("marks"));
    QVERIFY(waitLoop(d));
    d->findChild<QPushButton*>(QStringLiteral("designCreateProgram"))->click();
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    QTemporaryDir dir;
    const QString pdf = dir.filePath(QStringLiteral("designed.pdf"));
    QVERIFY(w.exportPdf(pdf));
    const QString drawing = pdfPage(pdf, 2);
    QVERIFY2(drawing.contains(QRegularExpression(QStringLiteral("Ø40\\s+h7"))), qPrintable(drawing));
    QVERIFY2(drawing.contains(QStringLiteral("Ra 1.6")), qPrintable(drawing));

    w.editor()->document()->setModified(false);
    w.document()->restoreHeader({w.document()->header(), {}, false});
    QVERIFY(w.openFile(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt")));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    const QString plain = dir.filePath(QStringLiteral("plain.pdf"));
    QVERIFY(w.exportPdf(plain));
    const QString again = pdfPage(plain, 2);
    QVERIFY2(!again.contains(QStringLiteral("h7")) && !again.contains(QStringLiteral("Ra 1.6")), qPrintable(again));
    d->close();
  }
};

KLUENG_GUI_TEST(PartDesignerTest)
#include "part_designer_test.moc"

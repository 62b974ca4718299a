// Issue 11: a new program's first line is numbered 7 — the strip above the
// editor says lines 1-6 are the job header, in English and Thai, and is not
// there for a plain G-code file.
#include <QApplication>
#include <QLabel>
#include <QTemporaryDir>
#include <QTest>

#include "gui_test_runner.h"
#include "fresh_user_folders.h"
#include "gui/code_editor.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/resources.h"

using namespace klueng;

class HeaderStripTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    klueng::test::freshUserFolders();
    gui::initResources();
  }

  void newProgramSaysWhatLinesOneToSixAre() {
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
    gui::MainWindow w;
    w.show();
    auto* strip = w.findChild<QLabel*>(QStringLiteral("headerStrip"));
    QVERIFY(strip);
    QVERIFY(strip->isVisible());
    QVERIFY2(strip->text().startsWith(QStringLiteral("Lines 1–6: job header")), qPrintable(strip->text()));
    QCOMPARE(w.findChild<gui::CodeEditor*>()->firstFileLine(), 7);
    QVERIFY(w.openFile(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt")));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    QVERIFY(strip->text().contains(QStringLiteral("Step shaft exercise, Shaft SS-01, Ø50 × 100 mm")));
    gui::Language::instance()->setLanguage(QStringLiteral("th"));
    QTRY_VERIFY2(strip->text().startsWith(QStringLiteral("บรรทัด 1–6: ส่วนหัวของงาน")), qPrintable(strip->text()));
    // The stock's unit in Thai words too (issue 28 item 8).
    QVERIFY2(strip->text().contains(QStringLiteral("Ø50 × 100 มม.")) && !strip->text().contains(QStringLiteral("mm")),
             qPrintable(strip->text()));
    gui::Language::instance()->setLanguage(QStringLiteral("en"));

    // A plain G-code file has no header: no strip, its first line is 1.
    QTemporaryDir dir;
    const QString plain = dir.filePath(QStringLiteral("plain.nc"));
    QFile f(plain);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("O0001\nG21 G99\nM30\n");
    f.close();
    QVERIFY(w.openFile(plain));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    QVERIFY(!strip->isVisible());
    QCOMPARE(w.findChild<gui::CodeEditor*>()->firstFileLine(), 1);

    // An inch header ("0" before the sizes) is shown as written, in inches (issue 28 item 4).
    const QString pin = dir.filePath(QStringLiteral("pin.txt"));
    QFile g(pin);
    QVERIFY(g.open(QIODevice::WriteOnly));
    g.write("Guide pin\nGP-2\nCRS\n01.75\n03\nShop\nO2010\nG20 G99\nM30\n");
    g.close();
    QVERIFY(w.openFile(pin));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    QVERIFY2(strip->text().contains(QStringLiteral("Guide pin, GP-2, Ø1.75 × 3 in")), qPrintable(strip->text()));
    gui::Language::instance()->setLanguage(QStringLiteral("th"));
    QTRY_VERIFY2(strip->text().contains(QStringLiteral("Ø1.75 × 3 นิ้ว")), qPrintable(strip->text()));
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
  }
};

KLUENG_GUI_TEST(HeaderStripTest)
#include "header_strip_test.moc"

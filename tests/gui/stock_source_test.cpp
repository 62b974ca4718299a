// Where the stock comes from in the GUI (SPEC 2 ext, issue 8): a plain file
// never keeps the previous file's stock; its Job details (with a bore) are
// remembered per file; the window always says where the stock came from.
#include <QApplication>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QRegularExpression>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include "gui_test_runner.h"
#include "fresh_user_folders.h"
#include "gui/document.h"
#include "gui/job_details_dialog.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/resources.h"
#include "gui/settings.h"

using namespace klueng;
using namespace klueng::gui;

namespace {

QString sample(const char* name) { return QStringLiteral(KLUENG_SAMPLES_DIR "/") + QString::fromLatin1(name); }

bool waitIdle(MainWindow& w, int ms = 30000) {
  return QTest::qWaitFor([&w] { return !w.isBusy(); }, ms);
}

// Facing from X34, turning Ø30 to Z-40: the stock inferred is a Ø32 x 60 mm bar.
const char* kPlain =
    "\nO0007\nN10 G21 G99 G97 S800 M03\nN20 T0101\nN30 G00 X34. Z0.\nN40 G01 X-1.6 F0.2\n"
    "N50 G00 Z2.\nN60 X30.\nN70 G01 Z-40.\nN80 G00 X40. Z2.\nN90 G00 X200. Z100.\nN100 M30\n";

QString writePlain(const QTemporaryDir& dir, const char* name) {
  const QString path = dir.filePath(QString::fromLatin1(name));
  QFile f(path);
  if (f.open(QIODevice::WriteOnly)) f.write(kPlain);
  return path;
}

bool openAndWait(MainWindow& w, const QString& path) {
  QSignalSpy loaded(&w, &MainWindow::fileLoaded);
  if (!w.openFile(path)) return false;
  return QTest::qWaitFor([&] { return loaded.count() > 0; }, 30000) && waitIdle(w);
}

}  // namespace

class StockSourceTest : public QObject {
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

  void jobDetailsWithABore() {
    core::io::JobHeader h;
    h.diameter = 118;
    h.length = 80;
    h.bore = 90;
    JobDetailsDialog d(h);
    auto* bore = d.findChild<QDoubleSpinBox*>(QStringLiteral("bore"));
    QVERIFY(bore);
    QCOMPARE(bore->value(), 90.0);
    QCOMPARE(d.header().bore, 90.0);
    QCOMPARE(d.header().boreMm(), 90.0);
    QPushButton* ok = d.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    QVERIFY(ok->isEnabled());
    bore->setValue(120.0);  // not inside the bar
    QVERIFY(!ok->isEnabled());
    auto* problem = d.findChild<QLabel*>(QStringLiteral("jobDetailsProblem"));
    QVERIFY(problem->text().contains(QStringLiteral("smaller than the stock diameter")));
    bore->setValue(0.0);  // a solid bar
    QVERIFY(ok->isEnabled());
    QCOMPARE(d.header().bore, 0.0);
  }

  void plainFileAfterAHeaderFileDoesNotKeepItsStock() {
    QTemporaryDir dir;
    const QString plain = writePlain(dir, "plain.nc");
    MainWindow w;
    w.show();
    QVERIFY(openAndWait(w, sample("01-step-shaft.txt")));  // Ø50 x 100 header
    QCOMPARE(w.document()->header().diameter, 50.0);
    QVERIFY(w.stockSourceText().contains(QStringLiteral("from the file's job header")));
    QVERIFY(openAndWait(w, plain));
    QVERIFY(w.document()->isPlainGcode());
    QCOMPARE(w.document()->header().diameter, 32.0);
    QCOMPARE(w.document()->header().length, 60.0);
    QVERIFY(w.document()->header().stockSource == core::io::StockSource::Inferred);
    QCOMPARE(w.stockSourceText(), QStringLiteral("Stock Ø32 x 60 mm inferred from N30 G00 X34. Z0. (first approach)"));
    QVERIFY(w.findChild<QLabel*>(QStringLiteral("stockSource"))->isVisible());
    // Thai at once.
    Language::instance()->setLanguage(QStringLiteral("th"));
    QTRY_VERIFY(w.stockSourceText().contains(QStringLiteral("ประมาณจาก N30 G00 X34. Z0.")));
  }

  // Issue 28 item 7: the GUI names its own place for the stock, never --stock,
  // in the words of its menus, English and Thai.
  void theDefaultStockNamesTheMenuNotTheFlag() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("nothing.nc"));
    {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write("%\nO0009\nG21 G99\nM30\n%\n");
    }
    MainWindow w;
    w.show();
    QVERIFY(openAndWait(w, path));
    const auto plain = [](const QString& menuText) {
      QString t = menuText;
      t.remove(QRegularExpression(QStringLiteral(" ?\\(&.\\)$")));
      t.remove(QLatin1Char('&'));
      t.remove(QStringLiteral("..."));
      return t.trimmed();
    };
    const auto title = [&](const char* menu) {
      QMenu* m = w.findChild<QMenu*>(QString::fromLatin1(menu));
      return m ? plain(m->title()) : QString();
    };
    const auto menuPath = [&] {
      return title("menuFile") + QStringLiteral(" ▸ ") + plain(w.action(QStringLiteral("actionJobDetails"))->text());
    };
    // The dialect's place, as the I102 note names it (messages_test.cpp).
    const auto dialectPath = [&] { return title("menuToolSetting") + QStringLiteral(" ▸ ") + title("menuDialect"); };
    QCOMPARE(dialectPath(), QStringLiteral("Tool setting ▸ G-code dialect"));
    QCOMPARE(menuPath(), QStringLiteral("File ▸ Job details"));
    QCOMPARE(w.stockSourceText(),
             QStringLiteral("Stock Ø50 x 100 mm is the default: the program has no approach to infer "
                            "it from; set it in File ▸ Job details"));
    Language::instance()->setLanguage(QStringLiteral("th"));
    QCoreApplication::processEvents();
    QCOMPARE(menuPath(), QStringLiteral("แฟ้ม ▸ รายละเอียดงาน"));
    QCOMPARE(dialectPath(), QStringLiteral("ตั้งค่ามีดตัด ▸ ภาษาจีโค้ด"));
    QTRY_VERIFY(w.stockSourceText().endsWith(QStringLiteral("ตั้งค่าได้ที่ แฟ้ม ▸ รายละเอียดงาน")));
    QVERIFY(!w.stockSourceText().contains(QStringLiteral("--")));
    Language::instance()->setLanguage(QStringLiteral("en"));
  }

  void jobDetailsAreRememberedPerFile() {
    QTemporaryDir dir;
    const QString a = writePlain(dir, "a.nc");
    const QString b = writePlain(dir, "b.nc");
    core::io::JobHeader tube;
    tube.diameter = 40;
    tube.length = 70;
    tube.bore = 20;
    Settings().setJobDetailsFor(a, tube);
    MainWindow w;
    w.show();
    QVERIFY(openAndWait(w, a));
    QCOMPARE(w.document()->header().diameter, 40.0);
    QCOMPARE(w.document()->header().bore, 20.0);
    QVERIFY(w.document()->header().stockSource == core::io::StockSource::JobDetails);
    QCOMPARE(w.stockSourceText(), QStringLiteral("Stock Ø40/Ø20 x 70 mm from Job details set for this file"));
    QVERIFY(!w.document()->isHeaderModified());  // a plain file stays plain
    // Another plain file does not get a's Job details.
    QVERIFY(openAndWait(w, b));
    QCOMPARE(w.document()->header().diameter, 32.0);
    QCOMPARE(w.document()->header().bore, 0.0);
  }
};

KLUENG_GUI_TEST(StockSourceTest)
#include "stock_source_test.moc"

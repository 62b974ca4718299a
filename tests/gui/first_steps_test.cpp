// Issue 28 item 8, first minutes: a first start with no file says what to do
// first and opens sample 01 in one click; File ▸ Open starts in the samples;
// once a program has been opened the offer is not made again.
#include <QApplication>
#include <QFileDialog>
#include <QPushButton>
#include <QTest>
#include <QTimer>

#include "gui_test_runner.h"
#include "fresh_user_folders.h"
#include "gui/code_editor.h"
#include "gui/first_steps_bar.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/resources.h"

using namespace klueng;

class FirstStepsTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    klueng::test::freshUserFolders();
    gui::initResources();
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
  }

  void aFirstStartOffersSample01AndOpenStartsInTheSamples() {
    {
      gui::MainWindow w;
      w.resize(1366, 768);
      w.show();
      QVERIFY(QTest::qWaitForWindowExposed(&w));
      gui::FirstStepsBar* bar = w.firstSteps();
      QVERIFY(bar->isVisible());
      QVERIFY2(
          bar->text().contains(QStringLiteral("open a sample program")) && bar->text().contains(QStringLiteral("Go")),
          qPrintable(bar->text()));
      // "All samples…" is File ▸ Open, in the shipped samples the first time.
      QString folder;
      QTimer::singleShot(200, [&folder] {
        if (auto* d = qobject_cast<QFileDialog*>(QApplication::activeModalWidget())) {
          folder = d->directory().absolutePath();
          d->reject();
        }
      });
      w.findChild<QPushButton*>(QStringLiteral("firstStepsBrowse"))->click();
      QCOMPARE(QDir(folder).canonicalPath(), QDir(QStringLiteral(KLUENG_SAMPLES_DIR)).canonicalPath());
      // One click opens sample 01; the offer goes.
      bar->openSampleButton()->click();
      QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
      QTRY_VERIFY(w.editor()->toPlainText().contains(QStringLiteral("N10 G21 G40 G97")));
      QVERIFY(!bar->isVisible());
    }
    // A later start (a file has been opened) goes straight to work.
    gui::MainWindow again;
    again.show();
    QVERIFY(QTest::qWaitForWindowExposed(&again));
    QVERIFY(!again.firstSteps()->isVisible());
  }

  void theOfferSpeaksThai() {
    gui::Language::instance()->setLanguage(QStringLiteral("th"));
    gui::FirstStepsBar bar;
    bar.offer(QStringLiteral(KLUENG_SAMPLES_DIR));
    QVERIFY(bar.isVisible());
    QVERIFY2(bar.text().contains(QStringLiteral("ตัวอย่าง")), qPrintable(bar.text()));
    QVERIFY(bar.openSampleButton()->text().contains(QStringLiteral("ตัวอย่าง")));
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
  }
};

KLUENG_GUI_TEST(FirstStepsTest)
#include "first_steps_test.moc"

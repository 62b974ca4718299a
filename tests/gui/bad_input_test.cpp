// Issue 13, hostile input in the GUI: a 200 MB file, a binary file, one 10 MB line
// and a UTF-16 program each get a clear answer within 2 s and no memory blow-up;
// saving where the program cannot be written says so and keeps the edits.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QFile>
#include <QMessageBox>
#include <QScopeGuard>
#include <QStringConverter>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include "gui_test_runner.h"
#include "fresh_user_folders.h"
#include "gui/code_editor.h"
#include "gui/diagnostics_panel.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/resources.h"

using namespace klueng::gui;

namespace {

// Message boxes are modal: record each one's text and close it so the test goes on.
class MessageCatcher {
 public:
  MessageCatcher() {
    QObject::connect(&timer_, &QTimer::timeout, [this] {
      if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
        texts_ << box->text();
        box->reject();
      }
    });
    timer_.start(20);
  }
  QStringList texts() const { return texts_; }

 private:
  QTimer timer_;
  QStringList texts_;
};

long peakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024;
}

bool writeFile(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

}  // namespace

class BadInputTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    klueng::test::freshUserFolders();
    initResources();
    Language::instance()->setLanguage(QStringLiteral("en"));
  }

  void aHugeFileIsRefusedAtOnce() {
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("huge.nc"));
    {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write("G21 G99\nG00 X40. Z2.\n");
      QVERIFY(f.resize(200LL * 1024 * 1024));  // sparse: 200 MB on paper, nothing on disk
    }
    const QStringList messages = openAndWait(path);
    QCOMPARE(messages.size(), 1);
    QVERIFY2(messages[0].contains(QStringLiteral("F103")) && messages[0].contains(QStringLiteral("64 MB")),
             qPrintable(messages[0]));
    QVERIFY2(messages[0].contains(QStringLiteral("huge.nc")), qPrintable(messages[0]));
  }

  void aBinaryFileIsRefusedWithWhereTheNulIs() {
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("picture.nc"));
    QByteArray bytes = "G21 G99\nG00 X40.";
    bytes.append('\0');
    bytes.append(QByteArray(1 << 20, '\x9c'));
    QVERIFY(writeFile(path, bytes));
    const QStringList messages = openAndWait(path);
    QCOMPARE(messages.size(), 1);
    // Line 2, column 9: the NUL byte right after "G00 X40.".
    QVERIFY2(messages[0].contains(QStringLiteral("F104")) && messages[0].contains(QStringLiteral(":2:9")),
             qPrintable(messages[0]));
  }

  // Issue 29 item 8: opening a pipe (FIFO) waited for a writer for ever, and
  // quitting waited on that load. It is refused at once, in both languages.
  void aPipeIsRefusedAtOnceAndNothingWaitsOnIt() {
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("pipe.nc"));
    QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0644), 0);
    // Should a load open the pipe after all, this writer lets it go when the test ends.
    const auto release = qScopeGuard([&] {
      const int fd = ::open(QFile::encodeName(path).constData(), O_WRONLY | O_NONBLOCK);
      if (fd >= 0) ::close(fd);
    });
    for (const QString& lang : {QStringLiteral("en"), QStringLiteral("th")}) {
      MainWindow w;  // takes the saved language: the test's comes after it
      Language::instance()->setLanguage(lang);
      const QStringList messages = openAndWait(path, &w);
      QCOMPARE(messages.size(), 1);
      QVERIFY2(messages[0].contains(QStringLiteral("pipe.nc")), qPrintable(messages[0]));
      QVERIFY2(
          messages[0].contains(lang == QStringLiteral("en")
                                   ? QStringLiteral("this is a pipe (FIFO), not an ordinary file, so it is not opened")
                                   : QStringLiteral("นี่คือไปป์ (FIFO) ไม่ใช่ไฟล์ธรรมดา จึงไม่เปิด")),
          qPrintable(messages[0]));
    }
    Language::instance()->setLanguage(QStringLiteral("en"));
  }

  void aTenMegabyteLineIsLeftOutAndNamed() {
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("oneline.nc"));
    QVERIFY(writeFile(path, "G21 G99\nG01 X" + QByteArray(10 * 1024 * 1024, '1') + "\nM30\n"));
    MainWindow w;
    const QStringList messages = openAndWait(path, &w);
    QVERIFY2(messages.isEmpty(), qPrintable(messages.join(QLatin1Char('\n'))));
    // The rest of the program is there to read; the long line is an F106 on line 2.
    QCOMPARE(w.editor()->blockCount(), 4);
    bool named = false;
    for (const auto& d : w.diagnosticsPanel()->diagnostics()) named = named || (d.code == "F106" && d.range.line == 2);
    QVERIFY(named);
  }

  void aUtf16ProgramOpensAsText() {
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("windows.nc"));
    const QString text = QStringLiteral("O0001 (กลึงปาด)\nG21 G99\nT0101\nG00 X40. Z2.\nM30\n");
    auto toUtf16 = QStringEncoder(QStringConverter::Utf16LE, QStringConverter::Flag::WriteBom);
    QVERIFY(writeFile(path, toUtf16(text)));
    MainWindow w;
    const QStringList messages = openAndWait(path, &w);
    QVERIFY2(messages.isEmpty(), qPrintable(messages.join(QLatin1Char('\n'))));
    QCOMPARE(w.editor()->toPlainText(), text);
    QCOMPARE(w.diagnosticsPanel()->errorCount(), 0);
  }

  // A folder the user may not write: Save says so, the file keeps its old text and
  // the editor keeps the edit (modified, ready for Save As). As root the save runs as
  // "nobody", so the folder is closed to it as it would be to a student.
  void savingWhereNothingCanBeWrittenKeepsTheEdits() {
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("part.nc"));
    const QByteArray original = "G21 G99\nT0101\nG00 X40. Z2.\nM30\n";
    QVERIFY(writeFile(path, original));
    QFile(path).setPermissions(QFileDevice::ReadOwner | QFileDevice::ReadGroup | QFileDevice::ReadOther);
    QFile(tmp.path())
        .setPermissions(QFileDevice::ReadOwner | QFileDevice::ExeOwner | QFileDevice::ReadGroup |
                        QFileDevice::ExeGroup | QFileDevice::ReadOther | QFileDevice::ExeOther);
    MainWindow w;
    QVERIFY(openAndWait(path, &w).isEmpty());
    QTextCursor c(w.editor()->document());
    c.movePosition(QTextCursor::End);
    c.insertText(QStringLiteral("(my edit)\n"));
    MessageCatcher catcher;
    const bool root = ::geteuid() == 0;
    if (root) QCOMPARE(::seteuid(65534), 0);
    const bool saved = w.save();
    if (root) QCOMPARE(::seteuid(0), 0);
    QVERIFY(!saved);
    QTRY_COMPARE(catcher.texts().size(), 1);
    QVERIFY2(catcher.texts()[0].contains(QStringLiteral("part.nc")), qPrintable(catcher.texts()[0]));
    QVERIFY(w.editor()->document()->isModified());
    QVERIFY(w.editor()->toPlainText().endsWith(QStringLiteral("(my edit)\n")));
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QVERIFY(f.readAll() == original);
  }

  // /dev/full: every write fails with "no space left on device".
  void savingToAFullDiskKeepsTheEdits() {
    if (!QFile::exists(QStringLiteral("/dev/full"))) QFAIL("/dev/full is missing");
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("part.nc"));
    QVERIFY(writeFile(path, "G21 G99\nM30\n"));
    MainWindow w;
    QVERIFY(openAndWait(path, &w).isEmpty());
    w.editor()->insertPlainText(QStringLiteral("(typed)\n"));
    MessageCatcher catcher;
    QVERIFY(!w.saveFile(QStringLiteral("/dev/full")));
    QTRY_COMPARE(catcher.texts().size(), 1);
    QVERIFY(w.editor()->document()->isModified());
  }

 private:
  // Opens the file, waits until the window is idle, and returns the message boxes
  // shown on the way; fails if that took 2 s or more, or the process grew past 1 GB.
  QStringList openAndWait(const QString& path, MainWindow* window = nullptr) {
    std::unique_ptr<MainWindow> own;
    if (!window) {
      own = std::make_unique<MainWindow>();
      window = own.get();
    }
    window->show();
    if (!QTest::qWaitForWindowExposed(window)) return {QStringLiteral("window not exposed")};
    MessageCatcher catcher;
    QElapsedTimer clock;
    clock.start();
    window->openFile(path);
    const bool idle = QTest::qWaitFor([window] { return !window->isBusy(); }, 10000);
    QTest::qWait(50);  // a message box opens from the finished load
    const qint64 ms = clock.elapsed();
    qInfo("%s: %lld ms, peak RSS %ld MB", qPrintable(QFileInfo(path).fileName()), ms, peakRssMb());
    [&] {
      QVERIFY(idle);
      QVERIFY2(ms < 2000, qPrintable(QStringLiteral("%1 ms").arg(ms)));
      QVERIFY2(peakRssMb() < 1024, qPrintable(QStringLiteral("%1 MB").arg(peakRssMb())));
    }();
    return catcher.texts();
  }
};

KLUENG_GUI_TEST(BadInputTest)
#include "bad_input_test.moc"

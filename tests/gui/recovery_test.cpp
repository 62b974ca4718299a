// Autosave and recovery (issue 13): a real Klueng window in a child process
// types into a program, autosaves, and is killed with SIGKILL; the next window
// (same settings and data folders) offers the unsaved work and restores
// exactly the typed text.
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QTextCursor>
#include <cstdio>
#include <cstring>

#include "gui/code_editor.h"
#include "gui/document.h"
#include "gui/document_manager.h"
#include "gui/main_window.h"
#include "gui/recovery_bar.h"
#include "gui/resources.h"
#include "gui/settings.h"

using namespace klueng::gui;

namespace {

constexpr const char* kTyped = "G01 X30. Z-5. F0.15 (typed before the crash)";

QString readAll(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

// The child: open the program, type at its end, wait past the autosave, say so, then hang until killed.
int childMain(int argc, char** argv) {
  QApplication app(argc, argv);
  initResources();
  Settings().setAutosaveSeconds(1);
  MainWindow w;
  w.show();
  w.openFile(QString::fromLocal8Bit(argv[2]));
  if (!QTest::qWaitFor([&] { return !w.isBusy(); }, 20000)) return 3;
  QTextCursor c(w.editor()->document());
  c.movePosition(QTextCursor::End);
  w.editor()->setTextCursor(c);
  QTest::keyClicks(w.editor(), QString::fromLatin1(kTyped));
  QTest::qWait(2500);  // more than the 1 s autosave interval
  std::printf("ready\n");
  std::fflush(stdout);
  for (;;) QTest::qWait(1000);
}

}  // namespace

class RecoveryTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { initResources(); }

  void killedWindowsWorkIsRestoredExactly() {
    QTemporaryDir home;
    QTemporaryDir work;
    const QString program = work.filePath(QStringLiteral("shaft.txt"));
    QVERIFY(QFile::copy(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt"), program));
    QFile(program).setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner);
    const QString original = readAll(program);
    qputenv("XDG_CONFIG_HOME", home.filePath(QStringLiteral("config")).toUtf8());
    qputenv("XDG_DATA_HOME", home.filePath(QStringLiteral("data")).toUtf8());

    QProcess child;
    child.setProgram(QCoreApplication::applicationFilePath());
    child.setArguments({QStringLiteral("--child"), program});
    child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    child.start();
    QVERIFY(child.waitForStarted(10000));
    QVERIFY(QTest::qWaitFor([&] { return child.canReadLine() || child.state() == QProcess::NotRunning; }, 60000));
    QCOMPARE(child.readLine().trimmed(), QByteArray("ready"));
    child.kill();  // SIGKILL: no close event, no destructor
    QVERIFY(child.waitForFinished(10000));
    QCOMPARE(child.exitStatus(), QProcess::CrashExit);
    QCOMPARE(readAll(program), original);  // the file itself was never written

    MainWindow w;
    w.show();
    RecoveryBar* bar = w.recoveryBar();
    QCOMPARE(bar->pending().size(), 1);
    QVERIFY(bar->isVisible());
    QVERIFY2(bar->text().contains(QStringLiteral("shaft.txt")), qPrintable(bar->text()));
    // One line differs from the file: the new last line, where the text was typed.
    const QString where = QStringLiteral("1 line(s) differ from the file, the first at line %1")
                              .arg(original.count(QLatin1Char('\n')) + 1);
    QVERIFY2(bar->text().contains(where), qPrintable(bar->text()));
    const QString oldCopy = bar->pending().front().copyPath;
    bar->restoreFirst();
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy() && w.document()->filePath() == QFileInfo(program).absoluteFilePath(); }, 20000));
    QVERIFY(!bar->isVisible());
    QVERIFY(w.editor()->toPlainText().endsWith(QString::fromLatin1(kTyped)));
    QVERIFY(w.isWindowModified());
    // Exactly the file plus the typed text, header lines aside.
    const QString expected = original;  // ends with a newline: the text went on a new last line
    const QString got = QString::fromStdString(w.document()->formatted(w.editor()->toPlainText()));
    QCOMPARE(got, expected + QString::fromLatin1(kTyped));  // Save writes the editor's text as it is
    QVERIFY(!QFileInfo::exists(oldCopy));  // restoring removes the copy
    // Saving ends it: no copy of this window is left.
    QVERIFY(w.save());
    QVERIFY(w.documentManager()->recovery().orphans().isEmpty());
    QVERIFY(!QFileInfo::exists(QDir(w.documentManager()->recovery().folder())
                                   .filePath(w.documentManager()->sessionId() + QStringLiteral(".nc"))));
  }

  void discardRemovesTheCopy() {
    QTemporaryDir folder;
    Recovery recovery(folder.path());
    QVERIFY(recovery.write(QStringLiteral("a"), "G00 X1.\n", QString(), QStringLiteral("untitled.txt")));
    // Written by this (running) process: not an orphan.
    QVERIFY(recovery.orphans().isEmpty());
    QSettings note(folder.filePath(QStringLiteral("a.ini")), QSettings::IniFormat);
    note.setValue(QStringLiteral("pid"), 0);  // as if its Klueng were gone
    note.sync();
    QCOMPARE(recovery.orphans().size(), 1);
    const RecoveryDifference d = Recovery::difference(recovery.orphans().front());
    QVERIFY(d.fileMissing);
    RecoveryBar bar;
    bar.offer(recovery.orphans());
    QVERIFY(bar.text().contains(QStringLiteral("untitled.txt")));
    QObject::connect(&bar, &RecoveryBar::discardRequested, [&](const RecoveryCopy& c) { recovery.remove(c.id); });
    bar.discardFirst();
    QVERIFY(recovery.orphans().isEmpty());
    QVERIFY(!QFileInfo::exists(folder.filePath(QStringLiteral("a.nc"))));
  }
};

int main(int argc, char** argv) {
  if (argc > 2 && std::strcmp(argv[1], "--child") == 0) return childMain(argc, argv);
  QApplication app(argc, argv);
  RecoveryTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "recovery_test.moc"

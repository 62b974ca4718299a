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
#include <QRandomGenerator>
#include <QSignalSpy>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "gui/code_editor.h"
#include "gui/document.h"
#include "gui/document_manager.h"
#include "gui/language.h"
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

// A Klueng that writes one recovery copy (`--write FOLDER ID ORIGINAL`) and ends, or
// that writes it, says "ready" and runs until its standard input closes (`--hold`).
int copyWriterMain(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  if (argc < 5) return 2;
  const Recovery recovery(QString::fromLocal8Bit(argv[2]));
  QString error;
  if (!recovery.write(QString::fromLocal8Bit(argv[3]), "G00 X10. Z2.\nG01 Z-5. F0.2\n", QString::fromLocal8Bit(argv[4]),
                      QStringLiteral("pin.txt"), &error)) {
    std::fprintf(stderr, "%s\n", qPrintable(error));
    return 1;
  }
  if (std::strcmp(argv[1], "--hold") == 0) {
    std::printf("ready\n");
    std::fflush(stdout);
    char c;
    while (::read(0, &c, 1) > 0) {
    }
  }
  return 0;
}

bool writeCopyInAnotherKlueng(const QString& folder, const QString& id, const QString& original = {}) {
  QProcess child;
  child.setProcessChannelMode(QProcess::ForwardedChannels);
  child.start(QCoreApplication::applicationFilePath(), {QStringLiteral("--write"), folder, id, original});
  return child.waitForFinished(20000) && child.exitStatus() == QProcess::NormalExit && child.exitCode() == 0;
}

char processState(pid_t pid) {
  QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
  if (!stat.open(QIODevice::ReadOnly)) return '?';
  const QByteArray text = stat.readAll();
  const qsizetype paren = text.lastIndexOf(')');
  return paren >= 0 && paren + 2 < text.size() ? text[paren + 2] : '?';
}

QStringList lines(const char* text) { return QString::fromLatin1(text).split(QLatin1Char(' '), Qt::SkipEmptyParts); }

// The length of the longest common subsequence, by the textbook table.
int lcsLength(const QStringList& a, const QStringList& b) {
  std::vector<std::vector<int>> t(static_cast<std::size_t>(a.size() + 1),
                                  std::vector<int>(static_cast<std::size_t>(b.size() + 1), 0));
  for (qsizetype i = 1; i <= a.size(); ++i)
    for (qsizetype j = 1; j <= b.size(); ++j)
      t[i][j] = a[i - 1] == b[j - 1] ? t[i - 1][j - 1] + 1 : std::max(t[i - 1][j], t[i][j - 1]);
  return t[a.size()][b.size()];
}

// `from` with the hunks applied: must be `to`.
QStringList applied(const QStringList& from, const QStringList& to, const QVector<RecoveryHunk>& hunks) {
  QStringList out;
  int at = 0;
  for (const RecoveryHunk& h : hunks) {
    while (at < h.fileStart) out << from[at++];
    for (int i = 0; i < h.copyCount; ++i) out << to[h.copyStart + i];
    at += h.fileCount;
  }
  while (at < from.size()) out << from[at++];
  return out;
}

QString sampleWithLine(const QString& original, int afterLine, const QString& line) {
  QStringList l = original.split(QLatin1Char('\n'));
  l.insert(afterLine, line);
  return l.join(QLatin1Char('\n'));
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
    QVERIFY(QTest::qWaitFor(
        [&] { return !w.isBusy() && w.document()->filePath() == QFileInfo(program).absoluteFilePath(); }, 20000));
    QVERIFY(!bar->isVisible());
    QVERIFY(w.editor()->toPlainText().endsWith(QString::fromLatin1(kTyped)));
    QVERIFY(w.isWindowModified());
    // Exactly the file plus the typed text, header lines aside.
    const QString expected = original;  // ends with a newline: the text went on a new last line
    const QString got = QString::fromStdString(w.document()->formatted(w.editor()->toPlainText()));
    QCOMPARE(got, expected + QString::fromLatin1(kTyped));  // Save writes the editor's text as it is
    QVERIFY(!QFileInfo::exists(oldCopy));                   // restoring removes the copy
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
    // Written by this (running) process: not an orphan, whatever its note says.
    QVERIFY(recovery.orphans().isEmpty());
    QSettings note(folder.filePath(QStringLiteral("a.ini")), QSettings::IniFormat);
    note.setValue(QStringLiteral("pid"), 0);
    note.sync();
    QVERIFY(recovery.orphans().isEmpty());
    recovery.remove(QStringLiteral("a"));
    QVERIFY(!QFileInfo::exists(folder.filePath(QStringLiteral("a.lock"))));
    // A copy whose Klueng has ended.
    QVERIFY(writeCopyInAnotherKlueng(folder.path(), QStringLiteral("b")));
    QCOMPARE(recovery.orphans().size(), 1);
    const RecoveryDifference d = Recovery::difference(recovery.orphans().front());
    QVERIFY(d.fileMissing);
    QCOMPARE(d.linesDiffering, 2);
    RecoveryBar bar;
    bar.offer(recovery.orphans());
    QVERIFY(bar.text().contains(QStringLiteral("pin.txt")));
    QVERIFY2(bar.text().contains(QStringLiteral("2 line(s) of unsaved work")), qPrintable(bar.text()));
    QObject::connect(&bar, &RecoveryBar::discardRequested, [&](const RecoveryCopy& c) { recovery.remove(c.id); });
    bar.discardFirst();
    QVERIFY(recovery.orphans().isEmpty());
    QCOMPARE(QDir(folder.path()).entryList(QDir::Files), QStringList());  // copy, note and lock gone
  }

  // Issue 29 item 11: the editor that wrote a copy has died but is not reaped yet
  // (a zombie: its process id still answers kill(pid, 0)). Its copy is offered; while
  // it ran, it was not.
  void aDeadEditorsZombieDoesNotHideItsCopy() {
    QTemporaryDir folder;
    const Recovery recovery(folder.path());
    int in[2], out[2];
    QCOMPARE(::pipe(in), 0);
    QCOMPARE(::pipe(out), 0);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in[0], 0);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_addclose(&actions, in[1]);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    const QByteArray self = QCoreApplication::applicationFilePath().toLocal8Bit();
    const QByteArray dir = folder.path().toLocal8Bit();
    char* argv[] = {const_cast<char*>(self.constData()),
                    const_cast<char*>("--hold"),
                    const_cast<char*>(dir.constData()),
                    const_cast<char*>("z"),
                    const_cast<char*>(""),
                    nullptr};
    pid_t pid = 0;
    QCOMPARE(::posix_spawn(&pid, self.constData(), &actions, nullptr, argv, environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    ::close(in[0]);
    ::close(out[1]);
    char ready[6] = {};
    QCOMPARE(::read(out[0], ready, 6), ssize_t(6));
    QCOMPARE(QByteArray(ready, 6), QByteArray("ready\n"));
    QVERIFY(recovery.orphans().isEmpty());                                      // its Klueng runs: a live copy
    ::close(in[1]);                                                             // the editor ends ...
    QVERIFY(QTest::qWaitFor([&] { return processState(pid) == 'Z'; }, 10000));  // ... and is not reaped
    QCOMPARE(::kill(pid, 0), 0);
    const QVector<RecoveryCopy> orphans = recovery.orphans();
    int status = 0;
    QCOMPARE(::waitpid(pid, &status, 0), pid);
    ::close(out[0]);
    QCOMPARE(orphans.size(), 1);
    QCOMPARE(orphans.front().id, QStringLiteral("z"));
    QCOMPARE(orphans.front().pid, qint64(pid));
  }

  // After a reboot the dead editor's process id may belong to another program: the
  // copy is still offered.
  void aProcessIdInUseAgainDoesNotHideACopy() {
    QTemporaryDir folder;
    const Recovery recovery(folder.path());
    QVERIFY(writeCopyInAnotherKlueng(folder.path(), QStringLiteral("r")));
    QSettings note(folder.filePath(QStringLiteral("r.ini")), QSettings::IniFormat);
    note.setValue(QStringLiteral("pid"), 1);  // init: always running
    note.sync();
    QCOMPARE(::kill(1, 0) == 0 || errno == EPERM, true);
    QCOMPARE(recovery.orphans().size(), 1);
    QVERIFY(writeCopyInAnotherKlueng(folder.path(), QStringLiteral("s")));
    QSettings mine(folder.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    mine.setValue(QStringLiteral("pid"), static_cast<qint64>(QCoreApplication::applicationPid()));  // even this one
    mine.sync();
    QCOMPARE(recovery.orphans().size(), 2);
  }

  // A copy from before the lock (no .lock file) still goes by its process id.
  void aCopyWithoutALockGoesByItsProcessId() {
    QTemporaryDir folder;
    const Recovery recovery(folder.path());
    QVERIFY(writeCopyInAnotherKlueng(folder.path(), QStringLiteral("old")));
    QVERIFY(QFile::remove(folder.filePath(QStringLiteral("old.lock"))));
    QSettings note(folder.filePath(QStringLiteral("old.ini")), QSettings::IniFormat);
    note.setValue(QStringLiteral("pid"), static_cast<qint64>(QCoreApplication::applicationPid()));
    note.sync();
    QVERIFY(recovery.orphans().isEmpty());
    note.setValue(QStringLiteral("pid"), 0);
    note.sync();
    QCOMPARE(recovery.orphans().size(), 1);
  }

  // "Autosave failed: <folder>" said where, not why.
  void aFailedAutosaveSaysWhy() {
    QTemporaryDir home;
    QFile blocker(home.filePath(QStringLiteral("klueng")));
    QVERIFY(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    const QString folder = home.filePath(QStringLiteral("klueng/recovery"));
    const Recovery recovery(folder);
    QString error;
    QVERIFY(!recovery.write(QStringLiteral("a"), "G00 X1.\n", QString(), QStringLiteral("untitled.txt"), &error));
    QCOMPARE(error, QStringLiteral("cannot create the recovery folder %1: %2 is a file, not a folder")
                        .arg(folder, home.filePath(QStringLiteral("klueng"))));
    Language::instance()->setLanguage(QStringLiteral("th"));
    QVERIFY(!recovery.write(QStringLiteral("a"), "G00 X1.\n", QString(), QStringLiteral("untitled.txt"), &error));
    Language::instance()->setLanguage(QStringLiteral("en"));
    QCOMPARE(error, QStringLiteral("สร้างโฟลเดอร์กู้คืน %1 ไม่ได้: %2 เป็นไฟล์ ไม่ใช่โฟลเดอร์")
                        .arg(folder, home.filePath(QStringLiteral("klueng"))));

    // The window's autosave reports the same reason.
    const QByteArray oldData = qgetenv("XDG_DATA_HOME");
    qputenv("XDG_DATA_HOME", home.path().toUtf8());
    {
      MainWindow w;
      QSignalSpy failed(w.documentManager(), &DocumentManager::autosaveFailed);
      QTest::keyClicks(w.editor(), QStringLiteral("G00 X1."));
      w.documentManager()->autosave();
      QCOMPARE(failed.size(), 1);
      QCOMPARE(failed.front().front().toString(),
               QStringLiteral("cannot create the recovery folder %1: %2 is a file, not a folder")
                   .arg(folder, home.filePath(QStringLiteral("klueng"))));
    }
    qputenv("XDG_DATA_HOME", oldData);
  }

  // One line typed into the middle of the program is one line that differs, where it was typed.
  void oneInsertedLineIsOneLineThatDiffers() {
    QTemporaryDir work;
    const QString program = work.filePath(QStringLiteral("shaft.txt"));
    QVERIFY(QFile::copy(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt"), program));
    QFile(program).setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner);
    const QString original = readAll(program);
    QVERIFY(original.count(QLatin1Char('\n')) > 40);
    QTemporaryDir folder;
    const Recovery recovery(folder.path());
    QVERIFY(writeCopyInAnotherKlueng(folder.path(), QStringLiteral("c"), program));
    const QString edited = sampleWithLine(original, 10, QStringLiteral("G04 P1. (typed)"));
    {
      QFile copy(folder.filePath(QStringLiteral("c.nc")));
      QVERIFY(copy.open(QIODevice::WriteOnly | QIODevice::Truncate));
      copy.write(edited.toUtf8());
    }
    QCOMPARE(recovery.orphans().size(), 1);
    const RecoveryDifference d = Recovery::difference(recovery.orphans().front());
    QCOMPARE(d.linesDiffering, 1);
    QCOMPARE(d.firstLine, 11);
    RecoveryBar bar;
    bar.offer(recovery.orphans());
    QVERIFY2(bar.text().contains(QStringLiteral(": 1 line(s) differ from the file, the first at line 11.")),
             qPrintable(bar.text()));
    QCOMPARE(bar.comparison(), QStringLiteral("line 11\n  + G04 P1. (typed)"));

    // A changed line and a deleted one further down: 2 lines, each shown once.
    QStringList l = edited.split(QLatin1Char('\n'));
    const QString changedFrom = l[20];
    l[20] = QStringLiteral("G01 X99.");
    const QString deleted = l[30];
    l.removeAt(30);
    {
      QFile copy(folder.filePath(QStringLiteral("c.nc")));
      QVERIFY(copy.open(QIODevice::WriteOnly | QIODevice::Truncate));
      copy.write(l.join(QLatin1Char('\n')).toUtf8());
    }
    const RecoveryDifference d2 = Recovery::difference(recovery.orphans().front());
    QCOMPARE(d2.linesDiffering, 3);
    QCOMPARE(d2.hunks.size(), 3);
    bar.offer(recovery.orphans());
    QCOMPARE(bar.comparison(),
             QStringLiteral("line 11\n  + G04 P1. (typed)\nline 21\n  - %1\n  + G01 X99.\nline 31\n  - %2")
                 .arg(changedFrom, deleted));
  }

  // The line diff is a shortest edit: checked against the longest common
  // subsequence on random texts, and applying it gives the copy.
  void theLineDiffIsAShortestEdit() {
    // Myers' example: ABCABBA -> CBABAC takes 5 lines removed or added.
    const QStringList a = lines("A B C A B B A"), b = lines("C B A B A C");
    const QVector<RecoveryHunk> h = diffLines(a, b);
    int edits = 0;
    for (const RecoveryHunk& x : h) edits += x.fileCount + x.copyCount;
    QCOMPARE(edits, 5);
    QCOMPARE(applied(a, b, h), b);
    QVERIFY(diffLines(a, a).isEmpty());
    QRandomGenerator random(29);
    for (int round = 0; round < 300; ++round) {
      QStringList x, y;
      const int n = static_cast<int>(random.bounded(0, 30)), m = static_cast<int>(random.bounded(0, 30));
      for (int i = 0; i < n; ++i) x << QString(QChar(u'a' + random.bounded(0, 4)));
      for (int i = 0; i < m; ++i) y << QString(QChar(u'a' + random.bounded(0, 4)));
      const QVector<RecoveryHunk> hunks = diffLines(x, y);
      int count = 0;
      for (const RecoveryHunk& k : hunks) count += k.fileCount + k.copyCount;
      QCOMPARE(count, int(n + m - 2 * lcsLength(x, y)));
      QCOMPARE(applied(x, y, hunks), y);
    }
    // Past the limit the middle that differs is one hunk, still exact at both ends.
    const QVector<RecoveryHunk> capped = diffLines(lines("s a b c d e"), lines("s f g h i e"), 2);
    QCOMPARE(capped.size(), 1);
    QCOMPARE(capped.front().fileStart, 1);
    QCOMPARE(capped.front().fileCount, 4);
    QCOMPARE(capped.front().copyCount, 4);
  }
};

int main(int argc, char** argv) {
  if (argc > 2 && std::strcmp(argv[1], "--child") == 0) return childMain(argc, argv);
  if (argc > 2 && (std::strcmp(argv[1], "--write") == 0 || std::strcmp(argv[1], "--hold") == 0))
    return copyWriterMain(argc, argv);
  QApplication app(argc, argv);
  RecoveryTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "recovery_test.moc"

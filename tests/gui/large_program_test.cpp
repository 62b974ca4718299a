// A 100,000-line program opens and is checked without freezing the window:
// the file is read and checked off the GUI thread. The test asserts behaviour
// (all lines in the editor, the checker's verdict, the window kept serving its
// event loop) and prints the longest event-loop stall as a measurement.
#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTimer>

#include "gui_test_runner.h"
#include "fresh_user_folders.h"
#include "../../bench/program_generator.h"
#include "gui/code_editor.h"
#include "gui/diagnostics_panel.h"
#include "gui/gcode_highlighter.h"
#include "gui/main_window.h"
#include "gui/resources.h"

using namespace klueng::gui;

class LargeProgramTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    klueng::test::freshUserFolders();
    initResources();
  }

  // Issue 13: saving while a big file is still going into the editor once wrote
  // only the part loaded so far (3.96 MB -> 59 KB) and marked it unmodified.
  void savingWhileTheFileStillFillsTheEditorSavesAllOfIt() {
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("big.txt"));
    const QByteArray original = QByteArray::fromStdString(klueng::bench::ProgramGenerator::generate(200000));
    {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(original);
    }
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(path));
    // Wait until the first chunks are in, but not all of them.
    QVERIFY(QTest::qWaitFor([&w] { return w.editor()->blockCount() > 1; }, 60000));
    QVERIFY(w.editor()->blockCount() < 200000);
    w.action(QStringLiteral("actionSave"))->trigger();
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.size(), original.size());
    QVERIFY(f.readAll() == original);
    QVERIFY(!w.editor()->document()->isModified());
    QVERIFY(w.editor()->blockCount() >= 200000);
  }

  // Issue 13: a line over 4096 characters is left out of the editor (F106);
  // an edit plus Save used to delete it from disk. Saving over it is refused now.
  void aLineTooLongToEditIsNeverSavedAway() {
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("long.nc"));
    const QByteArray original = "O0001\nG21 G99\n(" + QByteArray(5000, 'x') + ")\nG00 X50. Z5.\nM30\n";
    {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(original);
    }
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(path));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    QTextCursor c(w.editor()->document());
    c.movePosition(QTextCursor::End);
    c.insertText(QStringLiteral("(edited)\n"));
    QVERIFY(w.editor()->document()->isModified());
    bool warned = false;
    QTimer::singleShot(200, [&warned] {
      if (QWidget* box = QApplication::activeModalWidget()) {
        warned = true;
        box->close();
      }
    });
    QVERIFY(!w.save());
    QVERIFY(warned);
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QVERIFY(f.readAll() == original);
    QVERIFY(w.editor()->document()->isModified());  // the edit is still there to Save As
  }

  void hundredThousandLinesOpenAndCheckInTheBackground() {
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("big.txt"));
    {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(QByteArray::fromStdString(klueng::bench::ProgramGenerator::generate(100000)));
    }
    MainWindow w;
    w.resize(1280, 800);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 10000));

    // A 5 ms heartbeat: the largest gap between beats is the longest stall.
    QElapsedTimer clock;
    qint64 last = 0;
    qint64 longest = 0;
    int beats = 0;
    QTimer heartbeat;
    heartbeat.setInterval(5);
    connect(&heartbeat, &QTimer::timeout, this, [&] {
      const qint64 now = clock.elapsed();
      longest = std::max(longest, now - last);
      last = now;
      ++beats;
    });
    clock.start();
    heartbeat.start();
    QVERIFY(w.openFile(path));
    QVERIFY(w.isBusy());
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 120000));
    const qint64 total = clock.elapsed();
    heartbeat.stop();

    QVERIFY(w.editor()->blockCount() >= 100001);
    QCOMPARE(w.editor()->firstFileLine(), 7);  // the generator writes the 6-line header
    QVERIFY(w.editor()->document()->findBlockByNumber(1).text().startsWith(QStringLiteral("N1 ")));
    QCOMPARE(w.diagnosticsPanel()->errorCount(), 0);  // the generator writes a valid program
    QVERIFY(beats > 10);                              // the event loop kept running while loading and checking
    qInfo("100k-line open + check: %lld ms total, %d heartbeats, longest event-loop stall %lld ms", total, beats,
          longest);

    // Typing at the end re-checks in the background too.
    last = clock.elapsed();
    longest = 0;
    heartbeat.start();
    QTextCursor c(w.editor()->document());
    c.movePosition(QTextCursor::End);
    w.editor()->setTextCursor(c);
    QTest::keyClicks(w.editor(), QStringLiteral("G01 X20. Y1."));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 60000));
    heartbeat.stop();
    QVERIFY(w.diagnosticsPanel()->errorCount() >= 1);
    qInfo("100k-line re-check after typing: longest event-loop stall %lld ms", longest);
  }

  // Issue 29 item 8: a line's colours live in its own QTextLayout (hundreds of bytes);
  // colouring all of a 2,000,000-line program at load held 0.7 GB. A long program is
  // coloured where the editor draws it: lines scrolled to, edited or underlined there.
  void aLongProgramIsColouredWhereItIsShown() {
    using K = GcodeHighlighter::Kind;
    CodeEditor editor;
    editor.resize(600, 400);
    QStringList lines;
    for (int i = 0; i < 60000; ++i)
      lines << QStringLiteral("N%1 G01 X%2. Z-5. F0.2").arg(i % 9999 + 1).arg(20 + i % 30);
    editor.setPlainText(lines.join(QLatin1Char('\n')));
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    editor.viewport()->repaint();
    const QTextDocument* doc = editor.document();
    const GcodeHighlighter* h = editor.highlighter();
    const auto colourAt = [](const QTextBlock& b, int pos) {
      for (const QTextLayout::FormatRange& r : b.layout()->formats())
        if (pos >= r.start && pos < r.start + r.length) return r.format.foreground().color();
      return QColor();
    };
    const auto underlinedAt = [](const QTextBlock& b, int pos) {
      for (const QTextLayout::FormatRange& r : b.layout()->formats())
        if (pos >= r.start && pos < r.start + r.length)
          return r.format.underlineStyle() == QTextCharFormat::WaveUnderline;
      return false;
    };
    const QTextBlock first = doc->firstBlock();
    QCOMPARE(colourAt(first, static_cast<int>(first.text().indexOf(u'G'))), h->format(K::GCode).foreground().color());
    int coloured = 0;
    for (QTextBlock b = doc->begin(); b.isValid(); b = b.next()) coloured += GcodeHighlighter::isColoured(b) ? 1 : 0;
    QVERIFY2(coloured >= 10 && coloured <= 200, qPrintable(QString::number(coloured)));

    QTextBlock far = doc->findBlockByNumber(50000);
    QVERIFY(!GcodeHighlighter::isColoured(far));
    QVERIFY(far.layout()->formats().isEmpty());
    editor.goToFileLine(50001);
    editor.viewport()->repaint();
    QVERIFY(GcodeHighlighter::isColoured(far));
    const int x = static_cast<int>(far.text().indexOf(u'X'));
    QCOMPARE(colourAt(far, x), h->format(K::Axis).foreground().color());

    // An underline on a line on screen shows at once, one off screen once it is drawn.
    klueng::core::Diagnostic shown;
    shown.code = "E201";
    shown.range.line = 50001;
    shown.range.column = x + 1;
    shown.range.length = 3;
    klueng::core::Diagnostic hidden = shown;
    hidden.range.line = 20001;
    editor.setDiagnostics({shown, hidden});
    QVERIFY(underlinedAt(far, x));
    QVERIFY(!underlinedAt(far, x + 3));
    const QTextBlock other = doc->findBlockByNumber(20000);
    QVERIFY(!GcodeHighlighter::isColoured(other));
    editor.goToFileLine(20001);
    editor.viewport()->repaint();
    QVERIFY(underlinedAt(other, static_cast<int>(other.text().indexOf(u'X'))));

    // Typing on a line on screen colours it again where its words now are.
    QTextCursor c(other);
    c.insertText(QStringLiteral("M03 "));
    QCOMPARE(colourAt(other, 0), h->format(K::MCode).foreground().color());
    QCOMPARE(colourAt(other, static_cast<int>(other.text().indexOf(u'G'))), h->format(K::GCode).foreground().color());
  }
};

KLUENG_GUI_TEST(LargeProgramTest)
#include "large_program_test.moc"

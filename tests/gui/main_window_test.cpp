// The main window as a student uses it: open, see errors underlined and
// listed, jump to them, save, switch language, answer the unsaved-changes
// prompt, run a program that raises an alarm. Offscreen platform (QTest).
#include <QAction>
#include <QRegularExpression>
#include <QApplication>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QSplitter>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QScrollBar>
#include <QListWidget>
#include <QLineEdit>
#include <QTest>
#include <QTextDocument>
#include <QUrl>
#include <QTextBlock>
#include <QTimer>
#include <QLabel>
#include <QProgressBar>
#include <QStatusBar>

#include "gui_test_runner.h"
#include "fresh_user_folders.h"
#include "gui/code_editor.h"
#include "klueng/core/diagnostic_codes.h"
#include "gui/diagnostics_panel.h"
#include "gui/find_dialog.h"
#include "gui/gcode_highlighter.h"
#include "gui/help_contents.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/output_view.h"
#include "render/lathe_painters.h"
#include "gui/status_panel.h"
#include "gui/class_grade_dialog.h"
#include <QTableWidget>
#include <QTemporaryDir>
#include "gui/explain_bar.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/help/explain.h"
#include "gui/resources.h"
#include "gui/run_controller.h"
#include "gui/settings.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/messages.h"

using namespace klueng;
using namespace klueng::gui;

namespace {

QString sample(const char* name) { return QStringLiteral(KLUENG_SAMPLES_DIR "/") + QString::fromLatin1(name); }

QByteArray readAll(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool waitIdle(MainWindow& w, int ms = 30000) {
  return QTest::qWaitFor([&w] { return !w.isBusy(); }, ms);
}

// Answers the next modal message box by clicking the button with this object
// name. Polls from the event loop (never blocks), so it also works when the box
// opens inside another wait.
void answerNextMessageBox(const QString& buttonName, QString* seenBoxName = nullptr) {
  auto* poll = new QTimer(qApp);
  auto* waited = new int(0);
  poll->setInterval(20);
  QObject::connect(poll, &QTimer::timeout, poll, [poll, waited, buttonName, seenBoxName] {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    QPushButton* button = box ? box->findChild<QPushButton*>(buttonName) : nullptr;
    if (!button && ++*waited < 1000) return;  // up to 20 s
    poll->stop();
    poll->deleteLater();
    delete waited;
    if (!button) return;
    if (seenBoxName) *seenBoxName = box->objectName();
    button->click();
  });
  poll->start();
}

// The underline colour formats the highlighter put on block `block` at UTF-16 index `pos`.
bool hasWavyUnderlineAt(const QTextBlock& block, int pos) {
  for (const QTextLayout::FormatRange& r : block.layout()->formats())
    if (pos >= r.start && pos < r.start + r.length && r.format.underlineStyle() == QTextCharFormat::WaveUnderline)
      return true;
  return false;
}

}  // namespace

class MainWindowTest : public QObject {
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

  void opensSample01WithoutErrors() {
    MainWindow w;
    w.show();
    QSignalSpy loaded(&w, &MainWindow::fileLoaded);
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    QVERIFY(waitIdle(w));
    QCOMPARE(loaded.count(), 1);
    QCOMPARE(w.windowTitle(), QStringLiteral("Klueng : 01-step-shaft.txt[*]"));
    QVERIFY(!w.isWindowModified());
    // The editor shows the G-code part only; its first line is file line 7.
    QCOMPARE(w.editor()->firstFileLine(), 7);
    QCOMPARE(w.editor()->document()->firstBlock().text(), QStringLiteral("O0001"));
    // File line 54, the last one, is editor block 47.
    QCOMPARE(w.editor()->document()->findBlockByNumber(54 - 7).text(), QStringLiteral("N460 M30"));
    QCOMPARE(w.document()->header().project, std::string("Step shaft exercise"));
    QCOMPARE(w.document()->header().diameterMm(), 50.0);
    QCOMPARE(w.document()->header().lengthMm(), 100.0);
    QCOMPARE(w.diagnosticsPanel()->errorCount(), 0);
  }

  void grammarErrorsAreUnderlinedAndListed() {
    MainWindow w;
    w.setDialect(core::gcode::Dialect::Classic);
    w.show();
    QVERIFY(w.openFile(sample("04-grammar-errors.txt")));
    QVERIFY(waitIdle(w));
    DiagnosticsPanel* panel = w.diagnosticsPanel();
    QVERIFY(panel->errorCount() >= 15);
    // "N30 G01 X30. Y5. F0.2" is file line 11; Y (column 14) is not a lathe word.
    const auto& diags = panel->diagnostics();
    auto y = std::find_if(diags.begin(), diags.end(),
                          [](const core::Diagnostic& d) { return d.range.line == 11 && d.range.column == 14; });
    QVERIFY(y != diags.end());
    QCOMPARE(y->severity, core::Severity::Error);
    const QTextBlock block = w.editor()->document()->findBlockByNumber(11 - 7);
    QCOMPARE(block.text().mid(13, 3), QStringLiteral("Y5."));
    QVERIFY(hasWavyUnderlineAt(block, 13));
    QVERIFY(!hasWavyUnderlineAt(block, 0));  // N30 itself is fine
    // The panel shows the message in the UI language, and a click jumps to the word.
    const int row = static_cast<int>(y - diags.begin());
    const QModelIndex msg = panel->model()->index(row, DiagnosticsModel::MessageColumn);
    QCOMPARE(msg.data().toString(), QString::fromStdString(core::formatMessage(*y, core::Lang::En)));
    QCOMPARE(panel->model()->index(row, DiagnosticsModel::LineColumn).data().toInt(), 11);
    QTableView* view = panel->view();
    view->scrollTo(msg);
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->visualRect(msg).center());
    QCOMPARE(w.editor()->cursorFileLine(), 11);
    QCOMPARE(w.editor()->textCursor().positionInBlock(), 13);
    // Every diagnostic on an editor line is underlined at its column.
    for (const auto& d : diags) {
      if (d.range.line < 7 || d.range.column < 1) continue;
      const QTextBlock b = w.editor()->document()->findBlockByNumber(d.range.line - 7);
      QVERIFY2(
          hasWavyUnderlineAt(b, std::min<int>(d.range.column - 1, b.length() - 2)),
          qPrintable(
              QStringLiteral("%1 at %2:%3").arg(QString::fromStdString(d.code)).arg(d.range.line).arg(d.range.column)));
    }
  }

  void typingAnErrorUnderlinesItAfterThePause() {
    MainWindow w;
    w.show();
    QVERIFY(waitIdle(w));
    w.editor()->insertPlainText(QStringLiteral("G01 X20. Z-5. F0.2\n"));
    QTest::keyClicks(w.editor(), QStringLiteral("G01 X20. Q"));
    // Debounced: nothing is checked while typing goes on ...
    QVERIFY(w.isBusy());
    QVERIFY(waitIdle(w));
    // ... then the lone letter Q on editor line 2 (file line 8, column 10) is found.
    const auto& diags = w.diagnostics();
    auto it = std::find_if(diags.begin(), diags.end(), [](const core::Diagnostic& d) {
      return d.range.line == 8 && d.range.column == 10 && d.severity == core::Severity::Error;
    });
    QVERIFY(it != diags.end());
    QVERIFY(hasWavyUnderlineAt(w.editor()->document()->findBlockByNumber(1), 9));
    QVERIFY(w.isWindowModified());
    QVERIFY(w.windowTitle().startsWith(QStringLiteral("Klueng : untitled.txt")));
    // Fixing it clears the underline.
    QTest::keyClick(w.editor(), Qt::Key_Backspace);
    QVERIFY(waitIdle(w));
    QVERIFY(!hasWavyUnderlineAt(w.editor()->document()->findBlockByNumber(1), 9));
  }

  // Issue 11: a G01 with no feed is reported while typing, not only when the program runs.
  void aFeedMoveWithNoFeedIsReportedWhileTyping() {
    MainWindow w;
    w.show();
    QVERIFY(waitIdle(w));
    w.editor()->insertPlainText(QStringLiteral("G21 G99\nG00 X20. Z2.\n"));
    QTest::keyClicks(w.editor(), QStringLiteral("G01 Z-10."));
    QVERIFY(waitIdle(w));
    const auto& diags = w.diagnostics();
    auto it = std::find_if(diags.begin(), diags.end(), [](const core::Diagnostic& d) { return d.code == "W104"; });
    QVERIFY(it != diags.end());
    QCOMPARE(it->range.line, w.editor()->firstFileLine() + 2);
    QCOMPARE(it->range.column, 1);
    QCOMPARE(it->severity, core::Severity::Warning);
    QVERIFY(hasWavyUnderlineAt(w.editor()->document()->findBlockByNumber(2), 0));
    // Giving the feed clears it.
    QTest::keyClicks(w.editor(), QStringLiteral(" F0.2"));
    QVERIFY(waitIdle(w));
    QVERIFY(std::none_of(w.diagnostics().begin(), w.diagnostics().end(),
                         [](const core::Diagnostic& d) { return d.code == "W104"; }));
  }

  // Issue 11: "1 error", never "1 errors"; Thai counts items the same way for one or many.
  void theDiagnosticsTitleCountsInWords() {
    MainWindow w;
    w.show();
    QVERIFY(waitIdle(w));
    w.editor()->insertPlainText(QStringLiteral("G21 G99\nG01 X20. Q\n"));
    QVERIFY(waitIdle(w));
    QCOMPARE(w.diagnosticsPanel()->errorCount(), 1);
    const int warnings = w.diagnosticsPanel()->warningCount();
    QCOMPARE(w.diagnosticsPanel()->windowTitle(),
             QStringLiteral("Diagnostics: 1 error, %1")
                 .arg(warnings == 1 ? QStringLiteral("1 warning") : QStringLiteral("%1 warnings").arg(warnings)));
    Language::instance()->setLanguage(QStringLiteral("th"));
    QTRY_COMPARE(w.diagnosticsPanel()->windowTitle(),
                 QStringLiteral("การตรวจสอบไวยากรณ์: ข้อผิดพลาด 1 รายการ, คำเตือน %1 รายการ").arg(warnings));
    Language::instance()->setLanguage(QStringLiteral("en"));
  }

  void oneEditIsParsedOnce() {
    // Issue 12: the window never parses G-code itself; one typing pause = one
    // parse (the check's), whatever the highlighter, tool tips or status do.
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    QVERIFY(waitIdle(w));
    w.editor()->goToFileLine(15, 1);
    const std::size_t before = core::gcode::parseCount();
    QTest::keyClicks(w.editor(), QStringLiteral("G00 X60. "));
    QVERIFY(waitIdle(w));
    QCOMPARE(core::gcode::parseCount() - before, std::size_t{1});
  }

  void unsavedChangesPromptCancelKeepsAndDiscardDrops() {
    MainWindow w;
    w.show();
    QVERIFY(waitIdle(w));
    QTest::keyClicks(w.editor(), QStringLiteral("G00 X50. Z2."));
    QString boxName;
    answerNextMessageBox(QStringLiteral("cancelButton"), &boxName);
    w.newFile();
    QCOMPARE(boxName, QStringLiteral("unsavedChangesBox"));
    QCOMPARE(w.editor()->toPlainText(), QStringLiteral("G00 X50. Z2."));
    answerNextMessageBox(QStringLiteral("cancelButton"));
    QVERIFY(!w.close());  // closing asks too, and Cancel keeps the window
    boxName.clear();
    answerNextMessageBox(QStringLiteral("discardButton"), &boxName);
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    QCOMPARE(boxName, QStringLiteral("unsavedChangesBox"));
    QVERIFY(waitIdle(w));
    QCOMPARE(w.editor()->document()->firstBlock().text(), QStringLiteral("O0001"));
    QVERIFY(!w.isWindowModified());
    QVERIFY(w.close());  // nothing changed: no prompt
  }

  void saveRoundTripsTheFile() {
    QTemporaryDir tmp;
    const QString copy = tmp.filePath(QStringLiteral("shaft.txt"));
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    QVERIFY(waitIdle(w));
    QVERIFY(w.saveFile(copy));
    // Unchanged program: the saved bytes are the core's canonical form of the sample.
    const auto original = core::io::readProgramFile(sample("01-step-shaft.txt").toStdString());
    QVERIFY(original.value);
    QCOMPARE(readAll(copy), QByteArray::fromStdString(core::io::formatProgramFile(*original.value)));
    QCOMPARE(w.windowTitle(), QStringLiteral("Klueng : shaft.txt[*]"));
    // Edit line 8 (N10 ...) and save again: header kept, code changed.
    QTextCursor c(w.editor()->document()->findBlockByNumber(1));
    c.movePosition(QTextCursor::EndOfBlock);
    c.insertText(QStringLiteral(" (edited)"));
    QVERIFY(w.isWindowModified());
    QVERIFY(w.saveFile(copy));
    QVERIFY(!w.isWindowModified());
    const auto back = core::io::readProgramFile(copy.toStdString());
    QVERIFY(back.ok());
    QCOMPARE(back.value->header.project, std::string("Step shaft exercise"));
    QCOMPARE(back.value->header.programmer, std::string("Klueng samples"));
    QVERIFY(back.value->gcode.find("N10 G21 G40 G97 (edited)\n") != std::string::npos);
    QCOMPARE(QString::fromStdString(back.value->gcode).trimmed(), w.editor()->toPlainText().trimmed());
    // The recent files list remembers it.
    QCOMPARE(Settings().recentFiles().value(0), QFileInfo(copy).absoluteFilePath());
  }

  void fileChangedOnDiskOffersReload() {
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("p.txt"));
    QFile::copy(sample("01-step-shaft.txt"), path);
    QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(path));
    QVERIFY(waitIdle(w));
    QString boxName;
    answerNextMessageBox(QStringLiteral("reloadButton"), &boxName);
    {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
      f.write("P\nS\nSteel\n130\n150\nMe\nO0002\nG00 X10. Z5.\n");
    }
    QTRY_COMPARE_WITH_TIMEOUT(boxName, QStringLiteral("fileChangedBox"), 10000);
    QTRY_COMPARE_WITH_TIMEOUT(w.editor()->document()->firstBlock().text(), QStringLiteral("O0002"), 10000);
    QVERIFY(waitIdle(w));
    QCOMPARE(w.document()->header().material, std::string("Steel"));
  }

  void languageToggleTranslatesMenusAndMessages() {
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    QVERIFY(waitIdle(w));
    QMenu* file = w.menuBar()->findChild<QMenu*>(QStringLiteral("menuFile"));
    QVERIFY(file);
    QCOMPARE(file->title(), QStringLiteral("&File"));
    QCOMPARE(w.action(QStringLiteral("actionGo"))->text(), QStringLiteral("&Go"));
    // The mouse on Toggle Language: its tip in the status bar, then in Thai after the click (issue 40 item 4).
    QAction* toggle = w.action(QStringLiteral("actionToggleLanguage"));
    toggle->showStatusText(&w);
    QCOMPARE(w.statusBar()->currentMessage(), QStringLiteral("Switch between Thai and English"));
    toggle->trigger();
    QVERIFY(Language::instance()->isThai());
    QTRY_COMPARE(file->title(), QStringLiteral("แฟ้ม (&F)"));
    QCOMPARE(w.statusBar()->currentMessage(), QStringLiteral("สลับระหว่างภาษาไทยและภาษาอังกฤษ"));
    QCOMPARE(w.action(QStringLiteral("actionGo"))->text(), QStringLiteral("เริ่มทำงาน (&G)"));
    QCOMPARE(w.action(QStringLiteral("actionStep"))->text(), QStringLiteral("ทำงานทีละบรรทัด (&S)"));
    QCOMPARE(w.menuBar()->findChild<QMenu*>(QStringLiteral("menuToolSetting"))->title(),
             QStringLiteral("ตั้งค่ามีดตัด (&T)"));
    QCOMPARE(Settings().language(), QStringLiteral("th"));
    // Core texts follow: a diagnostic is listed in Thai.
    QTest::keyClicks(w.editor(), QStringLiteral("Y5 "));
    QVERIFY(waitIdle(w));
    QVERIFY(w.diagnosticsPanel()->errorCount() >= 1);
    const auto& d = w.diagnosticsPanel()->diagnostics().front();
    QCOMPARE(w.diagnosticsPanel()->model()->index(0, DiagnosticsModel::MessageColumn).data().toString(),
             QString::fromStdString(core::formatMessage(d, core::Lang::Th)));
    // And back.
    toggle->showStatusText(&w);
    toggle->trigger();
    QTRY_COMPARE(file->title(), QStringLiteral("&File"));
    QCOMPARE(w.statusBar()->currentMessage(), QStringLiteral("Switch between Thai and English"));
    QCOMPARE(Settings().language(), QStringLiteral("en"));
  }

  void everyMenuTextIsTranslated() {
    MainWindow w;
    Language::instance()->setLanguage(QStringLiteral("th"));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    QTRY_COMPARE(w.menuBar()->findChild<QMenu*>(QStringLiteral("menuFile"))->title(), QStringLiteral("แฟ้ม (&F)"));
    // Every action with text in a menu must contain Thai letters (no English left behind).
    const QList<QAction*> actions = w.findChildren<QAction*>();
    int checked = 0;
    for (QAction* a : actions) {
      if (a->parent() != &w || a->objectName().isEmpty() || a->text().isEmpty() ||
          a->objectName().startsWith(QStringLiteral("actionSpeed")))
        continue;
      if (a->objectName() == QStringLiteral("actionDialectFanuc")) continue;  // a product name
      bool thai = false;
      for (QChar c : a->text()) thai |= c.unicode() >= 0x0E00 && c.unicode() <= 0x0E7F;
      QVERIFY2(thai, qPrintable(a->objectName() + QStringLiteral(": ") + a->text()));
      ++checked;
    }
    QVERIFY(checked >= 35);
  }

  void breakpointsFollowTheirLines() {
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    QVERIFY(waitIdle(w));
    CodeEditor* e = w.editor();
    e->goToFileLine(13);  // N50 G00 X54. Z2. M08
    w.action(QStringLiteral("actionToggleBreakpoint"))->trigger();
    QCOMPARE(e->breakpointFileLines(), QList<int>{13});
    QVERIFY(w.runController()->breakpoints().contains(13));
    // A line inserted above moves the breakpoint down with its block.
    QTextCursor c(e->document()->findBlockByNumber(1));
    c.insertText(QStringLiteral("(new line)\n"));
    QCOMPARE(e->breakpointFileLines(), QList<int>{14});
    QCOMPARE(e->document()->findBlockByNumber(14 - 7).text(), QStringLiteral("N50 G00 X54. Z2. M08"));
    e->toggleBreakpoint(14);
    QVERIFY(e->breakpointFileLines().isEmpty());
  }

  void findReplaceAndGoToLine() {
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    QVERIFY(waitIdle(w));
    FindDialog find(w.editor());
    find.setFindText(QStringLiteral("G01"));
    QVERIFY(find.findNext());
    QCOMPARE(w.editor()->cursorFileLine(), 15);  // N70 G01 F0.2 (face)
    QVERIFY(find.findNext());
    QCOMPARE(w.editor()->cursorFileLine(), 18);  // N100 G01 Z-59.8 F0.25 (rough)
    find.setFindText(QStringLiteral("X100."));
    find.setReplaceText(QStringLiteral("X120."));
    QCOMPARE(find.replaceAll(), 2);
    QVERIFY(!w.editor()->toPlainText().contains(QStringLiteral("X100.")));
    w.editor()->undo();  // Replace All is one undo step
    QCOMPARE(w.editor()->toPlainText().count(QStringLiteral("X100.")), 2);
    find.setFindText(QStringLiteral("NOPE"));
    QVERIFY(!find.findNext());
  }

  void tooltipsExplainCodesFromTheCodeTable() {
    MainWindow w;
    w.editor()->setPlainText(QStringLiteral("N10 G01 X20. M03 (G02 in a comment)"));
    const auto g01 = core::gcode::lookupCode('G', 1, core::gcode::Dialect::Fanuc);
    QVERIFY(g01);
    const QString tipG = w.editor()->helpForPosition(5);  // on "G01"
    QVERIFY2(tipG.contains(QString::fromUtf8(g01->nameEn.data(), static_cast<qsizetype>(g01->nameEn.size()))),
             qPrintable(tipG));
    const auto m03 = core::gcode::lookupCode('M', 3, core::gcode::Dialect::Fanuc);
    QVERIFY(w.editor()->helpForPosition(15).contains(
        QString::fromUtf8(m03->nameEn.data(), static_cast<qsizetype>(m03->nameEn.size()))));
    QVERIFY(w.editor()->helpForPosition(9).contains(QStringLiteral("diameter")));  // X20.
    QVERIFY(w.editor()->helpForPosition(19).isEmpty());                            // G02 inside a comment
    Language::instance()->setLanguage(QStringLiteral("th"));
    QVERIFY(w.editor()->helpForPosition(5).contains(
        QString::fromUtf8(g01->nameTh.data(), static_cast<qsizetype>(g01->nameTh.size()))));
  }

  void layoutAndSettingsAreRemembered() {
    QList<int> sizes;
    {
      MainWindow w;
      w.resize(1200, 760);
      w.show();
      QVERIFY(QTest::qWaitForWindowExposed(&w));
      w.splitter()->setSizes({300, 880});
      sizes = w.splitter()->sizes();
      w.setDialect(core::gcode::Dialect::Classic);
      w.action(QStringLiteral("actionOptionalStop"))->setChecked(true);
      QVERIFY(w.close());
    }
    MainWindow again;
    again.show();
    QVERIFY(QTest::qWaitForWindowExposed(&again));
    QCOMPARE(again.size(), QSize(1200, 760));
    QCOMPARE(again.splitter()->sizes(), sizes);
    QCOMPARE(again.dialect(), core::gcode::Dialect::Classic);
    QVERIFY(again.action(QStringLiteral("actionDialectClassic"))->isChecked());
    QVERIFY(again.action(QStringLiteral("actionOptionalStop"))->isChecked());
    QVERIFY(again.runController()->optionalStop());
  }

  // Issue 11: F1 on a code opens its entry; the search finds G71 in English and Thai words.
  void helpOpensAtTheCodeUnderTheCursorAndSearches() {
    MainWindow w;
    w.show();
    QVERIFY(waitIdle(w));
    w.editor()->setPlainText(QStringLiteral("G00 X52. Z5.\nG76 P020060 Q50 R0.05\n"));
    QTextCursor c(w.editor()->document()->findBlockByNumber(1));
    c.setPosition(c.position() + 2);  // inside "G76"
    w.editor()->setTextCursor(c);
    w.editor()->setFocus();
    QTest::keyClick(w.editor(), Qt::Key_F1);
    auto* help = w.findChild<HelpContents*>();
    QTRY_VERIFY(help && help->isVisible());
    QCOMPARE(help->shownAnchor(), QStringLiteral("G76"));
    QVERIFY(help->browser()->verticalScrollBar()->value() > 0);
    // Its worked example is on the page, as a whole program, with a picture of its path; the tip numbers too.
    QVERIFY(help->browser()->toPlainText().contains(QStringLiteral("G76 X46.16 Z-25. P920 Q300 F1.5")));
    for (const QString& picture : {QStringLiteral("help-path-G76.png"), QStringLiteral("help-tips.png")}) {
      const QImage image =
          help->browser()->document()->resource(QTextDocument::ImageResource, QUrl(picture)).value<QImage>();
      QVERIFY2(!image.isNull() && image.width() > 200, qPrintable(picture));
      QVERIFY2(help->browser()->toHtml().contains(picture), qPrintable(picture));
    }
    for (const QString& query : {QStringLiteral("roughing"), QStringLiteral("กลึงปอกหยาบ")}) {
      help->searchField()->setText(query);
      QVERIFY(help->hits()->isVisible());
      bool found = false;
      for (int i = 0; i < help->hits()->count(); ++i)
        found |= help->hits()->item(i)->data(Qt::UserRole).toString() == QStringLiteral("G71");
      QVERIFY2(found, qPrintable(query));
    }
    help->searchField()->setText(QStringLiteral("g71"));
    QTest::keyClick(help->searchField(), Qt::Key_Return);
    QCOMPARE(help->shownAnchor(), QStringLiteral("G71"));
  }

  // Issue 11: File > Grade a class grades a folder against a reference; a double-click opens a student's program.
  void gradeAClassAndOpenAStudentsProgram() {
    QTemporaryDir dir;
    QFile ref(sample("01-step-shaft.txt"));
    QVERIFY(ref.open(QIODevice::ReadOnly));
    const QByteArray reference = ref.readAll();
    QDir(dir.path()).mkdir(QStringLiteral("class"));
    auto write = [&](const QString& name, const QByteArray& text) {
      QFile f(dir.path() + QStringLiteral("/class/") + name);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(text);
    };
    write(QStringLiteral("anna.nc"), reference);
    write(QStringLiteral("boon.nc"), QByteArray(reference).replace("N390 G01 Z-40.", "N390 G01 X39.8 Z-40."));
    write(QStringLiteral("chai.nc"), QByteArray(reference).replace("N100 G01 Z-59.8", "N100 G01 Y-59.8"));
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    QVERIFY(waitIdle(w));
    w.action(QStringLiteral("actionGradeClass"))->trigger();
    auto* dialog = w.findChild<ClassGradeDialog*>();
    QVERIFY(dialog && dialog->isVisible());
    dialog->setFolder(dir.path() + QStringLiteral("/class"));
    QSignalSpy done(dialog, &ClassGradeDialog::finished);
    dialog->grade();
    QTRY_COMPARE_WITH_TIMEOUT(done.count(), 1, 30000);
    QTableWidget* table = dialog->table();
    QCOMPARE(table->rowCount(), 3);
    QCOMPARE(table->item(0, 0)->text(), QStringLiteral("anna.nc"));
    QCOMPARE(table->item(0, 1)->text(), QStringLiteral("pass"));
    QCOMPARE(table->item(1, 1)->text(), QStringLiteral("fail"));
    QVERIFY(table->item(1, 6)->text().startsWith(QStringLiteral("0.191")));
    QCOMPARE(table->item(2, 1)->text(), QStringLiteral("fail"));
    QVERIFY(table->item(2, 2)->text().contains(QStringLiteral("E201")));
    const QString csv = dir.path() + QStringLiteral("/grades.csv");
    QVERIFY(dialog->saveCsv(csv));
    QFile saved(csv);
    QVERIFY(saved.open(QIODevice::ReadOnly));
    QCOMPARE(saved.readAll().count('\n'), 4);
    QSignalSpy loaded(&w, &MainWindow::fileLoaded);
    emit table->cellDoubleClicked(1, 0);
    QTRY_COMPARE_WITH_TIMEOUT(loaded.count(), 1, 20000);
    QVERIFY(w.windowTitle().contains(QStringLiteral("boon.nc")));
  }

  void helpContentsListsEveryCodeInBothLanguages() {
    MainWindow w;
    w.show();
    w.action(QStringLiteral("actionContents"))->trigger();
    auto* help = w.findChild<HelpContents*>();
    QVERIFY(help && help->isVisible());
    const QString page = help->browser()->toPlainText();
    int codes = 0;
    for (const auto& c : core::gcode::codeTable()) {
      const QString word = QStringLiteral("%1%2").arg(QLatin1Char(c.letter)).arg(c.number, 2, 10, QLatin1Char('0'));
      QVERIFY2(page.contains(word), qPrintable(word));
      QVERIFY(page.contains(QString::fromUtf8(c.nameEn.data(), static_cast<qsizetype>(c.nameEn.size()))));
      QVERIFY(page.contains(QString::fromUtf8(c.nameTh.data(), static_cast<qsizetype>(c.nameTh.size()))));
      ++codes;
    }
    QVERIFY(codes > 30);
    QVERIFY(page.contains(QStringLiteral("G codes")));
    // On a system-B machine the codes come in its own numbers' order (issue 27): G33
    // (system A's G32) before G40, G98 before G99, all before the M codes.
    core::gcode::Dialect romi{};
    QVERIFY(core::gcode::parseDialectId("romi-gl240m", romi));
    help->setDialect(romi);
    const QString b = help->browser()->toPlainText();
    const qsizetype gTable = b.indexOf(QStringLiteral("G codes ("));
    const qsizetype mTable = b.indexOf(QStringLiteral("M codes ("));
    QVERIFY(gTable > 0 && mTable > gTable);
    const auto at = [&b, gTable](const char* code) { return b.indexOf(QLatin1String(code), gTable); };
    QVERIFY2(at("G33") >= 0 && at("G33") < at("G40") && at("G40") < mTable, qPrintable(b.mid(gTable, 3000)));
    QVERIFY(at("G98") >= 0 && at("G98") < at("G99") && at("G99") < mTable);
    // Every row's code (a line of its own) in ascending order: the rows only system B has
    // (G90/G91 absolute/incremental, G98/G99 return levels) used to trail the table.
    const QStringList tableLines = b.mid(gTable, mTable - gTable).split(QLatin1Char('\n'));
    int last = -1, rowsSeen = 0;
    static const QRegularExpression codeLine(QStringLiteral("^G(\\d\\d)$"));
    for (const QString& line : tableLines)
      if (const QRegularExpressionMatch m = codeLine.match(line.trimmed()); m.hasMatch()) {
        const int n = m.captured(1).toInt();
        QVERIFY2(n >= last, qPrintable(QStringLiteral("G%1 after G%2").arg(n).arg(last)));
        last = n;
        ++rowsSeen;
      }
    QVERIFY(rowsSeen > 20);
    help->setDialect(core::gcode::Dialect::Fanuc);
    w.action(QStringLiteral("actionToggleLanguage"))->trigger();
    QTRY_VERIFY(help->browser()->toPlainText().contains(QStringLiteral("รหัส G")));
  }

  void highlighterColoursWordKinds() {
    using K = GcodeHighlighter::Kind;
    QCOMPARE(GcodeHighlighter::kindOf(u'g'), K::GCode);
    QCOMPARE(GcodeHighlighter::kindOf(u'M'), K::MCode);
    QCOMPARE(GcodeHighlighter::kindOf(u'T'), K::Tool);
    QCOMPARE(GcodeHighlighter::kindOf(u'X'), K::Axis);
    QCOMPARE(GcodeHighlighter::kindOf(u'N'), K::Sequence);
    MainWindow w;
    w.editor()->setPlainText(QStringLiteral("N10 G01 X20. T0101 (cut)"));
    const QTextBlock b = w.editor()->document()->firstBlock();
    auto colourAt = [&b](int pos) {
      for (const auto& r : b.layout()->formats())
        if (pos >= r.start && pos < r.start + r.length) return r.format.foreground().color();
      return QColor();
    };
    const GcodeHighlighter* h = w.editor()->highlighter();
    QCOMPARE(colourAt(4), h->format(K::GCode).foreground().color());
    QCOMPARE(colourAt(8), h->format(K::Axis).foreground().color());
    QCOMPARE(colourAt(13), h->format(K::Tool).foreground().color());
    QCOMPARE(colourAt(20), h->format(K::Comment).foreground().color());
    QVERIFY(colourAt(4) != colourAt(8) && colourAt(8) != colourAt(13) && colourAt(13) != colourAt(20));

    // Macro B: statement words and #variables have their own colours; X of X#101 stays an axis.
    w.editor()->setPlainText(QStringLiteral("WHILE [#101 GT 30.] DO1\nG00 X#101"));
    const QTextBlock m = w.editor()->document()->firstBlock();
    auto colourIn = [](const QTextBlock& block, int pos) {
      for (const auto& r : block.layout()->formats())
        if (pos >= r.start && pos < r.start + r.length) return r.format.foreground().color();
      return QColor();
    };
    QCOMPARE(colourIn(m, 0), h->format(K::Macro).foreground().color());     // WHILE
    QCOMPARE(colourIn(m, 7), h->format(K::Variable).foreground().color());  // #101
    QCOMPARE(colourIn(m, 12), h->format(K::Macro).foreground().color());    // GT
    QCOMPARE(colourIn(m, 20), h->format(K::Macro).foreground().color());    // DO
    QCOMPARE(colourIn(m.next(), 4), h->format(K::Axis).foreground().color());
    QCOMPARE(colourIn(m.next(), 5), h->format(K::Variable).foreground().color());
  }

  void programWithErrorsDoesNotRun() {
    MainWindow w;
    w.show();
    QVERIFY(waitIdle(w));
    w.editor()->setPlainText(QStringLiteral("G01 X20. Y5. F0.2\n"));
    QVERIFY(waitIdle(w));
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!w.bannerText().isEmpty(), 10000);
    QVERIFY(w.bannerText().contains(QStringLiteral("error")));
    QVERIFY(w.runController()->state() != RunState::Running);
    QCOMPARE(w.editor()->cursorFileLine(), 7);
  }

  void alarmStopsOnItsBlockAndSaysWhy() {
    MainWindow w;
    w.show();
    QVERIFY(waitIdle(w));
    // Cutting with the spindle stopped: G01 on file line 9 raises an alarm there.
    w.editor()->setPlainText(QStringLiteral("G21 G99\nT0101 G00 X60. Z5.\nG01 X40. Z-10. F0.2\nM30\n"));
    QVERIFY(waitIdle(w));
    QCOMPARE(w.diagnosticsPanel()->errorCount(), 0);
    QSignalSpy alarms(w.runController(), &RunController::alarmRaised);
    w.runController()->setSpeed(RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(w.runController()->state(), RunState::Alarm, 20000);
    QCOMPARE(alarms.count(), 1);
    const auto alarm = alarms.first().first().value<core::Diagnostic>();
    QCOMPARE(alarm.range.line, 9);
    QCOMPARE(w.editor()->executingFileLine(), 9);
    QVERIFY(w.bannerText().contains(QString::fromStdString(core::formatMessage(alarm, core::Lang::En))));
    QVERIFY(w.bannerText().contains(QStringLiteral("line 9")));
    // The alarm is also listed with the program's diagnostics.
    const auto& listed = w.diagnosticsPanel()->diagnostics();
    QVERIFY(std::any_of(listed.begin(), listed.end(), [&](const core::Diagnostic& d) { return d.code == alarm.code; }));
  }

  // Issue 11: opening another file drops the old file's alarm and errors.
  void openingAnotherFileDropsThePreviousFilesDiagnostics() {
    MainWindow w;
    w.show();
    QVERIFY(waitIdle(w));
    w.editor()->setPlainText(QStringLiteral("G21 G99\nT0101 G00 X60. Z5.\nG01 X40. Z-10. F0.2\nG01 Y3.\nM30\n"));
    QVERIFY(waitIdle(w));
    QVERIFY(w.diagnosticsPanel()->errorCount() > 0);  // Y is no lathe word
    w.editor()->setPlainText(QStringLiteral("G21 G99\nT0101 G00 X60. Z5.\nG01 X40. Z-10. F0.2\nM30\n"));
    QVERIFY(waitIdle(w));
    w.runController()->setSpeed(RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(w.runController()->state(), RunState::Alarm, 20000);
    QVERIFY(!w.diagnosticsPanel()->diagnostics().empty());
    answerNextMessageBox(QStringLiteral("discardButton"));
    QSignalSpy loaded(&w, &MainWindow::fileLoaded);
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    // As soon as the file is in, before its check has finished, and after it.
    QTRY_COMPARE_WITH_TIMEOUT(loaded.count(), 1, 20000);
    QVERIFY(w.diagnosticsPanel()->diagnostics().empty());
    QVERIFY(w.bannerText().isEmpty());
    QVERIFY(waitIdle(w));
    // After its check: only what sample 01 itself gives (notes, no errors), no alarm.
    QCOMPARE(w.diagnosticsPanel()->errorCount(), 0);
    for (const core::Diagnostic& d : w.diagnosticsPanel()->diagnostics()) {
      QVERIFY2(d.severity != core::Severity::Alarm && d.severity != core::Severity::Error, d.code.c_str());
    }
    MainWindow fresh;
    QVERIFY(fresh.openFile(sample("01-step-shaft.txt")));
    QVERIFY(waitIdle(fresh));
    QCOMPARE(w.diagnosticsPanel()->diagnostics().size(), fresh.diagnosticsPanel()->diagnostics().size());
  }

  // Issue 11: after an alarm at the fastest speed the status bar shows the
  // state at the alarm, not an empty one.
  void theStatusBarIsRightAfterAnAlarmAtTheFastestSpeed() {
    MainWindow w;
    w.show();
    QVERIFY(waitIdle(w));
    w.editor()->setPlainText(QStringLiteral("G21 G99\nT0101 G00 X60. Z5.\nG01 X40. Z-10. F0.2\nM30\n"));
    QVERIFY(waitIdle(w));
    w.runController()->setSpeed(RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(w.runController()->state(), RunState::Alarm, 20000);
    QCoreApplication::processEvents();
    const StatusFields* f = w.statusFields();
    QCOMPARE(f->fieldText(StatusFields::Field::Tool), QStringLiteral("T0101"));
    QCOMPARE(f->fieldText(StatusFields::Field::NoseRadius), QStringLiteral("0.800"));
    QCOMPARE(f->fieldText(StatusFields::Field::Tip), QStringLiteral("3"));
    QCOMPARE(f->fieldText(StatusFields::Field::Feed), QStringLiteral("0.200 mm/rev"));
    QCOMPARE(f->fieldText(StatusFields::Field::ToolX), QStringLiteral("60.000"));
    QCOMPARE(f->fieldText(StatusFields::Field::ToolZ), QStringLiteral("5.000"));
  }

  // Issue 11: a run that reaches M30 says so, with the cycle time of the core's timeline.
  void theEndOfARunGivesTheCycleTime() {
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    QVERIFY(waitIdle(w));
    w.runController()->setSpeed(RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(w.runController()->state(), RunState::Finished, 20000);
    const double seconds = w.runController()->timeline()->cycleTime();
    QVERIFY(seconds > 10.0);
    const int minutes = static_cast<int>(seconds / 60.0);
    const QString expected = minutes > 0
                                 ? QStringLiteral("%1 min %2 s").arg(minutes).arg(seconds - 60.0 * minutes, 0, 'f', 1)
                                 : QStringLiteral("%1 s").arg(seconds, 0, 'f', 1);
    QCOMPARE(w.bannerText(), QStringLiteral("The program ended. Cycle time: %1.").arg(expected));
    QCOMPARE(MainWindow::formatDuration(192.44), QStringLiteral("3 min 12.4 s"));
  }

  // Issue 28 item 6: the alarm banner and the alarm in the list belong to the
  // text that ran; fixing the line takes them away.
  void fixingTheAlarmsLineTakesTheBannerAway() {
    MainWindow w;
    w.show();
    QVERIFY(waitIdle(w));
    w.editor()->setPlainText(QStringLiteral("G21 G99\nT0101 G00 X60. Z5.\nG01 X40. Z-10. F0.2\nM30\n"));
    QVERIFY(waitIdle(w));
    w.runController()->setSpeed(RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(w.runController()->state(), RunState::Alarm, 20000);
    QVERIFY(w.bannerText().startsWith(QStringLiteral("Alarm ")));
    // The spindle was not started: the student adds S800 M03 to the tool block.
    QTextCursor c(w.editor()->document()->findBlockByNumber(1));
    c.movePosition(QTextCursor::EndOfBlock);
    c.insertText(QStringLiteral(" S800 M03"));
    QCOMPARE(w.bannerText(), QString());
    // Nor does the run stay at the alarm's block of the old text.
    QCOMPARE(w.runController()->state(), RunState::Idle);
    QCOMPARE(w.editor()->executingFileLine(), 0);
    QCOMPARE(w.statusFields()->fieldText(StatusFields::Field::Time), QStringLiteral("-"));
    QVERIFY(waitIdle(w));
    for (const core::Diagnostic& d : w.diagnosticsPanel()->diagnostics())
      QVERIFY2(d.severity != core::Severity::Alarm, d.code.c_str());
    QCOMPARE(w.bannerText(), QString());
  }

  // Issue 28 item 6: "fix the errors first" goes when the errors are fixed.
  void theRefusedRunsBannerGoesWhenTheErrorsAreFixed() {
    MainWindow w;
    w.show();
    QVERIFY(waitIdle(w));
    w.editor()->setPlainText(QStringLiteral("G21 G99 S800 M03\nT0101 G00 X60. Z5.\nG01 Y3.\nM30\n"));
    QVERIFY(waitIdle(w));
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(w.bannerText().startsWith(QStringLiteral("The program has 1 error")), 20000);
    w.editor()->setPlainText(QStringLiteral("G21 G99 S800 M03\nT0101 G00 X60. Z5.\nG01 X40. F0.2\nM30\n"));
    QVERIFY(waitIdle(w));
    QCOMPARE(w.diagnosticsPanel()->errorCount(), 0);
    QCOMPARE(w.bannerText(), QString());
  }

  // Issue 28 item 6: a language switch says the banner again in the new language.
  void theBannerFollowsTheLanguage() {
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    QVERIFY(waitIdle(w));
    w.runController()->setSpeed(RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(w.runController()->state(), RunState::Finished, 20000);
    QVERIFY(w.bannerText().startsWith(QStringLiteral("The program ended. Cycle time: ")));
    const double seconds = w.runController()->timeline()->cycleTime();
    Language::instance()->setLanguage(QStringLiteral("th"));
    QCoreApplication::processEvents();
    QCOMPARE(w.bannerText(),
             QStringLiteral("จบโปรแกรมแล้ว เวลาทำงาน (cycle time): %1").arg(MainWindow::formatDuration(seconds)));
    QVERIFY(MainWindow::formatDuration(seconds).contains(QStringLiteral("วินาที")));
    Language::instance()->setLanguage(QStringLiteral("en"));
    QCoreApplication::processEvents();
    QVERIFY(w.bannerText().startsWith(QStringLiteral("The program ended. Cycle time: ")));
  }

  // Issue 28 item 6: an empty program runs nothing and says so, never "ended, 0.0 s".
  void anEmptyProgramRunsNothing() {
    MainWindow w;
    w.show();
    QVERIFY(waitIdle(w));
    w.editor()->setPlainText(QStringLiteral("%\n(nothing yet)\n%\n"));
    QVERIFY(waitIdle(w));
    w.runController()->setSpeed(RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(w.runController()->state(), RunState::Finished, 20000);
    QCOMPARE(w.bannerText(), QStringLiteral("There is nothing to run: the program has no blocks. Type the program in "
                                            "the editor or open a file."));
  }

  // Issue 28 item 8: an untitled, empty window frames the stock (Ø50 x 100), not the
  // tool's start at Z300, also after the window is laid out and resized; once the user
  // zooms, a resize leaves the zoom alone.
  void anEmptyWindowFramesTheStock() {
    MainWindow w;
    w.resize(640, 400);
    w.show();
    QVERIFY(waitIdle(w));
    w.resize(1366, 768);
    QApplication::processEvents();
    OutputView* view = w.outputView();
    const auto check = [view]() -> QString {
      const QRectF visible = view->visibleSceneRect();
      if (visible.contains(render::toScene(300.0, 0.0))) return QStringLiteral("Z300 is in sight");
      if (!visible.contains(render::toScene(0.0, 25.0)) || !visible.contains(render::toScene(-100.0, -25.0)))
        return QStringLiteral("the bar is not whole in sight");
      const int bar =
          view->mapFromScene(render::toScene(0.0, 25.0)).x() - view->mapFromScene(render::toScene(-100.0, 25.0)).x();
      if (bar < 0.4 * view->viewport()->width())
        return QStringLiteral("the bar is %1 px of %2").arg(bar).arg(view->viewport()->width());
      return {};
    };
    QCOMPARE(check(), QString());
    w.resize(1100, 700);
    QApplication::processEvents();
    QCOMPARE(check(), QString());
    view->zoomOut();
    const double zoomed = view->pixelsPerMm();
    w.resize(1366, 768);
    QApplication::processEvents();
    QCOMPARE(view->pixelsPerMm(), zoomed);
    w.action(QStringLiteral("actionFitView"))->trigger();
    QCOMPARE(check(), QString());
  }

  // Issue 28 item 7: every status bar field is whole at 1366 px in both
  // languages, with wide values (a 10-minute program, a 2-digit day) and the
  // busy bar showing.
  void theStatusBarFieldsAreWholeAt1366() {
    for (const QString& lang : {QStringLiteral("en"), QStringLiteral("th")}) {
      MainWindow w;  // reads the language from the settings: set it after
      Language::instance()->setLanguage(lang);
      w.resize(1366, 740);
      w.show();
      QVERIFY(waitIdle(w));
      RunStatus s;
      s.position = core::zx(-123.456, 27.5);
      s.programmedFeed = 0.25;
      s.rpm = 2500;
      s.machine.tool = 1;
      s.machine.offset = 1;
      s.machine.offsetX = -12.345;
      s.machine.offsetZ = -123.456;
      s.machine.noseRadius = 0.8;
      s.machine.tip = 3;
      s.time = 610.1;
      s.cycleTime = 733.4;
      w.statusFields()->setStatus(s);
      auto* busy = w.findChild<QProgressBar*>(QStringLiteral("busyBar"));
      QVERIFY(busy);
      busy->show();  // as while a long program is checked
      w.statusBar()->clearMessage();
      QCoreApplication::processEvents();
      QVERIFY(QTest::qWaitForWindowExposed(&w));
      const QList<QLabel*> labels = w.statusFields()->findChildren<QLabel*>();
      QVERIFY(labels.size() >= 22);
      for (QLabel* l : labels) {
        QVERIFY2(l->isVisible(), qPrintable(l->text()));
        QVERIFY2(l->width() >= l->sizeHint().width(), qPrintable(QStringLiteral("%1: %2 px of %3 (%4)")
                                                                     .arg(l->text())
                                                                     .arg(l->width())
                                                                     .arg(l->sizeHint().width())
                                                                     .arg(lang)));
        QVERIFY2(l->geometry().right() <= w.statusFields()->width(), qPrintable(l->text()));
      }
      QVERIFY(w.statusFields()->geometry().right() <= w.width());
    }
    Language::instance()->setLanguage(QStringLiteral("en"));
  }

  // Issue 11: while stepping, the bar under the editor explains the block at the arrow.
  void stepExplainsTheBlockAtTheArrow() {
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    QVERIFY(waitIdle(w));
    RunController* run = w.runController();
    run->setSpeed(RunController::kAsFastAsPossible);
    QVERIFY(!w.explainBar()->isVisible());
    // O0001, N10 G21 G40 G97, N15 G99, N20 T0101 ..., N30 G50 S2500, N40 G96 S180 M03, N50 G00 X54. Z2. M08
    for (int i = 0; i < 7; ++i) {
      w.action(QStringLiteral("actionStep"))->trigger();
      QTRY_COMPARE_WITH_TIMEOUT(run->state(), RunState::Paused, 20000);
    }
    QTRY_VERIFY(w.explainBar()->isVisible());
    const int line = w.editor()->executingFileLine();
    QCOMPARE(line, 13);
    const core::machine::StateSnapshot& after =
        run->timeline()->snapshots[static_cast<std::size_t>(run->currentSnapshot())];
    QCOMPARE(after.line, 13);
    const core::gcode::Program one = core::gcode::parse("N50 G00 X54. Z2. M08", 13);
    const QString expected = QString::fromStdString(core::machine::explainBlock(
        one.blocks[0], after, core::gcode::Dialect::Fanuc, core::Lang::En, "N50 G00 X54. Z2. M08"));
    QTRY_COMPARE(w.explainBar()->text(), expected);
    QVERIFY(expected.startsWith(QStringLiteral("N50 G00 X54. Z2. M08: move at rapid speed")));
    // N70 G01 F0.2, the face cut under G96, ends at the centre: the G50 limit holds the rpm.
    for (int i = 0; i < 2; ++i) {
      w.action(QStringLiteral("actionStep"))->trigger();
      QTRY_COMPARE_WITH_TIMEOUT(run->state(), RunState::Paused, 20000);
    }
    QTRY_VERIFY(w.explainBar()->text().contains(QStringLiteral("(G96) the spindle turns 2500 rpm here")));
    QVERIFY(
        w.explainBar()->text().startsWith(QStringLiteral("N70 G01 X-1.6 F0.2: cut in a straight line to \u00D8-1.6")));
    QCOMPARE(w.explainBar()->explainLine(w.editor()->executingFileLine()), w.explainBar()->text());
    // In Thai.
    Language::instance()->setLanguage(QStringLiteral("th"));
    QTRY_VERIFY(w.explainBar()->text().contains(QStringLiteral("เพลาหมุน")));
    Language::instance()->setLanguage(QStringLiteral("en"));
    w.action(QStringLiteral("actionStop"))->trigger();
    QTRY_VERIFY(!w.explainBar()->isVisible());
  }

  // Issue 39: the bar's second line gives the block's cutting data, the plot under the output view
  // draws the run's power and Vc, and the hover help says the same as the bar.
  void stepShowsTheCuttingData() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("steel.txt"));
    {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(
          "Cutting data\nSteel\nS45C\n150\n1100\nTest\nG21 G40 G99\nT0101\nG97 S1000 M03\nG00 X60. Z2.\nX46.\n"
          "G01 Z-30. F0.2\nG00 X60.\nZ50.\nM30\n");
    }
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(path));
    QVERIFY(waitIdle(w));
    RunController* run = w.runController();
    run->setSpeed(RunController::kAsFastAsPossible);
    // G21 G40 G99, T0101, G97 S1000 M03, G00 X60. Z2., X46., G01 Z-30. F0.2: the arrow on line 12.
    for (int i = 0; i < 6; ++i) {
      w.action(QStringLiteral("actionStep"))->trigger();
      QTRY_COMPARE_WITH_TIMEOUT(run->state(), RunState::Paused, 20000);
    }
    QCOMPARE(w.editor()->executingFileLine(), 12);
    QTRY_VERIFY_WITH_TIMEOUT(w.explainBar()->cuttingData() != nullptr, 20000);
    // The hand calculation of tests/core/cut/cutting_data_test.cpp: pi * 46 * 1000 / 1000 = 144.5 m/min,
    // Rz = 0.2^2 / (8 * 0.8) = 6.25 um, and S45C's kc1.1 gives 2.06 kW and 19.7 N*m.
    QTRY_VERIFY(w.explainBar()->text().contains(
        QStringLiteral("\nCutting data: Vc 145 m/min, f 0.200 mm/rev, ap 2.00 mm, Rz 6.3 µm, Ra 1.6 µm, power 2.06 kW, "
                       "torque 19.7 N·m")));
    QCOMPARE(w.explainBar()->explainLine(12), w.explainBar()->text());
    auto* plot = w.findChild<QWidget*>(QStringLiteral("cuttingPlot"));
    QVERIFY(plot);
    QTRY_VERIFY(plot->isVisible());
    Language::instance()->setLanguage(QStringLiteral("th"));
    QTRY_VERIFY(w.explainBar()->text().contains(QStringLiteral("ข้อมูลการตัด: ความเร็วตัด Vc 145 ม./นาที")));
    Language::instance()->setLanguage(QStringLiteral("en"));
    w.action(QStringLiteral("actionStop"))->trigger();
    QTRY_VERIFY(!w.explainBar()->isVisible());
  }

  // Issue 39 item 1: the cutting-data warnings are in the diagnostics list from the check itself
  // (no run): on their block, in the UI's language; a sound program has none.
  void cuttingDataWarningsAreListedByTheCheck() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("rough.txt"));
    {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      // The shipped T01 (R0.8): a 0.3 mm pass at F0.35 leaves Ra = 0.35^2 / 25.6 * 1000 = 4.8 um > 3.2 (line 12).
      f.write(
          "Cutting data\nSteel\nS45C\n150\n1100\nTest\nG21 G40 G99\nT0101\nG97 S800 M03\nG00 X60. Z2.\nX49.4\n"
          "G01 Z-20. F0.35\nG00 X60.\nM30\n");
    }
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(path));
    QVERIFY(waitIdle(w));
    DiagnosticsPanel* panel = w.diagnosticsPanel();
    const auto& diags = panel->diagnostics();
    const auto rough = std::find_if(diags.begin(), diags.end(), [](const core::Diagnostic& d) {
      return d.code == std::string(core::codes::kFinishTooRough);
    });
    QVERIFY(rough != diags.end());
    QCOMPARE(rough->range.line, 12);
    QCOMPARE(rough->severity, core::Severity::Warning);
    QCOMPARE(panel->errorCount(), 0);
    const int row = static_cast<int>(rough - diags.begin());
    const QModelIndex msg = panel->model()->index(row, DiagnosticsModel::MessageColumn);
    QVERIFY(msg.data().toString().startsWith(
        QStringLiteral("finishing feed 0.350 mm/rev with nose radius R0.80 leaves Ra 4.8 um (Rz 19.1 um)")));
    Language::instance()->setLanguage(QStringLiteral("th"));
    QTRY_VERIFY(panel->model()
                    ->index(row, DiagnosticsModel::MessageColumn)
                    .data()
                    .toString()
                    .startsWith(QStringLiteral("อัตราป้อนกลึงละเอียด 0.350")));
    Language::instance()->setLanguage(QStringLiteral("en"));
    // F0.2 instead: Ra 1.6, nothing to say.
    w.editor()->setPlainText(w.editor()->toPlainText().replace(QStringLiteral("F0.35"), QStringLiteral("F0.2")));
    QTRY_VERIFY_WITH_TIMEOUT(std::none_of(panel->diagnostics().begin(), panel->diagnostics().end(),
                                          [](const core::Diagnostic& d) { return d.code.rfind("W33", 0) == 0; }),
                             20000);
  }

  void stepHighlightsTheExecutingBlock() {
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(sample("01-step-shaft.txt")));
    QVERIFY(waitIdle(w));
    RunController* run = w.runController();
    run->setSpeed(RunController::kAsFastAsPossible);
    int lastLine = 0;
    for (int i = 0; i < 5; ++i) {
      w.action(QStringLiteral("actionStep"))->trigger();
      QTRY_COMPARE_WITH_TIMEOUT(run->state(), RunState::Paused, 20000);
      QVERIFY(run->currentLine() > lastLine);
      lastLine = run->currentLine();
      QCOMPARE(w.editor()->executingFileLine(), run->currentLine());
    }
    // While paused the editor can be read; Stop clears the marker.
    w.action(QStringLiteral("actionStop"))->trigger();
    QTRY_COMPARE(w.editor()->executingFileLine(), 0);
  }
};

KLUENG_GUI_TEST(MainWindowTest)
#include "main_window_test.moc"

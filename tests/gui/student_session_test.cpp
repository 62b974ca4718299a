// A student's session through the main window: write a small program from
// scratch, make mistakes, see them underlined and listed, fix them, step
// through, then cut the part to the end; and the alarm case in Thai.
// With KLUENG_GUI_SHOT_DIR set, the window (and the two tool dialogs) are
// saved as PNGs there so a person can look at them.
#include <QAction>
#include <QDir>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>
#include <QTextBlock>

#include "gui_test_runner.h"
#include "fresh_user_folders.h"
#include "gui/code_editor.h"
#include "gui/diagnostics_panel.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/offset_define_dialog.h"
#include "gui/resources.h"
#include "gui/run_controller.h"
#include "gui/status_panel.h"
#include "gui/tool_select_dialog.h"
#include "klueng/core/messages.h"

using namespace klueng;
using namespace klueng::gui;

namespace {

void shot(QWidget& w, const char* name) {
  const QString dir = qEnvironmentVariable("KLUENG_GUI_SHOT_DIR");
  if (dir.isEmpty()) return;
  QDir().mkpath(dir);
  w.grab().save(QDir(dir).filePath(QString::fromLatin1(name) + QStringLiteral(".png")));
}

bool waitIdle(MainWindow& w) {
  return QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000);
}

bool hasCode(const std::vector<core::Diagnostic>& diags, int line) {
  return std::any_of(diags.begin(), diags.end(), [line](const core::Diagnostic& d) {
    return d.range.line == line && d.severity != core::Severity::Warning;
  });
}

}  // namespace

class StudentSessionTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    klueng::test::freshUserFolders();
    initResources();
    QSettings(QStringLiteral("Klueng"), QStringLiteral("klueng")).clear();
  }

  void writeFixStepAndCut() {
    Language::instance()->setLanguage(QStringLiteral("en"));
    MainWindow w;
    w.resize(1280, 800);
    w.show();
    QVERIFY(waitIdle(w));
    // Two mistakes: "X-" has no number (line 11) and Y is not a lathe word (line 12).
    QTest::keyClicks(w.editor(), QStringLiteral("O0010"));
    const char* lines[] = {
        "G21 G40 G97 G99",     "T0101", "G96 S150 M03", "G00 X52. Z2. M08", "G01 X- F0.2", "G01 Z-30. Y2.", "G01 X52.",
        "G00 X100. Z100. M09", "M05",   "M30"};
    for (const char* l : lines) {
      QTest::keyClick(w.editor(), Qt::Key_Return);
      QTest::keyClicks(w.editor(), QString::fromLatin1(l));
    }
    QVERIFY(waitIdle(w));
    QVERIFY(hasCode(w.diagnostics(), 12));
    QVERIFY(hasCode(w.diagnostics(), 13));
    shot(w, "student-1-mistakes");

    // Go refuses a program with errors.
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!w.bannerText().isEmpty(), 10000);
    QVERIFY(w.runController()->state() != RunState::Running);

    // Fix both lines through the editor, as a student would.
    auto replaceLine = [&w](int fileLine, const QString& text) {
      QTextCursor c(w.editor()->document()->findBlockByNumber(fileLine - 7));
      c.select(QTextCursor::BlockUnderCursor);
      c.movePosition(QTextCursor::StartOfBlock);
      c.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
      c.insertText(text);
    };
    replaceLine(12, QStringLiteral("G01 X40. F0.2"));
    replaceLine(13, QStringLiteral("G01 Z-30."));
    QVERIFY(waitIdle(w));
    QCOMPARE(w.diagnosticsPanel()->errorCount(), 0);

    // Step through the first blocks: the editor and the status bar follow the tool.
    RunController* run = w.runController();
    run->setSpeed(RunController::kAsFastAsPossible);
    for (int i = 0; i < 5; ++i) {
      w.action(QStringLiteral("actionStep"))->trigger();
      QTRY_COMPARE_WITH_TIMEOUT(run->state(), RunState::Paused, 20000);
    }
    QCOMPARE(w.editor()->executingFileLine(), run->currentLine());
    QCOMPARE(w.editor()->document()->findBlockByNumber(run->currentLine() - 7).text(),
             QStringLiteral("G00 X52. Z2. M08"));
    QCOMPARE(w.statusFields()->fieldText(StatusFields::Field::ToolX), QStringLiteral("52.000"));
    QCOMPARE(w.statusFields()->fieldText(StatusFields::Field::ToolZ), QStringLiteral("2.000"));
    shot(w, "student-2-stepping");

    // Go to the end: the part is cut, nothing is flagged.
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(run->state() == RunState::Finished || run->state() == RunState::Alarm, 30000);
    QVERIFY2(run->state() == RunState::Finished, qPrintable(w.bannerText()));
    // The only banner is the end of the program with its cycle time, no alarm.
    QVERIFY2(w.bannerText().startsWith(QStringLiteral("The program ended. Cycle time: ")), qPrintable(w.bannerText()));
    QTest::qWait(100);
    shot(w, "student-3-finished");
  }

  void alarmInThai() {
    // The window starts in the remembered language.
    QSettings(QStringLiteral("Klueng"), QStringLiteral("klueng"))
        .setValue(QStringLiteral("ui/language"), QStringLiteral("th"));
    MainWindow w;
    w.resize(1280, 800);
    w.show();
    QVERIFY(waitIdle(w));
    // Feeding with the spindle stopped: the alarm stops the run on file line 9.
    w.editor()->setPlainText(QStringLiteral("G21 G99\nT0101 G00 X60. Z5.\nG01 X40. Z-10. F0.2\nM30\n"));
    QVERIFY(waitIdle(w));
    w.runController()->setSpeed(RunController::kAsFastAsPossible);
    w.action(QStringLiteral("actionGo"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(w.runController()->state(), RunState::Alarm, 20000);
    QCOMPARE(w.editor()->executingFileLine(), 9);
    QVERIFY2(w.bannerText().startsWith(QStringLiteral("สัญญาณเตือน")), qPrintable(w.bannerText()));
    QTest::qWait(100);
    shot(w, "student-4-alarm-th");

    ToolSelectDialog tools(w.configDir());
    tools.show();
    QVERIFY(QTest::qWaitForWindowExposed(&tools));
    shot(tools, "dialog-tool-select-th");
    OffsetDefineDialog offsets(w.configDir());
    offsets.show();
    QVERIFY(QTest::qWaitForWindowExposed(&offsets));
    shot(offsets, "dialog-offset-define-th");
    QSettings(QStringLiteral("Klueng"), QStringLiteral("klueng")).clear();
    Language::instance()->setLanguage(QStringLiteral("en"));
  }
};

KLUENG_GUI_TEST(StudentSessionTest)
#include "student_session_test.moc"

// One undo history per document for the text and the setup (issue 30 item 2, as
// Tiled does it): Job details, Tool Select, Offset Define and the editor's typing
// are commands on the document's stack, the command is the edit (in memory),
// Edit > Undo is the one Undo, and File > Save writes tools.cfg / offset.cfg.
#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QTextCursor>
#include <QTimer>
#include <QUndoStack>

#include "gui_test_runner.h"
#include "gui/code_editor.h"
#include "gui/document.h"
#include "gui/document_manager.h"
#include "gui/job_details_dialog.h"
#include "gui/main_window.h"
#include "gui/offset_define_dialog.h"
#include "gui/resources.h"
#include "gui/run_controller.h"
#include "gui/tool_select_dialog.h"
#include "klueng/core/io/tool_config.h"

using namespace klueng;
using namespace klueng::gui;

namespace {

bool copyFile(const QDir& from, const QDir& to, const QString& name) {
  to.mkpath(QFileInfo(to.filePath(name)).absolutePath());
  return QFile::copy(from.filePath(name), to.filePath(name)) &&
         QFile(to.filePath(name)).setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner);
}

QByteArray readAll(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Runs `fill` on the next modal dialog of type D, then accepts it.
template <typename D, typename F>
void acceptNextDialog(F fill) {
  QTimer::singleShot(0, [fill] {
    QVERIFY(QTest::qWaitFor([] { return qobject_cast<D*>(QApplication::activeModalWidget()); }, 5000));
    auto* d = qobject_cast<D*>(QApplication::activeModalWidget());
    fill(*d);
    d->accept();
  });
}

// Presses `button` on the next message box and keeps its text.
void answerNextBox(const char* button, QString* text) {
  QTimer::singleShot(0, [button, text] {
    QVERIFY(QTest::qWaitFor([] { return qobject_cast<QMessageBox*>(QApplication::activeModalWidget()); }, 5000));
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    *text = box->objectName() + QLatin1Char(':') + box->text();
    box->findChild<QPushButton*>(QString::fromLatin1(button))->click();
  });
}

}  // namespace

class SetupUndoTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    initResources();
    // This process's own settings and recovery folder; the setup folder is a copy the window may write.
    qputenv("XDG_CONFIG_HOME", home_.filePath(QStringLiteral("config")).toUtf8());
    qputenv("XDG_DATA_HOME", home_.filePath(QStringLiteral("data")).toUtf8());
    const QDir src(QStringLiteral(KLUENG_SOURCE_DIR));
    const QDir dst(config_.path());
    for (const char* name : {"tools.cfg", "offset.cfg", "machine.cfg"})
      QVERIFY(copyFile(src, dst, QString::fromLatin1(name)));
    for (const QString& bmp :
         QDir(src.filePath(QStringLiteral("resources/tools"))).entryList({QStringLiteral("*.bmp")}))
      QVERIFY(copyFile(src, dst, QStringLiteral("resources/tools/") + bmp));
    qputenv("KLUENG_DATA_DIR", config_.path().toUtf8());
    QVERIFY(QFile::copy(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt"),
                        work_.filePath(QStringLiteral("shaft.txt"))));
    QFile(work_.filePath(QStringLiteral("shaft.txt"))).setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner);
    tools_ = readAll(config_.filePath(QStringLiteral("tools.cfg")));
    offsets_ = readAll(config_.filePath(QStringLiteral("offset.cfg")));
  }

  void init() {
    // Every test starts from the shipped setup: a test that saved leaves nothing behind.
    for (const auto& [name, bytes] : {std::pair{"tools.cfg", &tools_}, std::pair{"offset.cfg", &offsets_}}) {
      QFile f(config_.filePath(QString::fromLatin1(name)));
      QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
      QCOMPARE(f.write(*bytes), bytes->size());
    }
  }

  void jobDetailsUndoAndRedo() {
    MainWindow w;
    QVERIFY(w.openFile(work_.filePath(QStringLiteral("shaft.txt"))));
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    QCOMPARE(w.document()->header().diameter, 50.0);
    QAction* undo = w.action(QStringLiteral("actionUndo"));
    QAction* redo = w.action(QStringLiteral("actionRedo"));
    QVERIFY(!undo->isEnabled());
    acceptNextDialog<JobDetailsDialog>(
        [](JobDetailsDialog& d) { d.findChild<QDoubleSpinBox*>(QStringLiteral("diameter"))->setValue(40.0); });
    w.action(QStringLiteral("actionJobDetails"))->trigger();
    QCOMPARE(w.document()->header().diameter, 40.0);
    QVERIFY(w.document()->isHeaderModified());
    QVERIFY(undo->isEnabled());
    QCOMPARE(undo->text(), QStringLiteral("&Undo Job Details"));
    undo->trigger();
    QCOMPARE(w.document()->header().diameter, 50.0);
    QVERIFY(!w.document()->isHeaderModified());  // exactly as it was: unmodified again
    QVERIFY(!w.isWindowModified());
    QVERIFY(redo->isEnabled());
    redo->trigger();
    QCOMPARE(w.document()->header().diameter, 40.0);
    // Typing is a step of the same history, after the header's.
    QTest::keyClicks(w.editor(), QStringLiteral("G00 "));
    QCOMPARE(w.undoStack()->count(), 2);
    QCOMPARE(undo->text(), QStringLiteral("&Undo Typing"));
    // A new document starts a new history.
    QVERIFY(w.saveFile(work_.filePath(QStringLiteral("shaft2.txt"))));
    w.newFile();
    QCOMPARE(w.undoStack()->count(), 0);
    QVERIFY(!undo->isEnabled());
  }

  // A tool edit is in memory: the run uses it at once, tools.cfg is unchanged until
  // File > Save, and Undo puts back the row and the run's tool. (A library insert the
  // program's cuts suit, so the job keeps it: a boring bar there would be replaced.)
  void aToolEditIsUndoneAndSavedOnlyBySave() {
    MainWindow w;
    QVERIFY(w.openFile(work_.filePath(QStringLiteral("shaft.txt"))));
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    const QString cfg = QDir(w.configDir()).filePath(QStringLiteral("tools.cfg"));
    QCOMPARE(QDir(w.configDir()).absolutePath(), QDir(config_.path()).absolutePath());
    const std::string oldTool = w.jobDocument().setup().tools.bitmap[0];
    QCOMPARE(oldTool, std::string("resources/tools/01-outside-turning.bmp"));
    acceptNextDialog<ToolSelectDialog>(
        [](ToolSelectDialog& d) { d.setLibraryTool(1, QStringLiteral("cnmg-80-r04"), false); });
    w.action(QStringLiteral("actionToolSelect"))->trigger();
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    QCOMPARE(QString::fromStdString(w.jobDocument().setup().tools.bitmap[0]), QStringLiteral("library:cnmg-80-r04"));
    QCOMPARE(QString::fromStdString(w.runController()->machineSetup().tools.bitmap[0]),
             QStringLiteral("library:cnmg-80-r04"));
    QCOMPARE(readAll(cfg), tools_);  // nothing written yet
    QVERIFY(w.isWindowModified());   // the title's '*'
    QVERIFY(w.windowTitle().contains(QStringLiteral("[*]")));
    QCOMPARE(w.undoStack()->undoText(), QStringLiteral("Tool Select"));

    w.action(QStringLiteral("actionUndo"))->trigger();
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    QCOMPARE(w.jobDocument().setup().tools.bitmap[0], oldTool);
    QCOMPARE(QString::fromStdString(w.runController()->machineSetup().tools.bitmap[0]),
             QString::fromStdString(oldTool));  // the run's tool is the old one
    QVERIFY(!w.isWindowModified());
    QCOMPARE(readAll(cfg), tools_);

    w.action(QStringLiteral("actionRedo"))->trigger();
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    QCOMPARE(readAll(cfg), tools_);
    QVERIFY(w.save());
    const auto saved = core::io::readToolTable(cfg.toStdString());
    QVERIFY(saved.ok());
    QCOMPARE(saved.value->bitmap[0], std::string("library:cnmg-80-r04"));
    QCOMPARE(saved.value->bitmap[1], std::string("resources/tools/02-outside-left-hand.bmp"));
    QCOMPARE(readAll(QDir(w.configDir()).filePath(QStringLiteral("offset.cfg"))), offsets_);  // not edited: not written
    QVERIFY(!w.isWindowModified());
  }

  // Tool Select's "Only for this program (tools.cfg is not changed)": Save keeps the promise.
  void aStationForThisProgramNeverWritesToolsCfg() {
    MainWindow w;
    QVERIFY(w.openFile(work_.filePath(QStringLiteral("shaft.txt"))));
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    acceptNextDialog<ToolSelectDialog>(
        [](ToolSelectDialog& d) { d.setLibraryTool(1, QStringLiteral("cnmg-80-r04"), true); });
    w.action(QStringLiteral("actionToolSelect"))->trigger();
    QCOMPARE(w.jobDocument().overrides().size(), std::size_t(1));
    QVERIFY(w.isWindowModified());
    QVERIFY(w.save());
    QVERIFY(!w.isWindowModified());
    QCOMPARE(readAll(QDir(w.configDir()).filePath(QStringLiteral("tools.cfg"))), tools_);
    // Remembered for this file: opened again, the station is still this program's.
    MainWindow again;
    QVERIFY(again.openFile(work_.filePath(QStringLiteral("shaft.txt"))));
    QVERIFY(QTest::qWaitFor([&] { return !again.isBusy(); }, 20000));
    QCOMPARE(again.jobDocument().overrides().size(), std::size_t(1));
    QCOMPARE(again.jobDocument().overrides()[0].libraryId, std::string("cnmg-80-r04"));
  }

  // Text and setup share one history, undone in the order made; Ctrl+Z in the editor is the same Undo.
  void anOffsetEditAfterATextEditIsUndoneFirst() {
    MainWindow w;
    QVERIFY(w.openFile(work_.filePath(QStringLiteral("shaft.txt"))));
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    const QString original = w.editor()->toPlainText();
    QTextCursor c(w.editor()->document());
    c.movePosition(QTextCursor::End);
    w.editor()->setTextCursor(c);
    QTest::keyClicks(w.editor(), QStringLiteral("(A NOTE)"));
    QCOMPARE(w.editor()->toPlainText(), original + QStringLiteral("(A NOTE)"));
    acceptNextDialog<OffsetDefineDialog>([](OffsetDefineDialog& d) { d.setCell(0, 2, QStringLiteral("0.4")); });
    w.action(QStringLiteral("actionOffsetDefine"))->trigger();
    QCOMPARE(w.jobDocument().setup().offsets.at(1).r, 0.4);
    QCOMPARE(w.runController()->machineSetup().offsets.at(1).r, 0.4);  // the run uses it at once
    QCOMPARE(w.undoStack()->count(), 2);
    QCOMPARE(w.action(QStringLiteral("actionUndo"))->text(), QStringLiteral("&Undo Offset Define"));

    // Ctrl+Z with the focus in the editor undoes the last step, the offsets, not the text.
    w.show();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    w.editor()->setFocus();
    QTest::keyClick(w.editor(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(w.jobDocument().setup().offsets.at(1).r, 0.8);
    QCOMPARE(w.runController()->machineSetup().offsets.at(1).r, 0.8);
    QCOMPARE(w.editor()->toPlainText(), original + QStringLiteral("(A NOTE)"));
    w.action(QStringLiteral("actionUndo"))->trigger();
    QCOMPARE(w.editor()->toPlainText(), original);
    QCOMPARE(w.jobDocument().setup().offsets.at(1).r, 0.8);
    QVERIFY(!w.isWindowModified());
    w.action(QStringLiteral("actionRedo"))->trigger();
    QCOMPARE(w.editor()->toPlainText(), original + QStringLiteral("(A NOTE)"));
    QCOMPARE(w.jobDocument().setup().offsets.at(1).r, 0.8);
    w.action(QStringLiteral("actionRedo"))->trigger();
    QCOMPARE(w.jobDocument().setup().offsets.at(1).r, 0.4);
    QCOMPARE(readAll(QDir(w.configDir()).filePath(QStringLiteral("offset.cfg"))), offsets_);
    QString asked;
    answerNextBox("discardButton", &asked);
    QVERIFY(w.close());
  }

  // Typing that goes on where it stopped, after a setup edit, is a step of its own: the
  // editor would join it to the typing before the setup edit, undone in the wrong order.
  void typingAfterASetupEditIsItsOwnStep() {
    MainWindow w;
    QVERIFY(w.openFile(work_.filePath(QStringLiteral("shaft.txt"))));
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    const QString original = w.editor()->toPlainText();
    QTextCursor c(w.editor()->document());
    c.movePosition(QTextCursor::End);
    w.editor()->setTextCursor(c);
    QTest::keyClicks(w.editor(), QStringLiteral("(A"));
    acceptNextDialog<OffsetDefineDialog>([](OffsetDefineDialog& d) { d.setCell(0, 2, QStringLiteral("0.4")); });
    w.action(QStringLiteral("actionOffsetDefine"))->trigger();
    QTest::keyClicks(w.editor(), QStringLiteral("B)"));
    QCOMPARE(w.undoStack()->count(), 3);
    w.action(QStringLiteral("actionUndo"))->trigger();
    QCOMPARE(w.editor()->toPlainText(), original + QStringLiteral("(A"));
    QCOMPARE(w.jobDocument().setup().offsets.at(1).r, 0.4);
    w.action(QStringLiteral("actionUndo"))->trigger();
    QCOMPARE(w.jobDocument().setup().offsets.at(1).r, 0.8);
    w.action(QStringLiteral("actionUndo"))->trigger();
    QCOMPARE(w.editor()->toPlainText(), original);
    QVERIFY(!w.isWindowModified());  // all undone: nothing to save
    // Typed again after an undo, the editor's redo is given up, and so is the stack's.
    QTest::keyClicks(w.editor(), QStringLiteral("C"));
    QCOMPARE(w.undoStack()->count(), 1);
    QVERIFY(!w.action(QStringLiteral("actionRedo"))->isEnabled());
    w.action(QStringLiteral("actionUndo"))->trigger();
    QCOMPARE(w.editor()->toPlainText(), original);
  }

  void theEditMenuHasOneUndo() {
    MainWindow w;
    QMenu* edit = w.findChild<QMenu*>(QStringLiteral("menuEdit"));
    QVERIFY(edit);
    QStringList undos;
    for (QAction* a : edit->actions())
      if (a->text().contains(QStringLiteral("Undo")) || a->text().contains(QStringLiteral("Redo")))
        undos << a->objectName();
    QCOMPARE(undos, (QStringList{QStringLiteral("actionUndo"), QStringLiteral("actionRedo")}));
    QCOMPARE(w.action(QStringLiteral("actionUndo"))->shortcut(), QKeySequence(QKeySequence::Undo));
  }

  // Closing with only a setup change unsaved asks, as for a program; Cancel keeps the window.
  void closingWithAnUnsavedSetupAsks() {
    MainWindow w;
    QVERIFY(w.openFile(work_.filePath(QStringLiteral("shaft.txt"))));
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    acceptNextDialog<OffsetDefineDialog>([](OffsetDefineDialog& d) { d.setCell(2, 0, QStringLiteral("1.5")); });
    w.action(QStringLiteral("actionOffsetDefine"))->trigger();
    QVERIFY(w.isWindowModified());
    QString asked;
    answerNextBox("cancelButton", &asked);
    QVERIFY(!w.close());
    QCOMPARE(asked, QStringLiteral("unsavedChangesBox:The tool or offset tables have been changed."));
    answerNextBox("saveButton", &asked);
    QVERIFY(w.close());
    const auto saved =
        core::io::readOffsetTable(QDir(w.configDir()).filePath(QStringLiteral("offset.cfg")).toStdString());
    QVERIFY(saved.ok());
    QCOMPARE(saved.value->at(3).x, 1.5);
  }

  // The autosave keeps an unsaved setup edit; a window restoring the copy has it again, unsaved.
  void anUnsavedSetupEditIsRecovered() {
    QString copyId;
    {
      MainWindow w;
      QVERIFY(w.openFile(work_.filePath(QStringLiteral("shaft.txt"))));
      QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
      acceptNextDialog<OffsetDefineDialog>([](OffsetDefineDialog& d) { d.setCell(4, 2, QStringLiteral("0.2")); });
      w.action(QStringLiteral("actionOffsetDefine"))->trigger();
      w.documentManager()->autosave();
      // As if this window were killed now: its copy, under an id no running Klueng holds.
      const QDir folder(w.documentManager()->recovery().folder());
      const QString id = w.documentManager()->sessionId();
      copyId = QStringLiteral("crashed-") + id;
      QVERIFY(
          QFile::copy(folder.filePath(id + QStringLiteral(".nc")), folder.filePath(copyId + QStringLiteral(".nc"))));
      QVERIFY(
          QFile::copy(folder.filePath(id + QStringLiteral(".ini")), folder.filePath(copyId + QStringLiteral(".ini"))));
      QSettings(folder.filePath(copyId + QStringLiteral(".ini")), QSettings::IniFormat)
          .setValue(QStringLiteral("pid"), 0x7ffffff0);  // no such process
      QString asked;
      answerNextBox("discardButton", &asked);
      QVERIFY(w.close());
    }
    QCOMPARE(readAll(config_.filePath(QStringLiteral("offset.cfg"))), offsets_);
    MainWindow w;
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    RecoveryCopy copy;
    for (const RecoveryCopy& c : w.documentManager()->recovery().orphans())
      if (c.id == copyId) copy = c;
    QCOMPARE(copy.id, copyId);
    QVERIFY(copy.setup.present);
    w.documentManager()->restoreRecovery(copy);
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy() && w.jobDocument().isSetupModified(); }, 20000));
    QCOMPARE(w.jobDocument().setup().offsets.at(5).r, 0.2);
    QCOMPARE(w.runController()->machineSetup().offsets.at(5).r, 0.2);
    QVERIFY(w.isWindowModified());
    QCOMPARE(readAll(config_.filePath(QStringLiteral("offset.cfg"))), offsets_);
    QString asked;
    answerNextBox("discardButton", &asked);
    QVERIFY(w.close());
  }

  void anUnchangedDialogIsNoStep() {
    MainWindow w;
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    acceptNextDialog<OffsetDefineDialog>([](OffsetDefineDialog&) {});
    w.action(QStringLiteral("actionOffsetDefine"))->trigger();
    QCOMPARE(w.undoStack()->count(), 0);
    QVERIFY(!w.isWindowModified());
  }

 private:
  QTemporaryDir home_;
  QTemporaryDir config_;
  QTemporaryDir work_;
  QByteArray tools_, offsets_;
};

KLUENG_GUI_TEST(SetupUndoTest)
#include "setup_undo_test.moc"

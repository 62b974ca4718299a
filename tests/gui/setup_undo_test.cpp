// Undo for Job details, tool and offset edits (issue 12): one undo stack per
// document, beside the editor's own text undo.
#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include "gui_test_runner.h"
#include "gui/code_editor.h"
#include "gui/document.h"
#include "gui/job_details_dialog.h"
#include "gui/main_window.h"
#include "gui/offset_define_dialog.h"
#include "gui/resources.h"
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

}  // namespace

class SetupUndoTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    initResources();
    // The window's setup folder is a copy: Offset Define writes into it.
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
  }

  void jobDetailsUndoAndRedo() {
    MainWindow w;
    QVERIFY(w.openFile(work_.filePath(QStringLiteral("shaft.txt"))));
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    QCOMPARE(w.document()->header().diameter, 50.0);
    QAction* undo = w.action(QStringLiteral("actionUndoSetup"));
    QAction* redo = w.action(QStringLiteral("actionRedoSetup"));
    QVERIFY(!undo->isEnabled());
    acceptNextDialog<JobDetailsDialog>(
        [](JobDetailsDialog& d) { d.findChild<QDoubleSpinBox*>(QStringLiteral("diameter"))->setValue(40.0); });
    w.action(QStringLiteral("actionJobDetails"))->trigger();
    QCOMPARE(w.document()->header().diameter, 40.0);
    QVERIFY(w.document()->isHeaderModified());
    QVERIFY(undo->isEnabled());
    QCOMPARE(undo->statusTip(), QStringLiteral("Undo: Job details"));
    undo->trigger();
    QCOMPARE(w.document()->header().diameter, 50.0);
    QVERIFY(!w.document()->isHeaderModified());  // exactly as it was: unmodified again
    QVERIFY(!w.isWindowModified());
    QVERIFY(redo->isEnabled());
    redo->trigger();
    QCOMPARE(w.document()->header().diameter, 40.0);
    // The editor's text undo is its own: typing does not touch this stack.
    QTest::keyClicks(w.editor(), QStringLiteral("G00 "));
    QCOMPARE(w.setupUndoStack()->count(), 1);
    // A new document starts a new history.
    w.document()->setHeader(w.document()->header());  // (keeps the prompt away: saved below)
    QVERIFY(w.saveFile(work_.filePath(QStringLiteral("shaft2.txt"))));
    w.newFile();
    QCOMPARE(w.setupUndoStack()->count(), 0);
    QVERIFY(!undo->isEnabled());
  }

  void offsetDefineUndoRestoresTheFile() {
    MainWindow w;
    QVERIFY(w.openFile(work_.filePath(QStringLiteral("shaft.txt"))));
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    const QString offsets = QDir(w.configDir()).filePath(QStringLiteral("offset.cfg"));
    QCOMPARE(QDir(w.configDir()).absolutePath(), QDir(config_.path()).absolutePath());
    const QByteArray original = readAll(offsets);
    acceptNextDialog<OffsetDefineDialog>([](OffsetDefineDialog& d) { d.setCell(0, 2, QStringLiteral("0.4")); });
    w.action(QStringLiteral("actionOffsetDefine"))->trigger();
    const QByteArray edited = readAll(offsets);
    QVERIFY(edited != original);
    QCOMPARE(core::io::readOffsetTable(offsets.toStdString()).value->at(1).r, 0.4);
    QCOMPARE(w.runController()->machineSetup().offsets.at(1).r, 0.4);  // the run uses it at once
    QCOMPARE(w.setupUndoStack()->undoText(), QStringLiteral("Offset Define"));
    w.action(QStringLiteral("actionUndoSetup"))->trigger();
    QCOMPARE(readAll(offsets), original);
    QCOMPARE(w.runController()->machineSetup().offsets.at(1).r, 0.8);
    w.action(QStringLiteral("actionRedoSetup"))->trigger();
    QCOMPARE(readAll(offsets), edited);
    QCOMPARE(w.runController()->machineSetup().offsets.at(1).r, 0.4);
    w.action(QStringLiteral("actionUndoSetup"))->trigger();
    QCOMPARE(readAll(offsets), original);
  }

  void anUnchangedDialogIsNoStep() {
    MainWindow w;
    QVERIFY(QTest::qWaitFor([&] { return !w.isBusy(); }, 20000));
    acceptNextDialog<OffsetDefineDialog>([](OffsetDefineDialog&) {});
    w.action(QStringLiteral("actionOffsetDefine"))->trigger();
    QCOMPARE(w.setupUndoStack()->count(), 0);
  }

 private:
  QTemporaryDir config_;
  QTemporaryDir work_;
};

KLUENG_GUI_TEST(SetupUndoTest)
#include "setup_undo_test.moc"

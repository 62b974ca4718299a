// Issue 29 in the GUI (offscreen): Save over a read-only file asks whether to
// save elsewhere and never writes over it; Export PDF on a full disk says so,
// keeps the old PDF and never says "Exported"; the program is never the PDF.
#include <QApplication>
#include <QFile>
#include <QFileDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <csignal>
#include <sys/resource.h>

#include "gui_test_runner.h"
#include "fresh_user_folders.h"
#include "gui/code_editor.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/resources.h"

using namespace klueng::gui;

namespace {

QByteArray readAll(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeAll(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size() && f.flush();
}

// Each modal message box: its title, text and informative text recorded, then
// the button with object name `click` pressed (else the box is rejected).
class BoxAnswerer {
 public:
  explicit BoxAnswerer(QString click = {}) : click_(std::move(click)) {
    QObject::connect(&timer_, &QTimer::timeout, [this] {
      auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
      if (!box) return;
      boxes_ << box->objectName() + QStringLiteral("|") + box->windowTitle() + QStringLiteral("|") + box->text() +
                    QStringLiteral("|") + box->informativeText();
      if (auto* button = click_.isEmpty() ? nullptr : box->findChild<QPushButton*>(click_))
        button->click();
      else
        box->reject();
    });
    timer_.start(20);
  }
  QStringList boxes() const { return boxes_; }

 private:
  QString click_;
  QTimer timer_;
  QStringList boxes_;
};

// A "full disk" any CI container can make: the file size limit fails writes
// past it with EFBIG (SIGXFSZ ignored), root included, without a mount.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    oldHandler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, oldHandler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*oldHandler_)(int) = nullptr;
};

const QByteArray kProgram = "G21 G99\nT0101\nG00 X52. Z2.\nM30\n";

}  // namespace

class SafeSaveTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    klueng::test::freshUserFolders();
    initResources();
  }
  void init() { Language::instance()->setLanguage(QStringLiteral("en")); }

  // Ctrl+S over a 0444 file: asked, Cancel keeps the file and the edits.
  void saveOverAReadOnlyFileAsksAndKeepsIt() {
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("part.nc"));
    QVERIFY(writeAll(path, kProgram));
    // Read-only before it is opened (a chmod while open is a change on disk, with its own question).
    QVERIFY(QFile::setPermissions(path, QFileDevice::ReadOwner | QFileDevice::ReadGroup | QFileDevice::ReadOther));
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(path));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    w.editor()->moveCursor(QTextCursor::End);
    w.editor()->insertPlainText(QStringLiteral("(my edit)\n"));
    {
      BoxAnswerer answer(QStringLiteral("cancelButton"));
      w.action(QStringLiteral("actionSave"))->trigger();  // Ctrl+S
      QTRY_COMPARE(answer.boxes().size(), 1);
      QCOMPARE(answer.boxes()[0], QStringLiteral("readOnlyBox|Read-only file|\"%1\" is read-only, so Klueng will not "
                                                 "write over it.|Save your program under another name?")
                                      .arg(path));
    }
    QCOMPARE(readAll(path), kProgram);
    QVERIFY(w.editor()->document()->isModified());
    QCOMPARE(QFile::permissions(path) & QFileDevice::WriteOwner, QFileDevice::Permissions());  // never chmod'ed

    // In Thai too.
    Language::instance()->setLanguage(QStringLiteral("th"));
    {
      BoxAnswerer answer(QStringLiteral("cancelButton"));
      QVERIFY(!w.saveFile(path));
      QTRY_COMPARE(answer.boxes().size(), 1);
      QCOMPARE(answer.boxes()[0], QStringLiteral("readOnlyBox|ไฟล์แบบอ่านอย่างเดียว|\"%1\" เป็นไฟล์แบบอ่านอย่างเดียว "
                                                 "Klueng จึงจะไม่บันทึกทับไฟล์นี้|ต้องการบันทึกชุดรหัสสั่งการทำงานเป็นชื่ออื่นหรือไม่?")
                                      .arg(path));
    }
    Language::instance()->setLanguage(QStringLiteral("en"));

    // Save As... from the box: the file dialog, another name, the edits saved there.
    const QString other = tmp.filePath(QStringLiteral("part-mine.nc"));
    bool dialogSeen = false;
    QStringList unexpected;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, [&] {
      if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
        unexpected << box->objectName();
        if (auto* b = box->findChild<QPushButton*>(QStringLiteral("saveAsButton")))
          b->click();
        else
          box->reject();  // never hang on a question this test does not expect
      } else if (auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget())) {
        if (dialogSeen) return;
        dialogSeen = true;
        // Typed into the name field, then accepted from the event loop, so this poll keeps
        // answering any question the dialog might ask.
        dialog->selectFile(other);
        if (auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))) name->setText(other);
        QMetaObject::invokeMethod(dialog, "accept", Qt::QueuedConnection);
      }
    });
    poll.start(20);
    QVERIFY(w.save());
    poll.stop();
    QVERIFY(dialogSeen);
    QCOMPARE(unexpected, QStringList{QStringLiteral("readOnlyBox")});
    QCOMPARE(readAll(path), kProgram);
    QVERIFY(readAll(other).endsWith("(my edit)\n"));
    QVERIFY(!w.editor()->document()->isModified());
  }

  // Export PDF on a full disk: the old PDF keeps its bytes, a message says why, no "Exported".
  void exportPdfOnAFullDiskSaysSoAndKeepsTheOldPdf() {
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("part.nc"));
    QVERIFY(writeAll(path, kProgram));
    MainWindow w;
    w.show();
    QVERIFY(w.openFile(path));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    const QString pdf = tmp.filePath(QStringLiteral("part.pdf"));
    const QByteArray old(3000, 'p');
    QVERIFY(writeAll(pdf, old));
    w.statusBar()->clearMessage();
    {
      BoxAnswerer answer;
      bool exported = true;
      {
        const FileSizeLimit limit(4096);
        exported = w.exportPdf(pdf);
      }
      QVERIFY(!exported);
      QTRY_COMPARE(answer.boxes().size(), 1);
      QCOMPARE(answer.boxes()[0],
               QStringLiteral("|Export PDF|Cannot write %1\n\n%1: cannot write the file: there is no space for it (the "
                              "disk is full, or the file is over the size allowed); an existing file of that name is "
                              "left unchanged|")
                   .arg(pdf));
    }
    QCOMPARE(readAll(pdf), old);
    QVERIFY2(!w.statusBar()->currentMessage().contains(QStringLiteral("Exported")),
             qPrintable(w.statusBar()->currentMessage()));
    QCOMPARE(QDir(tmp.path()).entryList(QDir::Files | QDir::Hidden).size(), 2);  // no temporary file left

    // The program is never the PDF's name.
    {
      BoxAnswerer answer;
      QVERIFY(!w.exportPdf(path));
      QTRY_COMPARE(answer.boxes().size(), 1);
      QVERIFY2(answer.boxes()[0].contains(QStringLiteral("this output is the input file")),
               qPrintable(answer.boxes()[0]));
    }
    QCOMPARE(readAll(path), kProgram);

    // And with room, it is written and said.
    QVERIFY(w.exportPdf(pdf));
    QVERIFY(readAll(pdf).startsWith("%PDF"));
    QVERIFY(w.statusBar()->currentMessage().startsWith(QStringLiteral("Exported")));
  }
};

KLUENG_GUI_TEST(SafeSaveTest)
#include "safe_save_test.moc"

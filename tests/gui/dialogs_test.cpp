// Tool Select, Offset Define and Job details against the core's file formats:
// what the dialogs write is what the loader reads back (temp config folders).
#include <QApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <unistd.h>

#include "gui_test_runner.h"
#include "gui/job_details_dialog.h"
#include "gui/offset_define_dialog.h"
#include "gui/setup_save.h"
#include "gui/tool_select_dialog.h"
#include "klueng/core/io/tool_config.h"

using namespace klueng;
using namespace klueng::gui;

namespace {

// A private copy of the shipped configuration: cfg files and the bitmaps they name.
bool makeConfigCopy(const QString& to) {
  const QDir src(QStringLiteral(KLUENG_SOURCE_DIR));
  QDir dst(to);
  for (const char* name : {"tools.cfg", "offset.cfg", "machine.cfg"})
    if (!QFile::copy(src.filePath(QString::fromLatin1(name)), dst.filePath(QString::fromLatin1(name)))) return false;
  dst.mkpath(QStringLiteral("resources/tools"));
  for (const QString& bmp : QDir(src.filePath(QStringLiteral("resources/tools"))).entryList({QStringLiteral("*.bmp")}))
    QFile::copy(src.filePath(QStringLiteral("resources/tools/") + bmp),
                dst.filePath(QStringLiteral("resources/tools/") + bmp));
  for (const char* name : {"tools.cfg", "offset.cfg"})
    QFile(dst.filePath(QString::fromLatin1(name))).setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner);
  return true;
}

QByteArray readAll(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Closes the next message box (the dialogs' refusals) and remembers its text.
void closeNextMessageBox(QString* text) {
  QTimer::singleShot(0, [text] {
    if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
      if (text) *text = box->text();
      box->close();
    }
  });
}

}  // namespace

class DialogsTest : public QObject {
  Q_OBJECT
 private slots:
  void toolSelectRoundTripsToolsCfg() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    const auto before = *core::io::readToolTable(dir.filePath(QStringLiteral("tools.cfg")).toStdString()).value;
    ToolSelectDialog d(dir.path());
    QVERIFY(d.loadDiagnostics().isEmpty());
    d.setCurrentTool(1);
    QVERIFY(!d.previewSprite().isNull());
    // Tool 01 with offset 01 (tip 3): the controlled point is the lower-left corner of the edge box.
    const QRect box = d.previewSprite().cuttingEdgeBox();
    QCOMPARE(d.previewSprite().controlledPointPx(), QPointF(box.left(), box.bottom() + 1));

    d.setBitmapName(3, QStringLiteral("resources/tools/05-boring-bar.bmp"));
    d.setBitmapName(8, QString());
    const QByteArray original = readAll(dir.filePath(QStringLiteral("tools.cfg")));
    d.accept();
    QCOMPARE(d.result(), int(QDialog::Accepted));
    // The edited table, as File > Save will write it; the dialog itself writes nothing (issue 30 item 2).
    QVERIFY(d.toolsChanged());
    QCOMPARE(readAll(dir.filePath(QStringLiteral("tools.cfg"))), original);
    const auto after =
        core::io::parseToolTable(core::io::formatToolTable(d.toolTable()), dir.path().toStdString(), "tools.cfg");
    QVERIFY(after.value.has_value());
    QCOMPARE(after.value->bitmap[2], std::string("resources/tools/05-boring-bar.bmp"));
    QCOMPARE(after.value->bitmap[7], std::string());
    for (int i : {0, 1, 3, 4, 5, 6})
      QCOMPARE(after.value->bitmap[static_cast<std::size_t>(i)], before.bitmap[static_cast<std::size_t>(i)]);
  }

  void toolSelectRefusesAMissingBitmap() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    const QByteArray original = readAll(dir.filePath(QStringLiteral("tools.cfg")));
    ToolSelectDialog d(dir.path());
    d.setBitmapName(2, QStringLiteral("resources/tools/no-such-tool.bmp"));
    QVERIFY(d.previewSprite().isNull());
    QString message;
    closeNextMessageBox(&message);
    d.accept();
    QVERIFY(d.result() != QDialog::Accepted);
    QVERIFY2(message.contains(QStringLiteral("no-such-tool.bmp")), qPrintable(message));
    QCOMPARE(readAll(dir.filePath(QStringLiteral("tools.cfg"))), original);
  }

  // Saving a setup edited in a read-only folder asks (issue 29 item 2 for programs, issue 30
  // item 2): Cancel writes nothing; "Save to My Setup Folder" writes the per-user copy.
  void savingAReadOnlySetupAsksForTheUsersOwnFolder() {
    // A shared folder the user may read but not write (/usr/share/klueng). Root may write
    // anything, so as root the save runs as the user "nobody" (seteuid) against a folder
    // that nobody may write: the same test as root and as a normal user, never skipped.
    QTemporaryDir dir;
    QTemporaryDir home;
    QVERIFY(makeConfigCopy(dir.path()));
    const QByteArray originalTools = readAll(dir.filePath(QStringLiteral("tools.cfg")));
    const QFileDevice::Permissions readable = QFileDevice::ReadOwner | QFileDevice::ReadGroup | QFileDevice::ReadOther;
    QFile(dir.filePath(QStringLiteral("tools.cfg"))).setPermissions(readable);
    QFile(dir.filePath(QStringLiteral("offset.cfg"))).setPermissions(readable);
    const QFileDevice::Permissions listable =
        readable | QFileDevice::ExeOwner | QFileDevice::ExeGroup | QFileDevice::ExeOther;
    QFile(dir.path()).setPermissions(listable);
    QFile(dir.filePath(QStringLiteral("resources"))).setPermissions(listable);
    QFile(dir.filePath(QStringLiteral("resources/tools"))).setPermissions(listable);
    for (const QString& bmp :
         QDir(dir.filePath(QStringLiteral("resources/tools"))).entryList({QStringLiteral("*.bmp")}))
      QFile(dir.filePath(QStringLiteral("resources/tools/") + bmp)).setPermissions(readable);
    QFile(home.path())
        .setPermissions(listable | QFileDevice::WriteOwner | QFileDevice::WriteGroup | QFileDevice::WriteOther);
    const QByteArray oldHome = qgetenv("XDG_DATA_HOME");
    qputenv("XDG_DATA_HOME", home.path().toUtf8());
    const bool root = ::geteuid() == 0;
    if (root) QCOMPARE(::seteuid(65534), 0);
    core::io::ToolTable tools = *core::io::readToolTable(dir.filePath(QStringLiteral("tools.cfg")).toStdString()).value;
    tools.folder = dir.path().toStdString();
    tools.bitmap[3] = "resources/tools/01-outside-turning.bmp";
    const core::io::OffsetTable offsets =
        *core::io::readOffsetTable(dir.filePath(QStringLiteral("offset.cfg")).toStdString()).value;
    SetupToSave what{dir.path(), &tools, &offsets, true, false};
    QStringList asked;  // the box's text, each time; the button named is pressed
    const auto answer = [&asked](const char* button) {
      QTimer::singleShot(0, [&asked, button] {
        QVERIFY(QTest::qWaitFor([] { return qobject_cast<QMessageBox*>(QApplication::activeModalWidget()); }, 5000));
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        asked << box->objectName() + QLatin1Char(':') + box->text();
        box->findChild<QPushButton*>(QString::fromLatin1(button))->click();
      });
    };
    const bool writable = setupFolderWritable(dir.path());
    answer("cancelButton");
    const QString cancelled = saveSetupFiles(nullptr, what);
    answer("ownFolderButton");
    const QString savedDir = saveSetupFiles(nullptr, what);
    if (root) QCOMPARE(::seteuid(0), 0);
    qputenv("XDG_DATA_HOME", oldHome);
    QVERIFY(!writable);
    QVERIFY(cancelled.isEmpty());
    QCOMPARE(asked.size(), 2);
    QCOMPARE(asked[0],
             QStringLiteral("readOnlySetupBox:The setup in \"%1\" is read-only, so Klueng will not write over it.")
                 .arg(dir.path()));
    QCOMPARE(readAll(dir.filePath(QStringLiteral("tools.cfg"))), originalTools);
    QVERIFY2(savedDir.startsWith(home.path()), qPrintable(savedDir));
    const auto saved = core::io::readToolTable(savedDir.toStdString() + "/tools.cfg");
    QVERIFY(saved.ok());
    // Relative names still find their bitmaps from the new folder.
    QVERIFY(QFileInfo::exists(QString::fromStdString(saved.value->bitmapPath(4))));
    QVERIFY(QString::fromStdString(saved.value->bitmap[3])
                .endsWith(QStringLiteral("resources/tools/01-outside-turning.bmp")));
    QVERIFY(core::io::readOffsetTable(savedDir.toStdString() + "/offset.cfg").ok());
  }

  void offsetDefineRoundTripsOffsetCfg() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    const auto before = *core::io::readOffsetTable(dir.filePath(QStringLiteral("offset.cfg")).toStdString()).value;
    OffsetDefineDialog d(dir.path());
    QCOMPARE(d.cellText(0, 2), QStringLiteral("0.800"));
    QCOMPARE(d.cellText(0, 3), QStringLiteral("3"));
    d.setCell(3, 0, QStringLiteral("12.5"));
    d.setCell(3, 1, QStringLiteral("-0.25"));
    d.setCell(3, 2, QStringLiteral("0.4"));
    d.setCell(3, 3, QStringLiteral("2"));
    QVERIFY(d.isValid());
    const QByteArray original = readAll(dir.filePath(QStringLiteral("offset.cfg")));
    d.accept();
    QCOMPARE(d.result(), int(QDialog::Accepted));
    QCOMPARE(readAll(dir.filePath(QStringLiteral("offset.cfg"))), original);  // File > Save writes it
    const auto after = core::io::parseOffsetTable(core::io::formatOffsetTable(d.offsetTable()), "offset.cfg");
    QVERIFY(after.ok());
    const auto& o = after.value->at(4);
    QCOMPARE(o.x, 12.5);
    QCOMPARE(o.z, -0.25);
    QCOMPARE(o.r, 0.4);
    QCOMPARE(o.tip, 2);
    for (int n = 1; n <= 16; ++n) {
      if (n == 4) continue;
      QCOMPARE(after.value->at(n).r, before.at(n).r);
      QCOMPARE(after.value->at(n).tip, before.at(n).tip);
    }
  }

  void offsetDefineValidates() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    const QByteArray original = readAll(dir.filePath(QStringLiteral("offset.cfg")));
    OffsetDefineDialog d(dir.path());
    auto* ok = d.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    QVERIFY(ok->isEnabled());
    d.setCell(0, 2, QStringLiteral("-1"));
    QVERIFY(!d.isValid());
    QVERIFY(!ok->isEnabled());
    QVERIFY2(d.errorText().contains(QStringLiteral("01")) && d.errorText().contains(QStringLiteral("R")),
             qPrintable(d.errorText()));
    d.setCell(0, 2, QStringLiteral("0.8"));
    QVERIFY(d.isValid());
    for (const char* bad : {"12", "-1", "2.5", "x"}) {
      d.setCell(5, 3, QString::fromLatin1(bad));
      QVERIFY2(!d.isValid(), bad);
    }
    d.setCell(5, 3, QStringLiteral("7"));
    for (const char* bad : {"1.2345", "abc", "10000", "1e3", ""}) {
      d.setCell(2, 0, QString::fromLatin1(bad));
      QVERIFY2(!d.isValid(), bad);
    }
    QString message;
    closeNextMessageBox(&message);
    d.accept();
    QVERIFY(d.result() != QDialog::Accepted);
    QCOMPARE(readAll(dir.filePath(QStringLiteral("offset.cfg"))), original);
  }

  void jobDetailsKeepsEveryField() {
    core::io::JobHeader h;
    h.project = "เพลาขั้น";
    h.part = "SS-01";
    h.material = "Aluminium 6061";
    h.diameter = 2.5;
    h.diameterUnit = core::io::LengthUnit::Inch;
    h.length = 100;
    h.programmer = "Somchai";
    JobDetailsDialog d(h);
    const auto out = d.header();
    QCOMPARE(out.project, h.project);
    QCOMPARE(out.part, h.part);
    QCOMPARE(out.material, h.material);
    QCOMPARE(out.diameter, 2.5);
    QVERIFY(out.diameterUnit == core::io::LengthUnit::Inch);
    QCOMPARE(out.length, 100.0);
    QVERIFY(out.lengthUnit == core::io::LengthUnit::Millimetre);
    QCOMPARE(out.programmer, h.programmer);
    QCOMPARE(out.diameterMm(), 63.5);
  }
};

KLUENG_GUI_TEST(DialogsTest)
#include "dialogs_test.moc"

// Issue 42 item 2 in the GUI (offscreen): Save As of the program and the Part
// Designer's Save never write over a file the run reads — a setup table, a tool
// picture, a subprogram file of the program — F126, the file unchanged.
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include "fresh_user_folders.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/part_designer.h"
#include "gui/resources.h"
#include "gui_test_runner.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/setup_files.h"

using namespace klueng::gui;

namespace {

QByteArray fileBytes(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool putBytes(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size() && f.flush();
}

// A setup folder of its own: the shipped tables and tool pictures, copied.
bool copySetup(const QString& to) {
  const QDir from(QStringLiteral(KLUENG_SOURCE_DIR));
  if (!QDir().mkpath(to + QStringLiteral("/resources/tools"))) return false;
  for (const char* f : {"tools.cfg", "offset.cfg", "machine.cfg"})
    if (!QFile::copy(from.filePath(QLatin1String(f)), to + QLatin1Char('/') + QLatin1String(f))) return false;
  const QDir tools(from.filePath(QStringLiteral("resources/tools")));
  for (const QString& bmp : tools.entryList({QStringLiteral("*.bmp")}, QDir::Files))
    if (!QFile::copy(tools.filePath(bmp), to + QStringLiteral("/resources/tools/") + bmp)) return false;
  return true;
}

// Each modal message box's object name and text recorded, then rejected.
class BoxRecorder {
 public:
  BoxRecorder() {
    QObject::connect(&timer_, &QTimer::timeout, [this] {
      auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
      if (!box) return;
      boxes_ << box->objectName() + QStringLiteral("|") + box->text();
      box->reject();
    });
    timer_.start(20);
  }
  QStringList boxes() const { return boxes_; }

 private:
  QTimer timer_;
  QStringList boxes_;
};

}  // namespace

class InputOverwriteTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    klueng::test::freshUserFolders();
    initResources();
    Language::instance()->setLanguage(QStringLiteral("en"));
  }

  void saveAsNeverWritesOverTheSetupOrASubprogram() {
    QTemporaryDir tmp;
    const QString setup = tmp.filePath(QStringLiteral("setup"));
    QVERIFY(copySetup(setup));
    const QByteArray oldDataDir = qgetenv("KLUENG_DATA_DIR");
    qputenv("KLUENG_DATA_DIR", setup.toUtf8());
    const QString prog = tmp.filePath(QStringLiteral("main.nc"));
    const QString sub = tmp.filePath(QStringLiteral("O1000.nc"));
    QVERIFY(putBytes(prog, "O0001\nG21 G99\nT0101\nG97 S500 M03\nG00 X52. Z2.\nM98 P1000\nM30\n"));
    const QByteArray subBytes = "O1000\nG01 X50. F0.2\nM99\n";
    QVERIFY(putBytes(sub, subBytes));
    {
      MainWindow w;
      w.show();
      QCOMPARE(w.configDir(), setup);
      QVERIFY(w.openFile(prog));
      QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
      const QString picture = setup + QStringLiteral("/resources/tools/01-outside-turning.bmp");
      for (const QString& target : {setup + QStringLiteral("/tools.cfg"), picture, sub}) {
        const QByteArray before = fileBytes(target);
        BoxRecorder boxes;
        QVERIFY(!w.saveFile(target));
        QTRY_COMPARE(boxes.boxes().size(), 1);
        QVERIFY2(boxes.boxes()[0].startsWith(QStringLiteral("outputIsInputBox|") + target),
                 qPrintable(boxes.boxes()[0]));
        QVERIFY2(boxes.boxes()[0].contains(QStringLiteral("this output is the input file")),
                 qPrintable(boxes.boxes()[0]));
        QCOMPARE(fileBytes(target), before);
      }
      // Another name is written as before.
      QVERIFY(w.saveFile(tmp.filePath(QStringLiteral("copy.nc"))));
    }
    qputenv("KLUENG_DATA_DIR", oldDataDir);
  }

  void partDesignerNeverWritesOverTheSetup() {
    QTemporaryDir tmp;
    const QString setup = tmp.filePath(QStringLiteral("setup"));
    QVERIFY(copySetup(setup));
    const klueng::core::machine::LoadedSetup loaded =
        klueng::core::machine::loadMachineSetup(setup.toStdString(), true);
    PartDesignerDialog d(loaded.setup, klueng::core::gcode::Dialect::Fanuc, klueng::core::io::JobHeader{});
    const QString tools = setup + QStringLiteral("/tools.cfg");
    const QByteArray before = fileBytes(tools);
    BoxRecorder boxes;
    QVERIFY(!d.saveFile(tools));
    QTRY_COMPARE(boxes.boxes().size(), 1);
    QCOMPARE(fileBytes(tools), before);
    QVERIFY(d.saveFile(tmp.filePath(QStringLiteral("part.json"))));
  }
};

KLUENG_GUI_TEST(InputOverwriteTest)
#include "input_overwrite_test.moc"

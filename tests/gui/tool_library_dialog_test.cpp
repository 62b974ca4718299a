// Tool Select with the turret (12 stations), the tool library and the tools
// the program got from the library.
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLineEdit>
#include <QListWidget>
#include <QTemporaryDir>
#include <QApplication>
#include <QMessageBox>
#include <QTest>
#include <QTimer>

#include "gui_test_runner.h"
#include "gui/offset_define_dialog.h"
#include "gui/tool_select_dialog.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/image.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/io/tool_library.h"

using namespace klueng;
using namespace klueng::gui;

namespace {

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
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("(cannot read)");
}

core::machine::ToolInference inferFor(const std::string& text, const QString& configDir) {
  core::machine::MachineSetup setup;
  setup.tools = *core::io::readToolTable(configDir.toStdString() + "/tools.cfg").value;
  setup.offsets = *core::io::readOffsetTable(configDir.toStdString() + "/offset.cfg").value;
  const auto program = core::gcode::parse(text, 1);
  return core::machine::inferTools(program, text, 1, setup, core::io::shippedToolLibrary());
}

}  // namespace

class ToolLibraryDialogTest : public QObject {
  Q_OBJECT
 private slots:
  void listsTwelveStations() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    ToolSelectDialog d(dir.path());
    QCOMPARE(d.stationCount(), 12);
    auto* list = d.findChild<QListWidget*>();
    QVERIFY(list);
    QCOMPARE(list->count(), 12);
    QVERIFY(list->item(11)->text().startsWith(QStringLiteral("Tool 12")));
    d.setCurrentTool(12);
    QCOMPARE(d.currentTool(), 12);
  }

  void showsTheProgramsChoiceAtTrueScale() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    const auto inference =
        inferFor("T0101\nG00 X52. Z2.\n(CUT OFF)\nT1212\nG00 X55. Z-43.\nG01 X-1. F0.05\nM30\n", dir.path());
    QVERIFY(inference.choiceFor(12));
    ToolSelectDialog d(dir.path());
    d.setProgramTools(inference, {});
    auto* list = d.findChild<QListWidget*>();
    QVERIFY2(list->item(11)->text().contains(QStringLiteral("parting-3mm")), qPrintable(list->item(11)->text()));
    QVERIFY(list->item(11)->text().contains(QStringLiteral("from the program")));
    d.setCurrentTool(12);
    QVERIFY2(d.choiceText().contains(QStringLiteral("comment \"CUT OFF\" on line 3")), qPrintable(d.choiceText()));
    QVERIFY(!d.previewSprite().isNull());
    QCOMPARE(d.previewSprite().pixelsPerMm(), 10.0);
    // 3 mm parting insert, corner bottom-left (tip 3): 30 px wide cutting edge at 10 px/mm.
    QVERIFY(qAbs(d.previewSprite().cuttingEdgeBox().width() - 30) <= 1);
  }

  void aLibraryToolForThisProgramOnlyLeavesToolsCfg() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    QFile f(dir.filePath(QStringLiteral("tools.cfg")));
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray original = f.readAll();
    f.close();
    ToolSelectDialog d(dir.path());
    d.setLibraryTool(3, QStringLiteral("threading-60-id"), true);
    d.setLibraryTool(10, QStringLiteral("drill-16mm"), false);
    d.accept();
    QCOMPARE(d.result(), int(QDialog::Accepted));
    QCOMPARE(d.jobOverrides().size(), std::size_t(1));
    QCOMPARE(d.jobOverrides()[0].station, 3);
    QCOMPARE(d.jobOverrides()[0].libraryId, std::string("threading-60-id"));
    // The table File > Save writes: station 10 from the library, station 3 as it was.
    const core::io::ToolTable saved = d.toolTable();
    QCOMPARE(saved.libraryId(10), std::string("drill-16mm"));
    QCOMPARE(saved.bitmap[2], std::string("resources/tools/03-threading-60.bmp"));
    QCOMPARE(readAll(dir.filePath(QStringLiteral("tools.cfg"))), original);  // nothing written by the dialog
    QVERIFY(original.startsWith(QByteArray("resources/tools/01-outside-turning.bmp")));
  }

  // Issue 29 item 4: the user's order - a library tool chosen in the box first, then
  // "Only for this program" ticked - keeps tools.cfg byte for byte; the station is
  // this program's, and tools.cfg's own line is shown again.
  void tickingOnlyForThisProgramAfterChoosingKeepsToolsCfg() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    const QString cfg = dir.filePath(QStringLiteral("tools.cfg"));
    const QByteArray original = readAll(cfg);
    ToolSelectDialog d(dir.path());
    auto* combo = d.findChild<QComboBox*>(QStringLiteral("toolLibrary"));
    auto* jobOnly = d.findChild<QCheckBox*>(QStringLiteral("toolJobOnly"));
    auto* name = d.findChild<QLineEdit*>(QStringLiteral("toolBitmapName"));
    QVERIFY(combo && jobOnly && name);
    d.setCurrentTool(1);
    QVERIFY(!jobOnly->isChecked());
    const int index = combo->findData(QStringLiteral("cnmg-80-r04"));
    QVERIFY(index > 0);
    combo->setCurrentIndex(index);
    emit combo->activated(index);                                   // as a choice in the drop-down list
    QCOMPARE(name->text(), QStringLiteral("library:cnmg-80-r04"));  // going to tools.cfg, as shown
    jobOnly->click();
    QVERIFY(jobOnly->isChecked());
    QCOMPARE(name->text(), QStringLiteral("resources/tools/01-outside-turning.bmp"));
    QCOMPARE(combo->currentData().toString(), QStringLiteral("cnmg-80-r04"));
    QVERIFY2(d.choiceText().contains(QStringLiteral("tools.cfg has: resources/tools/01-outside-turning.bmp")),
             qPrintable(d.choiceText()));
    d.accept();
    QCOMPARE(d.result(), int(QDialog::Accepted));
    QVERIFY(!d.toolsChanged());  // nothing for File > Save to write to tools.cfg
    QCOMPARE(readAll(cfg), original);
    QCOMPARE(d.jobOverrides().size(), std::size_t(1));
    QCOMPARE(d.jobOverrides()[0].station, 1);
    QCOMPARE(d.jobOverrides()[0].libraryId, std::string("cnmg-80-r04"));
  }

  // Unticked again, the chosen tool goes to tools.cfg after all.
  void untickingSendsTheLibraryToolToToolsCfg() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    ToolSelectDialog d(dir.path());
    auto* combo = d.findChild<QComboBox*>(QStringLiteral("toolLibrary"));
    auto* jobOnly = d.findChild<QCheckBox*>(QStringLiteral("toolJobOnly"));
    QVERIFY(combo && jobOnly);
    d.setCurrentTool(4);
    const int index = combo->findData(QStringLiteral("cnmg-80-r04"));
    combo->setCurrentIndex(index);
    emit combo->activated(index);
    jobOnly->click();
    jobOnly->click();
    QVERIFY(!jobOnly->isChecked());
    d.accept();
    QCOMPARE(d.result(), int(QDialog::Accepted));
    QVERIFY(d.jobOverrides().empty());
    QVERIFY(d.toolsChanged());
    const core::io::ToolTable saved = d.toolTable();
    QCOMPARE(saved.libraryId(4), std::string("cnmg-80-r04"));
    QCOMPARE(saved.bitmap[0], std::string("resources/tools/01-outside-turning.bmp"));
  }

  // Issue 39: the Tool material box sets the station's `| material=` (the cutting data judges by it).
  void toolMaterialIsEditedPerStation() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    ToolSelectDialog d(dir.path());
    auto* material = d.findChild<QComboBox*>(QStringLiteral("toolMaterial"));
    QVERIFY(material);
    d.setCurrentTool(1);
    QCOMPARE(material->currentIndex(), 0);  // the shipped tools.cfg says none
    QVERIFY(!d.toolsChanged());
    const int hss = material->findData(QStringLiteral("hss"));
    QVERIFY(hss > 0);
    material->setCurrentIndex(hss);
    emit material->activated(hss);
    QVERIFY(d.toolsChanged());
    d.setCurrentTool(2);
    QCOMPARE(material->currentIndex(), 0);
    d.setCurrentTool(1);
    QCOMPARE(material->currentIndex(), hss);
    d.accept();
    QCOMPARE(d.result(), int(QDialog::Accepted));
    const core::io::ToolTable saved = d.toolTable();
    QCOMPARE(saved.material[0], std::string("hss"));
    QVERIFY(core::io::formatToolTable(saved).starts_with("resources/tools/01-outside-turning.bmp | material=hss\n"));
  }

  // OK with only a station for this program: tools.cfg is not rewritten at all (its
  // bytes stay as the user wrote them, Windows line ends included).
  void okWithOnlyThisProgramsStationsDoesNotRewriteToolsCfg() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    const QString cfg = dir.filePath(QStringLiteral("tools.cfg"));
    {
      QByteArray text = readAll(cfg);
      text.replace("\n", "\r\n");  // as saved by a Windows editor; the formatter writes \n
      QFile f(cfg);
      QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
      QCOMPARE(f.write(text), text.size());
    }
    const QByteArray original = readAll(cfg);
    ToolSelectDialog d(dir.path());
    d.setLibraryTool(2, QStringLiteral("parting-3mm"), true);
    d.accept();
    QCOMPARE(d.result(), int(QDialog::Accepted));
    QCOMPARE(readAll(cfg), original);
    QCOMPARE(d.jobOverrides().size(), std::size_t(1));
  }

  // Issue 29 item 10: a bitmap larger than a tool can be is refused here, as the setup refuses it (F139).
  void aBitmapLargerThanAToolIsRefused() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    const QByteArray original = readAll(dir.filePath(QStringLiteral("tools.cfg")));
    core::io::RgbImage image{1001, 40, std::vector<std::uint32_t>(1001 * 40, 0xFFFFFF)};
    image.pixels[0] = 0xFF0000;
    {
      QFile f(dir.filePath(QStringLiteral("wide.bmp")));
      QVERIFY(f.open(QIODevice::WriteOnly));
      const std::string bytes = core::io::encodeBmp(image);
      f.write(bytes.data(), static_cast<qint64>(bytes.size()));
    }
    ToolSelectDialog d(dir.path());
    d.setBitmapName(2, QStringLiteral("wide.bmp"));
    QString message;
    QTimer::singleShot(0, [&message] {
      if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
        message = box->text();
        box->accept();
      }
    });
    d.accept();
    QVERIFY(d.result() != QDialog::Accepted);
    QCOMPARE(message, dir.filePath(QStringLiteral("tools.cfg")) +
                          QStringLiteral(": tool 02: the bitmap 'wide.bmp' is 1001 x 40 pixels; a tool bitmap may be "
                                         "at most 1000 x 1000 pixels (500 mm each way at 2 pixels per mm)"));
    QCOMPARE(readAll(dir.filePath(QStringLiteral("tools.cfg"))), original);
  }

  void offsetDefineEditsSixtyFourRows() {
    QTemporaryDir dir;
    QVERIFY(makeConfigCopy(dir.path()));
    OffsetDefineDialog d(dir.path());
    d.setCell(39, 2, QStringLiteral("0.4"));
    d.setCell(39, 3, QStringLiteral("2"));
    d.accept();
    QCOMPARE(d.result(), int(QDialog::Accepted));
    const core::io::OffsetTable saved = d.offsetTable();
    QCOMPARE(saved.at(40).r, 0.4);
    QCOMPARE(saved.at(40).tip, 2);
    QCOMPARE(saved.at(1).r, 0.8);
  }
};

KLUENG_GUI_TEST(ToolLibraryDialogTest)
#include "tool_library_dialog_test.moc"

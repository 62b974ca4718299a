// Pictures of the output screen and the dialogs (offscreen): checks that the
// drawing is where the geometry says it is, and saves PNGs for people to look
// at (into $KLUENG_SHOT_DIR, default: the temp folder).
#include <QApplication>
#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QLabel>
#include <QTest>
#include <QWheelEvent>
#include <QLineF>

#include "gui_test_runner.h"
#include "gui/about_dialog.h"
#include "gui/job_details_dialog.h"
#include "gui/language.h"
#include "gui/offset_define_dialog.h"
#include "gui/output_view.h"
#include "gui/run_controller.h"
#include "gui/status_panel.h"
#include "gui/tool_select_dialog.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "render/lathe_painters.h"

#include "gui_test_support.h"

using namespace klueng;
using namespace klueng::gui;

namespace {

QString shotDir() {
  const QString dir =
      qEnvironmentVariableIsSet("KLUENG_SHOT_DIR")
          ? qEnvironmentVariable("KLUENG_SHOT_DIR")
          : QDir::tempPath() + QStringLiteral("/klueng-shots-%1").arg(QCoreApplication::applicationPid());
  QDir().mkpath(dir);
  return dir;
}

void save(QWidget& w, const QString& name) {
  const QImage img = w.grab().toImage();
  QVERIFY(!img.isNull());
  QVERIFY(img.save(QDir(shotDir()).filePath(name)));
}

using gui_test::loadSetup;

bool near(QRgb a, const QColor& b, int tolerance = 12) {
  return std::abs(qRed(a) - b.red()) <= tolerance && std::abs(qGreen(a) - b.green()) <= tolerance &&
         std::abs(qBlue(a) - b.blue()) <= tolerance;
}

}  // namespace

class OutputScreensTest : public QObject {
  Q_OBJECT
 private slots:
  // The pictures stay only where KLUENG_SHOT_DIR asks for them: nothing left in /tmp after a run.
  void cleanupTestCase() {
    if (!qEnvironmentVariableIsSet("KLUENG_SHOT_DIR")) QDir(shotDir()).removeRecursively();
  }
  void outputScreenShowsTheCutPart() {
    RunController controller;
    controller.setMachineSetup(loadSetup());
    controller.setProgram(*core::io::readProgramFile(KLUENG_SAMPLES_DIR "/01-step-shaft.txt").value);
    controller.setSpeed(RunController::kAsFastAsPossible);
    OutputView view;
    view.resize(1280, 800);
    view.setRunController(&controller);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    save(view, QStringLiteral("output-01-before.png"));

    // Stop in the middle of roughing (breakpoint on N170), then at the end.
    controller.setBreakpoints({25});  // file line of N170
    controller.go();
    controller.waitForIdle();
    QCOMPARE(controller.state(), RunState::Paused);
    QApplication::processEvents();
    save(view, QStringLiteral("output-01-middle.png"));
    controller.setBreakpoints({});
    controller.go();
    controller.waitForIdle();
    QCOMPARE(controller.state(), RunState::Finished);
    view.fitToView();
    QApplication::processEvents();
    const QImage img = view.grab().toImage();
    img.save(QDir(shotDir()).filePath(QStringLiteral("output-01-end.png")));

    // Sample the picture where the geometry says: material at (Z-30, r 15) both halves,
    // air at (Z-10, r 17), the chuck at the bar's left end.
    auto pixel = [&](double z, double r) {
      const QPoint vp = view.mapFromScene(render::toScene(z, r));
      return img.pixel(vp + view.viewport()->pos());
    };
    const auto& pal = render::palette();
    QVERIFY(near(pixel(-30.0, 15.0), pal.stockFill));
    QVERIFY(near(pixel(-30.0, -15.0), pal.stockFill));
    QVERIFY(!near(pixel(-10.0, 17.0), pal.stockFill));
    QVERIFY(near(pixel(-100.0 + 5.0, 28.0), pal.chuckFill));
  }

  // Issue 28 item 8: Fit frames the stock and the part, not the path to the
  // tool's start at Z300 (the part was 100 px wide); the wheel zooms at the pointer.
  void fitFramesTheStockAndTheWheelZoomsAtThePointer() {
    RunController controller;
    controller.setMachineSetup(loadSetup());
    controller.setProgram(*core::io::readProgramFile(KLUENG_SAMPLES_DIR "/01-step-shaft.txt").value);
    OutputView view;
    view.resize(800, 500);
    view.setRunController(&controller);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.fitToView();
    QApplication::processEvents();
    const QRectF visible = view.visibleSceneRect();
    QCOMPARE(view.toolItemPos().x(), 300.0);  // the start position, X0 Z300 of machine.cfg
    // The bar (Ø50 x 100) and its end face are in sight; the bar is over 40% of the width
    // (24% when the tool's start was framed too). The jaws above it set the height.
    const QPoint left = view.mapFromScene(render::toScene(-100.0, 25.0));
    const QPoint right = view.mapFromScene(render::toScene(0.0, 25.0));
    QVERIFY(visible.contains(render::toScene(0.0, 25.0)) && visible.contains(render::toScene(-100.0, -25.0)));
    QVERIFY2(
        right.x() - left.x() > 0.4 * view.viewport()->width(),
        qPrintable(QStringLiteral("the bar is %1 px of %2").arg(right.x() - left.x()).arg(view.viewport()->width())));
    // Wheel up over the bar's end: that point stays under the pointer, the view zooms in.
    const QPoint at = view.mapFromScene(render::toScene(0.0, 25.0));
    const QPointF before = view.mapToScene(at);
    const double zoomBefore = view.pixelsPerMm();
    QWheelEvent wheel(QPointF(at), view.viewport()->mapToGlobal(QPointF(at)), QPoint(), QPoint(0, 240), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view.viewport(), &wheel);
    QVERIFY(view.pixelsPerMm() > zoomBefore * 1.3);
    const QPointF after = view.mapToScene(at);
    QVERIFY2(QLineF(before, after).length() * view.pixelsPerMm() < 1.5,
             qPrintable(QStringLiteral("moved %1 px").arg(QLineF(before, after).length() * view.pixelsPerMm())));
  }

  // Issue 11: Qt's own file dialog speaks Thai in Thai mode (Debian has no qtbase_th.qm).
  void qtsOwnFileDialogIsThaiInThaiMode() {
    Language::instance()->setLanguage(QStringLiteral("th"));
    QFileDialog d(nullptr, QStringLiteral("x"), QDir::tempPath());
    d.setOption(QFileDialog::DontUseNativeDialog);
    d.show();
    QVERIFY(QTest::qWaitForWindowExposed(&d));
    auto* name = d.findChild<QLabel*>(QStringLiteral("fileNameLabel"));
    auto* look = d.findChild<QLabel*>(QStringLiteral("lookInLabel"));
    QVERIFY(name && look);
    QCOMPARE(name->text(), QStringLiteral("ชื่อไฟล์ (&N):"));
    QCOMPARE(look->text(), QStringLiteral("ค้นหาใน:"));
    save(d, QStringLiteral("dialog-file-th.png"));
    Language::instance()->setLanguage(QStringLiteral("en"));
  }

  void alarmPicture() {
    RunController controller;
    controller.setMachineSetup(loadSetup());
    controller.setProgram(*core::io::readProgramFile(KLUENG_SAMPLES_DIR "/05-runtime-alarms.txt").value);
    controller.setSpeed(RunController::kAsFastAsPossible);
    OutputView view;
    view.resize(1000, 600);
    view.setRunController(&controller);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    controller.go();
    controller.waitForIdle();
    QCOMPARE(controller.state(), RunState::Alarm);
    QApplication::processEvents();
    // The tool stays where the alarm happened: the start of N40, at X45 Z2.
    QCOMPARE(view.toolItemPos(), render::toScene(2.0, 22.5));
    save(view, QStringLiteral("output-05-alarm.png"));
  }

  void dialogsInEnglishAndThai() {
    const QString dir = QString::fromStdString(core::io::findConfigDir(KLUENG_SOURCE_DIR));
    for (const QString& lang : {QStringLiteral("en"), QStringLiteral("th")}) {
      Language::instance()->setLanguage(lang);
      {
        ToolSelectDialog d(dir);
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        QVERIFY(!d.previewSprite().isNull());
        save(d, QStringLiteral("dialog-tool-select-%1.png").arg(lang));
        d.setCurrentTool(5);
        save(d, QStringLiteral("dialog-tool-select-05-%1.png").arg(lang));
      }
      {
        OffsetDefineDialog d(dir);
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        d.setCell(2, 2, QStringLiteral("-1"));
        save(d, QStringLiteral("dialog-offset-define-%1.png").arg(lang));
      }
      {
        core::io::JobHeader h;
        h.project = "Step shaft exercise";
        h.part = "ชิ้นงาน SS-01";
        JobDetailsDialog d(h);
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        save(d, QStringLiteral("dialog-job-%1.png").arg(lang));
      }
      {
        AboutDialog d;
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        save(d, QStringLiteral("dialog-about-%1.png").arg(lang));
      }
      {
        QWidget bar;
        auto* fields = new StatusFields(&bar);
        auto* lamps = new StatusLamps(&bar);
        RunStatus s;
        s.position = core::zx(-20.0, 15.0);
        s.programmedFeed = 0.25;
        s.rpm = 1432;
        s.machine.tool = 1;
        s.machine.offset = 1;
        s.machine.noseRadius = 0.8;
        s.machine.tip = 3;
        s.machine.spindle = core::machine::SpindleDir::Cw;
        s.machine.coolant = true;
        fields->setStatus(s);
        lamps->setStatus(s);
        fields->move(0, 0);
        fields->resize(fields->sizeHint());
        lamps->move(0, fields->sizeHint().height() + 4);
        lamps->resize(lamps->sizeHint());
        bar.resize(std::max(fields->sizeHint().width(), lamps->sizeHint().width()),
                   fields->sizeHint().height() + lamps->sizeHint().height() + 8);
        bar.show();
        QVERIFY(QTest::qWaitForWindowExposed(&bar));
        QCOMPARE(fields->fieldText(StatusFields::Field::ToolX), QStringLiteral("30.000"));
        save(bar, QStringLiteral("status-%1.png").arg(lang));
      }
    }
    Language::instance()->setLanguage(QStringLiteral("en"));
  }
};

KLUENG_GUI_TEST(OutputScreensTest)
#include "output_screens_test.moc"

// Printed reports (SPEC 12): sample 01's program sheet and drawing sheet written
// to PDF with QPdfWriter in English and Thai, read back with pdftotext and
// checked with pdffonts (Thai font embedded); pagination of a long program; the
// drawing is to the stated scale (measured on a rasterised page).
#include <QDir>
#include <QFile>
#include <QGuiApplication>
#include <QImage>
#include <QPdfWriter>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <QApplication>
#include <QPrintPreviewDialog>
#include <QPrintPreviewWidget>
#include <QPrinter>
#include <QTimer>
#include <QToolBar>

#include "gui_test_runner.h"
#include "fresh_user_folders.h"
#include "klueng/core/job/job.h"
#include "gui/code_editor.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/resources.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "render/report_sheets.h"

#include "gui_test_support.h"

using namespace klueng;
using render::ReportLanguage;

namespace {

using gui_test::loadSetup;

// The job a report prints: the program as given, the setup's own tools.
std::shared_ptr<const core::job::Job> jobOf(const core::io::ProgramFile& program, core::gcode::Dialect dialect) {
  core::job::JobInput input;
  input.file = program;
  input.setup = loadSetup();
  input.run.dialect = dialect;
  input.inferTools = false;
  return core::job::makeJob(std::move(input));
}

render::ReportData sampleData(ReportLanguage lang) {
  render::ReportData d;
  d.program = *core::io::readProgramFile(KLUENG_SAMPLES_DIR "/01-step-shaft.txt").value;
  d.fileName = QStringLiteral("01-step-shaft.txt");
  d.date = QDate(1999, 10, 19);
  render::addRunResults(d, *jobOf(d.program, core::gcode::Dialect::Fanuc), lang, true);  // part, features, cycle time
  return d;
}

enum class Sheet { Program, Drawing };

// Writes one sheet to `path` (A4, 300 dpi); returns the program sheet's page count.
int writePdf(const QString& path, const render::ReportData& data, ReportLanguage lang, Sheet sheet) {
  QPdfWriter writer(path);
  writer.setResolution(300);
  writer.setPageSize(QPageSize(QPageSize::A4));
  writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
  if (sheet == Sheet::Drawing) writer.setPageOrientation(QPageLayout::Landscape);
  QPainter painter(&writer);
  int pages = 1;
  if (sheet == Sheet::Program)
    pages = render::paintProgramSheet(painter, writer, data, lang);
  else
    render::paintDrawingSheet(painter, writer, data, lang);
  painter.end();
  return pages;
}

QString run(const QString& program, const QStringList& args) {
  QProcess p;
  p.start(program, args);
  if (!p.waitForFinished(60000) || p.exitCode() != 0) return QStringLiteral("<%1 failed>").arg(program);
  return QString::fromUtf8(p.readAllStandardOutput());
}

// The TLWG Thai fonts reach their repositioned tone marks and vowels (drawn lower or
// further left over some consonants) through the legacy Thai code points U+F700-U+F71A
// of their cmap, draw a tone mark before the vowel it sits on, and shape SARA AM as NIKHAHIT + SARA AA; the PDF's text
// layer therefore reads back with those. Map them to the Unicode letters they stand for.
QString normaliseThai(QString text) {
  static const char16_t legacy[] = {0x0E10, 0x0E34, 0x0E35, 0x0E36, 0x0E37, 0x0E48, 0x0E49, 0x0E4A, 0x0E4B,
                                    0x0E4C, 0x0E48, 0x0E49, 0x0E4A, 0x0E4B, 0x0E4C, 0x0E0D, 0x0E31, 0x0E4D,
                                    0x0E47, 0x0E48, 0x0E49, 0x0E4A, 0x0E4B, 0x0E4C, 0x0E38, 0x0E39, 0x0E3A};
  for (QChar& c : text)
    if (c.unicode() >= 0xF700 && c.unicode() <= 0xF71A) c = QChar(legacy[c.unicode() - 0xF700]);
  // A tone mark drawn before the vowel under or over the same consonant: Unicode puts the vowel first.
  auto isToneMark = [](QChar c) { return c.unicode() >= 0x0E48 && c.unicode() <= 0x0E4C; };
  auto isVowelMark = [](QChar c) { return c.unicode() == 0x0E31 || (c.unicode() >= 0x0E34 && c.unicode() <= 0x0E3A); };
  for (qsizetype i = 0; i + 1 < text.size(); ++i)
    if (isToneMark(text[i]) && isVowelMark(text[i + 1])) std::swap(text[i], text[i + 1]);
  text.replace(QString::fromUtf8("\u0E4D\u0E32"), QString::fromUtf8("\u0E33"));
  return text;
}

// The text layer in drawing order (-raw keeps each mark with its letter).
QString pdfText(const QString& pdf) {
  return normaliseThai(run(QStringLiteral("pdftotext"), {QStringLiteral("-raw"), pdf, QStringLiteral("-")}));
}
QString pageText(const QString& pdf, int page) {
  const QString n = QString::number(page);
  return normaliseThai(run(QStringLiteral("pdftotext"), {QStringLiteral("-raw"), QStringLiteral("-f"), n,
                                                         QStringLiteral("-l"), n, pdf, QStringLiteral("-")}));
}

bool havePoppler() { return !QStandardPaths::findExecutable(QStringLiteral("pdftotext")).isEmpty(); }

}  // namespace

class ReportTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    // Never a silent skip: the reports are read back from the PDF with pdftotext.
    if (!havePoppler()) QFAIL("poppler-utils (pdftotext) is missing: scripts/setup.sh installs it");
  }

  void datesInBothLanguages() {
    QCOMPARE(render::reportDate(QDate(1999, 10, 19), ReportLanguage::Thai), QStringLiteral("19 ตุลาคม พ.ศ. 2542"));
    QCOMPARE(render::reportDate(QDate(1999, 10, 19), ReportLanguage::English), QStringLiteral("October 19, 1999"));
    QCOMPARE(render::reportDate(QDate(2026, 1, 2), ReportLanguage::Thai), QStringLiteral("2 มกราคม พ.ศ. 2569"));
    QCOMPARE(render::reportDate(QDate(2024, 2, 29), ReportLanguage::English), QStringLiteral("February 29, 2024"));
    // The status bar's short form: every Thai month's abbreviation, the year in the Buddhist era.
    const QStringList thaiShort = {QStringLiteral("ม.ค."),  QStringLiteral("ก.พ."), QStringLiteral("มี.ค."),
                                   QStringLiteral("เม.ย."), QStringLiteral("พ.ค."), QStringLiteral("มิ.ย."),
                                   QStringLiteral("ก.ค."),  QStringLiteral("ส.ค."), QStringLiteral("ก.ย."),
                                   QStringLiteral("ต.ค."),  QStringLiteral("พ.ย."), QStringLiteral("ธ.ค.")};
    for (int m = 1; m <= 12; ++m)
      QCOMPARE(render::reportDate(QDate(2026, m, 26), ReportLanguage::Thai, render::DateLength::Short),
               QStringLiteral("26 %1 2569").arg(thaiShort[m - 1]));
    QCOMPARE(render::reportDate(QDate(2026, 11, 26), ReportLanguage::English, render::DateLength::Short),
             QStringLiteral("Nov 26, 2026"));
    QCOMPARE(render::reportDate(QDate(2026, 7, 1), ReportLanguage::Thai), QStringLiteral("1 กรกฎาคม พ.ศ. 2569"));
  }

  void scalesAreStandardAndFit() {
    QCOMPARE(render::drawingScale(QSizeF(150, 50), QSizeF(250, 120)), 1.0);
    QCOMPARE(render::drawingScale(QSizeF(300, 80), QSizeF(250, 120)), 0.5);
    QCOMPARE(render::drawingScale(QSizeF(40, 20), QSizeF(250, 120)), 5.0);
    QCOMPARE(render::drawingScale(QSizeF(1100, 150), QSizeF(250, 120)), 0.2);
    QCOMPARE(render::scaleText(1.0), QStringLiteral("1:1"));
    QCOMPARE(render::scaleText(0.5), QStringLiteral("1:2"));
    QCOMPARE(render::scaleText(2.0), QStringLiteral("2:1"));
  }

  void englishProgramSheet() {
    const QString pdf = out(QStringLiteral("sheet-en.pdf"));
    QCOMPARE(writePdf(pdf, sampleData(ReportLanguage::English), ReportLanguage::English, Sheet::Program), 1);
    const QString text = pdfText(pdf);
    for (const char* s : {"CNC Program Sheet", "Page 1", "Project", "Material", "Part", "Diameter (mm.)", "Programmer",
                          "Length (mm.)", "Step shaft exercise", "Shaft SS-01", "Aluminium 6061", "Klueng samples",
                          "N100 G01 Z-59.8 F0.25 (rough)", "October 19, 1999"})
      QVERIFY2(text.contains(QString::fromUtf8(s)), s);
    QVERIFY(!text.contains(QStringLiteral("Page 2")));
    // The listing is numbered with file lines: N100 is line 18 of the file.
    QVERIFY2(text.contains(QRegularExpression(QStringLiteral("\\b18\\s+N100 G01 Z-59.8"))), qPrintable(text));
    QVERIFY(text.contains(QRegularExpression(QStringLiteral("\\b7\\s+O0001"))));
    // Diameter and length from the header ("150" = mm, 50; "1100" = mm, 100).
    QVERIFY(text.contains(QRegularExpression(QStringLiteral("Diameter \\(mm\\.\\)\\s+50\\b"))));
    QVERIFY(text.contains(QRegularExpression(QStringLiteral("Length \\(mm\\.\\)\\s+100\\b"))));
    // Cycle time of the whole program and of each tool, from the core's timeline.
    const render::ReportData data = sampleData(ReportLanguage::English);
    const auto job = jobOf(data.program, core::gcode::Dialect::Fanuc);  // a second job: its own run
    const core::machine::Timeline* timeline = job->timeline();
    QVERIFY(timeline && !timeline->alarm);
    QCOMPARE(data.cycleTime, timeline->cycleTime());
    QVERIFY(data.cycleTime > 60.0);
    const QString total = render::durationText(timeline->cycleTime(), ReportLanguage::English);
    QVERIFY(total.contains(QStringLiteral(" min ")));
    QVERIFY2(text.contains(QStringLiteral("Cycle time")), qPrintable(text));
    QVERIFY2(text.contains(total), qPrintable(total));
    for (const core::machine::ToolTime& t : timeline->timeByTool())
      if (t.tool > 0) {
        const QString tool = QStringLiteral("T%1 %2")
                                 .arg(t.tool, 2, 10, QLatin1Char('0'))
                                 .arg(render::durationText(t.seconds, ReportLanguage::English));
        QVERIFY2(text.contains(tool), qPrintable(tool));
      }
    QCOMPARE(render::durationText(192.44, ReportLanguage::English), QStringLiteral("3 min 12.4 s"));
    QCOMPARE(render::durationText(192.44, ReportLanguage::Thai), QStringLiteral("3 นาที 12.4 วินาที"));
    QCOMPARE(render::durationText(7.0, ReportLanguage::English), QStringLiteral("7.0 s"));
  }

  void thaiProgramSheetWithEmbeddedThaiFont() {
    const QString pdf = out(QStringLiteral("sheet-th.pdf"));
    QCOMPARE(writePdf(pdf, sampleData(ReportLanguage::Thai), ReportLanguage::Thai, Sheet::Program), 1);
    const QString text = pdfText(pdf);
    for (const char* s :
         {"ชุดรหัสสั่งการทำงาน", "หน้าที่ 1", "ชื่องาน", "วัสดุ", "ชิ้นงาน", "เส้นผ่าศก. (มม.)", "ผู้เขียน", "ความยาว (มม.)",
          "19 ตุลาคม พ.ศ. 2542", "Step shaft exercise", "N100 G01 Z-59.8 F0.25", "เวลาทำงาน", "นาที"})
      QVERIFY2(text.contains(QString::fromUtf8(s)), s);
    QVERIFY(!text.contains(QStringLiteral("CNC Program Sheet")));
    const QString fonts = run(QStringLiteral("pdffonts"), {pdf});
    // Every font embedded ("emb" column yes), the Thai one among them.
    QVERIFY2(fonts.contains(QStringLiteral("Loma")), qPrintable(fonts));
    for (const QString& line : fonts.split(QLatin1Char('\n')).mid(2))
      if (!line.trimmed().isEmpty()) QVERIFY2(line.contains(QStringLiteral(" yes ")), qPrintable(line));
  }

  void longProgramPaginatesWithTheHeaderOnEveryPage() {
    render::ReportData d = sampleData(ReportLanguage::English);
    std::string code;
    for (int n = 1; n <= 300; ++n) code += "N" + std::to_string(n * 10) + " G01 X" + std::to_string(n) + ". Z-1.\n";
    d.program.gcode = code;
    const QString pdf = out(QStringLiteral("long.pdf"));
    const int pages = writePdf(pdf, d, ReportLanguage::English, Sheet::Program);
    QVERIFY2(pages >= 3, qPrintable(QString::number(pages)));
    QCOMPARE(run(QStringLiteral("pdfinfo"), {pdf})
                 .contains(QRegularExpression(QStringLiteral("Pages:\\s+%1\\b").arg(pages))),
             true);
    int seen = 0;
    for (int p = 1; p <= pages; ++p) {
      const QString text = pageText(pdf, p);
      QVERIFY2(text.contains(QStringLiteral("CNC Program Sheet")), qPrintable(text));
      QVERIFY(text.contains(QStringLiteral("Page %1").arg(p)));
      QVERIFY(text.contains(QStringLiteral("Step shaft exercise")));
      QVERIFY(text.contains(QStringLiteral("Programmer")));
      // Every block printed exactly once, in order, across the pages.
      for (int n = seen + 1; n <= 300; ++n) {
        if (!text.contains(QStringLiteral("N%1 G01 X%2. Z-1.").arg(n * 10).arg(n))) break;
        seen = n;
      }
    }
    QCOMPARE(seen, 300);
  }

  void drawingSheetTitleBlock_data() {
    QTest::addColumn<int>("lang");
    QTest::newRow("en") << 0;
    QTest::newRow("th") << 1;
  }
  void drawingSheetTitleBlock() {
    QFETCH(int, lang);
    const ReportLanguage l = lang ? ReportLanguage::Thai : ReportLanguage::English;
    const render::ReportData d = sampleData(l);
    QVERIFY2(d.partNote.isEmpty(), qPrintable(d.partNote));
    const QString pdf = out(QStringLiteral("drawing-%1.pdf").arg(lang));
    writePdf(pdf, d, l, Sheet::Drawing);
    const QString text = pdfText(pdf);
    const QStringList expected =
        lang ? QStringList{QStringLiteral("เอกสารแสดงภาพชิ้นงาน"),
                           QStringLiteral("ชื่องาน"),
                           QStringLiteral("ชิ้นงาน"),
                           QStringLiteral("ผู้เขียน"),
                           QStringLiteral("วัสดุ"),
                           QStringLiteral("วันที่"),
                           QStringLiteral("19 ตุลาคม พ.ศ. 2542"),
                           QStringLiteral("มาตราส่วน")}
             : QStringList{QStringLiteral("Part Drawing"),     QStringLiteral("Project"),  QStringLiteral("Part"),
                           QStringLiteral("Programmer"),       QStringLiteral("Material"), QStringLiteral("Date"),
                           QStringLiteral("October 19, 1999"), QStringLiteral("Scale")};
    for (const QString& s : expected) QVERIFY2(text.contains(s), qPrintable(s + QStringLiteral("\n") + text));
    for (const char* s :
         {"Step shaft exercise", "Shaft SS-01", "Klueng samples", "Aluminium 6061", "01-step-shaft.txt"})
      QVERIFY2(text.contains(QString::fromUtf8(s)), s);
    QVERIFY(text.contains(render::kluengVersion()));
    QVERIFY(text.contains(QStringLiteral("Klueng 0.")));
  }

  void drawingShowsTheFinishedPartWithItsSize() {
    const render::ReportData d = sampleData(ReportLanguage::English);
    // Sample 01 finishes Ø30 from Z-3 to Z-20, Ø40 to Z-40 and Ø46 to Z-60 (bar Ø50 x 100);
    // the bar left in the chuck beyond Z-60 is not the part (issue 28 item 3).
    QVERIFY(d.part.containsMaterial(-10.0, 14.8));
    QVERIFY(!d.part.containsMaterial(-10.0, 15.3));
    QVERIFY(d.part.containsMaterial(-30.0, 19.8));
    QVERIFY(!d.part.containsMaterial(-30.0, 20.3));
    QVERIFY(d.part.containsMaterial(-59.9, 22.9));
    QVERIFY(!d.part.containsMaterial(-59.9, 23.3));  // no nose fillet up the bar's face
    QVERIFY(!d.part.containsMaterial(-80.0, 10.0));
    QVERIFY(d.part.blank.isEmpty());  // nor the bar's outline
    QCOMPARE(d.features.overallLength(), 60.0);
    const QString pdf = out(QStringLiteral("drawing-size.pdf"));
    writePdf(pdf, d, ReportLanguage::English, Sheet::Drawing);
    const QString text = pdfText(pdf);
    QVERIFY2(text.contains(QStringLiteral("Ø46")) && !text.contains(QStringLiteral("Ø50")), qPrintable(text));
    QVERIFY(text.contains(QRegularExpression(QStringLiteral("(^|\\n)60\\n"))));  // overall length: the part's
    QVERIFY(!text.contains(QStringLiteral("100")));
    QVERIFY(text.contains(QStringLiteral("Scale 1:1")));
  }

  // Issue 10: the drawing dimensions the finished part from its features, in
  // both languages, and every dimension stays inside the frame and off the
  // title block on the landscape A4 that Print Preview and Print use.
  void drawingDimensionsEveryFeature_data() {
    QTest::addColumn<int>("language");
    QTest::newRow("en") << static_cast<int>(ReportLanguage::English);
    QTest::newRow("th") << static_cast<int>(ReportLanguage::Thai);
  }
  void drawingDimensionsEveryFeature() {
    QFETCH(int, language);
    const auto lang = static_cast<ReportLanguage>(language);
    const render::ReportData d = sampleData(lang);
    QVERIFY(!d.features.empty());
    const QString pdf = out(QStringLiteral("dimensions-%1.pdf").arg(language));
    writePdf(pdf, d, lang, Sheet::Drawing);
    const QString text = pdfText(pdf);
    for (const char* s : {"Ø30", "Ø40", "Ø46", "C3", "R2", "C1"})
      QVERIFY2(text.contains(QString::fromUtf8(s)), qPrintable(QString::fromUtf8(s) + QStringLiteral("\n") + text));
    // Chained steps from the right face (20, 20, 20) and the part's overall 60.
    QCOMPARE(text.count(QRegularExpression(QStringLiteral("(^|\\s)20(?=\\s)"))), 3);
    QVERIFY(text.contains(QRegularExpression(QStringLiteral("(^|\\n)60\\n"))));

    QPrinter printer(QPrinter::HighResolution);
    printer.setOutputFormat(QPrinter::PdfFormat);
    printer.setPageSize(QPageSize(QPageSize::A4));
    printer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
    printer.setPageOrientation(QPageLayout::Landscape);
    QCOMPARE(printer.pageLayout().pageSize().id(), QPageSize::A4);
    QVERIFY(printer.width() > printer.height());
    const render::DrawingLayout layout = render::drawingLayout(printer, d.part);
    QCOMPARE(render::scaleText(layout.scale), QStringLiteral("1:1"));
    QVERIFY(layout.frame.contains(layout.partRect));
    const std::vector<render::DimensionItem> dims = render::drawingDimensions(printer, d, lang);
    QVERIFY(dims.size() >= 11);  // 3 diameters, 3 steps + overall, 3 leaders, the nose note
    const std::vector<QLineF> partLines = render::drawingDimensionFrame(printer, d, lang).partLines;
    QVERIFY(partLines.size() >= 16);  // both halves' outline
    for (const render::DimensionItem& item : dims) {
      const QRectF box = render::dimensionBounds(item);
      QVERIFY2(layout.frame.contains(box), qPrintable(item.text));
      QVERIFY2(!layout.titleBlock.intersects(box), qPrintable(item.text));
      // Every label off the part's drawn lines (issue 28 item 3).
      QVERIFY2(!render::touchesAny(item.textRect, partLines), qPrintable(item.text));
    }
    // No two texts on top of each other.
    for (std::size_t a = 0; a < dims.size(); ++a)
      for (std::size_t b = a + 1; b < dims.size(); ++b)
        QVERIFY2(!dims[a].textRect.intersects(dims[b].textRect),
                 qPrintable(dims[a].text + QStringLiteral(" / ") + dims[b].text));
  }

  void programWithErrorsDrawsTheBarAndSaysSo() {
    render::ReportData d;
    d.program = *core::io::readProgramFile(KLUENG_SAMPLES_DIR "/04-grammar-errors.txt").value;
    d.date = QDate(1999, 10, 19);
    const auto job = jobOf(d.program, core::gcode::Dialect::Classic);
    d.part = render::finishedPart(*job, ReportLanguage::English, &d.partNote);
    QCOMPARE(d.partNote, QStringLiteral("The program has errors: the drawing shows the uncut bar."));
    QCOMPARE(d.part.blank, d.part.fill.boundingRect());  // nothing cut
    const QString pdf = out(QStringLiteral("drawing-errors.pdf"));
    writePdf(pdf, d, ReportLanguage::English, Sheet::Drawing);
    QVERIFY(pdfText(pdf).contains(QStringLiteral("The program has errors")));
    QString thaiNote;
    render::finishedPart(*job, ReportLanguage::Thai, &thaiNote);
    QVERIFY(thaiNote.contains(QStringLiteral("ข้อผิดพลาด")));
  }

  void longLinesWrapWithoutLosingCode() {
    render::ReportData d = sampleData(ReportLanguage::English);
    std::string longLine = "N10 G01 X10. Z-5. F0.1 (";
    for (int i = 0; i < 40; ++i) longLine += "word" + std::to_string(i) + " ";
    longLine += "end)";
    d.program.gcode = longLine + "\nN20 M30\n";
    const QString pdf = out(QStringLiteral("wrap.pdf"));
    QCOMPARE(writePdf(pdf, d, ReportLanguage::English, Sheet::Program), 1);
    const QString text = pdfText(pdf);
    for (int i = 0; i < 40; ++i)
      QVERIFY2(text.contains(QStringLiteral("word%1 ").arg(i)) || text.contains(QStringLiteral("word%1\n").arg(i)),
               qPrintable(QString::number(i)));
    QVERIFY(text.contains(QStringLiteral("end)")));
    // Two file lines, the first wrapped: line numbers 7 and 8 only.
    QVERIFY(text.contains(QRegularExpression(QStringLiteral("(^|\\n)7 N10 G01"))));
    QVERIFY(text.contains(QRegularExpression(QStringLiteral("(^|\\n)8 N20 M30"))));
    QVERIFY(!text.contains(QRegularExpression(QStringLiteral("(^|\\n)9 "))));
  }

  void drawingIsToTheStatedScale() {
    // Sample 01's bar: Ø150 x 1100 is too long for 1:1 on A4 landscape; a short part is drawn 1:1.
    render::ReportData d = sampleData(ReportLanguage::English);
    d.part = render::stockShapeFromBlank(40.0, 120.0);
    d.features = {};
    d.partNote.clear();
    const QString pdf = out(QStringLiteral("scale.pdf"));
    writePdf(pdf, d, ReportLanguage::English, Sheet::Drawing);
    QVERIFY(pdfText(pdf).contains(QStringLiteral("Scale 1:1")));
    // Rasterise at 254 dpi (10 px per mm) and measure the stock fill: 120 x 40 mm on paper.
    const QString png = out(QStringLiteral("scale"));
    run(QStringLiteral("pdftoppm"),
        {QStringLiteral("-png"), QStringLiteral("-r"), QStringLiteral("254"), QStringLiteral("-singlefile"), pdf, png});
    const QImage image(png + QStringLiteral(".png"));
    QVERIFY(!image.isNull());
    const QColor fill = render::palette().stockFill;
    auto isFill = [&](int x, int y) {
      const QColor c = image.pixelColor(x, y);
      return std::abs(c.red() - fill.red()) < 12 && std::abs(c.green() - fill.green()) < 12 &&
             std::abs(c.blue() - fill.blue()) < 12;
    };
    int left = image.width(), right = -1, top = image.height(), bottom = -1;
    for (int y = 0; y < image.height(); y += 2)
      for (int x = 0; x < image.width(); x += 2)
        if (isFill(x, y)) {
          left = std::min(left, x);
          right = std::max(right, x);
          top = std::min(top, y);
          bottom = std::max(bottom, y);
        }
    QVERIFY(right > left);
    QVERIFY2(std::abs((right - left) - 1200) <= 12, qPrintable(QString::number(right - left)));
    QVERIFY2(std::abs((bottom - top) - 400) <= 12, qPrintable(QString::number(bottom - top)));

    // A long bar goes down to a smaller standard scale that fits.
    d.part = render::stockShapeFromBlank(150.0, 1100.0);
    QPdfWriter writer(out(QStringLiteral("layout.pdf")));
    writer.setResolution(300);
    writer.setPageSize(QPageSize(QPageSize::A4));
    writer.setPageOrientation(QPageLayout::Landscape);
    const render::DrawingLayout layout = render::drawingLayout(writer, d.part);
    QCOMPARE(layout.scale, 0.2);
    QVERIFY(layout.drawingArea.contains(layout.partRect));
    QCOMPARE(qRound(layout.partRect.width() / layout.pixelsPerMm), 220);
  }

  // Issue 28 item 3: a drawing gives no callout for what the machine leaves on its
  // own — a thread's run-out, a drill's point, a sliver — and keeps the designer's
  // chamfers, the one before the thread included.
  void machiningTracesGetNoCallout() {
    using core::cut::FeatureKind;
    using core::cut::FeatureSide;
    core::cut::PartFeatures part;
    part.zRight = 0.0;
    part.zLeft = -40.0;
    const auto feature = [](FeatureKind kind, FeatureSide side, double zLeft, double zRight, double dLeft,
                            double dRight) {
      core::cut::PartFeature f;
      f.kind = kind;
      f.side = side;
      f.zLeft = zLeft;
      f.zRight = zRight;
      f.diameterLeft = dLeft;
      f.diameterRight = dRight;
      f.axialLength = zRight - zLeft;
      f.radialHeight = std::abs(dRight - dLeft) / 2.0;
      return f;
    };
    core::cut::PartFeature thread = feature(FeatureKind::Thread, FeatureSide::Outside, -22.0, 0.0, 30.0, 30.0);
    thread.diameter = 30.0;
    thread.minorDiameter = 28.16;
    thread.pitch = 1.5;
    const auto lead = feature(FeatureKind::Chamfer, FeatureSide::Outside, -1.5, 0.0, 30.0, 27.0);
    const auto runOut = feature(FeatureKind::Taper, FeatureSide::Outside, -23.0, -22.0, 29.9, 28.3);
    const auto shoulder = feature(FeatureKind::Chamfer, FeatureSide::Outside, -31.0, -30.0, 40.0, 38.0);
    const auto sliver = feature(FeatureKind::Chamfer, FeatureSide::Outside, -30.02, -30.0, 38.0, 37.96);
    const auto drillPoint = feature(FeatureKind::Taper, FeatureSide::Inside, -36.0, -30.0, 0.0, 20.0);
    const auto boreMouth = feature(FeatureKind::Chamfer, FeatureSide::Inside, -1.0, 0.0, 20.0, 22.0);
    part.outside = {lead, thread, runOut, shoulder, sliver};
    part.inside = {boreMouth, drillPoint};
    QVERIFY(!render::isMachiningTrace(lead, part));
    QVERIFY(!render::isMachiningTrace(shoulder, part));
    QVERIFY(!render::isMachiningTrace(boreMouth, part));
    QVERIFY(render::isMachiningTrace(runOut, part));
    QVERIFY(render::isMachiningTrace(sliver, part));
    QVERIFY(render::isMachiningTrace(drillPoint, part));

    // A point fitted as several bevels and cut off by the part's left end (the
    // bar goes on into the chuck): every piece of it is the drill's, not the bore's
    // mouth chamfer, which widens towards the outside.
    core::cut::PartFeatures bush;
    bush.zRight = 0.0;
    bush.zLeft = -52.0;
    const auto bore = feature(FeatureKind::Cylinder, FeatureSide::Inside, -51.4, 0.0, 25.6, 25.6);
    const auto step = feature(FeatureKind::Cylinder, FeatureSide::Inside, -51.44, -51.4, 8.65, 8.65);
    const auto steep = feature(FeatureKind::Taper, FeatureSide::Inside, -51.65, -51.44, 7.8, 8.65);
    const auto flat = feature(FeatureKind::Taper, FeatureSide::Inside, -51.75, -51.65, 7.6, 7.8);
    const auto end = feature(FeatureKind::Chamfer, FeatureSide::Inside, -52.0, -51.75, 6.7, 7.6);
    bush.inside = {boreMouth, bore, step, steep, flat, end};
    QVERIFY(!render::isMachiningTrace(boreMouth, bush));
    QVERIFY(render::isMachiningTrace(steep, bush));
    QVERIFY(render::isMachiningTrace(flat, bush));
    QVERIFY(render::isMachiningTrace(end, bush));
    // The same bevels ending on a shoulder inside the part are the bore's own.
    const auto counterbore = feature(FeatureKind::Cylinder, FeatureSide::Inside, -60.0, -52.0, 6.7, 6.7);
    bush.zLeft = -60.0;
    bush.inside.push_back(counterbore);
    QVERIFY(!render::isMachiningTrace(steep, bush));
  }

  // Issue 28 item 3: tolerances and surface finish where the design gives them, drawn
  // after the size and as the ISO mark on the surface; none without a design.
  void designMarksPrintTolerancesAndFinish() {
    render::ReportData d = sampleData(ReportLanguage::English);
    d.finishes.clear();  // the roughness the cuts leave (issue 39) is a list of its own, tested by itself
    const QString plainPdf = out(QStringLiteral("marks-none.pdf"));
    writePdf(plainPdf, d, ReportLanguage::English, Sheet::Drawing);
    const QString plain = pdfText(plainPdf);
    QVERIFY(!plain.contains(QStringLiteral("h7")) && !plain.contains(QStringLiteral("Ra ")));
    d.marks.tolerance = [](const core::cut::PartFeature& f) {
      return f.kind == core::cut::FeatureKind::Cylinder && std::abs(f.diameter - 30.0) < 0.01 ? QStringLiteral("h7")
                                                                                              : QString();
    };
    d.marks.surfaceFinish = [](const core::cut::PartFeature& f) {
      return f.kind == core::cut::FeatureKind::Cylinder && std::abs(f.diameter - 40.0) < 0.01 ? QStringLiteral("Ra 1.6")
                                                                                              : QString();
    };
    const QString pdf = out(QStringLiteral("marks.pdf"));
    writePdf(pdf, d, ReportLanguage::English, Sheet::Drawing);
    const QString text = pdfText(pdf);
    // Written after the size on its line (pdftotext reads turned text one word a line).
    QVERIFY2(text.contains(QRegularExpression(QStringLiteral("Ø30\\s+h7"))), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("Ra 1.6")), qPrintable(text));
    QCOMPARE(text.count(QStringLiteral("h7")), 1);
  }

  // File > Export PDF of the main window: program sheet then the drawing (landscape),
  // in the UI's language; the actions are in the File menu and Print on the tool bar.
  void mainWindowExportsBothSheetsInTheUiLanguage() {
    klueng::test::freshUserFolders();
    gui::initResources();
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
    gui::MainWindow w;
    w.show();
    QVERIFY(w.openFile(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt")));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    for (const char* name :
         {"actionPrintCode", "actionPrintDrawing", "actionPrintPreview", "actionExportPdf", "actionPrint"}) {
      QAction* a = w.action(QString::fromLatin1(name));
      QVERIFY2(a && !a->icon().isNull() && !a->text().isEmpty(), name);
    }
    auto* fileBar = w.findChild<QToolBar*>(QStringLiteral("fileToolBar"));
    QVERIFY(fileBar && fileBar->actions().contains(w.action(QStringLiteral("actionPrint"))));
    QVERIFY(w.action(QStringLiteral("actionPrintCode"))->shortcut() == QKeySequence(QKeySequence::Print));

    const QString en = out(QStringLiteral("window-en.pdf"));
    QVERIFY(w.exportPdf(en));
    const QString info = run(QStringLiteral("pdfinfo"), {QStringLiteral("-f"), QStringLiteral("1"),
                                                         QStringLiteral("-l"), QStringLiteral("2"), en});
    QVERIFY2(info.contains(QRegularExpression(QStringLiteral("Pages:\\s+2\\b"))), qPrintable(info));
    QVERIFY2(info.contains(QRegularExpression(QStringLiteral("Page\\s+1 size:\\s+595(\\.\\d+)? x 84[12]"))),
             qPrintable(info));
    QVERIFY2(info.contains(QRegularExpression(QStringLiteral("Page\\s+2 size:\\s+84[12](\\.\\d+)? x 595"))),
             qPrintable(info));
    const QString sheet = pageText(en, 1);
    QVERIFY(sheet.contains(QStringLiteral("CNC Program Sheet")));
    QVERIFY(sheet.contains(QStringLiteral("N100 G01 Z-59.8 F0.25")));
    const QString drawing = pageText(en, 2);
    QVERIFY(drawing.contains(QStringLiteral("Part Drawing")));
    QVERIFY(drawing.contains(QStringLiteral("01-step-shaft.txt")));
    QVERIFY(drawing.contains(render::reportDate(QDate::currentDate(), ReportLanguage::English)));
    QVERIFY2(!drawing.contains(QStringLiteral("errors")) && !drawing.contains(QStringLiteral("alarm")),
             qPrintable(drawing));

    gui::Language::instance()->setLanguage(QStringLiteral("th"));
    QTRY_VERIFY(w.action(QStringLiteral("actionExportPdf"))
                    ->text()
                    .contains(QStringLiteral("ส่งออก")));  // LanguageChange is posted
    QVERIFY(w.action(QStringLiteral("actionPrintCode"))->text().contains(QStringLiteral("พิมพ์")));
    const QString th = out(QStringLiteral("window-th.pdf"));
    QVERIFY(w.exportPdf(th));
    QVERIFY(pageText(th, 1).contains(QStringLiteral("ชุดรหัสสั่งการทำงาน")));
    QVERIFY(pageText(th, 2).contains(render::reportDate(QDate::currentDate(), ReportLanguage::Thai)));
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
  }

  // Issue 28 item 3: every printout's title block is the file's own job header. After
  // sample 01 was open, a new program and a plain G-code file print without sample 01's
  // project, part and material (they used to carry them on every later sheet).
  void titleBlockIsTheFilesOwnAfterSample01() {
    klueng::test::freshUserFolders();
    gui::initResources();
    gui::Language::instance()->setLanguage(QStringLiteral("en"));
    gui::MainWindow w;
    w.show();
    QVERIFY(w.openFile(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt")));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    const QString first = out(QStringLiteral("stale-01.pdf"));
    QVERIFY(w.exportPdf(first));
    QVERIFY(pageText(first, 2).contains(QStringLiteral("Shaft SS-01")));  // the sample's own header

    const QStringList sample01 = {QStringLiteral("Step shaft exercise"), QStringLiteral("Shaft SS-01"),
                                  QStringLiteral("Aluminium 6061")};
    const auto carriesNothingOf01 = [&](const QString& pdf) {
      for (int page : {1, 2})
        for (const QString& s : sample01)
          if (pageText(pdf, page).contains(s)) return s + QStringLiteral(" on page ") + QString::number(page);
      return QString();
    };
    w.newFile();
    w.editor()->setPlainText(QStringLiteral("G00 X20. Z2.\nG01 Z-10. F0.2\nM30\n"));
    const QString untitled = out(QStringLiteral("stale-new.pdf"));
    QVERIFY(w.exportPdf(untitled));
    QCOMPARE(carriesNothingOf01(untitled), QString());
    QVERIFY(pageText(untitled, 2).contains(QStringLiteral("untitled.txt")));

    QTemporaryDir dir;
    const QString plain = dir.filePath(QStringLiteral("pin.nc"));
    QFile f(plain);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("O0007\nG21 G99\nT0101\nG97 S800 M03\nG00 X32. Z2.\nG01 X20. F0.2\nZ-15.\nX32.\nG00 X100. Z100.\nM30\n");
    f.close();
    w.editor()->document()->setModified(false);  // the typed program may go without asking
    QVERIFY(w.openFile(plain));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    const QString other = out(QStringLiteral("stale-plain.pdf"));
    QVERIFY(w.exportPdf(other));
    QCOMPARE(carriesNothingOf01(other), QString());
    QVERIFY(pageText(other, 2).contains(QStringLiteral("pin.nc")));
  }

  // File > Print Preview lays out both sheets: the program sheet, then the drawing.
  void printPreviewShowsBothSheets() {
    klueng::test::freshUserFolders();
    gui::initResources();
    gui::MainWindow w;
    w.show();
    QVERIFY(w.openFile(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt")));
    QVERIFY(QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000));
    int pages = -1;
    bool orientationRestored = false;
    QTimer::singleShot(0, this, [&] {
      QVERIFY(
          QTest::qWaitFor([] { return qobject_cast<QPrintPreviewDialog*>(QApplication::activeModalWidget()); }, 10000));
      auto* dialog = qobject_cast<QPrintPreviewDialog*>(QApplication::activeModalWidget());
      auto* preview = dialog->findChild<QPrintPreviewWidget*>();
      QVERIFY(preview);
      QVERIFY(QTest::qWaitFor([preview] { return preview->pageCount() > 0; }, 10000));
      pages = preview->pageCount();
      orientationRestored =
          dialog->printer()->pageLayout().orientation() == QPageLayout::Portrait;  // after the landscape drawing
      dialog->reject();
    });
    w.printPreview();
    QCOMPARE(pages, 2);
    QVERIFY(orientationRestored);
  }

 private:
  // KLUENG_REPORT_OUT=<folder> keeps the PDFs for a look (pdftoppm -png -r 60 ...).
  QString out(const QString& name) const {
    const QString keep = qEnvironmentVariable("KLUENG_REPORT_OUT");
    return keep.isEmpty() ? dir_.filePath(name) : QDir(keep).filePath(name);
  }
  QTemporaryDir dir_;
};

KLUENG_GUI_TEST(ReportTest)
#include "report_test.moc"

// The class grading report (issue 11): a summary table of every student, then,
// against a drawing (issue 28), each student's toleranced dimensions measured,
// then, with --sheets, each student's program sheet and drawing, in one PDF.
#include <QBuffer>
#include <QCoreApplication>
#include <QFileInfo>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QPageLayout>
#include <QPainter>
#include <QPdfWriter>
#include <QString>
#include <algorithm>
#include <cstring>

#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/diagnostic_codes.h"
#include "render/class_pdf_input.h"
#include "render/module_bytes.h"
#include "render/offscreen_app.h"
#include "render/report_sheets.h"

namespace klueng::render {

namespace {

QString cell(const KluengClassPdf& in, int row, int column) {
  return QString::fromUtf8(
      in.cells[static_cast<std::size_t>(row) * kClassPdfColumns + static_cast<std::size_t>(column)]);
}

// The summary table, as many pages as it needs. Returns false when nothing could be drawn.
void paintSummary(QPainter& p, QPdfWriter& writer, const KluengClassPdf& in) {
  const bool thai = in.thai != 0;
  const ReportLanguage lang = thai ? ReportLanguage::Thai : ReportLanguage::English;
  const double mm = writer.logicalDpiX() / 25.4;
  const QRectF page(0, 0, writer.width(), writer.height());
  namespace codes = core::codes;
  QStringList header;
  for (const char* code : {codes::kReportColumnProgram, codes::kReportColumnResult, codes::kReportColumnErrors,
                           codes::kReportColumnAlarm, codes::kReportColumnSeconds, codes::kReportColumnLeftover,
                           codes::kReportColumnGouge, codes::kReportColumnCutting})
    header << reportText(code, lang);
  if (in.drawing && !in.hasReference) {  // the drawing's dimensions in tolerance, no leftover or gouge
    header[5] = reportText(codes::kReportColumnInTolerance, lang);
    header[6] = QString();
  }
  const double widths[kClassPdfColumns] = {0.14, 0.07, 0.11, 0.11, 0.11, 0.11, 0.12, 0.23};
  const double rowHeight = 6.5 * mm, top = (in.drawing && in.hasReference ? 36 : 30) * mm;
  const int perPage = std::max(1, static_cast<int>((page.height() - top - 10 * mm) / rowHeight) - 1);
  int passed = 0;
  for (int r = 0; r < in.rows; ++r) passed += cell(in, r, 1) == QStringLiteral("pass") ? 1 : 0;
  const QFont titleFont(QString::fromLatin1(kReportFontFamily), 16, QFont::Bold);
  const QFont textFont(QString::fromLatin1(kReportFontFamily), 9);
  const QFont boldFont(QString::fromLatin1(kReportFontFamily), 9, QFont::Bold);
  for (int first = 0, pageNo = 0; first < in.rows || pageNo == 0; first += perPage, ++pageNo) {
    if (pageNo > 0) writer.newPage();
    p.setPen(Qt::black);
    p.setFont(titleFont);
    p.drawText(QRectF(0, 0, page.width(), 10 * mm), Qt::AlignLeft | Qt::AlignVCenter,
               reportText(codes::kReportClassTitle, lang));
    p.setFont(textFont);
    // What they were graded against: the reference, the drawing, or both on two lines.
    QStringList lines;
    const QString date = reportDate(QDate::currentDate(), lang);
    const QString drawing = in.drawing ? QString::fromUtf8(in.drawing) : QString();
    if (in.hasReference || !in.drawing)
      lines << reportText(
          codes::kReportAgainstReference, lang,
          {QString::fromUtf8(in.reference ? in.reference : ""), QString::number(in.tolerance, 'f', 3), date});
    if (in.drawing && in.hasReference)
      lines << reportText(codes::kReportAlsoDrawing, lang, {drawing, QString::number(in.dimensions)});
    else if (in.drawing)
      lines << reportText(codes::kReportAgainstDrawing, lang, {drawing, QString::number(in.dimensions), date});
    lines << reportText(codes::kCliClassTotals, lang,
                        {QString::number(in.rows), QString::number(passed), QString::number(in.rows - passed)});
    for (int i = 0; i < lines.size(); ++i)
      p.drawText(QRectF(0, (11 + 6 * i) * mm, page.width(), 6 * mm), Qt::AlignLeft | Qt::AlignVCenter,
                 p.fontMetrics().elidedText(lines[i], Qt::ElideRight, static_cast<int>(page.width())));
    double y = top;
    auto row = [&](const QStringList& texts, bool head, int index) {
      double x = 0;
      if (!head && index % 2 == 1) p.fillRect(QRectF(0, y, page.width(), rowHeight), QColor(242, 242, 242));
      for (int c = 0; c < kClassPdfColumns; ++c) {
        const double w = widths[c] * page.width();
        // A heading shrinks to its column (down to about 6 pt) rather than lose its words.
        QFont font = head ? boldFont : textFont;
        for (int i = 0; head && i < 4 && QFontMetricsF(font, p.device()).horizontalAdvance(texts[c]) > w - 2 * mm; ++i)
          font.setPointSizeF(font.pointSizeF() * 0.9);
        p.setFont(font);
        p.setPen(!head && c == 1 ? (texts[c] == QStringLiteral("pass") ? QColor(0, 120, 0) : QColor(190, 0, 0))
                                 : QColor(Qt::black));
        QString text = texts[c];
        if (!head && c == 1)  // the CSV's "pass"/"fail" in the sheet's words
          text = reportText(text == QStringLiteral("pass") ? codes::kReportPass : codes::kReportFail, lang);
        p.drawText(QRectF(x + 1 * mm, y, w - 2 * mm, rowHeight), Qt::AlignLeft | Qt::AlignVCenter,
                   p.fontMetrics().elidedText(text, Qt::ElideRight, static_cast<int>(w - 2 * mm)));
        x += w;
      }
      y += rowHeight;
    };
    row(header, true, 0);
    p.setPen(QPen(Qt::black, 0.3 * mm));
    p.drawLine(QPointF(0, y), QPointF(page.width(), y));
    for (int r = first; r < std::min(in.rows, first + perPage); ++r) {
      QStringList texts;
      for (int c = 0; c < kClassPdfColumns; ++c) texts << cell(in, r, c);
      row(texts, false, r);
    }
  }
}

// Against a drawing: each student's toleranced dimensions, measured, in or out,
// a block per student kept on one page when it fits.
void paintInspection(QPainter& p, QPdfWriter& writer, const KluengClassPdf& in) {
  const ReportLanguage lang = in.thai != 0 ? ReportLanguage::Thai : ReportLanguage::English;
  const double mm = writer.logicalDpiX() / 25.4;
  const QRectF page(0, 0, writer.width(), writer.height());
  namespace codes = core::codes;
  QStringList header;
  for (const char* code : {codes::kReportColumnDimension, codes::kReportColumnTolerance, codes::kReportColumnLimits,
                           codes::kReportColumnMeasured, codes::kReportColumnResult})
    header << reportText(code, lang);
  const double widths[5] = {0.24, 0.22, 0.20, 0.16, 0.18};
  const double rowHeight = 6.5 * mm, top = 24 * mm, bottom = page.height() - 5 * mm;
  const QFont titleFont(QString::fromLatin1(kReportFontFamily), 16, QFont::Bold);
  const QFont textFont(QString::fromLatin1(kReportFontFamily), 9);
  const QFont boldFont(QString::fromLatin1(kReportFontFamily), 9, QFont::Bold);
  const auto dimCell = [&](int row, int dim, int column) {
    const std::size_t at =
        (static_cast<std::size_t>(row) * static_cast<std::size_t>(in.dimensions) + static_cast<std::size_t>(dim)) * 5 +
        static_cast<std::size_t>(column);
    return QString::fromUtf8(in.dimensionCells[at]);
  };
  double y = 0;
  const auto drawRow = [&](const QStringList& texts, const QFont& font, const QColor& resultColour) {
    double x = 0;
    for (int c = 0; c < 5; ++c) {
      const double w = widths[c] * page.width();
      p.setFont(font);
      p.setPen(c == 4 ? resultColour : QColor(Qt::black));
      p.drawText(QRectF(x + 1 * mm, y, w - 2 * mm, rowHeight), Qt::AlignLeft | Qt::AlignVCenter,
                 p.fontMetrics().elidedText(texts[c], Qt::ElideRight, static_cast<int>(w - 2 * mm)));
      x += w;
    }
    y += rowHeight;
  };
  const auto newPage = [&] {
    writer.newPage();
    p.setPen(Qt::black);
    p.setFont(titleFont);
    p.drawText(QRectF(0, 0, page.width(), 10 * mm), Qt::AlignLeft | Qt::AlignVCenter,
               reportText(codes::kReportInspectionTitle, lang, {QString::fromUtf8(in.drawing)}));
    p.setFont(textFont);
    p.drawText(QRectF(0, 11 * mm, page.width(), 6 * mm), Qt::AlignLeft | Qt::AlignVCenter,
               reportText(codes::kReportInspectionRule, lang));
    y = top;
    drawRow(header, boldFont, Qt::black);
    p.setPen(QPen(Qt::black, 0.3 * mm));
    p.drawLine(QPointF(0, y), QPointF(page.width(), y));
  };
  newPage();
  for (int r = 0; r < in.rows; ++r) {
    const double block = rowHeight * (1 + in.dimensions);
    if (y + block > bottom && y > top + rowHeight) newPage();
    const bool pass = cell(in, r, 1) == QStringLiteral("pass");
    int inCount = 0;
    for (int d = 0; d < in.dimensions; ++d)
      inCount += in.verdicts[static_cast<std::size_t>(r * in.dimensions + d)] == 0;
    p.fillRect(QRectF(0, y, page.width(), rowHeight), QColor(230, 230, 230));
    const QString verdict = reportText(pass ? codes::kReportPass : codes::kReportFail, lang);
    const QString count =
        reportText(codes::kReportInCount, lang, {QString::number(inCount), QString::number(in.dimensions)});
    drawRow({cell(in, r, 0), count, QString(), QString(), verdict}, boldFont,
            pass ? QColor(0, 120, 0) : QColor(190, 0, 0));
    for (int d = 0; d < in.dimensions; ++d) {
      if (y + rowHeight > bottom) newPage();
      const int v = in.verdicts[static_cast<std::size_t>(r * in.dimensions + d)];
      drawRow({dimCell(r, d, 0), dimCell(r, d, 1), dimCell(r, d, 2), dimCell(r, d, 3), dimCell(r, d, 4)}, textFont,
              v == 0 ? QColor(0, 120, 0) : QColor(190, 0, 0));
    }
  }
}

}  // namespace

}  // namespace klueng::render

extern "C" __attribute__((visibility("default"))) int klueng_class_pdf(const KluengClassPdf* in, char** bytes,
                                                                       std::size_t* size, char* error,
                                                                       std::size_t errorSize) {
  using namespace klueng;
  // The reason in the sheets' language (messages_render.cpp): the CLI and the GUI show it as it is.
  auto fail = [&](const char* code) {
    const QByteArray why =
        render::reportText(code, in && in->thai ? render::ReportLanguage::Thai : render::ReportLanguage::English)
            .toUtf8();
    if (error && errorSize > 0) std::strncpy(error, why.constData(), errorSize - 1), error[errorSize - 1] = '\0';
    return 0;
  };
  if (!in || !bytes || !size) return fail(core::codes::kReportNothingToWrite);
  render::ensureGuiApplication();
  // Into memory: QPdfWriter does not report a failed file write (issue 29), the CLI's writer does.
  QBuffer pdf;
  pdf.open(QIODevice::WriteOnly);
  QPdfWriter writer(&pdf);
  writer.setResolution(300);
  writer.setPageSize(QPageSize(QPageSize::A4));
  writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
  QPainter painter;
  if (!painter.begin(&writer)) return fail(core::codes::kReportPdfNotStarted);
  render::paintSummary(painter, writer, *in);
  if (in->drawing && in->dimensions > 0 && in->rows > 0) render::paintInspection(painter, writer, *in);
  if (in->sheets > 0) {
    const core::machine::LoadedSetup setup = core::machine::loadMachineSetup(in->configDir ? in->configDir : "");
    const auto dialect = static_cast<core::gcode::Dialect>(in->dialect);
    const render::ReportLanguage lang = in->thai ? render::ReportLanguage::Thai : render::ReportLanguage::English;
    for (int i = 0; i < in->sheets; ++i) {
      // The job as the grading read it: its folder's subprograms, its tools, its stock.
      if (!in->sheetPaths[i] || !*in->sheetPaths[i]) continue;  // refused unread: its row says why
      core::job::JobInput input;
      input.path = in->sheetPaths[i];
      input.folderRun = true;  // no sheet prints a file that is not a program
      input.setup = setup.setup;
      input.run.dialect = dialect;
      const std::shared_ptr<const core::job::Job> job = core::job::makeJob(std::move(input));
      if (!job->file()) continue;  // unreadable: its row in the table says so
      render::ReportData data;
      data.program = *job->file();
      data.fileName = QFileInfo(QString::fromUtf8(in->sheetPaths[i])).fileName();
      render::addRunResults(data, *job, lang, true);
      writer.setPageOrientation(QPageLayout::Portrait);
      writer.newPage();
      render::paintProgramSheet(painter, writer, data, lang);
      writer.setPageOrientation(QPageLayout::Landscape);
      writer.newPage();
      render::paintDrawingSheet(painter, writer, data, lang);
    }
  }
  if (!painter.end()) return fail(core::codes::kReportPdfNotFinished);
  if (!render::handBytes(pdf.data(), bytes, size)) return fail(core::codes::kReportPdfEmpty);
  return 1;
}

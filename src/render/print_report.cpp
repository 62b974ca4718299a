// klueng-cli print (issue 10): the program sheet and/or the drawing sheet of one
// program as a PDF, painted exactly as the GUI's Export PDF paints them.
#include <QBuffer>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QString>
#include <algorithm>
#include <cmath>
#include <cstring>

#include "klueng/core/diagnostic_codes.h"
#include "render/drawing_dimensions.h"
#include "render/module_bytes.h"
#include "render/offscreen_app.h"
#include "render/print_pdf_input.h"
#include "render/report_sheets.h"

extern "C" __attribute__((visibility("default"))) int klueng_print_pdf(const KluengPrintPdf* in, char** bytes,
                                                                       std::size_t* size, char* error,
                                                                       std::size_t errorSize) {
  using namespace klueng;
  // The reason in the sheets' language (messages_render.cpp): the CLI and the GUI show it as it is.
  const auto fail = [&](const char* code) {
    const QByteArray why =
        render::reportText(code, in && in->thai ? render::ReportLanguage::Thai : render::ReportLanguage::English)
            .toUtf8();
    if (error && errorSize > 0) {
      std::strncpy(error, why.constData(), errorSize - 1);
      error[errorSize - 1] = '\0';
    }
    return 0;
  };
  if (!in || !bytes || !size || !in->job || !in->job->file()) return fail(core::codes::kReportNothingToWrite);
  if (!in->programSheet && !in->drawingSheet) return fail(core::codes::kReportNoSheet);
  render::ensureGuiApplication();
  const render::ReportLanguage lang = in->thai ? render::ReportLanguage::Thai : render::ReportLanguage::English;
  render::ReportData data;
  data.program = *in->job->file();
  data.fileName = QString::fromUtf8(in->fileName ? in->fileName : "");
  data.units = core::UnitFormat(in->inch ? core::DisplayUnits::Inch : core::DisplayUnits::Mm);
  render::addRunResults(data, *in->job, lang, in->drawingSheet != 0);
  if (in->design) data.marks = render::designMarks(*in->design);

  // Into memory: QPdfWriter does not report a failed file write (issue 29), the CLI's writer does.
  QBuffer pdf;
  pdf.open(QIODevice::WriteOnly);
  QPdfWriter writer(&pdf);
  writer.setCreator(render::kluengVersion());
  writer.setTitle(data.fileName);
  writer.setResolution(300);
  writer.setPageSize(QPageSize(QPageSize::A4));
  writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
  // A shaft is long: the drawing is landscape, the listing portrait.
  writer.setPageOrientation(in->programSheet ? QPageLayout::Portrait : QPageLayout::Landscape);
  QPainter painter;
  if (!painter.begin(&writer)) return fail(core::codes::kReportPdfNotStarted);
  if (in->programSheet) render::paintProgramSheet(painter, writer, data, lang);
  if (in->drawingSheet) {
    if (in->programSheet) {
      writer.setPageOrientation(QPageLayout::Landscape);
      writer.newPage();
    }
    render::paintDrawingSheet(painter, writer, data, lang);
  }
  if (!painter.end()) return fail(core::codes::kReportPdfNotFinished);
  if (!klueng::render::handBytes(pdf.data(), bytes, size)) return fail(core::codes::kReportPdfEmpty);
  return 1;
}

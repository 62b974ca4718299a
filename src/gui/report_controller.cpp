#include "gui/report_controller.h"

#include <QApplication>
#include <QBuffer>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QPrintDialog>
#include <QPrintPreviewDialog>
#include <QPrinter>
#include <QPrinterInfo>

#include "gui/file_save.h"
#include "gui/off_gui_thread.h"
#include "klueng/core/job/job.h"
#include "gui/language.h"
#include "render/drawing_dimensions.h"

namespace klueng::gui {

namespace {

render::ReportLanguage reportLanguage() {
  return Language::instance()->isThai() ? render::ReportLanguage::Thai : render::ReportLanguage::English;
}

void preparePrinter(QPrinter& printer, const QString& title) {
  printer.setDocName(title);
  printer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
}

}  // namespace

ReportController::ReportController(QWidget* window, std::function<Source()> source)
    : QObject(window), window_(window), source_(std::move(source)) {}

render::ReportData ReportController::reportData(const Source& source, bool withPart) const {
  render::ReportData data;
  data.program = source.program;
  data.fileName = source.displayName;
  data.date = QDate::currentDate();
  data.units = source.units;
  if (source.design) data.marks = render::designMarks(*source.design);
  core::job::JobInput input;
  input.file = source.program;
  input.setup = source.setup;  // the job's tools, as a run uses them
  input.inferTools = false;
  input.run.dialect = source.dialect;
  input.folder = std::string();
  QApplication::setOverrideCursor(Qt::WaitCursor);
  // The job, its run and its cut on a worker thread (issue 30); one run for both sheets.
  data = offGuiThread([data, input = std::move(input), lang = reportLanguage(), withPart]() mutable {
    render::addRunResults(data, *core::job::makeJob(std::move(input)), lang, withPart);
    return data;
  });
  QApplication::restoreOverrideCursor();
  return data;
}

void ReportController::paint(QPainter& painter, QPagedPaintDevice& device, const render::ReportData& data, bool code,
                             bool drawing) {
  const render::ReportLanguage lang = reportLanguage();
  if (code) render::paintProgramSheet(painter, device, data, lang);
  if (code && drawing) {
    // A shaft is long: the drawing goes on a landscape page (takes effect on the next page);
    // the device keeps its own orientation for the next job.
    const QPageLayout::Orientation before = device.pageLayout().orientation();
    device.setPageOrientation(QPageLayout::Landscape);
    device.newPage();
    render::paintDrawingSheet(painter, device, data, lang);
    device.setPageOrientation(before);
    return;
  }
  if (drawing) render::paintDrawingSheet(painter, device, data, lang);
}

void ReportController::printCode() {
  const Source source = source_();
  QPrinter printer(QPrinter::HighResolution);
  preparePrinter(printer, source.displayName);
  QPrintDialog dialog(&printer, window_);
  dialog.setWindowTitle(tr("Print Code"));
  if (dialog.exec() != QDialog::Accepted) return;
  const render::ReportData data = reportData(source, false);
  QPainter painter(&printer);
  paint(painter, printer, data, true, false);
}

void ReportController::printCodeNow() {
  const QPrinterInfo info = QPrinterInfo::defaultPrinter();
  if (info.isNull()) {
    emit message(tr("No printer is set up: use File > Export PDF to save the sheet."), 5000);
    return;
  }
  const Source source = source_();
  QPrinter printer(info, QPrinter::HighResolution);
  preparePrinter(printer, source.displayName);
  const render::ReportData data = reportData(source, false);
  QPainter painter(&printer);
  paint(painter, printer, data, true, false);
  emit message(tr("Program sheet sent to %1").arg(info.printerName()), 3000);
}

void ReportController::printDrawing() {
  const Source source = source_();
  QPrinter printer(QPrinter::HighResolution);
  preparePrinter(printer, source.displayName);
  printer.setPageOrientation(QPageLayout::Landscape);  // a shaft is long: landscape fits it larger
  QPrintDialog dialog(&printer, window_);
  dialog.setWindowTitle(tr("Print Drawing"));
  if (dialog.exec() != QDialog::Accepted) return;
  const render::ReportData data = reportData(source, true);
  QPainter painter(&printer);
  paint(painter, printer, data, false, true);
}

void ReportController::printPreview() {
  const Source source = source_();
  QPrinter printer(QPrinter::HighResolution);
  preparePrinter(printer, source.displayName);
  const render::ReportData data = reportData(source, true);
  QPrintPreviewDialog dialog(&printer, window_);
  dialog.setWindowTitle(tr("Print Preview"));
  connect(&dialog, &QPrintPreviewDialog::paintRequested, this, [&data](QPrinter* p) {
    QPainter painter(p);
    paint(painter, *p, data, true, true);
  });
  dialog.exec();
}

bool ReportController::exportPdf(const QString& path) {
  const Source source = source_();
  QString target = path;
  if (target.isEmpty()) {
    const QFileInfo file(source.filePath.isEmpty() ? source.displayName : source.filePath);
    target = QFileDialog::getSaveFileName(window_, tr("Export PDF"),
                                          file.dir().filePath(file.completeBaseName() + QStringLiteral(".pdf")),
                                          tr("PDF files (*.pdf)"));
    if (target.isEmpty()) return false;
  }
  // Refused with the path, and why when there is more to say than that.
  const auto fail = [&](const QString& why) {
    QString text = tr("Cannot write %1").arg(QDir::toNativeSeparators(target));
    if (!why.isEmpty()) text += QStringLiteral("\n\n") + why;
    QMessageBox::warning(window_, tr("Export PDF"), text);
    return false;
  };
  // The program itself is never the PDF's name (issue 29).
  if (const QString why = outputIsInput(target, source.filePath); !why.isEmpty()) return fail(why);
  // Nor is a file of the setup the run reads: a table, a tool picture, the library (issue 42).
  if (const QString why = outputIsAnyInput(target, setupInputs(source.setup)); !why.isEmpty()) return fail(why);
  const render::ReportData data = reportData(source, true);
  // Into memory, then the checked writer: QPdfWriter says nothing when its file write fails
  // (a full disk gave a 0-byte PDF and "Exported"); the old file is kept on failure.
  QBuffer pdf;
  pdf.open(QIODevice::WriteOnly);
  QPdfWriter writer(&pdf);
  writer.setTitle(source.displayName);
  writer.setCreator(render::kluengVersion());
  writer.setResolution(600);
  writer.setPageSize(QPageSize(QPageSize::A4));
  writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
  QPainter painter;
  if (!painter.begin(&writer)) return fail({});
  paint(painter, writer, data, true, true);
  if (!painter.end()) return fail({});
  const QByteArray& bytes = pdf.data();
  if (const QString why =
          writeFileChecked(target, std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
      !why.isEmpty())
    return fail(why);
  emit message(tr("Exported %1").arg(QDir::toNativeSeparators(target)), 3000);
  return true;
}

}  // namespace klueng::gui

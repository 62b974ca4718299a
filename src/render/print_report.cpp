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

#include "render/module_bytes.h"
#include "render/offscreen_app.h"
#include "render/print_pdf_input.h"
#include "render/report_sheets.h"

extern "C" __attribute__((visibility("default"))) int klueng_print_pdf(const KluengPrintPdf* in, char** bytes,
                                                                       std::size_t* size, char* error,
                                                                       std::size_t errorSize) {
  using namespace klueng;
  const auto fail = [&](const QString& why) {
    if (error && errorSize > 0) {
      std::strncpy(error, why.toUtf8().constData(), errorSize - 1);
      error[errorSize - 1] = '\0';
    }
    return 0;
  };
  if (!in || !bytes || !size || !in->job || !in->job->file()) return fail(QStringLiteral("nothing to print"));
  if (!in->programSheet && !in->drawingSheet) return fail(QStringLiteral("no sheet asked for"));
  render::ensureGuiApplication();
  const render::ReportLanguage lang = in->thai ? render::ReportLanguage::Thai : render::ReportLanguage::English;
  render::ReportData data;
  data.program = *in->job->file();
  data.fileName = QString::fromUtf8(in->fileName ? in->fileName : "");
  data.units = core::UnitFormat(in->inch ? core::DisplayUnits::Inch : core::DisplayUnits::Mm);
  render::addRunResults(data, *in->job, lang, in->drawingSheet != 0);
  if (in->design) {
    // A design's own tolerance after the Ø it belongs to (a general ISO 2768
    // class is the title block's, not each size's), and its roughness on the surface.
    const std::vector<core::cut::DrawnDimension> drawn = core::design::drawnDimensions(*in->design);
    struct Finish {
      core::cut::FeatureSide side;
      double diameter, zRight, zLeft, ra;
    };
    std::vector<Finish> finishes;
    for (const auto side : {core::cut::FeatureSide::Outside, core::cut::FeatureSide::Inside}) {
      double z = 0.0;
      for (const core::design::OutsideStep& s :
           side == core::cut::FeatureSide::Outside ? in->design->outside : in->design->inside) {
        if (s.kind == core::design::StepKind::Cylinder && s.roughness > 0.0)
          finishes.push_back({side, s.diameter, z, z - s.length, s.roughness});
        z -= s.length;
      }
    }
    data.marks.surfaceFinish = [finishes](const core::cut::PartFeature& f) {
      if (f.kind != core::cut::FeatureKind::Cylinder) return QString();
      for (const Finish& s : finishes)
        if (s.side == f.side && std::abs(s.diameter - f.diameter) <= 0.02 &&
            std::min(s.zRight, f.zRight) > std::max(s.zLeft, f.zLeft))
          return QStringLiteral("Ra %1").arg(s.ra);
      return QString();
    };
    data.marks.tolerance = [drawn](const core::cut::PartFeature& f) {
      if (f.kind != core::cut::FeatureKind::Cylinder) return QString();
      for (const core::cut::DrawnDimension& d : drawn) {
        if (d.kind != core::cut::DimensionKind::Diameter || d.side != f.side || !d.tolerance.given() ||
            d.tolerance.text.rfind("ISO 2768", 0) == 0)
          continue;
        const bool overlaps = std::min(d.zRight, f.zRight) > std::max(d.zLeft, f.zLeft);
        if (overlaps && std::abs(d.nominal - f.diameter) <= 0.02) return QString::fromStdString(d.tolerance.text);
      }
      return QString();
    };
  }

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
  if (!painter.begin(&writer)) return fail(QStringLiteral("the PDF could not be started"));
  if (in->programSheet) render::paintProgramSheet(painter, writer, data, lang);
  if (in->drawingSheet) {
    if (in->programSheet) {
      writer.setPageOrientation(QPageLayout::Landscape);
      writer.newPage();
    }
    render::paintDrawingSheet(painter, writer, data, lang);
  }
  if (!painter.end()) return fail(QStringLiteral("the PDF could not be finished"));
  if (!klueng::render::handBytes(pdf.data(), bytes, size)) return fail(QStringLiteral("the PDF is empty"));
  return 1;
}

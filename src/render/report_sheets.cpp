#include "render/report_sheets.h"
#include "render/number_text.h"

#include <QFontMetricsF>
#include <QLocale>
#include <QPen>
#include <QStringList>
#include <QTextLayout>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/part_span.h"
#include "klueng/core/job/job.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/messages.h"

#ifndef KLUENG_VERSION
#define KLUENG_VERSION "0"
#endif

namespace klueng::render {
namespace {

bool thai(ReportLanguage lang) { return lang == ReportLanguage::Thai; }

// The texts of SPEC 12 (and GLOSSARY.md), fixed per sheet language: read once from the catalog.
struct Texts {
  QString programTitle, page, project, material, part, diameter, programmer, length;
  QString drawingTitle, date, fileName, version, scale, untitled;
  QString cycleTime, toAlarm;
};

Texts textsIn(ReportLanguage lang) {
  namespace codes = core::codes;
  const auto t = [lang](const char* code) { return reportText(code, lang); };
  return Texts{t(codes::kReportProgramTitle), reportText(codes::kReportPage, lang, {QStringLiteral("%1")}),
               t(codes::kReportProject),      t(codes::kReportMaterial),
               t(codes::kReportPart),         t(codes::kReportDiameter),
               t(codes::kReportProgrammer),   t(codes::kReportLength),
               t(codes::kReportDrawingTitle), t(codes::kReportDate),
               t(codes::kReportFileName),     t(codes::kReportVersion),
               t(codes::kReportScale),        t(codes::kReportUntitled),
               t(codes::kReportCycleTime),    t(codes::kReportToAlarm)};
}

const Texts& texts(ReportLanguage lang) {
  static const Texts english = textsIn(ReportLanguage::English);
  static const Texts thaiTexts = textsIn(ReportLanguage::Thai);
  return thai(lang) ? thaiTexts : english;
}

QString number(double v) { return trimmedNumber(v, 3); }

QString qs(const std::string& s) { return QString::fromStdString(s); }

QFont reportFont(double points, bool bold = false) {
  QFont f(QString::fromLatin1(kReportFontFamily));
  f.setPointSizeF(points);
  f.setBold(bold);
  f.setStyleStrategy(QFont::PreferOutline);
  return f;
}

QFont monoFont(double points) {
  QFont f(QString::fromLatin1(kReportMonoFamily));
  f.setStyleHint(QFont::Monospace);
  f.setPointSizeF(points);
  return f;
}

double pixelsPerMm(const QPaintDevice& device) { return device.logicalDpiX() / 25.4; }

// A pen `mm` wide on paper.
QPen paperPen(const QPaintDevice& device, double mm, const QColor& colour = Qt::black,
              Qt::PenStyle style = Qt::SolidLine) {
  QPen pen(colour, mm * pixelsPerMm(device), style);
  pen.setCapStyle(Qt::FlatCap);
  return pen;
}

// One printed row of the listing: a file line, or the continuation of a long one.
struct ListingRow {
  int fileLine = 0;  // 0 for a continuation row
  QString text;
};

std::vector<ListingRow> listingRows(const core::io::ProgramFile& file, const QFont& font, QPaintDevice* device,
                                    double textWidth) {
  QString code = qs(file.gcode);
  if (code.endsWith(QLatin1Char('\n'))) code.chop(1);
  const QStringList lines = code.split(QLatin1Char('\n'));
  std::vector<ListingRow> rows;
  rows.reserve(static_cast<std::size_t>(lines.size()));
  const QFontMetricsF fm(font, device);
  for (int i = 0; i < lines.size(); ++i) {
    QString line = lines[i];
    line.replace(QLatin1Char('\t'), QStringLiteral("    "));
    const int fileLine = file.gcodeFirstLine + i;
    if (fm.horizontalAdvance(line) <= textWidth) {
      rows.push_back({fileLine, line});
      continue;
    }
    // Long lines wrap (a printout never drops code).
    QTextLayout layout(line, font, device);
    QTextOption option;
    option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    layout.setTextOption(option);
    layout.beginLayout();
    bool first = true;
    for (QTextLine tl = layout.createLine(); tl.isValid(); tl = layout.createLine()) {
      tl.setLineWidth(textWidth);
      rows.push_back({first ? fileLine : 0, line.mid(tl.textStart(), tl.textLength())});
      first = false;
    }
    layout.endLayout();
  }
  return rows;
}

// Draws `text` in `rect`, shrinking the font until it fits the width.
void drawFitted(QPainter& painter, const QRectF& rect, const QString& text, QFont font, int flags) {
  QPaintDevice* device = painter.device();
  for (int i = 0; i < 8 && QFontMetricsF(font, device).horizontalAdvance(text) > rect.width(); ++i)
    font.setPointSizeF(font.pointSizeF() * 0.9);
  painter.setFont(font);
  const QString shown = QFontMetricsF(font, device).elidedText(text, Qt::ElideRight, rect.width());
  painter.drawText(rect, flags | Qt::TextSingleLine, shown);
}

// ISO 5456-2 first-angle symbol: the truncated cone's front view (small end on
// the left) and, on its right, its view from the left (two circles), centred in
// `cell`. Klueng's drawings are first angle (ISO E), as Thai and ISO practice is.
void paintFirstAngleSymbol(QPainter& painter, const QRectF& cell, double mm) {
  const double d = std::min(cell.height() - 1.6 * mm, cell.width() / 3.2);  // the large end's diameter
  const double len = 1.2 * d, gap = 0.5 * d;
  const double left = cell.center().x() - (len + gap + d) / 2.0, cy = cell.center().y();
  painter.save();
  painter.setPen(paperPen(*painter.device(), 0.25));
  painter.setBrush(Qt::NoBrush);
  painter.drawPolygon(QPolygonF({QPointF(left, cy - d / 4.0), QPointF(left + len, cy - d / 2.0),
                                 QPointF(left + len, cy + d / 2.0), QPointF(left, cy + d / 4.0)}));
  const QPointF centre(left + len + gap + d / 2.0, cy);
  painter.drawEllipse(centre, d / 2.0, d / 2.0);
  painter.drawEllipse(centre, d / 4.0, d / 4.0);
  painter.setPen(paperPen(*painter.device(), 0.13, Qt::black, Qt::DashDotLine));
  painter.drawLine(QPointF(left - 0.8 * mm, cy), QPointF(centre.x() + d / 2.0 + 0.8 * mm, cy));
  painter.drawLine(QPointF(centre.x(), cy - d / 2.0 - 0.8 * mm), QPointF(centre.x(), cy + d / 2.0 + 0.8 * mm));
  painter.restore();
}

// A label/value cell: small label on the left, value after it.
void drawField(QPainter& painter, const QRectF& cell, const QString& label, const QString& value, double labelWidth) {
  const double pad = pixelsPerMm(*painter.device()) * 1.5;
  const QRectF labelRect(cell.left() + pad, cell.top(), labelWidth - pad, cell.height());
  const QRectF valueRect(cell.left() + labelWidth, cell.top(), cell.width() - labelWidth - pad, cell.height());
  painter.setPen(QColor(70, 70, 70));
  drawFitted(painter, labelRect, label, reportFont(9), Qt::AlignLeft | Qt::AlignVCenter);
  painter.setPen(Qt::black);
  drawFitted(painter, valueRect, value, reportFont(10.5, true), Qt::AlignLeft | Qt::AlignVCenter);
}

}  // namespace

QString reportText(const char* code, ReportLanguage lang, const QStringList& args) {
  core::Diagnostic d{core::Severity::Note, code, {}, {}};
  for (const QString& a : args) d.args.push_back(a.toStdString());
  return QString::fromStdString(core::formatMessage(d, thai(lang) ? core::Lang::Th : core::Lang::En));
}

QString reportDate(const QDate& date, ReportLanguage lang, DateLength length) {
  if (!date.isValid()) return {};
  const bool isLong = length == DateLength::Long;
  // Thai dates count years in the Buddhist era (2569 = 2026), which Qt's
  // calendars do not have; the month names are the locale's.
  const QLocale locale =
      thai(lang) ? QLocale(QLocale::Thai, QLocale::Thailand) : QLocale(QLocale::English, QLocale::UnitedStates);
  const QString month = locale.monthName(date.month(), isLong ? QLocale::LongFormat : QLocale::ShortFormat);
  const int year = date.year() + (thai(lang) ? 543 : 0);
  return reportText(isLong ? core::codes::kReportDateLong : core::codes::kReportDateShort, lang,
                    {QString::number(date.day()), month, QString::number(year)});
}

QString kluengVersion() { return QStringLiteral("Klueng %1").arg(QString::fromLatin1(KLUENG_VERSION)); }

namespace {

// One run of the program for a report: its cycle times into `times` (when
// given), then its finished part, cut only when `cutPart` (the drawing).
// The job's timeline and cut are computed here when nobody asked before: call on a worker thread.
StockShape runForReport(const core::job::Job& job, ReportLanguage lang, QString* note, ReportData* times, bool cutPart,
                        core::cut::PartFeatures* features = nullptr,
                        std::vector<std::pair<core::cut::PartFeature, core::cut::SurfaceFinish>>* finishes = nullptr) {
  if (!job.file()) return StockShape{};
  const core::io::ProgramFile& file = *job.file();
  const StockShape blank = stockShapeFromBlank(file.header.diameterMm(), file.header.lengthMm(), file.header.boreMm());
  const core::machine::Timeline* timeline = job.timeline();
  if (times && timeline) {
    times->cycleTime = timeline->cycleTime();
    times->cycleTimeToAlarm = timeline->alarm.has_value();
    times->toolTimes = timeline->timeByTool();
  }
  if (!cutPart) return blank;
  if (file.header.diameterMm() <= 0 || file.header.lengthMm() <= 0) {
    if (note) *note = reportText(core::codes::kReportBadStock, lang);
    return blank;
  }
  if (!timeline) {
    if (note) *note = reportText(core::codes::kReportProgramErrors, lang);
    return blank;
  }
  const core::cut::CutSimulator& cut = *job.cut();
  if (cut.alarm() && note) *note = reportText(core::codes::kReportStoppedOnAlarm, lang);
  // The finished part only: no parting gap, no bar left in the chuck (issue 28 item 3).
  const core::cut::Stock part = core::cut::cropToSpan(cut.stock(), core::cut::finishedPartSpan(cut.stock()));
  if (features) {
    *features = core::cut::partFeatures(part);
    core::cut::addThreadLeadChamfers(part, *features);  // the chamfer before a thread is the designer's
    // The roughness each surface got: the run measured, each surface's last cut (issue 39).
    if (finishes && !cut.alarm()) {
      finishes->clear();
      const core::cut::CuttingData measured = core::cut::measureRun(*timeline, file.header, job.setup(), job.units());
      for (const auto* side : {&features->outside, &features->inside})
        for (const core::cut::PartFeature& f : *side)
          if (f.isNoseFillet()) {
            continue;  // the tool's print in a corner, not a surface the drawing gives
          } else if (const auto got = core::cut::surfaceFinishOf(measured, cut.stock(), f)) {
            finishes->emplace_back(f, *got);
          }
    }
  }
  StockShape shape = stockShapeFromStock(part);
  shape.blank = QRectF();  // a drawing shows the part, not the bar it came from
  return shape;
}

}  // namespace

StockShape finishedPart(const core::job::Job& job, ReportLanguage lang, QString* note) {
  return runForReport(job, lang, note, nullptr, true);
}

void addRunResults(ReportData& data, const core::job::Job& job, ReportLanguage lang, bool withPart) {
  const StockShape part = runForReport(job, lang, &data.partNote, &data, withPart, &data.features, &data.finishes);
  if (withPart) data.part = part;
}

QString durationText(double seconds, ReportLanguage lang) {
  const double tenths = std::round(std::max(0.0, seconds) * 10.0) / 10.0;
  const int minutes = static_cast<int>(tenths / 60.0);
  const double rest = tenths - 60.0 * minutes;
  const QString secondsText = QString::number(rest, 'f', 1);
  return minutes > 0 ? reportText(core::codes::kReportMinutes, lang, {QString::number(minutes), secondsText})
                     : reportText(core::codes::kReportSeconds, lang, {secondsText});
}

void addCycleTimes(ReportData& data, const core::job::Job& job) {
  addRunResults(data, job, ReportLanguage::English, false);
}

namespace {

// "3 min 12.4 s (T01 2 min 10.0 s, T04 1 min 2.4 s)".
QString cycleTimeText(const ReportData& data, ReportLanguage lang) {
  QString text = durationText(data.cycleTime, lang);
  QStringList parts;
  for (const core::machine::ToolTime& t : data.toolTimes)
    if (t.tool > 0)
      parts << QStringLiteral("T%1 %2").arg(t.tool, 2, 10, QLatin1Char('0')).arg(durationText(t.seconds, lang));
  if (!parts.isEmpty()) text += QStringLiteral(" (") + parts.join(QStringLiteral(", ")) + QLatin1Char(')');
  if (data.cycleTimeToAlarm) text += QStringLiteral(", ") + texts(lang).toAlarm;
  return text;
}

}  // namespace

// ------------------------------------------------------------------ program sheet

int paintProgramSheet(QPainter& painter, QPagedPaintDevice& device, const ReportData& data, ReportLanguage lang) {
  const Texts& t = texts(lang);
  const double mm = pixelsPerMm(device);
  const QRectF page(0, 0, device.width(), device.height());
  const core::io::JobHeader& h = data.program.header;

  const QFont titleFont = reportFont(16, true);
  const QFont listFont = monoFont(9.5);
  const QFontMetricsF listMetrics(listFont, &device);
  const double rowHeight = listMetrics.lineSpacing();

  // Header block: title row, then a 3 x 2 grid of fields (SPEC 12 order, row by row).
  const double titleHeight = 12 * mm;
  const double fieldHeight = 8 * mm;
  const bool timed = data.cycleTime >= 0.0;
  const int gridRows = timed ? 4 : 3;  // the cycle time takes a full-width fourth row
  const QRectF grid(page.left(), page.top() + titleHeight, page.width(), gridRows * fieldHeight);
  const double listTop = grid.bottom() + 5 * mm;
  const double footerHeight = 6 * mm;
  const double listBottom = page.bottom() - footerHeight;

  int lastLine = data.program.gcodeFirstLine;
  for (char c : data.program.gcode) lastLine += (c == '\n') ? 1 : 0;
  const QString widest = QString(QString::number(lastLine).size(), QLatin1Char('0'));
  const double numberWidth = listMetrics.horizontalAdvance(widest);
  const double textLeft = page.left() + numberWidth + 4 * mm;
  const std::vector<ListingRow> rows = listingRows(data.program, listFont, &device, page.right() - textLeft);
  const int rowsPerPage = std::max(1, static_cast<int>((listBottom - listTop) / rowHeight));
  const int pages = std::max(1, static_cast<int>((rows.size() + static_cast<std::size_t>(rowsPerPage) - 1) /
                                                 static_cast<std::size_t>(rowsPerPage)));

  const QString fileName = data.fileName.isEmpty() ? t.untitled : data.fileName;
  const std::array<std::pair<QString, QString>, 6> fields = {{
      {t.project, qs(h.project)},
      {t.material, qs(h.material)},
      {t.part, qs(h.part)},
      // A tube as "118/Ø90" (outside/bore), as the stock line writes it (docs/program-file.md).
      {t.diameter, h.boreMm() > 0 ? number(h.diameterMm()) + QStringLiteral("/\u00D8") + number(h.boreMm())
                                  : number(h.diameterMm())},
      {t.programmer, qs(h.programmer)},
      {t.length, number(h.lengthMm())},
  }};

  for (int p = 0; p < pages; ++p) {
    if (p > 0) device.newPage();
    painter.save();
    // Title and page number.
    painter.setPen(Qt::black);
    drawFitted(painter, QRectF(page.left(), page.top(), page.width() * 0.7, titleHeight), t.programTitle, titleFont,
               Qt::AlignLeft | Qt::AlignVCenter);
    drawFitted(painter, QRectF(page.left() + page.width() * 0.7, page.top(), page.width() * 0.3, titleHeight),
               t.page.arg(p + 1), reportFont(11), Qt::AlignRight | Qt::AlignVCenter);
    // Field grid.
    painter.setPen(paperPen(device, 0.3));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(grid);
    const double half = grid.width() / 2;
    painter.drawLine(QPointF(grid.left() + half, grid.top()),
                     QPointF(grid.left() + half, grid.top() + 3 * fieldHeight));
    for (int r = 1; r < gridRows; ++r)
      painter.drawLine(QPointF(grid.left(), grid.top() + r * fieldHeight),
                       QPointF(grid.right(), grid.top() + r * fieldHeight));
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const int row = static_cast<int>(i / 2);
      const int col = static_cast<int>(i % 2);
      const QRectF cell(grid.left() + col * half, grid.top() + row * fieldHeight, half, fieldHeight);
      drawField(painter, cell, fields[i].first, fields[i].second, 32 * mm);
    }
    if (timed)
      drawField(painter, QRectF(grid.left(), grid.top() + 3 * fieldHeight, grid.width(), fieldHeight), t.cycleTime,
                cycleTimeText(data, lang), 32 * mm);
    // Listing.
    painter.setFont(listFont);
    const std::size_t first = static_cast<std::size_t>(p) * static_cast<std::size_t>(rowsPerPage);
    const std::size_t last = std::min(rows.size(), first + static_cast<std::size_t>(rowsPerPage));
    double y = listTop;
    for (std::size_t i = first; i < last; ++i, y += rowHeight) {
      if (rows[i].fileLine > 0) {
        painter.setPen(QColor(110, 110, 110));
        painter.drawText(QRectF(page.left(), y, numberWidth, rowHeight), Qt::AlignRight | Qt::AlignVCenter,
                         QString::number(rows[i].fileLine));
      }
      painter.setPen(Qt::black);
      painter.drawText(QRectF(textLeft, y, page.right() - textLeft, rowHeight), Qt::AlignLeft | Qt::AlignVCenter,
                       rows[i].text);
    }
    // Footer: file name and date, so loose pages find their program.
    painter.setPen(paperPen(device, 0.2, QColor(120, 120, 120)));
    painter.drawLine(QPointF(page.left(), listBottom + 1 * mm), QPointF(page.right(), listBottom + 1 * mm));
    painter.setPen(QColor(90, 90, 90));
    const QRectF footer(page.left(), listBottom + 1 * mm, page.width(), footerHeight - 1 * mm);
    drawFitted(painter, QRectF(footer.left(), footer.top(), footer.width() * 0.6, footer.height()), fileName,
               reportFont(8), Qt::AlignLeft | Qt::AlignVCenter);
    drawFitted(painter,
               QRectF(footer.left() + footer.width() * 0.6, footer.top(), footer.width() * 0.4, footer.height()),
               reportDate(data.date, lang), reportFont(8), Qt::AlignRight | Qt::AlignVCenter);
    painter.restore();
  }
  return pages;
}

// ------------------------------------------------------------------ drawing sheet

double drawingScale(const QSizeF& partMm, const QSizeF& areaMm) {
  static const std::array<double, 12> scales = {10.0, 5.0, 2.0, 1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002};
  for (double s : scales)
    if (partMm.width() * s <= areaMm.width() && partMm.height() * s <= areaMm.height()) return s;
  return scales.back();
}

QString scaleText(double scale) {
  if (scale >= 1.0) return QStringLiteral("%1:1").arg(number(scale));
  return QStringLiteral("1:%1").arg(number(1.0 / scale));
}

namespace {
constexpr int kTitleRows = 8;

QRectF partSceneRect(const StockShape& part) {
  QRectF r = part.boundingRect();
  if (r.isEmpty()) r = part.blank.united(QRectF(part.blank.left(), 0, part.blank.width(), part.blank.height()));
  return r;
}
}  // namespace

namespace {

// The roughness each surface got (issue 39): a heading and a row per surface where the drawing
// leaves room — left of the title block under a drawing across the sheet, above it beside one.
void paintFinishes(QPainter& painter, const DrawingLayout& l, const ReportData& data, ReportLanguage lang) {
  if (data.finishes.empty()) return;
  const double mm = l.pixelsPerMm;
  const bool beside = l.drawingArea.right() <= l.titleBlock.left() + 1.0;
  const QRectF box = beside ? QRectF(l.titleBlock.left(), l.drawingArea.top(), l.titleBlock.width(),
                                     l.titleBlock.top() - 4 * mm - l.drawingArea.top())
                            : QRectF(l.frame.left() + 5 * mm, l.titleBlock.top(),
                                     l.titleBlock.left() - 9 * mm - l.frame.left(), l.titleBlock.height());
  const double rowHeight = 4.6 * mm;
  const int rows = static_cast<int>(box.height() / rowHeight) - 1;
  if (rows < 1 || box.width() < 40 * mm) return;
  const core::Lang coreLang = lang == ReportLanguage::Thai ? core::Lang::Th : core::Lang::En;
  painter.save();
  painter.setPen(Qt::black);
  drawFitted(painter, QRectF(box.left(), box.top(), box.width(), rowHeight),
             reportText(core::codes::kReportFinishTitle, lang), reportFont(9, true), Qt::AlignLeft | Qt::AlignVCenter);
  const int count = static_cast<int>(data.finishes.size());
  const int shown = count > rows ? rows - 1 : count;
  const auto qs = [](const std::string& s) { return QString::fromStdString(s); };
  for (int i = 0; i < shown; ++i) {
    const auto& [f, got] = data.finishes[static_cast<std::size_t>(i)];
    QString surface = qs(core::cut::featureLabel(f, coreLang, data.units));
    if (f.kind == core::cut::FeatureKind::Face)
      surface = qs(core::cut::featureKindName(f.kind, coreLang)) + QStringLiteral(" Z") + qs(data.units.size(f.zLeft));
    else
      surface += QStringLiteral(" Z%1…%2").arg(qs(data.units.size(f.zRight)), qs(data.units.size(f.zLeft)));
    if (f.side == core::cut::FeatureSide::Inside) surface = reportText(core::codes::kReportInside, lang, {surface});
    const QString text = reportText(
        core::codes::kReportFinishRow, lang,
        {surface, QString::number(got.ra, 'f', 2), QString::number(got.rz, 'f', 1), QString::number(got.line),
         QString::number(data.units.value(got.feed), 'g', 3) + QLatin1Char(' ') +
             qs(data.units.feedUnit(true, coreLang)),
         qs(data.units.size(got.noseRadius, 3))});
    drawFitted(painter, QRectF(box.left(), box.top() + (i + 1) * rowHeight, box.width(), rowHeight), text,
               reportFont(8.5), Qt::AlignLeft | Qt::AlignVCenter);
  }
  if (shown < count)
    drawFitted(painter, QRectF(box.left(), box.top() + (shown + 1) * rowHeight, box.width(), rowHeight),
               reportText(core::codes::kReportFinishMore, lang, {QString::number(count - shown)}), reportFont(8.5),
               Qt::AlignLeft | Qt::AlignVCenter);
  painter.restore();
}

}  // namespace

DrawingLayout drawingLayout(const QPagedPaintDevice& device, const StockShape& part) {
  DrawingLayout l;
  l.pixelsPerMm = pixelsPerMm(device);
  const double mm = l.pixelsPerMm;
  l.frame = QRectF(0, 0, device.width(), device.height()).adjusted(1 * mm, 1 * mm, -1 * mm, -1 * mm);
  const double blockWidth = std::min(120 * mm, l.frame.width() * 0.6);
  const double blockHeight = kTitleRows * 7 * mm;
  l.titleBlock = QRectF(l.frame.right() - blockWidth, l.frame.bottom() - blockHeight, blockWidth, blockHeight);
  // The part goes above the title block across the sheet, or beside it down to
  // the frame, whichever draws it larger; the sheet title is above both.
  const double top = l.frame.top() + 16 * mm;
  const QRectF above(l.frame.left() + 8 * mm, top, l.frame.width() - 16 * mm, l.titleBlock.top() - 4 * mm - top);
  const QRectF beside(l.frame.left() + 8 * mm, top, l.titleBlock.left() - 4 * mm - (l.frame.left() + 8 * mm),
                      l.frame.bottom() - 4 * mm - top);
  // The part itself leaves room for diameters on its left, leaders above it and
  // two rows of lengths and a note below it.
  const auto partAreaOf = [&](const QRectF& area) { return area.adjusted(12 * mm, 22 * mm, -8 * mm, -24 * mm); };
  const QRectF scene = partSceneRect(part);
  const double scaleAbove = drawingScale(scene.size(), partAreaOf(above).size() / mm);
  const double scaleBeside = drawingScale(scene.size(), partAreaOf(beside).size() / mm);
  l.drawingArea = scaleBeside > scaleAbove ? beside : above;
  l.scale = std::max(scaleAbove, scaleBeside);
  const QRectF partArea = partAreaOf(l.drawingArea);
  const QSizeF onPaper = scene.size() * l.scale * mm;
  l.partRect = QRectF(partArea.center() - QPointF(onPaper.width() / 2, onPaper.height() / 2), onPaper);
  return l;
}

namespace {

DimensionFrame dimensionFrame(const QPagedPaintDevice& device, const ReportData& data, const DrawingLayout& l,
                              ReportLanguage lang) {
  DimensionFrame f;
  const QPointF sceneCentre = partSceneRect(data.part).center();
  const QPointF pageCentre = l.partRect.center();
  const double k = l.scale * l.pixelsPerMm;
  // Scene y is -X (radius): the upper half is drawn above the centre line.
  f.toPage = [=](double z, double r) {
    return QPointF(pageCentre.x() + (z - sceneCentre.x()) * k, pageCentre.y() + (-r - sceneCentre.y()) * k);
  };
  f.mm = l.pixelsPerMm;
  f.font = reportFont(8);
  f.device = &device;
  f.thai = thai(lang);
  f.bounds = l.drawingArea;
  f.marks = data.marks;
  // The part's outline, both halves, on the page: no label is written over it.
  const QPainterPath& outline = data.part.outline;
  QPointF from;
  for (int i = 0; i < outline.elementCount(); ++i) {
    const QPainterPath::Element e = outline.elementAt(i);
    const QPointF to(e.x, e.y);
    if (e.isLineTo())
      for (const double side : {1.0, -1.0})
        f.partLines.emplace_back(f.toPage(from.x(), -side * from.y()), f.toPage(to.x(), -side * to.y()));
    from = to;
  }
  f.units = data.units;
  return f;
}

}  // namespace

DimensionFrame drawingDimensionFrame(const QPagedPaintDevice& device, const ReportData& data, ReportLanguage lang) {
  return dimensionFrame(device, data, drawingLayout(device, data.part), lang);
}

std::vector<DimensionItem> drawingDimensions(const QPagedPaintDevice& device, const ReportData& data,
                                             ReportLanguage lang) {
  return layoutDimensions(data.features, dimensionFrame(device, data, drawingLayout(device, data.part), lang));
}

void paintDrawingSheet(QPainter& painter, QPagedPaintDevice& device, const ReportData& data, ReportLanguage lang) {
  const Texts& t = texts(lang);
  const DrawingLayout l = drawingLayout(device, data.part);
  const double mm = l.pixelsPerMm;
  const core::io::JobHeader& h = data.program.header;
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing);

  // Border and sheet title.
  painter.setPen(paperPen(device, 0.5));
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(l.frame);
  painter.setPen(Qt::black);
  drawFitted(painter, QRectF(l.frame.left() + 5 * mm, l.frame.top() + 3 * mm, l.frame.width() * 0.6, 12 * mm),
             t.drawingTitle, reportFont(16, true), Qt::AlignLeft | Qt::AlignVCenter);
  drawFitted(painter, QRectF(l.frame.right() - 65 * mm, l.frame.top() + 3 * mm, 60 * mm, 12 * mm),
             QStringLiteral("%1 %2").arg(t.scale, scaleText(l.scale)), reportFont(12),
             Qt::AlignRight | Qt::AlignVCenter);

  // The part, to scale: scene millimetres -> paper millimetres * scale.
  const QRectF scene = partSceneRect(data.part);
  const double k = l.scale * mm;
  painter.save();
  painter.translate(l.partRect.center());
  painter.scale(k, k);
  painter.translate(-scene.center());
  paintStock(painter, data.part, false);
  // Print-weight lines over the screen's hairlines.
  painter.setBrush(Qt::NoBrush);
  QPen outline(palette().stockEdge, 0.35 * mm / k);
  outline.setJoinStyle(Qt::MiterJoin);
  painter.setPen(outline);
  // Only the profile: the section's edge along the axis would hide the centre line.
  const double halfPen = outline.widthF() / 2;
  for (double side : {1.0, -1.0}) {
    painter.save();
    painter.scale(1.0, side);
    painter.setClipRect(
        QRectF(scene.left() - 1.0, scene.top() - 1.0, scene.width() + 2.0, -scene.top() + 1.0 - halfPen));
    painter.drawPath(data.part.outline);
    painter.restore();
  }
  QPen centre(palette().centreLine, 0.25 * mm / k, Qt::DashDotLine);
  painter.setPen(centre);
  painter.drawLine(QPointF(scene.left() - 8 * mm / k, 0.0), QPointF(scene.right() + 8 * mm / k, 0.0));
  painter.restore();

  // The part's features dimensioned; without them (no run) the overall size:
  // length below the part, diameter on its left (part millimetres).
  const QRectF fillBox = data.part.fill.boundingRect();
  const DimensionFrame dimFrame = dimensionFrame(device, data, l, lang);
  const std::vector<DimensionItem> dims = layoutDimensions(data.features, dimFrame);
  if (!dims.empty()) {
    paintDimensions(painter, dims, dimFrame);
  } else if (!fillBox.isEmpty()) {
    painter.setPen(paperPen(device, 0.2));
    const auto arrow = [&](const QPointF& tip, const QPointF& towards) {
      const QPointF d = towards - tip;
      const double len = std::hypot(d.x(), d.y());
      if (len <= 0) return;
      const QPointF u = d / len * (2.5 * mm);
      const QPointF n(-u.y() * 0.3, u.x() * 0.3);
      painter.save();
      painter.setBrush(Qt::black);
      painter.drawPolygon(QPolygonF({tip, tip + u + n, tip + u - n}));
      painter.restore();
    };
    const auto toPage = [&](double z, double y) {
      return QPointF(l.partRect.center().x() + (z - scene.center().x()) * k,
                     l.partRect.center().y() + (y - scene.center().y()) * k);
    };
    const QPointF a = toPage(fillBox.left(), scene.bottom());
    const QPointF b = toPage(fillBox.right(), scene.bottom());
    const double y = a.y() + 6 * mm;
    painter.drawLine(QPointF(a.x(), a.y() + 1 * mm), QPointF(a.x(), y + 1.5 * mm));
    painter.drawLine(QPointF(b.x(), b.y() + 1 * mm), QPointF(b.x(), y + 1.5 * mm));
    painter.drawLine(QPointF(a.x(), y), QPointF(b.x(), y));
    arrow(QPointF(a.x(), y), QPointF(b.x(), y));
    arrow(QPointF(b.x(), y), QPointF(a.x(), y));
    painter.drawText(QRectF(a.x(), y, std::max(b.x() - a.x(), 20 * mm), 6 * mm), Qt::AlignHCenter | Qt::AlignTop,
                     number(fillBox.width()));
    const QPointF top = toPage(scene.left(), -fillBox.height());
    const QPointF bottom = toPage(scene.left(), fillBox.height());
    const double x = top.x() - 6 * mm;
    painter.drawLine(QPointF(x, top.y()), QPointF(x, bottom.y()));
    arrow(QPointF(x, top.y()), QPointF(x, bottom.y()));
    arrow(QPointF(x, bottom.y()), QPointF(x, top.y()));
    painter.drawLine(QPointF(x - 1.5 * mm, top.y()), QPointF(top.x() - 1 * mm, top.y()));
    painter.drawLine(QPointF(x - 1.5 * mm, bottom.y()), QPointF(bottom.x() - 1 * mm, bottom.y()));
    painter.save();
    painter.translate(x - 1 * mm, (top.y() + bottom.y()) / 2);
    painter.rotate(-90);
    painter.setFont(reportFont(9));
    painter.drawText(QRectF(-30 * mm, -6 * mm, 60 * mm, 6 * mm), Qt::AlignHCenter | Qt::AlignBottom,
                     QStringLiteral("Ø%1").arg(number(2.0 * fillBox.height())));
    painter.restore();
  }
  if (!data.partNote.isEmpty()) {
    painter.setPen(QColor(170, 30, 30));
    drawFitted(painter, QRectF(l.frame.left() + 5 * mm, l.frame.top() + 14 * mm, l.frame.width() - 10 * mm, 7 * mm),
               data.partNote, reportFont(10), Qt::AlignLeft | Qt::AlignVCenter);
  }

  paintFinishes(painter, l, data, lang);

  // Title block.
  const QString fileName = data.fileName.isEmpty() ? t.untitled : data.fileName;
  const std::array<std::pair<QString, QString>, kTitleRows> rows = {{
      {t.project, qs(h.project)},
      {t.part, qs(h.part)},
      {t.programmer, qs(h.programmer)},
      {t.material, qs(h.material)},
      {t.date, reportDate(data.date, lang)},
      {t.fileName, fileName},
      {t.version, kluengVersion()},
      {t.scale, scaleText(l.scale)},
  }};
  painter.setPen(paperPen(device, 0.4));
  painter.setBrush(Qt::white);
  painter.drawRect(l.titleBlock);
  const double rowHeight = l.titleBlock.height() / kTitleRows;
  const double labelWidth = 35 * mm;
  painter.setPen(paperPen(device, 0.2));
  painter.drawLine(QPointF(l.titleBlock.left() + labelWidth, l.titleBlock.top()),
                   QPointF(l.titleBlock.left() + labelWidth, l.titleBlock.bottom()));
  for (int r = 0; r < kTitleRows; ++r) {
    const QRectF cell(l.titleBlock.left(), l.titleBlock.top() + r * rowHeight, l.titleBlock.width(), rowHeight);
    if (r > 0) {
      painter.setPen(paperPen(device, 0.2));
      painter.drawLine(cell.topLeft(), cell.topRight());
    }
    QRectF fieldCell = cell;
    if (r == kTitleRows - 1) {
      // The projection method beside the scale (ISO 7200 title block).
      const QRectF symbolCell(cell.right() - 24 * mm, cell.top(), 24 * mm, cell.height());
      painter.setPen(paperPen(device, 0.2));
      painter.drawLine(symbolCell.topLeft(), symbolCell.bottomLeft());
      paintFirstAngleSymbol(painter, symbolCell, mm);
      fieldCell.setRight(symbolCell.left());
    }
    drawField(painter, fieldCell, rows[static_cast<std::size_t>(r)].first, rows[static_cast<std::size_t>(r)].second,
              labelWidth + 1.5 * mm);
  }
  painter.restore();
}

}  // namespace klueng::render

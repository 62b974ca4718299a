#pragma once
// Printed reports (SPEC 12): the program sheet and the drawing sheet, painted
// onto any QPagedPaintDevice (QPrinter, QPdfWriter) in the language asked for,
// whatever language the UI shows. Qt Gui only (no widgets).
//
// Public API
//   ReportLanguage                 English or Thai (texts are fixed by SPEC 12, not tr()).
//   reportText(code, lang, args)   a sheet's own words from the core's catalog (messages_render.cpp).
//   reportDate(date, lang)         "October 19, 1999" / "19 ตุลาคม พ.ศ. 2542" (Buddhist era).
//   ReportData                     what both sheets print: the program file (header + G-code),
//                                  its file name, the date, the finished part.
//   finishedPart(job, lang, &note)   the job's finished cut (interpreted and cut on first ask)
//                                  end with the core; the uncut bar (and a note) if it cannot run.
//   paintProgramSheet(painter, device, data, lang)   header block on every page, numbered
//                                  listing (file line numbers), "Page n"; returns the page count.
//   paintDrawingSheet(painter, device, data, lang)   the part to scale (1:1, 1:2 ...,
//                                  chosen to fit) about the centre line, and the title block.
//   drawingScale(partMm, areaMm)   the standard scale used (paper mm per part mm).
//   The painter must be active on `device`; sheets after the first start with
//   device.newPage() by the caller.
#include <vector>

#include <QDate>
#include <QFont>
#include <QPagedPaintDevice>
#include <QPainter>
#include <QRectF>
#include <QSizeF>
#include <QString>

#include "klueng/core/cut/cutting_data.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/job/job.h"
#include "klueng/core/units.h"
#include "render/drawing_dimensions.h"
#include "render/lathe_painters.h"
#include "render/report_text.h"

namespace klueng::render {

// Fonts with Thai glyphs (fonts-thai-tlwg), so Thai never prints as boxes.
inline constexpr const char* kReportFontFamily = "Loma";
inline constexpr const char* kReportMonoFamily = "Tlwg Mono";

// Long: "October 19, 1999" / "19 ตุลาคม พ.ศ. 2542"; short: "Oct 19, 1999" / "19 ต.ค. 2542".
enum class DateLength { Long, Short };
QString reportDate(const QDate& date, ReportLanguage lang, DateLength length = DateLength::Long);
QString kluengVersion();

struct ReportData {
  core::io::ProgramFile program;  // header + G-code; gcodeFirstLine numbers the listing
  QString fileName;               // shown on the sheets ("Untitled" when empty)
  QDate date = QDate::currentDate();
  StockShape part;                   // the finished part (see finishedPart)
  QString partNote;                  // printed under the drawing when the part is not the finished one
  core::cut::PartFeatures features;  // the part's features, dimensioned on the drawing (empty: overall size only)
  DesignMarks marks;                 // tolerances and surface finish from a part design (none for a plain program)
  // The roughness each feature's surface got from the cut that left it (issue 39; cut::surfaceFinishOf):
  // listed beside the title block. Filled by addRunResults with the part.
  std::vector<std::pair<core::cut::PartFeature, core::cut::SurfaceFinish>> finishes;
  core::UnitFormat units;  // the unit the drawing's dimensions are written in (issue 28 item 4)
  // Cycle time (issue 11): total and per tool; total < 0 = not known (the program has errors).
  double cycleTime = -1.0;
  bool cycleTimeToAlarm = false;  // the run stops on an alarm: the time is up to it
  std::vector<core::machine::ToolTime> toolTimes;
};

// Fills data.cycleTime and data.toolTimes from the job's run (no cutting).
// These ask the Job for its timeline (and cut): call them on a worker thread.
void addCycleTimes(ReportData& data, const core::job::Job& job);
// The same and, with `withPart`, data.part, data.features and data.partNote as
// finishedPart gives them — from the job's one run — and data.finishes (the run measured).
void addRunResults(ReportData& data, const core::job::Job& job, ReportLanguage lang, bool withPart);
// "3 min 12.4 s" / "3 นาที 12.4 วินาที".
QString durationText(double seconds, ReportLanguage lang);

// Runs the whole program with the core and returns the stock it leaves. If the
// program has errors or stops on an alarm, `note` says so (in `lang`) and the
// shape is the uncut bar or the part up to the alarm.
StockShape finishedPart(const core::job::Job& job, ReportLanguage lang, QString* note);

int paintProgramSheet(QPainter& painter, QPagedPaintDevice& device, const ReportData& data, ReportLanguage lang);
void paintDrawingSheet(QPainter& painter, QPagedPaintDevice& device, const ReportData& data, ReportLanguage lang);

// Largest standard scale (5:1, 2:1, 1:1, 1:2, 1:5, 1:10, ...) at which partMm fits in areaMm.
double drawingScale(const QSizeF& partMm, const QSizeF& areaMm);
QString scaleText(double scale);  // "1:1", "1:2", "2:1"

// Where paintDrawingSheet put things, in device pixels (for tests and previews).
struct DrawingLayout {
  QRectF frame;        // sheet border
  QRectF drawingArea;  // where the part may go
  QRectF titleBlock;
  QRectF partRect;     // the part's both-halves bounding box on the page (room left around it for dimensions)
  double scale = 1.0;  // paper mm per part mm
  double pixelsPerMm = 1.0;
};
DrawingLayout drawingLayout(const QPagedPaintDevice& device, const StockShape& part);
// The dimensions paintDrawingSheet draws, where it draws them (tests check they stay in the frame).
// Where the part is on the page, the frame the labels stay in and the part's lines they keep off.
DimensionFrame drawingDimensionFrame(const QPagedPaintDevice& device, const ReportData& data, ReportLanguage lang);
std::vector<DimensionItem> drawingDimensions(const QPagedPaintDevice& device, const ReportData& data,
                                             ReportLanguage lang);

}  // namespace klueng::render

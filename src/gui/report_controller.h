#pragma once
// The window's reports (SPEC 12, issue 12): Print Code, Print (default
// printer), Print Drawing, Print Preview and Export PDF, in the UI's language.
// It asks the window for what to print (Source) and paints with render/.
#include <QObject>
#include <QString>
#include <functional>
#include <optional>

#include "klueng/core/design/part_design.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/units.h"
#include "render/report_sheets.h"

class QPagedPaintDevice;
class QPainter;
class QWidget;

namespace klueng::gui {

class ReportController : public QObject {
  Q_OBJECT
 public:
  // The open program as it is now (the editor's text, not the file on disk).
  struct Source {
    core::io::ProgramFile program;
    QString displayName;                // "untitled.txt" or the file's name
    QString filePath;                   // empty when untitled
    core::machine::MachineSetup setup;  // the job's tools, as a run uses them
    core::gcode::Dialect dialect = core::gcode::Dialect::Fanuc;
    core::UnitFormat units;                          // the drawing's dimensions (View ▸ Units shown)
    std::optional<core::design::PartDesign> design;  // the Part Designer's, when the program came from it
  };

  ReportController(QWidget* window, std::function<Source()> source);

  void printCode();                          // printer dialog, the program sheet
  void printCodeNow();                       // the default printer, no dialog
  void printDrawing();                       // printer dialog, the drawing sheet (landscape)
  void printPreview();                       // both sheets
  bool exportPdf(const QString& path = {});  // both sheets; asks for a path when empty

 signals:
  // A short note for the status bar.
  void message(const QString& text, int timeoutMs);

 private:
  render::ReportData reportData(const Source& source, bool withPart) const;
  // Paints the chosen sheets on `device` (painter active); a new page between them.
  static void paint(QPainter& painter, QPagedPaintDevice& device, const render::ReportData& data, bool code,
                    bool drawing);

  QWidget* window_;
  std::function<Source()> source_;
};

}  // namespace klueng::gui

#pragma once
// The class grades as the plain cells klueng_class_pdf draws (class_pdf_input.h),
// built once for the CLI's --pdf and the GUI's PDF button. No Qt.
#include <string>
#include <vector>

#include "klueng/core/job/class_grading.h"
#include "klueng/core/gcode/word_format.h"
#include "render/class_pdf_input.h"

namespace klueng::render {

class ClassPdfCells {
 public:
  // `lang`: the features' and verdicts' words; `reference`: graded against a reference program.
  ClassPdfCells(const std::vector<core::job::ClassRow>& rows, core::Lang lang, bool reference) {
    for (const core::job::ClassRow& r : rows) {
      cells_.push_back(r.file);
      cells_.push_back(r.pass ? "pass" : "fail");
      cells_.push_back(r.graded.errors > 0 ? std::to_string(r.graded.errors) + " (" + r.graded.firstError + ")" : "0");
      cells_.push_back(r.graded.alarm);
      cells_.push_back(r.graded.errors == 0 ? core::gcode::formatFixed(r.graded.cycleTime, 1) : "");
      std::size_t in = 0;
      for (const core::cut::InspectedDimension& d : r.inspection) in += d.in() ? 1 : 0;
      // Against a drawing only: the dimensions in tolerance where the reference's leftover would be.
      cells_.push_back(r.compared ? core::gcode::formatFixed(r.deviation.leftover, 3)
                       : reference || r.inspection.empty()
                           ? std::string()
                           : std::to_string(in) + "/" + std::to_string(r.inspection.size()));
      cells_.push_back(r.compared ? core::gcode::formatFixed(r.deviation.gouge, 3) : "");
      // The cutting-data warnings (issue 39), code and line; "–" for a program that ran without any.
      const std::string cutting = core::job::cuttingWarningsText(r.graded, lang);
      cells_.push_back(!cutting.empty() || r.graded.errors > 0 || !r.graded.alarm.empty() ? cutting : "–");
      // A refused entry (a link out of the folder, a pipe) gets no sheet: it is never read.
      paths_.push_back(r.graded.refusal ? std::string() : r.path);
      dimensions_ = static_cast<int>(r.inspection.size());
      for (const core::cut::InspectedDimension& d : r.inspection) {
        dimensionCells_.push_back(core::cut::dimensionLabel(d.drawn, lang));
        dimensionCells_.push_back(core::cut::toleranceLabel(d.drawn.tolerance));
        dimensionCells_.push_back(core::gcode::formatFixed(d.lowerLimit(), 3) + " – " +
                                  core::gcode::formatFixed(d.upperLimit(), 3));
        dimensionCells_.push_back(d.measured ? core::gcode::formatFixed(*d.measured, 3) : "–");
        dimensionCells_.push_back(core::cut::verdictName(d.verdict, lang));
        verdicts_.push_back(static_cast<int>(d.verdict));
      }
    }
    for (const std::string& c : cells_) cellPtrs_.push_back(c.c_str());
    for (const std::string& p : paths_) pathPtrs_.push_back(p.c_str());
    for (const std::string& c : dimensionCells_) dimensionPtrs_.push_back(c.c_str());
    rows_ = static_cast<int>(rows.size());
  }
  // Fills the table's fields of `in`; the cells stay owned by this object.
  void into(KluengClassPdf& in) const {
    in.rows = rows_;
    in.cells = cellPtrs_.data();
    in.sheetPaths = pathPtrs_.data();
    in.dimensions = dimensions_;
    in.dimensionCells = dimensionPtrs_.data();
    in.verdicts = verdicts_.data();
  }

 private:
  std::vector<std::string> cells_, paths_, dimensionCells_;
  std::vector<int> verdicts_;
  std::vector<const char*> cellPtrs_, pathPtrs_, dimensionPtrs_;
  int rows_ = 0;
  int dimensions_ = 0;
};

}  // namespace klueng::render

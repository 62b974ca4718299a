#pragma once
// Grading a class against a reference part (issue 11) and/or the teacher's
// drawing with tolerances (issue 28): each student's program is loaded,
// checked, run and cut as `simulate` does it, and its finished part compared
// with the reference's (part_compare.h) and measured against each toleranced
// dimension of the drawing (inspection.h). The CLI's `class` command and the
// GUI's File > Grade a class both use it.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/cut/inspection.h"
#include "klueng/core/cut/part_compare.h"
#include "klueng/core/cut/stock.h"
#include "klueng/core/job/job.h"

namespace klueng::core::job {

using cut::DrawnDimension;
using cut::InspectedDimension;
using cut::PartDeviation;
using cut::Stock;

// The setup exercise (issue 31 item 5, docs/program-file.md §9): a program (or
// the reference) whose head says `(OFFSETS: UNKNOWN)` is graded on the offsets
// its student touched off at the Operator panel, saved beside the program as
// `<name>.offset.cfg` (touchOffFilePath; offset.cfg's format: the rows the run
// used). Each tool the program uses: its row's X (diameter) and Z against the
// true ones (the class's offset.cfg), within the class tolerance or not; the
// program is also run on the student's offsets, so a wrong touch-off shows in its part.
struct ToolTouchOff {
  int station = 0;
  double enteredX = 0.0, enteredZ = 0.0;  // the student's row (X diameter), mm
  double trueX = 0.0, trueZ = 0.0;        // offset.cfg's row
  bool within = false;                    // both within the tolerance
};
struct TouchOffGrade {
  bool asked = false;     // the program or the reference says the offsets are unknown
  bool saved = false;     // the student's offsets file was found and read
  std::string file;       // its name in the folder
  std::string readError;  // why it could not be read (the file's first problem, English)
  std::vector<ToolTouchOff> tools;
  bool pass() const;
};
// "somchai.nc" -> "somchai.offset.cfg" in the same folder.
std::string touchOffFilePath(const std::string& programPath);
// "T01 X0.000/0.000 Z-0.012/0.000 in; T02 ... out", "not saved (somchai.offset.cfg)"; empty when not asked.
std::string touchOffSummary(const TouchOffGrade& grade);
// The graded line in words (I612 / W613 per tool, W614 when not saved), joined by "; "; empty when not asked.
std::string touchOffText(const TouchOffGrade& grade, double tolerance, Lang lang);

struct GradedProgram {
  std::optional<Stock> part;  // the finished part; none when it did not run to its end
  int errors = 0;
  std::string firstError;                    // "E201 line 18", "unreadable"
  std::string alarm;                         // "A104 line 15"
  double cycleTime = 0.0;                    // seconds (up to the alarm)
  std::vector<std::string> subprogramFiles;  // files of the folder its calls read (the program's own)
  std::vector<int> stations;                 // the turret stations its run used, in order
  // The cutting-data warnings of its run (W330-W336, cut/cutting_data.h; issue 39): what a teacher
  // would say about its speeds, feeds and depths. Not part of pass/fail.
  std::vector<Diagnostic> cuttingWarnings;
  // A folder entry that was not read (io::folderEntryRefusal: F158 a link out of the folder,
  // F157 a pipe, F102 a folder, F101 a dangling link); firstError says the same in words.
  std::optional<Diagnostic> refusal;
};

// Loads, checks, runs and cuts one program (makeJob with `base`, its path set
// to `path`). Never throws for a bad file.
GradedProgram gradeProgram(const std::string& path, const JobInput& base);

struct ClassRow {
  std::string file;  // the name in the folder
  std::string path;
  GradedProgram graded;  // (its part is dropped once compared)
  PartDeviation deviation;
  bool compared = false;  // it ran to its end and was compared with the reference
  // Against a drawing: every drawn dimension, measured (all missing when it did not run to its end).
  std::vector<InspectedDimension> inspection;
  TouchOffGrade touchOff;  // the setup exercise, when asked
  bool pass = false;       // ran to its end, within the reference's tolerance and every drawn dimension in (and every
                           // tool touched off within it, when asked)
};

// What a class is graded against: a reference program's part, a drawing's
// toleranced dimensions, or both.
struct GradeAgainst {
  std::string referencePath;         // left out of the folder's programs
  const Stock* reference = nullptr;  // none: no reference
  double tolerance = 0.05;           // mm on the diameter, against the reference
  std::string drawingPath;           // (a part file is not a program; named for the record)
  std::vector<DrawnDimension> drawing;
  bool hasDrawing = false;  // graded against the drawing
};

// Every program file of `folder` (io::isProgramFileName, as `check DIR` takes
// them; sorted by name; the reference itself left out) against `reference`'s
// part; `progress(i, n, name)` before each. A file the others call as a
// subprogram belongs to them and gets no row of its own.
std::vector<ClassRow> gradeClass(const std::string& folder, const std::string& referencePath, const Stock& reference,
                                 const JobInput& base, double tolerance,
                                 const std::function<void(int, int, const std::string&)>& progress = {});
std::vector<ClassRow> gradeClass(const std::string& folder, const GradeAgainst& against, const JobInput& base,
                                 const std::function<void(int, int, const std::string&)>& progress = {});

// The cutting-data warnings of a graded program, code and line: "W332 line 12, W330 line 15"
// (Thai "W332 บรรทัด 12"); empty when none. The CSV, the PDF and the dialog's column.
std::string cuttingWarningsText(const GradedProgram& g, Lang lang);

// file,result,errors,first_error,alarm,cycle_time_s,leftover_mm,leftover_z,gouge_mm,gouge_z,cutting_data (then
// touch_off, touchOffSummary, when a row was asked for the setup exercise); with a drawing (`drawing`), one line per
// student and drawn dimension, followed by feature,nominal_mm,tolerance,lower_mm,upper_mm,measured_mm,verdict (in, out
// or missing).
std::string classCsv(const std::vector<ClassRow>& rows, bool drawing = false);

}  // namespace klueng::core::job

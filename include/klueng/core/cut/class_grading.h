#pragma once
// Grading a class against a reference part (issue 11): each student's program
// is loaded, checked, run and cut as `simulate` does it, and its finished part
// compared with the reference's (part_compare.h). The CLI's `class` command and
// the GUI's File > Grade a class both use it.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/cut/part_compare.h"
#include "klueng/core/cut/stock.h"
#include "klueng/core/machine/job_file.h"
#include "klueng/core/machine/setup_files.h"

namespace klueng::core::cut {

struct GradedProgram {
  std::optional<Stock> part;  // the finished part; none when it did not run to its end
  int errors = 0;
  std::string firstError;     // "E201 line 18", "unreadable"
  std::string alarm;          // "A104 line 15"
  double cycleTime = 0.0;     // seconds (up to the alarm)
  std::vector<std::string> subprogramFiles;  // files of the folder its calls read (the program's own)
};

// Loads, checks, runs and cuts one program. Never throws for a bad file.
GradedProgram gradeProgram(const std::string& path, const machine::MachineSetup& setup,
                           const machine::JobFileRequest& request);

struct ClassRow {
  std::string file;           // the name in the folder
  std::string path;
  GradedProgram graded;       // (its part is dropped once compared)
  PartDeviation deviation;
  bool compared = false;      // it ran to its end and was compared
  bool pass = false;
};

// Every program file of `folder` (io::isProgramFileName, as `check DIR` takes
// them; sorted by name; the reference itself left out) against `reference`'s
// part; `progress(i, n, name)` before each. A file the others call as a
// subprogram belongs to them and gets no row of its own.
std::vector<ClassRow> gradeClass(const std::string& folder, const std::string& referencePath, const Stock& reference,
                                 const machine::MachineSetup& setup, const machine::JobFileRequest& request,
                                 double tolerance, const std::function<void(int, int, const std::string&)>& progress = {});

// file,result,errors,first_error,alarm,cycle_time_s,leftover_mm,leftover_z,gouge_mm,gouge_z
std::string classCsv(const std::vector<ClassRow>& rows);

}  // namespace klueng::core::cut

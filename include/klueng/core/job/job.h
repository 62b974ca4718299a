#pragma once
// One job (issue 30 item 1): a program (a file, or the editor's text with its
// header), a machine setup and options -> one immutable Job holding the parsed
// program with its subprogram files, every diagnostic, the tools, the stock and
// the timeline; the finished cut is computed on demand. makeJob is the only way
// to make one: the CLI, the editor's check, a run, the Part panel, the reports,
// the design loop and class grading all read the same Job.
//
// The timeline and the cut are computed on first ask, once, whichever thread
// asks first (std::call_once); the GUI asks on a worker thread.
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/cutting_data.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/machine/timeline.h"
#include "klueng/core/infer/point_reading.h"
#include "klueng/core/infer/tool_inference.h"
#include "klueng/core/units.h"

namespace klueng::core::job {

class Job;

struct JobInput {
  // The program: `file` when set (the editor's text and header, already in
  // memory), else the file at `path`, read here.
  std::string path;
  std::optional<io::ProgramFile> file;
  // What reading the program said when the caller read it already (a pipe or
  // standard input can be read only once, issue 42 item 4): with `file`, its
  // warnings; without, why it could not be read (then `path` is not read again).
  std::optional<std::vector<Diagnostic>> readDiagnostics;
  // Where subprogram files come from; nullopt = the folder of `path` (empty = none).
  std::optional<std::string> folder;
  machine::MachineSetup setup;  // tools.cfg / offset.cfg / machine.cfg as loaded
  // The run: dialect, power-on units, switches, #500-#999. The check and the
  // tool and stock inference use only its dialect and units.
  machine::RunOptions run;
  io::JobHeader defaultsForPlain;                   // text fields of a read file without a header
  std::optional<io::JobHeader> stock;               // a stock given for this run (--stock): wins over the file's
  std::vector<machine::StationOverride> overrides;  // stations set by the user (--tool, Tool Select)
  // Lengths without a decimal point (--decimal-point): wins over the file's own
  // choice, its numbers and the machine (machine/point_reading.h).
  std::optional<bool> calculatorInput;
  int stations = 0;  // highest T station (the dialect's limit, else the turret); 0 = the turret
  // False when no tool table was read: no library choices, and T words are not checked.
  bool toolTable = true;
  // False: the setup already holds the program's tools (a generated program, a
  // setup chosen by hand); T words are checked against it as it is.
  bool inferTools = true;
  // The editor's check while typing also follows the modal state (W104-W106).
  bool modalRules = false;
  // The machine the program names at its head, `(MACHINE: id)`, wins over run.dialect
  // (its keys join the setup's machine.cfg); a name not loaded is F205 and changes nothing.
  // Set where no machine was chosen for this very program (class grading a folder).
  bool programMachine = false;
  // The caller asks for timeline() next (simulate, a sheet with its run): the tool
  // inference's recorded run is kept, and when it is the very run (machine::recordIsTheRun)
  // it becomes the timeline, so the program is interpreted once (issue 29 item 14).
  // False (the editor's check): the record is freed when the tools and stock are known.
  bool timelineNext = false;
  // A file of a folder run (check DIR, class DIR): one that is not a G-code program
  // (binary data, no G-code in its first lines) is refused with F159, never parsed,
  // so no message quotes its text (issue 42 item 1).
  bool folderRun = false;
  // The cutting-data warnings (W330-W336, issue 39 item 1) join the diagnostics, measured on the
  // run the tool inference records (cut::checkCuttingData): no run of their own.
  bool cuttingData = true;
  // The drawing's roughness marks for W332 (design::finishMarks of the part the program is for);
  // where none lies under a finishing cut, Ra 3.2 um.
  std::vector<cut::FinishMark> finishMarks;
  // A job made before of the same text (the editor's last check, for the GUI's run): when it
  // read the text alike (first line, folder, dialect, units, decimal points), its parsed program
  // is shared, with its subprogram files as that job read them, not parsed a second time
  // (issue 42 item 3: the window's memory). Otherwise the text is parsed as usual.
  std::shared_ptr<const Job> sameText;
};

// The program as a run reads it: parsed once, its subprogram files attached, its power-on
// units and its lengths without a decimal point read (makeJob); and what it was read with.
struct ProgramReading {
  std::shared_ptr<const gcode::Program> program;
  std::vector<Diagnostic> notes;               // I107, the subprogram files' own diagnostics, F158
  std::optional<gcode::InputUnits> unitsRead;  // the power-on units its numbers decided (I107)
  machine::PointReading points;
  // What decided the reading: the same again reads the same blocks.
  std::string folder;
  gcode::Dialect dialect = gcode::Dialect::Fanuc;
  std::optional<gcode::InputUnits> givenUnits;
  std::optional<bool> givenPoint;
  bool machinePoint = false;
};

class Job {
 public:
  const JobInput& input() const { return input_; }
  const std::string& path() const { return input_.path; }
  // The program file with the resolved stock in its header; nullopt when unreadable.
  const std::optional<io::ProgramFile>& file() const { return file_; }
  // Subprogram files appended (Program::files); nullptr when unreadable.
  const gcode::Program* program() const { return reading_.program.get(); }
  // The program and what it was read with (shared by a later job of the same text, JobInput::sameText).
  const ProgramReading& reading() const { return reading_; }
  // The setup with the program's tools and its reading of lengths without a point.
  const machine::MachineSetup& setup() const { return tools_.setup; }
  const machine::ToolInference& tools() const { return tools_; }
  // File, subprogram files, checker, stock size, dialect fit (I102); sorted by file, line, column.
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  // The program file's own diagnostics as the editor shows one file: an error
  // inside a subprogram file is reported once, as E412 on the call that reaches it.
  std::vector<Diagnostic> programFileDiagnostics() const;
  std::vector<Diagnostic> toolNotes() const { return tools_.notes(); }       // I401-I410
  const std::vector<Diagnostic>& stockNotes() const { return stockNotes_; }  // I150-I157
  std::optional<gcode::Dialect> fit() const { return fit_; }                 // another dialect that accepts the program
  int fitBlocks() const { return fitBlocks_; }
  DisplayUnits units() const { return units_; }  // its last G20/G21, else the power-on units
  bool unreadable() const { return unreadable_; }
  bool hasErrors() const { return core::hasErrors(diagnostics_); }
  // The file a diagnostic belongs to: the program or one of its subprogram files.
  std::string fileOf(const Diagnostic& d) const;

  // The run, interpreted on first ask; nullptr when there is no program or an error.
  const machine::Timeline* timeline() const;
  // The same timeline, shared on its own: a holder keeps the run, not the job's program and
  // diagnostics (the GUI's run keeps a long program's timeline, issue 42 item 3).
  std::shared_ptr<const machine::Timeline> sharedTimeline() const {
    timeline();
    return timeline_;
  }
  // The bar the timeline cuts, run to its end (or its alarm) on first ask; nullptr without a timeline.
  const cut::CutSimulator* cut() const;

 private:
  friend std::shared_ptr<const Job> makeJob(JobInput input);
  Job() = default;

  JobInput input_;
  std::optional<io::ProgramFile> file_;
  ProgramReading reading_;
  machine::ToolInference tools_;
  std::vector<Diagnostic> diagnostics_;
  std::vector<Diagnostic> stockNotes_;
  std::optional<gcode::Dialect> fit_;
  int fitBlocks_ = 0;
  DisplayUnits units_ = DisplayUnits::Mm;
  bool unreadable_ = false;

  // The recorded run while it may still become the timeline (JobInput::timelineNext).
  mutable std::shared_ptr<const machine::Timeline> record_;
  bool programUsesVariables_ = false;  // some block has an expression or a macro statement
  mutable std::once_flag timelineOnce_;
  mutable std::shared_ptr<const machine::Timeline> timeline_;
  mutable std::once_flag cutOnce_;
  mutable std::unique_ptr<cut::CutSimulator> cut_;
};

// The one function that makes a Job: read (when `input.file` is unset), parse
// once, attach the subprogram files, read lengths without a point, infer the
// tools while checking, offer the dialect that fits, resolve the stock.
std::shared_ptr<const Job> makeJob(JobInput input);

// How many Jobs were made and how many timelines and cuts they computed in
// this process, and how many of those ran on the watched thread: the GUI's
// tests watch the GUI thread and prove nothing compiles or cuts there.
struct ComputeLog {
  long long jobs = 0;
  long long timelines = 0;
  long long cuts = 0;
  long long onWatchedThread = 0;  // jobs made, timelines and cuts computed on it
  long long reusedRecords = 0;    // timelines that are the tool inference's recorded run
};
ComputeLog computeLog();
void watchThread(std::thread::id id);

// The stations whose bitmap (tools.cfg line or library tool) names an existing
// file: the T words the check accepts (E305). The one meaning for the editor,
// a run, the CLI and the reports.
using machine::toolsWithBitmap;

}  // namespace klueng::core::job

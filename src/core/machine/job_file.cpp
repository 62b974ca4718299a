// One program file made ready to run (job_file.h).
#include "klueng/core/machine/job_file.h"

#include "check_with_tools.h"

#include <algorithm>
#include <filesystem>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/dialect_fit.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/machine/job.h"
#include "klueng/core/machine/point_reading.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/machine/stock_inference.h"
#include "klueng/core/machine/subprogram_files.h"

namespace klueng::core::machine {

namespace {

// SPEC 2 (ext): the stock given for the run, else the header, else inferred
// from the program, else the defaults. Returns the notes that say which.
std::vector<Diagnostic> resolveStock(io::ProgramFile& file, const gcode::Program& program,
                                     const std::optional<io::JobHeader>& stock, const MachineSetup& setup,
                                     const RunOptions& run, const Timeline* recorded) {
  io::JobHeader& h = file.header;
  if (stock) h.takeStockFrom(*stock);
  if (h.stockSource == io::StockSource::Header) return {};
  if (file.gcode.find_first_not_of(" \t\r\n") == std::string::npos) return {};  // nothing to cut
  if (h.stockSource == io::StockSource::CommandLine || h.stockSource == io::StockSource::JobDetails)
    return stockNotes(h, nullptr, file.gcode, file.gcodeFirstLine);
  // The run the tools were read from, when there was one: one recording for both.
  const StockInference inferred = recorded ? inferStock(program, *recorded, setup) : inferStock(program, setup, run);
  if (inferred.found) inferred.applyTo(h);
  else h.takeStockFrom(io::JobHeader{});
  return stockNotes(h, &inferred, file.gcode, file.gcodeFirstLine);
}

}  // namespace

std::string JobFile::fileOf(const Diagnostic& d) const {
  return program ? diagnosticFile(*program, d, path) : path;
}

JobFile loadJobFile(const std::string& path, const MachineSetup& setup, const JobFileRequest& request,
                    const io::ToolLibrary& library) {
  JobFile job;
  job.path = path;
  job.setup = setup;
  auto read = io::readProgramFile(path, request.defaultsForPlain);
  job.diagnostics = std::move(read.diagnostics);
  job.unreadable = std::any_of(job.diagnostics.begin(), job.diagnostics.end(), isUnreadable);
  if (!read.value) return job;
  io::ProgramFile& file = *read.value;
  gcode::Program program = gcode::parse(file.gcode, file.gcodeFirstLine);
  // The program's folder is the control's memory: subprograms it calls come from there.
  for (Diagnostic& d : attachSubprogramFiles(program, std::filesystem::path(path).parent_path().string(),
                                             request.run.dialect))
    job.diagnostics.push_back(std::move(d));
  job.unreadable = std::any_of(job.diagnostics.begin(), job.diagnostics.end(),
                               [](const Diagnostic& d) { return d.range.file == 0 && isUnreadable(d); });

  // Lengths without a decimal point, read as the user, the program or the machine says.
  MachineSetup readSetup = setup;
  PointReading reading = readDecimalPoints(
      program, file.plainGcode, request.calculatorInput ? request.calculatorInput : file.header.calculatorInput,
      setup.machine.calculatorInput,
      gcode::powerOnUnitsOf(request.run.dialect, request.run.powerOnUnits), request.run.dialect);
  readSetup.machine.calculatorInput = reading.calculatorInput;
  job.setup = readSetup;

  std::shared_ptr<const Timeline> recorded;
  gcode::CheckOptions check;
  check.dialect = request.run.dialect;
  check.powerOnUnits = request.run.powerOnUnits;
  check.turretStations = setup.tools.stations;  // the turret the tool table was read for
  std::vector<Diagnostic> found;
  if (request.toolTable) {
    // Tools from the program: library choices for stations without a fitting tool,
    // worked out while the rest of the check runs.
    check.toolsWithBitmap = std::vector<int>{};
    InferenceContext context;
    context.fromProgram = file.plainGcode;
    context.run = request.run;
    context.toolsBeyondCentre = file.header.toolsBeyondCentre;
    detail::CheckedWithTools checked = detail::checkWhileInferring(program, check, [&] {
      return inferTools(program, file.gcode, file.gcodeFirstLine, readSetup, library, request.overrides,
                        request.stations, context);
    });
    job.setup = std::move(checked.inference.setup);
    job.toolNotes = checked.inference.notes();
    recorded = checked.inference.record;
    check.toolsWithBitmap = toolsWithBitmap(job.setup);
    found = std::move(checked.diagnostics);
  } else {
    found = gcode::check(program, check);
  }
  found.insert(found.end(), reading.diagnostics.begin(), reading.diagnostics.end());
  // Say once which dialect accepts a program this one refuses (I102).
  if (auto fit = gcode::suggestDialect(program, check, found)) found.push_back(fit->note);
  job.diagnostics.insert(job.diagnostics.end(), std::make_move_iterator(found.begin()),
                         std::make_move_iterator(found.end()));
  std::stable_sort(job.diagnostics.begin(), job.diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
    if (a.range.file != b.range.file) return a.range.file < b.range.file;
    return a.range.line != b.range.line ? a.range.line < b.range.line : a.range.column < b.range.column;
  });
  job.stockNotes = resolveStock(file, program, request.stock, job.setup, request.run, recorded.get());
  job.file = std::move(read.value);
  job.program = std::move(program);
  return job;
}

}  // namespace klueng::core::machine

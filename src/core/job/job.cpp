// One job (job.h): the one chain from a program to its check, tools, stock and run.
#include "klueng/core/job/job.h"

#include "stick_out.h"
#include "klueng/core/machine/machine_files.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>
#include <thread>

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/gcode/dialect_fit.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/gcode/program_index.h"
#include "klueng/core/io/folder_files.h"
#include "klueng/core/io/image.h"
#include "klueng/core/messages.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/infer/point_reading.h"
#include "klueng/core/gcode/decimal_point.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/infer/stock_inference.h"
#include "klueng/core/infer/units_reading.h"
#include "klueng/core/machine/subprogram_files.h"
#include "infer/check_with_tools.h"  // the check and the tool inference side by side (infer's own)

namespace klueng::core::job {

namespace {

// The check measures the cutting data (issue 39) on the run it records for the tools, which
// then keeps each move's feeds and speeds beside its marks (RunOptions::recordSpeeds). A program
// longer than this (a CAM job of millions of blocks) keeps the marks alone (issue 42 item 3): its
// cutting data comes from simulate.
constexpr std::size_t kCuttingDataCheckBlocks = 200'000;
bool measuresCuttingData(const JobInput& input, const gcode::Program& program) {
  return input.cuttingData && program.blocks.size() <= kCuttingDataCheckBlocks;
}

std::atomic<long long> jobsMade{0};
std::atomic<long long> jobTimelines{0};
std::atomic<long long> jobCuts{0};
std::atomic<long long> jobOnWatched{0};
std::atomic<long long> jobReusedRecords{0};
std::mutex watchedMutex;
std::thread::id watched;

void logCompute(std::atomic<long long>& counter) {
  ++counter;
  const std::lock_guard lock(watchedMutex);
  if (watched != std::thread::id() && std::this_thread::get_id() == watched) ++jobOnWatched;
}

// SPEC 2 (ext): the stock given for the run, else the header, else inferred
// from the program, else the defaults. Returns the notes that say which.
std::vector<Diagnostic> resolveJobStock(io::ProgramFile& file, const gcode::Program& program,
                                        const std::optional<io::JobHeader>& stock, const machine::MachineSetup& setup,
                                        const machine::RunOptions& run, const machine::Timeline* recorded) {
  io::JobHeader& h = file.header;
  if (stock) h.takeStockFrom(*stock);
  if (h.stockSource == io::StockSource::Header) return {};
  if (file.gcode.find_first_not_of(" \t\r\n") == std::string::npos) return {};  // nothing to cut
  if (h.stockSource == io::StockSource::CommandLine || h.stockSource == io::StockSource::JobDetails)
    return machine::stockNotes(h, nullptr, file.gcode, file.gcodeFirstLine);
  // The run the tools were read from, when there was one: one recording for both.
  machine::StockInference inferred =
      recorded ? machine::inferStock(program, *recorded, setup) : machine::inferStock(program, setup, run);
  // The bar the program's own comment names wins over the approach (issue 38 item 8).
  machine::readStockComment(inferred, file.gcode, file.gcodeFirstLine);
  if (!inferred.found) {
    h.takeStockFrom(io::JobHeader{});
    return machine::stockNotes(h, &inferred, file.gcode, file.gcodeFirstLine);
  }
  inferred.applyTo(h);
  std::vector<Diagnostic> notes = machine::stockNotes(h, &inferred, file.gcode, file.gcodeFirstLine);
  // A bar the program's comment names keeps its length; one guessed from the cuts makes room for the tools.
  if (recorded && inferred.commentLine == 0)
    if (std::optional<Diagnostic> longer = lengthenForTools(h, *recorded, setup)) notes.push_back(std::move(*longer));
  return notes;
}

// The call in the program itself (file 0) that reaches subprogram file `file`.
SourceRange callInto(const gcode::Program& program, int file) {
  const gcode::ProgramIndex index(program);
  for (const gcode::Block& b : program.blocks) {
    if (b.file != 0) break;
    const gcode::Word* p = b.find('P');
    if (!p || p->expr >= 0) continue;
    for (const gcode::Word& w : b.words)
      if ((w.letter == 'M' && w.code() == 98) || (w.letter == 'G' && (w.code() == 65 || w.code() == 66))) {
        const gcode::CallTarget t = gcode::callTarget(p->value, std::nullopt, w.letter == 'M');
        const gcode::ProgramSection* s = index.program(t.number);
        if (!s) s = index.program(static_cast<int>(p->value));
        if (s && s->file == file) return p->range;
      }
  }
  return SourceRange{program.blocks.empty() ? program.firstLine : program.blocks.front().line, 1, 0, 0};
}

// Whether a run may read or write a macro variable: an expression or a macro statement.
bool usesVariables(const gcode::Program& program) {
  return std::any_of(program.blocks.begin(), program.blocks.end(), [](const gcode::Block& b) {
    return b.hasExpressions || b.statement().kind != gcode::StatementKind::None;
  });
}

// #500-#999 the run starts from and leaves: a record starts them vacant and keeps them
// nowhere, so it is the run only when the stored ones cannot matter.
bool persistentAlike(const machine::Timeline& record, const std::map<int, double>* stored, bool usesVariables) {
  if (!stored || !usesVariables) return true;  // none kept, or none read or written
  const auto persistent = [](int n) { return n >= 500 && n <= 999; };
  return std::none_of(stored->begin(), stored->end(), [&](const auto& v) { return persistent(v.first); }) &&
         std::none_of(record.flow.writes.begin(), record.flow.writes.end(),
                      [&](const machine::VariableWrite& w) { return persistent(w.number); });
}

// A subprogram file that is a link leaving the program's folder (O1000.nc -> /etc/shadow) is
// not the control's memory: its blocks and messages go, F158 stays, and the call is E404 as
// for a missing file, so nothing of its text reaches a message, a sheet or a PDF (issue 42).
void dropFilesOutside(gcode::Program& program, const std::string& folder, std::vector<Diagnostic>& diagnostics) {
  for (int k = 1; k < static_cast<int>(program.files.size()); ++k) {
    const std::string& path = program.files[static_cast<std::size_t>(k)];
    if (io::insideFolder(path, folder)) continue;
    const auto fromIt = [k](const Diagnostic& d) { return d.range.file == k; };
    std::erase_if(program.blocks, [k](const gcode::Block& b) { return b.file == k; });
    std::erase_if(program.lexicalDiagnostics, fromIt);
    std::erase_if(diagnostics, fromIt);
    Diagnostic refused{Severity::Error, codes::kOutsideFolder, {}, {path}};
    refused.range.file = k;
    diagnostics.push_back(std::move(refused));
  }
}

// E305 "tool 01 has no bitmap" for a station whose tools.cfg names a picture that cannot be
// used says why instead (E311: too large, a pipe, damaged; issue 42 item 6).
void explainUnusableBitmaps(std::vector<Diagnostic>& found, const io::ToolTable& tools) {
  for (Diagnostic& d : found) {
    if (d.code != "E305" || d.args.size() < 2) continue;  // the checker's kToolWithoutBitmap
    const int tool = std::atoi(d.args[1].c_str());
    if (tool < 1 || tool > static_cast<int>(tools.bitmap.size())) continue;
    const std::string& name = tools.bitmap[static_cast<std::size_t>(tool - 1)];
    const std::string path = tools.bitmapPath(tool);
    if (name.empty() || path.empty()) continue;
    const io::ReadResult<io::RgbImage> image = io::readImage(path);
    if (image.value || image.diagnostics.empty()) continue;
    Diagnostic why = image.diagnostics.front();
    if (!why.args.empty()) why.args.front() = name;
    d.code = codes::kToolBitmapUnusable;
    d.args = {d.args[0], d.args[1], formatMessage(why, Lang::En), formatMessage(why, Lang::Th)};
  }
}

bool byPlace(const Diagnostic& a, const Diagnostic& b) {
  if (a.range.file != b.range.file) return a.range.file < b.range.file;
  return a.range.line != b.range.line ? a.range.line < b.range.line : a.range.column < b.range.column;
}

}  // namespace

namespace {

bool isNoseInterference(const std::optional<Diagnostic>& alarm) {
  return alarm && (alarm->code == std::string_view(codes::kNoseDoesNotFit) ||
                   alarm->code == std::string_view(codes::kConcaveArcTooSmall));
}

std::string radiusText(double mm) {
  std::ostringstream s;
  s << mm;  // 0.8, 0.4: as an insert's radius is written
  return s.str();
}

// A guessed nose radius must not stop a run the shop's real insert would not (issue 38 item 7):
// when the compensated path does not fit a guessed tool's radius, the run is made again with the
// largest common insert radius below it that fits, and W205 says which guess and what radius.
machine::Timeline fitGuessedNose(machine::Timeline run, const gcode::Program& program,
                                 const machine::MachineSetup& setup, const machine::RunOptions& options) {
  if (!isNoseInterference(run.alarm) || run.snapshots.empty()) return run;
  const int tool = run.snapshots.back().machine.tool;
  const int offset = run.snapshots.back().machine.offset;
  if (!setup.tools.isGuess(tool) || offset < 1 || offset > io::kOffsetCount) return run;
  const double guess = setup.offsets.at(offset).r;
  for (const double radius : {1.2, 0.8, 0.4, 0.2, 0.1}) {
    if (radius >= guess - 1e-9) continue;
    machine::MachineSetup smaller = setup;
    smaller.offsets.at(offset).r = radius;
    machine::Timeline again = machine::interpret(program, smaller, options);
    if (isNoseInterference(again.alarm)) continue;
    Diagnostic w;
    w.severity = Severity::Warning;
    w.code = codes::kGuessedNoseTooBig;
    w.range = run.alarm->range;
    w.args = {(tool < 10 ? "0" : "") + std::to_string(tool), radiusText(guess), std::to_string(run.alarm->range.line),
              radiusText(radius), run.alarm->code};
    again.flow.notices.insert(again.flow.notices.begin(), std::move(w));
    return again;
  }
  return run;
}

// Parse once, attach the subprogram files from `folder`, read the power-on units from the
// numbers (issue 38 item 8), the angles and the lengths without a decimal point.
ProgramReading readProgram(const io::ProgramFile& file, const std::string& folder, bool ownFolder,
                           const machine::RunOptions& run, std::optional<bool> givenPoint, bool machinePoint) {
  ProgramReading r;
  r.folder = folder;
  r.dialect = run.dialect;
  r.givenUnits = run.powerOnUnits;
  r.givenPoint = givenPoint;
  r.machinePoint = machinePoint;
  auto program = std::make_shared<gcode::Program>(gcode::parse(file.gcode, file.gcodeFirstLine));
  std::optional<gcode::InputUnits> units = run.powerOnUnits;
  // A plain program without G20/G21 whose sizes clearly speak the other unit.
  if (!units && file.plainGcode)
    if (std::optional<machine::UnitsReading> read =
            machine::readPowerOnUnits(*program, run.dialect, gcode::powerOnUnitsOf(run.dialect, {}))) {
      r.unitsRead = units = read->units;
      r.notes.push_back(read->note);
    }
  if (ownFolder || !folder.empty())
    for (Diagnostic& d : machine::attachSubprogramFiles(*program, folder, run.dialect)) r.notes.push_back(std::move(d));
  dropFilesOutside(*program, folder, r.notes);
  if (gcode::machineProfile(run.dialect).angleWithoutComma) gcode::readAnglesWithoutComma(*program);
  r.points = machine::readDecimalPoints(*program, file.plainGcode, givenPoint, machinePoint,
                                        gcode::powerOnUnitsOf(run.dialect, units), run.dialect);
  r.program = std::move(program);
  return r;
}

// Whether `same` read this very text as this job would: then its blocks are this job's.
bool readAlike(const Job& same, const io::ProgramFile& file, const std::string& folder, const machine::RunOptions& run,
               std::optional<bool> givenPoint, const machine::MachineSetup& setup) {
  const ProgramReading& r = same.reading();
  const std::optional<io::ProgramFile>& other = same.file();
  // The GUI's run is given the check's setup, whose machine reads lengths as the check concluded:
  // read again with that, the program's numbers or the choice decide alike, or the machine did.
  const bool machineAlike =
      r.machinePoint == setup.machine.calculatorInput || r.points.calculatorInput == setup.machine.calculatorInput;
  return r.program && other && r.folder == folder && r.dialect == run.dialect && r.givenUnits == run.powerOnUnits &&
         r.givenPoint == givenPoint && machineAlike && other->plainGcode == file.plainGcode &&
         other->gcodeFirstLine == file.gcodeFirstLine && other->gcode == file.gcode;
}
}  // namespace

ComputeLog computeLog() {
  return ComputeLog{jobsMade.load(), jobTimelines.load(), jobCuts.load(), jobOnWatched.load(), jobReusedRecords.load()};
}

void watchThread(std::thread::id id) {
  const std::lock_guard lock(watchedMutex);
  watched = id;
}

std::shared_ptr<const Job> makeJob(JobInput input) {
  logCompute(jobsMade);
  std::shared_ptr<Job> job(new Job());
  Job& j = *job;
  j.tools_.setup = input.setup;
  const bool readBefore = input.readDiagnostics.has_value();
  if (readBefore) {
    j.diagnostics_ = std::move(*input.readDiagnostics);
    input.readDiagnostics.reset();
  }
  if (input.file) {
    j.file_ = std::move(input.file);
    input.file.reset();
  } else if (!readBefore) {
    auto read = io::readProgramFile(input.path, input.defaultsForPlain);
    j.diagnostics_ = std::move(read.diagnostics);
    j.file_ = std::move(read.value);
  }
  j.unreadable_ = std::any_of(j.diagnostics_.begin(), j.diagnostics_.end(), machine::isUnreadable);
  if (j.file_ && input.folderRun)
    if (std::optional<Diagnostic> refusal = io::notAGcodeProgram(j.file_->gcode, input.path)) {
      j.diagnostics_.push_back(std::move(*refusal));
      j.file_.reset();
    }
  if (!j.file_) {
    j.input_ = std::move(input);
    return job;
  }
  io::ProgramFile& file = *j.file_;
  // A program that names its machine at its head ((MACHINE: id), issue 27) runs on it:
  // its dialect, its machine.cfg keys, its turret's stations.
  if (input.programMachine) {
    std::vector<Diagnostic> warnings;
    if (const std::optional<gcode::Dialect> own = machine::machineOfProgram(file, warnings);
        own && *own != input.run.dialect) {
      const gcode::MachineProfile& profile = gcode::machineProfile(*own);
      input.run.dialect = *own;
      input.setup.machine = machine::withMachineKeys(input.setup.machine, profile);
      if (profile.maxToolStation > 0) input.stations = std::min(profile.maxToolStation, input.setup.tools.stations);
      j.tools_.setup = input.setup;
    }
    j.diagnostics_.insert(j.diagnostics_.end(), warnings.begin(), warnings.end());
  }
  // The program's folder is the control's memory: subprograms it calls come from there.
  // A file's own folder may be "" (a relative name: the current folder); an empty folder given means none.
  const bool ownFolder = !input.folder && !input.path.empty();
  const std::string folder =
      ownFolder ? std::filesystem::path(input.path).parent_path().string() : input.folder.value_or(std::string());
  const std::optional<bool> givenPoint = input.calculatorInput ? input.calculatorInput : file.header.calculatorInput;
  if (const Job* same = input.sameText.get();
      same && readAlike(*same, file, folder, input.run, givenPoint, input.setup))
    j.reading_ = same->reading_;  // the same blocks: shared, not parsed again
  else
    j.reading_ = readProgram(file, folder, ownFolder, input.run, givenPoint, input.setup.machine.calculatorInput);
  input.sameText.reset();
  const ProgramReading& read = j.reading_;
  const gcode::Program& program = *read.program;
  if (read.unitsRead) input.run.powerOnUnits = read.unitsRead;
  j.diagnostics_.insert(j.diagnostics_.end(), read.notes.begin(), read.notes.end());
  j.unreadable_ = std::any_of(j.diagnostics_.begin(), j.diagnostics_.end(),
                              [](const Diagnostic& d) { return d.range.file == 0 && machine::isUnreadable(d); });
  const machine::RunOptions& run = input.run;
  // The check and the inference read the program as a run in this dialect and these units would;
  // they never touch #500-#999.
  machine::RunOptions readRun;
  readRun.dialect = run.dialect;
  readRun.powerOnUnits = run.powerOnUnits;
  const gcode::InputUnits powerOn = gcode::powerOnUnitsOf(run.dialect, run.powerOnUnits);
  const machine::PointReading& reading = read.points;
  machine::MachineSetup readSetup = input.setup;
  readSetup.machine.calculatorInput = reading.calculatorInput;

  gcode::CheckOptions check;
  check.dialect = run.dialect;
  check.powerOnUnits = run.powerOnUnits;
  check.turretStations = input.setup.tools.stations;  // the turret the tool table was read for
  check.modalRules = input.modalRules;
  std::vector<Diagnostic> found;
  if (input.toolTable && input.inferTools) {
    // Tools from the program: library choices for stations without a fitting tool,
    // worked out while the rest of the check runs.
    check.toolsWithBitmap = std::vector<int>{};
    machine::InferenceContext context;
    context.fromProgram = file.plainGcode;
    context.run = readRun;
    // No run follows (the check, the editor's): the record keeps a mark a block, not its state,
    // and the moves as the evidence reads them, with their feeds and speeds when the cutting
    // data is measured on it.
    context.run.blockMarksOnly = !input.timelineNext;
    context.run.recordSpeeds = measuresCuttingData(input, program);
    context.toolsBeyondCentre = file.header.toolsBeyondCentre;
    machine::detail::CheckedWithTools checked = machine::detail::checkWhileInferring(program, check, [&] {
      return machine::inferTools(program, file.gcode, file.gcodeFirstLine, readSetup, io::shippedToolLibrary(),
                                 input.overrides, input.stations, context);
    });
    j.tools_ = std::move(checked.inference);
    check.toolsWithBitmap = machine::toolsWithBitmap(j.tools_.setup);
    found = std::move(checked.diagnostics);
  } else {
    j.tools_.setup = readSetup;
    // The setup as given: T words against its bitmaps, when it has any.
    if (input.toolTable)
      if (std::vector<int> tools = machine::toolsWithBitmap(readSetup); !tools.empty())
        check.toolsWithBitmap = std::move(tools);
    found = gcode::check(program, check);
  }
  explainUnusableBitmaps(found, j.tools_.setup.tools);
  found.insert(found.end(), reading.diagnostics.begin(), reading.diagnostics.end());
  // Say once which dialect accepts a program this one refuses (I102).
  if (auto fit = gcode::suggestDialect(program, check, found)) {
    j.fit_ = fit->dialect;
    j.fitBlocks_ = fit->blocks;
    found.push_back(fit->note);
  }
  j.diagnostics_.insert(j.diagnostics_.end(), std::make_move_iterator(found.begin()),
                        std::make_move_iterator(found.end()));
  j.stockNotes_ = resolveJobStock(file, program, input.stock, j.tools_.setup, readRun, j.tools_.record.get());
  // The units the program speaks, before any run (issue 28 item 4: View ▸ Units shown ▸ Auto).
  j.units_ = gcode::programInputUnits(program, powerOn, run.dialect) == gcode::InputUnits::Inch ? DisplayUnits::Inch
                                                                                                : DisplayUnits::Mm;
  // What a teacher would say about the speeds, feeds and depths (issue 39), from the same record.
  if (measuresCuttingData(input, program) && j.tools_.record && !core::hasErrors(j.diagnostics_))
    for (Diagnostic& w :
         cut::checkCuttingData(*j.tools_.record, file.header, j.tools_.setup, j.units_, input.finishMarks))
      j.diagnostics_.push_back(std::move(w));
  // The recorded run has told the tools and the stock all it knows. When it is the run
  // itself and the caller runs next, it is kept to be the timeline (interpreted once);
  // otherwise freed now, so a later timeline() does not hold two runs of a long program
  // at once (peak memory of `simulate`), nor the editor's check a run it never shows.
  if (input.timelineNext && j.tools_.record &&
      machine::recordIsTheRun(*j.tools_.record, readSetup, readRun, j.tools_.setup, run)) {
    j.record_ = std::move(j.tools_.record);
    j.programUsesVariables_ = usesVariables(program);
  }
  j.tools_.record.reset();
  // The run needs a bar: a header without a size is reported on its line (SPEC 2).
  const io::JobHeader& h = file.header;
  if (h.diameter <= 0 || h.length <= 0) {
    const char* code = h.diameter <= 0 ? codes::kDiameterMissing : codes::kLengthMissing;
    if (std::none_of(j.diagnostics_.begin(), j.diagnostics_.end(), [&](const Diagnostic& d) { return d.code == code; }))
      j.diagnostics_.push_back(Diagnostic{Severity::Error, code, SourceRange{h.diameter <= 0 ? 4 : 5, 1, 0}, {}});
  }
  std::stable_sort(j.diagnostics_.begin(), j.diagnostics_.end(), byPlace);
  j.input_ = std::move(input);
  return job;
}

std::vector<Diagnostic> Job::programFileDiagnostics() const {
  std::vector<Diagnostic> own;
  std::vector<int> reported;
  for (const Diagnostic& d : diagnostics_) {
    if (d.range.file == 0) {
      own.push_back(d);
      continue;
    }
    if (!isError(d.severity) || !reading_.program ||
        std::find(reported.begin(), reported.end(), d.range.file) != reported.end())
      continue;
    reported.push_back(d.range.file);
    Diagnostic e;
    e.severity = Severity::Error;
    e.code = codes::kSubprogramFileHasErrors;
    e.range = callInto(*reading_.program, d.range.file);
    const std::string& path = reading_.program->files[static_cast<std::size_t>(d.range.file)];
    e.args = {path.substr(path.find_last_of('/') + 1), std::to_string(d.range.line), std::to_string(d.range.column),
              d.code};
    own.push_back(std::move(e));
  }
  std::stable_sort(own.begin(), own.end(), byPlace);
  return own;
}

std::string Job::fileOf(const Diagnostic& d) const {
  return reading_.program ? machine::diagnosticFile(*reading_.program, d, input_.path) : input_.path;
}

const machine::Timeline* Job::timeline() const {
  std::call_once(timelineOnce_, [this] {
    std::shared_ptr<const machine::Timeline> record = std::move(record_);
    if (!reading_.program || hasErrors()) return;
    logCompute(jobTimelines);
    // #500-#999 are known only now (the CLI reads them after makeJob).
    if (record && persistentAlike(*record, input_.run.persistentVariables, programUsesVariables_)) {
      ++jobReusedRecords;
      timeline_ = std::move(record);
      return;
    }
    record.reset();  // one run in memory at a time
    timeline_ = std::make_shared<const machine::Timeline>(fitGuessedNose(
        machine::interpret(*reading_.program, tools_.setup, input_.run), *reading_.program, tools_.setup, input_.run));
  });
  return timeline_.get();
}

const cut::CutSimulator* Job::cut() const {
  std::call_once(cutOnce_, [this] {
    const machine::Timeline* t = timeline();
    if (!t || !file_) return;
    logCompute(jobCuts);
    cut::CutOptions options;
    options.checkpointBudgetBytes = 0;  // the finished cut only: nobody steps this one back
    cut_ = std::make_unique<cut::CutSimulator>(*t, cut::CutSetup::from(file_->header, tools_.setup), options);
    cut_->runToEnd();
  });
  return cut_.get();
}

}  // namespace klueng::core::job

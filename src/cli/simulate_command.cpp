// klueng-cli simulate FILE [--trace out.csv] [--cycle-time] [--config DIR]
//                          [--lang en|th] [--dialect fanuc|haas|classic]
//                          [--optional-stop] [--block-skip] [--no-persist]
//                          [--png out.png] [--profile out.csv] [--json summary.json] [--resolution MM]
//                          [--svg out.svg] [--dxf out.dxf] [--no-stock]   (--no-stock: interpret only, no stock
//                          collisions)
//                          [--stock DxL[xBORE][in]] [--units mm|inch] [--show-units auto|mm|inch]
// The stock: --stock, else the file's header, else inferred from the program
// (a note on stderr says which, SPEC 2 ext).
//                          [--tool N=ID]...   (library tool ID at station N for this run)
//                          [--cutting-data out.csv]  (per block: Vc, f, ap, Rz/Ra, power; W330-W336)
//                          [--design PART.json|PART.dxf]  (its roughness marks for W332)
// Checks the program (errors -> printed, exit 1), runs it into a Timeline and
// writes what was asked for. An alarm is printed like a diagnostic
// (FILE:LINE:COL: alarm A104: ...) and gives exit 1; the trace up to it is
// still written.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "batch_memory.h"
#include "cli_common.h"
#include "klueng/core/diagnostic_codes.h"
#include "commands.h"
#include "cut_outputs.h"
#include "klueng/core/cut/comp_compare.h"
#include "klueng/core/cut/cutting_data.h"
#include "klueng/core/cut/part_check.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/macro_variables.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/job/job.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/program_units.h"
#include "klueng/core/machine/trace.h"
#include "klueng/core/messages.h"

namespace klueng::cli {

namespace {

using namespace klueng::core;

struct SimulateOptions : JobOptions {
  std::string file;
  std::string tracePath;
  bool cycleTime = false;
  bool partCheck = false;            // --part-check
  bool compareCompensation = false;  // --compare-compensation [none|sharp]
  bool compareSharp = false;
  double partTolerance = 0.01;  // --part-tolerance MM (leftover allowed, radial)
  bool optionalStop = false;
  bool blockSkip = false;
  bool noPersist = false;                 // --no-persist: keep macro_variables.cfg as it is
  CutOutputOptions cut;                   // --png --profile --json --resolution (cut_outputs.h)
  std::optional<DisplayUnits> showUnits;  // --show-units (nullopt: auto, the program's)
  std::string cuttingDataPath;            // --cutting-data out.csv (issue 39)
  std::string design;                     // --design PART: its roughness marks judge the finishing feeds (W332)
};

// simulate's option table (cli_common.h): the shared rows, then its own. New outputs
// (--png, --json, ...) add a row here and a step in runSimulate.
std::optional<int> parseSimulateOptions(const std::vector<std::string>& args, SimulateOptions& o) {
  std::vector<CliOption> options = machineOptions(o);
  for (CliOption& row : runOptions(o)) options.push_back(std::move(row));
  bool noStock = false;
  const std::vector<CliOption> own = {
      valueOption("--trace", o.tracePath),
      flagOption("--cycle-time", o.cycleTime),
      flagOption("--optional-stop", o.optionalStop),
      flagOption("--block-skip", o.blockSkip),
      flagOption("--no-persist", o.noPersist),
      valueOption("--png", o.cut.pngPath),
      valueOption("--profile", o.cut.profilePath),
      valueOption("--json", o.cut.jsonPath),
      valueOption("--svg", o.cut.svgPath),
      valueOption("--dxf", o.cut.dxfPath),
      valueOption("--cutting-data", o.cuttingDataPath),
      valueOption("--design", o.design),
      flagOption("--features", o.cut.features),
      flagOption("--no-stock", noStock),
      flagOption("--part-check", o.partCheck),
      {"--part-tolerance",
       {},
       true,
       codes::kCliAllowedMillimetres,
       [&o](const std::string& v) {
         o.partCheck = true;
         return parseResolution(v, o.partTolerance);
       }},
      {"--resolution",
       {},
       true,
       codes::kCliAllowedMillimetres,
       [&o](const std::string& v) { return parseResolution(v, o.cut.resolution); }},
      {"--compare-compensation",
       {},
       true,
       codes::kCliAllowedCompare,
       [&o](const std::string& v) {
         o.compareCompensation = true;
         o.compareSharp = v == "sharp";
         return v == "none" || v == "sharp";
       }},
      {"--show-units",
       {},
       true,
       codes::kCliAllowedShowUnits,
       [&o](const std::string& v) {
         if (v == "mm")
           o.showUnits = DisplayUnits::Mm;
         else if (v == "inch")
           o.showUnits = DisplayUnits::Inch;
         else if (v != "auto")
           return false;
         return true;
       }},
  };
  options.insert(options.end(), own.begin(), own.end());
  const auto exit = parseCommandLine("simulate", codes::kCliSimulateUsage, args, options,
                                     oneFile("simulate", o.file, langOfArgs(args)));
  if (exit) return exit;
  if (noStock) o.cut.enabled = false;
  if (o.file.empty()) {
    std::fputs(cliText(codes::kCliSimulateUsage, o.lang).c_str(), stderr);
    return 2;
  }
  return std::nullopt;
}

void printDiagnostic(const std::string& file, const Diagnostic& d, Lang lang) {
  klueng::cli::printDiagnostic(stderr, file, d, lang);
}

}  // namespace

int runSimulate(const std::vector<std::string>& args) {
  SimulateOptions o;
  if (const auto exit = parseSimulateOptions(args, o)) return *exit;

  // The machine files first: the checker needs to know which tools have a bitmap.
  LoadedConfig config = loadConfig(o.configDir);
  // The machine the program names at its head, unless --machine or --dialect chose one.
  std::vector<Diagnostic> machineWarnings;
  const ProgramArg programArgument = programArg(o.file);  // `-` and pipes are read once, here
  o.file = programArgument.name;
  std::optional<io::ProgramFile> read;  // a file read once, for the machine and the job
  o.dialect = programMachine(programArgument, o.dialectGiven, o.dialect, machineWarnings, &read);
  if (!chooseMachine(o.machine, config, o.dialect, o.lang)) return 2;
  for (const auto& fd : config.diagnostics) printDiagnostic(fd.file, fd.diagnostic, o.lang);
  for (const Diagnostic& d : machineWarnings) printDiagnostic(o.file, d, o.lang);
  if (config.unreadable || config.hasErrors()) return 2;  // the setup, not the program, is wrong
  std::string error;
  std::optional<core::job::JobInput> request =
      jobRequest(config, o.dialect, o.powerOnUnits, o.stock, o.tools, error, o.lang);
  if (!request) {
    std::fprintf(stderr, "klueng-cli simulate: %s\n", error.c_str());
    return 2;
  }
  request->calculatorInput = o.calculatorInput;
  if (!o.design.empty()) {
    const std::optional<design::PartDesign> part =
        readPartDrawing(o.design, {}, config.setup.machine.chuckGrip, o.lang);
    if (!part) return 2;  // said, on its line
    request->finishMarks = design::finishMarks(*part);
  }
  programArgument.into(*request);
  request->run.optionalStop = o.optionalStop;
  request->run.blockSkip = o.blockSkip;
  // #500-#999 belong to the machine, not to the program's folder (issue 26 item 9): they live in
  // macro_variables.cfg in the --config folder, else in the user's data folder, between runs.
  const std::string variablesDir = !o.configDir.empty() ? o.configDir : io::userConfigDir();
  const std::string variablesPath = variablesDir.empty() ? std::string() : io::macroVariablesPath(variablesDir);
  io::MacroVariables variables;
  request->run.persistentVariables = &variables;  // read below, before the run asks for them
  request->timelineNext = true;                   // a recorded run that is the run is not made twice
  // Read and parse once: tools from the program (library choices, notes say which), the check, the stock.
  core::job::JobInput input = *request;
  if (read) input.file = std::move(read);  // moved, not copied: one text of the program in memory
  const core::job::Job& job = *keepUntilExit(core::job::makeJob(std::move(input)));
  for (const Diagnostic& n : job.toolNotes()) std::fprintf(stderr, "%s\n", formatNote(o.file, n, o.lang).c_str());
  for (const auto& d : job.diagnostics()) printDiagnostic(job.fileOf(d), d, o.lang);
  if (job.unreadable()) return 2;
  // An output naming the program, a subprogram file or a setup file would destroy it: refused
  // before the run, as a compiler refuses `-o` naming its source (issue 29).
  std::vector<std::string> inputs = programInputs(o.file, job, config);
  inputs.push_back(variablesPath);  // #500-#999 are read too
  if (!o.design.empty()) inputs.push_back(o.design);
  if (!o.machine.empty() && std::filesystem::is_regular_file(o.machine)) inputs.push_back(o.machine);
  if (!outputsAllowed({o.tracePath, o.cut.pngPath, o.cut.profilePath, o.cut.jsonPath, o.cut.svgPath, o.cut.dxfPath,
                       o.cuttingDataPath},
                      inputs, o.lang))
    return 2;
  if (!job.file() || !job.program() || job.hasErrors()) return 1;
  for (const Diagnostic& n : job.stockNotes()) std::fprintf(stderr, "%s\n", formatNote(o.file, n, o.lang).c_str());
  const machine::MachineSetup& setup = job.setup();
  const io::ProgramFile& programFile = *job.file();
  const gcode::Program& program = *job.program();
  machine::RunOptions runOptions = request->run;
  // Read, run and write #500-#999 under one lock: a parallel run waits, then reads our values.
  std::optional<io::MacroVariablesLock> variablesLock;
  if (!o.noPersist && !variablesPath.empty()) variablesLock.emplace(variablesDir);
  const io::ReadResult<io::MacroVariables> stored = variablesPath.empty()
                                                        ? io::ReadResult<io::MacroVariables>{io::MacroVariables{}, {}}
                                                        : io::readMacroVariables(variablesPath);
  for (const Diagnostic& d : stored.diagnostics) printDiagnostic(variablesPath, d, o.lang);
  variables = stored.value.value_or(io::MacroVariables{});
  const io::MacroVariables before = variables;
  const machine::Timeline& timeline = *job.timeline();  // the run, with the stored #500-#999
  for (const Diagnostic& n : timeline.flow.notices) printDiagnostic(job.fileOf(n), n, o.lang);
  bool variablesWritten = true;
  if (variables != before && !o.noPersist && stored.value && !variablesPath.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(variablesDir, ec);  // the user's data folder may not exist yet
    // The run's own result does not depend on it: said, the run goes on, and the exit status is 2
    // as for any output that could not be written (README).
    variablesWritten = writeOutput(variablesPath, io::formatMacroVariables(variables), o.lang);
  }
  variablesLock.reset();

  if (!o.tracePath.empty() && !writeOutput(o.tracePath, machine::formatTraceCsv(timeline), o.lang)) return 2;
  // The stock: collisions stop the run on their block (SPEC 8), and the cut outputs.
  CutOutputOptions cutOptions = o.cut;
  cutOptions.lang = o.lang;
  // Lengths on stdout/stderr in the program's units unless --show-units says otherwise (issue 28 item 4).
  const UnitFormat units(o.showUnits.value_or(
      machine::programUnits(timeline, gcode::powerOnUnitsOf(runOptions.dialect, runOptions.powerOnUnits))));
  cutOptions.units = units;
  const CutOutcome cut = o.cut.enabled ? runCut(o.file, programFile.header, setup, timeline, cutOptions) : CutOutcome{};
  for (const Diagnostic& n : cut.guessNotes) std::fprintf(stderr, "%s\n", formatNote(o.file, n, o.lang).c_str());
  for (const Diagnostic& w : cut.warnings) printDiagnostic(job.fileOf(w), w, o.lang);
  // The part check and the comparison cut with the tools the run used.
  const machine::MachineSetup& cutSetup = cut.setup ? *cut.setup : setup;
  if (o.cycleTime) std::printf("%.4f\n", timeline.cycleTime());
  if (o.partCheck && o.cut.enabled) {
    // The described part against the real cut: gouges and leftovers as warnings on their blocks.
    cut::PartCheckOptions check;
    check.resolution = o.cut.resolution;
    check.leftoverTolerance = o.partTolerance;
    const machine::Timeline programmed = cut::programmedPath(program, cutSetup, runOptions, timeline);
    const cut::PartCheck result =
        cut::checkPart(timeline, programmed, cut::CutSetup::from(programFile.header, cutSetup), check);
    for (const Diagnostic& d : cut::partCheckDiagnostics(result, units)) printDiagnostic(job.fileOf(d), d, o.lang);
  }
  if (o.compareCompensation && o.cut.enabled) {
    // What G41/G42 change: each difference as a note on the block that cut the surface.
    const cut::CompareWith with = o.compareSharp ? cut::CompareWith::SharpNose : cut::CompareWith::NoCompensation;
    const cut::CompComparison c = cut::compareCompensation(program, cutSetup, runOptions,
                                                           cut::CutSetup::from(programFile.header, cutSetup), with);
    for (const cut::CompDifference& d : c.differences)
      std::fprintf(stderr, "%s:%d:1: %s: %s\n",
                   job.fileOf(Diagnostic{Severity::Note, "", {d.line, 1, 0, d.file}, {}}).c_str(), d.line,
                   std::string(severityName(Severity::Note, o.lang)).c_str(),
                   cut::describeDifference(d, program, with, o.lang, units).c_str());
  }
  bool cuttingDataWritten = true;
  if (!o.cuttingDataPath.empty()) {
    // Cutting data (issue 39): measured on demand from the same run, with the tools the cut used.
    const cut::MaterialTable& materials = cut::shippedMaterials();
    cut::CuttingDataOptions options =
        cut::cuttingDataOptions(programFile.header.material, cutSetup.tools, cutSetup.machine, materials);
    options.finishMarks = request->finishMarks;
    options.units = machine::programUnits(timeline, gcode::powerOnUnitsOf(runOptions.dialect, runOptions.powerOnUnits));
    if (!options.material) {
      const Diagnostic note =
          programFile.header.material.empty()
              ? Diagnostic{Severity::Note, codes::kMaterialNotNamed, {}, {materials.idList()}}
              : Diagnostic{
                    Severity::Note, codes::kMaterialUnknown, {}, {programFile.header.material, materials.idList()}};
      std::fprintf(stderr, "%s\n", formatNote(o.file, note, o.lang).c_str());
    }
    const cut::CuttingData data =
        cut::measureCuts(timeline, cut::CutSetup::from(programFile.header, cutSetup), options);
    // The check's own (job.diagnostics(), printed above) are not said twice.
    for (const Diagnostic& w : data.warnings)
      if (std::none_of(job.diagnostics().begin(), job.diagnostics().end(), [&](const Diagnostic& d) {
            return d.code == w.code && d.range.line == w.range.line && d.range.file == w.range.file;
          }))
        printDiagnostic(job.fileOf(w), w, o.lang);
    cuttingDataWritten = writeOutput(o.cuttingDataPath, cut::formatCuttingDataCsv(data, options.units), o.lang);
  }
  const std::optional<Diagnostic>& alarm = cut.alarm ? cut.alarm : timeline.alarm;
  if (alarm) printDiagnostic(job.fileOf(*alarm), *alarm, o.lang);
  if (!cut.written || !variablesWritten || !cuttingDataWritten)
    return 2;  // an output could not be written (said); the old file is kept
  return alarm ? 1 : 0;
}

}  // namespace klueng::cli

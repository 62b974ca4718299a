// klueng-cli print FILE --pdf OUT.pdf [--sheet program|drawing|both] [--lang en|th]
//                  [--dialect fanuc|haas|classic] [--stock DxL[xBORE][in]] [--units mm|inch]
//                  [--config DIR] [--tool N=ID]...
// The program sheet and the drawing sheet (issue 10, item 6) as the GUI's
// Export PDF paints them, by the picture module. The program is loaded as
// `simulate` loads it (stock, tools from the program); a program with errors
// still prints (its drawing shows the uncut bar and says why), exit status 1.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.h"
#include "klueng/core/diagnostic_codes.h"
#include "commands.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/gcode/decimal_point.h"
#include "klueng/core/job/job.h"
#include "png_writer.h"

namespace klueng::cli {

using namespace klueng::core;

namespace {

struct PrintOptions : JobOptions {
  std::string file;
  std::string pdf;
  bool program = true;
  bool drawing = true;
  std::string design;  // --design PART.json|PART.dxf: its tolerances on the drawing
};

// print's option table (cli_common.h): the shared rows, then its own.
std::optional<int> parsePrintOptions(const std::vector<std::string>& args, PrintOptions& o) {
  std::vector<CliOption> options = machineOptions(o);
  for (CliOption& row : runOptions(o)) options.push_back(std::move(row));
  options.push_back(valueOption("--pdf", o.pdf));
  options.push_back(valueOption("--design", o.design));
  options.push_back({"--sheet", {}, true, codes::kCliAllowedSheet, [&o](const std::string& v) {
                       o.program = v != "drawing";
                       o.drawing = v != "program";
                       return v == "program" || v == "drawing" || v == "both";
                     }});
  const auto exit =
      parseCommandLine("print", codes::kCliPrintUsage, args, options, oneFile("print", o.file, langOfArgs(args)));
  if (exit) return exit;
  if (o.file.empty() || o.pdf.empty()) return usageError("print", codes::kCliPrintUsage, o.lang, codes::kCliPrintNeeds);
  return std::nullopt;
}

}  // namespace

int runPrint(const std::vector<std::string>& args) {
  PrintOptions o;
  if (const auto exit = parsePrintOptions(args, o)) return *exit;
  LoadedConfig config = loadConfig(o.configDir);
  // The machine the program names at its head, unless --machine or --dialect chose one.
  std::vector<Diagnostic> machineWarnings;
  const ProgramArg programArgument = programArg(o.file);  // `-` and pipes are read once, here
  o.file = programArgument.name;
  o.dialect = programMachine(programArgument, o.dialectGiven, o.dialect, machineWarnings);
  if (!chooseMachine(o.machine, config, o.dialect, o.lang)) return 2;
  for (const auto& fd : config.diagnostics) printDiagnostic(stderr, fd.file, fd.diagnostic, o.lang);
  for (const Diagnostic& d : machineWarnings) printDiagnostic(stderr, o.file, d, o.lang);
  if (config.unreadable || config.hasErrors()) return 2;
  std::string error;
  std::optional<core::job::JobInput> request =
      jobRequest(config, o.dialect, o.powerOnUnits, o.stock, o.tools, error, o.lang);
  if (!request) {
    std::fprintf(stderr, "klueng-cli print: %s\n", error.c_str());
    return 2;
  }
  request->calculatorInput = o.calculatorInput;
  programArgument.into(*request);
  const std::shared_ptr<const core::job::Job> made = core::job::makeJob(*request);
  const core::job::Job& job = *made;
  for (const Diagnostic& n : job.toolNotes()) std::fprintf(stderr, "%s\n", formatNote(o.file, n, o.lang).c_str());
  for (const auto& d : job.diagnostics()) printDiagnostic(stderr, job.fileOf(d), d, o.lang);
  for (const Diagnostic& n : job.stockNotes()) std::fprintf(stderr, "%s\n", formatNote(o.file, n, o.lang).c_str());
  if (job.unreadable() || !job.file()) return 2;
  // Refused before anything is drawn, as a compiler refuses `-o` naming its source.
  std::vector<std::string> inputs = programInputs(o.file, job, config);
  if (!o.design.empty()) inputs.push_back(o.design);
  if (!outputsAllowed({o.pdf}, inputs, o.lang)) return 2;

  const std::string name = std::filesystem::path(o.file).filename().string();
  KluengPrintPdf in{};
  in.thai = o.lang == Lang::Th ? 1 : 0;
  in.programSheet = o.program ? 1 : 0;
  in.drawingSheet = o.drawing ? 1 : 0;
  in.fileName = name.c_str();
  in.job = &job;
  // The drawing speaks the program's units (its G20/G21, else the power-on units; issue 28 item 4).
  in.inch = job.units() == DisplayUnits::Inch ? 1 : 0;
  std::optional<design::PartDesign> part;
  if (!o.design.empty()) {
    part = readPartDrawing(o.design, {}, config.setup.machine.chuckGrip, o.lang);
    if (!part) return 2;
    in.design = &*part;
  }
  // A failed write keeps the old PDF and exits 2 (issue 29).
  if (!reportWrite(o.pdf, writePrintPdf(in, o.pdf), o.lang)) return 2;
  return job.hasErrors() ? 1 : 0;
}

}  // namespace klueng::cli

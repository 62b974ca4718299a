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

struct PrintOptions {
  std::string file;
  std::string pdf;
  bool program = true;
  bool drawing = true;
  Lang lang = Lang::En;
  gcode::Dialect dialect = gcode::Dialect::Fanuc;
  bool dialectGiven = false;  // --dialect or --machine: wins over the machine a program names
  std::string machine;        // --machine NAME|FILE
  std::optional<io::JobHeader> stock;
  std::optional<gcode::InputUnits> powerOnUnits;
  std::optional<bool> calculatorInput;
  std::string configDir;
  std::vector<std::string> tools;
  std::string design;  // --design PART.json|PART.dxf: its tolerances on the drawing
};

std::optional<PrintOptions> parse(const std::vector<std::string>& args) {
  PrintOptions o;
  o.lang = langOfArgs(args);
  const Lang lang = o.lang;
  const auto bad = [lang](const std::string& option, const std::string& value, const char* allowed) {
    printCliError("print", codes::kCliBadValue, lang, {value, option, cliText(allowed, lang)});
    return std::nullopt;
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) != 0) {
      if (!o.file.empty()) {
        printCliError("print", codes::kCliOneFile, lang, {o.file, a});
        return std::nullopt;
      }
      o.file = a;
      continue;
    }
    if (i + 1 >= args.size()) {
      printCliError("print", codes::kCliNeedsValue, lang, {a});
      return std::nullopt;
    }
    const std::string v = args[++i];
    if (a == "--pdf") {
      o.pdf = v;
    } else if (a == "--sheet") {
      if (v != "program" && v != "drawing" && v != "both") return bad(a, v, codes::kCliAllowedSheet);
      o.program = v != "drawing";
      o.drawing = v != "program";
    } else if (a == "--lang") {
      const auto lang = parseLang(v);
      if (!lang) return bad(a, v, codes::kCliAllowedLang);
      o.lang = *lang;
    } else if (a == "--dialect") {
      const auto dialect = parseDialect(v);
      if (!dialect) return bad(a, v, codes::kCliAllowedDialect);
      o.dialect = *dialect;
      o.dialectGiven = true;
    } else if (a == "--machine") {
      o.machine = v;
      o.dialectGiven = true;
    } else if (a == "--design") {
      o.design = v;
    } else if (a == "--stock") {
      o.stock = parseStock(v);
      if (!o.stock) return bad(a, v, codes::kCliAllowedStock);
    } else if (a == "--units") {
      o.powerOnUnits = parseUnits(v);
      if (!o.powerOnUnits) return bad(a, v, codes::kCliAllowedUnits);
    } else if (a == "--decimal-point") {
      o.calculatorInput = parseDecimalPoint(v);
      if (!o.calculatorInput) return bad(a, v, codes::kCliAllowedDecimalPoint);
    } else if (a == "--config") {
      o.configDir = v;
    } else if (a == "--tool") {
      o.tools.push_back(v);
    } else {
      printCliError("print", codes::kCliUnknownOption, lang, {a});
      return std::nullopt;
    }
  }
  if (o.file.empty() || o.pdf.empty()) {
    printCliError("print", codes::kCliPrintNeeds, lang);
    return std::nullopt;
  }
  return o;
}

}  // namespace

int runPrint(const std::vector<std::string>& args) {
  if (std::find(args.begin(), args.end(), "--help") != args.end()) {
    std::fputs(cliText(codes::kCliPrintUsage, langOfArgs(args)).c_str(), stdout);
    return 0;
  }
  std::optional<PrintOptions> parsed = parse(args);
  if (!parsed) {
    std::fputs(cliText(codes::kCliPrintUsage, langOfArgs(args)).c_str(), stderr);
    return 2;
  }
  PrintOptions& o = *parsed;
  LoadedConfig config = loadConfig(o.configDir);
  // The machine the program names at its head, unless --machine or --dialect chose one.
  std::vector<Diagnostic> machineWarnings;
  o.dialect = programMachine(o.file, o.dialectGiven, o.dialect, machineWarnings);
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
  request->path = o.file;
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

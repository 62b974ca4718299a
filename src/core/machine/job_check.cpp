// One program's check for the GUI (see job_check.h).
#include "klueng/core/machine/job_check.h"

#include "klueng/core/gcode/decimal_point.h"

#include "check_with_tools.h"
#include "klueng/core/gcode/dialect_fit.h"
#include <algorithm>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/machine/point_reading.h"
#include "klueng/core/machine/job.h"
#include "klueng/core/gcode/program_index.h"
#include "klueng/core/machine/subprogram_files.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine {

namespace {

// The call in the program itself (file 0) that reaches subprogram file `file`.
SourceRange callInto(const gcode::Program& program, int file) {
  const gcode::ProgramIndex index(program);
  const bool packed = true;
  for (const gcode::Block& b : program.blocks) {
    if (b.file != 0) break;
    const gcode::Word* p = b.find('P');
    if (!p || p->expr >= 0) continue;
    for (const gcode::Word& w : b.words)
      if ((w.letter == 'M' && w.code() == 98) || (w.letter == 'G' && (w.code() == 65 || w.code() == 66))) {
        const gcode::CallTarget t = gcode::callTarget(p->value, std::nullopt, packed && w.letter == 'M');
        const gcode::ProgramSection* s = index.program(t.number);
        if (!s) s = index.program(static_cast<int>(p->value));
        if (s && s->file == file) return p->range;
      }
  }
  return SourceRange{program.blocks.empty() ? program.firstLine : program.blocks.front().line, 1, 0, 0};
}

}  // namespace

JobCheck checkJob(std::string_view gcode, int firstLine, gcode::CheckOptions options, const MachineSetup& setup,
                  const io::ToolLibrary& library, const std::vector<StationOverride>& overrides, int stations,
                  const std::string& folder, std::optional<bool> chosenCalculatorInput,
                  std::optional<bool> chosenToolsBeyondCentre) {
  JobCheck result;
  gcode::Program program = gcode::parse(gcode, firstLine);
  std::vector<Diagnostic> fileDiagnostics;
  if (!folder.empty()) fileDiagnostics = attachSubprogramFiles(program, folder, options.dialect);
  // G-code from the first line on: a plain program, without Klueng's job header.
  const bool plain = firstLine <= 1;
  PointReading reading =
      readDecimalPoints(program, plain, chosenCalculatorInput, setup.machine.calculatorInput,
                        gcode::powerOnUnitsOf(options.dialect, options.powerOnUnits), options.dialect);
  MachineSetup readSetup = setup;
  readSetup.machine.calculatorInput = reading.calculatorInput;
  // The program's tools decide which T words have a tool (one meaning: job.h);
  // they are worked out while the rest of the check runs.
  InferenceContext context;
  context.fromProgram = plain;
  context.toolsBeyondCentre = chosenToolsBeyondCentre;
  context.run.dialect = options.dialect;
  context.run.powerOnUnits = options.powerOnUnits;
  detail::CheckedWithTools checked = detail::checkWhileInferring(program, options, [&] {
    return inferTools(program, gcode, firstLine, readSetup, library, overrides, stations, context);
  });
  result.inference = std::move(checked.inference);
  if (options.toolsWithBitmap) options.toolsWithBitmap = toolsWithBitmap(result.inference.setup);
  result.diagnostics = std::move(checked.diagnostics);
  result.diagnostics.insert(result.diagnostics.end(), fileDiagnostics.begin(), fileDiagnostics.end());
  result.diagnostics.insert(result.diagnostics.end(), reading.diagnostics.begin(), reading.diagnostics.end());
  // Errors in subprogram files: one E412 per file, on the call that reaches it.
  std::vector<Diagnostic> own;
  std::vector<int> reported;
  for (Diagnostic& d : result.diagnostics) {
    if (d.range.file == 0) {
      own.push_back(std::move(d));
      continue;
    }
    if (!isError(d.severity) || std::find(reported.begin(), reported.end(), d.range.file) != reported.end()) continue;
    reported.push_back(d.range.file);
    Diagnostic e;
    e.severity = Severity::Error;
    e.code = codes::kSubprogramFileHasErrors;
    e.range = callInto(program, d.range.file);
    const std::string& path = program.files[static_cast<std::size_t>(d.range.file)];
    e.args = {path.substr(path.find_last_of('/') + 1), std::to_string(d.range.line), std::to_string(d.range.column), d.code};
    own.push_back(std::move(e));
  }
  result.diagnostics = std::move(own);
  // The units the program speaks, before any run (issue 28 item 4: View ▸ Units shown ▸ Auto).
  result.units = gcode::programInputUnits(program, gcode::powerOnUnitsOf(options.dialect, options.powerOnUnits), options.dialect) ==
                         gcode::InputUnits::Inch
                     ? DisplayUnits::Inch
                     : DisplayUnits::Mm;
  // The dialect that accepts a program this one refuses (I102), for the offer bar.
  if (auto fit = gcode::suggestDialect(program, options, result.diagnostics)) {
    result.fit = fit->dialect;
    result.fitBlocks = fit->blocks;
    result.diagnostics.push_back(fit->note);
  }
  return result;
}

StockInference inferStockFromText(std::string_view gcode, int firstLine, const MachineSetup& setup,
                                  const RunOptions& options, std::optional<bool> chosenCalculatorInput) {
  gcode::Program program = gcode::parse(gcode, firstLine);
  const PointReading reading =
      readDecimalPoints(program, firstLine <= 1, chosenCalculatorInput, setup.machine.calculatorInput,
                        gcode::powerOnUnitsOf(options.dialect, options.powerOnUnits), options.dialect);
  if (reading.calculatorInput == setup.machine.calculatorInput) return inferStock(program, setup, options);
  MachineSetup readSetup = setup;
  readSetup.machine.calculatorInput = reading.calculatorInput;
  return inferStock(program, readSetup, options);
}

}  // namespace klueng::core::machine

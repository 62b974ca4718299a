// Which other machine profile accepts a program (issue 8 item 5).
#include "klueng/core/gcode/dialect_fit.h"

#include <algorithm>
#include <set>
#include <string_view>
#include <string>

#include "diagnostic_codes.h"
#include "klueng/core/gcode/code_table.h"

namespace klueng::core::gcode {

namespace {

// A diagnostic that says a block is written in another machine's form: a code, letter, word format
// or M code this machine has not (Haas's G71 D, a 5-digit O, `G04 P3.`), or system B's `G92 S2500`
// read in system A (a warning). Rules every machine keeps in its own way (a profile's first block,
// text after ';', a comma for the point) are the program's mistakes, not forms of another machine.
// An M code this machine passes on as its builder's (W101) that another machine's control reads as a
// subprogram call (Haas's M97 P1000): here the blocks it calls never run, so the program is that
// machine's. Other builder M codes (M31 chip conveyor, M216 load monitor) say nothing of the control.
bool callOfAnotherMachine(const Diagnostic& d) {
  if (d.args.empty() || d.args[0].size() < 2 || (d.args[0][0] != 'M' && d.args[0][0] != 'm')) return false;
  const std::string digits = d.args[0].substr(1);
  if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 4) return false;
  const int number = std::stoi(digits);
  const std::vector<const MachineProfile*> machines = machineProfiles();
  return std::any_of(machines.begin(), machines.end(), [&](const MachineProfile* m) {
    const CodeInfo* row = findCode('M', number, m->dialect);
    return row && row->group == ModalGroup::MSubprogram;
  });
}

bool isForm(const Diagnostic& d) {
  static constexpr std::string_view kForms[] = {
      codes::kUnknownCharacter,  codes::kTooManyDecimals,  codes::kUnknownGCode,     codes::kUnknownMCode,
      codes::kBadSequenceNumber, codes::kBadToolWord,      codes::kBadToolWordFanuc, codes::kNotWholeNumber,
      codes::kBlanksInWord,      codes::kLetterNotAllowed, codes::kLetterTwice,      codes::kMustStandAlone,
      codes::kOneShotWithMotion, codes::kFeedModeNotAlone, codes::kG28WithoutAxes,   codes::kMacroNotInDialect,
  };
  if (d.code == std::string_view(codes::kClampOfAnotherSystem)) return true;
  if (d.code == std::string_view(codes::kMachineSpecificM)) return callOfAnotherMachine(d);
  return d.severity == Severity::Error && std::find(std::begin(kForms), std::end(kForms), d.code) != std::end(kForms);
}

// Where another machine is looked at: an M code it does not list (M93 typed for M03) is the
// program's slip there, not a sign that the machine is the wrong one.
bool isFormThere(const Diagnostic& d) {
  return isForm(d) && d.code != std::string_view(codes::kUnknownMCode) &&
         d.code != std::string_view(codes::kMachineSpecificM);
}

long errorCount(const std::vector<Diagnostic>& diags) {
  return std::count_if(diags.begin(), diags.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

// The blocks written in another machine's form, alone (with the expressions they use): a machine
// that does not read them as its own is ruled out by this small check, so a typed mistake every
// machine refuses costs no full check of a long program on each (the editor checks on every edit).
Program formBlocksOf(const Program& program, const std::set<int>& lines) {
  Program sample;
  sample.firstLine = program.firstLine;
  sample.lineCount = program.lineCount;
  sample.expressions = program.expressions;
  for (const Block& b : program.blocks)
    if (b.file == 0 && lines.count(b.line)) sample.blocks.push_back(b);
  return sample;
}

}  // namespace

std::optional<DialectFit> suggestDialect(const Program& program, const CheckOptions& options,
                                         const std::vector<Diagnostic>& diagnostics) {
  // Costs nothing for the common program, which has no block of another machine's form.
  if (std::none_of(diagnostics.begin(), diagnostics.end(), isForm)) return std::nullopt;
  std::set<int> current;
  for (const Diagnostic& d : diagnostics)
    if (isForm(d)) current.insert(d.range.line);
  const long errorsHere = errorCount(diagnostics);
  const Program forms = formBlocksOf(program, current);
  for (const MachineProfile* machine : machineProfiles()) {
    const MachineProfile& profile = *machine;
    if (profile.dialect == options.dialect) continue;
    CheckOptions other = options;
    other.dialect = profile.dialect;
    const std::vector<Diagnostic> formsThere = check(forms, other);
    if (std::any_of(formsThere.begin(), formsThere.end(), isFormThere)) continue;
    const std::vector<Diagnostic> there = check(program, other);
    // There, every block reads as that machine's own, and the program has no more errors
    // than here (its own mistakes stay mistakes on any machine).
    if (std::any_of(there.begin(), there.end(), isFormThere) || errorCount(there) > errorsHere) continue;
    DialectFit fit{profile.dialect, static_cast<int>(current.size()), {}};
    fit.note = Diagnostic{Severity::Note,
                          codes::kDialectFits,
                          {*current.begin(), 1, 0},
                          {std::to_string(fit.blocks), std::string(profile.nameEn), std::string(profile.id)}};
    return fit;
  }
  return std::nullopt;
}

}  // namespace klueng::core::gcode

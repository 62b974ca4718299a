// Which other machine profile accepts a program (issue 8 item 5).
#include "klueng/core/gcode/dialect_fit.h"

#include <algorithm>
#include <set>
#include <string_view>
#include <string>

#include "diagnostic_codes.h"

namespace klueng::core::gcode {

namespace {

// A diagnostic that says a block is written in another machine's form: a code, letter, word format
// or M code this machine has not (Haas's G71 D, a 5-digit O, `G04 P3.`), or system B's `G92 S2500`
// read in system A (a warning). Rules every machine keeps in its own way (a profile's first block,
// text after ';', a comma for the point) are the program's mistakes, not forms of another machine.
bool isForm(const Diagnostic& d) {
  static constexpr std::string_view kForms[] = {
      codes::kUnknownCharacter,  codes::kTooManyDecimals,  codes::kUnknownGCode,     codes::kUnknownMCode,
      codes::kBadSequenceNumber, codes::kBadToolWord,      codes::kBadToolWordFanuc, codes::kNotWholeNumber,
      codes::kBlanksInWord,      codes::kLetterNotAllowed, codes::kLetterTwice,      codes::kMustStandAlone,
      codes::kOneShotWithMotion, codes::kFeedModeNotAlone, codes::kG28WithoutAxes,   codes::kMacroNotInDialect,
  };
  if (d.code == std::string_view(codes::kClampOfAnotherSystem)) return true;
  return d.severity == Severity::Error && std::find(std::begin(kForms), std::end(kForms), d.code) != std::end(kForms);
}

// Where another machine is looked at: an M code it does not list (M93 typed for M03) is the
// program's slip there, not a sign that the machine is the wrong one.
bool isFormThere(const Diagnostic& d) { return isForm(d) && d.code != std::string_view(codes::kUnknownMCode); }

long errorCount(const std::vector<Diagnostic>& diags) {
  return std::count_if(diags.begin(), diags.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
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
  for (const MachineProfile* machine : machineProfiles()) {
    const MachineProfile& profile = *machine;
    if (profile.dialect == options.dialect) continue;
    CheckOptions other = options;
    other.dialect = profile.dialect;
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

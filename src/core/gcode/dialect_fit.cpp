// Which other machine profile accepts a program (issue 8 item 5).
#include "klueng/core/gcode/dialect_fit.h"

#include <set>
#include <string>

#include "diagnostic_codes.h"

namespace klueng::core::gcode {

namespace {

std::set<int> linesWithErrors(const std::vector<Diagnostic>& diags) {
  std::set<int> lines;
  for (const Diagnostic& d : diags)
    if (d.severity == Severity::Error) lines.insert(d.range.line);
  return lines;
}

}  // namespace

std::optional<DialectFit> suggestDialect(const Program& program, const CheckOptions& options,
                                         const std::vector<Diagnostic>& diagnostics) {
  if (!hasErrors(diagnostics)) return std::nullopt;
  // Lexical errors are the same in every dialect: no profile can fix them.
  if (hasErrors(program.lexicalDiagnostics)) return std::nullopt;
  const std::set<int> current = linesWithErrors(diagnostics);
  for (const MachineProfile* machine : machineProfiles()) {
    const MachineProfile& profile = *machine;
    if (profile.dialect == options.dialect) continue;
    CheckOptions other = options;
    other.dialect = profile.dialect;
    other.stopAtFirstError = true;  // only whether it accepts the program
    const std::vector<Diagnostic> there = check(program, other);
    if (hasErrors(there)) continue;
    // Every block with an error here is clean there.
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

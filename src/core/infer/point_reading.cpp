// How one job reads lengths without a decimal point (point_reading.h).
#include "klueng/core/infer/point_reading.h"

#include <string>

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/gcode/decimal_point.h"

namespace klueng::core::machine {

namespace {

Diagnostic readingNote(const gcode::PointClue& clue, bool increments) {
  Diagnostic d;
  d.severity = Severity::Note;
  d.code = increments ? codes::kLengthsInIncrements : codes::kLengthsWhole;
  d.range = clue.range;
  d.args = {clue.word, std::to_string(clue.range.line), gcode::clueLengthText(clue, increments)};
  return d;
}

}  // namespace

PointReading readDecimalPoints(gcode::Program& program, bool plainProgram, std::optional<bool> chosen,
                               bool machineCalculatorInput, gcode::InputUnits powerOnUnits, gcode::Dialect dialect) {
  PointReading out;
  const gcode::PointEvidence evidence = gcode::weighDecimalPoints(program, powerOnUnits, dialect);
  out.calculatorInput = chosen.value_or(machineCalculatorInput);
  if (!chosen && plainProgram) {
    const std::size_t increments = evidence.forIncrements.size();
    const std::size_t whole = evidence.forWholeUnits.size();
    if (increments != whole) {
      out.calculatorInput = whole > increments;
      out.fromProgram = true;
      // Said when it matters: increments (a shop's habit) or a reading the machine would not give.
      if (whole < increments || out.calculatorInput != machineCalculatorInput)
        out.diagnostics.push_back(readingNote(
            whole > increments ? evidence.forWholeUnits.front() : evidence.forIncrements.front(), whole < increments));
    }
  }
  if (!out.calculatorInput) gcode::readLengthsInIncrements(program, powerOnUnits, dialect);
  for (Diagnostic& d : gcode::decimalPointWarnings(evidence, !out.calculatorInput))
    out.diagnostics.push_back(std::move(d));
  return out;
}

}  // namespace klueng::core::machine

// Which unit a program without G20/G21 speaks, from the sizes shops write (units_reading.h).
// Typical values, inch against mm (Sandvik and Haas turning data; a class's programs):
//   roughing depth of cut (G71/G72 U, Haas D): 0.02-0.25 in, 0.5-6 mm
//   roughing retract (G71/G72 R):               0.005-0.05 in, 0.2-2 mm
//   feed per revolution (G99):                  0.001-0.025 in, 0.05-0.6 mm
//   constant surface speed (G96 S):             300-1500 ft/min, 50-350 m/min
//   a length with four decimals (X1.2345):      inch only (0.0001 in; mm is 0.001)
//   a diameter over 40:                         mm only, on a school or shop lathe
#include "klueng/core/infer/units_reading.h"

#include <cmath>
#include <string>

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/gcode/code_table.h"

namespace klueng::core::machine {

namespace {

struct UnitsEvidence {
  int inch = 0;
  int mm = 0;
  const gcode::Word* firstInch = nullptr;  // the first word that spoke inch, for the note
  const gcode::Word* firstMm = nullptr;
  void add(const gcode::Word& w, bool isInch, int weight) {
    (isInch ? inch : mm) += weight;
    const gcode::Word*& first = isInch ? firstInch : firstMm;
    if (!first) first = &w;
  }
};

bool unitsPlainValue(const gcode::Word* w) { return w && w->expr < 0 && !w->comma; }

}  // namespace

std::optional<UnitsReading> readPowerOnUnits(const gcode::Program& program, gcode::Dialect dialect,
                                             gcode::InputUnits machinePowerOn) {
  UnitsEvidence e;
  bool perMinute = false;
  for (const gcode::Block& b : program.blocks) {
    if (b.statement().kind != gcode::StatementKind::None) continue;
    bool roughing = false, surfaceSpeed = false;
    for (const gcode::Word* g : b.all('G')) {
      if (g->expr >= 0 || g->hasDecimalPoint) continue;
      const gcode::CodeInfo* row = gcode::findCode('G', g->code(), dialect);
      if (!row) continue;
      switch (row->action) {
        case gcode::CodeAction::Inch:
        case gcode::CodeAction::Metric: return std::nullopt;  // the program says its units
        case gcode::CodeAction::TurnRoughing:
        case gcode::CodeAction::FaceRoughing: roughing = true; break;
        case gcode::CodeAction::ConstantSurface: surfaceSpeed = true; break;
        case gcode::CodeAction::FeedPerMinute: perMinute = true; break;
        default: break;
      }
    }
    if (roughing) {
      // The depth: the first block's U (two-block form, no P), or Haas's D.
      const gcode::Word* depth = b.has('P') ? b.find('D') : b.find('U');
      if (unitsPlainValue(depth) && depth->value > 0.0) {
        if (depth->value <= 0.3) e.add(*depth, true, 2);
        if (depth->value >= 0.5) e.add(*depth, false, 2);
      }
      const gcode::Word* retract = b.has('P') ? nullptr : b.find('R');
      if (unitsPlainValue(retract) && retract->value > 0.0) {
        if (retract->value < 0.1) e.add(*retract, true, 1);
        if (retract->value >= 0.2) e.add(*retract, false, 1);
      }
    }
    if (const gcode::Word* s = b.find('S'); surfaceSpeed && unitsPlainValue(s) && s->value > 0.0) {
      if (s->value >= 450.0) e.add(*s, true, 1);
      if (s->value <= 300.0) e.add(*s, false, 1);
    }
    if (const gcode::Word* f = b.find('F'); !perMinute && unitsPlainValue(f) && f->value > 0.0) {
      if (f->value <= 0.02) e.add(*f, true, 1);
      if (f->value >= 0.06 && f->value < 2.0) e.add(*f, false, 1);
    }
    for (const gcode::Word& w : b.words) {
      if (w.comma || w.expr >= 0 || (w.letter != 'X' && w.letter != 'Z' && w.letter != 'U' && w.letter != 'W'))
        continue;
      if (w.decimals >= 4) e.add(w, true, 2);
      if (w.letter == 'X' && std::abs(w.value) > 40.0) e.add(w, false, 2);
    }
  }
  const bool inch = e.inch >= 3 && e.mm == 0;
  const bool mm = e.mm >= 3 && e.inch == 0;
  const gcode::InputUnits units = inch ? gcode::InputUnits::Inch : gcode::InputUnits::Millimetre;
  if ((!inch && !mm) || units == machinePowerOn) return std::nullopt;
  const gcode::Word& why = *(inch ? e.firstInch : e.firstMm);
  UnitsReading r{units, {}};
  r.note.severity = Severity::Note;
  r.note.code = codes::kUnitsFromProgram;
  r.note.range = why.range;
  r.note.args = {inch ? "inch" : "mm", why.text()};
  return r;
}

}  // namespace klueng::core::machine

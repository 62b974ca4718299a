// Decimal point input (decimal_point.h).
#include "klueng/core/gcode/decimal_point.h"

#include <cmath>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "diagnostic_codes.h"
#include "klueng/core/gcode/code_table.h"

namespace klueng::core::gcode {

namespace {

constexpr std::string_view kLengthLetters = "XZUWIKR";

// No lathe a school or a job shop runs these programs on reaches 2 m from its zero.
constexpr double kFarthestPositionMm = 2000.0;
// A position 0.1 mm from zero is no position anyone writes without a point.
constexpr double kNearestPositionMm = 0.1;
// A cycle's depth of cut, retract or finishing allowance lies between these.
constexpr double kLargestCycleSettingMm = 25.0;
constexpr double kSmallestCycleSettingMm = 0.01;

bool isCode(const Word& w, char letter) { return w.letter == letter && w.expr < 0 && !w.hasDecimalPoint; }

// The row of a G word without a macro value or a decimal point, if the dialect has one.
const CodeInfo* gRow(const Word& w, Dialect dialect) {
  return isCode(w, 'G') ? findCode('G', w.code(), dialect) : nullptr;
}

std::optional<InputUnits> unitsOf(const Block& b, Dialect dialect) {
  std::optional<InputUnits> units;
  for (const Word* w : b.all('G'))
    if (const CodeInfo* row = gRow(*w, dialect)) {
      if (row->action == CodeAction::Inch) units = InputUnits::Inch;
      if (row->action == CodeAction::Metric) units = InputUnits::Millimetre;
    }
  return units;
}

// What a block's length words are: positions, a cycle's settings, or neither.
struct BlockKind {
  bool passedAsWritten = false;  // G65/G66 arguments
  bool dwell = false;            // G04: X is a time
  bool cycle = false;            // G70-G76: U W R I K are depths, retracts, allowances
  bool rIsCount = false;         // G73's first block: R is the number of passes
};

BlockKind kindOf(const Block& b, Dialect dialect) {
  BlockKind k;
  for (const Word* w : b.all('G')) {
    const CodeInfo* row = gRow(*w, dialect);
    if (!row) continue;
    switch (row->action) {
      case CodeAction::MacroCall:
      case CodeAction::MacroModalCall: k.passedAsWritten = true; break;
      case CodeAction::Dwell: k.dwell = true; break;
      case CodeAction::PatternRepeating:
        k.cycle = true;
        if (!b.has('P')) k.rIsCount = true;
        break;
      case CodeAction::Finishing:
      case CodeAction::TurnRoughing:
      case CodeAction::FaceRoughing:
      case CodeAction::FacePecking:
      case CodeAction::Grooving:
      case CodeAction::ThreadCutting: k.cycle = true; break;
      default: break;
    }
  }
  return k;
}

// The length words of the block that a decimal point setting reads differently.
template <typename F>
void forEachPointlessLength(const Block& b, const BlockKind& kind, F&& f) {
  if (kind.passedAsWritten || b.statement().kind != StatementKind::None) return;
  for (std::size_t i = 0; i < b.words.size(); ++i) {
    const Word& w = b.words[i];
    if (w.hasDecimalPoint || w.expr >= 0 || w.comma || kLengthLetters.find(w.letter) == std::string_view::npos)
      continue;
    if (w.letter == 'R' && kind.rIsCount) continue;
    f(i, w);
  }
}

double incrementOf(InputUnits units) { return units == InputUnits::Inch ? 0.0001 : 0.001; }
double mmPer(InputUnits units) { return units == InputUnits::Inch ? 25.4 : 1.0; }

}  // namespace

std::string clueLengthText(const PointClue& clue, bool increments) {
  const char* unit = clue.inch ? "in" : "mm";
  const double perUnit = clue.inch ? 25.4 : 1.0;
  if (increments) return fmt::format("{:.{}f} {}", clue.incrementMm / perUnit, clue.inch ? 4 : 3, unit);
  return fmt::format("{:g} {}", clue.wholeMm / perUnit, unit);
}

InputUnits programInputUnits(const Program& program, InputUnits powerOnUnits, Dialect dialect) {
  InputUnits units = powerOnUnits;
  for (const Block& b : program.blocks)
    if (b.file == 0 && b.mayHave('G'))
      if (const auto u = unitsOf(b, dialect)) units = *u;
  return units;
}

PointEvidence weighDecimalPoints(const Program& program, InputUnits powerOnUnits, Dialect dialect) {
  PointEvidence out;
  InputUnits units = powerOnUnits;
  for (const Block& b : program.blocks) {
    if (auto u = unitsOf(b, dialect)) units = *u;
    const BlockKind kind = kindOf(b, dialect);
    if (kind.dwell) continue;
    forEachPointlessLength(b, kind, [&](std::size_t, const Word& w) {
      if (w.value == 0.0) return;  // zero reads the same both ways
      const bool position = w.letter == 'X' || w.letter == 'Z' || !kind.cycle;
      // Incremental moves and arc centres outside the cycles are as often small as large: no clue.
      if (position && w.letter != 'X' && w.letter != 'Z') return;
      PointClue clue{w.range, w.text(), units == InputUnits::Inch, std::abs(w.value) * mmPer(units),
                     std::abs(w.value) * incrementOf(units) * mmPer(units)};
      const bool wholeFits = clue.wholeMm <= (position ? kFarthestPositionMm : kLargestCycleSettingMm);
      const bool incrementsFit = clue.incrementMm >= (position ? kNearestPositionMm : kSmallestCycleSettingMm);
      if (wholeFits && !incrementsFit)
        out.forWholeUnits.push_back(std::move(clue));
      else if (!wholeFits && incrementsFit)
        out.forIncrements.push_back(std::move(clue));
    });
  }
  return out;
}

void readLengthsInIncrements(Program& program, InputUnits powerOnUnits, Dialect dialect) {
  InputUnits units = powerOnUnits;
  for (Block& b : program.blocks) {
    if (auto u = unitsOf(b, dialect)) units = *u;
    const BlockKind kind = kindOf(b, dialect);
    std::vector<std::size_t> pointless;
    forEachPointlessLength(b, kind, [&](std::size_t i, const Word&) { pointless.push_back(i); });
    // A dwell's X (or U) is a time: 0.001 s in mm and inch alike (Fanuc 0i-TF, G04 dwell: IS-B).
    for (std::size_t i : pointless)
      b.words[i].value *=
          kind.dwell && (b.words[i].letter == 'X' || b.words[i].letter == 'U') ? 0.001 : incrementOf(units);
  }
}

std::vector<Diagnostic> decimalPointWarnings(const PointEvidence& evidence, bool inIncrements) {
  std::vector<Diagnostic> out;
  for (const PointClue& c : inIncrements ? evidence.forWholeUnits : evidence.forIncrements) {
    Diagnostic d;
    d.severity = Severity::Warning;
    d.range = c.range;
    const double unit = c.inch ? 25.4 : 1.0;
    const std::string asIncrements = clueLengthText(c, true);
    const std::string asWhole = clueLengthText(c, false);
    if (inIncrements) {
      d.code = codes::kPointlessLengthInIncrements;
      d.args = {c.word, asIncrements, c.word + ".", asWhole};
    } else {
      d.code = codes::kPointlessLengthWhole;
      const double sign = c.word.find('-') != std::string::npos ? -1.0 : 1.0;
      std::string meant = c.word.substr(0, 1) + fmt::format("{:.{}f}", sign * c.incrementMm / unit, c.inch ? 4 : 3);
      d.args = {c.word, asWhole, asIncrements, std::move(meant)};
    }
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace klueng::core::gcode

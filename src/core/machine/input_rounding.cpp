// Rounding axis words to the least input increment (see input_rounding.h).
#include "machine/input_rounding.h"

#include <cmath>
#include <string_view>

#include "klueng/core/gcode/code_table.h"

namespace klueng::core::machine {

namespace {

constexpr std::string_view kRoundedLetters = "XZUWIKR";

// The inch/metric code of a block, if it has one, by its action (G70/G71 in G-code system C).
std::optional<gcode::InputUnits> roundingUnitsOf(const gcode::Block& b, gcode::Dialect dialect) {
  std::optional<gcode::InputUnits> units;
  for (const gcode::Word& w : b.words) {
    if (w.letter != 'G' || w.hasDecimalPoint || w.expr >= 0) continue;
    const gcode::CodeInfo* row = gcode::findCode('G', w.code(), dialect);
    if (row && row->action == gcode::CodeAction::Inch) units = gcode::InputUnits::Inch;
    if (row && row->action == gcode::CodeAction::Metric) units = gcode::InputUnits::Millimetre;
  }
  return units;
}

}  // namespace

double roundToDecimals(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(value * scale) / scale;  // std::round: half away from zero
}

std::optional<gcode::Program> roundToIncrements(const gcode::Program& program, const gcode::MachineProfile& profile,
                                                gcode::InputUnits powerOnUnits) {
  if (profile.extraDecimals != gcode::ExtraDecimals::RoundWithWarning) return std::nullopt;
  std::optional<gcode::Program> out;
  gcode::InputUnits units = powerOnUnits;
  for (std::size_t i = 0; i < program.blocks.size(); ++i) {
    const gcode::Block& b = program.blocks[i];
    if (auto u = roundingUnitsOf(b, profile.dialect)) units = *u;  // units apply to their whole block
    const int decimals = units == gcode::InputUnits::Inch ? profile.decimalsInch : profile.decimalsMm;
    for (std::size_t j = 0; j < b.words.size(); ++j) {
      const gcode::Word& w = b.words[j];
      if (w.decimals <= decimals || kRoundedLetters.find(w.letter) == std::string_view::npos) continue;
      if (!out) out = program;
      out->blocks[i].words[j].value = roundToDecimals(w.value, decimals);
    }
  }
  return out;
}

}  // namespace klueng::core::machine

// Rounding axis words to the least input increment (see input_rounding.h).
#include "machine/input_rounding.h"

#include <cmath>
#include <string_view>

namespace klueng::core::machine {

namespace {

constexpr std::string_view kRoundedLetters = "XZUWIKR";

// G20/G21 of a block, if it has one.
std::optional<gcode::InputUnits> unitsOf(const gcode::Block& b) {
  std::optional<gcode::InputUnits> units;
  for (const gcode::Word& w : b.words)
    if (w.letter == 'G' && !w.hasDecimalPoint && (w.code() == 20 || w.code() == 21))
      units = w.code() == 20 ? gcode::InputUnits::Inch : gcode::InputUnits::Millimetre;
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
    if (auto u = unitsOf(b)) units = *u;  // units apply to their whole block
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

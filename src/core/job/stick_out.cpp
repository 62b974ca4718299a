#include "stick_out.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/stock.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/geometry.h"

namespace klueng::core::job {

namespace {

constexpr double kJawClearanceMm = 2.0;         // air left between the tool and the jaws' face
constexpr double kLongestLengtheningMm = 60.0;  // beyond this the program means its own bar

std::string lengthText(double v) {
  std::ostringstream s;
  s << std::round(v * 1000.0) / 1000.0;
  return s.str();
}

}  // namespace

std::optional<Diagnostic> lengthenForTools(io::JobHeader& h, const machine::Timeline& run,
                                           const machine::MachineSetup& setup) {
  if (h.stockSource != io::StockSource::Inferred || run.moveCount() == 0) return std::nullopt;
  const cut::Chuck jaws{};  // the jaws' radial size above the bar
  const double grip = std::clamp(setup.machine.chuckGrip, 0.0, h.lengthMm());
  const double stickOut = h.lengthMm() - grip;
  const double jawTop = h.diameterMm() / 2.0 + jaws.jawHeight;
  cut::ToolLibrary shapes(setup.tools, setup.offsets);
  double reach = 0.0;                          // the deepest Z any part of a tool comes to (<= 0)
  std::optional<machine::RecordMove> deepest;  // what the note names of the deepest move
  run.forEachMove([&](const auto& m) {
    if (m.tool < 1) return;
    const double low = std::min(xOf(m.path.start), xOf(m.path.end));
    if (m.kind == machine::MoveKind::Rapid && low > jawTop) return;
    const double z = std::min(zOf(m.path.start), zOf(m.path.end));
    const cut::ToolShape* shape = shapes.get(m.tool, m.offset);
    if (!shape || low + shape->bounds.x0 > jawTop) return;
    if (z + shape->bounds.z0 < reach - 1e-9) {
      reach = z + shape->bounds.z0;
      deepest = machine::RecordMove{
          m.path, m.line, m.blockIndex, m.file, static_cast<std::int16_t>(m.tool), static_cast<std::int16_t>(m.offset),
          m.kind};
    }
  });
  const double needed = -reach + kJawClearanceMm;
  if (!deepest || needed <= stickOut + 1e-9 || needed - stickOut > kLongestLengtheningMm) return std::nullopt;
  const bool inch = h.lengthUnit == io::LengthUnit::Inch;
  const double unit = inch ? 25.4 : 1.0;
  const double step = inch ? 0.25 : 5.0;
  const double before = h.length;
  h.length = std::ceil((needed + grip) / unit / step - 1e-9) * step;
  Diagnostic note;
  note.severity = Severity::Note;
  note.code = codes::kStockLengthForTools;
  note.range = SourceRange{deepest->line, 1, 0};
  note.range.file = deepest->file;
  note.args = {lengthText(h.length), lengthText(before),
               (deepest->tool < 10 ? "0" : "") + std::to_string(deepest->tool), lengthText(-reach / unit)};
  return note;
}

}  // namespace klueng::core::job

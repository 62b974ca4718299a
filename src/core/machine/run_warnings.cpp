#include "run_warnings.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/word_format.h"
#include "gcode/diagnostic_codes.h"  // the walk's own codes: these are its warnings

namespace klueng::core::machine::detail {

namespace {

bool alreadyFound(const std::vector<Diagnostic>& found, const std::vector<Diagnostic>& added, const char* code,
                  int line) {
  const auto same = [&](const Diagnostic& d) { return d.code == code && d.range.file == 0 && d.range.line == line; };
  return std::any_of(found.begin(), found.end(), same) || std::any_of(added.begin(), added.end(), same);
}

Diagnostic warning(const char* code, const SourceRange& at, std::vector<std::string> args) {
  return Diagnostic{Severity::Warning, code, at, std::move(args)};
}

// The word of a program-file block at a source position (the alarm's range).
const gcode::Word* wordAt(const gcode::Program& program, const SourceRange& at) {
  for (const gcode::Block& b : program.blocks) {
    if (b.file != 0 || b.line != at.line) continue;
    for (const gcode::Word& w : b.words)
      if (w.range.column == at.column) return &w;
  }
  return nullptr;
}

}  // namespace

std::vector<Diagnostic> modalWarningsFromRun(const gcode::Program& program, const Timeline& record,
                                             const std::vector<Diagnostic>& found) {
  std::vector<Diagnostic> out;
  // W105: a G96 block run with no spindle limit in force, before the first alarm.
  for (std::size_t k = 0; k < record.blockCount(); ++k) {
    const BlockMark s = record.blockMark(k);
    if (record.alarm && s.line >= record.alarm->range.line && s.file == record.alarm->range.file) break;
    if (s.file != 0 || s.blockIndex < 0 || static_cast<std::size_t>(s.blockIndex) >= program.blocks.size()) continue;
    if (s.spindleMode != SpindleMode::ConstantSurface || s.rpmClamped) continue;
    const gcode::Block& b = program.blocks[static_cast<std::size_t>(s.blockIndex)];
    const gcode::Word* g96 = nullptr;
    for (const gcode::Word* g : b.all('G'))
      if (!g->hasDecimalPoint && g->expr < 0)
        if (const gcode::CodeInfo* row = gcode::findCode('G', g->code(), gcode::Dialect::Fanuc);
            row && row->action == gcode::CodeAction::ConstantSurface)
          g96 = g;
    if (!g96) continue;
    if (!alreadyFound(found, out, gcode::codes::kConstantSurfaceWithoutClamp, b.line))
      out.push_back(warning(gcode::codes::kConstantSurfaceWithoutClamp, g96->range, {}));
    break;  // one, as the walk gives one
  }
  // W104 / W106: the run's first alarm, when it is one of the walk's.
  if (record.alarm && record.alarm->range.file == 0) {
    const Diagnostic& a = *record.alarm;
    if (a.code == std::string(codes::kNoFeed) && !a.args.empty() &&
        !alreadyFound(found, out, gcode::codes::kFeedMoveWithoutFeed, a.range.line)) {
      out.push_back(warning(gcode::codes::kFeedMoveWithoutFeed, a.range, {a.args.front()}));
    } else if (a.code == std::string(codes::kArcRadiusTooSmall) &&
               !alreadyFound(found, out, gcode::codes::kArcRadiusCannotJoin, a.range.line)) {
      const gcode::Word* r = wordAt(program, a.range);
      const double halfMm = a.args.size() > 1 ? std::atof(a.args[1].c_str()) : 0.0;
      // The half chord in the block's own units, as the walk writes it.
      std::optional<BlockMark> before;
      if (record.blockCount() > 0) before = record.blockMark(record.blockCount() - 1);
      for (std::size_t k = 0; k < record.blockCount(); ++k)
        if (const BlockMark s = record.blockMark(k); s.file == 0 && s.line < a.range.line) before = s;
      const bool inch = before && before->units == Units::Inch;
      if (r)
        out.push_back(warning(gcode::codes::kArcRadiusCannotJoin, a.range,
                              {r->text(), gcode::formatFixed(inch ? halfMm / 25.4 : halfMm, 3)}));
    }
  }
  return out;
}

}  // namespace klueng::core::machine::detail

#pragma once
// The grammar checker (SPEC 4-5, 13 and the "ext" rules that need no
// positions: arc radius mismatch is the interpreter's). Units (G20/G21) and
// the motion group are tracked left to right. Returns every diagnostic of the
// whole program, sorted by line and column; a hostile input's report stops at
// 10,000 entries with a final E199. Codes: src/core/gcode/diagnostic_codes.h.
#include <optional>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/program.h"

namespace klueng::core::gcode {

struct CheckOptions {
  Dialect dialect = Dialect::Fanuc;
  // Turret stations of the machine (machine.cfg turret_stations), where the
  // profile takes the T range from the machine.
  int turretStations = 12;
  // Units before any G20/G21 (CLI --units, the GUI setting); nullopt = the
  // profile's power-on units (inch on a US Haas).
  std::optional<InputUnits> powerOnUnits;
  // Tools 1..8 that have a bitmap in tools.cfg; empty = do not check (no table loaded).
  std::optional<std::vector<int>> toolsWithBitmap;
  // Stop at the first error (a yes/no question: does this dialect accept the program?).
  bool stopAtFirstError = false;
  // Also follow the modal state and warn of the run-time alarms it shows (a feed
  // move with no F, G96 with no G50 S, an arc R too small: W104-W106). The
  // editor's check while typing asks for them (issue 11); the grammar alone does not.
  bool modalRules = false;
};

// Includes program.lexicalDiagnostics.
std::vector<Diagnostic> check(const Program& program, const CheckOptions& options = {});

// Only the tool rule of check(): E305 for each well-formed T word whose station
// is not in options.toolsWithBitmap (nothing when that is unset). check() with
// toolsWithBitmap unset plus this gives what check() with it gives, so the
// tool table can be worked out while the rest of the check runs.
std::vector<Diagnostic> checkToolBitmaps(const Program& program, const CheckOptions& options);

}  // namespace klueng::core::gcode

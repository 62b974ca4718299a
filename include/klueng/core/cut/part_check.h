#pragma once
// Part check (issue 10 item 2, issue 28 item 1): the real cut against the part
// the program describes, two ways:
// - the ideal tool on the controlled path — the nose circle with the tool's
//   front edges (a grooving blade's width, a boring bar's end) but none of its
//   trailing edges; threading passes and drilling on the axis keep the whole
//   tool — finds what the tool's own shape does (an 80° insert's trailing edge
//   running down into a neck);
// - the PROGRAMMED path (G41/G42 read but not applied: the contour where
//   compensation is on, the imaginary tip's path where it is off) finds what
//   the offset row and the compensation do: a real cut below the path of the
//   very move that made it (a wrong tip number puts the tool's edge elsewhere:
//   a thread 7 mm too deep) is a gouge; material left above the programmed
//   contour is a leftover (a chamfer cut without G41/G42 by a R0.8 nose), except
//   what no round nose of the tool's radius can reach (the fillet in a concave
//   corner is the tool's, as on every real part).
// Material removed inside the described part is a GOUGE, material left outside
// it beyond a tolerance a LEFTOVER, each with its depth, extent and block.
//
//   const Timeline programmed = programmedPath(program, setup, options, run);
//   const PartCheck check = checkPart(run, programmed, CutSetup::from(header, setup));
//   for (const Diagnostic& d : partCheckDiagnostics(check)) ...   // W320 / W321 / I322 / I323
#include <optional>
#include <vector>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/units.h"

namespace klueng::core::cut {

enum class DefectKind { Gouge, Leftover };

struct PartDefect {
  DefectKind kind = DefectKind::Gouge;
  FeatureSide side = FeatureSide::Outside;
  double zLeft = 0.0;  // extent along Z (column edges)
  double zRight = 0.0;
  double depth = 0.0;     // mm, radial: the largest along the extent
  double z = 0.0;         // where it is largest
  double diameter = 0.0;  // the described part's Ø there
  int line = 0;           // the block that caused it: the real cut that removed the
  int file = 0;           // material (gouge), the ideal cut that should have (leftover)
};

struct PartCheckOptions {
  double resolution = kDefaultResolution;  // stock column width, mm
  double gougeTolerance = 0.005;           // mm radial: less is the two cuts' rounding
  double leftoverTolerance = 0.01;         // mm radial: material allowed to stay
};

struct PartCheck {
  std::vector<PartDefect> defects;      // sorted by Z, right to left
  std::optional<Diagnostic> stoppedBy;  // the alarm the run stopped on: what was cut up to it is checked
  bool nothingCut = false;              // no move cut the stock (no moves, only rapids, empty stock)
  Stock cut;                            // the real cut (up to the alarm): the finished part
  double largestGouge() const;          // mm, 0 when none
  double largestLeftover() const;
};

// The programmed path of `run`: the same program run with G41/G42 read but not
// applied (#500-#999 neither read from nor written to a file); `run` itself
// when none of its moves was compensated.
machine::Timeline programmedPath(const gcode::Program& program, const machine::MachineSetup& setup,
                                 machine::RunOptions options, const machine::Timeline& run);

// `run`: the program as the machine runs it; `programmed`: programmedPath() of it.
PartCheck checkPart(const machine::Timeline& run, const machine::Timeline& programmed, const CutSetup& setup,
                    const PartCheckOptions& options = {});

// The same with ready tool shapes (tests): `tools` must give every (tool, offset) the timeline uses.
PartCheck checkPart(const machine::Timeline& run, const machine::Timeline& programmed, const CutSetup& setup,
                    const ToolLibrary& tools, const PartCheckOptions& options = {});

// W320 per gouge and W321 per leftover at their block's line; I322 when the run
// stopped on an alarm, I323 when nothing was cut. Depths, Z and Ø in `units`
// (a G20 program's check speaks inches: issue 28 item 4).
std::vector<Diagnostic> partCheckDiagnostics(const PartCheck& check, const UnitFormat& units = UnitFormat{});

// The tool the described part is cut with (see above): the nose circle, a body
// of the nose's width behind it (away from the part: a real insert removes all
// there), and the cutting edge within `strip` mm of the tool's front in the
// tip's directions.
ToolShape idealToolShape(const ToolShape& real, double strip = 0.02);

}  // namespace klueng::core::cut

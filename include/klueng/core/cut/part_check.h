#pragma once
// Part check (issue 10, item 2): the part the program describes is what the
// ideal tool cuts — the nose circle on the controlled path (G41/G42 applied),
// with the tool's front edges (a grooving blade's width, a boring bar's end)
// but none of its trailing edges; threading passes and drilling on the axis
// keep the whole tool, their form is the tool's. Compared with the real cut by
// the tool shapes: material the real tool removed inside the described part is
// a GOUGE (an 80° insert's trailing edge running down into a neck), material
// it left outside beyond a tolerance is a LEFTOVER. Each is reported with its
// depth, extent and the block that caused it.
//
//   const PartCheck check = checkPart(timeline, CutSetup::from(header, setup));
//   for (const Diagnostic& d : partCheckDiagnostics(check)) ...   // W320 / W321 / I322 / I323
#include <optional>
#include <vector>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/units.h"

namespace klueng::core::cut {

enum class DefectKind { Gouge, Leftover };

struct PartDefect {
  DefectKind kind = DefectKind::Gouge;
  FeatureSide side = FeatureSide::Outside;
  double zLeft = 0.0;    // extent along Z (column edges)
  double zRight = 0.0;
  double depth = 0.0;    // mm, radial: the largest along the extent
  double z = 0.0;        // where it is largest
  double diameter = 0.0; // the described part's Ø there
  int line = 0;          // the block that caused it: the real cut that removed the
  int file = 0;          // material (gouge), the ideal cut that should have (leftover)
};

struct PartCheckOptions {
  double resolution = kDefaultResolution;  // stock column width, mm
  double gougeTolerance = 0.005;           // mm radial: less is the two cuts' rounding
  double leftoverTolerance = 0.01;         // mm radial: material allowed to stay
};

struct PartCheck {
  std::vector<PartDefect> defects;          // sorted by Z, right to left
  std::optional<Diagnostic> stoppedBy;      // the alarm the run stopped on: what was cut up to it is checked
  bool nothingCut = false;                  // no move cut the stock (no moves, only rapids, empty stock)
  Stock cut;                                // the real cut (up to the alarm): the finished part
  double largestGouge() const;              // mm, 0 when none
  double largestLeftover() const;
};

PartCheck checkPart(const machine::Timeline& timeline, const CutSetup& setup, const PartCheckOptions& options = {});

// The same with ready tool shapes (tests): `tools` must give every (tool, offset) the timeline uses.
PartCheck checkPart(const machine::Timeline& timeline, const CutSetup& setup, const ToolLibrary& tools,
                    const PartCheckOptions& options = {});

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

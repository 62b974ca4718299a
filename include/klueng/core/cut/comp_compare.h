#pragma once
// What nose radius compensation changes (issue 10, item 3): the same program
// cut with its G41/G42 and without them (the imaginary tip on the programmed
// path, as under G40), or with a sharp nose (R 0, the programmed contour
// itself). Where the two parts differ is measured square to the surface and
// put on the block that cut it: "chamfer N350: 0.33 mm short without
// compensation".
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/units.h"

namespace klueng::core::cut {

enum class CompareWith {
  NoCompensation,  // G41/G42 ignored: the imaginary tip follows the program
  SharpNose,       // every nose radius 0 (and so no compensation to make)
};

struct CompDifference {
  double zLeft = 0.0;  // extent along Z (column edges)
  double zRight = 0.0;
  double normal = 0.0;    // mm, the largest gap square to the compensated surface (+ material left, - cut away)
  double radial = 0.0;    // mm on the radius at the same place
  double z = 0.0;         // where it is largest
  double diameter = 0.0;  // the compensated part's Ø there
  FeatureKind feature = FeatureKind::Cylinder;  // of the compensated part there
  std::string label;                            // its drawing label ("C3", "R2", "Ø30")
  int line = 0;                                 // the block that cut that surface in the compensated run
  int file = 0;
  int blockIndex = -1;  // into the program's blocks
};

struct CompComparison {
  std::optional<Stock> compensated;         // the program as written
  std::optional<Stock> other;               // without compensation / with a sharp nose
  std::vector<CompDifference> differences;  // largest first
  bool usesCompensation = false;            // the program has G41/G42 moves at all
  std::optional<Diagnostic> alarm;          // one of the runs stopped on it: the parts are cut up to it
};

// `minimum`: gaps smaller than this (mm, square to the surface) are the same surface.
CompComparison compareCompensation(const gcode::Program& program, const machine::MachineSetup& setup,
                                   const machine::RunOptions& run, const CutSetup& cut, CompareWith with,
                                   double minimum = 0.01);

// "chamfer N350: 0.33 mm short without compensation" / in Thai; `program`
// gives the block's N number (else "line 41").
// `units`: the amount in mm (0.33 mm) or, for an inch program, in inches (0.0130 in).
std::string describeDifference(const CompDifference& d, const gcode::Program& program, CompareWith with, Lang lang,
                               const UnitFormat& units = {});

}  // namespace klueng::core::cut

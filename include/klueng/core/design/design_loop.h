#pragma once
// Closing the loop (issue 14, item 4): a part design's program generated,
// checked, run and cut with the machine's tools, then the cut part read back
// as features and held against the drawing — every diameter, chamfer, round,
// arc, taper, groove, thread and bore of the design within 0.01 mm — and
// part-checked (no gouge, nothing left beyond 0.01 mm).
//
//   const DesignLoop loop = runDesignLoop(design, options, setup);
//   loop.matches()  // "the cut part matches the drawing within 0.01 mm"
//   loop.findings   // or where it does not (W530, and the part check's W320-W323)
#include <memory>
#include <optional>
#include <vector>

#include "klueng/core/cut/part_features.h"
#include "klueng/core/cut/stock.h"
#include "klueng/core/design/part_design.h"
#include "klueng/core/machine/setup_files.h"

namespace klueng::core::design {

inline constexpr double kDrawingTolerance = 0.01;  // mm on diameters and radii

struct DesignLoop {
  std::optional<GeneratedProgram> program;
  std::vector<Diagnostic> refused;   // why the generator wrote nothing (E5xx)
  std::vector<Diagnostic> problems;  // the program's errors and the run's alarm (should never happen)
  std::unique_ptr<cut::Stock> cut;   // the part as cut (null when nothing ran)
  cut::PartFeatures features;        // of the cut part
  std::vector<Diagnostic> findings;  // W530 per drawing feature not on the cut part; gouges and leftovers
  bool matches() const { return program && problems.empty() && findings.empty() && cut; }
};

DesignLoop runDesignLoop(const PartDesign& part, const GenerateOptions& options, const machine::MachineSetup& setup);

// The drawing's features missing from (or not within 0.01 mm on) the cut part's features: W530 each.
std::vector<Diagnostic> compareToDrawing(const PartDesign& part, const cut::PartFeatures& cut);

}  // namespace klueng::core::design

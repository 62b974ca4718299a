#pragma once
// The cut part of `klueng-cli simulate`: runs the CutSimulator over the
// timeline and writes --png (section view), --profile (CSV z,x_outer,x_inner
// in diameters), --svg / --dxf (profile drawing), --json (summary); --resolution sets
// the stock's Z column width.
#include <optional>
#include <string>

#include "klueng/core/diagnostic.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/messages.h"
#include "klueng/core/units.h"

namespace klueng::cli {

struct CutOutputOptions {
  std::string pngPath;
  std::string profilePath;
  std::string jsonPath;
  std::string svgPath;     // the finished part's profile, both halves
  std::string dxfPath;     // the same as DXF (R12 LINE entities)
  bool features = false;   // --features: the finished part's features on stdout
  core::UnitFormat units;  // the unit the features are written in
  core::Lang lang = core::Lang::En;
  double resolution = 0.05;  // mm
  bool enabled = true;       // false with --no-stock: the timeline alone
};

// Parses a --resolution value: a number in [0.001, 5] mm.
bool parseResolution(const std::string& text, double& out);

struct CutOutcome {
  std::optional<core::Diagnostic> alarm;             // the cut alarm (A3xx) that stopped the run
  std::vector<core::Diagnostic> toolErrors;          // bitmaps that could not be loaded
  std::vector<core::Diagnostic> warnings;            // a guessed tool's holder touching (W324/W325)
  std::vector<core::Diagnostic> guessNotes;          // a guessed tool replaced by another that fits (I413/I414)
  std::optional<core::machine::MachineSetup> setup;  // the tools the cut used (set when it ran)
  bool written = true;                               // false: an output file could not be written (message printed)
};

// Cuts, then writes the requested outputs. `file` only names the program in the JSON.
CutOutcome runCut(const std::string& file, const core::io::JobHeader& header, const core::machine::MachineSetup& setup,
                  const core::machine::Timeline& timeline, const CutOutputOptions& options);

}  // namespace klueng::cli

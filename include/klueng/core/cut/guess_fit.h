#pragma once
// A guess never stops a run the real tool would not (issue 26; docs/tools.md).
//
// A plain program's tools are guessed from its evidence (machine/tool_inference.h,
// io::ToolTable::guessed). When a guessed tool touches the stock or the chuck
// (W324/W325/W326, or an A301/A303/A304 of its edge or holder), the library's
// other tools of that kind are tried in its place, one station at a time, each
// with a whole run of the cut, and the first that runs clean for that station
// is kept (note I413/I414). When none does, the first guess stays and its
// warning says what the real tool needs. Tools the user chose (--tool, Tool
// Select) and a job header's tools are not guesses: they are never replaced.
//
//   GuessFit fit = fitGuessedTools(timeline, header, setup, io::shippedToolLibrary());
//   fit.setup  -> the tools the run used;  fit.notes -> I413/I414;  fit.cut -> that run, cut to its end
//
// A replacement has the same nose radius and tip as the offset rows its station
// uses, so the timeline (recorded with the first guess's rows) stays the path.
// No Qt; pure function of its inputs.
#include <memory>
#include <vector>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/timeline.h"

namespace klueng::core::cut {

// At most this many other tools are tried for one station.
constexpr int kMaxGuessCandidates = 3;

struct GuessFit {
  machine::MachineSetup setup;        // the setup the run used (replacements still marked guessed)
  std::vector<Diagnostic> notes;      // I413/I414, one per replaced station, in the order they were found
  std::unique_ptr<CutSimulator> cut;  // the run with `setup`, cut to its end or its alarm
  int runs = 0;                       // whole cuts made (1 when nothing was tried)
};

// `timeline` must outlive the result (its cut points to it).
GuessFit fitGuessedTools(const machine::Timeline& timeline, const io::JobHeader& header,
                         const machine::MachineSetup& setup, const io::ToolLibrary& library,
                         const CutOptions& options = {});

// The library tools tried in place of station's guess (a library tool, or a table bitmap whose
// name says its kind), best first (at most
// kMaxGuessCandidates): the same kind (grooving and parting blades of the same
// width count as one), drills of the same size, the nose of every offset row
// the station uses in the timeline.
std::vector<const io::LibraryTool*> guessCandidates(const machine::Timeline& timeline,
                                                    const machine::MachineSetup& setup, int station,
                                                    const io::ToolLibrary& library);

}  // namespace klueng::core::cut

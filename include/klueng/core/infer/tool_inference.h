#pragma once
// Tools from the program (issue 8 item 8; docs/tools.md). Real programs name
// their tools in comments ("OD ROUGH", "CUT OFF", "เกลียว" ...) on the T block
// or the comment lines around it, and use them in telling cycles (G76/G92/G32
// threading, G75 grooving, drilling on the centre line, internal G71, a
// plunge to X0 at the end = parting). For every station the program selects,
// inferTools decides a library tool from that evidence:
//   - a station set up for this job (an override) always gets its override;
//   - a station whose tools.cfg tool already fits the work keeps it (so the
//     shipped samples run exactly as before);
//   - a station with no tool gets the library choice, as does one whose tool
//     is clearly the wrong kind for strong evidence (a comment or a cycle);
//   - the offset rows such a station uses that are 0 0 0 0 get the library
//     tool's nose radius and tip.
// No Qt; pure function of its inputs.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/messages.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/machine/interpreter.h"

namespace klueng::core::machine {

// Why a tool was chosen; the note codes I401..I409 in that order.
enum class ToolReason {
  Comment,          // I401 the T block's comment or the comment lines before it
  Threading,        // I402 G76 / G92 / G32
  ThreadingInside,  // I403 the same, cutting outward from inside a bore
  Grooving,         // I404 G75 (or G74 off the centre line)
  Drilling,         // I405 G74 / G81..G83 / G01 along Z on X0
  Boring,           // I406 G71/G72/G73 with negative U, inside a bore
  Parting,          // I407 a plunge to X0 or below at one of the last tools
  Turning,          // I408 any other cutting (weak: only fills a station without a tool)
  Override,         // I409 set for this job (--tool, Tool Select)
};

struct StationOverride {
  int station = 0;  // 1..kMaxStations
  std::string libraryId;
};

struct ToolChoice {
  int station = 0;
  std::string libraryId;
  ToolReason reason = ToolReason::Turning;
  std::string detail;  // the comment text, or the code seen ("G76", "X0.")
  int line = 0;        // file line of the evidence; 0 for an override
  // The note in the catalog: code I401..I409, args {station "03", id, detail, line}.
  Diagnostic note() const;
};

struct ToolInference {
  MachineSetup setup;        // the input setup, amended (setup.tools.guessed marks the guesses)
  bool fromProgram = false;  // a plain program: its evidence decided every station
  // The recorded run (machine::recordRun) all evidence but the comments came
  // from; the stock is read from the same run.
  std::shared_ptr<const Timeline> record;
  std::vector<ToolChoice> choices;      // one per station that got a library tool, by station
  std::vector<Diagnostic> offsetNotes;  // I410 per offset row filled from a library tool
  // Every note, choices first: what the CLI prints and the GUI lists.
  std::vector<Diagnostic> notes() const;
  const ToolChoice* choiceFor(int station) const;
};

// How the program is read. A plain program (no job header: a file from the shop)
// gets every station's tool from its own evidence, the shipped table only
// breaking ties; the evidence of motion comes from one recorded run.
struct InferenceContext {
  bool fromProgram = false;
  RunOptions run;  // dialect and power-on units of the recorded run
  // The tool side the user chose for this file (io::JobHeader::toolsBeyondCentre):
  // it wins over what the run shows (no I412 note then).
  std::optional<bool> toolsBeyondCentre;
};

// gcodeText is the G-code part of the file (the text parse() read, its first
// line being file line gcodeFirstLine); comment-only lines are read from it.
// stations: the highest station T may name (the turret, or the dialect's
// limit, e.g. 8 in classic); 0 = setup.tools.stations. Stations beyond it are
// left alone (the checker reports them).
ToolInference inferTools(const gcode::Program& program, std::string_view gcodeText, int gcodeFirstLine,
                         const MachineSetup& setup, const io::ToolLibrary& library,
                         const std::vector<StationOverride>& overrides = {}, int stations = 0,
                         const InferenceContext& context = {});

// The recorded run made with (recordedWith, recorded) is the very run interpret(program,
// setup, run) makes, move by move (issue 29 item 14: the program is then interpreted once):
// no alarm, no stand-in feed or speed, no nose compensation asked for (or a run without it),
// the same dialect, units and switches, the same offsets and machine (a guessed tool may
// bring its own nose). #500-#999 are the caller's to weigh: a record starts them vacant.
bool recordIsTheRun(const Timeline& record, const MachineSetup& recordedWith, const RunOptions& recorded,
                    const MachineSetup& setup, const RunOptions& run);

// `N=ID` (the CLI's --tool value): station 1..stations and a library id.
// Returns false and fills error with a message in `lang` when it is not.
bool parseStationOverride(std::string_view text, int stations, const io::ToolLibrary& library, StationOverride& out,
                          std::string& error, Lang lang = Lang::En);

}  // namespace klueng::core::machine

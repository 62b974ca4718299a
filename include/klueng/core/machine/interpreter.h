#pragma once
// Runs a checked Program into a Timeline (SPEC 6-10).
#include <cstddef>
#include <map>
#include <optional>

#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/sink.h"
#include "klueng/core/machine/timeline.h"

namespace klueng::core::machine {

struct RunOptions {
  gcode::Dialect dialect = gcode::Dialect::Fanuc;
  bool optionalStop = false;  // M01 stops when on
  bool blockSkip = false;     // '/' blocks skipped when on
  bool stopAtM00 = false;     // false: a headless run records the stop and continues
  // Units before any G20/G21 (CLI --units, the GUI setting); nullopt = the dialect's.
  std::optional<gcode::InputUnits> powerOnUnits;
  // Custom macro B: the persistent common variables #500-#999 (io/macro_variables.h
  // keeps them in a file beside the program). The run reads them and writes
  // its assignments back; nullptr = they start vacant and are not kept.
  std::map<int, double>* persistentVariables = nullptr;
  // false: G41/G42 are read, but the imaginary tip follows the programmed path as
  // under G40 (issue 10: what nose compensation changes, side by side).
  bool noseCompensation = true;
  // A record for evidence (tool and stock inference): an alarm skips the rest of
  // its block and the run goes on with the next one, so what the program does
  // after it is still seen; Timeline::alarm keeps the first. The loop limits
  // still end the run.
  bool throughAlarms = false;
  // A record read only for evidence (the check's, when no run follows it): each executed block
  // leaves a BlockMark instead of a StateSnapshot (Timeline::marks), 24 bytes, not 176.
  bool blockMarksOnly = false;
  // With blockMarksOnly: each move's times, feeds and speeds too (Timeline::recordSpeeds, 48 bytes
  // a move), what the check's cutting data (issue 39) reads of the record besides the moves.
  bool recordSpeeds = false;
  // The memory the timeline may take: moves, snapshots and the macro values it logs (issue 42
  // item 3). A run that would need more stops with A156 at the block that reached it, instead of
  // taking all the computer's memory (an endless loop under max_blocks = 100000000). 0 = none.
  std::size_t memoryBudgetMb = kRunMemoryBudgetMb;
  static constexpr std::size_t kRunMemoryBudgetMb = 4096;
};

struct MachineSetup {
  io::MachineConfig machine;
  io::OffsetTable offsets;
  io::ToolTable tools;
};

// Tool offsets: the controlled point for a programmed position P is P + (X offset / 2, Z offset);
// a new offset takes effect with the next move (the tool does not jump), and
// U/W moves are plain displacements. G50 X Z declares the controlled point to
// be at the given position (+ offset) in work coordinates, where the stock is;
// the reference point and travel limits are machine positions and follow it.
// G27/G28/G29/G30/G53 bring the controlled point itself (no offset) to the
// reference or machine position. Under G96 the rpm follows the controlled
// point's diameter. C/H rotations take no time. Zero-length moves are not recorded.
//
// The full chain: interpreter -> compensation stage -> timeline builder.
Timeline interpret(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options = {});

// The run the inference reads (tools, stock, tool side; issue 26 item 2): the
// programmed path (no nose compensation: the nose belongs to a tool the evidence
// may replace), through alarms, with #500-#999 vacant and kept nowhere.
Timeline recordRun(const gcode::Program& program, const MachineSetup& setup, RunOptions options);

// The interpreter alone, emitting canonical calls to `sink` (for custom chains).
void run(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options, MachineSink& sink);
// Same, recording the program flow (call stacks, macro variables, notices) in `flow`.
void run(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options, MachineSink& sink,
         FlowLog& flow);

}  // namespace klueng::core::machine

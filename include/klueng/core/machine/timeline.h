#pragma once
#include <cstdint>
// The result of interpreting a program: every move with exact times, and the
// state after every block. Consumers: the cut simulator, trace/CSV writer,
// cycle-time report, the GUI's animation (which maps time -> pose).
#include <optional>
#include <vector>

#include "klueng/core/comp/segment.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/machine/flow.h"
#include "klueng/core/machine/state.h"

namespace klueng::core::machine {

enum class MoveKind : std::uint8_t { Rapid, Line, Arc, Thread, Dwell };

struct Move {
  // (Ordered to avoid padding: 168 bytes, not 200; a long program makes millions.)
  Segment path;                    // controlled point (imaginary tip), work coords, (z, x radius);
                                   // a rapid dog-leg is several Rapid moves, each a straight Segment
  Vec2 noseCentre = Vec2::Zero();  // nose centre minus controlled point (constant while a tool is active)
  double tStart = 0.0;             // seconds
  double tEnd = 0.0;
  double feed = 0.0;    // mm/min actually used (rapid rate for rapids; at the start for G96)
  double rpm = 0.0;     // spindle rpm at the move's start
  double rpmEnd = 0.0;  // spindle rpm at the move's end (differs under G96)
  double lead = 0.0;    // G32 lead mm/rev
  // Acceleration (machine.cfg accel_x/accel_z, 0 = off): seconds spent speeding
  // up at the start and slowing down at the end of the move (a trapezoid of
  // speed over time; a triangle when up + down is the whole move).
  float rampUp = 0.0f;
  float rampDown = 0.0f;
  int line = 0;  // source file line of the block
  int blockIndex = 0;
  int file = 0;       // Program::files index of the block
  int callLevel = 0;  // 0 = main program
  int program = 0;    // O number of the program the block belongs to
  int tool = 0;
  int offset = 0;
  MoveKind kind = MoveKind::Line;
  SpindleDir spindle = SpindleDir::Stopped;
  bool compensated = false;  // produced under G41/G42

  // Fraction of the path done at time t (0 before, 1 after), following the
  // speed profile: linear without acceleration.
  double fractionAt(double t) const;
  // The inverse: the time at which `fraction` of the path is done.
  double timeAt(double fraction) const;
};

// Machine time spent with one tool selected (issue 11: cycle time per tool).
struct ToolTime {
  int tool = 0;          // station; 0 = before the first tool call
  double seconds = 0.0;  // moves and dwells made with it
};

// What a record read only for evidence keeps of an executed block instead of its StateSnapshot
// (RunOptions::blockMarksOnly: the check's tool and stock inference and its modal warnings read
// no more; 24 bytes, not 176, issue 42 item 3).
struct BlockMark {
  int blockIndex = 0;
  int moveEnd = 0;  // Timeline::moves index one past the block's last move
  int line = 0;
  int file = 0;
  std::int16_t tool = 0;  // machine.tool, machine.offset (stations and offsets are small)
  std::int16_t offset = 0;
  Units units = Units::Mm;  // modal.units, modal.motion, modal.spindleMode
  MotionMode motion = MotionMode::Rapid;
  SpindleMode spindleMode = SpindleMode::ConstantRpm;
  bool rpmClamped = false;  // modal.rpmClamp > 0

  static BlockMark of(const StateSnapshot& s) {
    return {s.blockIndex,
            s.moveEnd,
            s.line,
            s.file,
            static_cast<std::int16_t>(s.machine.tool),
            static_cast<std::int16_t>(s.machine.offset),
            s.modal.units,
            s.modal.motion,
            s.modal.spindleMode,
            s.modal.rpmClamp > 0.0};
  }
};
static_assert(sizeof(void*) != 8 || sizeof(BlockMark) == 24, "a record keeps one a block");  // (64-bit builds)

// What a record of marks keeps of a move (RunOptions::blockMarksOnly): what the tool and stock
// inference read of it, under the names a Move gives them, 96 bytes, not 176. move() gives it
// back as a Move (times, feeds and speeds zero, as a fresh Move's).
struct RecordMove {
  Segment path;
  int line = 0;
  int blockIndex = 0;
  int file = 0;
  std::int16_t tool = 0;  // stations and offsets are small
  std::int16_t offset = 0;
  MoveKind kind = MoveKind::Line;

  static RecordMove of(const Move& m) {
    return {
        m.path, m.line, m.blockIndex, m.file, static_cast<std::int16_t>(m.tool), static_cast<std::int16_t>(m.offset),
        m.kind};
  }
  Move move() const {
    Move m;
    m.path = path;
    m.line = line;
    m.blockIndex = blockIndex;
    m.file = file;
    m.tool = tool;
    m.offset = offset;
    m.kind = kind;
    return m;
  }
};
static_assert(sizeof(void*) != 8 || sizeof(RecordMove) == 96, "a record of marks keeps one a move");  // (64-bit)

struct Timeline {
  std::vector<Move> moves;
  std::vector<StateSnapshot> snapshots;  // one per executed block, in execution order
  // Instead of snapshots, in a record made with RunOptions::blockMarksOnly: one per executed block.
  std::vector<BlockMark> marks;
  // Instead of moves, in a record made with RunOptions::blockMarksOnly.
  std::vector<RecordMove> recordMoves;
  std::optional<Diagnostic> alarm;  // the alarm that stopped the run, if any
  FlowLog flow;                     // call stacks and macro variables (flow.h)
  // A record (RunOptions::throughAlarms) differs from the run interpret() makes with the
  // same inputs when it made a cut with a stand-in feed, spindle or speed, or was asked
  // for nose compensation (it follows the programmed path): job.cpp reuses only one that is not.
  bool recordStandIns = false;
  bool recordCompensates = false;
  double cycleTime() const { return moves.empty() ? 0.0 : moves.back().tEnd; }
  // The executed blocks as the evidence reads them, from the marks or the snapshots.
  std::size_t blockCount() const { return snapshots.empty() ? marks.size() : snapshots.size(); }
  BlockMark blockMark(std::size_t k) const { return snapshots.empty() ? marks[k] : BlockMark::of(snapshots[k]); }
  // The moves as the evidence reads them: f(m) for each of the moves or of a record's moves, a
  // Move or a RecordMove (the same names for what both keep: path, line, blockIndex, file, tool,
  // offset, kind).
  std::size_t moveCount() const { return moves.empty() ? recordMoves.size() : moves.size(); }
  template <typename F>
  void forEachMove(F&& f) const {
    if (!moves.empty())
      for (const Move& m : moves) f(m);
    else
      for (const RecordMove& r : recordMoves) f(r);
  }
  // The cycle time split by tool, in the order the tools are first used.
  std::vector<ToolTime> timeByTool() const;
  // Position of the controlled point at time t (clamped to [0, cycleTime]).
  Vec2 positionAt(double t) const;
  // Index of the move active at time t (-1 before the first move).
  int moveAt(double t) const;
};

// A move beyond the centre line (X < 0) seen from the front: the bar is round,
// so the cut is the same (X negated, arcs turn the other way).
Move mirroredAcrossCentre(const Move& in);
// Which side of the centre line the run cuts on: the side with more feed length,
// at least 1 mm of it (Beyond = X < 0, a rear tool post; issue 26 item 5).
enum class CutSide { None, Front, Beyond };
CutSide sideOfCuts(const Timeline& timeline);

}  // namespace klueng::core::machine

#pragma once
#include <cstdint>
#include <cstring>
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

// A move of a record of marks (RunOptions::blockMarksOnly) as the tool and stock inference read
// it, under the names a Move gives them (96 bytes, made as it is read: RecordMoveList keeps 40 a
// move). move() gives it back as a Move (its times, feeds and speeds zero, as a fresh Move's;
// Timeline::recordedMove gives them too, when the record kept them).
struct RecordMove {
  Segment path;
  int line = 0;
  int blockIndex = 0;
  int file = 0;
  std::int16_t tool = 0;  // stations and offsets are small
  std::int16_t offset = 0;
  MoveKind kind = MoveKind::Line;
  SpindleDir spindle = SpindleDir::Stopped;

  static RecordMove of(const Move& m) {
    return {
        m.path, m.line,   m.blockIndex, m.file, static_cast<std::int16_t>(m.tool), static_cast<std::int16_t>(m.offset),
        m.kind, m.spindle};
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
    m.spindle = spindle;
    return m;
  }
};

// The moves of a record of marks, packed (issue 42 item 3): 40 bytes a move, not 96. A move
// keeps where it ends; where it starts only when that is not where the move before it ended (the
// first move, after a G50 or a dwell's jump), and an arc's centre, in lists of their own. Read
// back whole, bit for bit: list[i] and a loop over the list give RecordMoves (the loop without a
// search).
class RecordMoveList {
 public:
  // (Plain numbers: no 16-byte alignment to pad to.)
  struct Packed {
    double endZ = 0.0, endX = 0.0;
    int line = 0;
    int blockIndex = 0;
    int file = 0;
    std::int16_t tool = 0;
    std::int16_t offset = 0;
    MoveKind kind = MoveKind::Line;
    SpindleDir spindle = SpindleDir::Stopped;
    std::uint8_t flags = 0;  // kOwnStart, kCentre, kArc, kCcw
  };
  struct Point {  // a start or a centre kept apart: the move it belongs to
    std::size_t move = 0;
    double z = 0.0, x = 0.0;
  };
  static constexpr std::uint8_t kOwnStart = 1, kCentre = 2, kArc = 4, kCcw = 8;

  std::size_t size() const { return moves_.size(); }
  bool empty() const { return moves_.empty(); }
  void reserve(std::size_t n) { moves_.reserve(n); }
  // (Inline: the timeline builder packs every move of the check's record straight from its Move.)
  void push_back(const RecordMove& m) { pack(m); }
  void push_back(const Move& m) { pack(m); }
  RecordMove operator[](std::size_t i) const;

  class const_iterator {
   public:
    RecordMove operator*() const;
    const_iterator& operator++();
    bool operator!=(const const_iterator& o) const { return i_ != o.i_; }
    bool operator==(const const_iterator& o) const { return i_ == o.i_; }

   private:
    friend class RecordMoveList;
    const_iterator(const RecordMoveList* list, std::size_t i) : list_(list), i_(i) {}
    const RecordMoveList* list_;
    std::size_t i_ = 0, start_ = 0, centre_ = 0;  // the next of starts_, centres_
  };
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, moves_.size()}; }

  // What it keeps (the run's memory budget reads their sizes).
  const std::vector<Packed>& packed() const { return moves_; }
  const std::vector<Point>& starts() const { return starts_; }
  const std::vector<Point>& centres() const { return centres_; }

 private:
  // memcmp, not std::bit_cast: the WebAssembly build's libc++ (emscripten 3.1.6) has no bit_cast.
  static bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
  template <typename M>  // a Move or a RecordMove: the same names
  void pack(const M& m) {
    Packed p;
    p.endZ = m.path.end.x();
    p.endX = m.path.end.y();
    p.line = m.line;
    p.blockIndex = m.blockIndex;
    p.file = m.file;
    p.tool = static_cast<std::int16_t>(m.tool);
    p.offset = static_cast<std::int16_t>(m.offset);
    p.kind = m.kind;
    p.spindle = m.spindle;
    const std::size_t i = moves_.size();
    const Vec2& start = m.path.start;
    if (i == 0 || !sameBits(start.x(), moves_.back().endZ) || !sameBits(start.y(), moves_.back().endX)) {
      p.flags |= kOwnStart;
      starts_.push_back({i, start.x(), start.y()});
    }
    const Vec2& centre = m.path.centre;
    if (!sameBits(centre.x(), 0.0) || !sameBits(centre.y(), 0.0)) {
      p.flags |= kCentre;
      centres_.push_back({i, centre.x(), centre.y()});
    }
    if (m.path.kind == Segment::Kind::Arc) p.flags |= kArc;
    if (m.path.ccw) p.flags |= kCcw;
    moves_.push_back(p);
  }
  RecordMove unpack(std::size_t i, const Point* start, const Point* centre) const;
  std::vector<Packed> moves_;
  std::vector<Point> starts_;
  std::vector<Point> centres_;
};
static_assert(sizeof(void*) != 8 || sizeof(RecordMoveList::Packed) == 40, "a record of marks keeps one a move");

// What a record of marks keeps beside each move when the check measures its cutting data
// (RunOptions::recordSpeeds, issue 39): the times, feeds, speeds and ramps of the Move, 48 bytes
// (a move starts when the one before it ends, the first at 0).
struct MoveSpeeds {
  double tEnd = 0.0;
  double feed = 0.0;
  double rpm = 0.0;
  double rpmEnd = 0.0;
  double lead = 0.0;
  float rampUp = 0.0f;
  float rampDown = 0.0f;

  static MoveSpeeds of(const Move& m) { return {m.tEnd, m.feed, m.rpm, m.rpmEnd, m.lead, m.rampUp, m.rampDown}; }
};
static_assert(sizeof(MoveSpeeds) == 48, "a record keeps one a move");

struct Timeline {
  std::vector<Move> moves;
  std::vector<StateSnapshot> snapshots;  // one per executed block, in execution order
  // Instead of snapshots, in a record made with RunOptions::blockMarksOnly: one per executed block.
  std::vector<BlockMark> marks;
  // Instead of moves, in a record made with RunOptions::blockMarksOnly.
  RecordMoveList recordMoves;
  // Beside recordMoves, one a move, in a record made with RunOptions::recordSpeeds too.
  std::vector<MoveSpeeds> recordSpeeds;
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
  // Move i as the run made it, from the moves or from a record's moves and speeds (a record
  // without speeds gives them zero): the same Move but for its call level, program, nose
  // centre and compensated flag, which a record does not keep.
  Move recordedMove(std::size_t i) const;
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

#pragma once
// Cuts the stock along a machine::Timeline with the bitmap tools (SPEC 8, 10, 11).
//
//   CutSimulator sim(timeline, CutSetup::from(header, setup));
//   sim.runToEnd();                 // as fast as possible, or
//   sim.advanceTo(t);               // for the animation: any t; going back restores
//                                   // the nearest stock checkpoint and re-cuts from there
//   sim.stock(), sim.alarm(), sim.toolPosition(), FinishedPart(sim.stock())
//
// Every move removes what its cutting edge sweeps, without gaps: the nose circle
// is swept analytically along lines (arcs: chords within 0.0002 mm), bitmap
// boxes are swept per stock column. Rapid dog-legs come as separate Rapid moves.
// A G32 move stamps the tool once per lead along its path (the section plane sees
// the tool once per revolution), so threads show their teeth.
//
// Alarms (A3xx, Severity::Alarm; range.line = the block's line; args {0} = Z,
// {1} = X diameter of the controlled point where it happened, "%.3f"):
//   A301 rapid move overlaps the stock by more than the tolerance (grazing is fine)
//   A302 cutting while the spindle is stopped
//   A303 holder (black pixels) overlaps the stock
//   A304 tool or holder overlaps the chuck (the jaws, or the chuck body outside
//        the spindle bore: a drill passing the part's end inside it is fine)
// The simulation stops at the first alarm, with the tool where it happened.
// Tool loading problems (F1xx from the image reader, A310/A311) are reported by
// toolDiagnostics(); the first move of a tool whose bitmap is refused stops the
// run with that error (alarm(), Severity::Error, range.line = the move's block).
// Moves without a tool (T00 or before the first T) cut nothing.
#include <functional>
#include <map>
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "klueng/core/cut/stock.h"
#include "klueng/core/cut/tool_shape.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/timeline.h"

namespace klueng::core::cut {

struct CutOptions {
  double resolution = kDefaultResolution;  // stock column width along Z, mm
  double collisionTolerance = 0.001;       // mm of overlap that still counts as grazing
  // Width (Z) of material beside the tool's left and right sides that a rapid
  // or a stopped-spindle move may shave without a crash alarm: the wedge a
  // 95-degree tool's flank leaves at a shoulder, which G00 X retracts touch.
  double rapidFlankAllowance = 0.5;
  bool detectCollisions = true;
  // Going back (Step Back, scrubbing) restores a copy of the stock kept while
  // cutting forward, at most this many bytes of them (issue 12: a step back on
  // a 100,000-block program re-cuts a few hundred moves, not all of them).
  // 0 = none: a run that only goes forward (the CLI) keeps no copies.
  std::size_t checkpointBudgetBytes = 64u << 20;
};

struct CutSetup {
  double stockDiameter = 50.0;  // mm
  double stockLength = 100.0;   // mm
  double stockBore = 0.0;       // mm; 0 = solid bar, else a tube
  io::MachineConfig machine;    // chuck grip, jaw height, spindle bore
  io::ToolTable tools;
  io::OffsetTable offsets;
  static CutSetup from(const io::JobHeader& header, const machine::MachineSetup& setup);
};

// Tool shapes by (tool, offset), loaded on first use from the tool and offset tables.
class ToolLibrary {
 public:
  ToolLibrary() = default;
  ToolLibrary(io::ToolTable tools, io::OffsetTable offsets);
  // nullptr when the tool has no bitmap or it cannot be loaded (see diagnostics()).
  const ToolShape* get(int tool, int offset);
  // Installs a ready shape (tests, tools drawn in the GUI) for (tool, offset).
  void set(int tool, int offset, ToolShape shape);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  io::ToolTable tools_;
  io::OffsetTable offsets_;
  std::map<std::pair<int, int>, std::optional<ToolShape>> cache_;
  std::vector<Diagnostic> diagnostics_;
};

// The stock as it was after some moves (CutSimulator's way back).
struct CutCheckpoint {
  std::size_t nextMove = 0;  // the moves before it are cut whole
  double time = 0.0;         // when the last of them ended
  Stock stock;
};

class CutSimulator {
 public:
  // `timeline` must outlive the simulator.
  CutSimulator(const machine::Timeline& timeline, const CutSetup& setup, const CutOptions& options = {});
  CutSimulator(const machine::Timeline& timeline, const CutSetup& setup, ToolLibrary tools,
               const CutOptions& options = {});
  // The simulator keeps a pointer to the timeline: a temporary one would dangle.
  CutSimulator(machine::Timeline&&, const CutSetup&, const CutOptions& = {}) = delete;
  CutSimulator(machine::Timeline&&, const CutSetup&, ToolLibrary, const CutOptions& = {}) = delete;

  void advanceTo(double t);
  void runToEnd();
  // Back to the bar before the first move (the checkpoints stay: they depend only on the timeline).
  void reset();
  // How many moves advanceTo(t) would cut from where it would start (the
  // current state, or a checkpoint when going back): its cost, for a caller
  // deciding whether to cut on a worker thread.
  std::size_t movesToCut(double t) const;
  std::size_t checkpointCount() const { return checkpoints_.size(); }

  double time() const { return time_; }
  // The end of the run: the timeline's cycle time, or when the cut alarm happened.
  double endTime() const;
  bool finished() const;
  const std::optional<Diagnostic>& alarm() const { return alarm_; }
  // The alarm that stopped the run: the cut alarm, else the timeline's own alarm.
  std::optional<Diagnostic> stoppingAlarm() const;

  Vec2 toolPosition() const;             // controlled point at time()
  int currentMove() const;               // -1 before the first move
  const ToolShape* currentTool() const;  // shape of the tool at time(), nullptr if none (loads it on first use)
  const Stock& stock() const { return stock_; }
  const Chuck& chuck() const { return chuck_; }
  double removedVolume() const { return stock_.removedVolume(); }
  const std::vector<Diagnostic>& toolDiagnostics() const { return tools_.diagnostics(); }
  // Every removal from here on adds to `tally` (nullptr: none). Forward runs only: going
  // back or reset() restores a stock without it.
  void setRemovalTally(RemovalTally* tally) { stock_.setTally(tally); }
  // A guessed tool (io::ToolTable::guessed) whose holder or body touches the stock
  // or the chuck: a warning, once a station, and the run goes on (issue 26).
  const std::vector<Diagnostic>& warnings() const { return warnings_; }

 private:
  void cutMove(std::size_t index, double sEnd);
  // True when the touch is a guessed tool's: `warning` (W324-W326) is kept, once a station;
  // `depth` (asked only then) gives W324 how deep the holder went.
  bool excuseGuess(const char* warning, const machine::Move& m, const Vec2& where,
                   const std::function<double()>& depth = {});
  void keepCheckpoint();
  // The latest checkpoint at or before t; nullptr when only the bar is.
  const CutCheckpoint* checkpointBefore(double t) const;

 public:
  // The bounds of a tool's cutting edge, of its holder and of each cutting trapezoid, in its
  // own coordinates, kept for the last (tool, offset) cut with: every move asks them.
  struct ToolBounds {
    int tool = 0, offset = -1;
    Box edge, holder;
    std::vector<Box> edges;
    bool boundsHoldAll = false;  // the shape's bounds hold its edge, holder and nose
  };

 private:
  const machine::Timeline* timeline_;
  CutSetup setup_;
  CutOptions options_;
  mutable ToolLibrary tools_;  // a cache: loading a shape does not change what was cut
  Stock stock_;
  Chuck chuck_;
  double time_ = 0.0;
  std::size_t nextMove_ = 0;   // first move not completely cut
  double nextMoveDone_ = 0.0;  // path parameter of nextMove_ already cut
  std::optional<Diagnostic> alarm_;
  std::vector<Diagnostic> warnings_;
  std::array<bool, io::kMaxStations> warnedGuess_{};
  double alarmTime_ = 0.0;
  Vec2 alarmPosition_ = Vec2::Zero();
  // The stock after every checkpointEvery_ moves (at a move boundary, no alarm yet).
  std::vector<CutCheckpoint> checkpoints_;
  std::size_t checkpointEvery_ = 64;
  ToolBounds toolBounds_;
  // The controlled point's pieces of the move being cut (buffers kept from move to move).
  std::vector<std::pair<Vec2, Vec2>> nosePieces_, boxPieces_;
};

}  // namespace klueng::core::cut

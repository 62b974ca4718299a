#pragma once
// The canonical boundary between the interpreter and what consumes it
// (ARCHITECTURE: Interpreter -> Compensator -> Timeline). The interpreter
// turns blocks into a few canonical calls; sinks can be chained, each one
// forwarding (possibly transformed) calls to the next.
#include <cstddef>
#include <memory>

#include "klueng/core/comp/segment.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/machine/state.h"
#include "klueng/core/machine/timeline.h"

namespace klueng::core::machine {

// Everything that decides how fast a move runs, captured when its block runs.
struct MotionContext {
  FeedMode feedMode = FeedMode::PerRev;
  double feed = 0.0;  // mm/min (G98) or mm/rev (G99), already in mm
  SpindleMode spindleMode = SpindleMode::ConstantRpm;
  double sWord = 0.0;   // rpm (G97) or m/min (G96), 0 = not set
  double rpmCap = 0.0;  // min(G50 S, machine maximum): the G96 clamp
  SpindleDir spindle = SpindleDir::Stopped;
  int tool = 0;
  int offset = 0;
  double noseRadius = 0.0;
  int tip = 0;
};

// One programmed move of the controlled point (imaginary tool tip), work
// coordinates (z, x radius), tool offset already applied.
struct MotionCall {
  MoveKind kind = MoveKind::Line;  // Rapid, Line, Arc or Thread
  Segment path;
  double lead = 0.0;  // Thread: mm/rev
  int line = 0;
  int blockIndex = 0;
  int file = 0;  // as StateSnapshot: file, call level, O number
  int callLevel = 0;
  int program = 0;
  SourceRange where;  // the word an alarm about this move points at
  MotionContext ctx;
  bool compensated = false;  // set by the compensation stage
};

struct DwellCall {
  double seconds = 0.0;
  int line = 0;
  int blockIndex = 0;
  int file = 0;
  int callLevel = 0;
  int program = 0;
  MotionContext ctx;
};

class MachineSink {
 public:
  virtual ~MachineSink() = default;
  virtual void motion(const MotionCall& m) = 0;
  virtual void dwell(const DwellCall& d) = 0;
  // G50 X Z: the controlled point is declared to be at p; nothing moves.
  virtual void setPosition(const Vec2& p) = 0;
  // G40/G41/G42 for the motions that follow (radius and tip of the active offset).
  virtual void compensation(NoseCompMode mode, double radius, int tip) = 0;
  // A block has finished; position, time and moveEnd are filled by the timeline.
  virtual void blockDone(const StateSnapshot& s) = 0;
  virtual void alarm(const Diagnostic& d) = 0;
  // The program has ended (or the interpreter stopped): flush everything.
  virtual void end() = 0;
  // True once a sink down the chain has stopped the run (an alarm).
  virtual bool halted() const = 0;
  // Machining time so far in seconds, as far as the chain knows it (the
  // macro timers #3001/#3002 and the endless-loop limit read it).
  virtual double elapsed() const { return 0.0; }
};

// Nose radius compensation stage: buffers each compensated stretch (start-up
// move, contour, cancel move), runs comp::compensate on it and forwards the
// controlled-point path (nose centre + R * tipVector) to `next`.
std::unique_ptr<MachineSink> makeCompensationStage(MachineSink& next);

// Final stage: builds the Timeline (rapid dog-legs, move times, G96 rpm
// along the move, snapshots).
struct TimingConfig {
  double rapidX = 4000.0;  // mm/min, radial
  double rapidZ = 8000.0;  // mm/min
  double accelX = 0.0;     // mm/s², radial; 0 = moves start and stop at once
  double accelZ = 0.0;     // mm/s²
};
// What the builder keeps and how much of it (RunOptions::blockMarksOnly, memoryBudgetMb).
struct TimelineLimits {
  bool blockMarksOnly = false;  // Timeline::marks instead of snapshots
  bool recordSpeeds = false;    // with blockMarksOnly: Timeline::recordSpeeds beside recordMoves
  std::size_t budgetBytes = 0;  // moves, snapshots or marks and the flow's value logs; 0 = none
};
std::unique_ptr<MachineSink> makeTimelineBuilder(Timeline& out, const TimingConfig& config,
                                                 const TimelineLimits& limits = {});

}  // namespace klueng::core::machine

#pragma once
// Playing a timeline back (issue 12): where the next stop is for Go, Step,
// Step Over, Step Out, breakpoints, Run to cursor and M00/M01; where Step Back
// goes; how far a slow animation frame may move; and what the machine shows
// at any time. The GUI's RunController only keeps the clock and the cut.
#include <set>

#include "klueng/core/geometry.h"
#include "klueng/core/machine/timeline.h"

namespace klueng::core::machine {

inline constexpr double kPlaybackEps = 1e-9;  // s: two times this close are the same instant

enum class RunCommand { Go, Step, StepOver, StepOut };

struct StopRequest {
  RunCommand command = RunCommand::Go;
  int done = -1;                               // the last snapshot (block) finished; -1 = none yet
  double endTime = 0.0;                        // where the run ends: the cycle time, or earlier at a cut alarm
  bool optionalStop = false;                   // the M01 switch
  const std::set<int>* breakpoints = nullptr;  // file lines of the program itself (file 0)
  int runToLine = 0;                           // Run to cursor: stop before the first block at or after it (0 = none)
};

struct StopTarget {
  int snapshot = -1;        // the last block done when the run stops
  double time = 0.0;        // when that is
  bool isEnd = true;        // the run ends there (Finished, or the timeline's own alarm)
  bool beforeNext = false;  // stopped before the next block (a breakpoint, Run to cursor)
};

// Go: the end, or the first breakpoint / Run-to-cursor line (before that block; the block the
// run resumes on is not stopped at again), or an M00/M01 (with the switch on) block.
// Step: the next block; Step Over: the next of this call level (a call runs whole);
// Step Out: the next of the level above.
StopTarget nextStop(const Timeline& timeline, const StopRequest& request);

// Step Back from (done, time): back over the last block at a block boundary,
// to the start of the block in its middle.
StopTarget stepBackStop(const Timeline& timeline, int done, double time);

// How much of `dt` machine seconds from `from` keeps the tool's travel within
// maxMm (a slow animation frame never jumps over a short move).
double limitTravel(const Timeline& timeline, double from, double dt, double maxMm);

// The block whose state the machine shows at `time` when `done` blocks are
// finished: the executing one mid-block (its M03/T/F act before its motion).
int shownSnapshot(const Timeline& timeline, int done, double time);

// What the status bar and lamps show at `time`.
struct Pose {
  Vec2 position = Vec2::Zero();  // controlled point (z, radius)
  MachineState machine;
  double programmedFeed = 0.0;
  FeedMode feedMode = FeedMode::PerRev;
  double rpm = 0.0;
  double feedMmPerMin = 0.0;  // of the move under way; 0 between moves
  bool hasState = false;      // machine/feed come from a block (none has run yet: false)
};
Pose poseAt(const Timeline& timeline, int done, double time);

}  // namespace klueng::core::machine

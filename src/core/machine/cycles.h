#pragma once
// Fanuc 0i-TF lathe canned cycles (SPEC "Beyond") as a pure expansion: the
// cycle block's words, the start point and, for G70-G73, the profile blocks
// N(P)..N(Q) become the simple moves the control makes (rapids, lines, arcs,
// thread passes). The interpreter sends each move down the ordinary sink
// chain with the cycle block's line.
//
// All points are controlled-point positions in work coordinates (z, x radius),
// tool offset applied, like the interpreter's.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/comp/segment.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/state.h"

namespace klueng::core::machine::cycles {

enum class StepKind { Rapid, Feed, Thread, Compensation, Dwell };

struct Step {
  StepKind kind = StepKind::Rapid;
  Segment path;                           // Feed: a line or an arc
  double lead = 0.0;                      // Thread: mm/rev
  double feed = 0.0;                      // > 0: F (mm) takes effect from this step on (G70 profile F)
  NoseCompMode comp = NoseCompMode::Off;  // Compensation: G40/G41/G42 inside a G70 profile
  SourceRange where;                      // the word an alarm about this step points at (0 = the cycle's G)
  const gcode::Word* sWord = nullptr;     // G70: an S of the profile, applied before this step
  const gcode::Word* tWord = nullptr;     // G70: a T of the profile, applied before this step
  double seconds = 0.0;                   // Dwell: how long
};

struct CycleAlarm {
  std::string code;
  SourceRange where;
  std::vector<std::string> args;
};

// Parameters of the first block of the two-block formats (G71 U R, G76 P Q R,
// ...), kept until the next first block of the same cycle. Lengths in mm, radius.
struct CycleMemory {
  double g71Depth = 0.0, g71Retract = 0.0;
  double g72Depth = 0.0, g72Retract = 0.0;
  double g73ReliefX = 0.0, g73ReliefZ = 0.0;
  int g73Count = 0;
  double g74Retract = 0.0, g75Retract = 0.0;
  int g76Finishing = 1;       // m
  int g76Chamfer = 0;         // r: the pull-out is r/10 leads long, at 45 degrees
  double g76Angle = 60.0;     // a, degrees (tool angle)
  double g76MinDepth = 0.0;   // Δdmin
  double g76Allowance = 0.0;  // d
};

// The profile N(P)..N(Q) of G70-G73 as moves from the cycle's start point.
struct Profile {
  std::vector<Step> moves;   // moves[0] starts at the cycle's start point
  std::vector<int> blockOf;  // program block index of each move
  int ns = -1, nf = -1;
};

// Reads N(P)..N(Q) for the cycle block `cycle` (its G word `g`). The interpreter supplies it: it
// runs those blocks itself into a capturing sink, so a profile means exactly
// what the same blocks mean anywhere else (modal G, U/W, ,C ,R corners, macro
// values, G20). `withFeed`: F, S, T, G40-G42 and G04 inside apply (G70);
// the roughing cycles ignore them.
using ProfileReader = std::function<std::optional<CycleAlarm>(const gcode::Block& cycle, const gcode::Word* g,
                                                              bool withFeed, Profile& out)>;

struct CycleInput {
  const gcode::Program* program = nullptr;
  int blockIndex = 0;                              // the cycle block
  const gcode::Block* block = nullptr;             // its words with macro values evaluated (the interpreter's)
  const ProfileReader* readProfile = nullptr;      // G70-G73 (none: "no profile block" alarm)
  const gcode::Word* gWord = nullptr;              // the cycle's G word
  Vec2 start = Vec2::Zero();                       // controlled point when the cycle starts
  Vec2 offset = Vec2::Zero();                      // tool offset vector (z, x radius)
  const io::OffsetTable* offsets = nullptr;        // for a T inside a G70 profile (none: offsets stay)
  double unit = 1.0;                               // mm per program unit (25.4 under G20)
  double feed = 0.0;                               // modal F in mm (after the cycle block's own F)
  MotionMode motion = MotionMode::Rapid;           // modal motion when the profile starts
  bool blockSkip = false;                          // '/' blocks of the profile skipped
  const gcode::MachineProfile* profile = nullptr;  // one-block forms, drilling: settings, G04 P rule
  bool threadChamfer = true;                       // Haas M23/M24 state (G76 one-block pull-out)
  bool returnToRPoint = false;                     // G99 (return level) of G-code systems B and C
};

struct Expansion {
  std::vector<Step> steps;
  std::optional<CycleAlarm> alarm;
  int resumeAfter = -1;  // G71-G73 whose profile follows: the run continues after this block index
};

// G70-G76 (one block of either format). A first block only fills `memory`.
Expansion expand(const gcode::CodeInfo& code, const CycleInput& in, CycleMemory& memory);

// Haas one-block G70-G76 (MachineProfile::cycleForm == OneBlock): G71/G72
// P Q U W D I K F, G73 P Q U W I K D F, G70 P Q, G74/G75 X Z I K D F,
// G76 X Z K D F I A P U W. Readings and the manual's sections: docs/haas-cycles.md.
Expansion expandOneBlock(const gcode::CodeInfo& code, const CycleInput& in);

// The words of a drilling cycle G81/G82/G83, in mm (controlled point, work
// coordinates). Modal: a later block with only a hole position reuses them.
struct DrillWords {
  gcode::CodeAction g = gcode::CodeAction::Drilling;  // Drilling, SpotDrilling, PeckDrilling
  Vec2 hole = Vec2::Zero();                           // hole position and bottom (z = bottom of the hole)
  double rPlane = 0.0;                                // Z of the R point
  double peck = 0.0;                                  // Q: depth of each peck (G83), 0 = one feed to the bottom
  double firstPeck = 0.0;                             // Haas G83 I: first peck; J: reduction per peck; K: least peck
  double reduce = 0.0;
  double minPeck = 0.0;
  double dwell = 0.0;           // P: seconds at the bottom
  double clearance = 0.0;       // G83: rapid down to this much above the last peck
  int repeats = 1;              // Fanuc K, Haas L
  bool returnToRPoint = false;  // G99 of G-code systems B and C; else back to the initial level
  double initialLevel = 0.0;    // Z where the cycle was first given (G98 returns there)
};

// Reads a drilling block into `words` (words not in the block keep their
// value; `fresh` = a new G81-G83, whose R defaults to the initial level).
std::optional<CycleAlarm> readDrillWords(const gcode::CodeInfo& code, const CycleInput& in, bool fresh,
                                         DrillWords& words);
// The moves of one drilling cycle from `start` (the initial level): rapid to
// the hole's X, rapid to the R point, feed (in pecks) to the bottom, dwell,
// rapid back to the initial level (Fanuc G-code system A; Haas).
std::vector<Step> drill(const DrillWords& words, const Vec2& start);

// Seconds of a dwell word P as the profile reads it (Fanuc: ms; Haas: with a
// decimal point seconds, else ms).
double dwellSeconds(const gcode::Word& p, gcode::DwellPUnit rule);

// G90 (turning), G92 (threading, `lead` = F) and G94 (facing) from `start` to
// `target` with taper `taper` (radius for G90/G92, Z for G94: start of the cut
// minus its end).
std::vector<Step> singleCycle(gcode::CodeAction g, const Vec2& start, const Vec2& target, double taper, double lead);

// G76 cumulative depths of cut (radius) for thread height k, first depth d1,
// minimum depth dmin, finishing allowance d and m finishing passes: d1·√n
// (at least dmin more than the previous pass) up to k - d, then m passes at k.
std::vector<double> threadDepths(double k, double d1, double dmin, double d, int m);

}  // namespace klueng::core::machine::cycles

#pragma once
// What each station of a program does, read from one recorded run of the
// interpreter (issue 26 item 2): the blocks each tool really runs after macros,
// subprograms, cycles, offsets and G20/G21, and the moves they make. Only the
// comments come from the text, because a run has none: the T block's own,
// the comment lines around it and a tool list at the top. Private to infer;
// tool_inference.cpp decides the tools from it.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/machine/timeline.h"
#include "klueng/core/infer/tool_inference.h"

namespace klueng::core::machine::detail {

struct Evidence {
  io::ToolKind kind = io::ToolKind::Unknown;
  ToolReason reason = ToolReason::Turning;
  std::string detail;  // the comment or the code seen ("G75", "G01 X0", "G71 U-0.5")
  int line = 0;
  bool strong = false;
  bool finishing = false;
  bool roughing = false;  // the same comment also says roughing
  std::string insert;     // "vnmg" when a comment names the insert
  double drillMm = 0.0;
};

// The moves one tool makes, summed (mm; work coordinates seen from the front).
struct MotionUse {
  double towardChuck = 0.0;   // fed along -Z (a right-hand tool's work)
  double towardTail = 0.0;    // fed along +Z (a left-hand tool's)
  double inside = 0.0;        // Z feeds left by a retract inward (boring)
  double outside = 0.0;       // Z feeds left by a retract outward
  double threadInside = 0.0;  // the same for thread passes only
  double threadOutside = 0.0;
  double belowZero = 0.0;   // fed at X < 0 (a tool beyond the centre)
  double aboveZero = 0.0;   // fed at X > 0
  int insideLine = 0;       // the first Z feed left inward
  int belowLine = 0;        // the first feed at X < 0
  int threadLine = 0;       // the first thread pass
  double drillDepth = 0.0;  // deepest feed along -Z on the centre line (Z < 0)
  int drillLine = 0;
  double plunge = 0.0;      // deepest straight radial feed toward the centre off it (on the diameter)
  double plungeEndX = 0.0;  // the X it ended at (diameter)
  double plungeZ = 0.0;     // and its Z
  int plungeLine = 0;
};

struct StationUse {
  int firstLine = 0;      // the first T block selecting it
  std::set<int> offsets;  // offset numbers used with it (1..)
  std::optional<Evidence> comment;
  std::optional<Evidence> cycle;  // the first telling cycle or move
  std::optional<Evidence> turning;
  double drillDepthMm = 0.0;  // deepest drilling on centre
  int drillLine = 0;
  std::string drillCode;
  MotionUse motion;           // everything it moved
  bool holdsBar = false;      // a comment names it a bar puller or bar stop
  bool pullsBar = false;      // a bar puller
  double noseRadiusMm = 0.0;  // the radius one of its comments states ("R0.4", "CNMG 431")
  int noseRadiusLine = 0;
};

// The lines of a G-code text, kept as where each starts (4 bytes a line, not a 16-byte view:
// a long program's table is read only near its T blocks and its comment lines). A line ends
// at LF, CR or CRLF; a text over 4 GiB keeps the lines that start in its first 4 GiB.
class TextLines {
 public:
  TextLines() = default;
  explicit TextLines(std::string_view text);
  std::size_t size() const { return starts_.size(); }
  std::string_view operator[](std::size_t i) const;

 private:
  std::string_view text_;
  std::vector<std::uint32_t> starts_;
};

struct ProgramEvidence {
  std::map<int, StationUse> uses;    // by station, every station the run selects
  std::vector<int> order;            // the station of every T selection, in run order
  std::map<int, Evidence> partings;  // station -> its plunge to X0 (counts for one of the last tools)
  bool beyondCentre = false;         // the moves were mirrored: the tools work at X < 0
  TextLines lines;                   // the G-code text's lines (comments, block texts)
  int firstLine = 1;
  // The words of a file line ("G01 Z-51.4") without its comment, for a note.
  std::string blockText(int fileLine) const;
};

// `run` is the recorded run of `program` (its text `gcodeText` from file line
// `gcodeFirstLine`); `beyondCentre`: read its moves mirrored to the front.
ProgramEvidence gatherEvidence(const gcode::Program& program, std::string_view gcodeText, int gcodeFirstLine,
                               const Timeline& run, gcode::Dialect dialect, bool beyondCentre);

// Right-hand (feeds toward the chuck) or left-hand: by what the run shows.
bool leftHandWork(const MotionUse& m);
// Its Z feeds end with a retract toward the centre: it works inside a bore.
bool insideWork(const MotionUse& m);

}  // namespace klueng::core::machine::detail

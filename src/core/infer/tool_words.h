#pragma once
// What a comment says about a tool: the words real programs use, in English
// (Haas and Fanuc shop habits) and Thai (GLOSSARY.md). Private to infer.
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/io/tool_library.h"

namespace klueng::core::machine::detail {

struct CommentTool {
  io::ToolKind kind = io::ToolKind::Unknown;
  bool finishing = false;     // FINISH / กลึงละเอียด: the small nose radius
  bool roughing = false;      // ROUGH / กลึงหยาบ too ("ROUGH AND FINISH": one insert for both)
  std::string insert;         // "vnmg", "dnmg", "cnmg" when the comment names one
  double drillMm = 0.0;       // a size written with the drill ("DRILL 16MM", "Ø10"); 0 = none
  bool holdsBar = false;      // a bar puller or bar stop: no cutting tool (kind stays Unknown)
  bool pullsBar = false;      // a bar puller (it drags the bar out of the open chuck)
  double noseRadiusMm = 0.0;  // the nose radius the comment states ("R0.4", "CNMG 120408", "CNMG 431"); 0 = none
};

// Unknown kind when the comment names no tool.
// unitMm: mm per program unit where the comment is (a bare ".5 DIA" in an inch program).
CommentTool classifyComment(std::string_view comment, double unitMm = 1.0);

// A T word written inside a comment ("T1", "T0303"): the station it names (1-2
// digits as written, 3-4 digits = station and offset) and the part of the
// comment that speaks of it: from the word up to the next T word.
struct CommentToolWord {
  int station = 0;
  std::string_view text;
};
std::vector<CommentToolWord> toolWordsIn(std::string_view comment);

// What a comment says of one station: all of it when it names no station,
// "T1 OD TURN" of "T1 OD TURN, T3 THREAD" for station 1, nothing when it
// names only other stations.
std::string_view commentForStation(std::string_view comment, int station);

}  // namespace klueng::core::machine::detail

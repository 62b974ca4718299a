#pragma once
// The timeline as CSV, one row per move (klueng-cli simulate --trace):
//   kind,line,t_start,t_end,x_start,z_start,x_end,z_end,i,k,dir,feed_mm_min,rpm,level,program
// X as diameters, points = controlled point in work coordinates, i,k = arc
// centre relative to the start (i as a radius; 0 for non-arcs), dir CW/CCW
// (empty for non-arcs), numbers with 4 decimals; level = call level (0 main
// program, 1 a subprogram or macro it calls ...), program = the O number of
// the program the move is in ("O1000", empty when the main has none).
#include <string>
#include <string_view>

#include "klueng/core/machine/timeline.h"

namespace klueng::core::machine {

inline constexpr std::string_view kTraceHeader =
    "kind,line,t_start,t_end,x_start,z_start,x_end,z_end,i,k,dir,feed_mm_min,rpm,level,program";

std::string_view moveKindName(MoveKind kind);  // RAPID LINE ARC THREAD DWELL
std::string formatTraceCsv(const Timeline& timeline);

}  // namespace klueng::core::machine

#pragma once
// The checker's modal warnings from the recorded run (issue 26 item 2). The
// checker's own walk (gcode/modal_check.cpp) follows the modal state through
// the text while the user types and stops at the first block it cannot know
// without running (a macro statement, an expression, a call). The inference's
// record has run them: what the walk could not reach, the run says — the feed
// move with no F (W104), G96 with no G50 S limit (W105) and the arc whose R
// cannot join its ends (W106) that the run meets first. Private to machine.
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/machine/timeline.h"

namespace klueng::core::machine::detail {

// Warnings the run meets before its first alarm (and that alarm, when it is
// A102 or A114), in the program's own file, not already in `found`.
std::vector<Diagnostic> modalWarningsFromRun(const gcode::Program& program, const Timeline& record,
                                             const std::vector<Diagnostic>& found);

}  // namespace klueng::core::machine::detail

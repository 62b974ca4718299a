#pragma once
// The checker's modal rules (issue 11): run-time alarms that can be known while
// typing, found by following the modal state through the blocks — a feed move
// with no F in force (A102), G96 with no G50 S limit, an arc whose R cannot
// join its ends (A114). The walk stops at the first block whose effect cannot
// be known without running the program (macro statements, expressions, calls,
// jumps), so a warning here always means the run will meet it.
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/program.h"

namespace klueng::core::gcode {

void checkModalState(const Program& program, const CheckOptions& options, std::vector<Diagnostic>& out);

}  // namespace klueng::core::gcode

#pragma once
// The checker's program-flow rules (E4xx): DO/END pairs, GOTO and M97
// targets, called programs, macro arguments, call depth.
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/program.h"

namespace klueng::core::gcode {

void checkFlow(const Program& program, const CheckOptions& options, std::vector<Diagnostic>& out);

}  // namespace klueng::core::gcode

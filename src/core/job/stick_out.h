#pragma once
// How far an inferred bar must stick out of the chuck for the program's tools (issue 38).
#include <optional>

#include "klueng/core/diagnostic.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/timeline.h"

namespace klueng::core::job {

// The stock length inferred from the deepest cut leaves the jaws a cut-off's width behind it;
// a tool whose body reaches further towards the chuck (a threading insert, a wide holder) would
// then meet jaws that only the guess put there. Lengthens an inferred bar in `h` so every tool
// that feeds, or rapids below the jaws' top, clears the jaws' face; returns the note (I162)
// that says so, or nothing when the bar was long enough or not inferred.
std::optional<Diagnostic> lengthenForTools(io::JobHeader& h, const machine::Timeline& run,
                                           const machine::MachineSetup& setup);

}  // namespace klueng::core::job

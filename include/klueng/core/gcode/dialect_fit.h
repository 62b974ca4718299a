#pragma once
// "Say which dialect fits" (issue 8, SPEC 13): when a program has errors in
// the current dialect and another machine profile accepts it, name that one.
#include <optional>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/checker.h"

namespace klueng::core::gcode {

struct DialectFit {
  Dialect dialect;  // the dialect that checks the program without errors
  int blocks = 0;   // blocks with errors in the current dialect that are clean there
  // Note I102 ("13 blocks with errors are Haas ST (NGC) forms: choose ..."),
  // severity Note (never an error), at the first such block.
  Diagnostic note;
};

// diagnostics: check(program, options) as already computed. Returns nullopt
// at once when they hold no error (the common case costs nothing); otherwise
// checks the program in each other profile (same options, its own power-on
// units unless options.powerOnUnits is set) and returns the first, in menu
// order, with no errors.
std::optional<DialectFit> suggestDialect(const Program& program, const CheckOptions& options,
                                         const std::vector<Diagnostic>& diagnostics);

}  // namespace klueng::core::gcode

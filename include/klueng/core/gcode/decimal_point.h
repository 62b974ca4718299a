#pragma once
// Decimal point input (issue 26 item 6). A length written without a decimal
// point is read one of two ways, a setting of the control:
//   - calculator-type input: X30 = 30 mm (30 in under G20), as Klueng's own
//     programs and many school controls read it (Fanuc parameter 3401#0
//     DPI = 1, Haas setting 162 "Default to float" on);
//   - standard input: in least input increments, X30 = 0.030 mm (0.0030 in
//     under G20), as a Fanuc 0i or a Haas reads it out of the box; production
//     programs write cycle words that way (G71 U1250 R50, G76 ... R50).
// The words concerned are the lengths X Z U W I K R (a G04's X or U too: a
// time, in 0.001 s). P and Q keep their own rules (the cycles read them in increments
// without a point), A is an angle, F a feed, D a count or depth whose reading
// Haas keeps apart; words holding a macro expression take the value as it is,
// and G65/G66 arguments are passed as written.
#include <string>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/program.h"

namespace klueng::core::gcode {

// One length word without a decimal point whose reading tells the two settings apart.
struct PointClue {
  SourceRange range;
  std::string word;          // as written: "U1250"
  bool inch = false;         // G20 in force at its block
  double wholeMm = 0.0;      // its length read in whole units, mm
  double incrementMm = 0.0;  // read in least input increments, mm
};

// What the program's own numbers say about its machine's setting.
struct PointEvidence {
  // Words only least input increments make sense of: a cycle's depth,
  // retract or allowance over 25 mm, a position over 2 m ("G71 U1250").
  std::vector<PointClue> forIncrements;
  // Words only whole units make sense of: a position under 0.1 mm from zero
  // or a cycle setting under 0.01 mm when read in increments ("X30", "G71 U1").
  std::vector<PointClue> forWholeUnits;
};

// The clue's length in its own unit as one reading gives it: "0.1250 in" in
// increments, "1250 in" whole (for notes and warnings).
std::string clueLengthText(const PointClue& clue, bool increments);

// Codes are found by their action in `dialect`'s code table (issue 27): inch and
// metric input are G20/G21 in G-code systems A and B, G70/G71 in system C, and
// the multiple repetitive cycles G70-G76 (A, B) are G72-G78 in C.

// The units in force after the program's last inch/metric code in file order (the
// program itself, file 0), `powerOnUnits` when it has none.
InputUnits programInputUnits(const Program& program, InputUnits powerOnUnits, Dialect dialect);

// Reads the program in file order, the units from `powerOnUnits` on.
PointEvidence weighDecimalPoints(const Program& program, InputUnits powerOnUnits, Dialect dialect);

// Rescales every length word without a decimal point to least input
// increments (0.001 mm, 0.0001 in as the units code says at its block).
void readLengthsInIncrements(Program& program, InputUnits powerOnUnits, Dialect dialect);

// The words whose other reading is clearly what the author meant: W110 for a
// word read in increments that only makes sense whole ("write X30. for 30
// mm"), W111 for a word read whole that only makes sense in increments.
std::vector<Diagnostic> decimalPointWarnings(const PointEvidence& evidence, bool inIncrements);

}  // namespace klueng::core::gcode

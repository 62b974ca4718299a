#pragma once
// Plain-language explanations of blocks (issue 11), in English and in Thai as a
// lathe teacher says it (GLOSSARY.md): what each code does, built from the code
// table, and what the block does here, built from the machine state after it —
// "G01 X30. Z-20. F0.2: cut in a straight line to Ø30 at Z-20, 0.2 mm per
// revolution; at 180 m/min (G96) the spindle turns 1910 rpm here".
#include <string>
#include <string_view>

#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/machine/state.h"
#include "klueng/core/machine/timeline.h"
#include "klueng/core/messages.h"

namespace klueng::core::machine {

// What one code does ("cut in a straight line" / "กลึงเป็นเส้นตรง"); empty when
// the dialect has no such code.
std::string explainCode(char letter, int number, gcode::Dialect dialect, Lang lang);

// The block as written, a colon, and what it does with the state `after` it
// ran (the feed mode, G96 speed and rpm at its end point, the tool). A macro
// statement keeps no words: `statementText` (its line) heads it then.
std::string explainBlock(const gcode::Block& block, const StateSnapshot& after, gcode::Dialect dialect, Lang lang,
                         std::string_view statementText = {});

// Inside a block of many passes (a cycle): which pass move `moveIndex` is in,
// "pass 3 of 12" / "เที่ยวที่ 3 จาก 12" — a pass is a run of feed moves between
// rapids. Empty when the block makes one pass or less.
std::string explainPass(const Timeline& timeline, int moveIndex, Lang lang);

// One line of program text as the editor holds it: parsed here (the GUI parses
// no G-code), explained with the state `after` it ran, or from its words alone
// when `after` is null. Empty when the line holds no block. `lengthsInIncrements`:
// the job reads lengths without a decimal point in least input increments
// (machine.calculatorInput false; point_reading.h), so `G71 U1250` is said as 1.25.
std::string explainLineText(std::string_view lineText, int fileLine, const StateSnapshot* after, gcode::Dialect dialect,
                            Lang lang, bool lengthsInIncrements = false);

// The same without a run: what the words alone say (no rpm, feed mode unknown).
std::string explainWords(const gcode::Block& block, gcode::Dialect dialect, Lang lang,
                         std::string_view statementText = {});

}  // namespace klueng::core::machine

#pragma once
// Lexer + parser in one pass over the G-code text (SPEC 3).
#include <cstddef>
#include <string_view>

#include "klueng/core/gcode/program.h"

namespace klueng::core::gcode {

// text: the G-code part of a file (UTF-8, LF/CRLF/CR line ends).
// firstLine: the file line number of text's first line (7 after a 6-line header).
// An ISO program number ":0100" is read as an O word with Word::colon set
// (the checker decides whether the machine profile allows it).
// Never throws. Lexical errors (E101-E109, E120) go to lexicalDiagnostics;
// they stop at 2,000 (E109), and a block keeps at most 1,000 words (E120), so
// memory stays bounded on junk such as a 10 MB single line.
// file: the Program::files index the text belongs to (set on blocks and ranges).
// Macro B (issue 9): an address may hold an expression (X#101, Z-[#1+2.]) and
// a line may be a statement (#1=..., IF, WHILE/DO, END, GOTO); ',C' ',R' ',A'
// read as comma words.
Program parse(std::string_view text, int firstLine = 1, int file = 0);
// The same reading of a piece of a line (the checker reads a ';' or ')' tail with it); not counted
// by parseCount().
Program parseFragment(std::string_view text, int firstLine = 1, int file = 0);
// A machine that reads A without a comma as a G01's angle (`G01 X40. A-45.`, Fanuc parameter
// 3405#4, MachineProfile::angleWithoutComma): every such A word becomes the ,A the rest reads.
void readAnglesWithoutComma(Program& program);

// How many times parse() has run in this process (issue 12: the tests count
// the parses one edit or one CLI command costs).
std::size_t parseCount();

}  // namespace klueng::core::gcode

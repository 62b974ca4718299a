#pragma once
// Lexer + parser in one pass over the G-code text (SPEC 3).
#include <string_view>

#include "klueng/core/gcode/program.h"

namespace klueng::core::gcode {

// text: the G-code part of a file (UTF-8, LF/CRLF/CR line ends).
// firstLine: the file line number of text's first line (7 after a 6-line header).
Program parse(std::string_view text, int firstLine = 1);

}  // namespace klueng::core::gcode

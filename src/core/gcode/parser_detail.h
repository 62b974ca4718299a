#pragma once
// The line-by-line parser behind gcode::parse (parser.cpp); parse_split.cpp
// runs it on the halves of a big program at once.
#include <string_view>

#include "klueng/core/gcode/program.h"

namespace klueng::core::gcode {

// reserveBlocks: room for the blocks of the whole program when text is its first half.
Program parseLines(std::string_view text, int firstLine, int file, std::size_t reserveBlocks = 0);

}  // namespace klueng::core::gcode

#include "klueng/core/gcode/program.h"

#include <ostream>

namespace klueng::core::gcode {

int programNumberAt(const Program& program, int index) {
  if (index < 0 || index >= static_cast<int>(program.blocks.size())) return 0;
  const int file = program.blocks[static_cast<std::size_t>(index)].file;
  for (int i = index; i >= 0; --i) {
    const Block& b = program.blocks[static_cast<std::size_t>(i)];
    if (b.file != file) break;
    if (!b.words.empty() && b.words.front().letter == 'O' && b.words.front().expr < 0) return b.words.front().code();
  }
  return 0;
}

}  // namespace klueng::core::gcode

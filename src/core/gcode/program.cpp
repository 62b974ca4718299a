#include "klueng/core/gcode/program.h"

namespace klueng::core::gcode {

const Word* Block::find(char letter) const {
  for (const Word& w : words)
    if (w.letter == letter) return &w;
  return nullptr;
}

std::vector<const Word*> Block::all(char letter) const {
  std::vector<const Word*> out;
  for (const Word& w : words)
    if (w.letter == letter) out.push_back(&w);
  return out;
}

}  // namespace klueng::core::gcode

#include "klueng/core/gcode/word_number.h"

#include <ostream>

namespace klueng::core::gcode {

std::ostream& operator<<(std::ostream& os, const WordNumber& n) { return os << n.view(); }

}  // namespace klueng::core::gcode

#pragma once
// Pictures for the help where words are weak (issue 11): the imaginary tool
// tip numbers 0-9 from the core's own tip vectors, and the path a cycle's
// worked example really makes (G71 passes, G76 infeed), drawn from the core's
// timeline of that example.
#include <QImage>
#include <string>

#include "klueng/core/gcode/code_table.h"

namespace klueng::gui {

// The SPEC 9 grid of tip numbers 0-9; its legend in the UI language (tr).
QImage tipNumbersPicture();
// The moves of a code's worked example over a Ø50 x 100 bar: cuts red, rapids dashed blue.
QImage examplePathPicture(char letter, int number, core::gcode::Dialect dialect);

}  // namespace klueng::gui

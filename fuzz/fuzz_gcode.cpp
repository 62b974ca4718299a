// libFuzzer target: G-code text through the parser and the checker in both
// dialects. Checks invariants the editor relies on, not only "no crash".
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/messages.h"

using namespace klueng::core;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const gcode::Program program = gcode::parse(text, 7);
  for (const gcode::Block& b : program.blocks)
    for (const gcode::Word& w : b.words)
      if (w.range.line != b.line || w.range.column < 1 || w.range.length < 2 || w.letter < 'A' || w.letter > 'Z')
        std::abort();

  for (gcode::Dialect dialect : {gcode::Dialect::Fanuc, gcode::Dialect::Classic}) {
    gcode::CheckOptions options;
    options.dialect = dialect;
    if (size % 2) options.toolsWithBitmap = std::vector<int>{1, 3};
    const auto diags = gcode::check(program, options);
    int lastLine = 0, lastColumn = 0;
    std::size_t formatted = 0;
    for (const Diagnostic& d : diags) {
      // Sorted, inside the text, and every code has a message in both languages.
      if (d.range.line < lastLine || (d.range.line == lastLine && d.range.column < lastColumn)) std::abort();
      if (d.range.line < 7 || d.range.line >= 7 + program.lineCount + 1 || d.range.column < 1) std::abort();
      lastLine = d.range.line;
      lastColumn = d.range.column;
      if (!findMessage(d.code)) std::abort();
      // Formatting is slow under ASan; a sample of each input's messages is enough.
      if (formatted++ < 16) {
        (void)formatMessage(d, Lang::En);
        (void)formatMessage(d, Lang::Th);
      }
    }
  }
  return 0;
}

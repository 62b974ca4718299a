#pragma once
// The grammar check and the tool inference of one program, side by side on two
// threads (issues 12 and 13: a 100,000-block program's check is what a user
// waits for on every edit and every `klueng-cli check`). They share nothing but
// the tool rule E305, which needs the inferred tools: check() runs without it
// and checkToolBitmaps() adds it after, as one check() with the tools would.
#include <functional>
#include <vector>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/infer/tool_inference.h"

namespace klueng::core::machine::detail {

struct CheckedWithTools {
  ToolInference inference;
  std::vector<Diagnostic> diagnostics;  // sorted as check() sorts them
};

// `infer` runs on a second thread; options.toolsWithBitmap set = check T words
// against the inferred tools (its value is replaced by theirs).
CheckedWithTools checkWhileInferring(const gcode::Program& program, gcode::CheckOptions options,
                                     const std::function<ToolInference()>& infer);

}  // namespace klueng::core::machine::detail

#include "check_with_tools.h"

#include <algorithm>
#include <future>

#include "klueng/core/machine/setup_files.h"
#include "machine/run_warnings.h"

namespace klueng::core::machine::detail {

CheckedWithTools checkWhileInferring(const gcode::Program& program, gcode::CheckOptions options,
                                     const std::function<ToolInference()>& infer) {
  CheckedWithTools out;
  const bool toolRule = options.toolsWithBitmap.has_value();
  gcode::CheckOptions grammar = options;
  grammar.toolsWithBitmap.reset();
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
  // The WebAssembly build has no threads (issue 41): the check, then the inference.
  out.diagnostics = gcode::check(program, grammar);
  out.inference = infer();
#else
  // Both only read the program; the inference's result is waited for below.
  std::future<ToolInference> inferred = std::async(std::launch::async, infer);
  out.diagnostics = gcode::check(program, grammar);
  out.inference = inferred.get();
#endif
  // Where the editor's modal walk could not follow the program, the run did.
  std::vector<Diagnostic> more;
  if (options.modalRules && out.inference.record)
    more = modalWarningsFromRun(program, *out.inference.record, out.diagnostics);
  if (toolRule) {
    options.toolsWithBitmap = toolsWithBitmap(out.inference.setup);
    std::vector<Diagnostic> tools = gcode::checkToolBitmaps(program, options);
    more.insert(more.end(), std::make_move_iterator(tools.begin()), std::make_move_iterator(tools.end()));
  }
  if (more.empty()) return out;
  out.diagnostics.insert(out.diagnostics.end(), std::make_move_iterator(more.begin()),
                         std::make_move_iterator(more.end()));
  sortByPlace(out.diagnostics);
  return out;
}

}  // namespace klueng::core::machine::detail

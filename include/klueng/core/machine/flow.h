#pragma once
// What program flow did during a run (issue 9): the call stacks, the macro
// variables each block wrote and the values its expression words had. Kept
// beside the Timeline so the GUI can show the call stack, a variable watch and
// word values while stepping, and the trace can print the call level.
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/machine/state.h"

namespace klueng::core::machine {

// One level of the call stack: the call and where it came from.
struct CallFrame {
  enum class Kind { Main, Subprogram, Local, Macro, ModalMacro };  // main, M98, M97, G65, G66
  Kind kind = Kind::Main;
  int program = 0;   // O number running at this level (0 = unnumbered main)
  int callFile = 0;  // the calling block (Program::files index, file line), 0 for Main
  int callLine = 0;
  int repeat = 1;  // this pass of L repeats, 1-based
  int repeats = 1;
  int locals = -1;  // local-variable frame id (G65/G66 start a new one); -1 = the main's (0)
};

// A variable written by a block. Local variables (#1-#33) belong to a frame
// (0 = the main program's locals, then one per G65/G66 call); common and
// system variables have localFrame -1.
struct VariableWrite {
  int snapshot = 0;  // index of the Timeline snapshot of the block that wrote it
  int number = 0;
  int localFrame = -1;
  double value = 0.0;
  bool vacant = false;  // #0 written (vacant)
};

// The value an expression word had when its block ran ("X#101" -> 25.4).
struct WordValue {
  int snapshot = 0;
  int file = 0;
  int line = 0;
  int column = 0;
  double value = 0.0;
  bool vacant = false;  // the address was omitted (vacant variable)
};

struct FlowLog {
  // Distinct call stacks, outermost first; stacks[0] is the main program alone.
  std::vector<std::vector<CallFrame>> stacks{std::vector<CallFrame>{CallFrame{}}};
  std::vector<VariableWrite> writes;  // in execution order
  std::vector<WordValue> wordValues;  // in execution order
  std::vector<int> localFrames{0};    // per local frame id: the stack level that owns it
  std::vector<Diagnostic> notices;    // run notices that did not stop the run (M99 loop, vacant address)
  // The state when an alarm stopped the run: the alarmed block's modal words
  // (its F, S, T) are in force though it never finished (the status bar shows it).
  std::optional<StateSnapshot> alarmState;
};

}  // namespace klueng::core::machine

#pragma once
// The flow engine (issue 9, issue 30 item 4): which block runs next. It owns
// the program counter, the call stack (M98/M99, Haas M97, G65, G66/G67), the
// WHILE/DO/END loops and the endless-loop limits, and writes what it does into
// the run's FlowLog (call stacks, local frames, notices). The interpreter runs
// the blocks and asks it where to go; the macro store keeps the variables,
// whose local levels the calls push and pop. Private to machine.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/macro.h"
#include "klueng/core/gcode/program_index.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/flow.h"
#include "machine/loop_proof.h"
#include "machine/macro_store.h"

namespace klueng::core::machine {
class MachineSink;
}

namespace klueng::core::machine::detail {

// Moves the blocks run again may make, per block machine.cfg max_blocks allows.
inline constexpr long long kMovesPerRepeatedBlock = 10;

// One level of program flow: the main program, a subprogram (M98), a local
// subprogram (M97) or a macro (G65/G66) being run.
struct FlowFrame {
  CallFrame::Kind kind = CallFrame::Kind::Main;
  int program = 0;     // O number
  int section = 0;     // ProgramIndex section of the running program
  int entry = 0;       // block index where each pass starts
  int returnTo = -1;   // block index the caller continues at
  int callBlock = -1;  // block index of the call (M99 P searches the caller from here)
  int callFile = 0, callLine = 0;
  int repeat = 1, repeats = 1;
  int localLevel = 0;                          // index into the local-variable stack
  int localId = 0;                             // FlowLog local frame id
  std::array<int, 4> doBlock{-1, -1, -1, -1};  // the WHILE/DO block of each active loop 1-3
  MacroLocals arguments{};                     // G65/G66: each pass starts with these locals
};

// A call found in an NC block, performed after the block's motion.
struct PendingCall {
  enum class Kind { None, Subprogram, Local, Return } kind = Kind::None;
  gcode::CallTarget target;
  bool hasP = false;  // M99 P n
  SourceRange where;
  std::string text;
};

// The block making a call: where the callee returns to and what the FlowLog names.
struct CallSite {
  int blockIndex = 0;
  int file = 0, line = 0;
  int snapshot = 0;  // the index of the calling block's snapshot (its argument writes)
};

class FlowEngine {
 public:
  using AlarmFn = std::function<void(const Diagnostic&)>;

  FlowEngine(const gcode::Program& program, const gcode::MachineProfile& profile, MacroStore& macros, FlowLog* log,
             AlarmFn alarm);

  // Before the first block: the main program's frame, the loops matched.
  void start();

  // ---- the program counter ----------------------------------------------------
  // A block starts: the next one follows it unless flow says otherwise.
  void enter(int blockIndex) {
    current_ = blockIndex;
    next_ = blockIndex + 1;
    cameBack_ = jumpedBack_;
    jumpedBack_ = false;
  }
  int next() const { return next_; }
  void resumeAfter(int blockIndex) { next_ = blockIndex + 1; }  // G71-G73 skip their own profile
  bool ended() const { return ended_; }
  void end() { ended_ = true; }

  // ---- the call stack ---------------------------------------------------------
  const FlowFrame& frame() const { return frames_.back(); }
  int level() const { return static_cast<int>(frames_.size()) - 1; }
  int program() const { return frames_.empty() ? 0 : frames_.back().program; }
  int localLevel() const { return frames_.empty() ? 0 : frames_.back().localLevel; }
  int stackId() const { return stackId_; }  // FlowLog::stacks index of the current call stack
  const gcode::ProgramIndex& index() const { return index_; }

  // M98 / M97 / M99 of the running block, performed after its motion.
  void setPending(PendingCall call) { pending_ = std::move(call); }
  void clearPending() { pending_ = PendingCall{}; }
  bool hasPending() const { return pending_.kind != PendingCall::Kind::None; }
  bool performPending(const CallSite& site);

  bool call(CallFrame::Kind kind, int number, int repeats, const SourceRange& at, const std::string& text,
            const gcode::Block* arguments, const CallSite& site);
  // M99 (or the end of a subprogram's blocks); `sequence`: M99 P n.
  bool returnFromCall(std::optional<int> sequence, const SourceRange& at, const std::string& text);

  // G66 / G67: a macro called after each move of the blocks at this level.
  void setModalCall(int program, int repeats, const gcode::Block& arguments, const SourceRange& at,
                    const std::string& text);
  void cancelModalCall() { modalCall_.active = false; }
  bool modalCallActive() const { return modalCall_.active; }
  bool modalCallDue(bool moved) const { return modalCall_.active && moved && level() == modalCall_.level; }
  bool modalMacroCall(const CallSite& site);

  // ---- jumps and loops --------------------------------------------------------
  bool jumpTo(int sequence, const SourceRange& at, const std::string& text);
  // WHILE [..] DOm / DOm at the running block: enter the loop, or go past its END.
  bool loopStart(const gcode::Block& b, bool enter);
  // ENDm at the running block: back to its WHILE/DO.
  bool loopEnd(const gcode::Block& b);
  // The limits on a long run (blocks, time, moves run again), before the running block runs
  // (false: an alarm stopped the run).
  bool loopLimits(const gcode::Block& b, const io::MachineConfig& machine, const MachineSink& clock);
  // The running block was reached by a backward jump (GOTO, END, M99): the run's state here
  // goes to the proof of an endless loop (loop_proof.h).
  bool cameBack() const { return cameBack_; }
  // The flow's part of that state: the running block, the call stack, the modal macro call.
  void writeState(RunStateWords& out) const;
  // The run came back to the running block `b` in a state it was in before: it loops for
  // ever; the alarm stops it (false).
  bool stopEndlessLoop(const gcode::Block& b);
  bool loopStopped() const { return loopStopped_; }
  // A move made by the running block (blocks run again may make only so many).
  void noteMove() { repeatedMoves_ += repeating_; }

  // A run notice that does not stop the run (the FlowLog keeps the first 1000).
  void notice(Severity severity, const char* code, const SourceRange& at, std::vector<std::string> args);
  FlowLog* log() const { return log_; }

 private:
  bool alarm(const char* code, const SourceRange& at, std::vector<std::string> args);
  void matchLoops();
  void noteStack();
  void noteJump(const SourceRange& at, const std::string& text) {
    lastJumpAt_ = at;
    lastJumpText_ = text;
    jumpedBack_ = true;
  }
  // Stops a run that loops (or may loop) at the last backward jump: false.
  bool stopLoop(const char* code, const gcode::Block& b, std::vector<std::string> args);

  const gcode::Program& program_;
  const gcode::MachineProfile& profile_;
  MacroStore& macros_;
  FlowLog* log_;
  AlarmFn alarm_;
  gcode::ProgramIndex index_;
  std::vector<FlowFrame> frames_;
  std::vector<int> loopPartner_;  // WHILE/DO block -> its END, END -> its WHILE/DO (-1 none; empty: no loops)
  int partnerOf(int block) const {
    const auto i = static_cast<std::size_t>(block);
    return i < loopPartner_.size() ? loopPartner_[i] : -1;
  }
  std::vector<char> visited_;  // blocks run at least once (the endless-loop limit counts repeats)
  long long repeatedBlocks_ = 0;
  long long repeatedMoves_ = 0;  // moves made by blocks run again (bounded with max_blocks)
  bool repeating_ = false;       // the running block has run before
  bool loopStopped_ = false;     // a loop limit ended the run (even a run through alarms)
  SourceRange lastJumpAt_;       // the last backward jump (named by the loop alarms)
  std::string lastJumpText_;
  bool jumpedBack_ = false;  // a backward jump has set the next block
  bool cameBack_ = false;    // the running block was reached by one
  int current_ = 0;          // block index running
  int next_ = 0;             // block index to run next
  bool ended_ = false;
  int stackId_ = 0;
  int nextLocalId_ = 1;
  bool mainRepeated_ = false;  // M99 in the main program has looped once
  PendingCall pending_;
  struct ModalCall {
    bool active = false;
    int program = 0, repeats = 1, level = 0;
    gcode::Block arguments;
    SourceRange where;
    std::string text;
  } modalCall_;
};

}  // namespace klueng::core::machine::detail

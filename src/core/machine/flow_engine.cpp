// The flow engine (flow_engine.h): subprograms (M98/M99, Haas M97), macro
// calls (G65, G66/G67), GOTO and WHILE/DO/END, following the Fanuc 0i-TF
// manual's "Subprogram" and "Custom macro" chapters; Haas reads the same.
#include "machine/flow_engine.h"

#include <algorithm>
#include <cmath>

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/machine/sink.h"
#include "machine/number_text.h"

namespace klueng::core::machine::detail {

using gcode::Block;
using gcode::MacroValue;
using gcode::StatementKind;

namespace {

std::string flowLoopText(const Block& b) {
  return (b.statement().kind == StatementKind::End  ? "END"
          : b.statement().kind == StatementKind::Do ? "DO"
                                                    : "WHILE") +
         (b.statement().kind == StatementKind::While ? std::string() : std::to_string(b.statement().loop));
}

// Argument specification I (Fanuc): A B C -> #1 #2 #3, I J K -> #4 #5 #6,
// D E F -> #7 #8 #9, H -> #11, M -> #13, Q R S T U V W X Y Z -> #17 .. #26.
void flowSetArguments(const Block& b, MacroLocals& locals) {
  static constexpr int kArgument[26] = {1, 2, 3, 7,  8,  9,  0,  11, 4,  5,  6,  0,  13,
                                        0, 0, 0, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26};
  for (const gcode::Word& w : b.words) {
    if (w.letter < 'A' || w.letter > 'Z' || w.comma || w.expr >= 0) continue;
    const int n = kArgument[w.letter - 'A'];
    if (n == 0) continue;
    locals[static_cast<std::size_t>(n - 1)] = MacroValue::of(w.value);
  }
}

}  // namespace

FlowEngine::FlowEngine(const gcode::Program& program, const gcode::MachineProfile& profile, MacroStore& macros,
                       FlowLog* log, AlarmFn alarm)
    : program_(program), profile_(profile), macros_(macros), log_(log), alarm_(std::move(alarm)), index_(program) {}

bool FlowEngine::alarm(const char* code, const SourceRange& at, std::vector<std::string> args) {
  Diagnostic d;
  d.severity = Severity::Alarm;
  d.code = code;
  d.range = at;
  d.args = std::move(args);
  alarm_(d);
  return false;
}

void FlowEngine::notice(Severity severity, const char* code, const SourceRange& at, std::vector<std::string> args) {
  if (!log_) return;
  if (log_->notices.size() >= 1000) return;  // a loop repeating a notice stays readable
  log_->notices.push_back(Diagnostic{severity, code, at, std::move(args)});
}

void FlowEngine::start() {
  const int count = static_cast<int>(program_.blocks.size());
  visited_.assign(program_.blocks.size(), 0);
  matchLoops();
  FlowFrame main;
  main.section = count > 0 ? index_.sectionOf(0) : 0;
  main.program = count > 0 ? index_.section(main.section).number : 0;
  frames_.assign(1, main);
  if (log_) {
    log_->stacks.assign(1, std::vector<CallFrame>{CallFrame{CallFrame::Kind::Main, main.program}});
    log_->localFrames.assign(1, 0);
  }
  stackId_ = 0;
}

void FlowEngine::matchLoops() {
  // DO m ... END m pairs within each program (the checker reports the unmatched ones).
  // A program without WHILE, DO or END (most) needs no table: 400 KB on 100,000 blocks.
  loopPartner_.clear();
  const auto isLoop = [](const gcode::Block& b) {
    const StatementKind k = b.statement().kind;
    return k == StatementKind::While || k == StatementKind::Do || k == StatementKind::End;
  };
  if (std::none_of(program_.blocks.begin(), program_.blocks.end(), isLoop)) return;
  loopPartner_.assign(program_.blocks.size(), -1);
  for (const gcode::ProgramSection& s : index_.sections()) {
    std::vector<int> open;
    for (int i = s.first; i < s.end; ++i) {
      const gcode::Statement& st = program_.blocks[static_cast<std::size_t>(i)].statement();
      if (st.kind == StatementKind::While || st.kind == StatementKind::Do) {
        open.push_back(i);
      } else if (st.kind == StatementKind::End) {
        for (int k = static_cast<int>(open.size()) - 1; k >= 0; --k) {
          const int d = open[static_cast<std::size_t>(k)];
          if (program_.blocks[static_cast<std::size_t>(d)].statement().loop == st.loop) {
            loopPartner_[static_cast<std::size_t>(d)] = i;
            loopPartner_[static_cast<std::size_t>(i)] = d;
            open.resize(static_cast<std::size_t>(k));
            break;
          }
        }
      }
    }
  }
}

void FlowEngine::noteStack() {
  if (!log_) return;
  std::vector<CallFrame> stack;
  stack.reserve(frames_.size());
  for (const FlowFrame& f : frames_) {
    CallFrame c;
    c.kind = f.kind;
    c.program = f.program;
    c.callFile = f.callFile;
    c.callLine = f.callLine;
    c.repeat = f.repeat;
    c.repeats = f.repeats;
    c.locals = f.localId;
    stack.push_back(c);
  }
  auto same = [&](const std::vector<CallFrame>& other) {
    if (other.size() != stack.size()) return false;
    for (std::size_t i = 0; i < stack.size(); ++i) {
      const CallFrame &a = stack[i], &b = other[i];
      if (a.kind != b.kind || a.program != b.program || a.callFile != b.callFile || a.callLine != b.callLine ||
          a.repeat != b.repeat || a.repeats != b.repeats || a.locals != b.locals)
        return false;
    }
    return true;
  };
  // Calls repeat the same few stacks: look back a little before adding one.
  const int n = static_cast<int>(log_->stacks.size());
  for (int i = n - 1; i >= 0 && i >= n - 8; --i)
    if (same(log_->stacks[static_cast<std::size_t>(i)])) {
      stackId_ = i;
      return;
    }
  if (!stack.empty() && stack.size() == 1 && same(log_->stacks[0])) {
    stackId_ = 0;
    return;
  }
  log_->stacks.push_back(std::move(stack));
  stackId_ = static_cast<int>(log_->stacks.size()) - 1;
}

bool FlowEngine::stopLoop(const char* code, const Block& b, std::vector<std::string> args) {
  // The alarms name the last backward jump (else the block itself, an M99 repeat).
  loopStopped_ = true;
  args.insert(args.begin(), lastJumpText_.empty() ? std::string("M99") : lastJumpText_);
  return alarm(code, lastJumpAt_.line > 0 ? lastJumpAt_ : SourceRange{b.line, 1, 0, b.file}, std::move(args));
}

bool FlowEngine::loopLimits(const Block& b, const io::MachineConfig& m, const MachineSink& clock) {
  // Limits, not a proof that the run never ends (issue 42 item 6): the alarms say which
  // limit stopped the run and how to raise it; the interpreter's loopCanEnd (loop_proof.h)
  // proves the endless loops.
  // Blocks run again may also each make many moves (a G75 of 200,000 pecks in a
  // loop): what they make is bounded too, before it fills the memory.
  const long long moveBudget = kMovesPerRepeatedBlock * static_cast<long long>(m.maxBlocks);
  if (repeatedMoves_ > moveBudget)
    return stopLoop(codes::kMoveLimitReached, b,
                    {std::to_string(repeatedMoves_), std::to_string(m.maxBlocks), std::to_string(moveBudget)});
  const auto i = static_cast<std::size_t>(current_);
  repeating_ = visited_[i] != 0;
  if (visited_[i]) {
    if (++repeatedBlocks_ > m.maxBlocks)
      return stopLoop(codes::kBlockLimitReached, b, {std::to_string(repeatedBlocks_ - 1), std::to_string(m.maxBlocks)});
  } else {
    visited_[i] = 1;
  }
  // A time limit is no loop detector (issue 29 item 5): a program that has run no
  // block twice ends within its own length, however long it takes; only a run
  // that repeats blocks (through M99, GOTO, WHILE) is stopped by the clock.
  // Only while a block runs again: a subprogram called twice (M98 P1000 L2) followed by a long,
  // slow cut of the main program is no loop, and the clock does not stop it (issue 42 item 6).
  if (m.maxRunTime > 0.0 && repeating_ && clock.elapsed() > m.maxRunTime)
    return stopLoop(codes::kTimeLimitReached, b, {num(clock.elapsed()), num(m.maxRunTime)});
  return true;
}

void FlowEngine::writeState(RunStateWords& out) const {
  out.add(current_);
  out.add(mainRepeated_);
  out.add(static_cast<int>(pending_.kind));
  out.add(static_cast<int>(frames_.size()));
  // (A frame's localId only tells the FlowLog's frames apart: no state of the run.)
  for (const FlowFrame& f : frames_) {
    for (int v : {static_cast<int>(f.kind), f.program, f.section, f.entry, f.returnTo, f.callBlock, f.callFile,
                  f.callLine, f.repeat, f.repeats, f.localLevel})
      out.add(v);
    for (int d : f.doBlock) out.add(d);
    for (const MacroValue& v : f.arguments) out.add(v);
  }
  out.add(modalCall_.active);
  if (!modalCall_.active) return;
  for (int v : {modalCall_.program, modalCall_.repeats, modalCall_.level}) out.add(v);
  MacroLocals arguments{};  // what each call of the modal macro starts with
  flowSetArguments(modalCall_.arguments, arguments);
  for (const MacroValue& v : arguments) out.add(v);
}

bool FlowEngine::stopEndlessLoop(const Block& b) { return stopLoop(codes::kEndlessLoop, b, {std::to_string(b.line)}); }

bool FlowEngine::loopStart(const Block& b, bool enter) {
  const gcode::Statement& st = b.statement();
  const int end = partnerOf(current_);
  if (end < 0) return alarm(codes::kUnmatchedLoopEnd, st.range, {flowLoopText(b), "END" + std::to_string(st.loop)});
  if (enter)
    frames_.back().doBlock[static_cast<std::size_t>(st.loop)] = current_;
  else
    next_ = end + 1;
  return true;
}

bool FlowEngine::loopEnd(const Block& b) {
  const gcode::Statement& st = b.statement();
  const int start = partnerOf(current_);
  if (start < 0) return alarm(codes::kUnmatchedLoopEnd, st.range, {flowLoopText(b), "DO" + std::to_string(st.loop)});
  next_ = start;  // WHILE tests its condition again
  noteJump(st.range, flowLoopText(b));
  return true;
}

bool FlowEngine::jumpTo(int n, const SourceRange& at, const std::string& text) {
  const int target = index_.findSequence(frames_.back().section, n, current_);
  if (target < 0) return alarm(codes::kNoSuchSequence, at, {text, std::to_string(n)});
  if (target <= current_) noteJump(at, text);
  next_ = target;
  return true;
}

bool FlowEngine::performPending(const CallSite& site) {
  const PendingCall c = pending_;
  pending_ = PendingCall{};
  switch (c.kind) {
    case PendingCall::Kind::Subprogram:
      return call(CallFrame::Kind::Subprogram, c.target.number, c.target.repeats, c.where, c.text, nullptr, site);
    case PendingCall::Kind::Local:
      return call(CallFrame::Kind::Local, c.target.number, c.target.repeats, c.where, c.text, nullptr, site);
    case PendingCall::Kind::Return:
      return returnFromCall(c.hasP ? std::optional<int>(c.target.number) : std::nullopt, c.where, c.text);
    case PendingCall::Kind::None: return true;
  }
  return true;
}

bool FlowEngine::call(CallFrame::Kind kind, int number, int repeats, const SourceRange& at, const std::string& text,
                      const Block* arguments, const CallSite& site) {
  if (repeats <= 0) return true;  // L0: no call
  const bool macro = kind == CallFrame::Kind::Macro || kind == CallFrame::Kind::ModalMacro;
  int subLevels = 0, macroLevels = 0;
  for (const FlowFrame& f : frames_) {
    if (f.kind == CallFrame::Kind::Subprogram || f.kind == CallFrame::Kind::Local) ++subLevels;
    if (f.kind == CallFrame::Kind::Macro || f.kind == CallFrame::Kind::ModalMacro) ++macroLevels;
  }
  if (macro ? macroLevels >= profile_.flow.maxMacroNesting : subLevels >= profile_.flow.maxSubprogramNesting)
    return alarm(codes::kCallsTooDeep, at,
                 {text, std::to_string(macro ? profile_.flow.maxMacroNesting : profile_.flow.maxSubprogramNesting)});
  FlowFrame f;
  f.kind = kind;
  f.returnTo = next_;
  f.callBlock = site.blockIndex;
  f.callFile = site.file;
  f.callLine = site.line;
  f.repeats = repeats;
  if (kind == CallFrame::Kind::Local) {
    // M97 P n: the blocks from N n of the running program, up to its M99.
    f.section = frames_.back().section;
    f.program = frames_.back().program;
    f.entry = index_.findSequence(f.section, number, -1);
    if (f.entry < 0) return alarm(codes::kNoSuchSequence, at, {text, std::to_string(number)});
  } else {
    const gcode::ProgramSection* s = index_.program(number);
    if (!s) return alarm(codes::kNoSuchProgram, at, {text, std::to_string(number)});
    f.section = static_cast<int>(s - index_.sections().data());
    f.program = number;
    f.entry = s->first;
  }
  f.localLevel = frames_.back().localLevel;
  f.localId = frames_.back().localId;
  if (macro) {
    if (arguments) flowSetArguments(*arguments, f.arguments);
    f.localLevel = macros_.pushLevel(f.arguments);
    f.localId = nextLocalId_++;
    if (log_) {
      log_->localFrames.push_back(static_cast<int>(frames_.size()));
      // The arguments, as writes of the calling block into the new frame.
      for (int n = 1; n <= 33; ++n) {
        const MacroValue& v = f.arguments[static_cast<std::size_t>(n - 1)];
        if (!v.vacant) log_->writes.push_back(VariableWrite{site.snapshot, n, f.localId, v.value, false});
      }
    }
  }
  frames_.push_back(f);
  noteStack();
  next_ = f.entry;
  // The calling block's snapshot is already out; the call shows from the next block on.
  return true;
}

bool FlowEngine::returnFromCall(std::optional<int> sequence, const SourceRange& at, const std::string& text) {
  if (frames_.size() == 1) {
    // M99 in the main program: a control runs it again from the start (or
    // from N of P) for ever; the simulation repeats it once, then stops.
    if (mainRepeated_) {
      ended_ = true;
      return true;
    }
    mainRepeated_ = true;
    notice(Severity::Note, codes::kMainProgramRepeats, at, {});
    if (sequence) return jumpTo(*sequence, at, text);
    noteJump(at, text);
    next_ = index_.section(frames_.back().section).first;
    return true;
  }
  FlowFrame& f = frames_.back();
  if (f.repeat < f.repeats) {
    ++f.repeat;
    if (f.kind == CallFrame::Kind::Macro || f.kind == CallFrame::Kind::ModalMacro) {
      // Each pass of G65 ... L starts with the call's arguments again.
      macros_.resetLocals(f.localLevel, f.arguments);
    }
    noteStack();
    next_ = f.entry;
    noteJump(at, text);
    return true;
  }
  const FlowFrame done = f;
  frames_.pop_back();
  if (done.localLevel != frames_.back().localLevel) macros_.popLevel();
  noteStack();
  if (sequence) {
    // M99 P n: back to N n of the calling program instead of the block after the call.
    const int target = index_.findSequence(frames_.back().section, *sequence, done.callBlock);
    if (target < 0) return alarm(codes::kReturnTargetMissing, at, {text, std::to_string(*sequence)});
    if (target <= done.callBlock) noteJump(at, text);
    next_ = target;
    return true;
  }
  next_ = done.returnTo;
  return true;
}

void FlowEngine::setModalCall(int program, int repeats, const Block& arguments, const SourceRange& at,
                              const std::string& text) {
  modalCall_.active = true;
  modalCall_.program = program;
  modalCall_.repeats = repeats;
  modalCall_.level = level();
  modalCall_.arguments = arguments;
  modalCall_.where = at;
  modalCall_.text = text;
}

bool FlowEngine::modalMacroCall(const CallSite& site) {
  return call(CallFrame::Kind::ModalMacro, modalCall_.program, modalCall_.repeats, modalCall_.where, modalCall_.text,
              &modalCall_.arguments, site);
}

}  // namespace klueng::core::machine::detail

// Program flow (issue 9): the run loop, subprograms (M98/M99, Haas M97),
// custom macro B statements (#i=, IF, WHILE/DO/END, GOTO) and macro calls
// (G65, G66/G67), following the Fanuc 0i-TF manual's "Subprogram" and
// "Custom macro" chapters; Haas reads the same. Variables: interpreter_macro.cpp.
#include <cmath>

#include <string_view>

#include "klueng/core/gcode/word_format.h"
#include "machine/interpreter_impl.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine::detail {

using gcode::Block;
using gcode::MacroValue;
using gcode::StatementKind;

// A G65 / G66 / G67 block (the code table's macro call actions) runs as a call, not as motion.
bool isMacroCallBlock(const Block& b, gcode::Dialect dialect, CodeWord& g) {
  const CodeInfo* info = nullptr;
  const Word* w = gcode::macroCallWord(b, dialect, &info);
  if (w) g = {w, info};
  return w != nullptr;
}

namespace {

std::string statementText(const Block& b) {
  switch (b.statement.kind) {
    case StatementKind::Goto: return "GOTO";
    case StatementKind::If: return "IF";
    case StatementKind::While: return "WHILE";
    case StatementKind::Do: return "DO" + std::to_string(b.statement.loop);
    case StatementKind::End: return "END" + std::to_string(b.statement.loop);
    default: return "#";
  }
}

}  // namespace

bool Interpreter::flowAlarm(const char* code, const SourceRange& at, std::vector<std::string> args) {
  Diagnostic d;
  d.severity = Severity::Alarm;
  d.code = code;
  d.range = at;
  d.args = std::move(args);
  sink_->alarm(d);
  return false;
}

void Interpreter::notice(Severity severity, const char* code, const SourceRange& at, std::vector<std::string> args) {
  if (!flow_) return;
  if (flow_->notices.size() >= 1000) return;  // a loop repeating a notice stays readable
  flow_->notices.push_back(Diagnostic{severity, code, at, std::move(args)});
}

bool Interpreter::threadUnderCssAllowed(const Word* where) {
  if (modal_.spindleMode != SpindleMode::ConstantSurface) return true;
  if (profile_.threadUnderCssIsAlarm) return raise(codes::kThreadUnderConstantSurface, where, {});
  if (!threadCssWarned_)
    notice(Severity::Warning, codes::kThreadUnderCssWarning, where ? where->range : SourceRange{block_->line, 1, 0},
           {});
  threadCssWarned_ = true;
  return true;
}

void Interpreter::matchLoops() {
  // DO m ... END m pairs within each program (the checker reports the unmatched ones).
  loopPartner_.assign(program_.blocks.size(), -1);
  for (const gcode::ProgramSection& s : index_.sections()) {
    std::vector<int> open;
    for (int i = s.first; i < s.end; ++i) {
      const gcode::Statement& st = program_.blocks[static_cast<std::size_t>(i)].statement;
      if (st.kind == StatementKind::While || st.kind == StatementKind::Do) {
        open.push_back(i);
      } else if (st.kind == StatementKind::End) {
        for (int k = static_cast<int>(open.size()) - 1; k >= 0; --k) {
          const int d = open[static_cast<std::size_t>(k)];
          if (program_.blocks[static_cast<std::size_t>(d)].statement.loop == st.loop) {
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

void Interpreter::noteStack() {
  if (!flow_) return;
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
  const int n = static_cast<int>(flow_->stacks.size());
  for (int i = n - 1; i >= 0 && i >= n - 8; --i)
    if (same(flow_->stacks[static_cast<std::size_t>(i)])) {
      stackId_ = i;
      return;
    }
  if (!stack.empty() && stack.size() == 1 && same(flow_->stacks[0])) {
    stackId_ = 0;
    return;
  }
  flow_->stacks.push_back(std::move(stack));
  stackId_ = static_cast<int>(flow_->stacks.size()) - 1;
}

void Interpreter::run() {
  sink_->setPosition(pos_);
  const int count = static_cast<int>(program_.blocks.size());
  visited_.assign(program_.blocks.size(), 0);
  matchLoops();
  if (options_.persistentVariables) macros_.loadPersistent(*options_.persistentVariables);
  FlowFrame main;
  main.section = count > 0 ? index_.sectionOf(0) : 0;
  main.program = count > 0 ? index_.section(main.section).number : 0;
  frames_.assign(1, main);
  if (flow_) {
    flow_->stacks.assign(1, std::vector<CallFrame>{CallFrame{CallFrame::Kind::Main, main.program}});
    flow_->localFrames.assign(1, 0);
  }
  stackId_ = 0;

  int pc = 0;
  while (pc >= 0 && pc < count && !ended_ && !sink_->halted()) {
    // Leaving the running program's blocks: the next O block (or the end of
    // its file) ends the main program and returns from a subprogram.
    const gcode::ProgramSection& section = index_.section(frames_.back().section);
    if (pc >= section.end || pc < section.first) {
      if (frames_.size() == 1) break;
      block_ = &program_.blocks[static_cast<std::size_t>(section.end - 1)];
      if (!returnFromCall(
              std::nullopt,
              block_->words.empty() ? SourceRange{block_->line, 1, 0, block_->file} : block_->words.front().range,
              "M99"))
        break;
      pc = next_;
      continue;
    }
    const Block& b = program_.blocks[static_cast<std::size_t>(pc)];
    if (b.blockSkip && options_.blockSkip) {
      ++pc;
      continue;
    }
    if (!runBlock(pc)) {
      if (!options_.throughAlarms || loopStopped_) break;
      pc = blockIndex_ + 1;  // a record for evidence: on with the next block
      continue;
    }
    pc = next_;
  }
  // A chamfer or corner still waiting for its move when the program ends.
  if (corners_->holding() && !sink_->halted()) corners_->refuse();
  if (flow_ && sink_->halted() && block_ && !capture_) flow_->alarmState = snapshot();
  // The persistent variables go back to the caller (who keeps them in a file).
  if (options_.persistentVariables) macros_.savePersistent(*options_.persistentVariables);
  sink_->end();
}

bool Interpreter::loopLimits() {
  const auto& m = setup_.machine;
  // Blocks run again may also each make many moves (a G75 of 200,000 pecks in a
  // loop): what they make is bounded too, before it fills the memory.
  const long long moveBudget = kMovesPerRepeatedBlock * static_cast<long long>(m.maxBlocks);
  if (repeatedMoves_ > moveBudget)
    return flowAlarm(codes::kEndlessLoopMoves,
                     lastJumpAt_.line > 0 ? lastJumpAt_ : SourceRange{block_->line, 1, 0, block_->file},
                     {lastJumpText_.empty() ? std::string("M99") : lastJumpText_, std::to_string(repeatedMoves_),
                      std::to_string(m.maxBlocks), std::to_string(moveBudget)});
  repeating_ = visited_[static_cast<std::size_t>(blockIndex_)] != 0;
  if (visited_[static_cast<std::size_t>(blockIndex_)]) {
    if (++repeatedBlocks_ > m.maxBlocks)
      return flowAlarm(codes::kEndlessLoopBlocks,
                       lastJumpAt_.line > 0 ? lastJumpAt_ : SourceRange{block_->line, 1, 0, block_->file},
                       {lastJumpText_.empty() ? std::string("M99") : lastJumpText_, std::to_string(repeatedBlocks_ - 1),
                        std::to_string(m.maxBlocks)});
  } else {
    visited_[static_cast<std::size_t>(blockIndex_)] = 1;
  }
  // A time limit is no loop detector (issue 29 item 5): a program that has run no
  // block twice ends within its own length, however long it takes; only a run
  // that repeats blocks (through M99, GOTO, WHILE) is stopped by the clock.
  if (m.maxRunTime > 0.0 && repeatedBlocks_ > 0 && sink_->elapsed() > m.maxRunTime)
    return flowAlarm(
        codes::kEndlessLoopTime, lastJumpAt_.line > 0 ? lastJumpAt_ : SourceRange{block_->line, 1, 0, block_->file},
        {lastJumpText_.empty() ? std::string("M99") : lastJumpText_, num(sink_->elapsed()), num(m.maxRunTime)});
  return true;
}

bool Interpreter::runBlock(int index) {
  const Block& b = program_.blocks[static_cast<std::size_t>(index)];
  block_ = &b;
  blockIndex_ = index;
  next_ = index + 1;
  if (!loopLimits()) {
    loopStopped_ = true;
    return false;
  }
  if (b.statement.kind != StatementKind::None) {
    stopped_ = false;
    stopEndsRun_ = false;
    if (!statement(b)) return false;
    if (!sink_->halted()) emitSnapshot();
    return true;
  }
  if (b.hasExpressions && !evaluateWords(b)) return false;
  CodeWord g{};
  if (isMacroCallBlock(*block_, options_.dialect, g)) return macroCall(*block_, g);
  pending_ = PendingCall{};
  if (!executeBlock()) return false;
  if (resumeAfter_ >= 0) {  // G71-G73 skip their own profile
    next_ = resumeAfter_ + 1;
    resumeAfter_ = -1;
  }
  if (ended_) return true;
  if (pending_.kind != PendingCall::Kind::None) return performCall();
  if (modalCall_.active && movedThisBlock_ && static_cast<int>(frames_.size()) - 1 == modalCall_.level)
    return modalMacroCall();
  return true;
}

bool Interpreter::evaluate(int expr, const SourceRange& at, MacroValue& out) {
  if (expr < 0 || expr >= static_cast<int>(program_.expressions.size())) {
    out = MacroValue{};
    return true;
  }
  gcode::EvalResult r = gcode::evaluate(program_.expressions[static_cast<std::size_t>(expr)], *this);
  if (!r.ok) {
    SourceRange where = program_.expressions[static_cast<std::size_t>(expr)].range;
    if (where.line == 0) where = at;
    return flowAlarm(r.code, where, std::move(r.args));
  }
  out = r.value;
  return true;
}

// The block with every expression word replaced by its value; a vacant value
// omits the address, as the control does (with a notice).
bool Interpreter::evaluateWords(const Block& b) {
  scratch_.line = b.line;
  scratch_.blockSkip = b.blockSkip;
  scratch_.comment = b.comment;
  scratch_.file = b.file;
  scratch_.statement = b.statement;
  scratch_.hasExpressions = false;
  scratch_.letters = b.letters;  // its words are a subset of b's
  scratch_.words.clear();
  for (const Word& w : b.words) {
    if (w.expr < 0) {
      scratch_.words.push_back(w);
      continue;
    }
    MacroValue v;
    if (!evaluate(w.expr, w.range, v)) return false;
    if (flow_)
      flow_->wordValues.push_back(WordValue{snapshots_, w.range.file, w.range.line, w.range.column, v.value, v.vacant});
    if (v.vacant) {  // any address, a code word too, is left out
      notice(Severity::Warning, codes::kVacantAddressOmitted, w.range,
             {w.text(), w.number.substr(w.number.find('#') + 1), std::string(1, w.letter)});
      continue;
    }
    Word e = w;
    e.expr = -1;
    e.value = v.value;
    // A length takes the least input increment, as the control reads the address.
    if (std::string_view("XZUWIKRC").find(w.letter) != std::string_view::npos)
      e.value = gcode::roundToIncrement(
          v.value, profile_, modal_.units == Units::Inch ? gcode::InputUnits::Inch : gcode::InputUnits::Millimetre);
    e.hasDecimalPoint = true;
    e.number = gcode::macroNumberText(e.value);
    if (e.number.find('.') == std::string::npos) e.number += '.';
    const auto dot = e.number.find('.');
    e.decimals = static_cast<int>(e.number.size() - dot - 1);
    if (w.letter == 'G' || w.letter == 'M' || w.letter == 'T' || w.letter == 'N' || w.letter == 'O') {
      // Codes need whole values (G#1 with #1 = 1 runs G01).
      const double r = std::round(v.value);
      if (std::abs(r - v.value) > 1e-9 || std::abs(r) > 99999999.0)
        return flowAlarm(codes::kValueIsNoCode, w.range, {w.text(), gcode::macroNumberText(v.value)});
      e.value = r;
      e.hasDecimalPoint = false;
      e.decimals = 0;
      e.number = std::to_string(static_cast<long long>(r));
      if ((w.letter == 'G' || w.letter == 'M') && !gcode::findCode(w.letter, static_cast<int>(r), options_.dialect))
        return flowAlarm(codes::kValueIsNoCode, w.range, {w.text(), std::string(1, w.letter) + e.number});
    }
    scratch_.words.push_back(std::move(e));
  }
  block_ = &scratch_;
  return true;
}

bool Interpreter::statement(const Block& b) {
  const gcode::Statement& st = b.statement;
  MacroValue v;
  switch (st.kind) {
    case StatementKind::Assign: {
      MacroValue target;
      if (!evaluate(st.target, st.range, target) || !evaluate(st.value, st.range, v)) return false;
      return writeVariable(gcode::variableNumber(target.value), v, st.range);
    }
    case StatementKind::Goto: {
      if (!evaluate(st.value, st.range, v)) return false;
      if (v.vacant) return flowAlarm(codes::kVacantValueNeeded, st.range, {"GOTO", "GOTO"});
      return jumpTo(gcode::variableNumber(v.value), st.range, "GOTO" + gcode::macroNumberText(v.value));
    }
    case StatementKind::If: {
      MacroValue c;
      if (!evaluate(st.condition, st.range, c)) return false;
      if (c.vacant || c.value == 0.0) return true;
      if (st.then) {
        MacroValue target;
        if (!evaluate(st.target, st.range, target) || !evaluate(st.value, st.range, v)) return false;
        return writeVariable(gcode::variableNumber(target.value), v, st.range);
      }
      if (!evaluate(st.value, st.range, v)) return false;
      if (v.vacant) return flowAlarm(codes::kVacantValueNeeded, st.range, {"IF ... GOTO", "GOTO"});
      return jumpTo(gcode::variableNumber(v.value), st.range, "GOTO" + gcode::macroNumberText(v.value));
    }
    case StatementKind::While:
    case StatementKind::Do: {
      const int end = loopPartner_[static_cast<std::size_t>(blockIndex_)];
      if (end < 0)
        return flowAlarm(codes::kUnmatchedLoopEnd, st.range, {statementText(b), "END" + std::to_string(st.loop)});
      bool enter = true;
      if (st.kind == StatementKind::While) {
        MacroValue c;
        if (!evaluate(st.condition, st.range, c)) return false;
        enter = !c.vacant && c.value != 0.0;
      }
      if (enter)
        frames_.back().doBlock[static_cast<std::size_t>(st.loop)] = blockIndex_;
      else
        next_ = end + 1;
      return true;
    }
    case StatementKind::End: {
      const int start = loopPartner_[static_cast<std::size_t>(blockIndex_)];
      if (start < 0)
        return flowAlarm(codes::kUnmatchedLoopEnd, st.range, {statementText(b), "DO" + std::to_string(st.loop)});
      next_ = start;  // WHILE tests its condition again
      lastJumpAt_ = st.range;
      lastJumpText_ = statementText(b);
      return true;
    }
    case StatementKind::Output:  // DPRNT and friends print on the real control; nothing moves
    case StatementKind::None: return true;
  }
  return true;
}

bool Interpreter::jumpTo(int n, const SourceRange& at, const std::string& text) {
  const int target = index_.findSequence(frames_.back().section, n, blockIndex_);
  if (target < 0) return flowAlarm(codes::kNoSuchSequence, at, {text, std::to_string(n)});
  if (target <= blockIndex_) {
    lastJumpAt_ = at;
    lastJumpText_ = text;
  }
  next_ = target;
  return true;
}

bool Interpreter::performCall() {
  const PendingCall call = pending_;
  pending_ = PendingCall{};
  switch (call.kind) {
    case PendingCall::Kind::Subprogram:
      return callProgram(CallFrame::Kind::Subprogram, call.target.number, call.target.repeats, call.where, call.text,
                         nullptr);
    case PendingCall::Kind::Local:
      return callProgram(CallFrame::Kind::Local, call.target.number, call.target.repeats, call.where, call.text,
                         nullptr);
    case PendingCall::Kind::Return:
      return returnFromCall(call.hasP ? std::optional<int>(call.target.number) : std::nullopt, call.where, call.text);
    case PendingCall::Kind::None: return true;
  }
  return true;
}

bool Interpreter::callProgram(CallFrame::Kind kind, int number, int repeats, const SourceRange& at,
                              const std::string& text, const Block* arguments) {
  if (repeats <= 0) return true;  // L0: no call
  const bool macro = kind == CallFrame::Kind::Macro || kind == CallFrame::Kind::ModalMacro;
  int subLevels = 0, macroLevels = 0;
  for (const FlowFrame& f : frames_) {
    if (f.kind == CallFrame::Kind::Subprogram || f.kind == CallFrame::Kind::Local) ++subLevels;
    if (f.kind == CallFrame::Kind::Macro || f.kind == CallFrame::Kind::ModalMacro) ++macroLevels;
  }
  if (macro ? macroLevels >= profile_.flow.maxMacroNesting : subLevels >= profile_.flow.maxSubprogramNesting)
    return flowAlarm(
        codes::kCallsTooDeep, at,
        {text, std::to_string(macro ? profile_.flow.maxMacroNesting : profile_.flow.maxSubprogramNesting)});
  FlowFrame f;
  f.kind = kind;
  f.returnTo = next_;
  f.callBlock = blockIndex_;
  f.callFile = block_->file;
  f.callLine = block_->line;
  f.repeats = repeats;
  if (kind == CallFrame::Kind::Local) {
    // M97 P n: the blocks from N n of the running program, up to its M99.
    f.section = frames_.back().section;
    f.program = frames_.back().program;
    f.entry = index_.findSequence(f.section, number, -1);
    if (f.entry < 0) return flowAlarm(codes::kNoSuchSequence, at, {text, std::to_string(number)});
  } else {
    const gcode::ProgramSection* s = index_.program(number);
    if (!s) return flowAlarm(codes::kNoSuchProgram, at, {text, std::to_string(number)});
    f.section = static_cast<int>(s - index_.sections().data());
    f.program = number;
    f.entry = s->first;
  }
  f.localLevel = frames_.back().localLevel;
  f.localId = frames_.back().localId;
  if (macro) {
    if (arguments) setArguments(*arguments, f.arguments);
    f.localLevel = macros_.pushLevel(f.arguments);
    f.localId = nextLocalId_++;
    if (flow_) {
      flow_->localFrames.push_back(static_cast<int>(frames_.size()));
      // The arguments, as writes of the calling block into the new frame.
      for (int n = 1; n <= 33; ++n) {
        const MacroValue& v = f.arguments[static_cast<std::size_t>(n - 1)];
        if (!v.vacant) flow_->writes.push_back(VariableWrite{snapshots_, n, f.localId, v.value, false});
      }
    }
  }
  frames_.push_back(f);
  noteStack();
  next_ = f.entry;
  // The calling block's snapshot is already out; the call shows from the next block on.
  return true;
}

bool Interpreter::returnFromCall(std::optional<int> sequence, const SourceRange& at, const std::string& text) {
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
    lastJumpAt_ = at;
    lastJumpText_ = text;
    next_ = index_.section(frames_.back().section).first;
    return true;
  }
  FlowFrame& f = frames_.back();
  if (f.repeat < f.repeats) {
    ++f.repeat;
    if (f.kind == CallFrame::Kind::Macro || f.kind == CallFrame::Kind::ModalMacro) {
      // Each pass of G65 ... L starts with the call's arguments again.
      macros_.locals(f.localLevel) = f.arguments;
    }
    noteStack();
    next_ = f.entry;
    lastJumpAt_ = at;
    lastJumpText_ = text;
    return true;
  }
  const FlowFrame done = f;
  frames_.pop_back();
  if (done.localLevel != frames_.back().localLevel) macros_.popLevel();
  noteStack();
  if (sequence) {
    // M99 P n: back to N n of the calling program instead of the block after the call.
    const int target = index_.findSequence(frames_.back().section, *sequence, done.callBlock);
    if (target < 0) return flowAlarm(codes::kReturnTargetMissing, at, {text, std::to_string(*sequence)});
    if (target <= done.callBlock) {
      lastJumpAt_ = at;
      lastJumpText_ = text;
    }
    next_ = target;
    return true;
  }
  next_ = done.returnTo;
  return true;
}

// Argument specification I (Fanuc): A B C -> #1 #2 #3, I J K -> #4 #5 #6,
// D E F -> #7 #8 #9, H -> #11, M -> #13, Q R S T U V W X Y Z -> #17 .. #26.
void Interpreter::setArguments(const Block& b, std::array<MacroValue, 33>& locals) const {
  static constexpr int kArgument[26] = {1, 2, 3, 7,  8,  9,  0,  11, 4,  5,  6,  0,  13,
                                        0, 0, 0, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26};
  for (const Word& w : b.words) {
    if (w.letter < 'A' || w.letter > 'Z' || w.comma || w.expr >= 0) continue;
    const int n = kArgument[w.letter - 'A'];
    if (n == 0) continue;
    locals[static_cast<std::size_t>(n - 1)] = MacroValue::of(w.value);
  }
}

bool Interpreter::macroCall(const Block& b, const CodeWord& g) {
  const SourceRange at = g.word->range;
  const std::string text = "G" + std::to_string(g.info->number);
  emitSnapshot();
  if (g.info->action == CodeAction::MacroModalCancel) {
    modalCall_.active = false;
    return true;
  }
  // From this block's words: the letter index still describes the block before
  // (found by fuzz_macro: its pointers may be into a freed evaluation).
  const Word* p = nullptr;
  for (const Word& w : b.words)
    if (w.letter == 'P' && !w.comma && !p) p = &w;
  if (!p) return flowAlarm(codes::kNoSuchProgram, at, {text, "?"});
  const Word* l = nullptr;
  for (const Word& w : b.words)
    if (w.letter == 'L') l = &w;
  const CallTarget t = gcode::callTarget(p->value, l ? std::optional<double>(l->value) : std::nullopt, false);
  if (g.info->action == CodeAction::MacroModalCall) {
    // G66: the macro runs after each move of the following blocks until G67.
    if (!index_.program(t.number)) return flowAlarm(codes::kNoSuchProgram, at, {text, std::to_string(t.number)});
    modalCall_.active = true;
    modalCall_.program = t.number;
    modalCall_.repeats = t.repeats;
    modalCall_.level = static_cast<int>(frames_.size()) - 1;
    modalCall_.arguments = b;
    modalCall_.where = at;
    modalCall_.text = text;
    return true;
  }
  return callProgram(CallFrame::Kind::Macro, t.number, t.repeats, at, text, &b);
}

bool Interpreter::modalMacroCall() {
  return callProgram(CallFrame::Kind::ModalMacro, modalCall_.program, modalCall_.repeats, modalCall_.where,
                     modalCall_.text, &modalCall_.arguments);
}

}  // namespace klueng::core::machine::detail

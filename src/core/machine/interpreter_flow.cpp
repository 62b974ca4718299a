// The run loop and the custom macro B statements (#i=, IF, WHILE/DO/END,
// GOTO) and macro calls (G65, G66/G67) as the interpreter reads them: it
// evaluates their expressions; the flow engine (flow_engine.h) decides which
// block runs next and keeps the call stack. Variables: interpreter_macro.cpp.
#include <cmath>
#include <cstdint>
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

bool Interpreter::threadUnderCssAllowed(const Word* where) {
  if (modal_.spindleMode != SpindleMode::ConstantSurface) return true;
  if (profile_.threadUnderCssIsAlarm) return raise(codes::kThreadUnderConstantSurface, where, {});
  if (!threadCssWarned_)
    flow_.notice(Severity::Warning, codes::kThreadUnderCssWarning,
                 where ? where->range : SourceRange{block_->line, 1, 0}, {});
  threadCssWarned_ = true;
  return true;
}

void Interpreter::run() {
  sink_->setPosition(pos_);
  const int count = static_cast<int>(program_.blocks.size());
  if (options_.persistentVariables) macros_.loadPersistent(*options_.persistentVariables);
  flow_.start();

  int pc = 0;
  while (pc >= 0 && pc < count && !flow_.ended() && !sink_->halted()) {
    // Leaving the running program's blocks: the next O block (or the end of
    // its file) ends the main program and returns from a subprogram.
    const gcode::ProgramSection& section = flow_.index().section(flow_.frame().section);
    if (pc >= section.end || pc < section.first) {
      if (flow_.level() == 0) break;
      block_ = &program_.blocks[static_cast<std::size_t>(section.end - 1)];
      if (!flow_.returnFromCall(
              std::nullopt,
              block_->words.empty() ? SourceRange{block_->line, 1, 0, block_->file} : block_->words.front().range,
              "M99"))
        break;
      pc = flow_.next();
      continue;
    }
    const Block& b = program_.blocks[static_cast<std::size_t>(pc)];
    if (b.blockSkip && options_.blockSkip) {
      ++pc;
      continue;
    }
    if (!runBlock(pc)) {
      if (!options_.throughAlarms || flow_.loopStopped()) break;
      pc = blockIndex_ + 1;  // a record for evidence: on with the next block
      continue;
    }
    pc = flow_.next();
  }
  // A chamfer or corner still waiting for its move when the program ends.
  if (corners_->holding() && !sink_->halted()) corners_->refuse();
  if (flow_.log() && sink_->halted() && block_) flow_.log()->alarmState = snapshot();
  // The persistent variables go back to the caller (who keeps them in a file).
  if (options_.persistentVariables) macros_.savePersistent(*options_.persistentVariables);
  sink_->end();
}

bool Interpreter::runBlock(int index) {
  const Block& b = program_.blocks[static_cast<std::size_t>(index)];
  block_ = &b;
  blockIndex_ = index;
  flow_.enter(index);
  if (!flow_.loopLimits(b, setup_.machine, *sink_)) return false;
  if (flow_.cameBack() && !loopCanEnd()) return false;
  if (b.statement().kind != StatementKind::None) {
    stopped_ = false;
    stopEndsRun_ = false;
    if (!statement(b)) return false;
    if (!sink_->halted()) emitSnapshot();
    return true;
  }
  if (b.hasExpressions && !evaluateWords(b)) return false;
  CodeWord g{};
  if (isMacroCallBlock(*block_, options_.dialect, g)) return macroCall(*block_, g);
  flow_.clearPending();
  if (!executeBlock()) return false;
  if (resumeAfter_ >= 0) {  // G71-G73 skip their own profile
    flow_.resumeAfter(resumeAfter_);
    resumeAfter_ = -1;
  }
  if (flow_.ended()) return true;
  if (flow_.hasPending()) return flow_.performPending(callSite());
  if (flow_.modalCallDue(movedThisBlock_)) return flow_.modalMacroCall(callSite());
  return true;
}

bool Interpreter::loopCanEnd() {
  // Not proven here: a program that reads the clock (#3001 #3002), whose state then grows
  // with every pass, or a corner or compensated path still being worked out, which the
  // words below do not hold.
  if (macros_.clockRead() || corners_->holding() || modal_.noseComp != NoseCompMode::Off) return true;
  std::uint64_t quick = mixHash(macros_.valuesHash(), static_cast<std::uint64_t>(blockIndex_));
  quick = mixHash(mixHash(quick, bitsOf(pos_.x())), bitsOf(pos_.y()));
  const bool endless = loopProof_.seenBefore(quick, [this](RunStateWords& out) {
    flow_.writeState(out);
    macros_.writeState(out);
    writeState(out);
  });
  return !endless || flow_.stopEndlessLoop(*block_);
}

// Every field of ModalState, MachineState, DrillWords and CycleMemory: a field added to them is
// added here (a field left out could call a loop that ends endless).
void Interpreter::writeState(RunStateWords& out) const {
  for (int v : {static_cast<int>(modal_.motion), static_cast<int>(modal_.units), static_cast<int>(modal_.noseComp),
                static_cast<int>(modal_.spindleMode), static_cast<int>(modal_.feedMode), modal_.workCoordinate})
    out.add(v);
  for (double v : {modal_.feed, modal_.sWord, modal_.rpmClamp}) out.add(v);
  out.add(modal_.incremental);
  out.add(modal_.returnToRPoint);
  const MachineState& m = mach_;
  for (double v : {m.position.x(), m.position.y(), m.workShift.x(), m.workShift.y(), m.rpm, m.cAngle, m.offsetX,
                   m.offsetZ, m.noseRadius})
    out.add(v);
  for (int v : {m.tool, m.offset, m.tip, m.gearRange, static_cast<int>(m.spindle)}) out.add(v);
  for (bool v : {m.coolant, m.brake, m.cAxisMode, m.positionCheck, m.optionalStopSwitch, m.threadChamfer}) out.add(v);
  out.add(pos_.x());
  out.add(pos_.y());
  for (const std::optional<double>& g28 : {g28X_, g28Z_}) {
    out.add(g28.has_value());
    out.add(g28.value_or(0.0));
  }
  // The modal cycles: which (the code table's row) and their words.
  out.add(static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(singleCycle_)));
  for (double v : {singleTarget_.x(), singleTarget_.y(), singleTaper_}) out.add(v);
  out.add(static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(drillCycle_)));
  const cycles::DrillWords& d = drill_;
  out.add(static_cast<int>(d.g));
  for (double v : {d.hole.x(), d.hole.y(), d.rPlane, d.peck, d.firstPeck, d.reduce, d.minPeck, d.dwell, d.clearance,
                   d.initialLevel})
    out.add(v);
  out.add(d.repeats);
  out.add(d.returnToRPoint);
  const cycles::CycleMemory& c = cycleMemory_;
  for (double v : {c.g71Depth, c.g71Retract, c.g72Depth, c.g72Retract, c.g73ReliefX, c.g73ReliefZ, c.g74Retract,
                   c.g75Retract, c.g76Angle, c.g76MinDepth, c.g76Allowance})
    out.add(v);
  for (int v : {c.g73Count, c.g76Finishing, c.g76Chamfer}) out.add(v);
  // The offsets, where the program has written them (#2001.., G10).
  const bool offsetsWritten = offsets_.offsets != setup_.offsets.offsets;
  out.add(offsetsWritten);
  if (!offsetsWritten) return;
  for (const io::Offset& o : offsets_.offsets) {
    for (double v : {o.x, o.z, o.r}) out.add(v);
    out.add(o.tip);
  }
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
  scratch_.notes = b.notes;
  scratch_.file = b.file;
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
    if (FlowLog* log = flow_.log())
      log->wordValues.push_back(WordValue{snapshots_, w.range.file, w.range.line, w.range.column, v.value, v.vacant});
    if (v.vacant) {  // any address, a code word too, is left out
      flow_.notice(Severity::Warning, codes::kVacantAddressOmitted, w.range,
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
  const gcode::Statement& st = b.statement();
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
      return flow_.jumpTo(gcode::variableNumber(v.value), st.range, "GOTO" + gcode::macroNumberText(v.value));
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
      return flow_.jumpTo(gcode::variableNumber(v.value), st.range, "GOTO" + gcode::macroNumberText(v.value));
    }
    case StatementKind::While:
    case StatementKind::Do: {
      bool enter = true;
      if (st.kind == StatementKind::While) {
        MacroValue c;
        if (!evaluate(st.condition, st.range, c)) return false;
        enter = !c.vacant && c.value != 0.0;
      }
      return flow_.loopStart(b, enter);
    }
    case StatementKind::End: return flow_.loopEnd(b);
    case StatementKind::Output:  // DPRNT and friends print on the real control; nothing moves
    case StatementKind::None: return true;
  }
  return true;
}

bool Interpreter::macroCall(const Block& b, const CodeWord& g) {
  const SourceRange at = g.word->range;
  const std::string text = "G" + std::to_string(g.info->number);
  emitSnapshot();
  if (g.info->action == CodeAction::MacroModalCancel) {
    flow_.cancelModalCall();
    return true;
  }
  // From this block's words: the letter index still describes the block before
  // (found by fuzz_macro: its pointers may be into a freed evaluation).
  const Word* p = nullptr;
  for (const Word& w : b.words)
    if (w.letter == 'P' && !w.comma && !p) p = &w;
  if (!p) return flowAlarm(codes::kCallWithoutProgram, at, {text});  // not "program O?" (issue 42 item 6)
  const Word* l = nullptr;
  for (const Word& w : b.words)
    if (w.letter == 'L') l = &w;
  const CallTarget t = gcode::callTarget(p->value, l ? std::optional<double>(l->value) : std::nullopt, false);
  if (g.info->action == CodeAction::MacroModalCall) {
    // G66: the macro runs after each move of the following blocks until G67.
    if (!flow_.index().program(t.number)) return flowAlarm(codes::kNoSuchProgram, at, {text, std::to_string(t.number)});
    flow_.setModalCall(t.number, t.repeats, b, at, text);
    return true;
  }
  return flow_.call(CallFrame::Kind::Macro, t.number, t.repeats, at, text, &b, callSite());
}

}  // namespace klueng::core::machine::detail

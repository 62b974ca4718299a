// Program-flow rules checked before the run (issue 9; Fanuc 0i-TF manual,
// "Subprogram" and "Custom macro"): what can be known without running —
// loops that pair and nest, jump and call targets that exist, argument
// letters, and call chains deeper than the control allows. Targets given as
// expressions are checked when the program runs.
#include "flow_check.h"

#include <functional>
#include <map>
#include <optional>
#include <set>

#include "diagnostic_codes.h"
#include "klueng/core/gcode/program_index.h"

namespace klueng::core::gcode {

namespace {

std::optional<int> constantValue(const Program& program, int expr) {
  if (expr < 0 || expr >= static_cast<int>(program.expressions.size())) return std::nullopt;
  const Expression& e = program.expressions[static_cast<std::size_t>(expr)];
  if (e.code.size() != 1 || e.code[0].op != ExprOp::Constant) return std::nullopt;
  return static_cast<int>(e.code[0].value);
}

// The block's first G or M word whose code does `action` in `dialect` (the code
// table says which number that is: M97 is Haas only, G33 threads in system B).
const Word* actionWord(const Block& b, char letter, CodeAction action, Dialect dialect) {
  if (!b.mayHave(letter)) return nullptr;
  for (const Word& w : b.words) {
    if (w.letter != letter || w.expr >= 0 || w.hasDecimalPoint || w.comma) continue;
    const CodeInfo* row = findCode(letter, w.code(), dialect);
    if (row && row->action == action) return &w;
  }
  return nullptr;
}

const Word* constantWord(const Block& b, char letter) {
  const Word* w = b.find(letter);
  return w && w->expr < 0 ? w : nullptr;
}

struct Call {
  int section;       // the calling section
  int callee;        // the called section
  const Word* word;  // M98 / G65 / G66
  int block;
};

class FlowChecker {
 public:
  FlowChecker(const Program& program, const CheckOptions& options, std::vector<Diagnostic>& out)
      : program_(program), profile_(machineProfile(options.dialect)), out_(out), index_(program) {}

  void run() {
    for (std::size_t s = 0; s < index_.sections().size(); ++s) checkSection(static_cast<int>(s));
    checkDepth();
  }

 private:
  const Program& program_;
  const MachineProfile& profile_;
  std::vector<Diagnostic>& out_;
  ProgramIndex index_;
  std::vector<Call> calls_;
  std::vector<bool> hasConditions_;
  bool feedMayBeSet_ = true;     // some block before this one in the section may have given F
  std::set<int> profileStarts_;  // first profile blocks already looked at  // per section: IF/WHILE/GOTO/M99 P may end
                                 // a recursion

  void emit(const char* code, SourceRange range, std::vector<std::string> args) {
    if (out_.size() >= 10000) return;
    out_.push_back(Diagnostic{Severity::Error, code, range, std::move(args)});
  }

  void checkSection(int section) {
    const ProgramSection& s = index_.section(section);
    hasConditions_.resize(index_.sections().size(), false);
    struct Open {
      int loop;
      int block;
    };
    std::vector<Open> open;
    // A called program may run at its caller's feed: only the first program starts at feed zero.
    feedMayBeSet_ = section != 0 || s.first != 0;
    for (int i = s.first; i < s.end; ++i) {
      const Block& b = program_.blocks[static_cast<std::size_t>(i)];
      const Statement& st = b.statement();
      switch (st.kind) {
        case StatementKind::While:
        case StatementKind::Do:
          if (st.loop == 0) break;  // the lexer reported the number
          if (open.size() >= 3) emit(codes::kLoopsTooDeep, st.range, {std::to_string(st.loop)});
          open.push_back({st.loop, i});
          if (st.kind == StatementKind::While) hasConditions_[static_cast<std::size_t>(section)] = true;
          break;
        case StatementKind::End: {
          if (st.loop == 0) break;
          int match = -1;
          for (int k = static_cast<int>(open.size()) - 1; k >= 0; --k)
            if (open[static_cast<std::size_t>(k)].loop == st.loop) {
              match = k;
              break;
            }
          if (match < 0) {
            emit(codes::kEndWithoutDo, st.range, {std::to_string(st.loop)});
          } else {
            if (match != static_cast<int>(open.size()) - 1) {
              const Open& crossed = open.back();
              emit(codes::kLoopsCross, st.range,
                   {"END" + std::to_string(st.loop),
                    std::to_string(program_.blocks[static_cast<std::size_t>(crossed.block)].line)});
            }
            open.resize(static_cast<std::size_t>(match));
          }
          break;
        }
        case StatementKind::Goto:
        case StatementKind::If: {
          hasConditions_[static_cast<std::size_t>(section)] = true;
          if (st.kind == StatementKind::If && st.then) break;
          if (const auto n = constantValue(program_, st.value))
            if (index_.findSequence(section, *n, i) < 0) {
              // Point at the number after GOTO.
              SourceRange at = program_.expressions[static_cast<std::size_t>(st.value)].range;
              if (at.line == 0) at = st.range;
              emit(codes::kGotoNowhere, at, {"GOTO" + std::to_string(*n), std::to_string(*n)});
            }
          break;
        }
        default: break;
      }
      if (st.kind == StatementKind::None) {
        checkCalls(b, section, i);
        checkProfile(b, section, i);
      }
      // A feed may come from a block the walk cannot follow (a call, a jump, a macro value).
      if (st.kind != StatementKind::None || b.mayHave('F') || b.mayHave('P')) feedMayBeSet_ = true;
    }
    for (const Open& o : open) {
      const Block& b = program_.blocks[static_cast<std::size_t>(o.block)];
      emit(codes::kDoWithoutEnd, b.statement().range, {std::to_string(o.loop)});
    }
  }

  void checkCalls(const Block& b, int section, int index) {
    const Word* p = constantWord(b, 'P');
    const Word* lw = constantWord(b, 'L');
    const std::optional<double> l = lw ? std::optional<double>(lw->value) : std::nullopt;
    if (p) checkSubprogramCalls(b, p, l, section, index);
    const Word* g65 = actionWord(b, 'G', CodeAction::MacroCall, profile_.dialect);
    const Word* g66 = g65 ? nullptr : actionWord(b, 'G', CodeAction::MacroModalCall, profile_.dialect);
    const Word* g = g65 ? g65 : g66;
    if (!g || !profile_.flow.macroB) return;
    for (const Word& w : b.words) {
      if (&w == g || w.comma) continue;
      if (w.letter == 'G' || w.letter == 'O' || (w.letter == 'N' && &w != &b.words.front()))
        emit(codes::kBadMacroArgument, w.range, {w.text(), std::string(1, w.letter)});
    }
    if (!b.find('P')) {
      emit(codes::kCallWithoutP, g->range, {g->text()});  // not "program O?" (issue 42 item 6)
    } else if (p) {
      const CallTarget t = callTarget(p->value, l, false);
      if (const ProgramSection* callee = index_.program(t.number))
        calls_.push_back({section, static_cast<int>(callee - index_.sections().data()), g, index});
      else
        programNotFound(p->range, g->text() + " " + p->text(), t.number);
    }
  }

  // G70-G73 P Q with constant P and Q: both blocks exist (the run looks for
  // them as the interpreter does: P first after the cycle, else from the
  // program's start; Q at or after P), and where the machine wants it the
  // first block of the profile holds G00 or G01 (Fanuc 0i-TF PS0065).
  void checkProfile(const Block& b, int section, int index) {
    if (!b.mayHave('G')) return;  // (most blocks: their words are not read)
    const Word* g = nullptr;
    for (const Word& w : b.words) {
      if (w.letter != 'G' || w.expr >= 0 || w.hasDecimalPoint || w.comma) continue;
      const CodeInfo* info = findCode('G', w.code(), profile_.dialect);
      if (info && (info->action == CodeAction::Finishing || info->action == CodeAction::TurnRoughing ||
                   info->action == CodeAction::FaceRoughing || info->action == CodeAction::PatternRepeating))
        g = &w;
    }
    const Word* p = g ? constantWord(b, 'P') : nullptr;
    const Word* q = g ? constantWord(b, 'Q') : nullptr;
    if (!p || !q) return;  // Fanuc's first block (G71 U R), or values known at run time
    const int ns = index_.findSequence(section, p->code(), index);
    if (ns < 0) {
      emit(codes::kProfileBlockMissing, p->range, {g->text() + " " + p->text(), std::to_string(p->code())});
      return;
    }
    const int nf = index_.findSequence(section, q->code(), ns - 1);
    // N of Q found only above P: it exists, but the profile cannot end before it starts.
    if (nf >= 0 && nf < ns)
      emit(codes::kProfileEndsBeforeStart, q->range,
           {g->text() + " " + q->text(), std::to_string(q->code()), std::to_string(p->code())});
    else if (nf < ns)
      emit(codes::kProfileBlockMissing, q->range, {g->text() + " " + q->text(), std::to_string(q->code())});
    else if (ns <= index && index <= nf)
      // The shape would hold the cycle that reads it (Fanuc PS0066: a command not allowed in the shape).
      emit(codes::kProfileHoldsItsCycle, g->range,
           {g->text() + " " + p->text() + " " + q->text(), std::to_string(p->code()), std::to_string(q->code())});
    // A roughing cycle cuts at its own F or the modal one: none given yet is feed zero (Fanuc PS0011).
    const CodeInfo* row = findCode('G', g->code(), profile_.dialect);
    if (row && row->action != CodeAction::Finishing && !b.mayHave('F') && !feedMayBeSet_)
      emit(codes::kRoughingWithoutFeed, g->range, {g->text()});
    if (!profile_.cycles.profileFirstBlockNeedsG00G01 || !profileStarts_.insert(ns).second) return;
    const Block& first = program_.blocks[static_cast<std::size_t>(ns)];
    if (first.statement().kind != StatementKind::None || actionWord(first, 'G', CodeAction::Rapid, profile_.dialect) ||
        actionWord(first, 'G', CodeAction::Line, profile_.dialect))
      return;
    for (const Word& w : first.words)
      if (w.letter == 'G' && w.expr >= 0) return;  // a G code from a macro value: known at run time
    const SourceRange at = first.words.empty() ? SourceRange{first.line, 1, 0} : first.words.front().range;
    emit(codes::kProfileStartsWithoutMotion, at, {g->text() + " " + p->text(), std::to_string(p->code())});
  }

  // E404, or E416 when the folder has the program's file name as no file (a folder...).
  void programNotFound(const SourceRange& range, const std::string& call, int number) {
    for (const Program::NotAFile& n : program_.notProgramFiles) {
      if (n.number != number) continue;
      emit(codes::kProgramFileNotAFile, range,
           {call, std::to_string(number), n.name, n.folder ? "a folder" : "a pipe or a device",
            n.folder ? "โฟลเดอร์" : "ไปป์หรืออุปกรณ์"});
      return;
    }
    emit(codes::kProgramNotFound, range, {call, std::to_string(number)});
  }

  // M98 / M97 / M99 with a constant P (every M of the block is looked at only then).
  void checkSubprogramCalls(const Block& b, const Word* p, std::optional<double> l, int section, int index) {
    if (const Word* m98 = actionWord(b, 'M', CodeAction::SubprogramCall, profile_.dialect)) {
      const CallTarget t = callTarget(p->value, l, profile_.flow.packedRepeats);
      if (const ProgramSection* callee = index_.program(t.number))
        calls_.push_back({section, static_cast<int>(callee - index_.sections().data()), m98, index});
      else
        programNotFound(p->range, "M98 " + p->text(), t.number);
    }
    if (actionWord(b, 'M', CodeAction::LocalCall, profile_.dialect)) {
      const CallTarget t = callTarget(p->value, l, false);
      if (index_.findSequence(section, t.number, index) < 0)
        emit(codes::kLocalTargetMissing, p->range, {"M97 " + p->text(), std::to_string(t.number)});
    }
    if (actionWord(b, 'M', CodeAction::SubprogramReturn, profile_.dialect))
      hasConditions_[static_cast<std::size_t>(section)] = true;
  }

  // Call chains through constant calls: deeper than the control allows is an
  // error at the call that goes too deep; so is a recursion that nothing can end.
  void checkDepth() {
    const int n = static_cast<int>(index_.sections().size());
    std::vector<std::vector<const Call*>> out(static_cast<std::size_t>(n));
    for (const Call& c : calls_) out[static_cast<std::size_t>(c.section)].push_back(&c);
    std::vector<int> state(static_cast<std::size_t>(n), 0);  // 0 new, 1 on the path, 2 done
    std::vector<const Call*> path;
    bool reported = false;
    const int limit = profile_.flow.maxSubprogramNesting + profile_.flow.maxMacroNesting;
    long steps = 0;  // the walk is bounded whatever the call graph
    std::function<void(int)> visit = [&](int s) {
      if (reported || ++steps > 100000) return;
      state[static_cast<std::size_t>(s)] = 1;
      for (const Call* c : out[static_cast<std::size_t>(s)]) {
        if (reported) return;
        path.push_back(c);
        if (state[static_cast<std::size_t>(c->callee)] == 1) {
          // A cycle: fine when some program on it can stop calling (IF, WHILE, GOTO).
          bool conditional = false;
          for (const Call* k : path)
            conditional = conditional || hasConditions_[static_cast<std::size_t>(k->callee)] ||
                          hasConditions_[static_cast<std::size_t>(k->section)];
          if (!conditional) {
            emit(codes::kCallsTooDeep, c->word->range,
                 {c->word->text(), std::to_string(profile_.flow.maxSubprogramNesting)});
            reported = true;
          }
        } else if (static_cast<int>(path.size()) > limit) {
          emit(codes::kCallsTooDeep, c->word->range, {c->word->text(), std::to_string(limit)});
          reported = true;
        } else if (state[static_cast<std::size_t>(c->callee)] == 0 || static_cast<int>(path.size()) < limit) {
          visit(c->callee);
          state[static_cast<std::size_t>(c->callee)] = 0;  // other paths may reach it deeper
        }
        path.pop_back();
      }
      state[static_cast<std::size_t>(s)] = 2;
    };
    if (n > 0 && n <= 500) visit(0);
  }
};

}  // namespace

void checkFlow(const Program& program, const CheckOptions& options, std::vector<Diagnostic>& out) {
  FlowChecker(program, options, out).run();
}

}  // namespace klueng::core::gcode

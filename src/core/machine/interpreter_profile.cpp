// G70-G73 read their profile N(P)..N(Q) through the interpreter itself: the
// blocks run, from the cycle's start point, into a capturing sink instead of
// the chain, and the moves they make become the cycle's profile. So a profile
// block means what it means anywhere else: modal G00-G03, U/W, ,C/,R corners,
// ,A angles, macro values (X#1), G20. Then every bit of state is put back: the
// control reads the profile, it does not run it.
//
// What may stand in the profile follows the Fanuc 0i-TF manual (multiple
// repetitive cycles, "Limitations": no one-shot G code but G04, no other
// cycle, no subprogram or macro call); Haas reads its G71-G73 P..Q the same.
// F, S, T, G40-G42 and G04 take effect in G70 only (Fanuc: "F, S and T in
// blocks ns to nf are ignored in G71/G72/G73 and effective in G70").
#include "klueng/core/diagnostic_codes.h"
#include "machine/interpreter_impl.h"

namespace klueng::core::machine::detail {

using gcode::Block;

struct ProfileCapture final : MachineSink {
  ProfileCapture(bool withFeed, cycles::Profile& out, const MachineSink& chain, std::deque<Word>& words)
      : withFeed(withFeed), out(out), chain(chain), words(words) {}

  void motion(const MotionCall& m) override {
    cycles::Step s;
    s.kind = m.kind == MoveKind::Rapid ? cycles::StepKind::Rapid : cycles::StepKind::Feed;
    s.path = m.path;
    s.where = m.where;
    take(s);
    end_ = m.path.end;
    out.moves.push_back(s);
    out.blockOf.push_back(m.blockIndex);
  }
  void dwell(const DwellCall& d) override {
    if (!withFeed) return;
    cycles::Step s;
    s.kind = cycles::StepKind::Dwell;
    s.seconds = d.seconds;
    s.path = Segment::line(end_, end_);
    out.moves.push_back(s);
    out.blockOf.push_back(d.blockIndex);
  }
  void setPosition(const Vec2&) override {}  // G50 is refused in a profile
  void compensation(NoseCompMode mode, double, int) override {
    if (!withFeed) return;
    cycles::Step s;
    s.kind = cycles::StepKind::Compensation;
    s.comp = mode;
    s.path = Segment::line(end_, end_);
    out.moves.push_back(s);
    out.blockOf.push_back(block);
  }
  void blockDone(const StateSnapshot&) override {}
  void alarm(const Diagnostic& d) override {
    if (!alarmSeen) alarmSeen = d;
  }
  void end() override {}
  bool halted() const override { return alarmSeen.has_value(); }
  double elapsed() const override { return chain.elapsed(); }

  // F, S, T of a G70 profile apply from the block's move on, when the cycle runs.
  void feed(double mm) {
    if (withFeed) pendingFeed = mm;
  }
  void speed(const Word& s) {
    if (withFeed) pendingS = &words.emplace_back(s);
  }
  void tool(const Word& t) {
    if (withFeed) pendingT = &words.emplace_back(t);
  }
  void take(cycles::Step& s) {
    s.feed = pendingFeed;
    s.sWord = pendingS;
    s.tWord = pendingT;
    pendingFeed = 0.0;
    pendingS = pendingT = nullptr;
  }

  const bool withFeed;
  cycles::Profile& out;
  const MachineSink& chain;
  std::deque<Word>& words;
  std::optional<Diagnostic> alarmSeen;
  double pendingFeed = 0.0;
  const Word* pendingS = nullptr;
  const Word* pendingT = nullptr;
  Vec2 end_ = Vec2::Zero();
  int block = 0;
};

// A block the profile may not hold: `what` names it.
bool Interpreter::profileOnly(const char* what, const Word* where) {
  return raise(codes::kProfileCommandNotAllowed, where, {what, std::to_string(block_->line)});
}

bool Interpreter::profileBlockAllowed(const CodeWord* motion, const CodeWord* cycle, const CodeWord* oneShot,
                                      const CodeWord* single) {
  for (const CodeWord* c : {cycle, single})
    if (c) return profileOnly(wordText(*c->word).c_str(), c->word);
  if (motion && motion->info->action == CodeAction::Thread)
    return profileOnly(wordText(*motion->word).c_str(), motion->word);
  if (oneShot && oneShot->info->action != CodeAction::Dwell)
    return profileOnly(wordText(*oneShot->word).c_str(), oneShot->word);
  return true;
}

// A T in a G70 profile: its offset counts from this block's own target on,
// and the cycle changes the tool when it gets there. The roughing cycles ignore it.
bool Interpreter::captureTool(const Word& t) {
  if (!capture_->withFeed) return true;
  capture_->tool(t);
  const int number = gcode::splitToolNumber(t.code()).offset;
  if (number == 0) {
    mach_.offsetX = mach_.offsetZ = 0.0;
  } else if (number > 0 && number <= io::kOffsetCount) {  // a negative T (a typing slip the check reports) names none
    const io::Offset& o = offsets_.at(number);
    mach_.offsetX = o.x;
    mach_.offsetZ = o.z;
  }
  return true;
}

void Interpreter::captureFeed(double mm) { capture_->feed(mm); }
void Interpreter::captureSpeed(const Word& s) { capture_->speed(s); }

std::optional<cycles::CycleAlarm> Interpreter::readProfile(const Block& cycle, const Word* g, bool withFeed,
                                                           cycles::Profile& out) {
  const std::string name = g ? wordText(*g) : "G7x";
  auto alarmAt = [&](const char* code, const Word* w, std::vector<std::string> args) {
    return cycles::CycleAlarm{code, w ? w->range : SourceRange{cycle.line, 1, 0}, std::move(args)};
  };
  const Word* pw = cycle.find('P');
  const Word* qw = cycle.find('Q');
  if (!pw || !qw) return alarmAt(codes::kCycleNeedsPAndQ, g, {name});
  // The program's own sequence index: P the first N after the cycle (else the
  // first in the program), Q the first at or after P.
  const int section = index_.sectionOf(blockIndex_);
  out.ns = index_.findSequence(section, pw->code(), blockIndex_);
  if (out.ns < 0) return alarmAt(codes::kNoProfileBlock, pw, {name, "P", pw->number.str()});
  // Fanuc 0i-TF (PS0065): the profile's first block must hold G00 or G01.
  if (profile_.cycles.profileFirstBlockNeedsG00G01) {
    const Block& first = program_.blocks[static_cast<std::size_t>(out.ns)];
    bool motion = first.statement.kind != gcode::StatementKind::None;  // refused below (A148)
    for (const Word& w : first.words)
      motion =
          motion || (w.letter == 'G' && (w.expr >= 0 || gcode::actionOf(w, options_.dialect) == CodeAction::Rapid ||
                                         gcode::actionOf(w, options_.dialect) == CodeAction::Line));
    if (!motion)
      return cycles::CycleAlarm{codes::kProfileStartsWithoutMotion,
                                first.words.empty() ? SourceRange{first.line, 1, 0} : first.words.front().range,
                                {name + " " + wordText(*pw), std::to_string(pw->code())}};
  }
  out.nf = index_.findSequence(section, qw->code(), out.ns - 1);
  if (out.nf < out.ns) out.nf = -1;
  if (out.nf < 0) return alarmAt(codes::kNoProfileBlock, qw, {name, "Q", qw->number.str()});
  if (capture_) return alarmAt(codes::kProfileCommandNotAllowed, g, {name, std::to_string(cycle.line)});

  // Everything a block can change, put back when the profile has been read.
  const ModalState modal = modal_;
  const MachineState mach = mach_;
  const Vec2 pos = pos_;
  const gcode::Block* block = block_;
  const auto byLetter = byLetter_;
  const int blockIndex = blockIndex_, next = next_, resumeAfter = resumeAfter_;
  const bool movedThisBlock = movedThisBlock_, stopped = stopped_, stopEndsRun = stopEndsRun_,
             optionalStop = optionalStopBlock_;
  const PendingCorner corner = corner_;
  const CodeInfo* single = singleCycle_;
  const Vec2 singleTarget = singleTarget_;
  const double singleTaper = singleTaper_;
  const CodeInfo* drilling = drillCycle_;
  const std::optional<double> g28X = g28X_, g28Z = g28Z_;
  MachineSink* chain = sink_;
  gcode::Block scratch;
  std::swap(scratch, scratch_);  // the cycle block's evaluated words stay where `cycle` points

  profileWords_.clear();
  ProfileCapture capture(withFeed, out, *chain, profileWords_);
  capture.end_ = pos_;
  sink_ = &capture;
  capture_ = &capture;
  corner_ = PendingCorner{};
  singleCycle_ = nullptr;
  drillCycle_ = nullptr;
  for (int i = out.ns; i <= out.nf && !capture.halted(); ++i) {
    const Block& b = program_.blocks[static_cast<std::size_t>(i)];
    if (b.blockSkip && options_.blockSkip) continue;
    block_ = &b;
    blockIndex_ = i;
    capture.block = i;
    if (b.statement.kind != gcode::StatementKind::None) {
      raise(codes::kProfileHasMacro, g, {name, std::to_string(b.line)});
      break;
    }
    if (b.hasExpressions && !evaluateWords(b)) break;
    CodeWord call{};
    if (isMacroCallBlock(*block_, options_.dialect, call)) {
      profileOnly(call.word->text().c_str(), call.word);
      break;
    }
    if (!executeBlock()) break;
  }
  if (!capture.halted() && corner_.active) cornerNeedsMove();

  sink_ = chain;
  capture_ = nullptr;
  std::swap(scratch, scratch_);
  modal_ = modal;
  mach_ = mach;
  pos_ = pos;
  block_ = block;
  byLetter_ = byLetter;
  blockIndex_ = blockIndex;
  next_ = next;
  resumeAfter_ = resumeAfter;
  movedThisBlock_ = movedThisBlock;
  stopped_ = stopped;
  stopEndsRun_ = stopEndsRun;
  optionalStopBlock_ = optionalStop;
  corner_ = corner;
  singleCycle_ = single;
  singleTarget_ = singleTarget;
  singleTaper_ = singleTaper;
  drillCycle_ = drilling;
  g28X_ = g28X;
  g28Z_ = g28Z;

  if (capture.alarmSeen)
    return cycles::CycleAlarm{capture.alarmSeen->code, capture.alarmSeen->range, capture.alarmSeen->args};
  // Only moves count for the roughing cycles.
  const auto moves = std::count_if(out.moves.begin(), out.moves.end(), [](const cycles::Step& s) {
    return s.kind == cycles::StepKind::Rapid || s.kind == cycles::StepKind::Feed;
  });
  if (moves < 2) return alarmAt(codes::kProfileHasNoMoves, pw, {name, pw->number.str(), qw->number.str()});
  return std::nullopt;
}

}  // namespace klueng::core::machine::detail

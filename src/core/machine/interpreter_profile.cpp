// G70-G73 read their profile N(P)..N(Q) through the interpreter itself: the
// blocks run, from the cycle's start point, into a capturing sink instead of
// the chain (profile_capture.h), and the moves they make become the cycle's
// profile. So a profile block means what it means anywhere else: modal
// G00-G03, U/W, ,C/,R corners, ,A angles, macro values (X#1), G20. The
// capture is also the blocks' BlockEffects: it says what a profile may hold
// and keeps its F, S and T for G70. Then every bit of state is put back: the
// control reads the profile, it does not run it. Haas reads its G71-G73 P..Q
// the same.
#include "klueng/core/diagnostic_codes.h"
#include "machine/interpreter_impl.h"
#include "machine/profile_capture.h"

namespace klueng::core::machine::detail {

using gcode::Block;

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
  const gcode::ProgramIndex& index = flow_.index();
  const int section = index.sectionOf(blockIndex_);
  out.ns = index.findSequence(section, pw->code(), blockIndex_);
  if (out.ns < 0) return alarmAt(codes::kNoProfileBlock, pw, {name, "P", pw->number.str()});
  // Fanuc 0i-TF (PS0065): the profile's first block must hold G00 or G01.
  if (profile_.cycles.profileFirstBlockNeedsG00G01) {
    const Block& first = program_.blocks[static_cast<std::size_t>(out.ns)];
    bool motion = first.statement().kind != gcode::StatementKind::None;  // refused below (A148)
    for (const Word& w : first.words)
      motion =
          motion || (w.letter == 'G' && (w.expr >= 0 || gcode::actionOf(w, options_.dialect) == CodeAction::Rapid ||
                                         gcode::actionOf(w, options_.dialect) == CodeAction::Line));
    if (!motion)
      return cycles::CycleAlarm{codes::kProfileStartsWithoutMotion,
                                first.words.empty() ? SourceRange{first.line, 1, 0} : first.words.front().range,
                                {name + " " + wordText(*pw), std::to_string(pw->code())}};
  }
  out.nf = index.findSequence(section, qw->code(), out.ns - 1);
  if (out.nf < out.ns) out.nf = -1;
  if (out.nf < 0) return alarmAt(codes::kNoProfileBlock, qw, {name, "Q", qw->number.str()});
  // (A cycle in a profile is refused before it reads one: ProfileCapture::blockAllowed.)

  // Everything a block can change, put back when the profile has been read.
  const ModalState modal = modal_;
  const MachineState mach = mach_;
  const Vec2 pos = pos_;
  const gcode::Block* block = block_;
  const auto byLetter = byLetter_;
  const int blockIndex = blockIndex_, resumeAfter = resumeAfter_, snapshots = snapshots_;
  const bool movedThisBlock = movedThisBlock_, stopped = stopped_, stopEndsRun = stopEndsRun_,
             optionalStop = optionalStopBlock_;
  const CodeInfo* single = singleCycle_;
  const Vec2 singleTarget = singleTarget_;
  const double singleTaper = singleTaper_;
  const CodeInfo* drilling = drillCycle_;
  const std::optional<double> g28X = g28X_, g28Z = g28Z_;
  MachineSink* chain = sink_;
  gcode::Block scratch;
  std::swap(scratch, scratch_);  // the cycle block's evaluated words stay where `cycle` points

  profileWords_.clear();
  ProfileCapture capture(withFeed, out, *chain, profileWords_, mach_, offsets_, pos_);
  // A corner held before the cycle stays held in the run's stage; the profile's own go through a stage of its own.
  CornerStage corners(capture, [this](const Segment& s, const SourceRange& at) { return pathWithinTravel(s, at); });
  CornerStage* runCorners = corners_;
  corners_ = &corners;
  sink_ = &corners;
  effects_ = &capture;
  singleCycle_ = nullptr;
  drillCycle_ = nullptr;
  for (int i = out.ns; i <= out.nf && !capture.halted(); ++i) {
    const Block& b = program_.blocks[static_cast<std::size_t>(i)];
    if (b.blockSkip && options_.blockSkip) continue;
    block_ = &b;
    blockIndex_ = i;
    capture.startBlock(i, b.line);
    if (b.statement().kind != gcode::StatementKind::None) {
      raise(codes::kProfileHasMacro, g, {name, std::to_string(b.line)});
      break;
    }
    if (b.hasExpressions && !evaluateWords(b)) break;
    CodeWord call{};
    if (isMacroCallBlock(*block_, options_.dialect, call)) {
      capture.refuse(call.word->text(), call.word);
      break;
    }
    if (!executeBlock()) break;
  }
  if (!capture.halted() && corners.holding()) corners.refuse();

  sink_ = chain;
  corners_ = runCorners;
  effects_ = this;
  snapshots_ = snapshots;
  std::swap(scratch, scratch_);
  modal_ = modal;
  mach_ = mach;
  pos_ = pos;
  block_ = block;
  byLetter_ = byLetter;
  blockIndex_ = blockIndex;
  resumeAfter_ = resumeAfter;
  movedThisBlock_ = movedThisBlock;
  stopped_ = stopped;
  stopEndsRun_ = stopEndsRun;
  optionalStopBlock_ = optionalStop;
  singleCycle_ = single;
  singleTarget_ = singleTarget;
  singleTaper_ = singleTaper;
  drillCycle_ = drilling;
  g28X_ = g28X;
  g28Z_ = g28Z;

  if (const auto& seen = capture.alarmSeen()) return cycles::CycleAlarm{seen->code, seen->range, seen->args};
  // Only moves count for the roughing cycles.
  const auto moves = std::count_if(out.moves.begin(), out.moves.end(), [](const cycles::Step& s) {
    return s.kind == cycles::StepKind::Rapid || s.kind == cycles::StepKind::Feed;
  });
  if (moves < 2) return alarmAt(codes::kProfileHasNoMoves, pw, {name, pw->number.str(), qw->number.str()});
  return std::nullopt;
}

}  // namespace klueng::core::machine::detail

// The cycles inside the interpreter: G90/G92/G94 single cycles, G70-G76 in
// the profile's form (Fanuc two-block, Haas one-block) and G81-G83 drilling.
// cycles.h expands them into simple moves; they go down the ordinary chain
// with the ordinary checks, all carrying the cycle block's line.
#include "machine/interpreter_impl.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine::detail {

// A cycle under G41/G42: an alarm where the machine file says so (A123, the 1999 rules); on a Fanuc
// or Haas it runs (no manual found says it stops), with W134 once a run (docs/dialects.md §10).
bool Interpreter::compensationAllowed(const Word* g) {
  if (modal_.noseComp == NoseCompMode::Off) return true;
  if (profile_.cycleUnderCompensationIsAlarm) return raise(codes::kCycleUnderNoseComp, g, {wordText(*g)});
  if (!cycleCompWarned_) flow_.notice(Severity::Warning, codes::kCycleRunsUncompensated, g->range, {wordText(*g)});
  cycleCompWarned_ = true;
  return true;
}

// The cycle's own passes on the programmed shape: the compensation stage cancels on the cycle's
// first move and starts again on the first move after it, as a G40 before and a G41/G42 after
// the cycle would.
bool Interpreter::emitUncompensated(const std::vector<cycles::Step>& steps, const Word* g, const std::string& name) {
  const NoseCompMode held = modal_.noseComp;
  if (held == NoseCompMode::Off) return emitCycle(steps, g, name);
  sink_->compensation(NoseCompMode::Off, mach_.noseRadius, mach_.tip);
  const bool done = emitCycle(steps, g, name);
  if (modal_.noseComp == held) sink_->compensation(held, mach_.noseRadius, mach_.tip);
  return done;
}

bool Interpreter::singleCycle(const Word* where, bool fresh) {
  const double u = unit();
  if (fresh) {
    singleTarget_ = pos_;
    singleTaper_ = 0.0;
  }
  if (!hasAxisWords() && fresh) return true;  // G90 alone: the mode only
  if (!compensationAllowed(where)) return false;
  Vec2 target = singleTarget_;
  const Vec2 off = offsetVector();
  if (const Word* w = find('X')) target.y() = w->value * u / 2.0 + off.y();
  if (const Word* w = find('U')) target.y() = xOf(pos_) + w->value * u / 2.0;
  if (const Word* w = find('Z')) target.x() = w->value * u + off.x();
  if (const Word* w = find('W')) target.x() = zOf(pos_) + w->value * u;
  if (const Word* r = find('R')) singleTaper_ = r->value * u;  // G90/G92: radius; G94: Z
  singleTarget_ = target;
  return emitUncompensated(cycles::singleCycle(singleCycle_->action, pos_, target, singleTaper_, modal_.feed), where,
                           fmt::format("G{}", singleCycle_->number));
}

cycles::CycleInput Interpreter::cycleInput(const Word* g) const {
  cycles::CycleInput in;
  in.program = &program_;
  in.blockIndex = blockIndex_;
  in.block = block_;
  in.readProfile = &profileReader_;
  in.gWord = g;
  in.start = pos_;
  in.offset = offsetVector();
  in.offsets = &offsets_;
  in.unit = unit();
  in.feed = modal_.feed;
  in.motion = modal_.motion;
  in.blockSkip = options_.blockSkip;
  in.profile = &profile_;
  in.threadChamfer = mach_.threadChamfer;
  in.returnToRPoint = modal_.returnToRPoint;
  return in;
}

bool Interpreter::cycleAlarm(const cycles::CycleAlarm& a) {
  Diagnostic d;
  d.severity = Severity::Alarm;
  d.code = a.code;
  d.range = a.where;
  d.args = a.args;
  sink_->alarm(d);
  return false;
}

// G70-G76 in the profile's form, or a drilling cycle G81-G83.
bool Interpreter::cannedCycle(const CodeWord& c) {
  const CodeAction a = c.info->action;
  if (a == CodeAction::Drilling || a == CodeAction::SpotDrilling || a == CodeAction::PeckDrilling)
    return drillingCycle(*c.info, c.word, true);
  if (a != CodeAction::Finishing && !compensationAllowed(c.word)) return false;
  const cycles::CycleInput in = cycleInput(c.word);
  cycles::Expansion e = profile_.cycleForm == gcode::CycleForm::OneBlock ? cycles::expandOneBlock(*c.info, in)
                                                                         : cycles::expand(*c.info, in, cycleMemory_);
  if (e.alarm) return cycleAlarm(*e.alarm);
  const bool emitted = a == CodeAction::Finishing ? emitCycle(e.steps, c.word, wordText(*c.word))
                                                  : emitUncompensated(e.steps, c.word, wordText(*c.word));
  if (!emitted) return false;
  resumeAfter_ = e.resumeAfter;
  return true;
}

// G81/G82/G83: `fresh` for the cycle's own block, else a later block with
// only a hole position (the cycle is modal until G80 or a group 01 code).
bool Interpreter::drillingCycle(const CodeInfo& g, const Word* where, bool fresh) {
  if (!compensationAllowed(where)) return false;
  const cycles::CycleInput in = cycleInput(where);
  if (auto a = cycles::readDrillWords(g, in, fresh, drill_)) return cycleAlarm(*a);
  drillCycle_ = &g;
  return emitUncompensated(cycles::drill(drill_, pos_), where, fmt::format("G{}", g.number));
}

bool Interpreter::cycleReady(const std::vector<cycles::Step>& steps, const Word* g, const std::string& name) {
  double feed = modal_.feed;
  bool sSet = modal_.sWord > 0.0;
  for (const cycles::Step& s : steps) {
    Word at;
    const Word* where = g;
    if (s.where.line != 0) {
      at.range = s.where;
      where = &at;
    }
    if (s.feed > 0.0) feed = s.feed;
    if (s.sWord && s.sWord->value > 0.0) sSet = true;
    if (s.kind == cycles::StepKind::Feed) {
      if (feed <= 0.0 && !cuttingCondition(codes::kNoFeed, where, {name})) return false;
      if (modal_.feedMode == FeedMode::PerRev) {
        if (mach_.spindle == SpindleDir::Stopped && !cuttingCondition(codes::kFeedPerRevSpindleStopped, where, {name}))
          return false;
        if (!sSet && !cuttingCondition(codes::kFeedPerRevWithoutSpeed, where, {name})) return false;
      }
    } else if (s.kind == cycles::StepKind::Thread) {
      if (s.lead <= 0.0 && !cuttingCondition(codes::kNoFeed, where, {name})) return false;
      if (!threadUnderCssAllowed(where)) return false;
      if (mach_.spindle == SpindleDir::Stopped && !cuttingCondition(codes::kThreadSpindleStopped, where, {}))
        return false;
      if (!sSet && !cuttingCondition(codes::kThreadWithoutSpeed, where, {})) return false;
    }
  }
  return true;
}

bool Interpreter::emitCycle(const std::vector<cycles::Step>& steps, const Word* g, const std::string& name) {
  if (!cycleReady(steps, g, name)) return false;
  for (const cycles::Step& s : steps) {
    if (sink_->halted()) return false;
    Word at;  // a profile step points its alarms at its own block's word
    const Word* where = g;
    if (s.where.line != 0) {
      at.range = s.where;
      where = &at;
    }
    if (s.feed > 0.0) modal_.feed = s.feed;
    if (s.tWord && !selectTool(*s.tWord)) return false;
    if (s.sWord) {
      if (modal_.spindleMode == SpindleMode::ConstantSurface) {
        modal_.sWord = s.sWord->value * (modal_.units == Units::Inch ? kMetresPerFoot : 1.0);
      } else {
        const std::optional<double> rpm = allowedRpm(*s.sWord);
        if (!rpm) return false;
        modal_.sWord = *rpm;
      }
      updateRpm();
    }
    switch (s.kind) {
      case cycles::StepKind::Compensation:
        modal_.noseComp = s.comp;
        sink_->compensation(modal_.noseComp, mach_.noseRadius, mach_.tip);
        break;
      case cycles::StepKind::Rapid:
        if (!rapidTo(s.path.end, where)) return false;
        break;
      case cycles::StepKind::Feed: {
        if (!feedReady(where, name.c_str())) return false;
        Segment path = s.path;
        path.start = pos_;
        if (!feedMove(path.isArc() ? MoveKind::Arc : MoveKind::Line, path, where)) return false;
        break;
      }
      case cycles::StepKind::Thread: {
        if (s.lead <= 0.0 && !cuttingCondition(codes::kNoFeed, where, {name})) return false;
        if (!threadUnderCssAllowed(where)) return false;
        if (mach_.spindle == SpindleDir::Stopped && !cuttingCondition(codes::kThreadSpindleStopped, where, {}))
          return false;
        if (modal_.sWord <= 0.0 && !cuttingCondition(codes::kThreadWithoutSpeed, where, {})) return false;
        MotionCall m;
        m.kind = MoveKind::Thread;
        m.path = Segment::line(pos_, s.path.end);
        m.lead = s.lead;
        if (!pathWithinTravel(m.path, where)) return false;
        fillCall(m, where);
        sink_->motion(m);
        moved(s.path.end);
        break;
      }
      case cycles::StepKind::Dwell: {
        DwellCall d;
        d.seconds = s.seconds;
        fillDwell(d);
        sink_->dwell(d);
        break;
      }
    }
  }
  return true;
}

}  // namespace klueng::core::machine::detail

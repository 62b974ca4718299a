// The modal interpreter (SPEC 6-8, 13): one block at a time, in the in-block
// order of SPEC 7, emitting canonical calls to a MachineSink. Run-time alarms
// stop the run on the offending block, pointing at the offending word.
// Group 00 codes: interpreter_one_shot.cpp; cycles: interpreter_cycles.cpp.
#include "klueng/core/machine/interpreter.h"

#include <algorithm>
#include <limits>
#include <numbers>

#include "machine/input_rounding.h"
#include "machine/interpreter_impl.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine {

namespace detail {

using gcode::ModalGroup;
using gcode::Phase;

Interpreter::Interpreter(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options,
                         MachineSink& sink, FlowLog* flow)
    : program_(program),
      setup_(setup),
      options_(options),
      profile_(gcode::machineProfile(options.dialect)),
      runCorners_(sink, [this](const Segment& s, const SourceRange& at) { return pathWithinTravel(s, at); }),
      corners_(&runCorners_),
      sink_(&runCorners_),
      offsets_(setup.offsets),
      effects_(this),
      flow_(program, profile_, macros_, flow, [this](const Diagnostic& d) { sink_->alarm(d); }) {
  const auto& m = setup_.machine;
  pos_ = Vec2(m.startZ, m.startX / 2.0);
  mach_.position = pos_;
  mach_.optionalStopSwitch = options.optionalStop;
  // Power-on units: the run option (CLI --units, the GUI setting), else the profile's.
  const gcode::InputUnits units = options.powerOnUnits.value_or(profile_.powerOnUnits);
  modal_.units = units == gcode::InputUnits::Inch ? Units::Inch : Units::Mm;
  profileReader_ = [this](const gcode::Block& cycle, const Word* g, bool withFeed, cycles::Profile& out) {
    return readProfile(cycle, g, withFeed, out);
  };
  for (int n = 0; n < 100 && !distanceModes_; ++n)
    if (const CodeInfo* row = gcode::findCode('G', n, options.dialect))
      distanceModes_ = row->group == ModalGroup::Distance;
}

// G90/G91 of G-code systems B and C (group 03): the block's own code first, then
// under G91 its X and Z are distances, read as the U and W every other part of
// the interpreter and the cycles already knows. G92 X Z (coordinate setting)
// and G53 name positions in any mode.
void Interpreter::readDistanceMode() {
  bool positions = false;
  for (const Word& w : block_->words) {
    if (w.letter != 'G' || w.comma) continue;
    const CodeInfo* row = gcode::findCode('G', w.code(), options_.dialect);
    if (!row) continue;
    if (row->group == ModalGroup::Distance) modal_.incremental = row->action == CodeAction::Incremental;
    positions = positions || row->action == CodeAction::CoordinateSet ||
                row->action == CodeAction::MachineCoordinates || row->action == CodeAction::DataSetting;
  }
  if (!modal_.incremental || positions || !(block_->mayHave('X') || block_->mayHave('Z'))) return;
  incrementalBlock_ = *block_;
  for (Word& w : incrementalBlock_.words) {
    if (w.comma) continue;
    if (w.letter == 'X')
      w.letter = 'U';
    else if (w.letter == 'Z')
      w.letter = 'W';
  }
  incrementalBlock_.letters |= gcode::Block::letterBit('U') | gcode::Block::letterBit('W');
  block_ = &incrementalBlock_;
}

bool Interpreter::withinTravel(const Vec2& work, const SourceRange& at) {
  if (!effects_->checksMoves()) return true;  // a profile is a shape; the cycle's moves are checked
  const auto& m = setup_.machine;
  const Vec2 machine = work - mach_.workShift;
  const double xd = 2.0 * xOf(machine), z = zOf(machine);
  if (xd < m.travelXMin - kPositionTolerance || xd > m.travelXMax + kPositionTolerance)
    return raiseAt(codes::kBeyondTravelLimit, at, {"X", num(xd), num(m.travelXMin), num(m.travelXMax)});
  if (z < m.travelZMin - kPositionTolerance || z > m.travelZMax + kPositionTolerance)
    return raiseAt(codes::kBeyondTravelLimit, at, {"Z", num(z), num(m.travelZMin), num(m.travelZMax)});
  return true;
}

bool Interpreter::pathWithinTravel(const Segment& s, const SourceRange& at) {
  if (!withinTravel(s.end, at)) return false;
  if (!s.isArc()) return true;
  // The arc's extreme points that lie on the swept part of the circle.
  const double r = s.radius();
  const Vec2 a = s.start - s.centre;
  const double phi0 = std::atan2(xOf(a), zOf(a));
  const double sweep = s.sweep();
  for (int q = 0; q < 4; ++q) {
    const double phi = q * std::numbers::pi / 2.0;
    double u = (s.ccw ? 1.0 : -1.0) * (phi - phi0);
    u = std::fmod(u, 2.0 * std::numbers::pi);
    if (u < 0) u += 2.0 * std::numbers::pi;
    if (u <= sweep && !withinTravel(s.centre + r * Vec2(std::cos(phi), std::sin(phi)), at)) return false;
  }
  return true;
}

bool Interpreter::rapidTo(const Vec2& target, const Word* where) {
  if (!withinTravel(target, where)) return false;
  MotionCall m;
  m.kind = MoveKind::Rapid;
  m.path = Segment::line(pos_, target);
  fillCall(m, where);
  sink_->motion(m);
  moved(target);
  return true;
}

bool Interpreter::executeBlock() {
  // Sort the block's codes out of the words (codes as data: the table says
  // each code's group and in-block phase).
  std::array<CodeWord, 16> gs{};
  std::array<CodeWord, 16> ms{};
  std::size_t gCount = 0, mCount = 0;
  if (distanceModes_) readDistanceMode();
  byLetter_.fill(nullptr);
  movedThisBlock_ = false;
  for (const Word& w : block_->words) {
    if (w.comma) continue;  // ,C ,R ,A: the corner words, not addresses
    if (w.letter >= 'A' && w.letter <= 'Z' && !byLetter_[static_cast<std::size_t>(w.letter - 'A')])
      byLetter_[static_cast<std::size_t>(w.letter - 'A')] = &w;
    if (w.letter != 'G' && w.letter != 'M') continue;
    if (w.letter == 'G' && w.hasDecimalPoint) {  // G12.1, G05.1 (the checker let only the control's own pass)
      const gcode::DecimalCode* d = gcode::findDecimalCode(w.value, options_.dialect);
      if (!d || d->changesPath) return raise(codes::kNotSupportedYet, &w, {wordText(w)});
      continue;  // G05.1, G13.1 ...: how the control moves along the path, not the path
    }
    const CodeInfo* info = gcode::findCode(w.letter, w.code(), options_.dialect);
    if (info && info->action == CodeAction::NotSimulated) return raise(codes::kNotSupportedYet, &w, {wordText(w)});
    if (w.letter == 'G') {
      if (!info) return raise(codes::kNotSupportedYet, &w, {wordText(w)});
      if (gCount < gs.size()) gs[gCount++] = {&w, info};
    } else if (info && mCount < ms.size()) {  // unknown M codes: machine-specific, ignored (SPEC 13)
      ms[mCount++] = {&w, info};
    }
  }
  stopped_ = false;
  stopEndsRun_ = false;

  // 1. State words: units, T, modes, F, S, compensation.
  const CodeWord* motionG = nullptr;
  const CodeWord* oneShotG = nullptr;
  const CodeWord* cycleG = nullptr;        // G70-G76
  const CodeWord* singleCycleG = nullptr;  // G90 G92 G94
  bool compChanged = false;
  for (std::size_t i = 0; i < gCount; ++i)
    if (gs[i].info->group == ModalGroup::Units)
      modal_.units = gs[i].info->action == CodeAction::Inch ? Units::Inch : Units::Mm;
  if (const Word* t = find('T'))
    if (!effects_->tool(*t)) return false;
  for (std::size_t i = 0; i < gCount; ++i) {
    const CodeWord& c = gs[i];
    const CodeAction a = c.info->action;
    switch (c.info->group) {
      case ModalGroup::Motion:
        if (a == CodeAction::Rapid || a == CodeAction::Line || a == CodeAction::ArcCw || a == CodeAction::ArcCcw ||
            a == CodeAction::Thread) {
          motionG = &c;
          singleCycle_ = nullptr;
          drillCycle_ = nullptr;  // a group 01 code ends a drilling cycle
        } else if (a == CodeAction::BoxTurning || a == CodeAction::BoxThreading || a == CodeAction::BoxFacing) {
          singleCycleG = &c;  // G90/G92/G94 stay modal until another group 01 code
          singleCycle_ = c.info;
          drillCycle_ = nullptr;
        }  // any other group 01 row of a profile's code table: no motion of its own
        break;
      case ModalGroup::NonModal: oneShotG = &c; break;
      case ModalGroup::NoseComp:
        modal_.noseComp = a == CodeAction::CompLeft    ? NoseCompMode::Left
                          : a == CodeAction::CompRight ? NoseCompMode::Right
                                                       : NoseCompMode::Off;
        compChanged = true;
        break;
      case ModalGroup::SpindleMode:
        if (a == CodeAction::ConstantRpm) {
          // G97 without S keeps the rpm G96 last computed (Fanuc).
          if (modal_.spindleMode == SpindleMode::ConstantSurface && !find('S')) {
            MotionContext turning = context();
            turning.spindle = SpindleDir::Cw;
            modal_.sWord = std::round(spindleRpm(turning, xOf(pos_)));
          }
          modal_.spindleMode = SpindleMode::ConstantRpm;
        } else {
          modal_.spindleMode = SpindleMode::ConstantSurface;
        }
        break;
      case ModalGroup::FeedMode:
        modal_.feedMode = a == CodeAction::FeedPerMinute ? FeedMode::PerMinute : FeedMode::PerRev;
        break;
      case ModalGroup::WorkOffset: modal_.workCoordinate = c.info->number; break;  // G54..: all zero
      case ModalGroup::Distance: break;                                            // readDistanceMode
      case ModalGroup::ReturnLevel: modal_.returnToRPoint = a == CodeAction::ReturnToRPoint; break;
      case ModalGroup::CannedCycle:
        if (a == CodeAction::CycleCancel)
          drillCycle_ = nullptr;  // G80: drilling cycle cancel
        else
          cycleG = &c;  // G70-G76, G81-G83
        break;
      case ModalGroup::Plane: zxPlane_ = a == CodeAction::ZxPlane; break;
      default: break;  // G20/G21 done above; G61, G22, G187 ...: nothing on the path
    }
  }
  if (const Word* f = find('F')) {
    modal_.feed = f->value * unit();
    effects_->feed(modal_.feed);
  }
  if (const Word* s = find('S'))
    if (!effects_->speed(*s, oneShotG && oneShotG->info->action == CodeAction::CoordinateSet)) return false;
  if (compChanged) sink_->compensation(modal_.noseComp, mach_.noseRadius, mach_.tip);
  updateRpm();

  // 2. M codes before the motion, in code order: M03 M04 M08 M41 M86 M87 M91.
  if (mCount > 1)
    std::sort(ms.begin(), ms.begin() + static_cast<std::ptrdiff_t>(mCount), [](const CodeWord& a, const CodeWord& b) {
      return std::pair(a.info->phase, a.info->number) < std::pair(b.info->phase, b.info->number);
    });
  std::size_t mi = 0;
  if (!effects_->mCodes(ms.data(), mCount)) return false;
  for (; mi < mCount && ms[mi].info->phase != Phase::AfterMotion; ++mi)
    if (!mCode(ms[mi])) return false;

  // 3. The motion or one-shot G of the block.
  if (motionG) modal_.motion = motionFor(motionG->info->action);
  if (!zxPlane_ && (modal_.motion == MotionMode::ArcCw || modal_.motion == MotionMode::ArcCcw) && hasAxisWords() &&
      !oneShotG && !cycleG) {
    const Word* arc = motionWord(motionG ? motionG->word : nullptr);
    return raise(codes::kNotSupportedYet, arc, {(arc ? wordText(*arc) : std::string("G02/G03")) + " (G17/G19)"});
  }
  if (!cAxisWords()) return false;
  if (!effects_->blockAllowed(motionG, cycleG, oneShotG, singleCycleG)) return false;
  if (cycleG) {
    if (!cannedCycle(*cycleG)) return false;
  } else if (oneShotG) {
    if (!oneShot(*oneShotG)) return false;
  } else if (singleCycle_ && (singleCycleG || hasAxisWords())) {
    if (!singleCycle(singleCycleG ? singleCycleG->word : motionWord(nullptr), singleCycleG != nullptr)) return false;
  } else if (drillCycle_ && !motionG && hasAxisWords()) {
    if (!drillingCycle(*drillCycle_, motionWord(nullptr), false)) return false;  // the next hole
  } else if (hasAxisWords()) {
    if (!move(motionG ? motionG->word : nullptr)) return false;
  }

  // 4. M codes after the motion: M05 M09, then the program stops.
  for (; mi < mCount; ++mi)
    if (!mCode(ms[mi])) return false;
  updateRpm();

  // A chamfer or corner waits for a move in the very next block.
  if (corners_->heldBefore(blockIndex_)) {
    const bool dwellOnly = oneShotG && oneShotG->info->action == CodeAction::Dwell && !motionG && mCount == 0;
    if (!(dwellOnly && profile_.flow.dwellBeforeCornerMove)) return corners_->refuse();
  }
  const Word* t = find('T');
  const Word* n = find('N');
  macros_.noteBlock(t ? std::optional<int>(t->code()) : std::nullopt, n ? std::optional<int>(n->code()) : std::nullopt,
                    mCount > 0 ? std::optional<int>(ms[mCount - 1].info->number) : std::nullopt);
  emitSnapshot();
  return true;
}

void Interpreter::emitSnapshot() {
  sink_->blockDone(snapshot());
  ++snapshots_;
  if (stopped_ && stopEndsRun_) flow_.end();
}

StateSnapshot Interpreter::snapshot() {
  StateSnapshot snap;
  snap.line = block_->line;
  snap.blockIndex = blockIndex_;
  snap.file = block_->file;
  snap.callStack = flow_.stackId();
  snap.callLevel = flow_.level();
  snap.program = flow_.program();
  snap.modal = modal_;
  snap.machine = mach_;
  snap.machine.position = pos_;
  snap.stopped = stopped_;
  snap.optionalStop = optionalStopBlock_;
  optionalStopBlock_ = false;
  return snap;
}

MotionMode Interpreter::motionFor(CodeAction action) {
  switch (action) {
    case CodeAction::Line: return MotionMode::Line;
    case CodeAction::ArcCw: return MotionMode::ArcCw;
    case CodeAction::ArcCcw: return MotionMode::ArcCcw;
    case CodeAction::Thread: return MotionMode::Thread;
    default: return MotionMode::Rapid;
  }
}

// T: tool station (all but the last two digits) and offset (the last two).
// The limits come from the profile and the tables, whatever their sizes.
bool Interpreter::selectTool(const Word& t) {
  const int value = t.code();
  const auto [tool, offset] = gcode::splitToolNumber(value);
  // Stations: the profile's turret, else the tool table's (machine.cfg turret size).
  // TODO: read the turret size from io::MachineConfig once it has one.
  const int tableStations = static_cast<int>(setup_.tools.bitmap.size());
  const int stations = profile_.maxToolStation > 0 ? std::min(profile_.maxToolStation, tableStations) : tableStations;
  const int offsets = std::min(profile_.maxOffset, static_cast<int>(offsets_.offsets.size()));
  // A T from a macro expression skips the checker: refuse what no turret has.
  if (value < 0)
    return raise(codes::kNoSuchStation, &t, {wordText(t), t.number.str(), fmt::format("{:02d}", stations)});
  if (tool > stations)
    return raise(codes::kNoSuchStation, &t,
                 {wordText(t), fmt::format("{:02d}", tool), fmt::format("{:02d}", stations)});
  if (offset > offsets)
    return raise(codes::kNoSuchOffset, &t,
                 {wordText(t), fmt::format("{:02d}", offset), fmt::format("{:02d}", offsets)});
  // Tool 00 indexes nothing (T0000 cancels the offset of the tool in place).
  if (tool > 0 || offset > 0 || !profile_.toolZeroKeepsTurret) mach_.tool = tool;
  mach_.offset = offset;
  if (offset == 0) {
    mach_.offsetX = mach_.offsetZ = mach_.noseRadius = 0.0;
    mach_.tip = 0;
  } else {
    const io::Offset& o = offsets_.at(offset);
    mach_.offsetX = o.x;
    mach_.offsetZ = o.z;
    mach_.noseRadius = o.r;
    mach_.tip = o.tip;
  }
  return true;
}

// S: rpm (G97), surface speed (G96) or, in a G50 block, the rpm clamp.
bool Interpreter::speed(const Word& s, bool coordinateSet) {
  if (coordinateSet) {
    modal_.rpmClamp = s.value;
  } else if (modal_.spindleMode == SpindleMode::ConstantSurface) {
    modal_.sWord = s.value * (modal_.units == Units::Inch ? kMetresPerFoot : 1.0);
  } else {
    const std::optional<double> rpm = allowedRpm(s);
    if (!rpm) return false;
    modal_.sWord = *rpm;
  }
  return true;
}

std::optional<double> Interpreter::allowedRpm(const Word& s) {
  const double max = setup_.machine.maxSpindleRpm;
  if (s.value <= max + 1e-9) return s.value;
  if (profile_.spindleAboveMaximumIsAlarm) {
    raise(codes::kSpindleAboveMaximum, &s, {num(s.value), num(max)});
    return std::nullopt;
  }
  if (!spindleClampWarned_)
    flow_.notice(Severity::Warning, codes::kSpindleClampedToMaximum, s.range, {num(s.value), num(max)});
  spindleClampWarned_ = true;
  return max;
}

bool Interpreter::mCode(const CodeWord& c) {
  const CodeAction a = c.info->action;
  switch (c.info->group) {
    case ModalGroup::MSpindle:
      if (a == CodeAction::SpindleStop) {
        mach_.spindle = SpindleDir::Stopped;
      } else {
        const SpindleDir dir = a == CodeAction::SpindleCw ? SpindleDir::Cw : SpindleDir::Ccw;
        if (mach_.brake) return raise(codes::kSpindleStartedWithBrakeOn, c.word, {wordText(*c.word)});
        if (mach_.spindle != SpindleDir::Stopped && mach_.spindle != dir) {
          if (profile_.spindleReversalIsAlarm)
            return raise(codes::kSpindleReversedWithoutStop, c.word, {wordText(*c.word)});
          if (!reversalWarned_)
            flow_.notice(Severity::Warning, codes::kSpindleReversed, c.word->range, {wordText(*c.word)});
          reversalWarned_ = true;
        }
        mach_.spindle = dir;
      }
      updateRpm();
      return true;
    case ModalGroup::MCoolant: mach_.coolant = a == CodeAction::CoolantOn; return true;
    case ModalGroup::MBrake:
      if (a == CodeAction::SpindleClamp) {  // M86; Haas M14 (M15 releases, as M87)
        if (mach_.spindle != SpindleDir::Stopped) return raise(codes::kBrakeWhileTurning, c.word, {});
        mach_.brake = true;
      } else {
        if (mach_.cAxisMode) return raise(codes::kBrakeReleasedInCAxisMode, c.word, {});
        mach_.brake = false;
      }
      return true;
    case ModalGroup::MCAxis:
      if (a == CodeAction::CAxisOn) {
        if (!mach_.brake) return raise(codes::kCAxisModeWithoutBrake, c.word, {});
        mach_.cAxisMode = true;
      } else {
        mach_.cAxisMode = false;
      }
      return true;
    case ModalGroup::MGear: mach_.gearRange = c.info->number - 40; return true;  // M41 = range 1
    case ModalGroup::MThreadChamfer:
      // Haas M23/M24: chamfer out of a thread on/off (a profile without a
      // thread chamfer setting ignores them, as other machine M codes).
      mach_.threadChamfer = a == CodeAction::ThreadChamferOn;
      return true;
    case ModalGroup::MProgram:
      if (a == CodeAction::OptionalStop) optionalStopBlock_ = true;
      if (a == CodeAction::OptionalStop && !options_.optionalStop) return true;
      stopped_ = true;
      stopEndsRun_ = a == CodeAction::ProgramEnd || options_.stopAtM00;
      if (a == CodeAction::ProgramEnd) macros_.partFinished();
      return true;
    case ModalGroup::MSubprogram: {
      // Performed after the block (interpreter_flow.cpp): M98 P L, M97 P L, M99 [P].
      PendingCall call;
      call.kind = a == CodeAction::SubprogramCall ? PendingCall::Kind::Subprogram
                  : a == CodeAction::LocalCall    ? PendingCall::Kind::Local
                                                  : PendingCall::Kind::Return;
      call.where = c.word->range;
      call.text = wordText(*c.word);
      const Word* p = find('P');
      const Word* l = find('L');
      call.hasP = p != nullptr;
      const bool packed = a == CodeAction::SubprogramCall && profile_.flow.packedRepeats;
      call.target = gcode::callTarget(p ? p->value : 0.0, l ? std::optional<double>(l->value) : std::nullopt, packed);
      // A missing target stops the run on this block, before its snapshot.
      const gcode::ProgramIndex& index = flow_.index();
      if (a == CodeAction::SubprogramCall && !p) return raise(codes::kCallWithoutProgram, c.word, {call.text});
      if (a == CodeAction::SubprogramCall && call.target.repeats > 0 && !index.program(call.target.number))
        return raise(codes::kNoSuchProgram, c.word, {call.text, std::to_string(call.target.number)});
      if (a == CodeAction::LocalCall && call.target.repeats > 0 &&
          index.findSequence(index.sectionOf(blockIndex_), call.target.number, -1) < 0)
        return raise(codes::kNoSuchSequence, c.word, {call.text, std::to_string(call.target.number)});
      flow_.setPending(std::move(call));
      return true;
    }
    default: return true;
  }
}

bool Interpreter::cAxisWords() {
  const Word* c = find('C');
  const Word* h = find('H');
  if (!c && !h) return true;
  const Word* w = c ? c : h;
  if (!mach_.cAxisMode) {
    // Only a profile with a C-axis mode code can rotate C at all; on the others
    // a "C2." is a chamfer written the old way.
    bool hasCAxisMode = false;
    for (int m = 0; m < 200 && !hasCAxisMode; ++m) {
      const gcode::CodeInfo* info = gcode::findCode('M', m, profile_.dialect);
      hasCAxisMode = info && info->action == gcode::CodeAction::CAxisOn;
    }
    return raise(hasCAxisMode ? codes::kCAxisOutsideCAxisMode : codes::kNoCAxisOnThisMachine, w, {wordText(*w)});
  }
  // A C-axis rotation is recorded as the spindle angle; it takes no time.
  mach_.cAngle = c ? c->value : mach_.cAngle + h->value;
  mach_.cAngle = std::fmod(mach_.cAngle, 360.0);
  if (mach_.cAngle < 0) mach_.cAngle += 360.0;
  return true;
}

bool Interpreter::move(const Word* g) {
  const Word* where = motionWord(g);
  Vec2 target = axisTarget();
  if (corners_->holding() && modal_.motion != MotionMode::Line && modal_.motion != MotionMode::ArcCw &&
      modal_.motion != MotionMode::ArcCcw)
    return corners_->refuse();
  switch (modal_.motion) {
    case MotionMode::Rapid: return rapidTo(target, where);
    case MotionMode::Line: {
      if (!feedReady(where, "G01")) return false;
      if (!angleTarget(target)) return false;
      const Segment path = Segment::line(pos_, target);
      if (chamferWord() || cornerWord()) return holdCorner(path, where);
      return feedMoveAfterCorner(MoveKind::Line, path, where);
    }
    case MotionMode::ArcCw:
    case MotionMode::ArcCcw: {
      const bool ccw = modal_.motion == MotionMode::ArcCcw;
      if (!feedReady(where, ccw ? "G03" : "G02")) return false;
      std::optional<Segment> arc = arcTo(target, ccw, where);
      if (!arc) return false;
      return feedMoveAfterCorner(arc->isArc() ? MoveKind::Arc : MoveKind::Line, *arc, where);
    }
    case MotionMode::Thread: {
      if (modal_.feed <= 0.0 && !cuttingCondition(codes::kNoFeed, where, {"G32"})) return false;
      if (!threadUnderCssAllowed(where)) return false;
      if (mach_.spindle == SpindleDir::Stopped && !cuttingCondition(codes::kThreadSpindleStopped, where, {}))
        return false;
      if (modal_.sWord <= 0.0 && !cuttingCondition(codes::kThreadWithoutSpeed, where, {})) return false;
      MotionCall m;
      m.kind = MoveKind::Thread;
      m.path = Segment::line(pos_, target);
      m.lead = modal_.feed;
      if (!pathWithinTravel(m.path, where)) return false;
      fillCall(m, where);
      sink_->motion(m);
      moved(target);
      return true;
    }
  }
  return true;
}

bool Interpreter::feedReady(const Word* where, const char* code) {
  if (!effects_->checksMoves()) return true;  // the cycle checks its own moves when it makes them
  if (modal_.feed <= 0.0 && !cuttingCondition(codes::kNoFeed, where, {code})) return false;
  if (modal_.feedMode == FeedMode::PerRev) {
    if (mach_.spindle == SpindleDir::Stopped && !cuttingCondition(codes::kFeedPerRevSpindleStopped, where, {code}))
      return false;
    if (modal_.sWord <= 0.0 && !cuttingCondition(codes::kFeedPerRevWithoutSpeed, where, {code})) return false;
  }
  return true;
}

bool Interpreter::feedMove(MoveKind kind, const Segment& path, const Word* where) {
  if (!pathWithinTravel(path, where)) return false;
  MotionCall m;
  m.kind = kind;
  m.path = path;
  fillCall(m, where);
  sink_->motion(m);
  moved(path.end);
  return true;
}

std::optional<Segment> Interpreter::arcTo(const Vec2& end, bool ccw, const Word* where) {
  const Vec2 start = pos_;
  const double u = unit();
  if (const Word* rw = find('R')) {
    const double r = rw->value * u;
    const double chord = (end - start).norm();
    if (chord < 1e-9) return Segment::line(start, end);
    const double half = chord / 2.0;
    if (std::abs(r) < half - kArcTolerance) {
      raise(codes::kArcRadiusTooSmall, rw, {num(std::abs(r)), num(half)});
      return std::nullopt;
    }
    const double d = std::sqrt(std::max(0.0, r * r - half * half));
    const Vec2 dir = (end - start) / chord;
    const Vec2 left(-dir.y(), dir.x());  // +90 deg in the X-up drawing
    // Short arc (R > 0): the centre lies on the side the arc turns to.
    const double side = (ccw ? 1.0 : -1.0) * (r > 0 ? 1.0 : -1.0);
    const Vec2 centre = 0.5 * (start + end) + side * d * left;
    return Segment::arc(start, end, centre, ccw);
  }
  const Word* iw = find('I');
  const Word* kw = find('K');
  const Vec2 centre = start + Vec2(kw ? kw->value * u : 0.0, iw ? iw->value * u : 0.0);
  const double r0 = (start - centre).norm(), r1 = (end - centre).norm();
  const Word* at = iw ? iw : kw ? kw : where;
  if (r0 < 1e-9 || std::abs(r0 - r1) > kArcTolerance) {
    raise(codes::kArcEndsNotOnOneCircle, at, {num(r0), num(r1)});
    return std::nullopt;
  }
  return Segment::arc(start, end, centre, ccw);
}

}  // namespace detail

void run(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options, MachineSink& sink) {
  const gcode::MachineProfile& profile = gcode::machineProfile(options.dialect);
  const std::optional<gcode::Program> rounded =
      roundToIncrements(program, profile, options.powerOnUnits.value_or(profile.powerOnUnits));
  detail::Interpreter(rounded ? *rounded : program, setup, options, sink, nullptr).run();
}

void run(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options, MachineSink& sink,
         FlowLog& flow) {
  const gcode::MachineProfile& profile = gcode::machineProfile(options.dialect);
  const std::optional<gcode::Program> rounded =
      roundToIncrements(program, profile, options.powerOnUnits.value_or(profile.powerOnUnits));
  detail::Interpreter(rounded ? *rounded : program, setup, options, sink, &flow).run();
}

namespace {

constexpr double kRecordRpm = 500.0;  // rpm and mm/min of a cut made without them in a record
constexpr double kRecordFeed = 100.0;

// RunOptions::throughAlarms: keeps the first alarm and lets the run go on.
class ThroughAlarms final : public MachineSink {
 public:
  explicit ThroughAlarms(MachineSink& next) : next_(next) {}
  void motion(const MotionCall& m) override {
    // A cut made without its feed, spindle or speed (noted as an alarm) still
    // takes a finite time: a record's times are not its point.
    const bool stalled =
        m.kind != MoveKind::Rapid && (m.ctx.feed <= 0.0 || m.ctx.spindle == SpindleDir::Stopped || m.ctx.sWord <= 0.0 ||
                                      (m.kind == MoveKind::Thread && m.lead <= 0.0));
    if (!stalled) return next_.motion(m);
    standIns = true;
    MotionCall running = m;
    running.ctx.spindle = SpindleDir::Cw;
    running.ctx.spindleMode = SpindleMode::ConstantRpm;
    running.ctx.sWord = kRecordRpm;
    running.ctx.feedMode = FeedMode::PerMinute;
    running.ctx.feed = kRecordFeed;
    if (running.lead <= 0.0) running.lead = 1.0;
    next_.motion(running);
  }
  void dwell(const DwellCall& d) override { next_.dwell(d); }
  void setPosition(const Vec2& p) override { next_.setPosition(p); }
  void compensation(NoseCompMode mode, double radius, int tip) override {
    compensates = compensates || mode != NoseCompMode::Off;
    next_.compensation(mode, radius, tip);
  }
  void blockDone(const StateSnapshot& s) override { next_.blockDone(s); }
  void alarm(const Diagnostic& d) override {
    if (!first) first = d;
  }
  void end() override { next_.end(); }
  bool halted() const override { return next_.halted(); }
  double elapsed() const override { return next_.elapsed(); }
  std::optional<Diagnostic> first;
  bool standIns = false;     // a cut made with the stand-in feed and speed above
  bool compensates = false;  // G41/G42 asked for (a record follows the programmed path)

 private:
  MachineSink& next_;
};

}  // namespace

Timeline interpret(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options) {
  Timeline timeline;
  const std::size_t blocks = program.blocks.size();
  if (options.blockMarksOnly) {
    timeline.recordMoves.reserve(blocks + blocks / 2);
    if (options.recordSpeeds) timeline.recordSpeeds.reserve(blocks + blocks / 2);
    timeline.marks.reserve(blocks);
  } else {
    timeline.moves.reserve(blocks + blocks / 2);
    timeline.snapshots.reserve(blocks);
  }
  auto builder = makeTimelineBuilder(
      timeline, TimingConfig{setup.machine.rapidX, setup.machine.rapidZ, setup.machine.accelX, setup.machine.accelZ},
      TimelineLimits{options.blockMarksOnly, options.blockMarksOnly && options.recordSpeeds,
                     options.memoryBudgetMb << 20});
  std::unique_ptr<MachineSink> compensation;
  if (options.noseCompensation) compensation = makeCompensationStage(*builder);
  MachineSink& chain = compensation ? *compensation : *builder;
  if (!options.throughAlarms) {
    run(program, setup, options, chain, timeline.flow);
    return timeline;
  }
  ThroughAlarms through(chain);
  run(program, setup, options, through, timeline.flow);
  if (!timeline.alarm) timeline.alarm = through.first;
  timeline.recordStandIns = through.standIns;
  timeline.recordCompensates = through.compensates;
  return timeline;
}

Timeline recordRun(const gcode::Program& program, const MachineSetup& setup, RunOptions options) {
  options.persistentVariables = nullptr;
  options.noseCompensation = false;
  options.throughAlarms = true;
  return interpret(program, setup, options);
}

}  // namespace klueng::core::machine

// The modal interpreter (SPEC 6-8, 13): one block at a time, in the in-block
// order of SPEC 7, emitting canonical calls to a MachineSink. Run-time alarms
// stop the run on the offending block, pointing at the offending word.
#include "klueng/core/machine/interpreter.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "klueng/core/machine/kinematics.h"
#include "machine/cycles.h"

namespace klueng::core::machine {

namespace {

using gcode::CodeInfo;
using gcode::ModalGroup;
using gcode::Phase;
using gcode::Word;

constexpr double kMmPerInch = 25.4;
constexpr double kMetresPerFoot = 0.3048;   // G96 S is feet/min under G20
constexpr double kArcTolerance = 0.01;      // mm (SPEC 5 ext)
constexpr double kPositionTolerance = 0.001;

std::string num(double v) {
  if (std::abs(v) < 0.0005) v = 0.0;  // no "-0.000"
  return fmt::format("{:.3f}", v);
}

std::string wordText(const Word& w) { return std::string(1, w.letter) + w.number; }

struct CodeWord {
  const Word* word;
  const CodeInfo* info;
};

class Interpreter {
 public:
  Interpreter(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options, MachineSink& sink)
      : program_(program), setup_(setup), options_(options), sink_(sink) {
    const auto& m = setup_.machine;
    pos_ = Vec2(m.startZ, m.startX / 2.0);
    mach_.position = pos_;
    mach_.optionalStopSwitch = options.optionalStop;
  }

  void run() {
    sink_.setPosition(pos_);
    for (std::size_t i = 0; i < program_.blocks.size(); ++i) {
      const gcode::Block& b = program_.blocks[i];
      if (b.blockSkip && options_.blockSkip) continue;
      block_ = &b;
      blockIndex_ = static_cast<int>(i);
      if (!executeBlock()) break;
      if (sink_.halted() || ended_) break;
      if (resumeAfter_ >= 0) {  // G71-G73 skip their own profile
        i = static_cast<std::size_t>(resumeAfter_);
        resumeAfter_ = -1;
      }
    }
    sink_.end();
  }

 private:
  // ---- helpers -------------------------------------------------------------

  double unit() const { return modal_.units == Units::Inch ? kMmPerInch : 1.0; }
  Vec2 offsetVector() const { return Vec2(mach_.offsetZ, mach_.offsetX / 2.0); }

  double rpmCap() const {
    const double max = setup_.machine.maxSpindleRpm;
    return modal_.rpmClamp > 0.0 ? std::min(modal_.rpmClamp, max) : max;
  }

  MotionContext context() const {
    MotionContext c;
    c.feedMode = modal_.feedMode;
    c.feed = modal_.feed;
    c.spindleMode = modal_.spindleMode;
    c.sWord = modal_.sWord;
    c.rpmCap = rpmCap();
    c.spindle = mach_.spindle;
    c.tool = mach_.tool;
    c.offset = mach_.offset;
    c.noseRadius = mach_.noseRadius;
    c.tip = mach_.tip;
    return c;
  }

  void updateRpm() { mach_.rpm = spindleRpm(context(), xOf(pos_)); }

  bool raise(const char* code, const Word* where, std::vector<std::string> args) {
    Diagnostic d;
    d.severity = Severity::Alarm;
    d.code = code;
    if (where) d.range = where->range;
    else d.range = SourceRange{block_->line, 1, 0};
    d.args = std::move(args);
    sink_.alarm(d);
    return false;
  }

  // The block's first word of a letter (indexed once per block).
  const Word* find(char letter) const {
    return letter >= 'A' && letter <= 'Z' ? byLetter_[static_cast<std::size_t>(letter - 'A')] : nullptr;
  }

  // The word a motion alarm points at: the motion G of the block, else its
  // first axis word, else its first word.
  const Word* motionWord(const Word* g) const {
    if (g) return g;
    for (const Word& w : block_->words)
      if (w.letter == 'X' || w.letter == 'Z' || w.letter == 'U' || w.letter == 'W') return &w;
    return block_->words.empty() ? nullptr : &block_->words.front();
  }

  bool hasAxisWords() const { return find('X') || find('Z') || find('U') || find('W'); }

  // Target of the controlled point from X/Z (absolute) and U/W (incremental).
  Vec2 axisTarget() const {
    const double u = unit();
    Vec2 p = pos_;
    const Vec2 off = offsetVector();
    if (const Word* w = find('X')) p.y() = w->value * u / 2.0 + off.y();
    if (const Word* w = find('U')) p.y() += w->value * u / 2.0;
    if (const Word* w = find('Z')) p.x() = w->value * u + off.x();
    if (const Word* w = find('W')) p.x() += w->value * u;
    return p;
  }
  bool movesX() const { return find('X') || find('U'); }
  bool movesZ() const { return find('Z') || find('W'); }

  // ---- travel limits (machine coordinates = work - shift) --------------------

  bool withinTravel(const Vec2& work, const Word* where) {
    const auto& m = setup_.machine;
    const Vec2 machine = work - mach_.workShift;
    const double xd = 2.0 * xOf(machine), z = zOf(machine);
    if (xd < m.travelXMin - kPositionTolerance || xd > m.travelXMax + kPositionTolerance)
      return raise("A112", where, {"X", num(xd), num(m.travelXMin), num(m.travelXMax)});
    if (z < m.travelZMin - kPositionTolerance || z > m.travelZMax + kPositionTolerance)
      return raise("A112", where, {"Z", num(z), num(m.travelZMin), num(m.travelZMax)});
    return true;
  }

  bool pathWithinTravel(const Segment& s, const Word* where) {
    if (!withinTravel(s.end, where)) return false;
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
      if (u <= sweep && !withinTravel(s.centre + r * Vec2(std::cos(phi), std::sin(phi)), where)) return false;
    }
    return true;
  }

  // ---- emitting --------------------------------------------------------------

  bool rapidTo(const Vec2& target, const Word* where) {
    if (!withinTravel(target, where)) return false;
    MotionCall m;
    m.kind = MoveKind::Rapid;
    m.path = Segment::line(pos_, target);
    fillCall(m, where);
    sink_.motion(m);
    moved(target);
    return true;
  }

  void fillCall(MotionCall& m, const Word* where) const {
    m.line = block_->line;
    m.blockIndex = blockIndex_;
    m.where = where ? where->range : SourceRange{block_->line, 1, 0};
    m.ctx = context();
  }

  void moved(const Vec2& target) {
    if ((target - pos_).norm() > 1e-9) mach_.positionCheck = false;
    pos_ = target;
  }

  // ---- the block ---------------------------------------------------------------

  bool executeBlock() {
    // Sort the block's codes out of the words (codes as data: the table says
    // each code's group and in-block phase).
    std::array<CodeWord, 16> gs{};
    std::array<CodeWord, 16> ms{};
    std::size_t gCount = 0, mCount = 0;
    byLetter_.fill(nullptr);
    for (const Word& w : block_->words) {
      if (w.letter >= 'A' && w.letter <= 'Z' && !byLetter_[static_cast<std::size_t>(w.letter - 'A')])
        byLetter_[static_cast<std::size_t>(w.letter - 'A')] = &w;
      if (w.letter != 'G' && w.letter != 'M') continue;
      const CodeInfo* info = gcode::findCode(w.letter, w.code(), options_.dialect);
      if (w.letter == 'G') {
        if (!info) return raise("A117", &w, {wordText(w)});
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
        modal_.units = gs[i].info->number == 20 ? Units::Inch : Units::Mm;
    if (const Word* t = find('T'))
      if (!selectTool(*t)) return false;
    for (std::size_t i = 0; i < gCount; ++i) {
      const CodeWord& c = gs[i];
      const int n = c.info->number;
      switch (c.info->group) {
        case ModalGroup::Motion:
          if (n == 0 || n == 1 || n == 2 || n == 3 || n == 32) {
            motionG = &c;
            singleCycle_ = 0;
          } else {
            singleCycleG = &c;  // G90/G92/G94 stay modal until another group 01 code
            singleCycle_ = n;
          }
          break;
        case ModalGroup::NonModal: oneShotG = &c; break;
        case ModalGroup::NoseComp:
          modal_.noseComp = n == 41 ? NoseCompMode::Left : n == 42 ? NoseCompMode::Right : NoseCompMode::Off;
          compChanged = true;
          break;
        case ModalGroup::SpindleMode:
          if (n == 97) {
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
        case ModalGroup::FeedMode: modal_.feedMode = n == 98 ? FeedMode::PerMinute : FeedMode::PerRev; break;
        case ModalGroup::WorkOffset: modal_.workCoordinate = n; break;   // all work offsets are zero
        case ModalGroup::CannedCycle:
          if (n != 80) cycleG = &c;
          break;
        default: break;  // G18 plane, G20/G21 done above
      }
    }
    if (const Word* f = find('F')) modal_.feed = f->value * unit();
    if (const Word* s = find('S')) {
      if (oneShotG && oneShotG->info->number == 50) {
        modal_.rpmClamp = s->value;
      } else if (modal_.spindleMode == SpindleMode::ConstantSurface) {
        modal_.sWord = s->value * (modal_.units == Units::Inch ? kMetresPerFoot : 1.0);
      } else {
        if (s->value > setup_.machine.maxSpindleRpm + 1e-9)
          return raise("A101", s, {num(s->value), num(setup_.machine.maxSpindleRpm)});
        modal_.sWord = s->value;
      }
    }
    if (compChanged) sink_.compensation(modal_.noseComp, mach_.noseRadius, mach_.tip);
    updateRpm();

    // 2. M codes before the motion, in code order: M03 M04 M08 M41 M86 M87 M91.
    if (mCount > 1)
      std::sort(ms.begin(), ms.begin() + static_cast<std::ptrdiff_t>(mCount),
              [](const CodeWord& a, const CodeWord& b) {
                return std::pair(a.info->phase, a.info->number) < std::pair(b.info->phase, b.info->number);
              });
    std::size_t mi = 0;
    for (; mi < mCount && ms[mi].info->phase != Phase::AfterMotion; ++mi)
      if (!mCode(ms[mi])) return false;

    // 3. The motion or one-shot G of the block.
    if (motionG) modal_.motion = motionFor(motionG->info->number);
    if (!cAxisWords()) return false;
    if (cycleG) {
      if (!cannedCycle(*cycleG)) return false;
    } else if (oneShotG) {
      if (!oneShot(*oneShotG)) return false;
    } else if (singleCycle_ != 0 && (singleCycleG || hasAxisWords())) {
      if (!singleCycle(singleCycleG ? singleCycleG->word : motionWord(nullptr), singleCycleG != nullptr))
        return false;
    } else if (hasAxisWords()) {
      if (!move(motionG ? motionG->word : nullptr)) return false;
    }

    // 4. M codes after the motion: M05 M09, then the program stops.
    for (; mi < mCount; ++mi)
      if (!mCode(ms[mi])) return false;
    updateRpm();

    StateSnapshot snap;
    snap.line = block_->line;
    snap.blockIndex = blockIndex_;
    snap.modal = modal_;
    snap.machine = mach_;
    snap.machine.position = pos_;
    snap.stopped = stopped_;
    sink_.blockDone(snap);
    if (stopped_ && stopEndsRun_) ended_ = true;
    return true;
  }

  static MotionMode motionFor(int g) {
    switch (g) {
      case 1: return MotionMode::Line;
      case 2: return MotionMode::ArcCw;
      case 3: return MotionMode::ArcCcw;
      case 32: return MotionMode::Thread;
      default: return MotionMode::Rapid;
    }
  }

  bool selectTool(const Word& t) {
    const int value = t.code();
    const int tool = value / 100, offset = value % 100;
    if (offset > io::kOffsetCount) return raise("A118", &t, {wordText(t), fmt::format("{:02d}", offset)});
    mach_.tool = tool;
    mach_.offset = offset;
    if (offset == 0) {
      mach_.offsetX = mach_.offsetZ = mach_.noseRadius = 0.0;
      mach_.tip = 0;
    } else {
      const io::Offset& o = setup_.offsets.at(offset);
      mach_.offsetX = o.x;
      mach_.offsetZ = o.z;
      mach_.noseRadius = o.r;
      mach_.tip = o.tip;
    }
    return true;
  }

  bool mCode(const CodeWord& c) {
    const int n = c.info->number;
    switch (c.info->group) {
      case ModalGroup::MSpindle:
        if (n == 5) {
          mach_.spindle = SpindleDir::Stopped;
        } else {
          const SpindleDir dir = n == 3 ? SpindleDir::Cw : SpindleDir::Ccw;
          if (mach_.brake) return raise("A106", c.word, {wordText(*c.word)});
          if (mach_.spindle != SpindleDir::Stopped && mach_.spindle != dir)
            return raise("A105", c.word, {wordText(*c.word)});
          mach_.spindle = dir;
        }
        updateRpm();
        return true;
      case ModalGroup::MCoolant: mach_.coolant = n == 8; return true;
      case ModalGroup::MBrake:
        if (n == 86) {
          if (mach_.spindle != SpindleDir::Stopped) return raise("A107", c.word, {});
          mach_.brake = true;
        } else {
          if (mach_.cAxisMode) return raise("A111", c.word, {});
          mach_.brake = false;
        }
        return true;
      case ModalGroup::MCAxis:
        if (n == 41) {
          if (!mach_.brake) return raise("A110", c.word, {});
          mach_.cAxisMode = true;
        } else {
          mach_.cAxisMode = false;
        }
        return true;
      case ModalGroup::MGear: mach_.gearRange = n - 40; return true;
      case ModalGroup::MProgram:
        if (n == 1 && !options_.optionalStop) return true;
        stopped_ = true;
        stopEndsRun_ = n == 2 || n == 30 || options_.stopAtM00;
        return true;
      case ModalGroup::MSubprogram: return raise("A117", c.word, {wordText(*c.word)});
      default: return true;
    }
  }

  bool cAxisWords() {
    const Word* c = find('C');
    const Word* h = find('H');
    if (!c && !h) return true;
    const Word* w = c ? c : h;
    if (!mach_.cAxisMode) return raise("A109", w, {wordText(*w)});
    // A C-axis rotation is recorded as the spindle angle; it takes no time.
    mach_.cAngle = c ? c->value : mach_.cAngle + h->value;
    mach_.cAngle = std::fmod(mach_.cAngle, 360.0);
    if (mach_.cAngle < 0) mach_.cAngle += 360.0;
    return true;
  }

  // ---- motion of group 01 ----------------------------------------------------

  bool move(const Word* g) {
    const Word* where = motionWord(g);
    const Vec2 target = axisTarget();
    switch (modal_.motion) {
      case MotionMode::Rapid: return rapidTo(target, where);
      case MotionMode::Line: {
        if (!feedReady(where, "G01")) return false;
        return feedMove(MoveKind::Line, Segment::line(pos_, target), where);
      }
      case MotionMode::ArcCw:
      case MotionMode::ArcCcw: {
        const bool ccw = modal_.motion == MotionMode::ArcCcw;
        if (!feedReady(where, ccw ? "G03" : "G02")) return false;
        std::optional<Segment> arc = arcTo(target, ccw, where);
        if (!arc) return false;
        return feedMove(arc->isArc() ? MoveKind::Arc : MoveKind::Line, *arc, where);
      }
      case MotionMode::Thread: {
        if (modal_.feed <= 0.0) return raise("A102", where, {"G32"});
        if (modal_.spindleMode == SpindleMode::ConstantSurface) return raise("A108", where, {});
        if (mach_.spindle == SpindleDir::Stopped) return raise("A116", where, {});
        if (modal_.sWord <= 0.0) return raise("A119", where, {});
        MotionCall m;
        m.kind = MoveKind::Thread;
        m.path = Segment::line(pos_, target);
        m.lead = modal_.feed;
        if (!pathWithinTravel(m.path, where)) return false;
        fillCall(m, where);
        sink_.motion(m);
        moved(target);
        return true;
      }
    }
    return true;
  }

  bool feedReady(const Word* where, const char* code) {
    if (modal_.feed <= 0.0) return raise("A102", where, {code});
    if (modal_.feedMode == FeedMode::PerRev) {
      if (mach_.spindle == SpindleDir::Stopped) return raise("A104", where, {code});
      if (modal_.sWord <= 0.0) return raise("A103", where, {code});
    }
    return true;
  }

  bool feedMove(MoveKind kind, const Segment& path, const Word* where) {
    if (!pathWithinTravel(path, where)) return false;
    MotionCall m;
    m.kind = kind;
    m.path = path;
    fillCall(m, where);
    sink_.motion(m);
    moved(path.end);
    return true;
  }

  // The arc from the current point to `end`, by R or by I/K (SPEC 7);
  // nullopt after an alarm. A zero-chord arc by R is a zero-length line.
  std::optional<Segment> arcTo(const Vec2& end, bool ccw, const Word* where) {
    const Vec2 start = pos_;
    const double u = unit();
    if (const Word* rw = find('R')) {
      const double r = rw->value * u;
      const double chord = (end - start).norm();
      if (chord < 1e-9) return Segment::line(start, end);
      const double half = chord / 2.0;
      if (std::abs(r) < half - kArcTolerance) {
        raise("A114", rw, {num(std::abs(r)), num(half)});
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
      raise("A113", at, {num(r0), num(r1)});
      return std::nullopt;
    }
    return Segment::arc(start, end, centre, ccw);
  }

  // ---- canned cycles (cycles.h expands them; the moves go down the same chain) ----

  bool compensationAllowed(const Word* g) {
    if (modal_.noseComp == NoseCompMode::Off) return true;
    return raise("A123", g, {wordText(*g)});
  }

  // G90/G92/G94: X Z R are modal while the cycle is (Fanuc); U/W count from the start point.
  bool singleCycle(const Word* where, bool fresh) {
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
    return emitCycle(cycles::singleCycle(singleCycle_, pos_, target, singleTaper_, modal_.feed), where,
                     fmt::format("G{}", singleCycle_));
  }

  bool cannedCycle(const CodeWord& c) {
    const int g = c.info->number;
    if (g != 70 && !compensationAllowed(c.word)) return false;
    cycles::CycleInput in;
    in.program = &program_;
    in.blockIndex = blockIndex_;
    in.gWord = c.word;
    in.start = pos_;
    in.offset = offsetVector();
    in.offsets = &setup_.offsets;
    in.unit = unit();
    in.feed = modal_.feed;
    in.motion = modal_.motion;
    in.blockSkip = options_.blockSkip;
    cycles::Expansion e = cycles::expand(g, in, cycleMemory_);
    if (e.alarm) {
      Diagnostic d;
      d.severity = Severity::Alarm;
      d.code = e.alarm->code;
      d.range = e.alarm->where;
      d.args = e.alarm->args;
      sink_.alarm(d);
      return false;
    }
    if (!emitCycle(e.steps, c.word, wordText(*c.word))) return false;
    resumeAfter_ = e.resumeAfter;
    return true;
  }

  // The feed and spindle alarms of a whole cycle before its first move (the
  // control refuses the cycle; no half-run cycle). F and S inside a G70 profile count.
  bool cycleReady(const std::vector<cycles::Step>& steps, const Word* g, const std::string& name) {
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
        if (feed <= 0.0) return raise("A102", where, {name});
        if (modal_.feedMode == FeedMode::PerRev) {
          if (mach_.spindle == SpindleDir::Stopped) return raise("A104", where, {name});
          if (!sSet) return raise("A103", where, {name});
        }
      } else if (s.kind == cycles::StepKind::Thread) {
        if (s.lead <= 0.0) return raise("A102", where, {name});
        if (modal_.spindleMode == SpindleMode::ConstantSurface) return raise("A108", where, {});
        if (mach_.spindle == SpindleDir::Stopped) return raise("A116", where, {});
        if (!sSet) return raise("A119", where, {});
      }
    }
    return true;
  }

  // Sends a cycle's moves down the chain as if each were its own block (same
  // checks), all carrying the cycle block's line.
  bool emitCycle(const std::vector<cycles::Step>& steps, const Word* g, const std::string& name) {
    if (!cycleReady(steps, g, name)) return false;
    for (const cycles::Step& s : steps) {
      if (sink_.halted()) return false;
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
          if (s.sWord->value > setup_.machine.maxSpindleRpm + 1e-9)
            return raise("A101", s.sWord, {num(s.sWord->value), num(setup_.machine.maxSpindleRpm)});
          modal_.sWord = s.sWord->value;
        }
        updateRpm();
      }
      switch (s.kind) {
        case cycles::StepKind::Compensation:
          modal_.noseComp = s.comp;
          sink_.compensation(modal_.noseComp, mach_.noseRadius, mach_.tip);
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
          if (s.lead <= 0.0) return raise("A102", where, {name});
          if (modal_.spindleMode == SpindleMode::ConstantSurface) return raise("A108", where, {});
          if (mach_.spindle == SpindleDir::Stopped) return raise("A116", where, {});
          if (modal_.sWord <= 0.0) return raise("A119", where, {});
          MotionCall m;
          m.kind = MoveKind::Thread;
          m.path = Segment::line(pos_, s.path.end);
          m.lead = s.lead;
          if (!pathWithinTravel(m.path, where)) return false;
          fillCall(m, where);
          sink_.motion(m);
          moved(s.path.end);
          break;
        }
      }
    }
    return true;
  }

  // ---- one-shot codes of group 00 ----------------------------------------------

  Vec2 referencePoint() const {
    const auto& m = setup_.machine;
    return Vec2(m.referenceZ, m.referenceX / 2.0) + mach_.workShift;
  }

  bool oneShot(const CodeWord& c) {
    const Word* w = c.word;
    switch (c.info->number) {
      case 4: {
        if (modal_.feedMode == FeedMode::PerRev && mach_.spindle == SpindleDir::Stopped)
          return raise("A104", w, {"G04"});
        double seconds = 0.0;
        if (const Word* p = find('P')) seconds = p->value / 1000.0;
        else if (const Word* x = find('X')) seconds = x->value;
        else if (const Word* uw = find('U')) seconds = uw->value;
        DwellCall d;
        d.seconds = std::max(0.0, seconds);
        d.line = block_->line;
        d.blockIndex = blockIndex_;
        d.ctx = context();
        sink_.dwell(d);
        return true;
      }
      case 27: {
        if (!hasAxisWords()) return true;
        if (!rapidTo(axisTarget(), w)) return false;
        const Vec2 ref = referencePoint();
        if (movesX() && std::abs(xOf(pos_) - xOf(ref)) > kPositionTolerance)
          return raise("A115", w, {"X", num(2.0 * xOf(pos_)), num(2.0 * xOf(ref))});
        if (movesZ() && std::abs(zOf(pos_) - zOf(ref)) > kPositionTolerance)
          return raise("A115", w, {"Z", num(zOf(pos_)), num(zOf(ref))});
        mach_.positionCheck = true;
        return true;
      }
      case 28: {
        // Only the axes given move: to the intermediate point, then to the
        // reference point. G28 without axes moves nothing (Fanuc).
        if (!hasAxisWords()) return true;
        const Vec2 via = axisTarget();
        if (movesX()) g28X_ = xOf(via);
        if (movesZ()) g28Z_ = zOf(via);
        if (!rapidTo(via, w)) return false;
        Vec2 home = pos_;
        const Vec2 ref = referencePoint();
        if (movesX()) home.y() = xOf(ref);
        if (movesZ()) home.x() = zOf(ref);
        if (!rapidTo(home, w)) return false;
        mach_.positionCheck = true;
        return true;
      }
      case 29: {
        // From the reference point via the G28 intermediate point to the target.
        if (!hasAxisWords()) return true;
        const Vec2 target = axisTarget();
        Vec2 via = pos_;
        if (movesX() && g28X_) via.y() = *g28X_;
        if (movesZ() && g28Z_) via.x() = *g28Z_;
        if (!rapidTo(via, w)) return false;
        return rapidTo(target, w);
      }
      case 50: {
        // Coordinate setting: the tool's controlled point now reads X Z.
        if (!hasAxisWords()) return true;  // G50 S alone: the clamp, handled with the S word
        const Vec2 declared = axisTarget();
        mach_.workShift += declared - pos_;
        pos_ = declared;
        sink_.setPosition(pos_);
        return true;
      }
      case 53: {
        // Rapid to a position in machine coordinates (offsets ignored).
        if (!hasAxisWords()) return true;
        Vec2 target = pos_;
        const double u = unit();
        if (const Word* x = find('X')) target.y() = x->value * u / 2.0 + xOf(mach_.workShift);
        if (const Word* z = find('Z')) target.x() = z->value * u + zOf(mach_.workShift);
        return rapidTo(target, w);
      }
      default: return raise("A117", w, {wordText(*w)});
    }
  }

  const gcode::Program& program_;
  const MachineSetup& setup_;
  const RunOptions& options_;
  MachineSink& sink_;

  ModalState modal_;
  MachineState mach_;
  Vec2 pos_ = Vec2::Zero();            // controlled point without compensation, work coordinates
  std::optional<double> g28X_, g28Z_;  // G28 intermediate point (work coordinates)
  const gcode::Block* block_ = nullptr;
  std::array<const Word*, 26> byLetter_{};
  int blockIndex_ = 0;
  int resumeAfter_ = -1;               // block index the run continues after (G71-G73 profile)
  int singleCycle_ = 0;                // 90, 92 or 94 while a single cycle is modal
  Vec2 singleTarget_ = Vec2::Zero();   // its modal X Z (controlled point)
  double singleTaper_ = 0.0;           // its modal R (mm)
  cycles::CycleMemory cycleMemory_;
  bool stopped_ = false;
  bool stopEndsRun_ = false;
  bool ended_ = false;
};

}  // namespace

void run(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options, MachineSink& sink) {
  Interpreter(program, setup, options, sink).run();
}

Timeline interpret(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options) {
  Timeline timeline;
  timeline.moves.reserve(program.blocks.size() + program.blocks.size() / 2);
  timeline.snapshots.reserve(program.blocks.size());
  auto builder = makeTimelineBuilder(timeline, TimingConfig{setup.machine.rapidX, setup.machine.rapidZ});
  auto compensation = makeCompensationStage(*builder);
  run(program, setup, options, *compensation);
  return timeline;
}

}  // namespace klueng::core::machine

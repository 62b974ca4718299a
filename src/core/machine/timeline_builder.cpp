// Last stage of the chain: turns canonical calls into the Timeline with exact
// times (SPEC 10).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/comp/nose_comp.h"
#include "klueng/core/geometry.h"
#include "klueng/core/machine/kinematics.h"
#include "klueng/core/machine/sink.h"

namespace klueng::core::machine {

namespace {

constexpr double kMinLength = 1e-9;  // mm; shorter moves take no time and are not recorded

class TimelineBuilder final : public MachineSink {
 public:
  TimelineBuilder(Timeline& out, const TimingConfig& config, const TimelineLimits& limits)
      : out_(out), config_(config), limits_(limits) {}

  void motion(const MotionCall& m) override {
    if (halted()) return;
    if (!m.path.isArc() && (m.path.end - m.path.start).norm() < kMinLength) {
      position_ = m.path.end;
      return;
    }
    if (m.kind == MoveKind::Rapid && !m.path.isArc()) {
      rapidDogLeg(m);
      return;
    }
    double seconds = 0.0;
    double feed = 0.0;
    const double rpmStart = spindleRpm(m.ctx, xOf(m.path.start));
    switch (m.kind) {
      case MoveKind::Rapid:  // a bridging arc of a compensated rapid
        seconds = rapidSeconds(m.path, config_.rapidX, config_.rapidZ);
        break;
      case MoveKind::Thread:
        feed = m.lead * rpmStart;
        seconds = feed > 0.0 ? m.path.length() / feed * 60.0 : std::numeric_limits<double>::infinity();
        break;
      default:
        seconds = feedMoveSeconds(m.path, m.ctx);
        feed = m.ctx.feedMode == FeedMode::PerMinute ? m.ctx.feed : m.ctx.feed * rpmStart;
        break;
    }
    if (m.kind == MoveKind::Rapid) feed = seconds > 0.0 ? m.path.length() / seconds * 60.0 : 0.0;
    // Speeds at both ends (mm/s): under G96 with G99 the feed changes with the rpm.
    double feedEnd = feed;
    if (m.kind != MoveKind::Rapid && rpmStart > 0.0 &&
        (m.kind == MoveKind::Thread || m.ctx.feedMode == FeedMode::PerRev))
      feedEnd = feed * spindleRpm(m.ctx, xOf(m.path.end)) / rpmStart;
    const Ramp ramp = rampMove(m.path.length(), seconds, feed / 60.0, feedEnd / 60.0,
                               pathAcceleration(m.path, config_.accelX, config_.accelZ));
    push(m, m.path, ramp.seconds, feed, ramp.up, ramp.down);
  }

  void dwell(const DwellCall& d) override {
    if (halted()) return;
    Move mv;
    stamp(mv, d, d.seconds);
    mv.kind = MoveKind::Dwell;
    mv.path = Segment::line(position_, position_);
    mv.rpm = mv.rpmEnd = spindleRpm(d.ctx, xOf(position_));
    time_ = mv.tEnd;
    keep(mv);
  }

  void setPosition(const Vec2& p) override { position_ = p; }
  void compensation(NoseCompMode, double, int) override {}

  void blockDone(const StateSnapshot& s) override {
    if (halted()) return;
    if (limits_.blockMarksOnly) {
      BlockMark& mark = out_.marks.emplace_back(BlockMark::of(s));
      mark.moveEnd = static_cast<int>(out_.recordMoves.size());
    } else {
      StateSnapshot& snap = out_.snapshots.emplace_back(s);
      snap.time = time_;
      snap.moveEnd = static_cast<int>(out_.moves.size());
      snap.machine.position = position_;
    }
    if (limits_.budgetBytes > 0 && neededBytes() > limits_.budgetBytes) {
      const std::size_t mb = limits_.budgetBytes >> 20;
      out_.alarm = Diagnostic{Severity::Alarm,
                              codes::kRunMemoryBudget,
                              SourceRange{s.line, 1, 0, s.file},
                              {std::to_string(mb), std::to_string(s.line)}};
    }
  }

  void alarm(const Diagnostic& d) override {
    if (!out_.alarm) out_.alarm = d;
  }
  void end() override {}
  bool halted() const override { return out_.alarm.has_value(); }
  double elapsed() const override { return time_; }

 private:
  // What every move takes from its call: the block, the time from now, the tool.
  template <typename Call>
  void stamp(Move& mv, const Call& c, double seconds) const {
    mv.line = c.line;
    mv.blockIndex = c.blockIndex;
    mv.file = c.file;
    mv.callLevel = c.callLevel;
    mv.program = c.program;
    mv.tStart = time_;
    mv.tEnd = time_ + seconds;
    mv.noseCentre = -c.ctx.noseRadius * comp::tipVector(c.ctx.tip);
    mv.tool = c.ctx.tool;
    mv.offset = c.ctx.offset;
    mv.spindle = c.ctx.spindle;
  }

  // A record of marks keeps what the evidence reads of a move; a timeline keeps it whole.
  void keep(const Move& mv) {
    if (limits_.blockMarksOnly) {
      out_.recordMoves.push_back(mv);
      if (limits_.recordSpeeds) out_.recordSpeeds.push_back(MoveSpeeds::of(mv));
    } else {
      out_.moves.push_back(mv);
    }
  }

  void push(const MotionCall& m, const Segment& path, double seconds, double feed, double up = 0.0, double down = 0.0) {
    Move mv;
    stamp(mv, m, seconds);
    mv.kind = m.kind;
    mv.path = path;
    mv.feed = feed;
    mv.rpm = spindleRpm(m.ctx, xOf(path.start));
    mv.rpmEnd = spindleRpm(m.ctx, xOf(path.end));
    mv.lead = m.lead;
    mv.compensated = m.compensated;
    mv.rampUp = static_cast<float>(up);
    mv.rampDown = static_cast<float>(down);
    time_ = mv.tEnd;
    position_ = path.end;
    keep(mv);
  }

  // G00: both axes start together, each at its own rapid rate (and with its
  // own acceleration when set); the one with less time to go arrives first,
  // the other finishes alone (SPEC 7).
  void rapidDogLeg(const MotionCall& m) {
    const Vec2 p0 = m.path.start, p1 = m.path.end;
    const double dz = zOf(p1) - zOf(p0), dx = xOf(p1) - xOf(p0);
    const double rateZ = config_.rapidZ / 60.0, rateX = config_.rapidX / 60.0;  // mm/s
    const double tz = axisSeconds(std::abs(dz), rateZ, config_.accelZ);
    const double tx = axisSeconds(std::abs(dx), rateX, config_.accelX);
    // Each axis's ramp (seconds), shorter than half its move when it cannot reach its rate.
    const double rampZ = config_.accelZ > 0.0 ? std::min(rateZ / config_.accelZ, tz / 2.0) : 0.0;
    const double rampX = config_.accelX > 0.0 ? std::min(rateX / config_.accelX, tx / 2.0) : 0.0;
    const double tBoth = std::min(tz, tx);
    const double tRest = std::max(tz, tx) - tBoth;
    if (tBoth <= 0.0 || tRest <= 1e-12 * std::max(tz, tx)) {
      const double seconds = std::max(tz, tx);
      const double ramp = tz >= tx ? rampZ : rampX;
      push(m, m.path, seconds, m.path.length() / seconds * 60.0, ramp, ramp);
      return;
    }
    // Where the faster-arriving axis is done: how far the other has come by then.
    const Vec2 corner =
        tz < tx
            ? Vec2(zOf(p1), xOf(p0) + std::copysign(axisDistanceAt(tBoth, std::abs(dx), rateX, config_.accelX), dx))
            : Vec2(zOf(p0) + std::copysign(axisDistanceAt(tBoth, std::abs(dz), rateZ, config_.accelZ), dz), xOf(p1));
    const Segment first = Segment::line(p0, corner);
    const Segment second = Segment::line(corner, p1);
    const double rampFast = tz < tx ? rampZ : rampX, rampSlow = tz < tx ? rampX : rampZ;
    push(m, first, tBoth, first.length() / tBoth * 60.0, std::max(rampZ, rampX), rampFast);
    push(m, second, tRest, second.length() / tRest * 60.0, 0.0, rampSlow);
  }

  // What the run keeps so far (it grows with every block and every move), the copy a full list
  // makes when it grows next (it moves into one twice its size while the old one is still held:
  // an endless loop's states took 1.5 x what they kept), and the lists it has outgrown: a batch
  // run keeps freed memory in its heap (src/cli/batch_memory.cpp), so the smaller copies a list
  // left behind as it doubled are still the process's (the check of an endless loop peaked at
  // 1.5 x its budget). A list reserved for the whole program (interpret() reserves the moves and
  // states) makes no copy and leaves none behind.
  std::size_t neededBytes() {
    std::size_t held = 0, copies = 0, k = 0;
    const auto add = [&](const auto& list) {
      const std::size_t size = sizeof(list.front());
      const std::size_t bytes = list.size() * size;
      held += bytes;
      if (!list.empty() && list.size() == list.capacity()) copies += bytes;
      // (Each doubling since the last block: a block of many moves may grow a list more than once.)
      std::size_t& seen = capacities_[k++];
      for (; seen > 0 && seen < list.capacity(); seen *= 2) outgrown_ += seen * size;
      seen = list.capacity();
    };
    if (limits_.blockMarksOnly) {  // (the lists of the other kind stay empty)
      add(out_.marks);
      add(out_.recordMoves.packed());
      add(out_.recordMoves.starts());
      add(out_.recordMoves.centres());
      add(out_.recordSpeeds);
    } else {
      add(out_.moves);
      add(out_.snapshots);
    }
    add(out_.flow.writes);
    add(out_.flow.wordValues);
    return held + copies + outgrown_;
  }

  Timeline& out_;
  TimingConfig config_;
  TimelineLimits limits_;
  Vec2 position_ = Vec2::Zero();
  double time_ = 0.0;
  // neededBytes(): the capacity each list had when last seen, and the bytes of those it outgrew.
  std::array<std::size_t, 9> capacities_{};
  std::size_t outgrown_ = 0;
};

}  // namespace

std::unique_ptr<MachineSink> makeTimelineBuilder(Timeline& out, const TimingConfig& config,
                                                 const TimelineLimits& limits) {
  return std::make_unique<TimelineBuilder>(out, config, limits);
}

}  // namespace klueng::core::machine

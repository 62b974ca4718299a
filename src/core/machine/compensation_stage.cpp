// Nose radius compensation in the sink chain (SPEC 9): a compensated stretch
// (start-up move, contour, cancel move) is buffered with everything that
// happens in between (dwells, finished blocks), compensated as a whole by the
// comp kernel, then forwarded in the original order.
#include <variant>
#include <vector>

#include "klueng/core/comp/nose_comp.h"
#include "klueng/core/machine/sink.h"

namespace klueng::core::machine {

namespace {

class CompensationStage final : public MachineSink {
 public:
  explicit CompensationStage(MachineSink& next) : next_(next) {}

  void motion(const MotionCall& m) override {
    if (halted()) return;
    if (state_ == State::Off) {
      next_.motion(m);
      return;
    }
    if (!m.path.isArc() && (m.path.end - m.path.start).norm() < 1e-9) return;  // takes no time, no offset
    state_ = State::Active;
    motions_.push_back(m);
    events_.push_back(MotionRef{motions_.size() - 1});
    if (cancelPending_) {
      flush(true);
      state_ = State::Off;
      cancelPending_ = false;
    }
  }

  void dwell(const DwellCall& d) override {
    if (state_ == State::Active)
      events_.push_back(d);
    else
      next_.dwell(d);
  }

  void setPosition(const Vec2& p) override {
    if (state_ == State::Active) {
      flush(false);
      state_ = State::Armed;
    }
    next_.setPosition(p);
  }

  void compensation(NoseCompMode mode, double radius, int tip) override {
    if (mode == NoseCompMode::Off) {
      if (state_ == State::Active)
        cancelPending_ = true;
      else
        state_ = State::Off;
      return;
    }
    cancelPending_ = false;
    if (state_ == State::Active) {
      if (mode == mode_) return;
      flush(false);  // G41 <-> G42 without G40: a new stretch starts at the next move
    }
    state_ = State::Armed;
    mode_ = mode;
    radius_ = radius;
    tip_ = tip;
  }

  void blockDone(const StateSnapshot& s) override {
    if (state_ == State::Active)
      events_.push_back(s);
    else
      next_.blockDone(s);
  }

  void alarm(const Diagnostic& d) override {
    if (state_ == State::Active) flush(false);
    next_.alarm(d);
  }

  void end() override {
    if (state_ == State::Active) flush(false);
    next_.end();
  }

  bool halted() const override { return next_.halted(); }
  double elapsed() const override { return next_.elapsed(); }

 private:
  enum class State { Off, Armed, Active };
  struct MotionRef {
    std::size_t index;
  };
  using Event = std::variant<MotionRef, DwellCall, StateSnapshot>;

  void flush(bool endsWithCancel) {
    std::vector<Segment> paths;
    paths.reserve(motions_.size());
    for (const auto& m : motions_) paths.push_back(m.path);
    comp::CompInput in;
    in.moves = paths;
    in.side = mode_ == NoseCompMode::Left ? comp::Side::Left : comp::Side::Right;
    in.radius = radius_;
    in.tip = tip_;
    in.endsWithCancel = endsWithCancel;
    const comp::CompOutput out = comp::compensate(in);
    const std::size_t stopAt = out.interference ? static_cast<std::size_t>(out.interference->source) : motions_.size();

    std::size_t piece = 0;
    for (const Event& e : events_) {
      if (const auto* ref = std::get_if<MotionRef>(&e)) {
        if (ref->index >= stopAt) break;
        const MotionCall& source = motions_[ref->index];
        while (piece < out.pieces.size() && static_cast<std::size_t>(out.pieces[piece].source) < ref->index) ++piece;
        for (; piece < out.pieces.size() && static_cast<std::size_t>(out.pieces[piece].source) == ref->index; ++piece) {
          MotionCall m = source;
          m.path = comp::controlledPath(out.pieces[piece].path, radius_, tip_);
          if (m.path.isArc() && m.kind == MoveKind::Line) m.kind = MoveKind::Arc;   // bridging arc
          if (!m.path.isArc() && m.kind == MoveKind::Arc) m.kind = MoveKind::Line;  // degenerate arc
          m.compensated = true;
          next_.motion(m);
        }
      } else if (const auto* d = std::get_if<DwellCall>(&e)) {
        next_.dwell(*d);
      } else {
        next_.blockDone(std::get<StateSnapshot>(e));
      }
    }
    if (out.interference) {
      const MotionCall& where = motions_[stopAt];
      Diagnostic d;
      d.severity = Severity::Alarm;
      d.code = std::string(comp::interferenceCode(out.interference->kind));
      d.range = where.where;
      d.args = comp::interferenceArgs(*out.interference, in);
      next_.alarm(d);
    }
    motions_.clear();
    events_.clear();
  }

  MachineSink& next_;
  State state_ = State::Off;
  bool cancelPending_ = false;
  NoseCompMode mode_ = NoseCompMode::Off;
  double radius_ = 0.0;
  int tip_ = 0;
  std::vector<MotionCall> motions_;
  std::vector<Event> events_;
};

}  // namespace

std::unique_ptr<MachineSink> makeCompensationStage(MachineSink& next) {
  return std::make_unique<CompensationStage>(next);
}

}  // namespace klueng::core::machine

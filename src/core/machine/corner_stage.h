#pragma once
// The corner stage (Fanuc 0i-TF manual, "Chamfering and corner R"): a sink
// stage in front of the chain, as the compensation stage is. A G01 with ,C or
// ,R is held here until the next block's move shows the corner; then the held
// G01 goes on cut short, followed by the chamfer or the corner arc, and the
// move itself from the corner piece's end. Everything else passes through at
// once, so the chain sees the calls in the order the interpreter made them.
#include <functional>
#include <optional>
#include <string>

#include "klueng/core/machine/sink.h"

namespace klueng::core::machine::detail {

// What a ,C or ,R word asks for.
struct CornerRequest {
  char kind = 'C';    // 'C' chamfer, 'R' radius
  double size = 0.0;  // mm
  SourceRange where;  // the ,C / ,R word (its alarms point here)
  std::string text;   // as written, for the alarms
};

class CornerStage final : public MachineSink {
 public:
  // The interpreter's travel check: false once it has raised its alarm.
  using TravelCheck = std::function<bool(const Segment&, const SourceRange&)>;

  CornerStage(MachineSink& next, TravelCheck travel) : next_(next), travel_(std::move(travel)) {}

  // A corner held by a block before `blockIndex` waits for this block's move.
  bool heldBefore(int blockIndex) const { return held_ && held_->first.blockIndex != blockIndex; }
  bool holding() const { return held_.has_value(); }

  // What a cut did to the controlled point: the held G01's moves start at
  // `restart`, the corner piece ends at `pieceEnd` (the next move goes on from
  // there). `ok` is false once an alarm has been raised.
  struct Cut {
    bool ok = true;
    std::optional<Vec2> restart;
    std::optional<Vec2> pieceEnd;
  };

  // A G01 to the virtual corner with ,C / ,R. A corner an earlier block holds
  // is cut first, with this G01 as its next move.
  Cut hold(const MotionCall& toCorner, const CornerRequest& request);
  // The next block's feed move (`m.path` from the virtual corner) after a held corner.
  Cut follow(const MotionCall& m);
  // The held corner has no next move: alarm, nothing held any more.
  bool refuse();

  void motion(const MotionCall& m) override { next_.motion(m); }
  void dwell(const DwellCall& d) override { next_.dwell(d); }
  void setPosition(const Vec2& p) override { next_.setPosition(p); }
  void compensation(NoseCompMode mode, double radius, int tip) override { next_.compensation(mode, radius, tip); }
  void blockDone(const StateSnapshot& s) override { next_.blockDone(s); }
  void alarm(const Diagnostic& d) override { next_.alarm(d); }
  void end() override { next_.end(); }
  bool halted() const override { return next_.halted(); }
  double elapsed() const override { return next_.elapsed(); }

 private:
  struct Held {
    MotionCall first;  // the G01 to the virtual corner
    CornerRequest request;
  };
  // Cuts the held corner before the move `m`.
  Cut cut(const MotionCall& m);
  bool alarmAt(const Held& held, const char* code);

  MachineSink& next_;
  TravelCheck travel_;
  std::optional<Held> held_;
};

}  // namespace klueng::core::machine::detail

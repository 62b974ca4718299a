#pragma once
// G70-G73 read their profile N(P)..N(Q) by running its blocks through the
// interpreter into this capturing sink instead of the chain (interpreter_profile.cpp):
// the moves they make become the cycle's profile. It is also the profile's
// BlockEffects: what may stand in a profile follows the Fanuc 0i-TF manual
// (multiple repetitive cycles, "Limitations": no one-shot G code but G04, no
// other cycle, no subprogram or macro call); F, S and T take effect in G70
// only ("F, S and T in blocks ns to nf are ignored in G71/G72/G73 and
// effective in G70"), from the block's move on, when the cycle runs.
#include <deque>
#include <optional>
#include <string>

#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/sink.h"
#include "machine/block_effects.h"
#include "machine/cycles.h"

namespace klueng::core::machine::detail {

class ProfileCapture final : public MachineSink, public BlockEffects {
 public:
  // `withFeed`: G70 (the profile's F, S, T, G40-G42 and G04 count); `words`
  // keeps the S and T words the steps point at; `mach`: a T of a G70 profile
  // sets its offset there (the interpreter puts the state back afterwards).
  ProfileCapture(bool withFeed, cycles::Profile& out, const MachineSink& chain, std::deque<gcode::Word>& words,
                 MachineState& mach, const io::OffsetTable& offsets, const Vec2& start)
      : withFeed_(withFeed), out_(out), chain_(chain), words_(words), mach_(mach), offsets_(offsets), end_(start) {}

  // The profile block about to be read.
  void startBlock(int index, int line) {
    block_ = index;
    line_ = line;
  }
  // A block the profile may not hold, `what` naming it: the reading stops.
  bool refuse(const std::string& what, const gcode::Word* where);
  // The first alarm the profile's blocks raised.
  const std::optional<Diagnostic>& alarmSeen() const { return alarmSeen_; }

  // MachineSink: moves, dwells and compensation changes become the profile's steps.
  void motion(const MotionCall& m) override;
  void dwell(const DwellCall& d) override;
  void setPosition(const Vec2&) override {}  // G50 is refused in a profile
  void compensation(NoseCompMode mode, double radius, int tip) override;
  void blockDone(const StateSnapshot&) override {}  // a profile block is read, not run
  void alarm(const Diagnostic& d) override {
    if (!alarmSeen_) alarmSeen_ = d;
  }
  void end() override {}
  bool halted() const override { return alarmSeen_.has_value(); }
  double elapsed() const override { return chain_.elapsed(); }

  // BlockEffects.
  bool checksMoves() const override { return false; }
  bool blockAllowed(const CodeWord* motion, const CodeWord* cycle, const CodeWord* oneShot,
                    const CodeWord* single) override;
  bool tool(const gcode::Word& t) override;
  void feed(double mm) override {
    if (withFeed_) pendingFeed_ = mm;
  }
  bool speed(const gcode::Word& s, bool) override {
    if (withFeed_) pendingS_ = &words_.emplace_back(s);
    return true;
  }
  bool mCodes(const CodeWord* ms, std::size_t& count) override;

 private:
  void add(cycles::Step s, int block) {
    out_.moves.push_back(s);
    out_.blockOf.push_back(block);
  }

  const bool withFeed_;
  cycles::Profile& out_;
  const MachineSink& chain_;
  std::deque<gcode::Word>& words_;
  MachineState& mach_;
  const io::OffsetTable& offsets_;
  std::optional<Diagnostic> alarmSeen_;
  double pendingFeed_ = 0.0;
  const gcode::Word* pendingS_ = nullptr;
  const gcode::Word* pendingT_ = nullptr;
  Vec2 end_;
  int block_ = 0, line_ = 0;
};

}  // namespace klueng::core::machine::detail

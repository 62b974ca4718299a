#pragma once
// The modal interpreter's class (SPEC 6-8, 13), shared by its source files:
//   interpreter.cpp          the block (in-block order of SPEC 7), T, M, C, group-01 motion
//   interpreter_one_shot.cpp group 00: G04 G27 G28 G29 G30 G50 G53
//   interpreter_cycles.cpp   G90/G92/G94, G70-G76 (both forms), G81-G83 drilling
// It reads its dialect's rules from the machine profile (gcode/machine_profile.h),
// never from the dialect itself.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/kinematics.h"
#include "machine/cycles.h"

namespace klueng::core::machine::detail {

using gcode::CodeInfo;
using gcode::Word;

inline constexpr double kMmPerInch = 25.4;
inline constexpr double kMetresPerFoot = 0.3048;   // G96 S is feet/min under G20
inline constexpr double kArcTolerance = 0.01;      // mm (SPEC 5 ext)
inline constexpr double kPositionTolerance = 0.001;

inline std::string num(double v) {
  if (std::abs(v) < 0.0005) v = 0.0;  // no "-0.000"
  return fmt::format("{:.3f}", v);
}

inline std::string wordText(const Word& w) { return std::string(1, w.letter) + w.number; }

struct CodeWord {
  const Word* word;
  const CodeInfo* info;
};

class Interpreter {
 public:
  Interpreter(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options, MachineSink& sink);
  void run();

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

  // ---- interpreter.cpp ---------------------------------------------------------
  bool withinTravel(const Vec2& work, const Word* where);
  bool pathWithinTravel(const Segment& s, const Word* where);
  bool rapidTo(const Vec2& target, const Word* where);
  bool executeBlock();
  static MotionMode motionFor(int g);
  bool selectTool(const Word& t);
  bool mCode(const CodeWord& c);
  bool cAxisWords();
  bool move(const Word* g);
  bool feedReady(const Word* where, const char* code);
  bool feedMove(MoveKind kind, const Segment& path, const Word* where);
  std::optional<Segment> arcTo(const Vec2& end, bool ccw, const Word* where);

  // ---- interpreter_one_shot.cpp -------------------------------------------------
  Vec2 referencePoint() const;
  bool oneShot(const CodeWord& c);
  bool dwell(const Word* w);
  bool referenceReturn(const Word* w);

  // ---- interpreter_cycles.cpp ---------------------------------------------------
  bool compensationAllowed(const Word* g);
  bool singleCycle(const Word* where, bool fresh);
  cycles::CycleInput cycleInput(const Word* g) const;
  bool cannedCycle(const CodeWord& c);
  bool drillingCycle(int g, const Word* where, bool fresh);
  bool cycleAlarm(const cycles::CycleAlarm& a);
  bool cycleReady(const std::vector<cycles::Step>& steps, const Word* g, const std::string& name);
  bool emitCycle(const std::vector<cycles::Step>& steps, const Word* g, const std::string& name);

  const gcode::Program& program_;
  const MachineSetup& setup_;
  const RunOptions& options_;
  const gcode::MachineProfile& profile_;
  MachineSink& sink_;

  ModalState modal_;
  MachineState mach_;
  Vec2 pos_ = Vec2::Zero();            // controlled point without compensation, work coordinates
  std::optional<double> g28X_, g28Z_;  // G28/G30 intermediate point (work coordinates)
  const gcode::Block* block_ = nullptr;
  std::array<const Word*, 26> byLetter_{};
  int blockIndex_ = 0;
  int resumeAfter_ = -1;               // block index the run continues after (G71-G73 profile)
  int singleCycle_ = 0;                // 90, 92 or 94 while a single cycle is modal
  Vec2 singleTarget_ = Vec2::Zero();   // its modal X Z (controlled point)
  double singleTaper_ = 0.0;           // its modal R (mm)
  int drillCycle_ = 0;                 // 81, 82 or 83 while a drilling cycle is modal (G80 ends it)
  cycles::DrillWords drill_;           // its modal words
  cycles::CycleMemory cycleMemory_;
  bool stopped_ = false;
  bool stopEndsRun_ = false;
  bool ended_ = false;
};

}  // namespace klueng::core::machine::detail

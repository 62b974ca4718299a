#pragma once
// The modal interpreter's class (SPEC 6-8, 13), shared by its source files:
//   interpreter.cpp          the block (in-block order of SPEC 7), T, M, C, group-01 motion
//   interpreter_one_shot.cpp group 00: G04 G27 G28 G29 G30 G50 G53
//   interpreter_cycles.cpp   G90/G92/G94, G70-G76 (both forms), G81-G83 drilling
//   interpreter_corner.cpp   ,C ,R ,A on G01 (the CornerStage cuts the corner)
//   interpreter_flow.cpp     the run loop, macro statements (the FlowEngine moves the counter)
//   interpreter_macro.cpp    the system variables that show machine state (the MacroStore keeps the rest)
//   interpreter_profile.cpp  G70-G73 reading their profile into a ProfileCapture
// It owns the running block and the modal and machine state; the parts it
// composes own the rest (README.md). It reads its dialect's rules from the
// machine profile (gcode/machine_profile.h), never from the dialect itself.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <deque>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/gcode/address_table.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/macro.h"
#include "klueng/core/gcode/program_index.h"
#include "klueng/core/machine/flow.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/kinematics.h"
#include "machine/block_effects.h"
#include "machine/corner_stage.h"
#include "machine/cycles.h"
#include "machine/flow_engine.h"
#include "machine/macro_store.h"
#include "machine/number_text.h"

namespace klueng::core::machine::detail {

using gcode::CallTarget;
using gcode::CodeAction;
using gcode::CodeInfo;
using gcode::Word;

inline constexpr double kMmPerInch = 25.4;
inline constexpr double kMetresPerFoot = 0.3048;  // G96 S is feet/min under G20
inline constexpr double kArcTolerance = 0.01;     // mm (SPEC 5 ext)
inline constexpr double kPositionTolerance = 0.001;

inline std::string wordText(const Word& w) { return std::string(1, w.letter) + w.number; }

// A G65 / G66 / G67 block (the code table's macro call actions) runs as a call, not as motion.
bool isMacroCallBlock(const gcode::Block& b, gcode::Dialect dialect, CodeWord& g);

// The running block's T, F, S and M take effect on the machine (the
// interpreter is the run's BlockEffects) or in a profile being read.
class Interpreter final : public gcode::MacroVariables, private BlockEffects {
 public:
  Interpreter(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options, MachineSink& sink,
              FlowLog* flow);
  Interpreter(const Interpreter&) = delete;  // its profile reader points at itself
  Interpreter& operator=(const Interpreter&) = delete;
  void run();
  bool read(int n, gcode::MacroValue& out, const char*& errorCode) override;

 private:
  // ---- helpers -------------------------------------------------------------

  double unit() const { return modal_.units == Units::Inch ? kMmPerInch : 1.0; }
  // What an absolute X/Z word is measured from: the tool's offset, and a G52 local zero.
  Vec2 offsetVector() const { return Vec2(mach_.offsetZ, mach_.offsetX / 2.0) + localShift_; }

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

  // Where an alarm about `where` points: the word, else the block's line.
  SourceRange rangeOf(const Word* where) const { return where ? where->range : SourceRange{block_->line, 1, 0}; }

  bool raise(const char* code, const Word* where, std::vector<std::string> args) {
    return raiseAt(code, rangeOf(where), std::move(args));
  }
  bool raiseAt(const char* code, const SourceRange& at, std::vector<std::string> args) {
    Diagnostic d;
    d.severity = Severity::Alarm;
    d.code = code;
    d.range = at;
    d.args = std::move(args);
    sink_->alarm(d);
    return false;
  }

  // Feed, spindle or speed missing for a cut: the run stops there, but a record
  // for evidence (RunOptions::throughAlarms) notes it and makes the move.
  bool cuttingCondition(const char* code, const Word* where, std::vector<std::string> args) {
    raise(code, where, std::move(args));
    return options_.throughAlarms;
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

  void fillDwell(DwellCall& d) const {
    d.line = block_->line;
    d.blockIndex = blockIndex_;
    d.file = block_->file;
    d.callLevel = flow_.level();
    d.program = flow_.program();
    d.ctx = context();
  }

  void fillCall(MotionCall& m, const Word* where) const {
    m.line = block_->line;
    m.blockIndex = blockIndex_;
    m.file = block_->file;
    m.callLevel = flow_.level();
    m.program = flow_.program();
    m.where = rangeOf(where);
    m.ctx = context();
  }

  void moved(const Vec2& target) {
    movedThisBlock_ = true;
    flow_.noteMove();
    if ((target - pos_).norm() > 1e-9) mach_.positionCheck = false;
    pos_ = target;
  }

  // ---- interpreter.cpp ---------------------------------------------------------
  bool withinTravel(const Vec2& work, const SourceRange& at);
  bool withinTravel(const Vec2& work, const Word* where) { return withinTravel(work, rangeOf(where)); }
  bool pathWithinTravel(const Segment& s, const SourceRange& at);
  bool pathWithinTravel(const Segment& s, const Word* where) { return pathWithinTravel(s, rangeOf(where)); }
  bool rapidTo(const Vec2& target, const Word* where);
  bool executeBlock();
  void readDistanceMode();
  static MotionMode motionFor(gcode::CodeAction action);
  bool selectTool(const Word& t);
  // BlockEffects of a run: the words act on the machine.
  bool checksMoves() const override { return true; }
  bool blockAllowed(const CodeWord*, const CodeWord*, const CodeWord*, const CodeWord*) override { return true; }
  bool tool(const Word& t) override { return selectTool(t); }
  void feed(double) override {}  // modal: the block has set it
  bool speed(const Word& s, bool coordinateSet) override;
  bool mCodes(const CodeWord*, std::size_t&) override { return true; }
  bool mCode(const CodeWord& c);
  bool cAxisWords();
  bool move(const Word* g);
  bool feedReady(const Word* where, const char* code);
  bool feedMove(MoveKind kind, const Segment& path, const Word* where);
  std::optional<Segment> arcTo(const Vec2& end, bool ccw, const Word* where);

  void emitSnapshot();
  StateSnapshot snapshot();  // the state after the current block

  // ---- interpreter_flow.cpp (the run loop, macro statements; the flow engine moves the counter) ---
  CallSite callSite() const { return CallSite{blockIndex_, block_->file, block_->line, snapshots_}; }
  bool flowAlarm(const char* code, const SourceRange& at, std::vector<std::string> args) {
    return raiseAt(code, at, std::move(args));
  }
  bool runBlock(int index);
  // At a block reached by a backward jump: false (an alarm stopped the run) when the run
  // was in this very state before (loop_proof.h).
  bool loopCanEnd();
  void writeState(RunStateWords& out) const;  // the modal and machine state, the position, the offsets
  bool statement(const gcode::Block& b);
  bool evaluateWords(const gcode::Block& b);
  bool evaluate(int expr, const SourceRange& at, gcode::MacroValue& out);
  bool writeVariable(int n, gcode::MacroValue v, const SourceRange& at);
  bool macroCall(const gcode::Block& b, const CodeWord& g);
  double positionValue(int axis, bool machine) const;
  int modalCode(int group) const;
  int modalCodeInA(int group) const;  // as system A numbers it
  // Threading under G96: the profile's alarm, or a warning (once a run) and true.
  bool threadUnderCssAllowed(const Word* where);
  bool threadCssWarned_ = false;
  bool spindleClampWarned_ = false;  // W132 once a run
  bool reversalWarned_ = false;      // W133 once a run
  bool cycleCompWarned_ = false;     // W134 once a run
  // S above the machine's maximum under G97: an alarm, or the speed the control clamps it to.
  std::optional<double> allowedRpm(const Word& s);

  // ---- interpreter_corner.cpp (,C ,R ,A on G01; the corner stage cuts the corner) ---
  const Word* commaWord(char letter) const { return block_->findComma(letter); }
  // ,C, or an I or K where the profile reads them as ,C (Haas, 90-degree corners).
  const Word* chamferWord() const {
    if (const Word* c = commaWord('C')) return c;
    if (!profile_.flow.chamferWithIOrK) return nullptr;
    const Word* i = block_->find('I');
    return i ? i : block_->find('K');
  }
  // ,R, or an R where the profile reads it as ,R (Fanuc T "Chamfering and corner R").
  const Word* cornerWord() const {
    if (const Word* r = commaWord('R')) return r;
    return profile_.flow.cornerRWithoutComma ? block_->find('R') : nullptr;
  }
  bool holdCorner(const Segment& path, const Word* where);
  bool feedMoveAfterCorner(MoveKind kind, const Segment& path, const Word* where);
  bool cornerCut(const CornerStage::Cut& cut);
  bool angleTarget(Vec2& target);

  // ---- interpreter_one_shot.cpp -------------------------------------------------
  Vec2 referencePoint() const;
  bool oneShot(const CodeWord& c);
  bool dwell(const Word* w);
  bool referenceReturn(const Word* w);
  bool dataSetting(const Word* w);
  bool localCoordinates(const Word* w);

  // ---- interpreter_cycles.cpp ---------------------------------------------------
  bool compensationAllowed(const Word* g);
  bool singleCycle(const Word* where, bool fresh);
  cycles::CycleInput cycleInput(const Word* g) const;
  bool cannedCycle(const CodeWord& c);
  bool drillingCycle(const CodeInfo& g, const Word* where, bool fresh);
  bool cycleAlarm(const cycles::CycleAlarm& a);
  bool cycleReady(const std::vector<cycles::Step>& steps, const Word* g, const std::string& name);
  bool emitCycle(const std::vector<cycles::Step>& steps, const Word* g, const std::string& name);
  bool emitUncompensated(const std::vector<cycles::Step>& steps, const Word* g, const std::string& name);

  // ---- interpreter_profile.cpp (G70-G73 read N(P)..N(Q) by running them) ---------
  std::optional<cycles::CycleAlarm> readProfile(const gcode::Block& cycle, const Word* g, bool withFeed,
                                                cycles::Profile& out);

  const gcode::Program& program_;
  const MachineSetup& setup_;
  const RunOptions& options_;
  const gcode::MachineProfile& profile_;
  CornerStage runCorners_;  // the corner stage in front of the run's sink
  CornerStage* corners_;    // it, or the one in front of a profile's capturing sink
  MachineSink* sink_;       // the same stage: every call goes through it

  ModalState modal_;
  MachineState mach_;
  io::OffsetTable offsets_;            // the setup's offsets; macro B may write them (#2001 ...)
  Vec2 pos_ = Vec2::Zero();            // controlled point without compensation, work coordinates
  std::optional<double> g28X_, g28Z_;  // G28/G30 intermediate point (work coordinates)
  Vec2 localShift_{0.0, 0.0};          // G52 local zero (Z, X radius) in the work coordinates
  bool zxPlane_ = true;                // G18 (a lathe's plane); G17/G19 arcs are not simulated
  const gcode::Block* block_ = nullptr;
  gcode::Block incrementalBlock_;  // a block read under G91 (systems B, C): X Z as U W
  bool distanceModes_ = false;     // the machine's G-code system has G90/G91 absolute/incremental
  std::array<const Word*, 26> byLetter_{};
  int blockIndex_ = 0;
  int resumeAfter_ = -1;                   // block index the run continues after (G71-G73 profile)
  const CodeInfo* singleCycle_ = nullptr;  // G90, G92 or G94 while a single cycle is modal
  Vec2 singleTarget_ = Vec2::Zero();       // its modal X Z (controlled point)
  double singleTaper_ = 0.0;               // its modal R (mm)
  const CodeInfo* drillCycle_ = nullptr;   // G81, G82 or G83 while a drilling cycle is modal (G80 ends it)
  cycles::DrillWords drill_;               // its modal words
  cycles::CycleMemory cycleMemory_;
  cycles::ProfileReader profileReader_;   // readProfile, for the cycle expansions
  BlockEffects* effects_;                 // the interpreter, or the capture of a profile being read
  std::deque<gcode::Word> profileWords_;  // the S and T words a G70 profile hands to its steps
  bool stopped_ = false;
  bool stopEndsRun_ = false;
  bool optionalStopBlock_ = false;  // this block holds M01

  MacroStore macros_;    // #1-#999 and the system variables a run keeps
  FlowEngine flow_;      // the program counter, call stack and loops (after macros_: its calls push their levels)
  LoopProof loopProof_;  // the states at the backward jumps, compared (an endless loop is proven)
  int snapshots_ = 0;    // snapshots emitted so far (the index of the next one)
  bool movedThisBlock_ = false;
  gcode::Block scratch_;  // the running block with its expressions evaluated
};

}  // namespace klueng::core::machine::detail

#include "modal_check.h"

#include <cmath>
#include <optional>
#include <string>

#include "diagnostic_codes.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/word_format.h"

namespace klueng::core::gcode {

namespace {

constexpr double kArcToleranceMm = 0.01;  // as the interpreter's arcs (SPEC 5 ext)

bool isFeedMotion(CodeAction a) {
  return a == CodeAction::Line || a == CodeAction::ArcCw || a == CodeAction::ArcCcw || a == CodeAction::Thread;
}

// Codes after which the walk cannot know the state without running the program.
bool endsTheWalk(CodeAction a) {
  switch (a) {
    case CodeAction::MacroCall:
    case CodeAction::MacroModalCall:
    case CodeAction::LocalCall:
    case CodeAction::SubprogramCall:
    case CodeAction::SubprogramReturn: return true;
    default: return false;
  }
}

// Codes after which the tool's position in program coordinates is not known
// from the words alone (cycles return to their start, G28 goes to the reference
// point, G50 X/Z renames the position, a corner moves the next move's start).
bool losesPosition(CodeAction a) {
  if (isCuttingCycle(a)) return true;
  switch (a) {
    case CodeAction::BoxTurning:
    case CodeAction::BoxThreading:
    case CodeAction::BoxFacing:
    case CodeAction::ReferenceCheck:
    case CodeAction::ReferenceReturn:
    case CodeAction::SecondReferenceReturn:
    case CodeAction::ReturnFromReference:
    case CodeAction::CoordinateSet:
    case CodeAction::MachineCoordinates:
    case CodeAction::WorkOffset:
    case CodeAction::Inch:
    case CodeAction::Metric: return true;
    default: return false;
  }
}

class ModalWalk {
 public:
  ModalWalk(const CheckOptions& options, std::vector<Diagnostic>& out) : options_(options), out_(out) {}

  // False when the rest of the program cannot be followed.
  bool block(const Block& b, bool firstOfFile) {
    if (b.file != 0 || b.statement().kind != StatementKind::None || b.hasExpressions) return false;
    if (!firstOfFile && !b.words.empty() && b.words.front().letter == 'O') return false;  // another program
    // One pass over the words (the walk runs on every edit of a 100,000-block program).
    std::optional<CodeAction> motion;  // a group-01 code written in this block
    const Word *motionWord = nullptr, *g96 = nullptr, *x = nullptr, *z = nullptr, *u = nullptr, *w = nullptr;
    bool hasS = false, coordinateSet = false, cycle = false, position = true, axisWordsNotAMove = false;
    bool ends = false;
    for (const Word& word : b.words) {
      if (word.comma) {
        position = false;  // ,C ,R ,A: a corner moves the next move's start
        continue;
      }
      switch (word.letter) {
        case 'X':
          if (!x) x = &word;
          continue;
        case 'Z':
          if (!z) z = &word;
          continue;
        case 'U':
          if (!u) u = &word;
          continue;
        case 'W':
          if (!w) w = &word;
          continue;
        case 'F': feedSet_ = true; continue;
        case 'S': hasS = true; continue;
        case 'T': position = false; continue;
        case 'G':
        case 'M': break;
        default: continue;
      }
      const CodeInfo* info = word.hasDecimalPoint ? nullptr : findCode(word.letter, word.code(), options_.dialect);
      if (!info) continue;
      const CodeAction a = info->action;
      if (endsTheWalk(a)) return false;
      if (a == CodeAction::ProgramEnd) ends = true;
      if (word.letter == 'M') continue;
      if (losesPosition(a)) position = false;
      if (info->group == ModalGroup::Motion) {
        motion = a;
        motionWord = &word;
      }
      switch (a) {
        case CodeAction::ConstantSurface: g96 = &word; break;
        case CodeAction::CoordinateSet: coordinateSet = true; [[fallthrough]];
        case CodeAction::Dwell:
        case CodeAction::ReferenceCheck:
        case CodeAction::ReferenceReturn:
        case CodeAction::SecondReferenceReturn:
        case CodeAction::ReturnFromReference:
        case CodeAction::MachineCoordinates:
        case CodeAction::DataSetting:
          axisWordsNotAMove = true;  // X/Z/U/W here are a time, a point or a name, not a feed move
          break;
        case CodeAction::Inch: inch_ = true; break;
        case CodeAction::Metric: inch_ = false; break;
        case CodeAction::CycleCancel: drilling_ = false; break;
        default: break;
      }
      if (isCuttingCycle(a)) cycle = true;
      if (isDrillingCycle(a)) drilling_ = true;
    }
    if (coordinateSet && hasS) clamped_ = true;
    if (g96 && !clamped_ && !b.blockSkip) report(codes::kConstantSurfaceWithoutClamp, *g96, {});
    if (motion) {
      motion_ = *motion;
      drilling_ = false;  // a group-01 code ends a drilling cycle
    }
    const bool boxCycle =
        motion_ == CodeAction::BoxTurning || motion_ == CodeAction::BoxThreading || motion_ == CodeAction::BoxFacing;
    if (boxCycle || drilling_) cycle = true;

    const bool moves = (x || z || u || w) && !cycle && !axisWordsNotAMove;
    if (moves && isFeedMotion(motion_) && !feedSet_ && !b.blockSkip) {
      report(codes::kFeedMoveWithoutFeed,
             motionWord ? *motionWord
                        : *(x   ? x
                            : z ? z
                            : u ? u
                                : w),
             {motionWord ? motionWord->text() : codeName(motion_)});
      feedSet_ = true;  // the run stops at the first: one warning, not one per block after it
    }
    // A feed given in this block counts for its own move (F is read before the motion).

    // Where the block ends, in program coordinates (X as a diameter).
    const std::optional<double> toX = x   ? std::optional<double>(x->value)
                                      : u ? (x_ ? std::optional<double>(*x_ + u->value) : std::nullopt)
                                          : x_;
    const std::optional<double> toZ = z   ? std::optional<double>(z->value)
                                      : w ? (z_ ? std::optional<double>(*z_ + w->value) : std::nullopt)
                                          : z_;
    if (moves && (motion_ == CodeAction::ArcCw || motion_ == CodeAction::ArcCcw) && !b.blockSkip)
      arcRadius(b, toX, toZ);
    if (moves) {
      x_ = toX;
      z_ = toZ;
    }
    if (!position || cycle || axisWordsNotAMove || b.blockSkip) x_.reset(), z_.reset();
    return !ends;
  }

  void setInch(bool inch) { inch_ = inch; }

 private:
  // The dialect's code for a modal motion (G33 for a thread in G-code system B).
  std::string codeName(CodeAction a) const {
    const CodeInfo* row = findAction('G', a, options_.dialect);
    return row ? codeWord(*row) : std::string();
  }

  // A114 as the interpreter raises it: R shorter than half the chord.
  void arcRadius(const Block& b, const std::optional<double>& toX, const std::optional<double>& toZ) {
    const Word* r = b.find('R');
    if (!r || !x_ || !z_ || !toX || !toZ) return;
    const double dz = *toZ - *z_, dx = (*toX - *x_) / 2.0;
    const double half = std::hypot(dz, dx) / 2.0;
    const double tolerance = kArcToleranceMm / (inch_ ? 25.4 : 1.0);
    if (half < 1e-9 || std::abs(r->value) >= half - tolerance) return;
    report(codes::kArcRadiusCannotJoin, *r, {r->text(), formatFixed(half, 3)});
  }

  void report(const char* code, const Word& at, std::vector<std::string> args) {
    out_.push_back(Diagnostic{Severity::Warning, code, at.range, std::move(args)});
  }

  const CheckOptions& options_;
  std::vector<Diagnostic>& out_;
  CodeAction motion_ = CodeAction::Rapid;  // G00 at power on
  bool feedSet_ = false;
  bool clamped_ = false;
  bool inch_ = false;
  bool drilling_ = false;        // a drilling cycle is modal until G80 or a group-01 code
  std::optional<double> x_, z_;  // unknown until both are given absolutely
};

}  // namespace

void checkModalState(const Program& program, const CheckOptions& options, std::vector<Diagnostic>& out) {
  ModalWalk walk(options, out);
  walk.setInch(options.powerOnUnits.value_or(machineProfile(options.dialect).powerOnUnits) == InputUnits::Inch);
  bool first = true;
  for (const Block& b : program.blocks) {
    if (!walk.block(b, first)) break;
    first = false;
  }
}

}  // namespace klueng::core::gcode

// Custom macro B variables (Fanuc 0i-TF manual, "Types of variables" and
// "System variables"): #0 vacant; what the run keeps (#1-#999, timers,
// counters) is the MacroStore's (macro_store.h); here the system variables
// that show the machine's state (offsets, modal codes, positions). Writes are
// recorded in the FlowLog for the variable watch.
#include <algorithm>
#include <cmath>

#include "machine/interpreter_impl.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine::detail {

using gcode::MacroValue;

// The modal G code of a Fanuc group number (#4001-#4022), numbered as the
// machine's G-code system numbers it (G33, G95 in system B).
int Interpreter::modalCode(int group) const {
  // A cycle's row already carries its number in the machine's system.
  if (group == 1 && singleCycle_) return singleCycle_->number;
  if (group == 10 && drillCycle_) return drillCycle_->number;
  const int code = modalCodeInA(group);
  const int inSystem = code > 0 ? gcode::numberInSystem('G', code, profile_.dialect) : code;
  return inSystem >= 0 ? inSystem : code;
}

int Interpreter::modalCodeInA(int group) const {
  switch (group) {
    case 1:
      if (singleCycle_) return singleCycle_->number;
      switch (modal_.motion) {
        case MotionMode::Rapid: return 0;
        case MotionMode::Line: return 1;
        case MotionMode::ArcCw: return 2;
        case MotionMode::ArcCcw: return 3;
        case MotionMode::Thread: return 32;
      }
      return 0;
    case 2: return modal_.spindleMode == SpindleMode::ConstantSurface ? 96 : 97;
    case 5: return modal_.feedMode == FeedMode::PerMinute ? 98 : 99;
    case 6: return modal_.units == Units::Inch ? 20 : 21;
    case 7: return modal_.noseComp == NoseCompMode::Left ? 41 : modal_.noseComp == NoseCompMode::Right ? 42 : 40;
    case 10: return drillCycle_ ? drillCycle_->number : 80;
    case 12: return flow_.modalCallActive() ? 66 : 67;
    case 14: return modal_.workCoordinate;
    case 16: return 18;
    default: return 0;
  }
}

// #5001/#5002 (#5041/#5042): the programmed point in work coordinates; #5021/#5022
// in machine coordinates. X as a diameter, in the input units.
double Interpreter::positionValue(int axis, bool machine) const {
  Vec2 p = machine ? pos_ - mach_.workShift : pos_ - offsetVector();
  const double v = axis == 1 ? 2.0 * xOf(p) : zOf(p);
  return v / unit();
}

bool Interpreter::read(int n, MacroValue& out, const char*& errorCode) {
  errorCode = codes::kNoSuchVariable;
  out = MacroValue{};
  if (n == 0) return true;
  if (macros_.read(n, flow_.localLevel(), *sink_, out)) return true;
  const int offsets = static_cast<int>(offsets_.offsets.size());
  // Tool offsets: #2001+ X, #2101+ Z, #2201+ nose radius, #2301+ tip (per offset number).
  if (n >= 2001 && n <= 2400) {
    const int kind = (n - 2001) / 100, row = (n - 2001) % 100 + 1;
    if (row > offsets) return false;
    const io::Offset& o = offsets_.at(row);
    const double lengthUnit = unit();
    switch (kind) {
      case 0: out = MacroValue::of(o.x / lengthUnit); break;
      case 1: out = MacroValue::of(o.z / lengthUnit); break;
      case 2: out = MacroValue::of(o.r / lengthUnit); break;
      default: out = MacroValue::of(o.tip); break;
    }
    return true;
  }
  switch (n) {
    case 3000: return true;  // vacant until written (the write raises the alarm)
    case 4109: out = MacroValue::of(modal_.feed / unit()); return true;
    case 4115: out = MacroValue::of(flow_.program()); return true;
    case 4119: out = MacroValue::of(modal_.sWord); return true;
    case 5001:
    case 5041: out = MacroValue::of(positionValue(1, false)); return true;
    case 5002:
    case 5042: out = MacroValue::of(positionValue(2, false)); return true;
    case 5021: out = MacroValue::of(positionValue(1, true)); return true;
    case 5022: out = MacroValue::of(positionValue(2, true)); return true;
    default: break;
  }
  if (n >= 4001 && n <= 4022) {
    out = MacroValue::of(modalCode(n - 4000));
    return true;
  }
  return false;
}

bool Interpreter::writeVariable(int n, MacroValue v, const SourceRange& at) {
  const std::string name = "#" + std::to_string(n);
  const int localFrame = n >= 1 && n <= 33 ? flow_.frame().localId : -1;
  if (macros_.write(n, flow_.localLevel(), *sink_, v)) {
    // kept by the store
  } else if (n == 3000) {
    // #3000 = n (MESSAGE): a program alarm with the block's comment as its text.
    if (FlowLog* log = flow_.log()) log->writes.push_back(VariableWrite{snapshots_, n, -1, v.value, v.vacant});
    // The control shows it as alarm 3000 + n (Fanuc: n = 0..200).
    const int number = 3000 + static_cast<int>(std::clamp(std::round(v.value), 0.0, 999.0));
    return flowAlarm(codes::kProgramAlarm, at,
                     {gcode::macroNumberText(v.value), std::string(block_->comment()), std::to_string(number)});
  } else if (n == 3006) {
    // #3006 = n (MESSAGE): a stop with a message, as M00.
    flow_.notice(Severity::Note, codes::kMacroStop, at, {std::string(block_->comment())});
    stopped_ = true;
    stopEndsRun_ = options_.stopAtM00;
  } else if (n >= 2001 && n <= 2400 && (n - 2001) % 100 < static_cast<int>(offsets_.offsets.size())) {
    // Offsets: #2001+ X (diameter), #2101+ Z, #2201+ nose radius, #2301+ tip. A program
    // that corrects its own wear writes them; the new value counts from the next T word.
    const int kind = (n - 2001) / 100, row = (n - 2001) % 100;
    io::Offset& o = offsets_.offsets[static_cast<std::size_t>(row)];
    const double value = v.vacant ? 0.0 : v.value;
    switch (kind) {
      case 0: o.x = value * unit(); break;
      case 1: o.z = value * unit(); break;
      case 2:
        if (value < 0.0) return flowAlarm(codes::kReadOnlyVariable, at, {name + " =", std::to_string(n)});
        o.r = value * unit();
        break;
      default: {
        const double tip = std::round(value);
        if (tip < 0.0 || tip > 9.0 || tip != value)
          return flowAlarm(codes::kReadOnlyVariable, at, {name + " =", std::to_string(n)});
        o.tip = static_cast<int>(tip);
        break;
      }
    }
  } else {
    MacroValue ignored;
    const char* code = nullptr;
    if (n == 0 || read(n, ignored, code))
      return flowAlarm(codes::kReadOnlyVariable, at, {name + " =", std::to_string(n)});
    return flowAlarm(codes::kNoSuchVariable, at, {std::to_string(n)});
  }
  if (FlowLog* log = flow_.log()) log->writes.push_back(VariableWrite{snapshots_, n, localFrame, v.value, v.vacant});
  return true;
}

}  // namespace klueng::core::machine::detail

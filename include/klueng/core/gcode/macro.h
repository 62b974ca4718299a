#pragma once
// Custom macro B expressions (Fanuc 0i-TF manual, "Custom macro": arithmetic
// and logic operations; Haas reads the same): reading them from text and
// evaluating them. Values follow the vacant (#0) rules of the manual:
// a vacant variable reads as 0 in arithmetic, stays vacant when assigned
// plainly (#2=#1), and EQ/NE tell vacant from 0.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/gcode/program.h"

namespace klueng::core::gcode {

struct MacroValue {
  double value = 0.0;
  bool vacant = true;
  static MacroValue of(double v) { return MacroValue{v, false}; }
};

// Reading an expression: `text` starts at the expression; stops at the first
// character that cannot continue it. Columns count bytes from `column` (an
// expression is ASCII). On error, code/args/errorColumn say what went wrong.
struct ExprReadResult {
  bool ok = false;
  std::size_t end = 0;         // bytes consumed
  const char* code = nullptr;  // E121.. (diagnostic_codes.h)
  std::vector<std::string> args;
  int errorColumn = 0;
};

enum class ExprForm {
  Full,      // a whole expression: #1+2*SIN[#3] EQ 4
  Address,   // after an address letter: [-+]? ( #var | [expr] )
  Variable,  // after '#' of an assignment: the number of the variable (100, [#1+100], #5)
};

ExprReadResult readExpression(std::string_view text, int column, ExprForm form, Expression& out);

// Variable access for evaluation.
class MacroVariables {
 public:
  virtual ~MacroVariables() = default;
  // Value of #n; false (with the error code filled) when n names no variable.
  virtual bool read(int n, MacroValue& out, const char*& errorCode) = 0;
};

struct EvalResult {
  bool ok = true;
  MacroValue value;
  const char* code = nullptr;  // run-time alarm code (A13x)
  std::vector<std::string> args;
};

EvalResult evaluate(const Expression& expr, MacroVariables& variables);

// The variable number an assignment target evaluates to: a whole number
// (rounded as the control rounds, to the nearest integer).
int variableNumber(double v);

// A number as a macro value is printed in messages and the watch: up to 4 decimals, no trailing zeros.
std::string macroNumberText(double v);

}  // namespace klueng::core::gcode

// Evaluating macro B expressions (macro.h): a small stack machine over the
// postfix code. Angles in degrees, as the Fanuc and Haas controls use them.
#include <cmath>
#include <cstdint>
#include <fmt/format.h>
#include <numbers>

#include "klueng/core/gcode/macro.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::gcode {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// ROUND, FIX and FUP of the manual: half away from zero, toward zero, away from zero.
double roundHalfAway(double v) { return v < 0 ? -std::floor(-v + 0.5) : std::floor(v + 0.5); }
double fix(double v) { return std::trunc(v); }
double fup(double v) {
  const double t = std::trunc(v);
  return t == v ? v : t + (v > 0 ? 1.0 : -1.0);
}

// Logical operations work on the whole-number (binary) values of the operands.
std::int64_t bits(double v) {
  if (!(std::abs(v) < 9.0e15)) return 0;
  return static_cast<std::int64_t>(roundHalfAway(v));
}

double toBcd(double v) {  // BIN -> BCD: 123 -> 0x123
  std::int64_t n = bits(v), out = 0, shift = 0;
  if (n < 0) n = -n;
  while (n > 0 && shift < 60) {
    out |= (n % 10) << shift;
    n /= 10;
    shift += 4;
  }
  return static_cast<double>(out);
}
double fromBcd(double v) {  // BCD -> BIN: 0x123 -> 123
  std::int64_t n = bits(v), out = 0, scale = 1;
  if (n < 0) n = -n;
  while (n > 0) {
    out += (n & 0xF) * scale;
    n >>= 4;
    scale *= 10;
  }
  return static_cast<double>(out);
}

// A comparison treats vacant as 0, except EQ/NE between a vacant and a value (manual: #0 rules).
bool equal(const MacroValue& a, const MacroValue& b) {
  if (a.vacant || b.vacant) return a.vacant == b.vacant;
  return std::abs(a.value - b.value) < 1e-9 * std::max(1.0, std::max(std::abs(a.value), std::abs(b.value)));
}

}  // namespace

int variableNumber(double v) {
  if (!(std::abs(v) < 1e9)) return -1;
  return static_cast<int>(roundHalfAway(v));
}

std::string macroNumberText(double v) {
  if (std::abs(v) < 0.00005) v = 0.0;
  std::string s = fmt::format("{:.4f}", v);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

EvalResult evaluate(const Expression& expr, MacroVariables& variables) {
  EvalResult r;
  // Small fixed stack: expressions are nested at most 64 deep, so this rarely grows.
  std::vector<MacroValue> stack;
  stack.reserve(16);
  auto fail = [&](const char* code, std::vector<std::string> args) {
    r.ok = false;
    r.code = code;
    r.args = std::move(args);
    return r;
  };
  auto pop = [&]() {
    if (stack.empty()) return MacroValue{};
    const MacroValue v = stack.back();
    stack.pop_back();
    return v;
  };
  auto push = [&](double v) { stack.push_back(MacroValue::of(v)); };

  for (const ExprToken& t : expr.code) {
    switch (t.op) {
      case ExprOp::Constant: push(t.value); break;
      case ExprOp::Variable: {
        const MacroValue n = pop();
        const int number = variableNumber(n.value);
        MacroValue v;
        const char* code = codes::kNoSuchVariable;
        if (!variables.read(number, v, code)) return fail(code, {std::to_string(number)});
        stack.push_back(v);
        break;
      }
      case ExprOp::Negate: {  // -#1 of a vacant #1 stays vacant (an address is then omitted)
        const MacroValue a = pop();
        stack.push_back(a.vacant ? a : MacroValue::of(-a.value));
        break;
      }
      case ExprOp::Plus: {
        const MacroValue a = pop();
        push(a.value);
        break;
      }
      case ExprOp::Eq:
      case ExprOp::Ne: {
        const MacroValue b = pop(), a = pop();
        const bool e = equal(a, b);
        push((t.op == ExprOp::Eq) == e ? 1.0 : 0.0);
        break;
      }
      case ExprOp::Add:
      case ExprOp::Sub:
      case ExprOp::Mul:
      case ExprOp::Div:
      case ExprOp::Mod:
      case ExprOp::And:
      case ExprOp::Or:
      case ExprOp::Xor:
      case ExprOp::Gt:
      case ExprOp::Ge:
      case ExprOp::Lt:
      case ExprOp::Le:
      case ExprOp::Atan2:
      case ExprOp::Pow: {
        const double b = pop().value, a = pop().value;
        double v = 0.0;
        switch (t.op) {
          case ExprOp::Add: v = a + b; break;
          case ExprOp::Sub: v = a - b; break;
          case ExprOp::Mul: v = a * b; break;
          case ExprOp::Div:
            if (b == 0.0) return fail(codes::kDivisionByZero, {macroNumberText(a), "/"});
            v = a / b;
            break;
          case ExprOp::Mod:
            if (roundHalfAway(b) == 0.0) return fail(codes::kDivisionByZero, {macroNumberText(a), "MOD"});
            v = std::fmod(roundHalfAway(a), roundHalfAway(b));
            break;
          case ExprOp::And: v = static_cast<double>(bits(a) & bits(b)); break;
          case ExprOp::Or: v = static_cast<double>(bits(a) | bits(b)); break;
          case ExprOp::Xor: v = static_cast<double>(bits(a) ^ bits(b)); break;
          case ExprOp::Gt: v = a > b ? 1.0 : 0.0; break;
          case ExprOp::Ge: v = a >= b ? 1.0 : 0.0; break;
          case ExprOp::Lt: v = a < b ? 1.0 : 0.0; break;
          case ExprOp::Le: v = a <= b ? 1.0 : 0.0; break;
          case ExprOp::Atan2: {
            // ATAN[a]/[b] = the angle of the point (b, a): 0..360 (Fanuc's default range).
            if (a == 0.0 && b == 0.0) return fail(codes::kOutsideFunctionDomain, {"ATAN", "0, 0"});
            v = std::atan2(a, b) / kDeg;
            if (v < 0) v += 360.0;
            break;
          }
          case ExprOp::Pow:
            v = std::pow(a, b);
            if (!std::isfinite(v))
              return fail(codes::kOutsideFunctionDomain, {"POW", macroNumberText(a) + ", " + macroNumberText(b)});
            break;
          default: break;
        }
        push(v);
        break;
      }
      default: {  // one-argument functions
        const double a = pop().value;
        double v = 0.0;
        switch (t.op) {
          case ExprOp::Sin: v = std::sin(a * kDeg); break;
          case ExprOp::Cos: v = std::cos(a * kDeg); break;
          case ExprOp::Tan:
            if (std::abs(std::fmod(std::abs(a), 180.0) - 90.0) < 1e-12)
              return fail(codes::kOutsideFunctionDomain, {"TAN", macroNumberText(a)});
            v = std::tan(a * kDeg);
            break;
          case ExprOp::Asin:
            if (a < -1.0 || a > 1.0) return fail(codes::kOutsideFunctionDomain, {"ASIN", macroNumberText(a)});
            v = std::asin(a) / kDeg;
            break;
          case ExprOp::Acos:
            if (a < -1.0 || a > 1.0) return fail(codes::kOutsideFunctionDomain, {"ACOS", macroNumberText(a)});
            v = std::acos(a) / kDeg;
            break;
          case ExprOp::Atan: v = std::atan(a) / kDeg; break;
          case ExprOp::Sqrt:
            if (a < 0.0) return fail(codes::kOutsideFunctionDomain, {"SQRT", macroNumberText(a)});
            v = std::sqrt(a);
            break;
          case ExprOp::Abs: v = std::abs(a); break;
          case ExprOp::Round: v = roundHalfAway(a); break;
          case ExprOp::Fix: v = fix(a); break;
          case ExprOp::Fup: v = fup(a); break;
          case ExprOp::Ln:
            if (a <= 0.0) return fail(codes::kOutsideFunctionDomain, {"LN", macroNumberText(a)});
            v = std::log(a);
            break;
          case ExprOp::Exp:
            v = std::exp(a);
            if (!std::isfinite(v)) return fail(codes::kOutsideFunctionDomain, {"EXP", macroNumberText(a)});
            break;
          case ExprOp::Bin: v = fromBcd(a); break;
          case ExprOp::Bcd: v = toBcd(a); break;
          default: break;
        }
        push(v);
        break;
      }
    }
  }
  r.value = stack.empty() ? MacroValue{} : stack.back();
  if (!r.value.vacant && !std::isfinite(r.value.value)) return fail(codes::kOutsideFunctionDomain, {"=", "overflow"});
  return r;
}

}  // namespace klueng::core::gcode

// Reading macro B expressions into postfix code (macro.h). Recursive descent
// over the Fanuc precedence: functions and brackets, then * / AND MOD, then
// + - OR XOR, then the comparisons EQ NE GT GE LT LE.
#include <cctype>
#include <charconv>
#include <cstring>

#include "diagnostic_codes.h"
#include "klueng/core/gcode/display_tokens.h"
#include "klueng/core/gcode/macro.h"
#include "klueng/core/number_read.h"

namespace klueng::core::gcode {

namespace {

// Nested brackets deeper than this are refused (Fanuc allows 5; a hostile
// line must not exhaust the stack).
constexpr int kMaxDepth = 64;

struct Function {
  const char* name;
  ExprOp op;
};
constexpr Function kFunctions[] = {
    {"SIN", ExprOp::Sin},   {"COS", ExprOp::Cos},     {"TAN", ExprOp::Tan},   {"ASIN", ExprOp::Asin},
    {"ACOS", ExprOp::Acos}, {"ATAN", ExprOp::Atan},   {"SQRT", ExprOp::Sqrt}, {"SQR", ExprOp::Sqrt},
    {"ABS", ExprOp::Abs},   {"ROUND", ExprOp::Round}, {"RND", ExprOp::Round}, {"FIX", ExprOp::Fix},
    {"FUP", ExprOp::Fup},   {"LN", ExprOp::Ln},       {"EXP", ExprOp::Exp},   {"POW", ExprOp::Pow},
    {"BIN", ExprOp::Bin},   {"BCD", ExprOp::Bcd},
};

struct Operator {
  const char* name;
  ExprOp op;
  int level;  // 1 comparison, 2 additive, 3 multiplicative
};
constexpr Operator kWordOperators[] = {
    {"EQ", ExprOp::Eq, 1},   {"NE", ExprOp::Ne, 1},   {"GT", ExprOp::Gt, 1}, {"GE", ExprOp::Ge, 1},
    {"LT", ExprOp::Lt, 1},   {"LE", ExprOp::Le, 1},   {"OR", ExprOp::Or, 2}, {"XOR", ExprOp::Xor, 2},
    {"AND", ExprOp::And, 3}, {"MOD", ExprOp::Mod, 3},
};

// Statement keywords (the parser reads them, parser.cpp), for isMacroKeyword.
constexpr const char* kStatementWords[] = {"IF",  "THEN",  "GOTO",  "WHILE", "DO",
                                           "END", "POPEN", "PCLOS", "DPRNT", "BPRNT"};

class Reader {
 public:
  Reader(std::string_view text, int column, Expression& out) : s_(text), column_(column), out_(out) {}

  ExprReadResult read(ExprForm form) {
    out_.code.clear();
    bool ok = false;
    switch (form) {
      case ExprForm::Full: ok = comparison(0); break;
      case ExprForm::Address: ok = address(); break;
      case ExprForm::Variable: ok = variableNumber(0); break;
    }
    ExprReadResult r;
    if (!ok) {
      r.code = error_.code;
      r.args = std::move(error_.args);
      r.errorColumn = error_.at == std::string_view::npos ? column_ - 1 : column_ + static_cast<int>(error_.at);
      r.end = i_;
      return r;
    }
    // Trailing blanks are not part of the expression.
    while (end_ > 0 && end_ <= s_.size() && std::isspace(static_cast<unsigned char>(s_[end_ - 1]))) --end_;
    r.ok = true;
    r.end = end_;
    out_.range.column = column_;
    out_.range.length = static_cast<int>(end_);
    return r;
  }

 private:
  struct Error {
    const char* code = nullptr;
    std::vector<std::string> args;
    std::size_t at = 0;
  };

  std::string_view s_;
  int column_;
  Expression& out_;
  std::size_t i_ = 0;
  std::size_t end_ = 0;  // one past the last character consumed by a term
  // Where the last '#' is; npos: just before the text (the '#' of an assignment).
  std::size_t hash_ = std::string_view::npos;
  Error error_;

  void blanks() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t')) ++i_;
  }
  char peek() {
    blanks();
    return i_ < s_.size() ? s_[i_] : '\0';
  }
  bool fail(const char* code, std::vector<std::string> args, std::size_t at) {
    if (!error_.code) error_ = Error{code, std::move(args), at};
    return false;
  }
  void emit(ExprOp op, double v = 0.0) { out_.code.push_back(ExprToken{op, v}); }

  // The upper-case letter word at i_ (without consuming it).
  std::string letterWord() {
    std::string w;
    for (std::size_t k = i_; k < s_.size() && std::isalpha(static_cast<unsigned char>(s_[k])); ++k)
      w += static_cast<char>(std::toupper(static_cast<unsigned char>(s_[k])));
    return w;
  }

  bool comparison(int depth) {
    if (!additive(depth)) return false;
    if (std::isalpha(static_cast<unsigned char>(peek()))) {
      const std::string w = letterWord();
      for (const Operator& o : kWordOperators)
        if (o.level == 1 && w == o.name) {
          i_ += w.size();
          if (!additive(depth)) return false;
          emit(o.op);
          return true;
        }
    }
    return true;
  }

  bool additive(int depth) { return binary(depth, 2); }

  // One level of left-associative binary operators: 2 = + - OR XOR, 3 = * / AND MOD.
  bool binary(int depth, int level) {
    const auto operand = [&] { return level == 3 ? unary(depth) : binary(depth, 3); };
    if (!operand()) return false;
    for (;;) {
      const char c = peek();
      ExprOp op = ExprOp::Add;
      std::size_t len = 1;
      bool found = true;
      if (level == 2 && (c == '+' || c == '-')) {
        op = c == '+' ? ExprOp::Add : ExprOp::Sub;
      } else if (level == 3 && (c == '*' || c == '/')) {
        op = c == '*' ? ExprOp::Mul : ExprOp::Div;
      } else if (std::isalpha(static_cast<unsigned char>(c))) {
        const std::string w = letterWord();
        found = false;
        for (const Operator& o : kWordOperators)
          if (o.level == level && w == o.name) {
            op = o.op;
            len = w.size();
            found = true;
          }
      } else {
        found = false;
      }
      if (!found) return true;
      i_ += len;
      if (!operand()) return false;
      emit(op);
    }
  }

  bool unary(int depth) {
    const char c = peek();
    if (c == '-' || c == '+') {
      ++i_;
      if (!unary(depth)) return false;
      if (c == '-') emit(ExprOp::Negate);
      return true;
    }
    return primary(depth);
  }

  bool bracketed(int depth) {
    // At '['.
    if (depth >= kMaxDepth) return fail(codes::kMacroTooDeep, {std::to_string(kMaxDepth)}, i_);
    const std::size_t open = i_;
    ++i_;
    if (!comparison(depth + 1)) return false;
    if (peek() != ']') {
      if (std::isalpha(static_cast<unsigned char>(peek()))) return fail(codes::kMacroUnknownWord, {letterWord()}, i_);
      return fail(codes::kMacroUnclosedBracket, {}, open);
    }
    ++i_;
    end_ = i_;
    return true;
  }

  bool number() {
    const std::size_t start = i_;
    bool digits = false;
    while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) {
      ++i_;
      digits = true;
    }
    if (i_ < s_.size() && s_[i_] == '.') {
      ++i_;
      while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) {
        ++i_;
        digits = true;
      }
    }
    if (!digits) return fail(codes::kMacroExpectedValue, {std::string(s_.substr(start, 1))}, start);
    // 1e300, 2.5E-3: no control reads an exponent (the E would be read as a word of its own).
    if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      std::size_t k = i_ + 1;
      if (k < s_.size() && (s_[k] == '+' || s_[k] == '-')) ++k;
      if (k < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k]))) {
        while (k < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k]))) ++k;
        return fail(codes::kExponentInMacro, {std::string(s_.substr(start, k - start))}, start);
      }
    }
    double v = 0.0;
    const auto r = readDouble(s_.data() + start, s_.data() + i_, v);
    if (r.ec != std::errc()) v = 1e308;
    emit(ExprOp::Constant, v);
    end_ = i_;
    return true;
  }

  // At '#': a variable whose number follows.
  bool variable(int depth) {
    hash_ = i_;
    ++i_;
    if (!variableNumber(depth + 1)) return false;
    emit(ExprOp::Variable);
    return true;
  }

  // After '#': the variable number (a constant, a bracket or another #).
  bool variableNumber(int depth) {
    if (depth >= kMaxDepth) return fail(codes::kMacroTooDeep, {std::to_string(kMaxDepth)}, i_);
    const char c = peek();
    if (c == '[') return bracketed(depth);
    if (c == '#') return variable(depth);
    if (std::isdigit(static_cast<unsigned char>(c))) {
      const std::size_t start = i_;
      while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
      if (i_ < s_.size() && s_[i_] == '.')
        return fail(codes::kMacroBadVariable, {std::string(s_.substr(start, i_ + 1 - start))}, start);
      double v = 0.0;
      readDouble(s_.data() + start, s_.data() + i_, v);
      emit(ExprOp::Constant, v);
      end_ = i_;
      return true;
    }
    return fail(codes::kMacroBadVariable, {"#"}, hash_);
  }

  bool primary(int depth) {
    if (depth >= kMaxDepth) return fail(codes::kMacroTooDeep, {std::to_string(kMaxDepth)}, i_);
    const char c = peek();
    if (c == '[') return bracketed(depth);
    if (c == '#') return variable(depth);
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c))) {
      const std::size_t start = i_;
      const std::string w = letterWord();
      for (const Function& f : kFunctions) {
        if (w != f.name) continue;
        i_ += w.size();
        if (peek() != '[') return fail(codes::kMacroExpectedBracket, {w}, start);
        const std::size_t open = i_;
        ++i_;
        if (!comparison(depth + 1)) return false;
        const bool twoArgs = f.op == ExprOp::Pow || f.op == ExprOp::Atan;
        if (twoArgs && peek() == ',') {  // ATAN[a,b], POW[a,b]
          ++i_;
          if (!comparison(depth + 1)) return false;
          if (peek() != ']') return fail(codes::kMacroUnclosedBracket, {}, open);
          ++i_;
          end_ = i_;
          emit(f.op == ExprOp::Atan ? ExprOp::Atan2 : ExprOp::Pow);
          return true;
        }
        if (peek() != ']') return fail(codes::kMacroUnclosedBracket, {}, open);
        ++i_;
        end_ = i_;
        if (f.op == ExprOp::Pow) return fail(codes::kMacroExpectedValue, {"POW[a,b]"}, start);
        if (f.op == ExprOp::Atan) {
          // ATAN[a]/[b]: the two-argument form of the 0i (angle 0..360).
          const std::size_t save = i_;
          if (peek() == '/') {
            ++i_;
            if (peek() == '[') {
              if (!bracketed(depth + 1)) return false;
              emit(ExprOp::Atan2);
              return true;
            }
          }
          i_ = save;
        }
        emit(f.op);
        return true;
      }
      return fail(codes::kMacroUnknownWord, {w.empty() ? std::string(1, c) : w}, start);
    }
    if (c == '\0') return fail(codes::kMacroExpectedValue, {"end of line"}, i_);
    return fail(codes::kMacroExpectedValue, {std::string(1, c)}, i_);
  }

  bool address() {
    const char c = peek();
    bool negate = false;
    if (c == '-' || c == '+') {
      negate = c == '-';
      ++i_;
    }
    const char d = peek();
    if (d != '#' && d != '[') return fail(codes::kMacroExpectedValue, {std::string(1, d ? d : ' ')}, i_);
    if (!primary(0)) return false;
    if (negate) emit(ExprOp::Negate);
    return true;
  }
};

}  // namespace

bool isMacroKeyword(std::string_view upperWord) {
  for (const char* w : kStatementWords)
    if (upperWord == w) return true;
  for (const Function& f : kFunctions)
    if (upperWord == f.name) return true;
  for (const Operator& o : kWordOperators)
    if (upperWord == o.name) return true;
  return false;
}

ExprReadResult readExpression(std::string_view text, int column, ExprForm form, Expression& out) {
  return Reader(text, column, out).read(form);
}

}  // namespace klueng::core::gcode

// Custom macro B expressions (Fanuc 0i-TF manual, "Arithmetic and logic
// operation"): precedence, functions in degrees, the vacant (#0) rules, errors.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "klueng/core/gcode/macro.h"
#include "klueng/core/gcode/parser.h"

namespace klueng::core::gcode {
namespace {

class Vars final : public MacroVariables {
 public:
  std::map<int, double> set;
  bool read(int n, MacroValue& out, const char*& code) override {
    code = "A137";
    if (n < 0 || n > 999) return false;
    const auto it = set.find(n);
    out = it == set.end() ? MacroValue{} : MacroValue::of(it->second);
    return true;
  }
};

EvalResult eval(const std::string& text, Vars vars = {}) {
  Expression e;
  const ExprReadResult r = readExpression(text, 1, ExprForm::Full, e);
  EXPECT_TRUE(r.ok) << text << ": " << (r.code ? r.code : "");
  EXPECT_EQ(r.end, text.size()) << text;
  return evaluate(e, vars);
}

double value(const std::string& text, Vars vars = {}) {
  const EvalResult r = eval(text, std::move(vars));
  EXPECT_TRUE(r.ok) << text;
  EXPECT_FALSE(r.value.vacant) << text;
  return r.value.value;
}

TEST(MacroExpression, PrecedenceAndBrackets) {
  EXPECT_DOUBLE_EQ(value("1+2*3"), 7.0);
  EXPECT_DOUBLE_EQ(value("[1+2]*3"), 9.0);
  EXPECT_DOUBLE_EQ(value("10-4-3"), 3.0);  // left to right
  EXPECT_DOUBLE_EQ(value("12/4/3"), 1.0);
  EXPECT_DOUBLE_EQ(value("-2*-3"), 6.0);
  EXPECT_DOUBLE_EQ(value("2+3 GT 4"), 1.0);     // comparisons bind last
  EXPECT_DOUBLE_EQ(value("7 MOD 3 + 1"), 2.0);  // MOD with * and /
  EXPECT_DOUBLE_EQ(value("[[1+1]*[2+2]]"), 8.0);
  EXPECT_DOUBLE_EQ(value("5 AND 3"), 1.0);
  EXPECT_DOUBLE_EQ(value("5 OR 3"), 7.0);
  EXPECT_DOUBLE_EQ(value("5 XOR 3"), 6.0);
}

TEST(MacroExpression, FunctionsInDegrees) {
  EXPECT_NEAR(value("SIN[30]"), 0.5, 1e-12);
  EXPECT_NEAR(value("COS[60.]"), 0.5, 1e-12);
  EXPECT_NEAR(value("TAN[45]"), 1.0, 1e-12);
  EXPECT_NEAR(value("ASIN[0.5]"), 30.0, 1e-9);
  EXPECT_NEAR(value("ACOS[0]"), 90.0, 1e-9);
  EXPECT_NEAR(value("ATAN[1]"), 45.0, 1e-9);
  EXPECT_NEAR(value("ATAN[-1]/[-1]"), 225.0, 1e-9);  // two arguments: 0..360
  EXPECT_NEAR(value("ATAN[1,-1]"), 135.0, 1e-9);
  EXPECT_DOUBLE_EQ(value("SQRT[16]"), 4.0);
  EXPECT_DOUBLE_EQ(value("ABS[-2.5]"), 2.5);
  EXPECT_DOUBLE_EQ(value("ROUND[2.5]"), 3.0);
  EXPECT_DOUBLE_EQ(value("ROUND[-2.5]"), -3.0);
  EXPECT_DOUBLE_EQ(value("FIX[1.7]"), 1.0);
  EXPECT_DOUBLE_EQ(value("FIX[-1.7]"), -1.0);
  EXPECT_DOUBLE_EQ(value("FUP[1.2]"), 2.0);
  EXPECT_DOUBLE_EQ(value("FUP[-1.2]"), -2.0);
  EXPECT_NEAR(value("LN[EXP[2]]"), 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(value("POW[2,10]"), 1024.0);
  EXPECT_DOUBLE_EQ(value("BCD[123]"), 0x123);
  EXPECT_DOUBLE_EQ(value("BIN[291]"), 123.0);  // 291 = 0x123
  EXPECT_DOUBLE_EQ(value("sin[90]"), 1.0);     // lower case reads too
}

TEST(MacroExpression, VariablesAndTheVacantRules) {
  Vars v;
  v.set[1] = 2.0;
  v.set[101] = 7.0;
  EXPECT_DOUBLE_EQ(value("#1*#101", v), 14.0);
  EXPECT_DOUBLE_EQ(value("#[#1+99]", v), 7.0);  // #101 through a computed number
  v.set[2] = 5.0;
  EXPECT_DOUBLE_EQ(value("##1", v), 5.0);  // #[#1] = #2
  v.set.erase(2);
  // #2 = #3 keeps a vacant value vacant; #3*5 is 0.
  EXPECT_TRUE(eval("#3", v).value.vacant);
  EXPECT_DOUBLE_EQ(value("#3*5", v), 0.0);
  EXPECT_DOUBLE_EQ(value("#3+#3", v), 0.0);
  // EQ/NE tell vacant from 0; the other comparisons read vacant as 0.
  EXPECT_DOUBLE_EQ(value("#3 EQ #0", v), 1.0);
  EXPECT_DOUBLE_EQ(value("#3 EQ 0", v), 0.0);
  EXPECT_DOUBLE_EQ(value("#3 NE 0", v), 1.0);
  EXPECT_DOUBLE_EQ(value("#3 GE 0", v), 1.0);
  EXPECT_DOUBLE_EQ(value("#1 EQ #0", v), 0.0);
}

TEST(MacroExpression, ErrorsAreRunTimeAlarms) {
  EvalResult r = eval("1/[2-2]");
  EXPECT_FALSE(r.ok);
  EXPECT_STREQ(r.code, "A131");
  r = eval("SQRT[-4]");
  EXPECT_STREQ(r.code, "A138");
  r = eval("ASIN[2]");
  EXPECT_STREQ(r.code, "A138");
  r = eval("LN[0]");
  EXPECT_STREQ(r.code, "A138");
  r = eval("5 MOD 0");
  EXPECT_STREQ(r.code, "A131");
  r = eval("#1000");
  EXPECT_STREQ(r.code, "A137");
}

TEST(MacroExpression, SyntaxErrorsSayWhereAndWhat) {
  struct Case {
    const char* text;
    const char* code;
    int column;
  };
  for (const Case& c : {Case{"[1+2", "E121", 1}, Case{"1+", "E122", 3}, Case{"[1 PLUS 2]", "E123", 4},
                        Case{"SIN 30", "E124", 1}, Case{"#A", "E125", 1}, Case{"#1.5", "E125", 2}}) {
    Expression e;
    const ExprReadResult r = readExpression(c.text, 1, ExprForm::Full, e);
    EXPECT_FALSE(r.ok) << c.text;
    if (!r.ok) {
      EXPECT_STREQ(r.code, c.code) << c.text;
      EXPECT_EQ(r.errorColumn, c.column) << c.text;
    }
  }
}

TEST(MacroStatements, ParseIntoStatementsWithTheirColumns) {
  const Program p = parse(
      "N10 #101 = [#1+2.] * 3\n"
      "IF [#101 GT 30.] GOTO 90\n"
      "IF [#1 EQ #0] THEN #1 = 2.\n"
      "WHILE [#101 GT 30.] DO2\n"
      "END2\n"
      "GOTO #5\n"
      "G01 X#101 Z-[#1+2.] F[#9*0.5]\n"
      "DPRNT[X#5001[44]]\n");
  ASSERT_TRUE(p.lexicalDiagnostics.empty()) << p.lexicalDiagnostics.front().code;
  ASSERT_EQ(p.blocks.size(), 8u);
  EXPECT_EQ(p.blocks[0].statement().kind, StatementKind::Assign);
  EXPECT_EQ(p.blocks[0].words.size(), 1u);  // N10
  EXPECT_EQ(p.blocks[0].statement().range.column, 5);
  EXPECT_EQ(p.blocks[1].statement().kind, StatementKind::If);
  EXPECT_FALSE(p.blocks[1].statement().then);
  EXPECT_TRUE(p.blocks[2].statement().then);
  EXPECT_EQ(p.blocks[3].statement().kind, StatementKind::While);
  EXPECT_EQ(p.blocks[3].statement().loop, 2);
  EXPECT_EQ(p.blocks[4].statement().kind, StatementKind::End);
  EXPECT_EQ(p.blocks[5].statement().kind, StatementKind::Goto);
  const Block& nc = p.blocks[6];
  EXPECT_EQ(nc.statement().kind, StatementKind::None);
  EXPECT_TRUE(nc.hasExpressions);
  ASSERT_EQ(nc.words.size(), 4u);
  EXPECT_EQ(nc.words[1].text(), "X#101");
  EXPECT_EQ(nc.words[2].text(), "Z-[#1+2.]");
  EXPECT_EQ(nc.words[2].range.column, 11);
  EXPECT_EQ(nc.words[2].range.length, 9);
  EXPECT_EQ(nc.words[3].text(), "F[#9*0.5]");
  EXPECT_EQ(p.blocks[7].statement().kind, StatementKind::Output);
}

TEST(MacroStatements, BlanksMayStandBetweenAnAddressAndItsExpression) {
  const Program p = parse("G01 X [#1 + 2.] Z -#2\n");
  ASSERT_TRUE(p.lexicalDiagnostics.empty()) << p.lexicalDiagnostics.front().code;
  ASSERT_EQ(p.blocks[0].words.size(), 3u);
  EXPECT_EQ(p.blocks[0].words[1].text(), "X[#1 + 2.]");
  EXPECT_EQ(p.blocks[0].words[1].range, (SourceRange{1, 5, 11}));
  EXPECT_EQ(p.blocks[0].words[2].text(), "Z-#2");
}

}  // namespace
}  // namespace klueng::core::gcode

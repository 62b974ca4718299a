// A big program is parsed as two halves on two threads (parse_split.cpp): the
// result must be what one pass over the lines gives — line numbers across
// every kind of line end, macro expressions found through their indices, and
// the E109 cut-off after 2,000 lexical errors.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "klueng/core/gcode/parser.h"

namespace klueng::core::gcode {
namespace {

struct Line {
  std::string text;
  const char* end;
};

// 24,000 lines (~470 KB): moves, macro statements and words with expressions,
// a lone letter (E101) on every sixth line after the first 6,000, and LF, CRLF, CR and CR CR LF ends.
std::vector<Line> bigProgram() {
  static const char* const kEnds[] = {"\n", "\r\n", "\r", "\r\r\n"};
  std::vector<Line> lines;
  for (int i = 0; i < 24000; ++i) {
    std::string t;
    switch (i % 6) {
      case 0: t = "N" + std::to_string(i) + " G01 X" + std::to_string(20 + i % 30) + ". Z-" + std::to_string(i % 90) + ". F0.2"; break;
      case 1: t = "#" + std::to_string(100 + i % 50) + "=[#1+" + std::to_string(i % 7) + "]*2 (step)"; break;
      case 2: t = "G00 X#" + std::to_string(100 + i % 50) + " Z[#2-" + std::to_string(i % 5) + "]"; break;
      case 3: t = "IF [#1 GT " + std::to_string(i % 9) + "] GOTO " + std::to_string(i); break;
      case 4: t = i >= 6000 ? "G01 Z-2. X F0.1" : "G01 Z-2. X30. F0.1"; break;  // E101 at column 10
      case 5: t = "(only a comment " + std::to_string(i) + ")"; break;
    }
    lines.push_back({t, kEnds[(i / 6) % 4]});
  }
  return lines;
}

TEST(ParseSplit, ABigProgramReadsExactlyAsLineByLine) {
  const std::vector<Line> lines = bigProgram();
  std::string text;
  for (const Line& l : lines) text += l.text + l.end;
  ASSERT_GT(text.size(), 400000u);
  const int firstLine = 7;
  const Program whole = parse(text, firstLine);
  EXPECT_EQ(whole.lineCount, static_cast<int>(lines.size()));

  std::size_t b = 0;
  int errors = 0, errorLineOf2000th = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int lineNo = firstLine + static_cast<int>(i);
    const Program one = parse(lines[i].text, lineNo);
    for (const Diagnostic& d : one.lexicalDiagnostics) {
      ASSERT_EQ(d.code, "E101");
      if (++errors == 2000) errorLineOf2000th = lineNo;
    }
    for (const Block& expected : one.blocks) {
      ASSERT_LT(b, whole.blocks.size());
      const Block& got = whole.blocks[b++];
      ASSERT_EQ(got.line, lineNo);
      ASSERT_EQ(got.comment, expected.comment);
      ASSERT_EQ(got.statement.kind, expected.statement.kind) << lineNo;
      ASSERT_EQ(got.words.size(), expected.words.size()) << lineNo;
      // An expression index from either half leads to the same postfix code.
      const auto sameExpression = [&](int gotIndex, int expectedIndex) {
        ASSERT_EQ(gotIndex < 0, expectedIndex < 0) << lineNo;
        if (expectedIndex < 0) return;
        const auto& g = whole.expressions.at(static_cast<std::size_t>(gotIndex));
        const auto& e = one.expressions.at(static_cast<std::size_t>(expectedIndex));
        ASSERT_EQ(g.range, e.range) << lineNo;
        ASSERT_EQ(g.code.size(), e.code.size()) << lineNo;
        for (std::size_t k = 0; k < e.code.size(); ++k) {
          ASSERT_EQ(g.code[k].op, e.code[k].op) << lineNo;
          ASSERT_EQ(g.code[k].value, e.code[k].value) << lineNo;
        }
      };
      for (std::size_t w = 0; w < expected.words.size(); ++w) {
        ASSERT_EQ(got.words[w].letter, expected.words[w].letter) << lineNo;
        ASSERT_EQ(got.words[w].number, expected.words[w].number) << lineNo;
        ASSERT_EQ(got.words[w].value, expected.words[w].value) << lineNo;
        ASSERT_EQ(got.words[w].range, expected.words[w].range) << lineNo;
        sameExpression(got.words[w].expr, expected.words[w].expr);
      }
      sameExpression(got.statement.condition, expected.statement.condition);
      sameExpression(got.statement.target, expected.statement.target);
      sameExpression(got.statement.value, expected.statement.value);
    }
  }
  EXPECT_EQ(b, whole.blocks.size());
  // 3,000 lone letters: 1,999 reported, then E109 where the 2,000th is.
  ASSERT_EQ(errors, 3000);
  ASSERT_EQ(whole.lexicalDiagnostics.size(), 2000u);
  EXPECT_EQ(whole.lexicalDiagnostics[1998].code, "E101");
  EXPECT_EQ(whole.lexicalDiagnostics.back().code, "E109");
  EXPECT_EQ(whole.lexicalDiagnostics.back().range.line, errorLineOf2000th);
  EXPECT_EQ(whole.lexicalDiagnostics.back().range.column, 10);
  // The 2,000th error lies in the second half: the seam's cut-off is the one tested.
  EXPECT_GT(errorLineOf2000th, firstLine + static_cast<int>(lines.size()) / 2);
}

}  // namespace
}  // namespace klueng::core::gcode

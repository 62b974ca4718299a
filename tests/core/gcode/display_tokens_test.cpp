// The editor's colouring tokens come from the core (issue 12).
#include <gtest/gtest.h>

#include "klueng/core/gcode/display_tokens.h"

namespace klueng::core::gcode {
namespace {

std::string describe(std::u16string_view line) {
  std::string out;
  for (const DisplayToken& t : displayTokens(line)) {
    static const char* const names[] = {"comment", "skip", "var", "macro", "addr"};
    out += names[static_cast<int>(t.kind)];
    out += '@' + std::to_string(t.start) + '+' + std::to_string(t.length);
    if (t.kind == DisplayTokenKind::Address) out += std::string(":") + t.letter;
    out += ' ';
  }
  return out;
}

TEST(DisplayTokens, WordsCommentsAndSkip) {
  EXPECT_EQ(describe(u"/N10 g01 X-2.5 (กลึงปาด) F.2"),
            "skip@0+1 addr@1+3:N addr@5+3:G addr@9+5:X comment@15+9 addr@25+3:F ");
  EXPECT_EQ(describe(u"G00 X50. ; rapid in"), "addr@0+3:G addr@4+4:X comment@9+10 ");
  EXPECT_EQ(describe(u"%"), "skip@0+1 ");
}

TEST(DisplayTokens, MacroWordsAndVariables) {
  EXPECT_EQ(describe(u"IF [#1 GT 10] GOTO 20"), "macro@0+2 var@4+2 macro@7+2 macro@14+4 ");
  EXPECT_EQ(describe(u"#100=SQRT[#1]"), "var@0+4 macro@5+4 var@10+2 ");
  // Letters that are no macro word are not coloured as one; the last one starts a word.
  EXPECT_EQ(describe(u"XY10"), "addr@1+3:Y ");
}

TEST(DisplayTokens, AnUnclosedCommentRunsToTheEnd) { EXPECT_EQ(describe(u"G01 (no close"), "addr@0+3:G comment@4+9 "); }

TEST(DisplayTokens, ACommentEndsWhereItsParenthesesBalanceAsTheParserReadsIt) {
  // "(n = Vc*1000/(pi*D))" is one comment (issue 26); the F word after it is a word.
  EXPECT_EQ(describe(u"G97 (n = Vc*1000/(pi*D)) F.2"), "addr@0+3:G comment@4+20 addr@25+3:F ");
}

TEST(DisplayTokens, MacroKeywordsAreTheReadersOwn) {
  for (const char* w : {"IF", "THEN", "WHILE", "DO", "END", "GOTO", "EQ", "MOD", "XOR", "SIN", "ATAN", "ROUND", "FUP",
                        "BCD", "POPEN", "DPRNT"})
    EXPECT_TRUE(isMacroKeyword(w)) << w;
  for (const char* w : {"G", "XY", "FOO", "if"}) EXPECT_FALSE(isMacroKeyword(w)) << w;
}

}  // namespace
}  // namespace klueng::core::gcode

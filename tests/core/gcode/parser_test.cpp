// Lexer/parser tests (SPEC 3): words, columns, comments, line ends, errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"

namespace klueng::core::gcode {
namespace {

using ::testing::ElementsAre;

struct WordView {
  char letter;
  std::string number;
  int column;
  int length;
  friend bool operator==(const WordView&, const WordView&) = default;
  friend std::ostream& operator<<(std::ostream& os, const WordView& w) {
    return os << w.letter << w.number << "@" << w.column << "+" << w.length;
  }
};

std::vector<WordView> wordsOf(const Block& b) {
  std::vector<WordView> out;
  for (const Word& w : b.words) out.push_back({w.letter, w.number.str(), w.range.column, w.range.length});
  return out;
}

// ---- words, spacing, case -------------------------------------------------

TEST(Parser, WordsWrittenTogether) {
  const Program p = parse("G01X20.Z-5.");
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_TRUE(p.lexicalDiagnostics.empty());
  EXPECT_THAT(wordsOf(p.blocks[0]),
              ElementsAre(WordView{'G', "01", 1, 3}, WordView{'X', "20.", 4, 4}, WordView{'Z', "-5.", 8, 4}));
  EXPECT_EQ(p.blocks[0].words[0].code(), 1);
  EXPECT_DOUBLE_EQ(p.blocks[0].words[1].value, 20.0);
  EXPECT_TRUE(p.blocks[0].words[1].hasDecimalPoint);
  EXPECT_EQ(p.blocks[0].words[1].decimals, 0);
  EXPECT_DOUBLE_EQ(p.blocks[0].words[2].value, -5.0);
}

// The plain words the lexer reads in one pass (letter, sign, digits, one point) and the words next
// to them that it leaves to the long way: every field as the long way makes it.
TEST(Parser, PlainWordsAndTheirNeighboursKeepEveryField) {
  const Program p = parse("n10g1x-.5Z+12.3450 F0.25\tS0800 X20 30 G0O1 Z2,5 X1.2.3 X-#1 T0101\n");
  ASSERT_EQ(p.blocks.size(), 1u);
  const WordList& w = p.blocks[0].words;
  ASSERT_EQ(w.size(), 9u);
  struct Want {
    char letter;
    const char* number;
    double value;
    bool point;
    int decimals;
    int column;
    int length;
  };
  const Want want[] = {{'N', "10", 10.0, false, 0, 1, 3},      {'G', "1", 1.0, false, 0, 4, 2},
                       {'X', "-.5", -0.5, true, 1, 6, 4},      {'Z', "+12.3450", 12.345, true, 4, 10, 9},
                       {'F', "0.25", 0.25, true, 2, 20, 5},    {'S', "0800", 800.0, false, 0, 26, 5},
                       {'X', "2030", 2030.0, false, 0, 32, 6}, {'X', "-#1", 0.0, true, 0, 56, 4},
                       {'T', "0101", 101.0, false, 0, 61, 5}};
  for (std::size_t i = 0; i < w.size(); ++i) {
    const Want& x = want[i];
    SCOPED_TRACE(w[i].text());
    EXPECT_EQ(w[i].letter, x.letter);
    EXPECT_EQ(w[i].number, x.number);
    EXPECT_DOUBLE_EQ(w[i].value, x.value);
    EXPECT_EQ(w[i].hasDecimalPoint, x.point);
    EXPECT_EQ(w[i].decimals, x.decimals);
    EXPECT_EQ(w[i].range.line, 1);
    EXPECT_EQ(w[i].range.column, x.column);
    EXPECT_EQ(w[i].range.length, x.length);
    EXPECT_EQ(w[i].blanks, i == 6);  // "X20 30": X2030, the blanks noted
    EXPECT_EQ(w[i].expr >= 0, i == 7);
    EXPECT_FALSE(w[i].colon);
    EXPECT_FALSE(w[i].comma);
  }
  // The blanks inside X20 30 (a warning); G0O1, Z2,5 and X1.2.3 are errors, not words.
  std::vector<std::string> codes;
  for (const Diagnostic& d : p.lexicalDiagnostics) codes.push_back(d.code + ":" + std::to_string(d.range.column));
  EXPECT_THAT(codes, ::testing::ElementsAre(::testing::EndsWith(":32"), ::testing::EndsWith(":39"),
                                            ::testing::EndsWith(":44"), ::testing::EndsWith(":49")));
}

TEST(Parser, WordsWithSpacesAndTabs) {
  const Program p = parse("G01  X20.\tZ-5.");
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_THAT(wordsOf(p.blocks[0]),
              ElementsAre(WordView{'G', "01", 1, 3}, WordView{'X', "20.", 6, 4}, WordView{'Z', "-5.", 11, 4}));
}

TEST(Parser, LowerCaseLettersAndShortNumbers) {
  const Program p = parse("g1 x.5 z-.5 m3 f+0.25");
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_TRUE(p.lexicalDiagnostics.empty());
  const auto& w = p.blocks[0].words;
  ASSERT_EQ(w.size(), 5u);
  EXPECT_EQ(w[0].letter, 'G');
  EXPECT_EQ(w[0].code(), 1);
  EXPECT_EQ(w[1].letter, 'X');
  EXPECT_DOUBLE_EQ(w[1].value, 0.5);
  EXPECT_EQ(w[1].decimals, 1);
  EXPECT_DOUBLE_EQ(w[2].value, -0.5);
  EXPECT_EQ(w[3].letter, 'M');
  EXPECT_EQ(w[3].code(), 3);
  EXPECT_DOUBLE_EQ(w[4].value, 0.25);
  EXPECT_EQ(w[4].decimals, 2);
}

TEST(Parser, ValuesMatchTheCompilersDoubles) {
  const Program p = parse("X25.4 Z-0.1 U9999.999 W1234567890123456789.5 K0.30000000000000004");
  ASSERT_EQ(p.blocks.size(), 1u);
  const auto& w = p.blocks[0].words;
  EXPECT_EQ(w[0].value, 25.4);
  EXPECT_EQ(w[1].value, -0.1);
  EXPECT_EQ(w[2].value, 9999.999);
  EXPECT_EQ(w[3].value, 1234567890123456789.5);
  EXPECT_EQ(w[4].value, 0.30000000000000004);
  EXPECT_EQ(w[4].decimals, 17);
}

// ---- comments, block skip, tape marks, blank lines ----------------------------

TEST(Parser, CommentsAreKeptAndSkipped) {
  const Program p = parse("N10 (face) G00 ; rapid in\n(only a comment)\n; another\n");
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_TRUE(p.lexicalDiagnostics.empty());
  EXPECT_THAT(wordsOf(p.blocks[0]), ElementsAre(WordView{'N', "10", 1, 3}, WordView{'G', "00", 12, 3}));
  EXPECT_EQ(p.blocks[0].comment(), "face rapid in");
  EXPECT_EQ(p.lineCount, 3);
}

TEST(Parser, ThaiCommentBeforeAWordGivesCodePointColumn) {
  // "กลึงปาดหน้า" is 11 code points (33 bytes in UTF-8).
  const Program p = parse("(กลึงปาดหน้า) X20.");
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_THAT(wordsOf(p.blocks[0]), ElementsAre(WordView{'X', "20.", 15, 4}));
  EXPECT_EQ(p.blocks[0].comment(), "กลึงปาดหน้า");
}

TEST(Parser, ThaiCommentBeforeAnErrorGivesCodePointColumn) {
  const Program p = parse("G01 (ปอก) X");
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(p.lexicalDiagnostics[0].code, "E101");
  EXPECT_EQ(p.lexicalDiagnostics[0].range, (SourceRange{1, 11, 1}));
}

TEST(Parser, LineEndsLfCrlfCr) {
  for (const char* text :
       {"G00\nG01\n\nG02 X1. Z1. R1.\n", "G00\r\nG01\r\n\r\nG02 X1. Z1. R1.\r\n", "G00\rG01\r\rG02 X1. Z1. R1.\r"}) {
    const Program p = parse(text, 7);
    ASSERT_EQ(p.blocks.size(), 3u) << text;
    EXPECT_EQ(p.blocks[0].line, 7);
    EXPECT_EQ(p.blocks[1].line, 8);
    EXPECT_EQ(p.blocks[2].line, 10);
    EXPECT_EQ(p.lineCount, 4);
    EXPECT_EQ(p.firstLine, 7);
    EXPECT_TRUE(p.lexicalDiagnostics.empty());
  }
}

TEST(Parser, MixedLineEndsAndNoFinalNewline) {
  const Program p = parse("G00\r\n\nG01\rG02 X1. Z1. R1.");
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_EQ(p.blocks[0].line, 1);
  EXPECT_EQ(p.blocks[1].line, 3);
  EXPECT_EQ(p.blocks[2].line, 4);
  EXPECT_EQ(p.lineCount, 4);
}

TEST(Parser, BlockSkipAtTheStartOfABlock) {
  const Program p = parse("/N10 G00 X50.\n  / G01 Z-5.\nG00 X1.");
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_TRUE(p.blocks[0].blockSkip);
  EXPECT_EQ(p.blocks[0].words[0].range.column, 2);
  EXPECT_TRUE(p.blocks[1].blockSkip);
  EXPECT_FALSE(p.blocks[2].blockSkip);
  EXPECT_TRUE(p.lexicalDiagnostics.empty());
}

TEST(Parser, BlockSkipInsideABlockIsAnError) {
  const Program p = parse("G00 /X50.");
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(p.lexicalDiagnostics[0].code, "E106");
  EXPECT_EQ(p.lexicalDiagnostics[0].range, (SourceRange{1, 5, 1}));
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_EQ(p.blocks[0].words.size(), 2u);
  EXPECT_FALSE(p.blocks[0].blockSkip);
}

TEST(Parser, TapeMarksAndBlankLinesAreDropped) {
  const Program p = parse("%\n\n   \nO0001\nG00 X1.\n% (end of tape)\n");
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.blocks[0].line, 4);
  EXPECT_EQ(p.blocks[1].line, 5);
  EXPECT_TRUE(p.lexicalDiagnostics.empty());
  EXPECT_EQ(p.lineCount, 6);
}

TEST(Parser, WordsAfterATapeMarkAreReported) {
  const Program p = parse("% G00");
  EXPECT_TRUE(p.blocks.empty());
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(p.lexicalDiagnostics[0].code, "E108");
  EXPECT_EQ(p.lexicalDiagnostics[0].range, (SourceRange{1, 3, 3}));
}

// A control skips what follows the first '%' to the line end (B-63524EN §8): a title there is one
// E108 (a warning on Fanuc and Haas), never read as a line of text (E138) or as words.
TEST(Parser, TextAfterATapeMarkIsOneDiagnosticForTheWholeRest) {
  const Program p = parse("%PART 7 OD  \nG21\n");
  ASSERT_EQ(p.blocks.size(), 1u);
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(p.lexicalDiagnostics[0].code, "E108");
  EXPECT_EQ(p.lexicalDiagnostics[0].range, (SourceRange{1, 2, 9}));
  ASSERT_FALSE(p.lexicalDiagnostics[0].args.empty());
  EXPECT_EQ(p.lexicalDiagnostics[0].args[0], "PART 7 OD");
  EXPECT_TRUE(parse("% (TAPE START)\n").lexicalDiagnostics.empty());
}

// The closing '%' ends the tape: what follows (a note, a DOS end-of-file byte) is counted, not read.
TEST(Parser, LinesAfterTheClosingTapeMarkAreNotRead) {
  const Program p = parse("%\nO1000\nG00 X10.\nM30\n%\nEND OF TAPE  made by DNC\n\x1a");
  ASSERT_EQ(p.blocks.size(), 3u);
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(p.lexicalDiagnostics[0].code, "I163");
  EXPECT_EQ(p.lexicalDiagnostics[0].range.line, 6);
  EXPECT_EQ(p.lexicalDiagnostics[0].args, (std::vector<std::string>{"6", "7"}));
  EXPECT_EQ(p.lineCount, 7);
  // Another tape after it is read: several programs, each between its own '%' lines.
  const Program two = parse("%\nO1\nG00 X1.\n%\n%\nO2\nG00 X2.\n%\n");
  EXPECT_EQ(two.blocks.size(), 4u);
  EXPECT_TRUE(two.lexicalDiagnostics.empty());
}

TEST(Parser, PercentInsideABlockIsAnError) {
  const Program p = parse("G00 % X1.");
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(p.lexicalDiagnostics[0].code, "E107");
  EXPECT_EQ(p.lexicalDiagnostics[0].range.column, 5);
}

// ---- lexical errors: code, line, column, length ---------------------------

struct LexCase {
  const char* text;
  const char* code;
  int column;
  int length;
  const char* arg;
};

class LexicalError : public ::testing::TestWithParam<LexCase> {};

TEST_P(LexicalError, IsReportedAtTheWord) {
  const LexCase& c = GetParam();
  const Program p = parse(std::string("N5 G01\n") + c.text, 1);
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u) << c.text;
  const Diagnostic& d = p.lexicalDiagnostics[0];
  EXPECT_EQ(d.code, c.code);
  EXPECT_EQ(d.severity, Severity::Error);
  EXPECT_EQ(d.range, (SourceRange{2, c.column, c.length}));
  if (c.arg) {
    ASSERT_FALSE(d.args.empty());
    EXPECT_EQ(d.args[0], c.arg);
  }
  // The checker passes lexical errors on.
  const auto all = check(p);
  EXPECT_TRUE(std::any_of(all.begin(), all.end(), [&](const Diagnostic& x) { return x.code == c.code; }));
}

INSTANTIATE_TEST_SUITE_P(
    Table, LexicalError,
    ::testing::Values(LexCase{"G01 X", "E101", 5, 1, "X"},            // lone letter at the end
                      LexCase{"G01 X Z5.", "E101", 5, 1, "X"},        // lone letter before a word
                      LexCase{"g01 x(comment)", "E101", 5, 1, "X"},   // lower case, comment after
                      LexCase{"20 G01", "E102", 1, 2, "20"},          // lone number ("G01 20" is G0120, as on a Fanuc)
                      LexCase{"X1.2.3", "E103", 1, 6, "X1.2.3"},      // two decimal points
                      LexCase{"Z5. X--1", "E103", 5, 4, "X--1"},      // two signs
                      LexCase{"X-", "E103", 1, 2, "X-"},              // sign without digits
                      LexCase{"X.", "E103", 1, 2, "X."},              // point without digits
                      LexCase{"X1-2", "E103", 1, 4, "X1-2"},          // sign in the middle
                      LexCase{"G01 # X1.", "E125", 5, 1, "#"},        // '#' without a variable number
                      LexCase{"G01 X[#1+2.", "E121", 6, 1, nullptr},  // unclosed bracket
                      LexCase{"G01 X#1 Z[#2 PLUS 1]", "E123", 14, 1, "PLUS"},
                      LexCase{"#1=SIN 30.", "E124", 4, 1, "SIN"}, LexCase{"WHILE [#1 LT 3] DO 4", "E130", 20, 1, "4"},
                      LexCase{"IF [#1 EQ 0] X1.", "E128", 1, 2, nullptr}, LexCase{"G01 X20. @", "E104", 10, 1, "@"},
                      LexCase{"G01 X20. ===", "E104", 10, 3, "="},  // a run of unknown characters
                      LexCase{"G01 X20. []", "E104", 10, 2, "["}));

TEST(Parser, EveryErrorOfALineIsReported) {
  const Program p = parse("X Y. @Z1.2.3 #Z (x");
  std::vector<std::string> codes;
  for (const auto& d : p.lexicalDiagnostics) codes.push_back(d.code + "@" + std::to_string(d.range.column));
  // '#' starts a macro statement; its error skips to the comment.
  EXPECT_THAT(codes, ElementsAre("E101@1", "E103@3", "E104@6", "E103@7", "E125@14", "W108@17"));
}

// ---- bad input never crashes ------------------------------------------------

TEST(ParserRobustness, EmptyText) {
  const Program p = parse("", 7);
  EXPECT_TRUE(p.blocks.empty());
  EXPECT_TRUE(p.lexicalDiagnostics.empty());
  EXPECT_EQ(p.lineCount, 0);
  EXPECT_TRUE(check(p).empty());
}

TEST(ParserRobustness, BinaryBytes) {
  std::string junk;
  for (int i = 0; i < 4096; ++i) junk += static_cast<char>((i * 131 + 7) & 0xFF);
  junk += std::string("\0\0\0G01\0X1.", 10);
  const Program p = parse(junk);
  EXPECT_FALSE(p.lexicalDiagnostics.empty());
  for (const auto& d : p.lexicalDiagnostics) {
    EXPECT_GE(d.range.line, 1);
    EXPECT_GE(d.range.column, 1);
  }
  for (Dialect dialect : {Dialect::Fanuc, Dialect::Classic}) {
    CheckOptions o;
    o.dialect = dialect;
    EXPECT_TRUE(hasErrors(check(p, o)));
  }
}

TEST(ParserRobustness, InvalidUtf8CountsOneColumnPerByte) {
  // \xff and a truncated 3-byte sequence each count as single code points.
  const Program p = parse("(\xff\xe0\x80) X1. \xfe");
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_EQ(p.blocks[0].words[0].range.column, 7);
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(p.lexicalDiagnostics[0].code, "E104");
  EXPECT_EQ(p.lexicalDiagnostics[0].range.column, 11);
}

TEST(ParserRobustness, TenMegabyteSingleLineOfWords) {
  std::string line;
  const std::string unit = "G01X20.Z-5.F0.2";
  line.reserve(10'000'000 + unit.size());
  while (line.size() < 10'000'000) line += unit;
  const Program p = parse(line);
  // The block keeps its first 1000 words; the rest of the line is reported.
  ASSERT_EQ(p.blocks.size(), 1u);
  ASSERT_EQ(p.blocks[0].words.size(), 1000u);
  EXPECT_EQ(p.blocks[0].words.back().range.column, 250 * 15 - 3);
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(p.lexicalDiagnostics[0].code, "E120");
  EXPECT_EQ(p.lexicalDiagnostics[0].range.column, 250 * 15 + 1);
  // Every repeated letter of the kept words is an error.
  const auto diags = check(p);
  EXPECT_TRUE(hasErrors(diags));
  EXPECT_GT(diags.size(), 900u);
}

TEST(ParserRobustness, TenMegabyteCommentBeforeAWord) {
  const std::string text = "(" + std::string(10'000'000, 'a') + ") X1. Y";
  const Program p = parse(text);
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_EQ(p.blocks[0].words[0].range.column, 10'000'004);
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(p.lexicalDiagnostics[0].range.column, 10'000'008);
}

TEST(ParserRobustness, TenMegabyteSingleLineOfJunk) {
  const std::string junk(10'000'000, '@');
  const Program p = parse(junk);
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(p.lexicalDiagnostics[0].range, (SourceRange{1, 1, 10'000'000}));
}

TEST(ParserRobustness, TenMegabytesOfHashesAreOneMacroError) {
  // '##...#' nests variable references: refused past the depth limit, no stack overflow.
  const Program p = parse(std::string(10'000'000, '#'));
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(p.lexicalDiagnostics[0].code, "E126");
  EXPECT_EQ(p.lexicalDiagnostics[0].range.line, 1);
}

TEST(ParserRobustness, TenMegabyteNumberAndComment) {
  std::string text = "X" + std::string(5'000'000, '9') + " (" + std::string(5'000'000, 'a');
  const Program p = parse(text);
  ASSERT_EQ(p.blocks.size(), 1u);
  ASSERT_EQ(p.lexicalDiagnostics.size(), 1u);
  EXPECT_EQ(p.lexicalDiagnostics[0].code, "W108");  // the comment runs to the line end (E105 in classic)
  const auto diags = check(p);
  ASSERT_EQ(diags.size(), 2u);
  EXPECT_EQ(diags[0].code, "E110");  // X out of range, at column 1
  EXPECT_EQ(diags[0].range.column, 1);
}

TEST(ParserRobustness, TenMegabytesOfCrOnlyLineEndsIsLinear) {
  std::string text;
  text.reserve(10'000'000);
  while (text.size() < 10'000'000) text += "(c)\r";
  text += "X1.";
  const Program p = parse(text);
  EXPECT_EQ(p.lineCount, 2'500'001);
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_EQ(p.blocks[0].line, 2'500'001);
}

TEST(ParserRobustness, ManyErrorsAreCapped) {
  std::string text;
  for (int i = 0; i < 5000; ++i) text += "X\n";
  const Program p = parse(text);
  ASSERT_FALSE(p.lexicalDiagnostics.empty());
  EXPECT_LE(p.lexicalDiagnostics.size(), 2000u);
  EXPECT_EQ(p.lexicalDiagnostics.back().code, "E109");
}

TEST(ParserRobustness, HundredThousandBlocks) {
  std::string text;
  for (int i = 0; i < 100'000; ++i) text += "G01 X20. Z-5. F0.2\n";
  const Program p = parse(text, 7);
  ASSERT_EQ(p.blocks.size(), 100'000u);
  EXPECT_EQ(p.blocks.back().line, 100'006);
  EXPECT_EQ(p.lineCount, 100'000);
}

}  // namespace
}  // namespace klueng::core::gcode

// A word's number as written (word_number.h): short numbers inside the word,
// long ones on the heap or in the parser's store; copies and moves keep the text; the letter mask of a
// parsed block lets find() skip blocks without the letter.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"

namespace klueng::core::gcode {
namespace {

TEST(WordNumber, KeepsShortAndLongTextExactly) {
  const std::string seven = "-12.345";  // the most held inside the word
  const std::string eight = "-123.456";
  const std::string sixteen = "-123456789.01234";
  const std::string long4k = "1" + std::string(4000, '0') + ".";
  for (const std::string& text : {std::string(), std::string("01"), seven, eight, sixteen, long4k}) {
    const WordNumber n(text);
    EXPECT_EQ(n.size(), text.size());
    EXPECT_EQ(n.view(), text);
    EXPECT_EQ(n.str(), text);
    EXPECT_EQ(n.empty(), text.empty());
  }
}

TEST(WordNumber, CopiesMovesAndAssignmentsKeepTheirOwnText) {
  const std::string longText = "-" + std::string(40, '7') + ".5";
  WordNumber a(longText);
  WordNumber b = a;  // a deep copy: changing one leaves the other
  b = "2.";
  EXPECT_EQ(a, longText);
  EXPECT_EQ(b, "2.");
  WordNumber c = std::move(a);
  EXPECT_EQ(c, longText);
  EXPECT_TRUE(a.empty());  // NOLINT(bugprone-use-after-move): a moved-from number is empty
  const WordNumber& same = c;
  c = same;  // self-assignment keeps the text
  EXPECT_EQ(c, longText);
  c.assign(c.view().substr(1));  // from its own text
  EXPECT_EQ(c, longText.substr(1));
  b = std::move(c);
  EXPECT_EQ(b, longText.substr(1));
  b += '0';
  EXPECT_EQ(b, longText.substr(1) + "0");
  WordNumber s("25");
  s += '.';
  EXPECT_EQ(s, "25.");
}

TEST(WordNumber, ReadsLikeAString) {
  const WordNumber n("-[#1+2.]");
  EXPECT_EQ(n.front(), '-');
  EXPECT_EQ(n.back(), ']');
  EXPECT_EQ(n[1], '[');
  EXPECT_EQ(n.find('#'), 2u);
  EXPECT_EQ(n.find("+2"), 4u);
  EXPECT_EQ(n.find('X'), WordNumber::npos);
  EXPECT_EQ(n.substr(n.find('#') + 1), "1+2.]");
  EXPECT_EQ('X' + n, "X-[#1+2.]");
  EXPECT_EQ("G" + WordNumber("71"), "G71");
  std::ostringstream os;
  os << n;
  EXPECT_EQ(os.str(), "-[#1+2.]");
}

TEST(WordNumber, ParsedWordsKeepNumbersPastTheInlineSize) {
  const std::string digits = "0000000000000000000012.5";  // 24 characters
  const Program p = parse("N10 G01 X" + digits + " Z-5.\n");
  ASSERT_EQ(p.blocks.size(), 1u);
  const Word* x = p.blocks[0].find('X');
  ASSERT_NE(x, nullptr);
  EXPECT_EQ(x->number, digits);
  EXPECT_EQ(x->text(), "X" + digits);
  EXPECT_DOUBLE_EQ(x->value, 12.5);
  EXPECT_EQ(x->decimals, 1);
  const Program copy = p;  // the interpreter's rounding copies whole programs
  EXPECT_EQ(copy.blocks[0].find('X')->number, digits);
}

TEST(WordNumber, IsEightBytesAndABlockFortyOnA64BitBuild) {
  EXPECT_EQ(sizeof(WordNumber), 8u);
  if constexpr (sizeof(void*) == 8) {
    EXPECT_EQ(sizeof(Word), 40u);
    EXPECT_EQ(sizeof(Block), 40u);
  }
}

TEST(WordNumber, ANumberFromTheParsersStoreOutlivesItsProgramInACopy) {
  // "-123.4567" and the 20-digit number are too long to be held inside: the parser's store keeps
  // them, and a word copied out of the program owns its own text.
  std::vector<Word> kept;
  {
    Program p = parse("G01 X-123.4567 Z12345678901234567890.\n#1 = 2\nN5 #2 = 3 (a note)\n");
    ASSERT_EQ(p.blocks.size(), 3u);
    const Program moved = std::move(p);  // a moved program keeps its store
    EXPECT_EQ(moved.blocks[0].find('X')->number, "-123.4567");
    EXPECT_EQ(moved.blocks[0].find('X')->decimals, 4);
    EXPECT_DOUBLE_EQ(moved.blocks[0].find('X')->value, -123.4567);
    EXPECT_EQ(moved.blocks[0].find('Z')->text(), "Z12345678901234567890.");
    EXPECT_EQ(moved.blocks[1].statement().kind, StatementKind::Assign);
    EXPECT_EQ(moved.blocks[2].statement().kind, StatementKind::Assign);
    EXPECT_EQ(moved.blocks[2].comment(), "a note");
    EXPECT_EQ(moved.blocks[0].statement().kind, StatementKind::None);  // an NC block has no notes
    EXPECT_EQ(moved.blocks[0].comment(), "");
    for (const Word& w : moved.blocks[0].words) kept.push_back(w);
    Block copy = moved.blocks[2];  // a copy has its own notes
    copy.editComment() = "changed";
    EXPECT_EQ(moved.blocks[2].comment(), "a note");
  }
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[1].number, "-123.4567");
  EXPECT_EQ(kept[2].number, "12345678901234567890.");
}

TEST(BlockLetters, ParseRecordsTheLettersOfEveryWordAndFindTrustsThem) {
  const Program p = parse("N10 G01 X20. ,C1. F0.2\n#1 = 5\nN20 IF [#1 GT 2] GOTO 40\n");
  ASSERT_EQ(p.blocks.size(), 3u);
  const Block& b = p.blocks[0];
  EXPECT_EQ(b.letters, Block::letterBit('N') | Block::letterBit('G') | Block::letterBit('X') | Block::letterBit('C') |
                           Block::letterBit('F'));
  EXPECT_EQ(b.find('Z'), nullptr);
  EXPECT_EQ(b.find('C'), nullptr);  // ,C is a comma word
  ASSERT_NE(b.findComma('C'), nullptr);
  EXPECT_EQ(b.findComma('C')->value, 1.0);
  EXPECT_EQ(p.blocks[1].letters, 0u);                     // an assignment has no words
  EXPECT_EQ(p.blocks[2].letters, Block::letterBit('N'));  // a statement keeps only its N
  int gs = 0;
  for (const Word* g : b.all('G')) gs += g->code();
  EXPECT_EQ(gs, 1);
  for ([[maybe_unused]] const Word* m : b.all('M')) ADD_FAILURE() << "no M word in the block";
}

TEST(BlockLetters, ABlockBuiltByHandIsSearchedWordByWord) {
  Block b;  // letters unknown: every bit set, so find() looks at the words
  Word x;
  x.letter = 'X';
  x.number = "30.";
  x.value = 30.0;
  b.words.push_back(x);
  ASSERT_NE(b.find('X'), nullptr);
  EXPECT_EQ(b.find('X')->value, 30.0);
  EXPECT_EQ(b.find('Z'), nullptr);
  EXPECT_EQ(Block::letterBit('a'), 0u);  // not an address letter: no bit, no word
  EXPECT_EQ(b.find('a'), nullptr);
}

TEST(BlockLetters, TheCheckerStillSeesEveryWordOfAParsedProgram) {
  // T, M98 P and G65 are found through the letter mask by the checks that ask for them.
  const Program p = parse("O0001\nN1 T0909\nN2 M98 P1234\nN3 G65 P9010 A1.\nM30\n");
  CheckOptions options;
  options.turretStations = 8;
  const std::vector<Diagnostic> d = check(p, options);
  bool station = false;
  for (const Diagnostic& x : d) station |= x.range.line == 2;
  EXPECT_TRUE(station) << "T0909 on an 8-station turret is reported at line 2";
}

}  // namespace
}  // namespace klueng::core::gcode

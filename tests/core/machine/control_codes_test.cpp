// Codes of the Fanuc 0i-TF and Haas lathes beyond the ones that cut (issue 38): G52 moves the
// program's zero, G09/G61/G64 and the other machine functions leave the path as it is, and a code
// Klueng does not simulate stops the run with A117 on its own line.
#include <gtest/gtest.h>

#include "test_support.h"

namespace klueng::core::machine {
namespace {

using testing::runText;

TEST(LocalCoordinates, G52MovesTheZeroTheAbsoluteWordsAreReadFrom) {
  const Timeline t = runText(
      "G21 G99\n"       // 1
      "G00 X40. Z2.\n"  // 2
      "G52 Z-20.\n"     // 3: the program's Z0 is now the work's Z-20, the tool stays
      "G00 X30. Z0.\n"  // 4: to the work's Z-20
      "G00 W5.\n"       // 5: incremental words are not shifted: Z-15
      "G52 X10. Z0\n"   // 6: Z back, X0 at the work's X10 (diameter)
      "G00 X20. Z5.\n"  // 7: work X30 Z5
      "G52 X0 Z0\n"     // 8: cancelled
      "G00 X20.\n");    // 9: work X20
  ASSERT_FALSE(t.alarm.has_value()) << t.alarm->code;
  const auto endOfLine = [&](int line) {
    const Move* last = nullptr;
    for (const Move& m : t.moves)
      if (m.line == line) last = &m;
    EXPECT_NE(last, nullptr) << "no move on line " << line;
    return last ? last->path.end : Vec2(0.0, 0.0);
  };
  for (const Move& m : t.moves) EXPECT_NE(m.line, 3) << "G52 moves nothing";
  EXPECT_POINT(endOfLine(4), 30.0, -20.0);
  EXPECT_POINT(endOfLine(5), 30.0, -15.0);
  EXPECT_POINT(endOfLine(7), 30.0, 5.0);
  EXPECT_POINT(endOfLine(9), 20.0, 5.0);
}

TEST(MachineFunctions, ExactStopAndTheOtherFunctionsLeaveThePathAsItIs) {
  const std::string plain = "G21 G99\nT0101\nG97 S800 M03\nG00 X40. Z2.\nG01 Z-10. F0.2\nX46.\nM30\n";
  const std::string withFunctions =
      "G21 G99 G23 G25 G69\nT0101\nG97 S800 M03 G05.1 Q1\nG00 X40. Z2.\nG61\nG09 G01 Z-10. F0.2\nG64 X46.\nM30\n";
  const Timeline a = runText(plain);
  const Timeline b = runText(withFunctions);
  ASSERT_FALSE(a.alarm.has_value());
  ASSERT_FALSE(b.alarm.has_value()) << b.alarm->code;
  ASSERT_EQ(a.moves.size(), b.moves.size());
  for (std::size_t i = 0; i < a.moves.size(); ++i) {
    EXPECT_POINT(b.moves[i].path.end, 2.0 * a.moves[i].path.end.y(), a.moves[i].path.end.x());
    EXPECT_DOUBLE_EQ(b.moves[i].tEnd, a.moves[i].tEnd);
  }
}

TEST(NotSimulated, ARunStopsAtACodeKluengDoesNotSimulateOnItsLine) {
  struct Case {
    const char* text;
    int line;
    const char* word;
  };
  const Case cases[] = {
      {"G21 G99\nG00 X40. Z2.\nG12.1\nG01 X20. F0.1\n", 3, "G12.1"},
      {"G21 G99\nG00 X40. Z2.\nG68\nG00 X20.\n", 3, "G68"},
      {"G21 G99\nG00 X40. Z2.\nG31 Z-10. F100.\n", 3, "G31"},
      // An arc in the XY plane of a live tool: the plane is read, the arc not drawn.
      {"G21 G99\nG97 S500 M03\nG17\nG01 X30. F0.1\nG02 X20. Z-3. R5. F0.1\n", 5, "G02"},
  };
  for (const Case& c : cases) {
    const Timeline t = runText(c.text);
    ASSERT_TRUE(t.alarm.has_value()) << c.text;
    EXPECT_EQ(t.alarm->code, "A117") << c.text;
    EXPECT_EQ(t.alarm->range.line, c.line) << c.text;
    ASSERT_FALSE(t.alarm->args.empty());
    EXPECT_EQ(t.alarm->args[0].rfind(c.word, 0), 0u) << t.alarm->args[0];
  }
  // Back in G18, arcs are drawn again.
  const Timeline back = runText("G21 G99\nG97 S500 M03\nG00 X40. Z2.\nG19\nG18\nG02 X20. Z-3. R15. F0.1\n");
  EXPECT_FALSE(back.alarm.has_value());
}

// Fanuc T series "Chamfering and corner R" without the comma (B-63944EN-1/02 §4.5, parameter 3405#4
// CCR = 0 as shipped): `X30. K-2.` chamfers the corner to the next Z move, `Z-20. R2.` rounds it.
TEST(ChamferWithoutComma, FanucReadsIKAndRAsTheNinetyDegreeChamferAndCornerR) {
  const Timeline t = runText(
      "G21 G99 G97 S500 M03\n"  // 1
      "G00 X22. Z2.\n"          // 2
      "G01 Z0 F0.1\n"           // 3
      "X30. K-2.\n"             // 4: up the face to X26., then 45 degrees to X30. Z-2.
      "Z-20. R2.\n"             // 5: along Z to Z-18., then R2 up to X34. Z-20.
      "X40.\n"                  // 6
      "G00 X100.\n");           // 7
  ASSERT_FALSE(t.alarm.has_value()) << t.alarm->code;
  std::vector<const Move*> cuts;
  for (const Move& m : t.moves)
    if (m.kind != MoveKind::Rapid && m.line >= 4 && m.line <= 6) cuts.push_back(&m);
  ASSERT_EQ(cuts.size(), 5u);
  EXPECT_POINT(cuts[0]->path.end, 26.0, 0.0);
  EXPECT_POINT(cuts[1]->path.end, 30.0, -2.0);  // the chamfer
  EXPECT_POINT(cuts[2]->path.end, 30.0, -18.0);
  EXPECT_TRUE(cuts[3]->path.isArc());
  EXPECT_POINT(cuts[3]->path.end, 34.0, -20.0);  // the corner R
  EXPECT_POINT(cuts[4]->path.end, 40.0, -20.0);
}

}  // namespace
}  // namespace klueng::core::machine

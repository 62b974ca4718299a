// Explanations of blocks (issue 11): one block per code family with its exact
// English and Thai text, and a sentence for every code of the table.
#include "klueng/core/help/explain.h"

#include <gtest/gtest.h>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/machine/interpreter.h"
#include "../machine/test_support.h"

namespace klueng::core::machine {
namespace {

// The state after block `line` of `text` when it runs.
struct Ran {
  gcode::Program program;
  Timeline timeline;
  const StateSnapshot& after(int line) const {
    for (const StateSnapshot& s : timeline.snapshots)
      if (s.line == line) return s;
    ADD_FAILURE() << "line " << line << " did not run";
    return timeline.snapshots.front();
  }
  const gcode::Block& block(int line) const {
    for (const gcode::Block& b : program.blocks)
      if (b.line == line) return b;
    ADD_FAILURE() << "no block on line " << line;
    return program.blocks.front();
  }
  std::string explain(int line, Lang lang, std::string_view text = {}) const {
    return explainBlock(block(line), after(line), gcode::Dialect::Fanuc, lang, text);
  }
};

Ran run(const std::string& text) {
  Ran r{gcode::parse(text, 1), {}};
  r.timeline = interpret(r.program, testing::testSetup(), {});
  EXPECT_FALSE(r.timeline.alarm) << r.timeline.alarm->code;
  return r;
}

constexpr char kTurning[] =
    "G21 G99\n"
    "G50 S2500\n"
    "T0101\n"
    "G96 S180 M03\n"
    "G00 X52. Z2. M08\n"
    "G01 X30. Z-20. F0.2\n"
    "G02 X40. Z-25. R5.\n"
    "G04 X1.5\n"
    "G00 X100. Z100. M09\n"
    "M30\n";

TEST(Explain, AFeedMoveUnderG96SaysWhereHowFastAndTheRpmThere) {
  const Ran r = run(kTurning);
  EXPECT_EQ(r.explain(6, Lang::En),
            "G01 X30. Z-20. F0.2: cut in a straight line to Ø30 at Z-20, 0.2 mm per revolution; at 180 m/min (G96) "
            "the spindle turns 1910 rpm here");
  EXPECT_EQ(r.explain(6, Lang::Th),
            "G01 X30. Z-20. F0.2: กลึงเป็นเส้นตรง ไปที่ Ø30 Z-20 ป้อน 0.2 มม./รอบ; ที่ความเร็วตัด 180 ม./นาที (G96) "
            "เพลาหมุน 1910 รอบ/นาที ที่ตำแหน่งนี้");
}

TEST(Explain, AnArcGivesItsDirectionAndRadius) {
  const Ran r = run(kTurning);
  EXPECT_EQ(r.explain(7, Lang::En),
            "G02 X40. Z-25. R5.: cut a clockwise arc of radius 5 to Ø40 at Z-25, 0.2 mm per revolution; at 180 m/min "
            "(G96) the spindle turns 1432 rpm here");
  EXPECT_EQ(r.explain(7, Lang::Th),
            "G02 X40. Z-25. R5.: กลึงส่วนโค้งตามเข็มนาฬิกา รัศมี 5 ไปที่ Ø40 Z-25 ป้อน 0.2 มม./รอบ; ที่ความเร็วตัด 180 "
            "ม./นาที (G96) เพลาหมุน 1432 รอบ/นาที ที่ตำแหน่งนี้");
}

TEST(Explain, StateCodesSpindleAndTool) {
  const Ran r = run(kTurning);
  EXPECT_EQ(r.explain(2, Lang::En), "G50 S2500: G50 limit the spindle to 2500 rpm");
  EXPECT_EQ(r.explain(2, Lang::Th), "G50 S2500: G50 จำกัดความเร็วรอบเพลาไม่เกิน 2500 รอบ/นาที");
  EXPECT_EQ(r.explain(3, Lang::En), "T0101: turn to tool 01 with offset 01");
  EXPECT_EQ(r.explain(3, Lang::Th), "T0101: เปลี่ยนมีดตัดหมายเลข 01 ใช้ออฟเซต 01");
  EXPECT_EQ(
      r.explain(4, Lang::En),
      "G96 S180 M03: G96 constant cutting speed: the rpm follows the diameter; cutting speed 180 m/min; M03 start "
      "the spindle clockwise");
  EXPECT_EQ(r.explain(4, Lang::Th),
            "G96 S180 M03: G96 ความเร็วตัดคงที่: รอบเพลาเปลี่ยนตามเส้นผ่าศูนย์กลาง; ความเร็วตัด 180 ม./นาที; M03 "
            "เปิดเพลาหมุนตามเข็มนาฬิกา");
  EXPECT_EQ(r.explain(1, Lang::En),
            "G21 G99: G21 lengths from here on are in millimetres; G99 feed in mm per revolution");
}

TEST(Explain, RapidsDwellsAndMCodes) {
  const Ran r = run(kTurning);
  EXPECT_EQ(r.explain(5, Lang::En),
            "G00 X52. Z2. M08: move at rapid speed, not cutting to Ø52 at Z2; M08 turn the coolant on");
  EXPECT_EQ(r.explain(5, Lang::Th), "G00 X52. Z2. M08: เคลื่อนที่เร็วโดยไม่ตัดเฉือน ไปที่ Ø52 Z2; M08 เปิดน้ำหล่อเย็น");
  EXPECT_EQ(r.explain(8, Lang::En), "G04 X1.5: G04 wait with the tool standing still 1.5 s");
  EXPECT_EQ(r.explain(8, Lang::Th), "G04 X1.5: G04 หยุดรอโดยมีดอยู่กับที่ 1.5 วินาที");
  EXPECT_EQ(r.explain(10, Lang::En), "M30: M30 end of the program");
  EXPECT_EQ(r.explain(10, Lang::Th), "M30: M30 จบโปรแกรม");
}

TEST(Explain, CyclesSayTheirProfileDepthAndAllowance) {
  const Ran r =
      run("G21 G99\nG50 S2000\nT0101\nG96 S150 M03\nG00 X52. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n"
          "N10 G00 X30.\nG01 Z-20.\nN20 X52.\nG00 X100. Z100.\nM30\n");
  EXPECT_EQ(
      r.explain(6, Lang::En),
      "G71 U2. R0.5: G71 rough turning cycle: take the profile down in passes along Z; depth of cut 2 mm per pass, "
      "retract 0.5 mm");
  EXPECT_EQ(r.explain(6, Lang::Th),
            "G71 U2. R0.5: G71 วัฏจักรกลึงปอกหยาบ: กลึงตามรูปร่างทีละเที่ยวตามแนวแกน Z; ป้อนลึกเที่ยวละ 2 มม. ถอยมีด 0.5 มม.");
  EXPECT_EQ(
      r.explain(7, Lang::En),
      "G71 P10 Q20 U0.4 W0.1 F0.25: G71 rough turning cycle: take the profile down in passes along Z; the profile "
      "is blocks N10 to N20; finishing allowance U0.4 on the diameter; 0.25 mm per revolution");
}

TEST(Explain, InsideACycleThePassIsCounted) {
  const Ran r =
      run("G21 G99\nG50 S2000\nT0101\nG96 S150 M03\nG00 X52. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n"
          "N10 G00 X30.\nG01 Z-20.\nN20 X52.\nG00 X100. Z100.\nM30\n");
  // Roughing from Ø52 to Ø30.4 at 2 mm a side: passes at Ø48, 44, 40, 36, 32 and the last at 30.4 plus
  // the pass along the profile.
  std::vector<int> cuts;  // the G71 block's moves that cut
  for (std::size_t i = 0; i < r.timeline.moves.size(); ++i)
    if (r.timeline.moves[i].line == 7 && r.timeline.moves[i].kind == MoveKind::Line)
      cuts.push_back(static_cast<int>(i));
  ASSERT_GT(cuts.size(), 3u);
  const std::string first = explainPass(r.timeline, cuts.front(), Lang::En);
  const std::string last = explainPass(r.timeline, cuts.back(), Lang::En);
  ASSERT_EQ(first.rfind("pass 1 of ", 0), 0u) << first;
  const std::string total = first.substr(std::string("pass 1 of ").size());
  EXPECT_EQ(last, "pass " + total + " of " + total);
  EXPECT_EQ(explainPass(r.timeline, cuts.front(), Lang::Th), "เที่ยวที่ 1 จาก " + total);
  EXPECT_GE(std::stoi(total), 6);
  // A plain G01 is one pass: nothing to count.
  for (std::size_t i = 0; i < r.timeline.moves.size(); ++i)
    if (r.timeline.moves[i].line == 5) {
      EXPECT_EQ(explainPass(r.timeline, static_cast<int>(i), Lang::En), "");
    }
}

TEST(Explain, ThreadsAndMacroStatements) {
  const Ran r = run("G21 G99\nT0303\nG97 S800 M03\nG00 X30. Z5.\nG32 Z-30. F1.5\n#1=2\nG00 X40.\nM30\n");
  EXPECT_EQ(r.explain(5, Lang::En),
            "G32 Z-30. F1.5: cut one pass of a thread, the feed locked to the spindle to Z-30, lead 1.5 mm");
  EXPECT_EQ(r.explain(3, Lang::En),
            "G97 S800 M03: G97 constant spindle rpm; spindle speed 800 rpm; M03 start the spindle clockwise");
  EXPECT_EQ(r.explain(6, Lang::En, "#1=2"), "#1=2: give a macro variable a value");
  EXPECT_EQ(r.explain(6, Lang::Th, "#1=2"), "#1=2: กำหนดค่าให้ตัวแปรมาโคร");
}

TEST(Explain, WithoutARunTheWordsAloneAreSaid) {
  const gcode::Program p = gcode::parse("G01 X30. Z-20. F0.2\n", 1);
  EXPECT_EQ(explainWords(p.blocks[0], gcode::Dialect::Fanuc, Lang::En),
            "G01 X30. Z-20. F0.2: cut in a straight line to Ø30 at Z-20, feed F0.2");
}

TEST(Explain, ALineOfTextAsTheEditorHoldsIt) {
  EXPECT_EQ(explainLineText("#1=2", 6, nullptr, gcode::Dialect::Fanuc, Lang::En),
            "#1=2: give a macro variable a value");
  EXPECT_EQ(explainLineText("G01 X30. Z-20. F0.2 (finish)", 9, nullptr, gcode::Dialect::Fanuc, Lang::En),
            "G01 X30. Z-20. F0.2: cut in a straight line to Ø30 at Z-20, feed F0.2");
  EXPECT_EQ(explainLineText("(only a comment)", 3, nullptr, gcode::Dialect::Fanuc, Lang::En), "");
  const Ran r = run(kTurning);
  EXPECT_EQ(explainLineText("G01 X30. Z-20. F0.2", 6, &r.after(6), gcode::Dialect::Fanuc, Lang::En),
            r.explain(6, Lang::En));
}

// Issue 26 item 6: a job that reads lengths without a point in least input
// increments says the lengths it will cut, not the digits as written.
TEST(Explain, LengthsInIncrementsAreSaidAsTheyAreRead) {
  const std::string whole = explainLineText("G71 U1500 R500", 12, nullptr, gcode::Dialect::Fanuc, Lang::En);
  EXPECT_NE(whole.find("depth of cut 1500 mm per pass, retract 500 mm"), std::string::npos) << whole;
  const std::string increments = explainLineText("G71 U1500 R500", 12, nullptr, gcode::Dialect::Fanuc, Lang::En, true);
  EXPECT_NE(increments.find("depth of cut 1.5 mm per pass, retract 0.5 mm"), std::string::npos) << increments;
  EXPECT_EQ(explainLineText("G01 X30000 Z-20. F0.2", 9, nullptr, gcode::Dialect::Fanuc, Lang::En, true),
            "G01 X30000 Z-20. F0.2: cut in a straight line to Ø30 at Z-20, feed F0.2");
}

TEST(Explain, EveryCodeOfTheTableHasASentenceInBothLanguages) {
  int rows = 0;
  for (const gcode::CodeInfo& row : gcode::codeTable())
    for (gcode::Dialect d : {gcode::Dialect::Fanuc, gcode::Dialect::Haas, gcode::Dialect::Classic}) {
      if (!row.in(d)) continue;
      ++rows;
      const std::string en = explainCode(row.letter, row.number, d, Lang::En);
      const std::string th = explainCode(row.letter, row.number, d, Lang::Th);
      EXPECT_GE(en.size(), 6u) << row.letter << row.number;
      EXPECT_GE(th.size(), 6u) << row.letter << row.number;
      EXPECT_NE(en, th) << row.letter << row.number;
      // Thai text is Thai: it holds a letter of the Thai block (U+0E00..U+0E7F: E0 B8/B9 in UTF-8).
      EXPECT_TRUE(th.find("\xE0\xB8") != std::string::npos || th.find("\xE0\xB9") != std::string::npos)
          << row.letter << row.number;
    }
  EXPECT_GT(rows, 100);
  EXPECT_TRUE(explainCode('G', 999, gcode::Dialect::Fanuc, Lang::En).empty());
}

}  // namespace
}  // namespace klueng::core::machine

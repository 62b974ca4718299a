// The checker's modal rules (issue 11): the run-time alarms a student can be
// told about while typing, at the word the run would stop on.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/messages.h"

namespace klueng::core::gcode {
namespace {

std::vector<Diagnostic> modal(const std::string& text, Dialect dialect = Dialect::Fanuc) {
  CheckOptions o;
  o.dialect = dialect;
  o.modalRules = true;
  return check(parse(text, 1), o);
}

std::string where(const Diagnostic& d) {
  return d.code + "@" + std::to_string(d.range.line) + ":" + std::to_string(d.range.column) + "+" +
         std::to_string(d.range.length);
}

std::vector<std::string> places(const std::vector<Diagnostic>& ds) {
  std::vector<std::string> out;
  for (const Diagnostic& d : ds) out.push_back(where(d));
  return out;
}

TEST(ModalCheck, AFeedMoveWithNoFInForceIsWarnedAtItsGWordOnce) {
  const auto d = modal("G21 G99\nG00 X20. Z2.\nG01 Z-10.\nX24.\nM30\n");
  ASSERT_EQ(places(d), std::vector<std::string>{"W104@3:1+3"});
  EXPECT_EQ(d[0].severity, Severity::Warning);
  EXPECT_EQ(formatMessage(d[0], Lang::En),
            "G01 with no feed rate in force: no F has been given yet, so the run stops here with alarm A102; add F "
            "(e.g. F0.2 under G99)");
  EXPECT_EQ(formatMessage(d[0], Lang::Th),
            "G01 ไม่มีอัตราป้อน: ยังไม่ได้กำหนด F มาก่อน เมื่อรันจะหยุดที่บล็อกนี้ด้วยสัญญาณเตือน A102 ให้เติม F (เช่น F0.2 เมื่อใช้ G99)");
}

TEST(ModalCheck, AReferenceReturnsAxisWordsAreAPointNotAFeedMove) {
  // G28 and G30 (each its own action) under G01 with no F: their U W name the
  // intermediate point; only the G01 after them is a feed move without F.
  const auto d = modal("G21 G99\nG00 X20. Z2.\nG01\nG28 U0. W0.\nG30 U0. W0.\nZ-10.\nM30\n");
  EXPECT_EQ(places(d), std::vector<std::string>{"W104@6:1+5"});
}

TEST(ModalCheck, AModalFeedMoveWithoutItsGIsWarnedAtItsFirstAxisWord) {
  EXPECT_EQ(places(modal("G21 G98\nG01\nG00 X20. Z2.\nG01 F100. Z0.\nG00 X30.\nG01\nZ-5.\n")),
            std::vector<std::string>{});
  EXPECT_EQ(places(modal("G21 G98\nG00 X20. Z2.\nG01\nU-2. W-1.\n")), std::vector<std::string>{"W104@4:1+4"});
}

TEST(ModalCheck, AFeedGivenBeforeOrInTheBlockIsInForce) {
  EXPECT_TRUE(modal("G99 F0.2\nG01 X20. Z2.\n").empty());
  EXPECT_TRUE(modal("G01 X20. Z2. F0.2\n").empty());
  // G04's X is a time, G50's a name for the position: neither is a feed move.
  EXPECT_TRUE(modal("G01\nG04 X1.5\nG50 X100. Z200.\n").empty());
}

TEST(ModalCheck, WhatOnlyTheRunCanKnowIsNotGuessed) {
  EXPECT_TRUE(modal("#1=0.2\nG01 X20. F#1\nG01 Z-5.\n").empty());  // a macro statement ends the walk
  EXPECT_TRUE(modal("O0001\nM98 P100\nG01 X20. Z0.\nM30\nO0100\nF0.2\nM99\n").empty());  // the subprogram may set F
  EXPECT_TRUE(modal("/G01 X20. Z0.\n").empty());                                         // a skipped block may not run
}

TEST(ModalCheck, G96WithoutAG50LimitIsWarned) {
  const auto d = modal("G21 G99\nT0101\nG96 S180 M03\nG00 X40. Z2.\nG01 Z-10. F0.2\n");
  ASSERT_EQ(places(d), std::vector<std::string>{"W105@3:1+3"});
  EXPECT_NE(formatMessage(d[0], Lang::Th).find("G50 S"), std::string::npos);
  EXPECT_TRUE(modal("G21 G99\nG50 S2000\nG96 S180 M03\n").empty());
  EXPECT_TRUE(modal("G50 S1800\nG96 S200 M03\n", Dialect::Haas).empty());
}

TEST(ModalCheck, AnArcWhoseRadiusCannotJoinItsEndsIsWarnedAtR) {
  // From X20 Z0 to X40 Z-30: 10 mm radial, 30 mm along Z, half the chord 15.811 mm.
  const std::string text = "G21 G98\nG00 X20. Z0.\nG02 X40. Z-30. R5. F100.\nM30\n";
  const auto d = modal(text);
  ASSERT_EQ(places(d), std::vector<std::string>{"W106@3:16+3"});
  EXPECT_EQ(formatMessage(d[0], Lang::En),
            "R5. cannot join the arc's ends: the radius is smaller than half their distance (15.811), so the run stops "
            "here with alarm A114");
  // The run agrees: alarm A114 on that block.
  machine::MachineSetup setup;
  const machine::Timeline t = machine::interpret(parse(text, 1), setup, {});
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A114");
  EXPECT_EQ(t.alarm->range.line, 3);
  // Incremental ends (U is a diameter): from X20 Z-10 to X30 Z-15, half 3.536 < R5.
  EXPECT_TRUE(modal("G98 G00 X20. Z0.\nG01 W-10. F0.1\nG03 U10. W-5. R5.\n").empty());
  // After a cycle the tool is back at its start, which the words alone do not say.
  EXPECT_TRUE(modal("G98 G00 X50. Z2.\nG90 X45. Z-20. F100.\nG00\nG02 X40. Z-30. R5.\n").empty());
}

TEST(ModalCheck, OnlyWhenAsked) { EXPECT_TRUE(check(parse("G01 X20. Z0.\nG96 S100\n", 1)).empty()); }

}  // namespace
}  // namespace klueng::core::gcode

// Fanuc 0i-TF canned cycles through the whole interpreter chain. Every
// expected point is derived by hand in the comments (X as diameters, like the
// program; no tool offset unless said, so the controlled point is the program point).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string_view>
#include <string>
#include <vector>

#include "../../../src/core/machine/cycles.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

using testing::at;
using testing::runText;

// One programmed move as the interpreter sends it down the chain (before the
// timeline splits rapids into dog-leg legs): its kind and end point.
struct Corner {
  MoveKind kind;
  double x;  // diameter
  double z;
};

class RecordingSink final : public MachineSink {
 public:
  std::vector<MotionCall> calls;
  void motion(const MotionCall& m) override { calls.push_back(m); }
  void dwell(const DwellCall&) override {}
  void setPosition(const Vec2&) override {}
  void compensation(NoseCompMode, double, int) override {}
  void blockDone(const StateSnapshot&) override {}
  void alarm(const Diagnostic&) override { halted_ = true; }
  void end() override {}
  bool halted() const override { return halted_; }

 private:
  bool halted_ = false;
};

// A program run twice: through the whole chain (times, alarms) and into a
// recording sink (the moves as programmed).
struct CycleRun {
  explicit CycleRun(std::string_view text) : timeline(runText(text)), alarm(timeline.alarm), moves(timeline.moves) {
    RecordingSink sink;
    run(gcode::parse(text, 1), testing::testSetup(), RunOptions{}, sink);
    calls = std::move(sink.calls);
  }
  Timeline timeline;
  std::optional<Diagnostic> alarm;
  std::vector<Move> moves;
  std::vector<MotionCall> calls;
};

std::vector<Corner> pathOf(const CycleRun& r, int line) {
  std::vector<Corner> out;
  for (const MotionCall& m : r.calls)
    if (m.line == line) out.push_back({m.kind, 2.0 * xOf(m.path.end), zOf(m.path.end)});
  return out;
}

const char* kindName(MoveKind k) {
  switch (k) {
    case MoveKind::Rapid: return "RAPID";
    case MoveKind::Line: return "LINE";
    case MoveKind::Arc: return "ARC";
    case MoveKind::Thread: return "THREAD";
    case MoveKind::Dwell: return "DWELL";
  }
  return "?";
}

void expectPath(const CycleRun& r, int line, const std::vector<Corner>& expected) {
  const auto got = pathOf(r, line);
  ASSERT_EQ(got.size(), expected.size()) << "corners of line " << line;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(kindName(got[i].kind), std::string(kindName(expected[i].kind))) << "corner " << i;
    EXPECT_NEAR(got[i].x, expected[i].x, 1e-6) << "X of corner " << i;
    EXPECT_NEAR(got[i].z, expected[i].z, 1e-6) << "Z of corner " << i;
  }
}

constexpr MoveKind R = MoveKind::Rapid;
constexpr MoveKind L = MoveKind::Line;
constexpr MoveKind T = MoveKind::Thread;

// ---- G90 / G92 / G94 ----------------------------------------------------------

TEST(SingleCycles, G90StraightTurningRepeatsWithOnlyX) {
  const CycleRun t(
      "G98 G97 S500 M03\n"
      "G00 X50. Z2.\n"
      "G90 X40. Z-20. F100.\n"
      "X35.\n"
      "G00 X60.\n");
  ASSERT_FALSE(t.alarm);
  // Rapid in X to the cut diameter, cut to Z-20, out to the start X, rapid back.
  expectPath(t, 3, {{R, 40, 2}, {L, 40, -20}, {L, 50, -20}, {R, 50, 2}});
  // Only X given: Z-20 (and F) stay modal while G90 is.
  expectPath(t, 4, {{R, 35, 2}, {L, 35, -20}, {L, 50, -20}, {R, 50, 2}});
  // G00 cancels the cycle: a plain rapid.
  expectPath(t, 5, {{R, 60, 2}});
  // The Z cut is 22 mm at 100 mm/min = 13.2 s.
  int zCuts = 0;
  for (const Move& m : t.moves) {
    if (m.line == 3 && m.kind == L && std::abs(zOf(m.path.end) + 20) < 1e-9 && xOf(m.path.end) == 20.0) {
      EXPECT_NEAR(m.tEnd - m.tStart, 13.2, 1e-9);
      ++zCuts;
    }
  }
  EXPECT_EQ(zCuts, 1);
}

TEST(SingleCycles, G90TaperStartsRAboveTheEndDiameter) {
  // R-2 (radius): the cut starts at X 40 + 2*(-2) = 36 at the start Z.
  const CycleRun t("G98 G97 S500 M03\nG00 X50. Z2.\nG90 X40. Z-20. R-2. F100.\n");
  ASSERT_FALSE(t.alarm);
  expectPath(t, 3, {{R, 36, 2}, {L, 40, -20}, {L, 50, -20}, {R, 50, 2}});
}

TEST(SingleCycles, G94FacesAlongXThenBackAlongZ) {
  const CycleRun t("G98 G97 S500 M03\nG00 X50. Z2.\nG94 X20. Z-2. F100.\nZ-4.\n");
  ASSERT_FALSE(t.alarm);
  expectPath(t, 3, {{R, 50, -2}, {L, 20, -2}, {L, 20, 2}, {R, 50, 2}});
  expectPath(t, 4, {{R, 50, -4}, {L, 20, -4}, {L, 20, 2}, {R, 50, 2}});
}

TEST(SingleCycles, G92ThreadsSeveralPassesAtTheLeadTimesRpm) {
  const CycleRun t(
      "G97 S500 M03\n"
      "G00 X35. Z5.\n"
      "G92 X29.4 Z-20. F1.5\n"
      "X28.9\n"
      "X28.6\n");
  ASSERT_FALSE(t.alarm);
  expectPath(t, 3, {{R, 29.4, 5}, {T, 29.4, -20}, {R, 35, -20}, {R, 35, 5}});
  expectPath(t, 4, {{R, 28.9, 5}, {T, 28.9, -20}, {R, 35, -20}, {R, 35, 5}});
  expectPath(t, 5, {{R, 28.6, 5}, {T, 28.6, -20}, {R, 35, -20}, {R, 35, 5}});
  // 25 mm at 1.5 mm/rev * 500 rpm = 750 mm/min: 2 s per pass.
  int threads = 0;
  for (const Move& m : t.moves)
    if (m.kind == T) {
      ++threads;
      EXPECT_NEAR(m.tEnd - m.tStart, 2.0, 1e-9);
      EXPECT_DOUBLE_EQ(m.lead, 1.5);
    }
  EXPECT_EQ(threads, 3);
}

TEST(SingleCycles, G92WithTheSpindleStoppedRaisesA116AtTheCycle) {
  const CycleRun t("G97 S500\nG00 X35. Z5.\nG92 X29.4 Z-20. F1.5\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A116");
  EXPECT_EQ(t.alarm->range.line, 3);
  EXPECT_EQ(t.alarm->range.column, 1);
  expectPath(t, 3, {});
}

TEST(SingleCycles, G90UnderG99WithTheSpindleStoppedRaisesA104) {
  const CycleRun t("G99 G97 S500\nG00 X50. Z2.\nG90 X40. Z-20. F0.2\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A104");
  EXPECT_EQ(t.alarm->range.line, 3);
  // The cycle is refused as a whole: none of its moves ran.
  expectPath(t, 3, {});
}

// ---- G71 / G70 -----------------------------------------------------------------

// Start A = X50 Z2; depth 2 per side, retract 0.5; allowance U0.4 (0.2 per
// side) W0.1. Profile A' = X30 Z2 -> Z-20 -> X40 -> Z-40 -> X50, offset by
// (X +0.4, Z +0.1). Pass levels (diameter) 50 - 4k while above the offset A'
// (X30.4): X46, X42, X38, X34. X46 and X42 meet the offset profile at its
// Z-39.9 shoulder, X38 and X34 at its Z-19.9 shoulder. Each pass retracts
// 0.5 at 45 degrees (X +1, Z +0.5) and rapids back to Z2.
constexpr const char* kG71 =
    "G98 G97 S500 M03\n"             // 1
    "G00 X50. Z2.\n"                 // 2
    "G71 U2. R0.5\n"                 // 3
    "G71 P10 Q20 U0.4 W0.1 F100.\n"  // 4
    "N10 G00 X30.\n"                 // 5
    "G01 Z-20.\n"                    // 6
    "X40.\n"                         // 7
    "Z-40.\n"                        // 8
    "N20 X50.\n";                    // 9

// clang-format off: one row per pass, as the manual draws them
const std::vector<Corner> kG71Path = {{R, 46, 2},
                                      {L, 46, -39.9},
                                      {R, 47, -39.4},
                                      {R, 47, 2},
                                      {R, 42, 2},
                                      {L, 42, -39.9},
                                      {R, 43, -39.4},
                                      {R, 43, 2},
                                      {R, 38, 2},
                                      {L, 38, -19.9},
                                      {R, 39, -19.4},
                                      {R, 39, 2},
                                      {R, 34, 2},
                                      {L, 34, -19.9},
                                      {R, 35, -19.4},
                                      {R, 35, 2},
                                      // The last pass: to the offset A', along the offset profile, back to A.
                                      {R, 30.4, 2.1},
                                      {L, 30.4, -19.9},
                                      {L, 40.4, -19.9},
                                      {L, 40.4, -39.9},
                                      {L, 50.4, -39.9},
                                      {R, 50, 2}};
// clang-format on

TEST(StockRemoval, G71RoughsFourPassesThenTheOffsetProfile) {
  const CycleRun t(std::string(kG71) + "G00 X100. Z100.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  EXPECT_TRUE(pathOf(t, 3).empty());  // the first block only stores U and R
  expectPath(t, 4, kG71Path);
  // The profile blocks are skipped after the cycle: the next move is line 10's.
  for (int line = 5; line <= 9; ++line) EXPECT_TRUE(pathOf(t, line).empty()) << line;
  expectPath(t, 10, {{R, 100, 100}});
  int feedPasses = 0;
  for (const Move& m : t.moves)
    if (m.line == 4 && m.kind == L && std::abs(xOf(m.path.start) - xOf(m.path.end)) < 1e-9 && zOf(m.path.start) == 2.0)
      ++feedPasses;
  EXPECT_EQ(feedPasses, 4);
}

// A bore roughed with G71 whose shape ends with a G00 step down to the bore's
// bottom (`G00 X22.` at Z-20, a French school's habit): the last pass cuts the
// whole shape A'->B at the feed, the G00 step included (Fanuc's pre-finishing
// cut); only the approach to A' keeps the first block's G00. Start X22 Z2,
// depth 1 per side, allowance U-0.4 (inside): levels X24, X26; offset A' X27.6.
TEST(StockRemoval, G71ShapeStepWrittenG00IsCutInTheLastPass) {
  const CycleRun t(
      "G98 G97 S500 M03\n"             // 1
      "G00 X22. Z2.\n"                 // 2
      "G71 U1. R0.3\n"                 // 3
      "G71 P10 Q20 U-0.4 W0. F100.\n"  // 4
      "N10 G00 X28.\n"                 // 5
      "G01 Z-20.\n"                    // 6
      "N20 G00 X22.\n"                 // 7
      "G00 Z100.\n");                  // 8
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  const std::vector<Corner> last = {{R, 27.6, 2}, {L, 27.6, -20}, {L, 21.6, -20}, {R, 22, 2}};
  const auto got = pathOf(t, 4);
  ASSERT_GE(got.size(), last.size());
  for (std::size_t i = 0; i < last.size(); ++i) {
    const Corner& c = got[got.size() - last.size() + i];
    EXPECT_EQ(kindName(c.kind), std::string(kindName(last[i].kind))) << "corner " << i;
    EXPECT_NEAR(c.x, last[i].x, 1e-6) << "X of corner " << i;
    EXPECT_NEAR(c.z, last[i].z, 1e-6) << "Z of corner " << i;
  }
}

TEST(StockRemoval, G71PassesEndWhereTheyMeetAnArcOfTheProfile) {
  // Profile X20 -> Z-10 -> G02 to X40 Z-20 R10 -> X50, no allowance. The arc
  // is centred at Z-10 X40 (on the right of travel, cw), so on it
  // x(z) = 20 - sqrt(100 - (z + 10)^2) (radius). From X50, U2: levels
  // (radius) 23 21 19 17 15 13 11. 23 and 21 meet the X50 face at Z-20; level
  // x meets the arc at z = -10 - sqrt(100 - (20 - x)^2): x19 -> -10 - sqrt(99),
  // x17 -> -10 - sqrt(91), x15 -> -10 - sqrt(75), x13 -> -10 - sqrt(51), x11 -> -10 - sqrt(19).
  const CycleRun t(
      "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 F100.\n"
      "N10 G00 X20.\nG01 Z-10.\nG02 X40. Z-20. R10.\nN20 G01 X50.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  std::vector<Corner> cuts;
  for (const Corner& c : pathOf(t, 4))
    if (c.kind == L && c.x < 50.0 - 1e-9) cuts.push_back(c);
  const std::vector<std::pair<double, double>> expected = {{46, -20},
                                                           {42, -20},
                                                           {38, -10 - std::sqrt(99.0)},
                                                           {34, -10 - std::sqrt(91.0)},
                                                           {30, -10 - std::sqrt(75.0)},
                                                           {26, -10 - std::sqrt(51.0)},
                                                           {22, -10 - std::sqrt(19.0)}};
  // The seven pass ends, then the profile's own Z-10 line and arc (the last pass).
  ASSERT_GE(cuts.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(cuts[i].x, expected[i].first, 1e-9) << i;
    EXPECT_NEAR(cuts[i].z, expected[i].second, 1e-9) << i;
  }
  int arcs = 0;
  for (const MotionCall& m : t.calls) arcs += m.line == 4 && m.kind == MoveKind::Arc;
  EXPECT_EQ(arcs, 1);  // only the last pass follows the arc
}

TEST(StockRemoval, G70FinishesAlongTheProfileAndReturns) {
  const CycleRun t(std::string(kG71) + "G70 P10 Q20\nG00 X100. Z100.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  expectPath(t, 10, {{R, 30, 2}, {L, 30, -20}, {L, 40, -20}, {L, 40, -40}, {L, 50, -40}, {R, 50, 2}});
  // At 100 mm/min: 22 + 5 + 20 + 5 = 52 mm of profile (radius steps) in 31.2 s.
  double feedTime = 0.0;
  for (const Move& m : t.moves)
    if (m.line == 10 && m.kind == L) feedTime += m.tEnd - m.tStart;
  EXPECT_NEAR(feedTime, 31.2, 1e-9);
}

TEST(StockRemoval, G70UnderG42CompensatesTheProfile) {
  // Offset 01: R0.8, tip 3. The approach G42 G00 X50 Z2 starts compensation;
  // along the Z line at X30 the imaginary tip stays on X30, and the inside
  // corner at X30 Z-20 stays on the programmed corner (as g42_nose_comp_right).
  const CycleRun t(
      "G98 G97 S500 M03 T0101\n"
      "G00 X100. Z50.\n"
      "G42 G00 X50. Z2.\n"
      "G70 P10 Q20\n"
      "G40 G00 X100. Z50.\n"
      "N10 G00 X30.\n"
      "G01 Z-20. F80.\n"
      "X40.\n"
      "Z-40.\n"
      "N20 X50.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  bool sawZLine = false;
  for (const Move& m : t.moves) {
    if (m.line != 4) continue;
    EXPECT_TRUE(m.compensated);
    if (m.kind == L && std::abs(zOf(m.path.end) + 20.0) < 1e-6 && std::abs(xOf(m.path.end) - 15.0) < 1e-6) {
      sawZLine = true;
      EXPECT_NEAR(xOf(m.path.start), 15.0, 1e-6);
      EXPECT_NEAR(m.feed, 80.0, 1e-9);  // F inside the profile applies under G70
    }
  }
  EXPECT_TRUE(sawZLine);
}

TEST(StockRemoval, FSAndTInTheProfileApplyUnderG70Only) {
  // N10 carries S800 and T0202 (offset 02: X +0.4 diameter, Z -0.2), the next block F80.
  // G71 roughs at the cycle's F100 and S500 without the offset; G70 turns at
  // 800 rpm, cuts the Z line at 80 mm/min and moves the controlled point by
  // the offset from its first move on: X30.4 Z-20.2 at the end of the Z line.
  const CycleRun t(
      "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F100.\n"
      "N10 G00 X30. S800 T0202\nG01 Z-20. F80.\nX40.\nZ-40.\nN20 X50.\nG70 P10 Q20\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  for (const Move& m : t.moves) {
    if (m.line == 4) {
      EXPECT_DOUBLE_EQ(m.rpm, 500.0);
      if (m.kind == L) {
        EXPECT_DOUBLE_EQ(m.feed, 100.0);
      }
    }
    if (m.line == 10) {
      EXPECT_DOUBLE_EQ(m.rpm, 800.0);
    }
  }
  const auto g70 = pathOf(t, 10);
  ASSERT_GE(g70.size(), 2u);
  EXPECT_NEAR(g70[1].x, 30.4, 1e-9);
  EXPECT_NEAR(g70[1].z, -20.2, 1e-9);
  bool sawFeed80 = false;
  for (const Move& m : t.moves) sawFeed80 = sawFeed80 || (m.line == 10 && m.kind == L && m.feed == 80.0);
  EXPECT_TRUE(sawFeed80);
}

TEST(StockRemoval, G71UnderG42RaisesA123InTheClassicRules) {
  RunOptions classic;
  classic.dialect = gcode::Dialect::Classic;
  const Timeline t = runText("G98 G97 S500 M03 T0101\nG42 G00 X50. Z2.\nG71 U2. R0.5\n", classic);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A123");
  EXPECT_EQ(t.alarm->range.line, 3);
}

// G42 written before G71 and cancelled after G70, as many shops write it: a Fanuc runs it (no
// manual found says it stops). The roughing passes run on the programmed shape (W134, once), the
// G70 pass is compensated, and the run goes on to its end.
TEST(StockRemoval, G71UnderG42RunsOnAFanucWithOneWarning) {
  const std::string text =
      "G21 G99\n"                      // 1
      "T0101\n"                        // 2  offset 01: R0.8, tip 3
      "G97 S1000 M03\n"                // 3
      "G00 G42 X50. Z2.\n"             // 4
      "G71 U2. R0.5\n"                 // 5
      "G71 P10 Q20 U0.4 W0.1 F0.25\n"  // 6
      "N10 G00 X30.\n"                 // 7
      "G01 Z-20. F0.1\n"               // 8
      "X40. Z-25.\n"                   // 9
      "N20 X50.\n"                     // 10
      "G70 P10 Q20\n"                  // 11
      "G40 G00 X100. Z50.\n"           // 12
      "G00 G42 X50. Z-30.\n"           // 13  a single cycle under G42 too
      "G90 X46. Z-40. F0.2\n"          // 14
      "G40 G00 X100. Z50.\n"           // 15
      "M30\n";                         // 16
  const Timeline t = runText(text);
  EXPECT_FALSE(t.alarm) << t.alarm->code;
  std::vector<const Diagnostic*> w134;
  for (const Diagnostic& d : t.flow.notices)
    if (d.code == "W134") w134.push_back(&d);
  ASSERT_EQ(w134.size(), 1u);
  EXPECT_EQ(w134[0]->range.line, 5);
  EXPECT_EQ(w134[0]->args, (std::vector<std::string>{"G71"}));
  // The roughing passes: the last one along the shape plus U0.4, uncompensated, down to Z-20 + W0.1.
  double smallest = 1e9;
  for (const Move& m : t.moves)
    if (m.line == 6 && m.kind == MoveKind::Line) {
      EXPECT_FALSE(m.compensated);
      smallest = std::min(smallest, 2.0 * std::min(xOf(m.path.start), xOf(m.path.end)));
    }
  EXPECT_NEAR(smallest, 30.4, 1e-9);
  // G70's pass (its moves carry its line) is compensated: along Z at X30 (tip 3 on a Z-parallel line:
  // the imaginary tip stays on the line) to the taper's start, Z-20.
  bool finished = false;
  for (const Move& m : t.moves)
    if (m.line == 11 && m.kind == MoveKind::Line) {
      EXPECT_TRUE(m.compensated);
      if (std::abs(zOf(m.path.end) - zOf(m.path.start)) > 10.0) {
        EXPECT_NEAR(2.0 * xOf(m.path.start), 30.0, 1e-9);
        EXPECT_NEAR(2.0 * xOf(m.path.end), 30.0, 1e-9);
        finished = true;
      }
    }
  EXPECT_TRUE(finished);
  // The G90 under G42 runs too: its cut along Z at X46 to Z-40, not compensated; no second W134.
  bool turned = false;
  for (const Move& m : t.moves)
    if (m.line == 14 && m.kind == MoveKind::Line && std::abs(zOf(m.path.end) + 40.0) < 1e-9 &&
        std::abs(xOf(m.path.end) - xOf(m.path.start)) < 1e-9) {
      EXPECT_FALSE(m.compensated);
      EXPECT_NEAR(2.0 * xOf(m.path.end), 46.0, 1e-9);
      turned = true;
    }
  EXPECT_TRUE(turned);
  EXPECT_EQ(t.snapshots.back().line, 16);  // to the end
}

TEST(StockRemoval, G71WithAMissingProfileRaisesA120AtP) {
  const CycleRun t("G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F100.\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A120");
  EXPECT_EQ(t.alarm->range.line, 4);
  EXPECT_EQ(t.alarm->range.column, 5);
}

TEST(StockRemoval, G71WithoutDepthRaisesA122) {
  const CycleRun t("G98 G97 S500 M03\nG00 X50. Z2.\nG71 P10 Q20 U0.4 W0.1 F100.\nN10 G00 X30.\nN20 G01 Z-20.\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A122");
  EXPECT_EQ(t.alarm->range.line, 3);
}

// The run of `text` stops with alarm `code` on `line`.
void expectAlarm(std::string_view text, const char* code, int line) {
  const CycleRun t(text);
  ASSERT_TRUE(t.alarm) << text;
  EXPECT_EQ(t.alarm->code, code) << text;
  EXPECT_EQ(t.alarm->range.line, line) << text;
}

TEST(StockRemoval, G71ProfileThatTurnsBackRaisesA121OnItsBlock) {
  // X30 -> Z-20 -> X40 -> Z-30 -> X36: the last block goes back down in X.
  expectAlarm(
      "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F100.\n"
      "N10 G00 X30.\nG01 Z-20.\nX40.\nZ-30.\nN20 X36.\n",
      "A121", 9);
}

// ---- G71 type II (pockets) -------------------------------------------------------

// Fanuc 0i-TF: a first profile block naming X and Z (here W0, the shop habit)
// makes a type II profile: it must move one way in Z but may dip into pockets.
// A = X50 Z2, U2 R0.5, no allowance. Profile X40 Z2 -> Z-10 -> X30 -> Z-20 ->
// X40 -> Z-30 -> X50: a Ø30 pocket from Z-10 to Z-20. Deepest point Ø30, so the
// levels are 46, 42, 38, 34. At 46 and 42 the whole profile lies below: one pass
// from Z2 to the X50 face at Z-30 as in type I. At 38 and 34 only the pocket
// does (the Ø40 lands are above): rapid up to X50, along to Z-10, down to the
// previous level + U + R (38 + 4 + 1 = 43; 34 + 5 = 39), feed to the level and
// along to Z-20, retract 0.5 at 45 degrees, up to X50 and back to Z2. Then the
// last pass along the profile.
TEST(StockRemoval, G71TypeIIRoughsAPocketLevelByLevel) {
  const CycleRun t(
      "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 F100.\n"
      "N10 G00 X40. W0.\nG01 Z-10.\nX30.\nZ-20.\nX40.\nZ-30.\nN20 X50.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  expectPath(t, 4,
             {{R, 46, 2},     {L, 46, -30}, {R, 47, -29.5}, {R, 47, 2},   {R, 42, 2},   {L, 42, -30}, {R, 43, -29.5},
              {R, 43, 2},     {R, 50, 2},   {R, 50, -10},   {R, 43, -10}, {L, 38, -10}, {L, 38, -20}, {R, 39, -19.5},
              {R, 50, -19.5}, {R, 50, 2},   {R, 50, -10},   {R, 39, -10}, {L, 34, -10}, {L, 34, -20}, {R, 35, -19.5},
              {R, 50, -19.5}, {R, 50, 2},   {R, 40, 2},     {L, 40, -10}, {L, 30, -10}, {L, 30, -20}, {L, 40, -20},
              {L, 40, -30},   {L, 50, -30}, {R, 50, 2}});
  // The same profile as type I (X only in its first block) turns back in X: A121 at the X40 block.
  expectAlarm(
      "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 F100.\n"
      "N10 G00 X40.\nG01 Z-10.\nX30.\nZ-20.\nX40.\nZ-30.\nN20 X50.\n",
      "A121", 7);
  // Type II still needs Z one way: a profile that turns back in Z is A121.
  expectAlarm(
      "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 F100.\n"
      "N10 G00 X40. Z2.\nG01 Z-10.\nX30. Z-5.\nN20 X50.\n",
      "A121", 7);
}

// A round-bottomed pocket: G02 X24 Z-30 R15 from X24 Z-10 dips to
// 12 - (15 - sqrt(15^2 - 10^2)) = 8.1803 (radius). The cut part after G70 has
// the pocket's bottom at Ø16.361 at Z-20 and Ø24 either side; nothing was removed
// below the profile by the roughing (every pass ends on the arc).
TEST(StockRemoval, G71TypeIIFollowsAnArcPocketAndG70FinishesIt) {
  const CycleRun t(
      "G98 G97 S500 M03\nG00 X42. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 F100.\n"
      "N10 G00 X24. Z2.\nG01 Z-10.\nG02 X24. Z-30. R15.\nG01 Z-40.\nN20 X42.\nG70 P10 Q20\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  const double bottom = 12.0 - (15.0 - std::sqrt(125.0));
  // Every roughing pass (a Z line of line 4 below X42) ends on the arc moved up by 0.2,
  // or on the Ø24.4 lands: never below the profile plus the allowance.
  int pocketPasses = 0;
  for (const MotionCall& m : t.calls) {
    if (m.line != 4 || m.kind != L || std::abs(xOf(m.path.start) - xOf(m.path.end)) > 1e-9) continue;
    const double r = xOf(m.path.end), z = zOf(m.path.end);
    EXPECT_GE(r, bottom + 0.2 - 1e-6) << z;
    if (z < -10.0 && z > -30.0) {
      ++pocketPasses;
      // Ends on the arc moved up by the allowance (U0.4: +0.2 in X, as the control shifts
      // the profile): centre Z-20 X(12 + sqrt(125) + 0.2), radius 15.
      const double dz = z + 20.0, dx = r - (12.0 + std::sqrt(125.0) + 0.2);
      EXPECT_NEAR(std::hypot(dz, dx), 15.0, 1e-6) << z;
    }
  }
  EXPECT_GE(pocketPasses, 2);
  // G70 runs the arc itself: through the bottom at Z-20.
  bool sawArc = false;
  for (const MotionCall& m : t.calls)
    if (m.line == 10 && m.kind == MoveKind::Arc) {
      sawArc = true;
      EXPECT_NEAR(m.path.radius(), 15.0, 1e-9);
      EXPECT_NEAR(xOf(m.path.centre) - m.path.radius(), bottom, 1e-9);
    }
  EXPECT_TRUE(sawArc);
}

// Twenty 1 mm pockets 5 mm deep (radius) and U0.002: 2,499 levels, each cutting
// most pockets - over 200,000 moves, refused with A149 before they are made.
TEST(StockRemoval, G71TypeIIBoundsItsMovesNotOnlyItsPasses) {
  std::string text = "G98 G97 S500 M03\nG00 X52. Z2.\nG71 U0.002 R0.5\nG71 P10 Q20 F100.\nN10 G00 X50. W0.\n";
  for (int k = 0; k < 20; ++k) {
    const double z = -2.0 * k;
    text += fmt::format("G01 Z{:.1f}\nX40.\nZ{:.1f}\nX50.\n", z - 1.0, z - 2.0);
  }
  text += "N20 X52.\n";
  const CycleRun t(text);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A149");
  EXPECT_EQ(t.alarm->range.line, 4);
  EXPECT_TRUE(pathOf(t, 4).empty());
}

// ---- G72 -----------------------------------------------------------------------

TEST(StockRemoval, G72RoughsAlongXThreePassesThenTheOffsetProfile) {
  // A = X52 Z2, W2 per pass, R0.5, U0.4 W0.2. Profile: A' = Z-6 (Z only),
  // X30, Z-2, X10, Z2. Offset by (X +0.4, Z +0.2): Z-5.8, X30.4, Z-1.8, X10.4, Z2.2.
  // Levels Z 2 - 2k above Z-5.8: Z0, Z-2, Z-4. Z0 meets the offset profile on
  // its X10.4 step; Z-2 and Z-4 on its X30.4 step. Retract X +1, Z +0.5.
  const CycleRun t(
      "G98 G97 S500 M03\nG00 X52. Z2.\nG72 W2. R0.5\nG72 P10 Q20 U0.4 W0.2 F100.\n"
      "N10 G00 Z-6.\nG01 X30.\nZ-2.\nX10.\nN20 Z2.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  expectPath(t, 4,
             {{R, 52, 0},
              {L, 10.4, 0},
              {R, 11.4, 0.5},
              {R, 52, 0.5},
              {R, 52, -2},
              {L, 30.4, -2},
              {R, 31.4, -1.5},
              {R, 52, -1.5},
              {R, 52, -4},
              {L, 30.4, -4},
              {R, 31.4, -3.5},
              {R, 52, -3.5},
              {R, 52.4, -5.8},
              {L, 30.4, -5.8},
              {L, 30.4, -1.8},
              {L, 10.4, -1.8},
              {L, 10.4, 2.2},
              {R, 52, 2}});
}

// ---- G73 -----------------------------------------------------------------------

TEST(PatternRepeating, G73ThreePassesWithTheReliefShrinking) {
  // U3 (X relief, radius) W1 R3: the offsets are the allowance (X +0.4 dia,
  // Z +0.1) plus 1, 1/2, 0 of the relief: (X +6.4, Z +1.1), (X +3.4, Z +0.6), (X +0.4, Z +0.1).
  const CycleRun t(
      "G98 G97 S500 M03\nG00 X50. Z2.\nG73 U3. W1. R3\nG73 P10 Q20 U0.4 W0.1 F100.\n"
      "N10 G00 X30.\nG01 Z-20.\nN20 X50.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  expectPath(t, 4,
             {{R, 36.4, 3.1},
              {L, 36.4, -18.9},
              {L, 56.4, -18.9},
              {R, 50, 2},
              {R, 33.4, 2.6},
              {L, 33.4, -19.4},
              {L, 53.4, -19.4},
              {R, 50, 2},
              {R, 30.4, 2.1},
              {L, 30.4, -19.9},
              {L, 50.4, -19.9},
              {R, 50, 2}});
}

// ---- G74 / G75 -------------------------------------------------------------------

TEST(PeckCycles, G74DrillsInPecksOfQWithRetractR) {
  // Q4000 = 4 mm pecks to Z-10 from Z2: bottoms Z-2, Z-6, Z-10, backing off 1 mm.
  const CycleRun t("G98 G97 S500 M03\nG00 X0. Z2.\nG74 R1.\nG74 Z-10. Q4000 F100.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  expectPath(t, 4, {{L, 0, -2}, {R, 0, -1}, {L, 0, -6}, {R, 0, -5}, {L, 0, -10}, {R, 0, 2}});
}

TEST(PeckCycles, G75GroovesWithPecksInXAndStepsInZ) {
  // From X42 Z-20 to X30 Z-24: P3000 = 3 mm pecks (radius) X36, X30 with a
  // 0.5 mm back-off (X37); Q2000 = Z steps of 2 mm: Z-20, Z-22, Z-24.
  const CycleRun t("G98 G97 S500 M03\nG00 X42. Z-20.\nG75 R0.5\nG75 X30. Z-24. P3000 Q2000 F100.\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  std::vector<Corner> expected;
  for (double z : {-20.0, -22.0, -24.0}) {
    if (z != -20.0) expected.push_back({R, 42, z});
    expected.insert(expected.end(), {{L, 36, z}, {R, 37, z}, {L, 30, z}, {R, 42, z}});
  }
  expected.push_back({R, 42, -20});
  expectPath(t, 4, expected);
}

// ---- G76 -------------------------------------------------------------------------

TEST(Threading, G76DepthsFollowTheSquareRootThenFinish) {
  // k = 0.92, Δd = 0.3, d = 0.05, m = 2: 0.3·√n up to k - d = 0.87:
  // 0.3, 0.42426, 0.51962, 0.6, 0.67082, 0.73485, 0.79373, 0.84853, then 0.87,
  // then two passes at 0.92.
  const auto d = cycles::threadDepths(0.92, 0.3, 0.05, 0.05, 2);
  // clang-format off: one row per pass, as the manual draws them
  const std::vector<double> expected = {0.3,
                                        0.3 * std::sqrt(2.0),
                                        0.3 * std::sqrt(3.0),
                                        0.6,
                                        0.3 * std::sqrt(5.0),
                                        0.3 * std::sqrt(6.0),
                                        0.3 * std::sqrt(7.0),
                                        0.3 * std::sqrt(8.0),
                                        0.87,
                                        0.92,
                                        0.92};
  // clang-format on
  ASSERT_EQ(d.size(), expected.size());
  for (std::size_t i = 0; i < d.size(); ++i) EXPECT_NEAR(d[i], expected[i], 1e-12) << i;
}

TEST(Threading, G76MinimumDepthClampsTheIncrements) {
  // Δdmin 0.1: 0.3, 0.42426 (+0.124), then 0.3·√3 = 0.5196 is only +0.095 ->
  // 0.52426, 0.62426, 0.72426, 0.82426, then 0.92426 > k - d -> 0.87; m = 1.
  const auto d = cycles::threadDepths(0.92, 0.3, 0.1, 0.05, 1);
  const double s2 = 0.3 * std::sqrt(2.0);
  const std::vector<double> expected = {0.3, s2, s2 + 0.1, s2 + 0.2, s2 + 0.3, s2 + 0.4, 0.87, 0.92};
  ASSERT_EQ(d.size(), expected.size());
  for (std::size_t i = 0; i < d.size(); ++i) EXPECT_NEAR(d[i], expected[i], 1e-12) << i;
}

TEST(Threading, G76PassesRunAtTheRootPlusTheDepthLeftWithFlankInfeed) {
  const CycleRun t("G97 S500 M03\nG00 X35. Z5.\nG76 P020060 Q50 R0.05\nG76 X28.16 Z-20. P920 Q300 F1.5\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  const auto d = cycles::threadDepths(0.92, 0.3, 0.05, 0.05, 2);
  std::vector<const Move*> threads;
  for (const Move& m : t.moves)
    if (m.line == 4 && m.kind == T) threads.push_back(&m);
  ASSERT_EQ(threads.size(), 11u);
  const double flank = std::tan(std::numbers::pi / 6.0);  // a = 60: tan 30
  for (std::size_t i = 0; i < threads.size(); ++i) {
    // Diameter = root 28.16 + 2 (k - depth); start Z5 moved -depth·tan 30 along the thread.
    EXPECT_NEAR(2.0 * xOf(threads[i]->path.start), 28.16 + 2.0 * (0.92 - d[i]), 1e-9) << i;
    EXPECT_NEAR(zOf(threads[i]->path.start), 5.0 - d[i] * flank, 1e-9) << i;
    EXPECT_NEAR(zOf(threads[i]->path.end), -20.0, 1e-9);
    EXPECT_DOUBLE_EQ(threads[i]->lead, 1.5);
  }
  EXPECT_NEAR(2.0 * xOf(threads.front()->path.start), 29.4, 1e-9);  // 28.16 + 2·0.62
  // Back at the start point after the cycle.
  EXPECT_POINT(t.moves.back().path.end, 35.0, 5.0);
}

TEST(Threading, G76ChamferPullsOutAt45DegreesOverRTenthsOfALead) {
  // P021060: m = 2, r = 10 -> 1.0 lead = 1.5 mm. The first pass (X29.4)
  // threads to Z-18.5, then, still threading, out to X29.4 + 2·1.5 = X32.4 at Z-20.
  const CycleRun t("G97 S500 M03\nG00 X35. Z5.\nG76 P021060 Q50 R0.05\nG76 X28.16 Z-20. P920 Q300 F1.5\n");
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  const auto p = pathOf(t, 4);
  ASSERT_GE(p.size(), 6u);
  // Rapid to Z5 - 0.3 tan 30, rapid in to X29.4, thread, thread out, rapid out, rapid back.
  EXPECT_EQ(p[2].kind, T);
  EXPECT_NEAR(p[2].x, 29.4, 1e-9);
  EXPECT_NEAR(p[2].z, -18.5, 1e-9);
  EXPECT_EQ(p[3].kind, T);
  EXPECT_NEAR(p[3].x, 32.4, 1e-9);
  EXPECT_NEAR(p[3].z, -20.0, 1e-9);
  EXPECT_EQ(p[4].kind, R);
  EXPECT_NEAR(p[4].x, 35.0, 1e-9);
}

// Fanuc 0i-TF operator's manual, constant surface speed control: it stays effective
// during threading (G97 is recommended); the control runs the thread. One warning.
TEST(Threading, G76UnderG96WarnsOnceAndThreads) {
  const Timeline t = interpret(gcode::parse("G96 S100 M03\nG00 X35. Z5.\nG76 P010060 Q50 R0.05\n"
                                            "G76 X28.16 Z-20. P920 Q300 F1.5\nG76 X28.16 Z-20. P920 Q300 F1.5\n",
                                            1),
                               testing::testSetup(), RunOptions{});
  EXPECT_FALSE(t.alarm);
  ASSERT_EQ(t.flow.notices.size(), 1u);
  EXPECT_EQ(t.flow.notices[0].code, "W131");
  EXPECT_EQ(t.flow.notices[0].range.line, 4);
  EXPECT_TRUE(std::any_of(t.moves.begin(), t.moves.end(), [](const Move& m) { return m.kind == MoveKind::Thread; }));
}

TEST(Threading, G76UnderG96RaisesA108OnTheClassicTrainer) {
  RunOptions classic;
  classic.dialect = gcode::Dialect::Classic;
  const Timeline t =
      interpret(gcode::parse("G96 S100 M03\nG00 X35. Z5.\nG32 Z-10. F1.5\n", 1), testing::testSetup(), classic);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A108");
  EXPECT_EQ(t.alarm->range.line, 3);
}

// ---- the sample ----------------------------------------------------------------

struct SampleRun {
  gcode::Program program;
  Timeline timeline;
  int lineOf(int n) const {  // file line of block N<n>
    for (const gcode::Block& b : program.blocks)
      if (const gcode::Word* w = b.find('N'); w && w->code() == n) return b.line;
    return -1;
  }
};

SampleRun runFile(const std::string& path) {
  SampleRun r;
  const auto file = io::readProgramFile(path);
  EXPECT_TRUE(file.ok()) << path;
  if (!file.value) return r;
  r.program = gcode::parse(file.value->gcode, file.value->gcodeFirstLine);
  for (const Diagnostic& d : gcode::check(r.program))
    EXPECT_NE(d.severity, Severity::Error) << d.code << " at line " << d.range.line;
  r.timeline = interpret(r.program, testing::testSetup());
  return r;
}

// Sample 01's finished contour (radius at z), 0 > z > -60: Ø24 at Z0 with a
// 3x45 chamfer to Ø30, Ø30 to Z-20, Ø36 then the R2 corner (centre Z-22 x18)
// to Ø40, Ø40 to Z-40, Ø44 then a 1x45 chamfer to Ø46, Ø46 to Z-60.
double contourRadius(double z) {
  if (z > -3.0) return 12.0 - z;
  if (z > -20.0) return 15.0;
  if (z > -22.0) return 18.0 + std::sqrt(std::max(0.0, 4.0 - (z + 22.0) * (z + 22.0)));
  if (z > -40.0) return 20.0;
  if (z > -41.0) return 22.0 + (-40.0 - z);
  return 23.0;
}

TEST(Samples, CannedCycleSampleRoughsAndFinishesLikeSample01) {
  const SampleRun s06 = runFile(std::string(KLUENG_SOURCE_DIR) + "/resources/samples/06-canned-cycles.txt");
  const SampleRun s01 = runFile(std::string(KLUENG_SAMPLES_DIR) + "/01-step-shaft.txt");
  const Timeline& t = s06.timeline;
  ASSERT_FALSE(t.alarm) << t.alarm->code << " at line " << t.alarm->range.line;
  ASSERT_FALSE(s01.timeline.alarm);

  // G70 (N240) under G42 cuts exactly sample 01's compensated finishing path
  // N340..N430: the same feed moves, point for point. (`klueng-cli simulate
  // --profile` of both samples gives the same finished diameters outside the thread.)
  std::vector<const Move*> finish06, finish01;
  for (const Move& m : t.moves)
    if (m.line == s06.lineOf(240) && m.kind != MoveKind::Rapid) finish06.push_back(&m);
  for (const Move& m : s01.timeline.moves)
    if (m.line >= s01.lineOf(340) && m.line <= s01.lineOf(430) && m.kind != MoveKind::Rapid) finish01.push_back(&m);
  ASSERT_EQ(finish06.size(), finish01.size());
  ASSERT_EQ(finish06.size(), 10u);  // N340..N430: ten blocks, one move each
  for (std::size_t i = 0; i < finish06.size(); ++i) {
    EXPECT_EQ(finish06[i]->kind, finish01[i]->kind) << i;
    EXPECT_TRUE(finish06[i]->compensated) << i;
    // Only the compensated ends differ: the start-up (G42 on a different
    // approach) and the last move's end (G70 goes on to its rapid back to A).
    if (i > 0) {
      EXPECT_LT((finish06[i]->path.start - finish01[i]->path.start).norm(), 1e-9) << i;
    }
    if (i + 1 < finish06.size()) {
      EXPECT_LT((finish06[i]->path.end - finish01[i]->path.end).norm(), 1e-9) << i;
    }
    if (finish06[i]->path.isArc()) {
      EXPECT_LT((finish06[i]->path.centre - finish01[i]->path.centre).norm(), 1e-9) << i;
    }
  }

  // G71 (N100), U1.5 from Ø50: levels Ø47 44 41 38 35 32 29 26 above the
  // offset A' (Ø24.4): 8 roughing passes along Z from Z2. No roughing feed
  // move goes inside the contour offset by U0.4 (0.2 per side) and W0.1.
  const int g71 = s06.lineOf(100);
  int passes = 0;
  for (const Move& m : t.moves) {
    if (m.line != g71 || m.kind == MoveKind::Rapid) continue;
    if (std::abs(zOf(m.path.start) - 2.0) < 1e-9 && std::abs(xOf(m.path.start) - xOf(m.path.end)) < 1e-9) ++passes;
    for (double f : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const Vec2 p = m.path.pointAt(f);
      const double z = zOf(p) - 0.1;  // back onto the unshifted contour
      if (z > 0.0 || z < -60.0) continue;
      const double floor = std::min(contourRadius(z - 1e-6), contourRadius(z + 1e-6)) + 0.2;
      EXPECT_GE(xOf(p), floor - 1e-6) << "at Z" << zOf(p) << " X" << 2.0 * xOf(p);
    }
  }
  EXPECT_EQ(passes, 8);

  // G76 (N300): 11 thread passes (as G76PassesRun...), the last at the root Ø28.16.
  std::vector<const Move*> threads;
  for (const Move& m : t.moves)
    if (m.kind == MoveKind::Thread) threads.push_back(&m);
  ASSERT_EQ(threads.size(), 11u);
  EXPECT_EQ(threads.back()->line, s06.lineOf(300));
  EXPECT_NEAR(2.0 * xOf(threads.back()->path.end), 28.16, 1e-9);
  EXPECT_NEAR(zOf(threads.back()->path.end), -15.0, 1e-9);
}

// Found by fuzz_macro (issue 13): a G83 repeated thousands of times over
// thousands of pecks asked for 2.4 GB of moves. Here the R point is the initial
// level Z2 (Fanuc R0: no distance), so the hole is 50 mm deep: 5,000 pecks of
// 0.01 mm (Q10, least increments); 3500 x (3 x 5000 + 3) = 52,510,500 moves:
// A149 at K (column 23) before anything is allocated.
TEST(PeckCycles, ADrillingCycleOfMillionsOfMovesIsRefusedAtItsRepeatCount) {
  const CycleRun t("G98 G97 S500 M03\nG00 X0. Z2.\nG83 X0. Z-48. R0. Q10 K3500 F50.\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A149");
  EXPECT_EQ(t.alarm->range.line, 3);
  EXPECT_EQ(t.alarm->range.column, 23);
  EXPECT_EQ(t.alarm->args.at(1), "52510500");
  EXPECT_TRUE(t.moves.size() < 10u);
}

// Found by fuzz_pipeline (issue 13): a negative T inside a G71 profile (the check
// refuses it with E118; the interpreter runs what it is given) threw out of the
// offset table's at(-2). It names no offset: the profile keeps the one in force.
TEST(CycleProfile, ANegativeTInTheProfileNamesNoOffset) {
  const Timeline t = testing::runText(
      "G21 G99\nT0101\nG97 S500 M03\nG00 X52. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\n"
      "N10 G00 X30. T-101\nG01 Z-20.\nN20 X52.\nM30\n");
  ASSERT_FALSE(t.moves.empty());
  for (const Move& m : t.moves) EXPECT_TRUE(std::isfinite(m.path.end.x()) && std::isfinite(m.path.end.y()));
}

}  // namespace
}  // namespace klueng::core::machine

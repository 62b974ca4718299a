// Haas one-block cycles and the G81-G83 drilling cycles of both controls,
// through the whole interpreter. Expected points are derived by hand in the
// comments, in the program's units (inch for Haas), as diameters.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/machine/interpreter.h"
#include "test_support.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace klueng::core::machine::haas_cycles_test {
namespace {

using gcode::Dialect;

class RecordingSink final : public MachineSink {
 public:
  std::vector<MotionCall> calls;
  std::vector<DwellCall> dwells;
  void motion(const MotionCall& m) override { calls.push_back(m); }
  void dwell(const DwellCall& d) override { dwells.push_back(d); }
  void setPosition(const Vec2&) override {}
  void compensation(NoseCompMode, double, int) override {}
  void blockDone(const StateSnapshot&) override {}
  void alarm(const Diagnostic& d) override { alarms.push_back(d); }
  void end() override {}
  bool halted() const override { return !alarms.empty(); }
  std::vector<Diagnostic> alarms;
};

struct Corner {
  MoveKind kind;
  double x;  // diameter, program units
  double z;
};

constexpr MoveKind R = MoveKind::Rapid;
constexpr MoveKind L = MoveKind::Line;
constexpr MoveKind T = MoveKind::Thread;

struct CycleRun {
  CycleRun(std::string_view text, Dialect dialect) {
    RunOptions o;
    o.dialect = dialect;
    timeline = testing::runText(text, o);
    run(gcode::parse(text, 1), testing::testSetup(), o, sink);
  }
  // The moves of a line as programmed (before the timeline splits rapids), in `unit` per mm.
  std::vector<Corner> path(int line, double unit) const {
    std::vector<Corner> out;
    for (const MotionCall& m : sink.calls)
      if (m.line == line) out.push_back({m.kind, 2.0 * xOf(m.path.end) / unit, zOf(m.path.end) / unit});
    return out;
  }
  Timeline timeline;
  RecordingSink sink;
};

constexpr double kInch = 25.4;

void expectPath(const CycleRun& r, int line, double unit, const std::vector<Corner>& expected) {
  const auto got = r.path(line, unit);
  ASSERT_EQ(got.size(), expected.size()) << "moves of line " << line;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(static_cast<int>(got[i].kind), static_cast<int>(expected[i].kind)) << "move " << i;
    EXPECT_NEAR(got[i].x, expected[i].x, 1e-6) << "X of move " << i;
    EXPECT_NEAR(got[i].z, expected[i].z, 1e-6) << "Z of move " << i;
  }
}

// ---- G71 / G70 one-block ---------------------------------------------------------

// Inch (Haas powers on in inch). Start X2.0 Z0.1; profile A' = X1.5, Z-1.,
// X1.8, Z-2., X2.0. U0.02 (0.01 a side) W0.005: the finish profile is
// X1.52 Z0.105 -> Z-0.995 -> X1.82 -> Z-1.995 -> X2.02. D0.05 (radius) gives
// pass diameters 2.0 - 2*0.05*k: X1.9, X1.8, X1.7, X1.6 (the next, X1.5, is
// not above X1.52). X1.9 meets the profile at the Z-1.995 shoulder (above
// X1.82), the others at Z-0.995. Each pass retracts Setting 73 = 0.05 at 45
// degrees (X +0.1 diameter, Z +0.05) and rapids back to Z0.1.
constexpr const char* kHaasG71 =
    "G98 G97 S500 M03\n"                     // 1
    "G00 X2. Z0.1\n"                         // 2
    "G71 P10 Q20 U0.02 W0.005 D0.05 F10.\n"  // 3
    "N10 G00 X1.5\n"                         // 4
    "G01 Z-1.\n"                             // 5
    "X1.8\n"                                 // 6
    "Z-2.\n"                                 // 7
    "N20 X2.\n"                              // 8
    "G70 P10 Q20\n";                         // 9

TEST(HaasG71, PassesAtExactDiametersThenTheFinishAllowanceProfile) {
  const CycleRun r(kHaasG71, Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm) << r.timeline.alarm->code;
  expectPath(r, 3, kInch,
             {{R, 1.9, 0.1},
              {L, 1.9, -1.995},
              {R, 2.0, -1.945},
              {R, 2.0, 0.1},
              {R, 1.8, 0.1},
              {L, 1.8, -0.995},
              {R, 1.9, -0.945},
              {R, 1.9, 0.1},
              {R, 1.7, 0.1},
              {L, 1.7, -0.995},
              {R, 1.8, -0.945},
              {R, 1.8, 0.1},
              {R, 1.6, 0.1},
              {L, 1.6, -0.995},
              {R, 1.7, -0.945},
              {R, 1.7, 0.1},
              // The last roughing pass follows the profile at the finish allowance.
              {R, 1.52, 0.105},
              {L, 1.52, -0.995},
              {L, 1.82, -0.995},
              {L, 1.82, -1.995},
              {L, 2.02, -1.995},
              {R, 2.0, 0.1}});
  // G70 P Q (same in both forms): the profile itself, then back to the start.
  expectPath(r, 9, kInch,
             {{R, 1.5, 0.1}, {L, 1.5, -1.0}, {L, 1.8, -1.0}, {L, 1.8, -2.0}, {L, 2.0, -2.0}, {R, 2.0, 0.1}});
  // The first pass cuts 0.1 - (-1.995) = 2.095 in at F10. in/min: 0.2095 min = 12.57 s.
  bool found = false;
  for (const Move& m : r.timeline.moves)
    if (m.line == 3 && m.kind == L && !found) {
      EXPECT_NEAR(m.tEnd - m.tStart, 12.57, 1e-9);
      found = true;
    }
  EXPECT_TRUE(found);
}

TEST(HaasG71, RoughAllowanceIKStopsThePassesShort) {
  // I0.01 (radius) K0.01 more: the passes stop at X1.54 / X1.84 shoulders moved
  // to Z-0.985 and Z-1.985; the pass levels stay X1.9 .. X1.6 (X1.6 is above X1.54).
  const CycleRun r(
      "G98 G97 S500 M03\nG00 X2. Z0.1\nG71 P10 Q20 U0.02 W0.005 I0.01 K0.01 D0.05 F10.\n"
      "N10 G00 X1.5\nG01 Z-1.\nX1.8\nZ-2.\nN20 X2.\n",
      Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm);
  const auto p = r.path(3, kInch);
  ASSERT_EQ(p.size(), 22u);
  EXPECT_NEAR(p[1].z, -1.985, 1e-6);
  EXPECT_NEAR(p[5].z, -0.985, 1e-6);
  EXPECT_NEAR(p[13].x, 1.6, 1e-6);
  // The last pass still runs at the finish allowance only.
  EXPECT_NEAR(p[16].x, 1.52, 1e-6);
  EXPECT_NEAR(p[17].z, -0.995, 1e-6);
}

TEST(HaasG71, WithoutDTheSetting72DepthApplies) {
  // Setting 72 = 0.1 in: passes X1.8 and X1.6 (X1.4 is not above X1.52).
  const CycleRun r(
      "G98 G97 S500 M03\nG00 X2. Z0.1\nG71 P10 Q20 U0.02 W0.005 F10.\n"
      "N10 G00 X1.5\nG01 Z-1.\nX1.8\nZ-2.\nN20 X2.\n",
      Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm);
  const auto p = r.path(3, kInch);
  ASSERT_EQ(p.size(), 4u * 2 + 6);
  EXPECT_NEAR(p[0].x, 1.8, 1e-6);
  EXPECT_NEAR(p[4].x, 1.6, 1e-6);
}

TEST(HaasG71, APBlockWithXAndZIsAccepted) {
  // Haas type 2 form of a monotonic profile: N10 G00 X1.5 Z0.05.
  const CycleRun r(
      "G98 G97 S500 M03\nG00 X2. Z0.1\nG71 P10 Q20 D0.25 F10.\n"
      "N10 G00 X1.5 Z0.05\nG01 Z-1.\nN20 X2.\n",
      Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm);
  // D0.25: the first level, X2.0 - 0.5 = X1.5, is not above A' X1.5: no roughing pass;
  // the last pass goes to A' (X1.5 Z0.05), along the profile, and back.
  expectPath(r, 3, kInch, {{R, 1.5, 0.05}, {L, 1.5, -1.0}, {L, 2.0, -1.0}, {R, 2.0, 0.1}});
}

// Haas shops end the profile where it reached the start point's X and retract
// along Z over the bar (`X2.` then `N20 G00 Z0.1`): the retract lies wholly at
// the start level, outside the stock, so it cuts nothing. The roughing is that
// of kHaasG71 (levels X1.9 .. X1.6, direction -Z); the last pass follows the
// profile at the allowance and travels the retract too, at X2.02 back to
// Z0.105, then goes to the start. G70 runs the profile as written.
constexpr const char* kHaasG71Retract =
    "G98 G97 S500 M03\n"                     // 1
    "G00 X2. Z0.1\n"                         // 2
    "G71 P10 Q20 U0.02 W0.005 D0.05 F10.\n"  // 3
    "N10 G00 X1.5 Z0.1\n"                    // 4
    "G01 Z-1.\n"                             // 5
    "X1.8\n"                                 // 6
    "Z-2.\n"                                 // 7
    "X2.\n"                                  // 8
    "N20 G00 Z0.1\n"                         // 9
    "G70 P10 Q20\n";                         // 10

TEST(HaasG71, ARetractAtTheStartLevelEndingTheProfileIsTravelledNotChecked) {
  const CycleRun r(kHaasG71Retract, Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm) << r.timeline.alarm->code;
  expectPath(r, 3, kInch, {{R, 1.9, 0.1},     {L, 1.9, -1.995}, {R, 2.0, -1.945},  {R, 2.0, 0.1},     {R, 1.8, 0.1},
                           {L, 1.8, -0.995},  {R, 1.9, -0.945}, {R, 1.9, 0.1},     {R, 1.7, 0.1},     {L, 1.7, -0.995},
                           {R, 1.8, -0.945},  {R, 1.8, 0.1},    {R, 1.6, 0.1},     {L, 1.6, -0.995},  {R, 1.7, -0.945},
                           {R, 1.7, 0.1},     {R, 1.52, 0.105}, {L, 1.52, -0.995}, {L, 1.82, -0.995}, {L, 1.82, -1.995},
                           {L, 2.02, -1.995}, {R, 2.02, 0.105}, {R, 2.0, 0.1}});
  expectPath(
      r, 10, kInch,
      {{R, 1.5, 0.1}, {L, 1.5, -1.0}, {L, 1.8, -1.0}, {L, 1.8, -2.0}, {L, 2.0, -2.0}, {R, 2.0, 0.1}, {R, 2.0, 0.1}});
}

TEST(HaasG71, APieceBelowTheStartLevelAfterTheRetractStillCounts) {
  // Only the end of the profile may lie outside: X1.9 after the retract comes
  // back below the start's X2.0 and turns back in X (A121 on its block).
  const CycleRun r(
      "G98 G97 S500 M03\nG00 X2. Z0.1\nG71 P10 Q20 D0.05 F10.\n"
      "N10 G00 X1.5\nG01 Z-1.\nX2.\nZ-0.5\nN20 X1.9\n",
      Dialect::Haas);
  ASSERT_TRUE(r.timeline.alarm);
  EXPECT_EQ(r.timeline.alarm->code, "A121");
  EXPECT_EQ(r.timeline.alarm->range.line, 7);
}

TEST(FanucG71, ARetractEndingTheProfileIsNotMonotonic) {
  // Fanuc 0i-TF wants the whole shape A'..B monotonic (docs/haas-cycles.md):
  // the same profile in the two-block form stops with A121 on the retract.
  const CycleRun r(
      "G98 G97 S500 M03\nG00 X2. Z0.1\nG71 U0.05 R0.05\nG71 P10 Q20 U0.02 W0.005 F10.\n"
      "N10 G00 X1.5 Z0.1\nG01 Z-1.\nX1.8\nZ-2.\nX2.\nN20 G00 Z0.1\n",
      Dialect::Fanuc);
  ASSERT_TRUE(r.timeline.alarm);
  EXPECT_EQ(r.timeline.alarm->code, "A121");
  EXPECT_EQ(r.timeline.alarm->range.line, 10);
}

TEST(FanucG71, OneBlockFormIsNotReadInFanuc) {
  // In Fanuc the same block is the second block of the two-block form and
  // needs the first block's depth: A122.
  const CycleRun r(kHaasG71, Dialect::Fanuc);
  ASSERT_TRUE(r.timeline.alarm);
  EXPECT_EQ(r.timeline.alarm->code, "A122");
}

// ---- G72 one-block ------------------------------------------------------------------

TEST(HaasG72, FacingPassesDAlongZ) {
  // Start X2.2 Z0.1; profile N10 Z-0.3 (A'), X1.0, Z0. ... facing from the
  // outside: A' = Z-0.3; passes at Z 0.1 - 0.1k while above Z-0.3: Z0, Z-0.1,
  // Z-0.2; each cuts from X2.2 to the profile at X1.0 (no allowance), retracts
  // 0.05 at 45 degrees (Z +0.05, X +0.1 diameter) and rapids back to X2.2.
  const CycleRun r(
      "G98 G97 S500 M03\nG00 X2.2 Z0.1\nG72 P10 Q20 D0.1 F10.\n"
      "N10 G00 Z-0.3\nG01 X1.0\nN20 Z0.1\n",
      Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm) << r.timeline.alarm->code;
  expectPath(r, 3, kInch,
             {{R, 2.2, 0.0},
              {L, 1.0, 0.0},
              {R, 1.1, 0.05},
              {R, 2.2, 0.05},
              {R, 2.2, -0.1},
              {L, 1.0, -0.1},
              {R, 1.1, -0.05},
              {R, 2.2, -0.05},
              {R, 2.2, -0.2},
              {L, 1.0, -0.2},
              {R, 1.1, -0.15},
              {R, 2.2, -0.15},
              {R, 2.2, -0.3},
              {L, 1.0, -0.3},
              {L, 1.0, 0.1},
              {R, 2.2, 0.1}});
}

TEST(HaasG72, ARetractAlongXAtTheStartLevelEndsTheProfile) {
  // The profile of FacingPassesDAlongZ, ending at the start's Z0.1, then
  // `N20 G00 X2.2` back over the face: outside the stock, so the passes are
  // the same; the last pass travels the retract (X2.2 Z0.1 is the start).
  const CycleRun r(
      "G98 G97 S500 M03\nG00 X2.2 Z0.1\nG72 P10 Q20 D0.1 F10.\n"
      "N10 G00 Z-0.3\nG01 X1.0\nZ0.1\nN20 G00 X2.2\n",
      Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm) << r.timeline.alarm->code;
  expectPath(r, 3, kInch,
             {{R, 2.2, 0.0},
              {L, 1.0, 0.0},
              {R, 1.1, 0.05},
              {R, 2.2, 0.05},
              {R, 2.2, -0.1},
              {L, 1.0, -0.1},
              {R, 1.1, -0.05},
              {R, 2.2, -0.05},
              {R, 2.2, -0.2},
              {L, 1.0, -0.2},
              {R, 1.1, -0.15},
              {R, 2.2, -0.15},
              {R, 2.2, -0.3},
              {L, 1.0, -0.3},
              {L, 1.0, 0.1},
              {R, 2.2, 0.1},
              {R, 2.2, 0.1}});
}

// ---- G73 one-block ------------------------------------------------------------------

TEST(HaasG73, DPassesFromTheReliefIKDownToTheProfile) {
  // D3, I0.1 (radius) K0: passes shifted 0.1, 0.05, 0 radius = X +0.2, +0.1, +0 diameter.
  const CycleRun r(
      "G98 G97 S500 M03\nG00 X2. Z0.1\nG73 P10 Q20 I0.1 K0. D3 F10.\n"
      "N10 G01 X1.5 Z0.\nZ-1.\nN20 X2.\n",
      Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm) << r.timeline.alarm->code;
  expectPath(r, 3, kInch,
             {{L, 1.7, 0.0},
              {L, 1.7, -1.0},
              {L, 2.2, -1.0},
              {R, 2.0, 0.1},
              {L, 1.6, 0.0},
              {L, 1.6, -1.0},
              {L, 2.1, -1.0},
              {R, 2.0, 0.1},
              {L, 1.5, 0.0},
              {L, 1.5, -1.0},
              {L, 2.0, -1.0},
              {R, 2.0, 0.1}});
}

// ---- G76 one-block ------------------------------------------------------------------

TEST(HaasG76, DepthsGrowAsDTimesRootNAndEndAtK) {
  // K0.05 D0.02, P1 (default), A0 (radial), Setting 99 = 0.001, Setting 86 = 0:
  // depths 0.02*sqrt(n) = .02, .028284, .034641, .04, .044721, .048990, then
  // .052915 capped at K = .05: 7 passes. Pass diameter = X0.9 + 2*(K - depth).
  const CycleRun r("G97 S500 M03\nG00 X1.1 Z0.2\nG76 X0.9 Z-1. K0.05 D0.02 F0.1\n", Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm) << r.timeline.alarm->code;
  std::vector<double> starts;  // X of each pass's first thread move
  const auto p = r.path(3, kInch);
  for (std::size_t i = 1; i < p.size(); ++i)
    if (p[i].kind == T && p[i - 1].kind == R) starts.push_back(p[i - 1].x);
  const std::vector<double> depths = {
      0.02, 0.02 * std::sqrt(2.0), 0.02 * std::sqrt(3.0), 0.04, 0.02 * std::sqrt(5.0), 0.02 * std::sqrt(6.0), 0.05};
  ASSERT_EQ(starts.size(), depths.size());
  for (std::size_t i = 0; i < depths.size(); ++i) EXPECT_NEAR(starts[i], 0.9 + 2.0 * (0.05 - depths[i]), 1e-6);
  // The last pass: rapid to X0.9, thread to Z-0.9, then the 45-degree chamfer of
  // Setting 95 = 1 lead (0.1) out to X1.1 at Z-1., rapid up to X1.1, back to Z0.2.
  const std::vector<Corner> last(p.end() - 5, p.end());
  const std::vector<Corner> expected = {{R, 0.9, 0.2}, {T, 0.9, -0.9}, {T, 1.1, -1.0}, {R, 1.1, -1.0}, {R, 1.1, 0.2}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(static_cast<int>(last[i].kind), static_cast<int>(expected[i].kind)) << i;
    EXPECT_NEAR(last[i].x, expected[i].x, 1e-6) << i;
    EXPECT_NEAR(last[i].z, expected[i].z, 1e-6) << i;
  }
}

TEST(HaasG76, SingleEdgeInfeedMovesAlongTheFlankByDepthTimesTanHalfA) {
  // A60 P1: the first pass starts 0.02 * tan(30 deg) = 0.011547 before Z0.2 (towards -Z).
  const CycleRun r("G97 S500 M03\nG00 X1.1 Z0.2\nG76 X0.9 Z-1. K0.05 D0.02 A60 P1 F0.1\n", Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm);
  const auto p = r.path(3, kInch);
  ASSERT_FALSE(p.empty());
  EXPECT_NEAR(p[0].z, 0.2 - 0.02 * std::tan(std::numbers::pi / 6.0), 1e-6);
  EXPECT_NEAR(p[0].x, 1.1, 1e-6);
}

TEST(HaasG76, M24TurnsTheChamferOff) {
  // M24 is a Haas code (thread chamfer off, the M23/M24 group): the last pass
  // threads straight to Z-1. and rapids out. The table must know it: a code
  // missing from it is a failure here, never a skip.
  const gcode::CodeInfo* m24 = gcode::findCode('M', 24, Dialect::Haas);
  ASSERT_NE(m24, nullptr) << "M24 is missing from the Haas code table";
  EXPECT_EQ(m24->group, gcode::ModalGroup::MThreadChamfer);
  const CycleRun r("G97 S500 M03 M24\nG00 X1.1 Z0.2\nG76 X0.9 Z-1. K0.05 D0.02 F0.1\n", Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm);
  const auto p = r.path(3, kInch);
  ASSERT_GE(p.size(), 4u);
  EXPECT_EQ(static_cast<int>(p[p.size() - 3].kind), static_cast<int>(T));
  EXPECT_NEAR(p[p.size() - 3].z, -1.0, 1e-6);
  EXPECT_NEAR(p[p.size() - 3].x, 0.9, 1e-6);
}

TEST(HaasG76, P3CutsAConstantDepthPerPass) {
  // P3: depths n*D = .02, .04, then .06 capped at K .05: 3 passes.
  const CycleRun r("G97 S500 M03\nG00 X1.1 Z0.2\nG76 X0.9 Z-1. K0.05 D0.02 P3 F0.1\n", Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm);
  int passes = 0;
  for (const Corner& c : r.path(3, kInch))
    if (c.kind == T && std::abs(c.z + 0.9) < 1e-6) ++passes;
  EXPECT_EQ(passes, 3);
}

// ---- G74 / G75 one-block ----------------------------------------------------------------

TEST(HaasG75, PecksIInXRowsKInZ) {
  // Start X1.5 Z-0.3, groove to X1.0 Z-0.5: I0.1 (radius) pecks = X1.3, X1.1,
  // X1.0 with a Setting 22 = 0.05 (X +0.1) retract between them; rows K0.2 apart.
  const CycleRun r("G98 G97 S500 M03\nG00 X1.5 Z-0.3\nG75 X1.0 Z-0.5 I0.1 K0.2 F5.\n", Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm) << r.timeline.alarm->code;
  expectPath(r, 3, kInch,
             {{L, 1.3, -0.3},
              {R, 1.4, -0.3},
              {L, 1.1, -0.3},
              {R, 1.2, -0.3},
              {L, 1.0, -0.3},
              {R, 1.5, -0.3},
              {R, 1.5, -0.5},
              {L, 1.3, -0.5},
              {R, 1.4, -0.5},
              {L, 1.1, -0.5},
              {R, 1.2, -0.5},
              {L, 1.0, -0.5},
              {R, 1.5, -0.5},
              {R, 1.5, -0.3}});
}

TEST(HaasG74, PecksKInZ) {
  // On centre from Z0.1 to Z-0.5 with K0.25 pecks: Z-0.15, Z-0.4, Z-0.5,
  // retracting 0.05 between them, then back to Z0.1.
  const CycleRun r("G98 G97 S500 M03\nG00 X0 Z0.1\nG74 Z-0.5 K0.25 F5.\n", Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm);
  expectPath(r, 3, kInch, {{L, 0, -0.15}, {R, 0, -0.1}, {L, 0, -0.4}, {R, 0, -0.35}, {L, 0, -0.5}, {R, 0, 0.1}});
}

// ---- drilling ---------------------------------------------------------------------------

TEST(FanucG83, PecksQFromTheRPointAndReturnsToTheInitialLevel) {
  // Initial level Z5; R-3. = 3 mm below it: R point Z2. Q8000 = 8 mm pecks to
  // Z-20 (22 mm): Z-6, Z-14, Z-20. Between pecks: rapid to Z2, then down to
  // 1 mm (parameter 5115) above the last peck: Z-5, Z-13.
  const CycleRun r("G98 G97 S500 M03\nG00 X0 Z5.\nG83 Z-20. R-3. Q8000 F100.\nG80\nG00 X50.\n", Dialect::Fanuc);
  ASSERT_FALSE(r.timeline.alarm) << r.timeline.alarm->code;
  expectPath(
      r, 3, 1.0,
      {{R, 0, 2}, {L, 0, -6}, {R, 0, 2}, {R, 0, -5}, {L, 0, -14}, {R, 0, 2}, {R, 0, -13}, {L, 0, -20}, {R, 0, 5}});
  expectPath(r, 5, 1.0, {{R, 50, 5}});
  // Feeds: 8 + 9 + 7 = 24 mm at 100 mm/min = 14.4 s.
  double feedTime = 0.0;
  for (const Move& m : r.timeline.moves)
    if (m.line == 3 && m.kind == L) feedTime += m.tEnd - m.tStart;
  EXPECT_NEAR(feedTime, 14.4, 1e-9);
}

TEST(FanucG83, StaysModalForTheNextHoleUntilG80) {
  // A block with only Z repeats the cycle to the new bottom (R point kept).
  const CycleRun r("G98 G97 S500 M03\nG00 X0 Z5.\nG83 Z-10. R-3. F100.\nZ-12.\nG80\nZ8.\n", Dialect::Fanuc);
  ASSERT_FALSE(r.timeline.alarm);
  expectPath(r, 3, 1.0, {{R, 0, 2}, {L, 0, -10}, {R, 0, 5}});
  expectPath(r, 4, 1.0, {{R, 0, 2}, {L, 0, -12}, {R, 0, 5}});
  expectPath(r, 6, 1.0, {{R, 0, 8}});
}

// G-code system B (issue 27; Fanuc 0i-TF operator's manual, G code list): G95 is
// the feed per revolution, G98/G99 the drilling cycles' return level. Under G99
// the cycle ends at the R point and the next hole starts from there; G98 goes
// back to the initial level as system A always does.
TEST(SystemBG83, G99EndsAtTheRPointAndG98AtTheInitialLevel) {
  Dialect romi{};
  ASSERT_TRUE(gcode::parseDialectId("romi-gl240m", romi));
  const CycleRun r("G95 G97 S500 M03\nG00 X0 Z5.\nG99 G83 Z-10. R-3. F0.1\nZ-12.\nG98 Z-14.\nG80\n", romi);
  ASSERT_FALSE(r.timeline.alarm) << r.timeline.alarm->code;
  expectPath(r, 3, 1.0, {{R, 0, 2}, {L, 0, -10}, {R, 0, 2}});
  // The next hole from the R point: no rapid up to Z5 first.
  expectPath(r, 4, 1.0, {{L, 0, -12}, {R, 0, 2}});
  expectPath(r, 5, 1.0, {{L, 0, -14}, {R, 0, 5}});
  // F0.1 under G95 is per revolution: 12 mm (R point Z2 to Z-10) at 0.1 mm x 500 rpm = 14.4 s.
  double feedTime = 0.0;
  for (const Move& m : r.timeline.moves)
    if (m.line == 3 && m.kind == L) feedTime += m.tEnd - m.tStart;
  EXPECT_NEAR(feedTime, 14.4, 1e-9);
  // In system A, G99 is the feed per revolution and the cycle returns to the initial level.
  const CycleRun a("G99 G97 S500 M03\nG00 X0 Z5.\nG83 Z-10. R-3. F0.1\n", Dialect::Fanuc);
  ASSERT_FALSE(a.timeline.alarm);
  expectPath(a, 3, 1.0, {{R, 0, 2}, {L, 0, -10}, {R, 0, 5}});
}

TEST(HaasG82, DwellsPSecondsAtTheBottom) {
  // Haas: R is the R plane's Z (Z2.), P0.5 with a point = 0.5 s; back to the initial Z5.
  const CycleRun r("G21 G98 G97 S500 M03\nG00 X0 Z5.\nG82 Z-4. R2. P0.5 F100.\n", Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm);
  ASSERT_EQ(r.sink.dwells.size(), 1u);
  EXPECT_DOUBLE_EQ(r.sink.dwells[0].seconds, 0.5);
  expectPath(r, 3, 1.0, {{R, 0, 2}, {L, 0, -4}, {R, 0, 5}});
}

TEST(FanucG82, IsNotAFanucLatheCode) {
  // The 0i-TF's G-code system A has no G82 (docs/dialects.md): the run refuses it.
  const CycleRun r("G98 G97 S500 M03\nG00 X0 Z5.\nG82 Z-4. R-3. P500 F100.\n", Dialect::Fanuc);
  ASSERT_TRUE(r.timeline.alarm);
  EXPECT_EQ(r.timeline.alarm->code, "A117");
}

TEST(FanucG81, DrillsInOneFeedAndIgnoresP) {
  // from the initial level Z3: the R point Z0.5; feed to Z-12 (12.5 mm at
  // 125 mm/min = 6 s), no dwell for G81, rapid back to Z3.
  const CycleRun r("G98 G97 S500 M03\nG00 X0 Z3.\nG81 Z-12. R-2.5 P500 F125.\n", Dialect::Fanuc);
  ASSERT_FALSE(r.timeline.alarm);
  expectPath(r, 3, 1.0, {{R, 0, 0.5}, {L, 0, -12}, {R, 0, 3}});
  EXPECT_TRUE(r.sink.dwells.empty());
  for (const Move& m : r.timeline.moves) {
    if (m.line == 3 && m.kind == L) {
      EXPECT_NEAR(m.tEnd - m.tStart, 6.0, 1e-9);
    }
  }
}

TEST(FanucG83, WIsCountedFromTheRPoint) {
  // Initial level Z5, R point Z2 (R-3.); W-10. = 10 mm below the R point: Z-8.
  const CycleRun r("G98 G97 S500 M03\nG00 X0 Z5.\nG83 W-10. R-3. F100.\n", Dialect::Fanuc);
  ASSERT_FALSE(r.timeline.alarm);
  expectPath(r, 3, 1.0, {{R, 0, 2}, {L, 0, -8}, {R, 0, 5}});
}

TEST(HaasG81, RIsTheRPlaneZ) {
  // Haas R0.05 is the plane Z0.05 (not a distance): rapid there, drill to Z-0.5, back to Z0.2.
  const CycleRun r("G98 G97 S500 M03\nG00 X0 Z0.2\nG81 Z-0.5 R0.05 F5.\n", Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm);
  expectPath(r, 3, kInch, {{R, 0, 0.05}, {L, 0, -0.5}, {R, 0, 0.2}});
}

TEST(HaasG83, PecksIThenLessByJNeverUnderK) {
  // R plane Z0.05, bottom Z-1.: depth 1.05. Pecks I0.3, then 0.2 (J0.1), then
  // 0.15 (K: never under): reached .3 .5 .65 .8 .95 1.05 = Z-0.25 -0.45 -0.6
  // -0.75 -0.9 -1.0. Between pecks: Z0.05, then Setting 22 = 0.05 above the
  // last peck. P0.5 (decimal point: seconds) at the bottom.
  const CycleRun r("G98 G97 S500 M03\nG00 X0 Z0.2\nG83 Z-1. R0.05 I0.3 J0.1 K0.15 P0.5 F5.\n", Dialect::Haas);
  ASSERT_FALSE(r.timeline.alarm) << r.timeline.alarm->code;
  expectPath(r, 3, kInch,
             {{R, 0, 0.05},
              {L, 0, -0.25},
              {R, 0, 0.05},
              {R, 0, -0.2},
              {L, 0, -0.45},
              {R, 0, 0.05},
              {R, 0, -0.4},
              {L, 0, -0.6},
              {R, 0, 0.05},
              {R, 0, -0.55},
              {L, 0, -0.75},
              {R, 0, 0.05},
              {R, 0, -0.7},
              {L, 0, -0.9},
              {R, 0, 0.05},
              {R, 0, -0.85},
              {L, 0, -1.0},
              {R, 0, 0.2}});
  ASSERT_EQ(r.sink.dwells.size(), 1u);
  EXPECT_DOUBLE_EQ(r.sink.dwells[0].seconds, 0.5);
}

TEST(Drilling, ClassicDoesNotKnowG83) {
  const CycleRun r("G98 G97 S500 M03\nG00 X0 Z5.\nG83 Z-20. R-3. Q8000 F100.\n", Dialect::Classic);
  ASSERT_TRUE(r.timeline.alarm);
  EXPECT_EQ(r.timeline.alarm->code, "A117");
}

}  // namespace
}  // namespace klueng::core::machine::haas_cycles_test

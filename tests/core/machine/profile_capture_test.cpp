// G70-G73 read their profile N(P)..N(Q) by running those blocks through the
// interpreter into a capturing sink (issue 12): the profile means what the
// same blocks mean anywhere else. Expected points derived by hand in the
// comments (X as diameters; no tool offset, so the controlled point is the
// program point).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "klueng/core/machine/interpreter.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

using testing::runText;

struct Cut {
  MoveKind kind;
  double x;  // diameter at the end
  double z;
};

// The feed moves (lines and arcs) the timeline made for `line`.
std::vector<Cut> cutsOf(const Timeline& t, int line) {
  std::vector<Cut> out;
  for (const Move& m : t.moves)
    if (m.line == line && (m.kind == MoveKind::Line || m.kind == MoveKind::Arc))
      out.push_back({m.kind, 2.0 * xOf(m.path.end), zOf(m.path.end)});
  return out;
}

void expectCuts(const std::vector<Cut>& got, const std::vector<Cut>& expected) {
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].kind, expected[i].kind) << "cut " << i;
    EXPECT_NEAR(got[i].x, expected[i].x, 1e-6) << "X of cut " << i;
    EXPECT_NEAR(got[i].z, expected[i].z, 1e-6) << "Z of cut " << i;
  }
}

constexpr MoveKind L = MoveKind::Line;
constexpr MoveKind A = MoveKind::Arc;

// A G70 profile with a ,C2 chamfer and a ,R3 corner (Fanuc "chamfering and
// corner R" on G01), from X50 Z2:
//   N10 G00 X20.    -> X20 Z2 (rapid)
//   G01 Z0.         -> X20 Z0
//   X30. ,C2.       -> the face stops 2 short: X26 Z0, chamfer to X30 Z-2
//   Z-20. ,R3.      -> the line stops 3 short: X30 Z-17, arc to X36 Z-20
//   N20 X50.        -> X50 Z-20
constexpr const char* kCornerProfile =
    "N10 G00 X20.\n"
    "G01 Z0.\n"
    "X30. ,C2.\n"
    "Z-20. ,R3.\n"
    "N20 X50.\n";

TEST(ProfileCapture, G70CutsTheChamferAndCornerOfItsProfile) {
  const Timeline t = runText(std::string("G98 G97 S500 M03\nG00 X50. Z2.\nG70 P10 Q20 F100.\nG00 X100. Z100.\nM30\n") +
                             kCornerProfile);
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  expectCuts(cutsOf(t, 3), {{L, 20, 0}, {L, 26, 0}, {L, 30, -2}, {L, 30, -17}, {A, 36, -20}, {L, 50, -20}});
  for (const Move& m : t.moves)
    if (m.line == 3 && m.kind == A) {
      EXPECT_NEAR(m.path.radius(), 1.5 * 2.0, 1e-9);  // R3
      EXPECT_NEAR(zOf(m.path.centre), -17.0, 1e-9);
      EXPECT_NEAR(2.0 * xOf(m.path.centre), 36.0, 1e-9);
    }
  // Then the program goes on with the block after the cycle.
  EXPECT_EQ(t.moves.back().line, 4);
}

// A chamfer held by the block before the cycle is the run's, not the
// profile's: the profile cuts its own corners, and the held ,C still has no
// move of its own in the next block (A144 at the ,C of line 3).
TEST(ProfileCapture, ACornerHeldBeforeTheCycleStaysTheRuns) {
  const Timeline t =
      runText(std::string("G98 G97 S500 M03\nG00 X50. Z2.\nG01 X52. ,C1. F100.\nG70 P10 Q20\nG00 X100. Z100.\nM30\n") +
              kCornerProfile);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A144");
  EXPECT_EQ(t.alarm->range, (SourceRange{3, 10, 4}));
  EXPECT_EQ(t.alarm->args, std::vector<std::string>{",C1."});
  // The cycle's moves came first, its profile's corners cut; the held G01 never went.
  expectCuts(cutsOf(t, 4), {{L, 20, 0}, {L, 26, 0}, {L, 30, -2}, {L, 30, -17}, {A, 36, -20}, {L, 50, -20}});
  EXPECT_TRUE(cutsOf(t, 3).empty());
}

// An M98 in a profile is refused where it stands (the capture decides, not
// the run): the alarm names the M98 and the cycle's profile line.
TEST(ProfileCapture, ASubprogramCallInTheProfileIsRefused) {
  const Timeline t = runText(
      "G98 G97 S500 M03\nG00 X50. Z2.\nG70 P10 Q20 F100.\nM30\nN10 G00 X20.\nG01 Z0. M98 P100\nN20 X50.\n"
      "O100\nG00 U1.\nM99\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A150");
  EXPECT_EQ(t.alarm->range, (SourceRange{6, 9, 3}));
  EXPECT_EQ(t.alarm->args, (std::vector<std::string>{"M98", "6"}));
}

TEST(ProfileCapture, G71FinishesItsLastPassAlongTheChamferAndCorner) {
  // No finishing allowance: the last pass is the profile itself.
  const Timeline t =
      runText(std::string("G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 F100.\n") + kCornerProfile);
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  const std::vector<Cut> cuts = cutsOf(t, 4);
  ASSERT_GE(cuts.size(), 6u);
  const std::vector<Cut> last(cuts.end() - 5, cuts.end());
  expectCuts(last, {{L, 26, 0}, {L, 30, -2}, {L, 30, -17}, {A, 36, -20}, {L, 50, -20}});
}

TEST(ProfileCapture, AProfileReadsMacroValuesLikeNumbers) {
  const std::string cycle = "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F100.\n";
  const Timeline numbers = runText(cycle + "N10 G00 X30.\nG01 Z-20.\nX40.\nZ-40.\nN20 X50.\nG70 P10 Q20\n");
  const Timeline values =
      runText("#1=30.\n#2=20.\n" + cycle + "N10 G00 X#1\nG01 Z-#2\nX[#1+10]\nZ-[#2*2]\nN20 X50.\nG70 P10 Q20\n");
  ASSERT_FALSE(numbers.alarm) << numbers.alarm->code;
  ASSERT_FALSE(values.alarm) << values.alarm->code;
  // Same cuts, two lines further down.
  for (const auto& [a, b] : {std::pair{4, 6}, std::pair{10, 12}}) {
    const std::vector<Cut> expected = cutsOf(numbers, a);
    ASSERT_FALSE(expected.empty());
    expectCuts(cutsOf(values, b), expected);
  }
  // G70: X30 from Z2 to Z-20, then X40, Z-40, X50.
  expectCuts(cutsOf(values, 12), {{L, 30, -20}, {L, 40, -20}, {L, 40, -40}, {L, 50, -40}});
}

TEST(ProfileCapture, TheCycleBlockReadsItsOwnMacroValues) {
  const std::string profile = "N10 G00 X30.\nG01 Z-20.\nN20 X50.\n";
  const Timeline numbers =
      runText("G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F100.\n" + profile);
  const Timeline values = runText(
      "#1=2.\n#2=0.4\nG98 G97 S500 M03\nG00 X50. Z2.\nG71 U#1 R0.5\nG71 P10 Q20 U#2 W0.1 F[#2*250]\n" + profile);
  ASSERT_FALSE(numbers.alarm) << numbers.alarm->code;
  ASSERT_FALSE(values.alarm) << values.alarm->code;
  const std::vector<Cut> expected = cutsOf(numbers, 4);
  ASSERT_GT(expected.size(), 4u);  // passes of 2 mm from X50 to X30.4
  expectCuts(cutsOf(values, 6), expected);
}

struct Refused {
  const char* block;  // the profile's middle block
  const char* word;   // what the alarm names
  int column;
};

class ProfileRefuses : public ::testing::TestWithParam<Refused> {};

TEST_P(ProfileRefuses, ABlockThatIsNoMoveWithA150AtItsWord) {
  const Refused r = GetParam();
  const Timeline t = runText(std::string("G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 F100.\n") +
                             "N10 G00 X30.\n" + r.block + "\nN20 X50.\nM30\nO0100\nG00 U1.\nM99\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A150");
  EXPECT_EQ(t.alarm->range.line, 6);
  EXPECT_EQ(t.alarm->range.column, r.column);
  EXPECT_EQ(t.alarm->args.at(0), r.word);
  EXPECT_EQ(t.alarm->args.at(1), "6");
  // Nothing of the cycle ran.
  for (const Move& m : t.moves) EXPECT_NE(m.line, 4);
}

INSTANTIATE_TEST_SUITE_P(FanucLimitations, ProfileRefuses,
                         ::testing::Values(Refused{"G01 Z-20. G28 U0.", "G28", 11},
                                           Refused{"G01 Z-20. M98 P100", "M98", 11},
                                           Refused{"G32 Z-20. F1.5", "G32", 1}, Refused{"G90 X40. Z-20.", "G90", 1},
                                           Refused{"G65 P100 A1.", "G65", 1}));

TEST(ProfileCapture, ADwellInTheProfileWaitsUnderG70Only) {
  const std::string program =
      "G98 G97 S500 M03\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 F100.\n"
      "N10 G00 X30.\nG01 Z-20.\nG04 P1500\nN20 X50.\nG70 P10 Q20\n";
  const Timeline t = runText(program);
  ASSERT_FALSE(t.alarm) << t.alarm->code;
  double roughing = 0.0, finishing = 0.0;
  for (const Move& m : t.moves)
    if (m.kind == MoveKind::Dwell) (m.line == 4 ? roughing : finishing) += m.tEnd - m.tStart;
  EXPECT_DOUBLE_EQ(roughing, 0.0);
  EXPECT_NEAR(finishing, 1.5, 1e-9);  // G04 P1500: 1500 ms (Fanuc)
}

}  // namespace
}  // namespace klueng::core::machine

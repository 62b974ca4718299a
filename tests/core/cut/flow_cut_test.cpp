// Program flow cuts real parts (issue 9): a macro roughing loop cuts exactly
// the part of its unrolled twin, and a groove subprogram called at four Z
// positions cuts four equal grooves. The whole pipeline: parse, check,
// interpret, cut with the shipped tools.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "cut_test_util.h"
#include "klueng/core/cut/finished_part.h"

namespace klueng::core::cut {
namespace {

const char* kHeader = "Flow test\nShaft\nAluminium\n140\n180\nKlueng tests\n";

// The cut stock (FinishedPart measures it by reference: keep the simulator).
struct Cut {
  testing::Run run;
  std::unique_ptr<CutSimulator> sim;
  FinishedPart part() const { return FinishedPart(sim->stock()); }
};

Cut cut(const std::string& text) {
  Cut c;
  c.run = testing::runProgramText(text);
  EXPECT_FALSE(hasErrors(c.run.checkDiagnostics))
      << c.run.checkDiagnostics.front().code << " line " << c.run.checkDiagnostics.front().range.line;
  EXPECT_FALSE(c.run.timeline.alarm.has_value()) << c.run.timeline.alarm->code;
  c.sim = std::make_unique<CutSimulator>(c.run.timeline, CutSetup::from(c.run.file.header, c.run.setup));
  c.sim->runToEnd();
  EXPECT_FALSE(c.sim->alarm().has_value()) << c.sim->alarm()->code << " line " << c.sim->alarm()->range.line;
  return c;
}

// Roughing Ø40 down to Ø30 over 25 mm, 0.5 mm depth of cut (1 mm on the
// diameter) per pass: ten passes, X39 ... X30.
TEST(FlowCut, MacroRoughingLoopCutsTheSamePartAsItsUnrolledTwin) {
  const std::string loop = std::string(kHeader) +
                           "O0001 (MACRO ROUGHING)\n"
                           "G21 G40 G99\n"
                           "T0101\n"
                           "G97 S1200 M03\n"
                           "#100 = 40.   (CURRENT DIAMETER)\n"
                           "#101 = 30.   (FINISHED DIAMETER)\n"
                           "#102 = 0.5   (DEPTH OF CUT)\n"
                           "G00 X42. Z2.\n"
                           "WHILE [#100 GT #101] DO1\n"
                           "#100 = #100 - 2 * #102\n"
                           "G00 X#100\n"
                           "G01 Z-25. F0.2\n"
                           "G00 U1. Z2.\n"
                           "END1\n"
                           "G00 X100. Z100.\n"
                           "M30\n";
  std::string unrolled =
      std::string(kHeader) + "O0002 (THE SAME, WRITTEN OUT)\nG21 G40 G99\nT0101\nG97 S1200 M03\nG00 X42. Z2.\n";
  for (int d = 39; d >= 30; --d) unrolled += "G00 X" + std::to_string(d) + ".\nG01 Z-25. F0.2\nG00 U1. Z2.\n";
  unrolled += "G00 X100. Z100.\nM30\n";

  const Cut ca = cut(loop);
  const Cut cb = cut(unrolled);
  const FinishedPart a = ca.part();
  const FinishedPart b = cb.part();
  const auto pa = a.outerProfile();
  const auto pb = b.outerProfile();
  ASSERT_EQ(pa.size(), pb.size());
  for (std::size_t k = 0; k < pa.size(); ++k) {
    EXPECT_NEAR(pa[k].x(), pb[k].x(), 0.001) << k;
    EXPECT_NEAR(pa[k].y(), pb[k].y(), 0.001) << k;
  }
  // And it is the part asked for: Ø30 on the roughed length, Ø40 beyond it.
  EXPECT_NEAR(*a.outerDiameterAt(-12.0), 30.0, 0.01);
  EXPECT_NEAR(*a.outerDiameterAt(-30.0), 40.0, 0.01);
}

// O2000 plunges the 3 mm grooving tool (T0404) to Ø32 where it stands; the main
// program calls it at Z-10, -20, -30 and -40.
TEST(FlowCut, GrooveSubprogramCalledFourTimesCutsFourEqualGrooves) {
  const std::string text = std::string(kHeader) +
                           "O0003 (FOUR GROOVES)\n"
                           "G21 G40 G99\n"
                           "T0404 (GROOVING 3 MM)\n"
                           "G97 S600 M03\n"
                           "G00 X44. Z2.\n"
                           "Z-10.\nM98 P2000\n"
                           "Z-20.\nM98 P2000\n"
                           "Z-30.\nM98 P2000\n"
                           "Z-40.\nM98 P2000\n"
                           "G00 X100. Z100.\n"
                           "M30\n"
                           "O2000 (ONE GROOVE TO D32)\n"
                           "G01 X32. F0.05\n"
                           "G00 X44.\n"
                           "M99\n";
  const Cut c = cut(text);
  const FinishedPart part = c.part();
  // Each groove: the diameter is 32 over the tool's width, 40 between grooves.
  struct Groove {
    double from = 1e9, to = -1e9, bottom = 1e9;
  };
  Groove g[4];
  for (double z = -50.0; z <= -1.0; z += 0.01) {
    const double d = *part.outerDiameterAt(z);
    if (d > 39.99) continue;
    const int k = static_cast<int>(std::lround(-z / 10.0)) - 1;
    ASSERT_GE(k, 0);
    ASSERT_LT(k, 4);
    g[k].from = std::min(g[k].from, z);
    g[k].to = std::max(g[k].to, z);
    g[k].bottom = std::min(g[k].bottom, d);
  }
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(g[k].bottom, 32.0, 0.01) << k;
    EXPECT_NEAR(g[k].to - g[k].from, g[0].to - g[0].from, 0.011) << k;  // equal widths
    EXPECT_NEAR(g[k].from + 10.0 * k, g[0].from, 0.011) << k;           // 10 mm apart
  }
  EXPECT_NEAR(g[0].to - g[0].from, 3.0, 0.05);  // the 3 mm tool
}

// Sample 01's finishing contour with ,C and ,R instead of the written-out
// chamfer (N350 X30. Z-3.) and corner arc (N370 X36. / N380 G03 X40. Z-22. R2.).
TEST(FlowCut, ChamferAndCornerWordsCutSampleOnesPart) {
  const std::string sample = testing::readText(testing::samplesDir() + "/01-step-shaft.txt");
  ASSERT_FALSE(sample.empty());
  std::string words = sample;
  const auto swap = [&words](const std::string& from, const std::string& to) {
    const auto at = words.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    words.replace(at, from.size(), to);
  };
  swap("N350 X30. Z-3.\n", "N350 X30. ,C3.\n");
  swap("N370 X36.\nN380 G03 X40. Z-22. R2.\nN390 G01 Z-40.\n", "N370 X40. ,R2.\nN390 Z-40.\n");
  const Cut written = cut(sample);
  const Cut corners = cut(words);
  const auto a = written.part().outerProfile();
  const auto b = corners.part().outerProfile();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_NEAR(a[k].x(), b[k].x(), 0.001) << k;
    EXPECT_NEAR(a[k].y(), b[k].y(), 0.001) << k;
  }
  // The same moves, too (under G42: the compensated path).
  ASSERT_EQ(written.run.timeline.moves.size(), corners.run.timeline.moves.size());
  for (std::size_t k = 0; k < written.run.timeline.moves.size(); ++k) {
    const Segment& p = written.run.timeline.moves[k].path;
    const Segment& q = corners.run.timeline.moves[k].path;
    EXPECT_LT((p.end - q.end).norm(), 0.001) << k;
    EXPECT_EQ(p.isArc(), q.isArc()) << k;
  }
}

}  // namespace
}  // namespace klueng::core::cut

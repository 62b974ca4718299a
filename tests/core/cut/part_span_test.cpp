// The finished part inside the cut stock (issue 28 item 3): the drawing shows
// the part, not the bar left in the chuck nor the piece beyond a parting cut.
#include <gtest/gtest.h>

#include <algorithm>

#include "cut_test_util.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/cut/part_span.h"

namespace klueng::core::cut {
namespace {

using testing::cutToEnd;

TEST(PartSpan, Sample01LeavesTheChuckedStubOut) {
  const auto c = cutToEnd(testing::readText(testing::samplesDir() + "/01-step-shaft.txt"));
  const Stock& stock = c.sim->stock();
  const PartSpan span = finishedPartSpan(stock);
  EXPECT_FALSE(span.parted);
  EXPECT_TRUE(span.stubLeftOut);
  EXPECT_NEAR(span.zRight, 0.0, 1e-9);
  EXPECT_NEAR(span.zLeft, -60.0, stock.resolution());  // the Ø46 step's end; the Ø50 bar beyond it stays in the chuck
  const PartFeatures part = partFeatures(cropToSpan(stock, span));
  EXPECT_NEAR(part.overallLength(), 60.0, stock.resolution());
  ASSERT_FALSE(part.outside.empty());
  // Nothing of the bar's Ø50, nor the nose's fillet in its corner: the Ø46 step is the part's end.
  for (const PartFeature& f : part.outside)
    EXPECT_LT(std::max(f.diameterLeft, f.diameterRight), 46.0 + 0.01) << describeFeature(f, Lang::En);
  const auto last = std::find_if(part.outside.rbegin(), part.outside.rend(),
                                 [](const PartFeature& f) { return f.kind == FeatureKind::Cylinder; });
  ASSERT_NE(last, part.outside.rend());
  EXPECT_NEAR(last->diameter, 46.0, 0.01);
  EXPECT_NEAR(last->zLeft, -60.0, stock.resolution());
}

TEST(PartSpan, APartingCutKeepsThePieceOnTheFaceSide) {
  const auto c = cutToEnd(
      "Parted\nPin\nSteel\n140\n170\nT\n"
      "G21 G40 G99\nT0101\nG97 S800 M03\nG00 X42. Z2.\nG01 X30. F0.2\nZ-30.\nX42.\nG00 X100. Z100.\n"
      "T0707\nG00 X42. Z-34.\nG01 X0. F0.05\nG00 X100.\nZ100.\nM30\n");
  const Stock& stock = c.sim->stock();
  const PartSpan span = finishedPartSpan(stock);
  EXPECT_TRUE(span.parted);
  EXPECT_NEAR(span.zRight, 0.0, 1e-9);
  // The parting blade's right side: the part ends where the gap begins.
  EXPECT_GT(span.zLeft, -34.0);
  EXPECT_LT(span.zLeft, -30.0);
  const PartFeatures part = partFeatures(cropToSpan(stock, span));
  EXPECT_NEAR(part.zLeft, span.zLeft, 1e-9);
  EXPECT_NEAR(part.zRight, 0.0, 1e-9);
}

TEST(PartSpan, AnUncutBarIsTheWholeBar) {
  const Stock stock(40.0, 70.0);
  const PartSpan span = finishedPartSpan(stock);
  EXPECT_FALSE(span.parted);
  EXPECT_FALSE(span.stubLeftOut);
  EXPECT_NEAR(span.zLeft, -70.0, 1e-9);
  EXPECT_NEAR(span.zRight, 0.0, 1e-9);
  EXPECT_TRUE(finishedPartSpan(Stock()).empty());
}

}  // namespace
}  // namespace klueng::core::cut

namespace klueng::core::cut {
namespace {

// The chamfer before a thread (issue 28 item 3): a C1.5 turned on the Ø30 end, then
// threaded M30×1.5 through it; the crests at the start still lie on the chamfer.
TEST(PartSpan, TheChamferBeforeAThreadIsKept) {
  const auto c = cutToEnd(
      "Chamfered thread\nBolt\nSteel\n132\n160\nT\n"
      "G21 G40 G99\nT0101\nG97 S800 M03\nG42 G00 X27. Z2.\nG01 Z0. F0.2\nX30. Z-1.5\nZ-30.\nX34.\n"
      "G40 G00 X100. Z100.\nT0303\nG97 S600 M03\nG00 X34. Z4.5\n"
      "G76 P011060 Q50 R0.05\nG76 X28.16 Z-22. P920 Q400 F1.5\nG00 X100. Z100.\nM30\n");
  PartFeatures part = partFeatures(c.sim->stock());
  const auto thread = std::find_if(part.outside.begin(), part.outside.end(),
                                   [](const PartFeature& f) { return f.kind == FeatureKind::Thread; });
  ASSERT_NE(thread, part.outside.end());
  const std::size_t before = part.outside.size();
  addThreadLeadChamfers(c.sim->stock(), part);
  ASSERT_EQ(part.outside.size(), before + 1);
  const auto chamfer = std::find_if(part.outside.begin(), part.outside.end(),
                                    [](const PartFeature& f) { return f.kind == FeatureKind::Chamfer; });
  ASSERT_NE(chamfer, part.outside.end());
  EXPECT_EQ(featureLabel(*chamfer, Lang::En), "C1.5");
  EXPECT_NEAR(chamfer->zRight, 0.0, 0.05);
  EXPECT_NEAR(chamfer->zLeft, -1.5, 0.1);
  EXPECT_EQ(std::next(chamfer)->kind, FeatureKind::Thread);  // listed before the thread, from the face

  // A thread without a chamfer gets none.
  const auto plain = cutToEnd(
      "Plain thread\nBolt\nSteel\n132\n160\nT\n"
      "G21 G40 G99\nT0101\nG97 S800 M03\nG00 X34. Z2.\nG01 X30. F0.2\nZ-30.\nX34.\n"
      "G00 X100. Z100.\nT0303\nG97 S600 M03\nG00 X34. Z4.5\n"
      "G76 P011060 Q50 R0.05\nG76 X28.16 Z-22. P920 Q400 F1.5\nG00 X100. Z100.\nM30\n");
  PartFeatures plainPart = partFeatures(plain.sim->stock());
  const std::size_t n = plainPart.outside.size();
  addThreadLeadChamfers(plain.sim->stock(), plainPart);
  EXPECT_EQ(plainPart.outside.size(), n);
}

}  // namespace
}  // namespace klueng::core::cut

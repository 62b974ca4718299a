#include "klueng/core/cut/stock.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <numbers>

namespace klueng::core::cut {
namespace {

TEST(Stock, ColumnsTileTheBarInWorkCoordinates) {
  Stock s(50.0, 100.0);
  ASSERT_EQ(s.columnCount(), 2000);
  EXPECT_DOUBLE_EQ(s.resolution(), 0.05);
  EXPECT_DOUBLE_EQ(s.zLeft(0), -100.0);
  EXPECT_NEAR(s.zCentre(1999), -0.025, 1e-12);
  EXPECT_EQ(s.columnAt(-0.01), 1999);
  EXPECT_EQ(s.columnAt(-100.0), 0);
  EXPECT_EQ(s.columnAt(0.5), -1);
  EXPECT_EQ(s.columnAt(-100.5), -1);
  EXPECT_DOUBLE_EQ(s.outerRadius(7), 25.0);
  EXPECT_DOUBLE_EQ(s.innerRadius(7), 0.0);
  int first, last;
  s.columnRange(-1.0, 0.0, first, last);  // centres -0.975 .. -0.025
  EXPECT_EQ(first, 1980);
  EXPECT_EQ(last, 1999);
}

TEST(Stock, ResolutionIsAdjustedToTileTheLengthExactly) {
  Stock s(20.0, 10.0, 0.03);
  EXPECT_EQ(s.columnCount(), 334);
  EXPECT_NEAR(s.zLeft(s.columnCount() - 1) + s.resolution(), 0.0, 1e-12);
}

TEST(Stock, RemovingTheOutsideIsExactAndCountsVolume) {
  Stock s(50.0, 100.0);
  const double before = s.volume();
  EXPECT_NEAR(before, std::numbers::pi * 625.0 * 100.0, 1e-6);
  const double removed = s.remove(10, 23.4567, 40.0);
  EXPECT_DOUBLE_EQ(s.outerRadius(10), 23.4567);
  EXPECT_NEAR(removed, std::numbers::pi * (625.0 - 23.4567 * 23.4567) * 0.05, 1e-9);
  EXPECT_NEAR(s.volume(), before - removed, 1e-6);
  EXPECT_EQ(s.remove(10, 24.0, 30.0), 0.0);  // air
}

TEST(Stock, BoresAndUndercutsAreSeparateIntervals) {
  Stock s(40.0, 50.0);
  s.remove(3, 0.0, 5.0);    // bore
  s.remove(3, 10.0, 12.0);  // internal groove
  const auto col = s.column(3);
  ASSERT_EQ(col.size(), 2u);
  EXPECT_DOUBLE_EQ(col[0].lo, 5.0);
  EXPECT_DOUBLE_EQ(col[0].hi, 10.0);
  EXPECT_DOUBLE_EQ(col[1].lo, 12.0);
  EXPECT_DOUBLE_EQ(col[1].hi, 20.0);
  EXPECT_DOUBLE_EQ(s.innerRadius(3), 5.0);
  EXPECT_DOUBLE_EQ(s.outerRadius(3), 20.0);
  EXPECT_DOUBLE_EQ(s.overlap(3, 9.0, 13.0), 1.0);
  EXPECT_DOUBLE_EQ(s.overlap(3, 10.5, 11.5), 0.0);
  s.remove(3, 0.0, 100.0);
  EXPECT_TRUE(s.column(3).empty());
  EXPECT_DOUBLE_EQ(s.outerRadius(3), 0.0);
}

TEST(Stock, BlockMaximaFollowRemovals) {
  Stock s(50.0, 100.0);
  for (int i = 0; i < 1000; ++i) s.remove(i, 10.0, 30.0);
  EXPECT_DOUBLE_EQ(s.maxOuterRadius(0, 999), 10.0);
  EXPECT_DOUBLE_EQ(s.maxOuterRadius(0, 1000), 25.0);
  EXPECT_DOUBLE_EQ(s.maxOuterRadius(500, 531), 10.0);
  s.remove(517, 3.0, 30.0);
  EXPECT_DOUBLE_EQ(s.maxOuterRadius(517, 517), 3.0);
  EXPECT_DOUBLE_EQ(s.maxOuterRadius(500, 600), 10.0);
}

// The block and super-block maxima (1024 columns) answer exactly what a scan
// of every column would, after thousands of removals of every size.
TEST(Stock, RangeMaximaMatchAScanOfEveryColumn) {
  Stock s(50.0, 100.0, 0.02);  // 5000 columns: five super-blocks and a part
  ASSERT_EQ(s.columnCount(), 5000);
  std::mt19937 random(12);
  std::uniform_int_distribution<int> column(0, 4999);
  std::uniform_real_distribution<double> radius(0.0, 26.0);
  for (int round = 0; round < 3000; ++round) {
    const int a = column(random);
    const int width = round % 3 == 0 ? 1 : round % 3 == 1 ? 40 : 2000;
    const double lo = radius(random);
    for (int i = a; i < std::min(a + width, 5000); ++i) s.remove(i, lo, 30.0);
    const int first = column(random);
    const int last = std::min(4999, first + std::uniform_int_distribution<int>(0, 4000)(random));
    double expected = 0.0;
    for (int i = first; i <= last; ++i) expected = std::max(expected, s.outerRadius(i));
    ASSERT_DOUBLE_EQ(s.maxOuterRadius(first, last), expected)
        << "round " << round << " [" << first << ", " << last << "]";
  }
  EXPECT_DOUBLE_EQ(s.maxOuterRadius(3000, 2999), 0.0);  // an empty range
}

// A part cut off the bar drops into the catcher (issue 38): it stays in view for the finished
// part, but nothing later cuts it or collides with it.
TEST(StockCatcher, APartCutOffStaysInViewAndIsNeverCutAgain) {
  Stock bar(20.0, 30.0, 1.0);  // 30 columns of 1 mm, Z-30..0
  ASSERT_EQ(bar.columnCount(), 30);
  EXPECT_FALSE(bar.catchCutOffPart());  // one piece: nothing to catch
  const int cut = bar.columnAt(-10.5);  // a 1 mm blade cuts off Z-11..-10 to the centre
  bar.remove(cut, 0.0, 10.0);
  ASSERT_EQ(bar.outerRadius(cut), 0.0);
  EXPECT_TRUE(bar.catchCutOffPart());
  const int part = bar.columnAt(-5.0), stub = bar.columnAt(-20.0);
  EXPECT_TRUE(bar.caught(part));
  EXPECT_FALSE(bar.caught(stub));
  // The next part's facing sweeps through where the part was: it stays whole.
  EXPECT_EQ(bar.remove(part, 0.0, 10.0), 0.0);
  EXPECT_EQ(bar.overlap(part, 0.0, 10.0), 0.0);
  EXPECT_DOUBLE_EQ(bar.outerRadius(part), 10.0);
  // The bar in the chuck is cut as before.
  EXPECT_GT(bar.remove(stub, 8.0, 10.0), 0.0);
  EXPECT_DOUBLE_EQ(bar.outerRadius(stub), 8.0);
  EXPECT_FALSE(bar.catchCutOffPart());  // nothing new cut off
}

}  // namespace
}  // namespace klueng::core::cut

// The library's tools at their own resolution (10 px/mm): their flank angles,
// measured from the tool shape the simulator cuts with, are the real ones.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "klueng/core/cut/tool_shape.h"
#include "klueng/core/io/tool_library.h"

namespace klueng::core::cut {
namespace {

ToolShape libraryShape(const std::string& id) {
  const io::ToolLibrary& lib = io::shippedToolLibrary();
  const io::LibraryTool* t = lib.find(id);
  EXPECT_NE(t, nullptr) << id;
  if (!t) return {};
  const auto r = loadToolShape(lib.bitmapPath(*t), t->noseRadius, t->tip, t->pixelsPerMm);
  EXPECT_TRUE(r.ok()) << id;
  return r.value ? *r.value : ToolShape{};
}

// Lowest x of the cutting edge at z (mm, relative to the controlled point); NaN if none.
double bottomAt(const ToolShape& s, double z) {
  double best = std::numeric_limits<double>::quiet_NaN();
  for (const Trapezoid& t : s.cutting)
    if (z >= t.z0 && z <= t.z1) {
      const double b = t.bottomAt(z);
      if (std::isnan(best) || b < best) best = b;
    }
  return best;
}

// Leftmost z of the cutting edge at height x.
double leftAt(const ToolShape& s, double x) {
  double best = std::numeric_limits<double>::quiet_NaN();
  for (const Trapezoid& t : s.cutting) {
    const Box b = t.bounds();
    if (x >= b.x0 && x <= b.x1 && (std::isnan(best) || t.z0 < best)) best = t.z0;
  }
  return best;
}

// Least-squares slope of f over [a, b] in n steps.
template <typename F>
double slope(F f, double a, double b, int n = 40) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int count = 0;
  for (int i = 0; i <= n; ++i) {
    const double x = a + (b - a) * i / n;
    const double y = f(x);
    if (std::isnan(y)) continue;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    ++count;
  }
  return (count * sxy - sx * sy) / (count * sxx - sx * sx);
}

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

struct RhombicCase {
  const char* id;
  double included;  // the insert's corner angle
};

class RhombicInsert : public ::testing::TestWithParam<RhombicCase> {};

// The leading edge leaves the corner at 87 degrees from +Z (93-degree approach),
// the trailing edge at 87 - included.
TEST_P(RhombicInsert, FlankAnglesWithinOneDegree) {
  const ToolShape s = libraryShape(GetParam().id);
  EXPECT_EQ(s.pixelsPerMm, 10.0);
  EXPECT_EQ(s.tip, 3);
  const double trailing = degrees(std::atan(slope([&](double z) { return bottomAt(s, z); }, 1.5, 6.0)));
  const double leading = 90.0 - degrees(std::atan(slope([&](double x) { return leftAt(s, x); }, 1.5, 9.0)));
  EXPECT_NEAR(leading, 87.0, 1.0) << GetParam().id;
  EXPECT_NEAR(trailing, 87.0 - GetParam().included, 1.0) << GetParam().id;
  EXPECT_NEAR(leading - trailing, GetParam().included, 1.0) << GetParam().id;
}

INSTANTIATE_TEST_SUITE_P(Library, RhombicInsert,
                         ::testing::Values(RhombicCase{"cnmg-80-r08", 80.0}, RhombicCase{"cnmg-80-r04", 80.0},
                                           RhombicCase{"dnmg-55-r04", 55.0}, RhombicCase{"vnmg-35-r02", 35.0}));

TEST(LibraryShape, ThreadingToolIsSixtyDegrees) {
  const ToolShape s = libraryShape("threading-60");
  ASSERT_EQ(s.tip, 8);
  // Tip 8: the controlled point is the bottom middle; the flanks rise both ways.
  const double right = degrees(std::atan(slope([&](double z) { return bottomAt(s, z); }, 0.5, 4.5)));
  const double left = degrees(std::atan(-slope([&](double z) { return bottomAt(s, z); }, -4.5, -0.5)));
  EXPECT_NEAR(right, 60.0, 1.0);  // each flank 30 degrees from the X axis
  EXPECT_NEAR(left, 60.0, 1.0);
  EXPECT_NEAR(bottomAt(s, 0.0), 0.0, 0.1);
}

TEST(LibraryShape, SizesAtTheirOwnResolution) {
  const ToolShape parting = libraryShape("parting-3mm");
  EXPECT_NEAR(parting.bounds.z0, 0.0, 1e-9);
  // The insert is 3 mm wide: the cutting edge at its bottom spans 3 mm.
  double width = 0.0;
  for (double z = 0.0; z < 5.0; z += 0.01)
    if (!std::isnan(bottomAt(parting, z)) && bottomAt(parting, z) < 0.2) width = z;
  EXPECT_NEAR(width, 3.0, 0.1);

  const ToolShape drill = libraryShape("drill-16mm");
  EXPECT_EQ(drill.tip, 7);
  double top = -1e9, bottom = 1e9;
  for (const Trapezoid& t : drill.cutting) {
    top = std::max(top, t.bounds().x1);
    bottom = std::min(bottom, t.bounds().x0);
  }
  EXPECT_NEAR(top - bottom, 16.0, 0.1);
  EXPECT_NEAR(top, 8.0, 0.1);  // the drill point on the axis
}

TEST(LibraryShape, ThePixelLimitFollowsTheResolution) {
  EXPECT_EQ(maxToolPixels(2.0), kMaxToolPixels);
  EXPECT_EQ(maxToolPixels(10.0), 5000);
}

}  // namespace
}  // namespace klueng::core::cut

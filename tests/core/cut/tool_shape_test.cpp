#include <string>
#include "klueng/core/cut/tool_shape.h"

#include <unistd.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "cut_test_util.h"
#include "../../scratch_folders.h"

namespace klueng::core::cut {
namespace {

using testing::blankImage;
using testing::paint;
using testing::squareToolImage;

struct TipCase {
  int tip;
  double pz, px;  // controlled point in bitmap mm (z from left, x up from bottom) for the square tool
};

class ControlledPoint : public ::testing::TestWithParam<TipCase> {};

TEST_P(ControlledPoint, IsTheBoundingBoxPointInTheTipDirection) {
  const TipCase c = GetParam();
  // The insert's pixels span columns 0..9 and rows 20..29 of 30: z 0..5, x 0..5 mm.
  const auto r = makeToolShape(squareToolImage(), "sq.bmp", 0.0, c.tip);
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(r.value->controlPixelX, c.pz * 2.0);
  EXPECT_DOUBLE_EQ(r.value->controlPixelY, 30.0 - c.px * 2.0);
  // The holder sits 5..15 mm above the insert's bottom edge in local coordinates.
  double holderBottom = 1e9;
  for (const Box& b : r.value->holder) holderBottom = std::min(holderBottom, b.x0);
  EXPECT_DOUBLE_EQ(holderBottom, 5.0 - c.px);
}

INSTANTIATE_TEST_SUITE_P(AllTips, ControlledPoint,
                         ::testing::Values(TipCase{1, 5.0, 5.0}, TipCase{2, 0.0, 5.0}, TipCase{3, 0.0, 0.0},
                                           TipCase{4, 5.0, 0.0}, TipCase{5, 5.0, 2.5}, TipCase{6, 2.5, 5.0},
                                           TipCase{7, 0.0, 2.5}, TipCase{8, 2.5, 0.0}, TipCase{0, 2.5, 2.5},
                                           TipCase{9, 2.5, 2.5}));

TEST(ToolShape, NoseIsExactAndPixelsLeaveTheNoseSquare) {
  const auto r = makeToolShape(squareToolImage(), "sq.bmp", 0.8, 3);
  ASSERT_TRUE(r.ok());
  const ToolShape& t = *r.value;
  EXPECT_DOUBLE_EQ(t.noseRadius, 0.8);
  EXPECT_DOUBLE_EQ(t.noseCentre.x(), 0.8);
  EXPECT_DOUBLE_EQ(t.noseCentre.y(), 0.8);
  for (const Trapezoid& e : t.cutting) {
    const Box b = e.bounds();
    const bool insideSquare = b.z0 < 0.8 && b.x0 < 0.8;
    EXPECT_FALSE(insideSquare) << b.z0 << " " << b.z1 << " " << b.x0 << " " << b.x1;
  }
  // Cutting boxes still reach the bbox edges away from the nose.
  double minX = 1e9, minZ = 1e9;
  for (const Trapezoid& e : t.cutting) {
    const Box b = e.bounds();
    minX = std::min(minX, b.x0);
    minZ = std::min(minZ, b.z0);
  }
  EXPECT_DOUBLE_EQ(minX, 0.0);
  EXPECT_DOUBLE_EQ(minZ, 0.0);
  EXPECT_DOUBLE_EQ(t.bounds.z0, 0.0);
  EXPECT_DOUBLE_EQ(t.bounds.x0, 0.0);
  EXPECT_DOUBLE_EQ(t.bounds.x1, 15.0);
  EXPECT_DOUBLE_EQ(t.bounds.z1, 5.0);
}

TEST(ToolShape, TipEightNoseSquareIsCentred) {
  const auto r = makeToolShape(squareToolImage(), "sq.bmp", 0.5, 8);
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(r.value->noseCentre.x(), 0.0);
  EXPECT_DOUBLE_EQ(r.value->noseCentre.y(), 0.5);
  for (const Trapezoid& e : r.value->cutting) {
    const Box b = e.bounds();
    const bool inside = b.z0 < 0.5 && b.z1 > -0.5 && b.x0 < 0.5;
    EXPECT_FALSE(inside);
  }
}

TEST(ToolShape, ABitmapWithoutCuttingPixelsIsRefused) {
  io::RgbImage img = blankImage(20, 20);
  paint(img, 0, 0, 19, 9, 0x000000);
  const auto r = makeToolShape(img, "holder-only.bmp", 0.4, 3);
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "A310");
  EXPECT_EQ(r.diagnostics[0].args.at(0), "holder-only.bmp");
}

TEST(ToolShape, AnOversizedBitmapIsRefused) {
  io::RgbImage img = blankImage(kMaxToolPixels + 1, 4);
  paint(img, 0, 0, 3, 3, 0xE0A000);
  const auto r = makeToolShape(img, "huge.bmp", 0.4, 3);
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "A311");
  EXPECT_EQ(r.diagnostics[0].args.at(0), "huge.bmp");
  EXPECT_EQ(r.diagnostics[0].args.at(1), std::to_string(kMaxToolPixels + 1));
}

TEST(ToolShape, MissingAndMalformedFilesGiveErrorsNamingTheFile) {
  const auto missing = loadToolShape("/nonexistent/dir/tool.bmp", 0.8, 3);
  EXPECT_FALSE(missing.ok());
  ASSERT_FALSE(missing.diagnostics.empty());
  EXPECT_EQ(missing.diagnostics[0].code[0], 'F');
  bool named = false;
  for (const auto& a : missing.diagnostics[0].args) named = named || a.find("tool.bmp") != std::string::npos;
  EXPECT_TRUE(named);

  const auto dir = std::filesystem::temp_directory_path() / ("klueng_cut_tool_test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string bad = (dir / "garbage.bmp").string();
  std::FILE* f = std::fopen(bad.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  std::fputs("BM this is not a bitmap", f);
  std::fclose(f);
  const auto malformed = loadToolShape(bad, 0.8, 3);
  EXPECT_FALSE(malformed.ok());
  ASSERT_FALSE(malformed.diagnostics.empty());
  named = false;
  for (const auto& a : malformed.diagnostics[0].args) named = named || a.find("garbage.bmp") != std::string::npos;
  EXPECT_TRUE(named);
}

TEST(ToolShape, ShippedBitmapsLoadWithTheirOffsets) {
  const auto tools = io::readToolTable(testing::sourceDir() + "/tools.cfg");
  const auto offsets = io::readOffsetTable(testing::sourceDir() + "/offset.cfg");
  ASSERT_TRUE(tools.ok());
  ASSERT_TRUE(offsets.ok());
  for (int tool = 1; tool <= 8; ++tool) {
    const io::Offset& o = offsets.value->at(tool);
    const auto r = loadToolShape(tools.value->bitmapPath(tool), o.r, o.tip);
    EXPECT_TRUE(r.ok()) << tool;
    if (!r.ok()) continue;
    EXPECT_FALSE(r.value->cutting.empty()) << tool;
    EXPECT_FALSE(r.value->holder.empty()) << tool;
  }
}

}  // namespace
}  // namespace klueng::core::cut

// Its scratch folders go with the process: nothing left in /tmp after a run.
[[maybe_unused]] ::testing::Environment* const kToolShapeScratchCleanup =
    klueng::test::removeScratchFoldersAtExit({"klueng_cut_tool_test-"});

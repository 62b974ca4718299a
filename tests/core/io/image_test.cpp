#include "klueng/core/io/image.h"

#include <gtest/gtest.h>
#include <png.h>

#include <sys/stat.h>

#include <cstring>

#include "klueng/core/io/file_read.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/messages.h"
#include "test_util.h"

namespace klueng::core::io {
namespace {

using testing::TempDir;

void put16(std::string& s, std::size_t at, std::uint16_t v) {
  s[at] = static_cast<char>(v & 0xFF);
  s[at + 1] = static_cast<char>(v >> 8);
}
void put32(std::string& s, std::size_t at, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) s[at + k] = static_cast<char>((v >> (8 * k)) & 0xFF);
}

// A BMP built by hand: file header, BITMAPINFOHEADER (or a larger one), then
// `extra` (masks and palette) and the pixel rows exactly as given.
std::string makeBmp(int width, int height, int bits, std::uint32_t compression, const std::string& extra,
                    const std::string& rows, std::uint32_t headerSize = 40, std::uint32_t colorsUsed = 0) {
  std::string s(14 + headerSize, '\0');
  s[0] = 'B';
  s[1] = 'M';
  put32(s, 10, static_cast<std::uint32_t>(14 + headerSize + extra.size()));
  put32(s, 14, headerSize);
  put32(s, 18, static_cast<std::uint32_t>(width));
  put32(s, 22, static_cast<std::uint32_t>(height));
  put16(s, 26, 1);
  put16(s, 28, static_cast<std::uint16_t>(bits));
  put32(s, 30, compression);
  put32(s, 46, colorsUsed);
  s += extra;
  s += rows;
  put32(s, 2, static_cast<std::uint32_t>(s.size()));
  return s;
}

std::string bytes(std::initializer_list<int> v) {
  std::string s;
  for (int b : v) s += static_cast<char>(b);
  return s;
}

std::string firstCode(const ReadResult<RgbImage>& r) {
  return r.diagnostics.empty() ? std::string("none") : r.diagnostics[0].code;
}

TEST(Bmp, TwentyFourBitBottomUpWithRowPadding) {
  // 3 x 2: bottom row first; each row is 9 bytes + 3 padding. Pixels are B G R.
  const std::string rows = bytes({0, 0, 255, 0, 255, 0, 255, 0, 0, 0, 0, 0}) +     // bottom: red green blue
                           bytes({0, 0, 0, 255, 255, 255, 0, 160, 224, 0, 0, 0});  // top: black white gold
  const auto r = decodeImage(makeBmp(3, 2, 24, 0, "", rows), "t.bmp");
  ASSERT_TRUE(r.ok()) << firstCode(r);
  ASSERT_EQ(r.value->width, 3);
  ASSERT_EQ(r.value->height, 2);
  EXPECT_EQ(r.value->at(0, 0), 0x000000u);
  EXPECT_EQ(r.value->at(1, 0), 0xFFFFFFu);
  EXPECT_EQ(r.value->at(2, 0), 0xE0A000u);
  EXPECT_EQ(r.value->at(0, 1), 0xFF0000u);
  EXPECT_EQ(r.value->at(1, 1), 0x00FF00u);
  EXPECT_EQ(r.value->at(2, 1), 0x0000FFu);
}

TEST(Bmp, TopDownRowsWhenHeightIsNegative) {
  const std::string rows = bytes({0, 0, 255, 0}) + bytes({255, 0, 0, 0});  // 1 x 2, padded to 4
  const auto r = decodeImage(makeBmp(1, -2, 24, 0, "", rows), "t.bmp");
  ASSERT_TRUE(r.ok()) << firstCode(r);
  EXPECT_EQ(r.value->at(0, 0), 0xFF0000u);  // first row stored is the top
  EXPECT_EQ(r.value->at(0, 1), 0x0000FFu);
}

TEST(Bmp, OneBitPalette) {
  const std::string palette = bytes({0, 0, 0, 0, 255, 255, 255, 0});  // 0 black, 1 white
  // 10 x 1: bits 1011001110 -> padded to 4 bytes
  const std::string rows = bytes({0b10110011, 0b10000000, 0, 0});
  const auto r = decodeImage(makeBmp(10, 1, 1, 0, palette, rows), "t.bmp");
  ASSERT_TRUE(r.ok()) << firstCode(r);
  const int expected[10] = {1, 0, 1, 1, 0, 0, 1, 1, 1, 0};
  for (int x = 0; x < 10; ++x) EXPECT_EQ(r.value->at(x, 0), expected[x] ? 0xFFFFFFu : 0u) << x;
}

TEST(Bmp, FourBitPaletteWithFewColoursUsed) {
  const std::string palette = bytes({255, 255, 255, 0, 0, 0, 0, 0, 0, 160, 224, 0});  // 3 colours
  const std::string rows = bytes({0x01, 0x20, 0, 0});                                 // 3 x 1: 0 1 2
  const auto r = decodeImage(makeBmp(3, 1, 4, 0, palette, rows, 40, 3), "t.bmp");
  ASSERT_TRUE(r.ok()) << firstCode(r);
  EXPECT_EQ(r.value->at(0, 0), 0xFFFFFFu);
  EXPECT_EQ(r.value->at(1, 0), 0x000000u);
  EXPECT_EQ(r.value->at(2, 0), 0xE0A000u);
}

TEST(Bmp, EightBitPaletteIndexOutOfRange) {
  const std::string palette = bytes({0, 0, 0, 0, 255, 255, 255, 0});
  const auto r = decodeImage(makeBmp(2, 1, 8, 0, palette, bytes({1, 7, 0, 0}), 40, 2), "pal.bmp");
  EXPECT_FALSE(r.value);
  ASSERT_EQ(firstCode(r), "F156");
  EXPECT_EQ(r.diagnostics[0].args, (std::vector<std::string>{"pal.bmp", "7", "2"}));
}

TEST(Bmp, ThirtyTwoBitRgbIgnoresTheUnusedByte) {
  const auto r = decodeImage(makeBmp(1, 1, 32, 0, "", bytes({0, 160, 224, 0})), "t.bmp");
  ASSERT_TRUE(r.ok()) << firstCode(r);
  EXPECT_EQ(r.value->at(0, 0), 0xE0A000u);
}

TEST(Bmp, ThirtyTwoBitBitfieldsWithAlphaInAV5Header) {
  std::string pixels = bytes({0, 0, 255, 255, 0, 0, 255, 10});  // opaque red, nearly clear red
  std::string bmp = makeBmp(2, 1, 32, 3, "", pixels, 124);
  put32(bmp, 54, 0x00FF0000);
  put32(bmp, 58, 0x0000FF00);
  put32(bmp, 62, 0x000000FF);
  put32(bmp, 66, 0xFF000000);
  const auto r = decodeImage(bmp, "t.bmp");
  ASSERT_TRUE(r.ok()) << firstCode(r);
  EXPECT_EQ(r.value->at(0, 0), 0xFF0000u);
  EXPECT_EQ(r.value->at(1, 0), 0xFFFFFFu);  // alpha < 128 reads as white (empty)
}

TEST(Bmp, SixteenBitRgb565Bitfields) {
  const std::string masks = bytes({0x00, 0xF8, 0, 0, 0xE0, 0x07, 0, 0, 0x1F, 0, 0, 0});
  // 0xF800 = red, 0x07E0 = green, little-endian, then 0 padding to 4 bytes.
  const auto r = decodeImage(makeBmp(2, 1, 16, 3, masks, bytes({0x00, 0xF8, 0xE0, 0x07})), "t.bmp");
  ASSERT_TRUE(r.ok()) << firstCode(r);
  EXPECT_EQ(r.value->at(0, 0), 0xFF0000u);
  EXPECT_EQ(r.value->at(1, 0), 0x00FF00u);
}

TEST(Bmp, Os2CoreHeader) {
  std::string s(14 + 12, '\0');
  s[0] = 'B';
  s[1] = 'M';
  put32(s, 10, 26);
  put32(s, 14, 12);
  put16(s, 18, 1);
  put16(s, 20, 1);
  put16(s, 22, 1);
  put16(s, 24, 24);
  s += bytes({0x00, 0xA0, 0xE0, 0});
  const auto r = decodeImage(s, "os2.bmp");
  ASSERT_TRUE(r.ok()) << firstCode(r);
  EXPECT_EQ(r.value->at(0, 0), 0xE0A000u);
}

struct BadImage {
  const char* name;
  std::string bytes;
  const char* code;
};

class MalformedImages : public ::testing::TestWithParam<BadImage> {};

TEST_P(MalformedImages, GiveADiagnosticNamingTheFile) {
  const auto r = decodeImage(GetParam().bytes, "bad.img");
  EXPECT_FALSE(r.value);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, GetParam().code);
  EXPECT_EQ(r.diagnostics[0].args.at(0), "bad.img");
  EXPECT_NE(formatMessage(r.diagnostics[0], Lang::Th).find("bad.img"), std::string::npos);
}

std::string withField(std::string s, std::size_t at, std::uint32_t v) {
  put32(s, at, v);
  return s;
}

const std::string kGood = makeBmp(3, 2, 24, 0, "", std::string(24, '\xFF'));

INSTANTIATE_TEST_SUITE_P(
    Cases, MalformedImages,
    ::testing::Values(BadImage{"empty", "", "F150"}, BadImage{"text", "hello world", "F150"},
                      BadImage{"magic_only", "BM", "F151"},
                      BadImage{"truncated_rows", kGood.substr(0, kGood.size() - 5), "F151"},
                      BadImage{"zero_width", withField(kGood, 18, 0), "F152"},
                      BadImage{"huge_height", withField(kGood, 22, 100000), "F152"},
                      BadImage{"most_negative_height", withField(kGood, 22, 0x80000000u), "F152"},
                      BadImage{"width_over_4096", withField(kGood, 18, 4097), "F152"},
                      BadImage{"rle8", withField(makeBmp(3, 2, 8, 1, "", std::string(24, '\0')), 30, 1), "F153"},
                      BadImage{"bad_header_size", withField(kGood, 14, 41), "F154"},
                      BadImage{"pixel_offset_past_end", withField(kGood, 10, 1000000), "F154"},
                      BadImage{"png_truncated", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16), "F155"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(Bmp, WriteThenReadRoundTrips) {
  TempDir dir;
  RgbImage image;
  image.width = 5;  // 15 bytes per row: padding needed
  image.height = 3;
  for (int i = 0; i < 15; ++i) image.pixels.push_back(static_cast<std::uint32_t>(i * 0x10203 + 0x0A0B0C));
  std::string error;
  ASSERT_TRUE(writeBmp(dir.file("rt.bmp"), image, &error)) << error;
  const auto r = readImage(dir.file("rt.bmp"));
  ASSERT_TRUE(r.ok()) << firstCode(r);
  EXPECT_EQ(r.value->width, 5);
  EXPECT_EQ(r.value->height, 3);
  EXPECT_EQ(r.value->pixels, image.pixels);
  EXPECT_EQ(testing::readFile(dir.file("rt.bmp")).size(), 54u + 16u * 3u);
}

// Issue 29 item 8: a bitmap that is a pipe made Tool Select's preview wait for
// a writer for ever. It is refused from stat() alone, before anything opens it.
TEST(Bmp, APipeOrADeviceIsRefusedWithoutOpeningIt) {
  TempDir dir;
  const std::string pipe = dir.file("pipe.bmp");
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0644), 0);
  const auto r = readImage(pipe);  // before the fix: open() blocks here, no writer ever comes
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "F157");
  EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::En),
            pipe + ": this is a pipe (FIFO), not an ordinary file, so it is not opened");
  EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::Th), pipe + ": นี่คือไปป์ (FIFO) ไม่ใช่ไฟล์ธรรมดา จึงไม่เปิด");
  const auto device = notAnOrdinaryFile("/dev/null");
  ASSERT_TRUE(device);
  EXPECT_EQ(formatMessage(*device, Lang::En), "/dev/null: this is a device, not an ordinary file, so it is not opened");
  // Ordinary files, folders and missing paths are left to the readers (F101, F102).
  std::string error;
  RgbImage one;
  one.width = one.height = 1;
  one.pixels = {0};
  ASSERT_TRUE(writeBmp(dir.file("one.bmp"), one, &error)) << error;
  EXPECT_FALSE(notAnOrdinaryFile(dir.file("one.bmp")));
  EXPECT_FALSE(notAnOrdinaryFile(dir.path().string()));
  EXPECT_FALSE(notAnOrdinaryFile(dir.file("missing.bmp")));
}

TEST(Bmp, WriteRefusesAnImageWithoutPixels) {
  TempDir dir;
  std::string error;
  EXPECT_FALSE(writeBmp(dir.file("x.bmp"), RgbImage{}, &error));
  EXPECT_FALSE(error.empty());
}

std::string encodePng(png_uint_32 width, png_uint_32 height, png_uint_32 format, const std::vector<unsigned char>& px) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = width;
  png.height = height;
  png.format = format;
  png_alloc_size_t size = 0;
  EXPECT_TRUE(png_image_write_to_memory(&png, nullptr, &size, 0, px.data(), 0, nullptr));
  std::string out(size, '\0');
  EXPECT_TRUE(png_image_write_to_memory(&png, out.data(), &size, 0, px.data(), 0, nullptr));
  out.resize(size);
  return out;
}

TEST(Png, RgbaWithTransparencyReadsClearAsWhite) {
  const std::vector<unsigned char> px = {224, 160, 0, 255, 0, 0, 0, 255, 10, 20, 30, 0, 10, 20, 30, 127};
  const auto r = decodeImage(encodePng(2, 2, PNG_FORMAT_RGBA, px), "t.png");
  ASSERT_TRUE(r.ok()) << firstCode(r);
  EXPECT_EQ(r.value->at(0, 0), 0xE0A000u);
  EXPECT_EQ(r.value->at(1, 0), 0x000000u);
  EXPECT_EQ(r.value->at(0, 1), 0xFFFFFFu);
  EXPECT_EQ(r.value->at(1, 1), 0xFFFFFFu);
}

TEST(Png, GreyImageBecomesRgb) {
  const auto r = decodeImage(encodePng(3, 1, PNG_FORMAT_GRAY, {0, 255, 0}), "g.png");
  ASSERT_TRUE(r.ok()) << firstCode(r);
  EXPECT_EQ(r.value->pixels, (std::vector<std::uint32_t>{0x000000u, 0xFFFFFFu, 0x000000u}));
}

TEST(Png, PaletteImageBecomesRgb) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = 3;
  png.height = 1;
  png.format = PNG_FORMAT_RGB_COLORMAP;
  png.colormap_entries = 3;
  const unsigned char colormap[] = {255, 255, 255, 0, 0, 0, 224, 160, 0};
  const unsigned char indices[] = {2, 1, 0};
  png_alloc_size_t size = 0;
  ASSERT_TRUE(png_image_write_to_memory(&png, nullptr, &size, 0, indices, 0, colormap));
  std::string bytes(size, '\0');
  ASSERT_TRUE(png_image_write_to_memory(&png, bytes.data(), &size, 0, indices, 0, colormap));
  bytes.resize(size);
  ASSERT_EQ(bytes[25], 3);  // IHDR colour type 3: really a palette PNG
  ASSERT_NE(bytes.find("PLTE"), std::string::npos);
  const auto r = decodeImage(bytes, "p.png");
  ASSERT_TRUE(r.ok()) << firstCode(r);
  EXPECT_EQ(r.value->pixels, (std::vector<std::uint32_t>{0xE0A000u, 0x000000u, 0xFFFFFFu}));
}

TEST(Png, TruncatedDataIsReported) {
  const std::string png = encodePng(8, 8, PNG_FORMAT_RGB, std::vector<unsigned char>(8 * 8 * 3, 77));
  const auto r = decodeImage(png.substr(0, png.size() - 20), "cut.png");
  EXPECT_FALSE(r.value);
  ASSERT_EQ(firstCode(r), "F155");
}

TEST(Png, OversizedDimensionsAreRefusedBeforeDecoding) {
  std::string png = encodePng(1, 1, PNG_FORMAT_RGB, {1, 2, 3});
  // IHDR width is at byte 16, big-endian; the CRC no longer matches, which
  // libpng reports for IHDR; either way nothing is allocated.
  png[16] = 0;
  png[17] = 0;
  png[18] = 0x13;
  png[19] = static_cast<char>(0x88);  // 5000
  const auto r = decodeImage(png, "wide.png");
  EXPECT_FALSE(r.value);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_TRUE(r.diagnostics[0].code == "F152" || r.diagnostics[0].code == "F155") << r.diagnostics[0].code;
}

TEST(Image, ReadReportsAMissingFile) {
  const auto r = readImage("/no/such/tool.bmp");
  ASSERT_EQ(firstCode(r), "F101");
}

// The shipped tools: holder black, insert one clear colour, and the holder never
// reaches past the insert in the direction of the tool's tip (SPEC 11, 9).
struct ShippedTool {
  int tool;
  int tip;
};

class ShippedBitmaps : public ::testing::TestWithParam<ShippedTool> {};

TEST_P(ShippedBitmaps, InsertLeadsInTheTipDirection) {
  const auto table = readToolTable(std::string(KLUENG_SOURCE_DIR) + "/tools.cfg");
  ASSERT_TRUE(table.value);
  const auto r = readImage(table.value->bitmapPath(GetParam().tool));
  ASSERT_TRUE(r.ok()) << firstCode(r);
  const RgbImage& img = *r.value;
  int minX = img.width, maxX = -1, minY = img.height, maxY = -1;
  int black = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint32_t c = img.at(x, y);
      ASSERT_TRUE(c == 0x000000u || c == 0xFFFFFFu || c == 0xE0A000u) << std::hex << c;
      if (c == 0) ++black;
      if (c != 0xE0A000u) continue;
      minX = std::min(minX, x), maxX = std::max(maxX, x);
      minY = std::min(minY, y), maxY = std::max(maxY, y);
    }
  ASSERT_GE(maxX, 0) << "no cutting edge";
  EXPECT_GT(black, 0) << "no holder";
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      if (img.at(x, y) != 0) continue;
      const int tip = GetParam().tip;
      if (tip == 3 || tip == 4 || tip == 8) {
        EXPECT_LE(y, maxY) << "holder below the insert";
      }
      if (tip == 2 || tip == 6 || tip == 1) {
        EXPECT_GE(y, minY) << "holder above the insert";
      }
      if (tip == 3 || tip == 2 || tip == 7) {
        EXPECT_GE(x, minX) << "holder left of the insert";
      }
      if (tip == 4 || tip == 1 || tip == 5) {
        EXPECT_LE(x, maxX) << "holder right of the insert";
      }
    }
  // Edge-middle tips sit on the middle of the insert's bounding box.
  if (GetParam().tip == 8 || GetParam().tip == 6) {
    const int y = GetParam().tip == 8 ? maxY : minY;
    EXPECT_EQ(img.at((minX + maxX) / 2, y), 0xE0A000u) << "point not in the middle";
  }
  if (GetParam().tip == 7) {
    EXPECT_EQ(img.at(minX, (minY + maxY) / 2), 0xE0A000u) << "drill point off axis";
  }
}

INSTANTIATE_TEST_SUITE_P(Tools, ShippedBitmaps,
                         ::testing::Values(ShippedTool{1, 3}, ShippedTool{2, 4}, ShippedTool{3, 8}, ShippedTool{4, 3},
                                           ShippedTool{5, 2}, ShippedTool{6, 7}, ShippedTool{7, 3}, ShippedTool{8, 6}));

}  // namespace
}  // namespace klueng::core::io

#pragma once
// Reading tool bitmaps (.bmp, .png) into a plain RGB raster, without Qt.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/io/result.h"

namespace klueng::core::io {

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint32_t> pixels;  // 0xRRGGBB, row-major, row 0 at the top
  std::uint32_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

// Refuses files over 4096 x 4096 pixels or 64 MB, and malformed data, with F1xx diagnostics naming the file.
ReadResult<RgbImage> readImage(const std::string& path);
// BMP: 1/4/8/16/24/32 bits per pixel, bottom-up or top-down, BI_RGB or
// BI_BITFIELDS. PNG: any colour type; see-through pixels (alpha < 128) read as white.
ReadResult<RgbImage> decodeImage(std::string_view bytes, const std::string& fileName);
// 24-bit bottom-up BMP bytes of the image.
std::string encodeBmp(const RgbImage& image);
// Writes a 24-bit BMP atomically; false (with error filled) on failure.
bool writeBmp(const std::string& path, const RgbImage& image, std::string* error = nullptr);

}  // namespace klueng::core::io

#include "klueng/core/io/image.h"

// PNG: libpng on the desktop; the WebAssembly build (issue 41), which has no libpng, reads
// the same 8-bit RGBA through stb_image (shipped with emscripten), defined by its CMakeLists.
#if defined(KLUENG_PNG_STB)
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#include <stb_image.h>
#else
#include <png.h>
#endif

#include <algorithm>
#include <bit>
#include <cstring>
#include <fstream>
#include <optional>

#include "io/text_util.h"
#include "klueng/core/io/file_read.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::io {

namespace {

using detail::makeDiagnostic;

constexpr int kMaxSide = 4096;

std::uint32_t readLe32(std::string_view b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24;
}
std::uint16_t readLe16(std::string_view b, std::size_t at) {
  return static_cast<std::uint16_t>(static_cast<unsigned char>(b[at]) | static_cast<unsigned char>(b[at + 1]) << 8);
}

Diagnostic fileError(const char* code, const std::string& fileName, std::vector<std::string> more = {}) {
  std::vector<std::string> args{fileName};
  args.insert(args.end(), more.begin(), more.end());
  return makeDiagnostic(Severity::Error, code, 0, 0, 0, std::move(args));
}

// One colour channel described by a BI_BITFIELDS mask, scaled to 0..255.
struct Channel {
  std::uint32_t mask = 0;
  int shift = 0;
  std::uint32_t max = 0;
  explicit Channel(std::uint32_t m) : mask(m) {
    if (m == 0) return;
    shift = std::countr_zero(m);
    max = m >> shift;
  }
  std::uint32_t extract(std::uint32_t v) const {
    if (mask == 0) return 0;
    const std::uint32_t raw = (v & mask) >> shift;
    return static_cast<std::uint32_t>((static_cast<std::uint64_t>(raw) * 255 + max / 2) / max);
  }
};

// What a BMP's file header and info header say.
struct BmpHeader {
  std::uint32_t pixelOffset = 0;
  std::uint32_t headerSize = 0;  // 12: OS/2 BITMAPCOREHEADER; 40 .. 124: the Windows headers
  std::int64_t width = 0, height = 0;
  bool topDown = false;  // rows stored from the top (a negative height)
  int bitsPerPixel = 0;
  std::uint32_t compression = 0, colorsUsed = 0;
  int paletteEntrySize = 4;
  bool indexed() const { return bitsPerPixel == 1 || bitsPerPixel == 4 || bitsPerPixel == 8; }
};

// Each step of reading a BMP: nothing, or why the file is refused.
using BmpError = std::optional<Diagnostic>;

constexpr std::uint32_t kBmpRgb = 0, kBmpBitfields = 3, kBmpAlphaBitfields = 6;

Diagnostic bmpDamaged(const std::string& fileName, const char* what) {
  return fileError(codes::kBmpHeaderDamaged, fileName, {what});
}

// The file header and the info header: where the pixels are, the size, the pixel format.
BmpError readBmpHeader(std::string_view b, const std::string& fileName, BmpHeader& h) {
  if (b.size() < 14 + 12) return fileError(codes::kImageTruncated, fileName);
  h.pixelOffset = readLe32(b, 10);
  h.headerSize = readLe32(b, 14);
  if (h.headerSize != 12 && h.headerSize != 40 && h.headerSize != 52 && h.headerSize != 56 && h.headerSize != 64 &&
      h.headerSize != 108 && h.headerSize != 124)
    return bmpDamaged(fileName, "unknown header size");
  if (14 + static_cast<std::size_t>(h.headerSize) > b.size()) return fileError(codes::kImageTruncated, fileName);
  if (h.headerSize == 12) {  // OS/2 BITMAPCOREHEADER
    h.width = readLe16(b, 18);
    h.height = static_cast<std::int16_t>(readLe16(b, 20));
    if (readLe16(b, 22) != 1) return bmpDamaged(fileName, "planes must be 1");
    h.bitsPerPixel = readLe16(b, 24);
    h.paletteEntrySize = 3;
  } else {
    h.width = static_cast<std::int32_t>(readLe32(b, 18));
    h.height = static_cast<std::int32_t>(readLe32(b, 22));
    if (readLe16(b, 26) != 1) return bmpDamaged(fileName, "planes must be 1");
    h.bitsPerPixel = readLe16(b, 28);
    h.compression = readLe32(b, 30);
    h.colorsUsed = readLe32(b, 46);
  }
  h.topDown = h.height < 0;
  if (h.topDown) h.height = -h.height;
  return std::nullopt;
}

// The sizes and pixel formats read: indexed colours, 24-bit, 16 and 32 bits with masks.
BmpError checkBmpFormat(const BmpHeader& h, const std::string& fileName) {
  if (h.width < 1 || h.height < 1 || h.width > kMaxSide || h.height > kMaxSide)
    return fileError(codes::kImageSizeRefused, fileName, {std::to_string(h.width), std::to_string(h.height)});
  const bool supported =
      (h.indexed() && h.compression == kBmpRgb) ||
      ((h.bitsPerPixel == 16 || h.bitsPerPixel == 32) &&
       (h.compression == kBmpRgb || h.compression == kBmpBitfields || h.compression == kBmpAlphaBitfields)) ||
      (h.bitsPerPixel == 24 && h.compression == kBmpRgb);
  if (!supported)
    return fileError(codes::kUnsupportedBmp, fileName, {std::to_string(h.bitsPerPixel), std::to_string(h.compression)});
  return std::nullopt;
}

// Channel masks: defaults for BI_RGB; after a 40-byte header they follow it (`afterHeader`,
// where the palette would start, moves past them), in larger headers they are part of it.
BmpError readBmpMasks(std::string_view b, const BmpHeader& h, const std::string& fileName, std::uint32_t (&masks)[4],
                      std::size_t& afterHeader) {
  afterHeader = 14 + h.headerSize;
  if (h.bitsPerPixel == 16 && h.compression == kBmpRgb) {
    masks[0] = 0x7C00;
    masks[1] = 0x03E0;
    masks[2] = 0x001F;
  } else if (h.bitsPerPixel == 32 && h.compression == kBmpRgb) {
    masks[0] = 0xFF0000;
    masks[1] = 0x00FF00;
    masks[2] = 0x0000FF;
  } else if (h.compression == kBmpBitfields || h.compression == kBmpAlphaBitfields) {
    std::size_t at = 14 + 40;
    const int count = h.compression == kBmpAlphaBitfields || h.headerSize >= 56 ? 4 : 3;
    if (h.headerSize == 40) afterHeader += static_cast<std::size_t>(count) * 4;
    if (at + static_cast<std::size_t>(count) * 4 > b.size()) return fileError(codes::kImageTruncated, fileName);
    for (int i = 0; i < count; ++i) masks[i] = readLe32(b, at + static_cast<std::size_t>(i) * 4);
    if (masks[0] == 0 && masks[1] == 0 && masks[2] == 0) return bmpDamaged(fileName, "colour masks are zero");
  }
  return std::nullopt;
}

// An indexed picture's colours, as 0xRRGGBB.
BmpError readBmpPalette(std::string_view b, const BmpHeader& h, std::size_t afterHeader, const std::string& fileName,
                        std::vector<std::uint32_t>& palette) {
  if (!h.indexed()) return std::nullopt;
  const std::uint32_t maxColors = 1u << h.bitsPerPixel;
  const std::uint32_t count = h.colorsUsed == 0 ? maxColors : h.colorsUsed;
  if (count > maxColors) return bmpDamaged(fileName, "too many palette colours");
  if (afterHeader + static_cast<std::size_t>(count) * h.paletteEntrySize > b.size())
    return fileError(codes::kImageTruncated, fileName);
  palette.resize(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::size_t at = afterHeader + static_cast<std::size_t>(i) * h.paletteEntrySize;
    palette[i] = static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
                 static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
                 static_cast<unsigned char>(b[at]);
  }
  return std::nullopt;
}

// The bytes of one row of pixels (rows are padded to 4 bytes).
std::size_t bmpStride(const BmpHeader& h) {
  return ((static_cast<std::size_t>(h.width) * h.bitsPerPixel + 31) / 32) * 4;
}

// The pixel rows lie after the headers and within the file.
BmpError checkBmpPixelData(std::string_view b, const BmpHeader& h, std::size_t afterHeader,
                           const std::string& fileName) {
  const std::size_t needed =
      static_cast<std::size_t>(h.pixelOffset) + bmpStride(h) * static_cast<std::size_t>(h.height);
  if (h.pixelOffset < afterHeader || h.pixelOffset > b.size())
    return bmpDamaged(fileName, "pixel data offset out of range");
  if (needed > b.size()) return fileError(codes::kImageTruncated, fileName);
  return std::nullopt;
}

// The pixels, top row first, as 0xRRGGBB. Many programs write an alpha mask but leave every
// alpha at 0: then it means nothing; else a pixel less than half opaque is background (white).
BmpError readBmpPixels(std::string_view b, const BmpHeader& h, const std::uint32_t (&masks)[4],
                       const std::vector<std::uint32_t>& palette, const std::string& fileName, RgbImage& image) {
  image.width = static_cast<int>(h.width);
  image.height = static_cast<int>(h.height);
  image.pixels.resize(static_cast<std::size_t>(h.width) * static_cast<std::size_t>(h.height));
  const Channel red(masks[0]), green(masks[1]), blue(masks[2]), alpha(masks[3]);
  std::vector<std::uint8_t> alphas;
  if (alpha.mask) alphas.resize(image.pixels.size());
  const int bitsPerPixel = h.bitsPerPixel;
  const std::size_t stride = bmpStride(h);
  for (int row = 0; row < image.height; ++row) {
    const int y = h.topDown ? row : image.height - 1 - row;
    const std::size_t rowStart = h.pixelOffset + stride * static_cast<std::size_t>(row);
    for (int x = 0; x < image.width; ++x) {
      std::uint32_t rgb = 0;
      const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      if (h.indexed()) {
        const std::size_t bit = static_cast<std::size_t>(x) * bitsPerPixel;
        const auto byte = static_cast<unsigned char>(b[rowStart + bit / 8]);
        const unsigned shift = 8 - bitsPerPixel - static_cast<unsigned>(bit % 8);
        const std::uint32_t index = (byte >> shift) & ((1u << bitsPerPixel) - 1);
        if (index >= palette.size())
          return fileError(codes::kColourOutsidePalette, fileName,
                           {std::to_string(index), std::to_string(palette.size())});
        rgb = palette[index];
      } else if (bitsPerPixel == 24) {
        const std::size_t at = rowStart + static_cast<std::size_t>(x) * 3;
        rgb = static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
              static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
              static_cast<unsigned char>(b[at]);
      } else {
        const std::size_t at = rowStart + static_cast<std::size_t>(x) * (bitsPerPixel / 8);
        const std::uint32_t v = bitsPerPixel == 16 ? readLe16(b, at) : readLe32(b, at);
        rgb = red.extract(v) << 16 | green.extract(v) << 8 | blue.extract(v);
        if (alpha.mask) alphas[i] = static_cast<std::uint8_t>(alpha.extract(v));
      }
      image.pixels[i] = rgb;
    }
  }
  if (alpha.mask && std::any_of(alphas.begin(), alphas.end(), [](std::uint8_t a) { return a != 0; }))
    for (std::size_t i = 0; i < alphas.size(); ++i)
      if (alphas[i] < 128) image.pixels[i] = 0xFFFFFF;
  return std::nullopt;
}

ReadResult<RgbImage> decodeBmp(std::string_view b, const std::string& fileName) {
  BmpHeader h;
  std::uint32_t masks[4] = {0, 0, 0, 0};
  std::size_t afterHeader = 0;
  std::vector<std::uint32_t> palette;
  RgbImage image;
  BmpError error = readBmpHeader(b, fileName, h);
  if (!error) error = checkBmpFormat(h, fileName);
  if (!error) error = readBmpMasks(b, h, fileName, masks, afterHeader);
  if (!error) error = readBmpPalette(b, h, afterHeader, fileName, palette);
  if (!error) error = checkBmpPixelData(b, h, afterHeader, fileName);
  if (!error) error = readBmpPixels(b, h, masks, palette, fileName, image);
  ReadResult<RgbImage> result;
  if (error)
    result.diagnostics.push_back(std::move(*error));
  else
    result.value = std::move(image);
  return result;
}

// 8-bit RGBA rows into the raster; a see-through pixel is empty space, like white.
RgbImage rgbaImage(int width, int height, const unsigned char* rgba) {
  RgbImage image;
  image.width = width;
  image.height = height;
  image.pixels.resize(static_cast<std::size_t>(image.width) * image.height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const unsigned char* p = &rgba[i * 4];
    image.pixels[i] =
        p[3] < 128 ? 0xFFFFFFu : static_cast<std::uint32_t>(p[0]) << 16 | static_cast<std::uint32_t>(p[1]) << 8 | p[2];
  }
  return image;
}

#if defined(KLUENG_PNG_STB)
ReadResult<RgbImage> decodePng(std::string_view bytes, const std::string& fileName) {
  ReadResult<RgbImage> result;
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(bytes.size());  // decodeImage refused more than 64 MB
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(data, size, &width, &height, &channels)) {
    result.diagnostics.push_back(fileError(codes::kPngDamaged, fileName, {stbi_failure_reason()}));
    return result;
  }
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
    result.diagnostics.push_back(
        fileError(codes::kImageSizeRefused, fileName, {std::to_string(width), std::to_string(height)}));
    return result;
  }
  // Palette, grey and 16-bit all become 8-bit RGBA.
  stbi_uc* rgba = stbi_load_from_memory(data, size, &width, &height, &channels, 4);
  if (!rgba) {
    result.diagnostics.push_back(fileError(codes::kPngDamaged, fileName, {stbi_failure_reason()}));
    return result;
  }
  result.value = rgbaImage(width, height, rgba);
  stbi_image_free(rgba);
  return result;
}
#else
ReadResult<RgbImage> decodePng(std::string_view bytes, const std::string& fileName) {
  ReadResult<RgbImage> result;
  // libpng's simplified API keeps its setjmp/longjmp error handling inside the
  // library, so a damaged file ends as a failed call here, never a jump
  // across C++ frames.
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size())) {
    result.diagnostics.push_back(fileError(codes::kPngDamaged, fileName, {png.message}));
    png_image_free(&png);
    return result;
  }
  if (png.width < 1 || png.height < 1 || png.width > kMaxSide || png.height > kMaxSide) {
    result.diagnostics.push_back(
        fileError(codes::kImageSizeRefused, fileName, {std::to_string(png.width), std::to_string(png.height)}));
    png_image_free(&png);
    return result;
  }
  png.format = PNG_FORMAT_RGBA;  // palette, grey and 16-bit all become 8-bit RGBA
  std::vector<unsigned char> rgba(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, rgba.data(), 0, nullptr)) {
    result.diagnostics.push_back(fileError(codes::kPngDamaged, fileName, {png.message}));
    png_image_free(&png);
    return result;
  }
  result.value = rgbaImage(static_cast<int>(png.width), static_cast<int>(png.height), rgba.data());
  png_image_free(&png);
  return result;
}
#endif

}  // namespace

ReadResult<RgbImage> decodeImage(std::string_view bytes, const std::string& fileName) {
  if (bytes.size() > detail::kMaxFileBytes) {
    ReadResult<RgbImage> result;
    result.diagnostics.push_back(fileError(codes::kFileTooLarge, fileName,
                                           {std::to_string(bytes.size()), sizeLimitText(detail::kMaxFileBytes)}));
    return result;
  }
  if (bytes.size() >= 2 && bytes[0] == 'B' && bytes[1] == 'M') return decodeBmp(bytes, fileName);
  if (bytes.size() >= 8 && bytes.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8))
    return decodePng(bytes, fileName);
  ReadResult<RgbImage> result;
  result.diagnostics.push_back(fileError(codes::kNotAnImage, fileName));
  return result;
}

ReadResult<RgbImage> readImage(const std::string& path) {
  ReadResult<RgbImage> result;
  // A bitmap is always a file: a pipe would wait for a writer for ever.
  if (auto refused = notAnOrdinaryFile(path)) {
    result.diagnostics.push_back(std::move(*refused));
    return result;
  }
  const std::optional<std::string> bytes = detail::readFileBytes(path, result.diagnostics);
  if (!bytes) return result;
  return decodeImage(*bytes, path);
}

std::string encodeBmp(const RgbImage& image) {
  const std::size_t stride = (static_cast<std::size_t>(image.width) * 3 + 3) & ~std::size_t{3};
  const std::size_t dataSize = stride * static_cast<std::size_t>(image.height);
  std::string out(54 + dataSize, '\0');
  const auto put32 = [&](std::size_t at, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) out[at + k] = static_cast<char>((v >> (8 * k)) & 0xFF);
  };
  const auto put16 = [&](std::size_t at, std::uint16_t v) {
    out[at] = static_cast<char>(v & 0xFF);
    out[at + 1] = static_cast<char>(v >> 8);
  };
  out[0] = 'B';
  out[1] = 'M';
  put32(2, static_cast<std::uint32_t>(out.size()));
  put32(10, 54);
  put32(14, 40);
  put32(18, static_cast<std::uint32_t>(image.width));
  put32(22, static_cast<std::uint32_t>(image.height));  // positive: bottom-up rows
  put16(26, 1);
  put16(28, 24);
  put32(34, static_cast<std::uint32_t>(dataSize));
  put32(38, 3780);  // 96 dpi
  put32(42, 3780);
  for (int y = 0; y < image.height; ++y) {
    const std::size_t row = 54 + stride * static_cast<std::size_t>(image.height - 1 - y);
    for (int x = 0; x < image.width; ++x) {
      const std::uint32_t c = image.at(x, y);
      out[row + static_cast<std::size_t>(x) * 3] = static_cast<char>(c & 0xFF);
      out[row + static_cast<std::size_t>(x) * 3 + 1] = static_cast<char>((c >> 8) & 0xFF);
      out[row + static_cast<std::size_t>(x) * 3 + 2] = static_cast<char>((c >> 16) & 0xFF);
    }
  }
  return out;
}

bool writeBmp(const std::string& path, const RgbImage& image, std::string* error) {
  if (image.width < 1 || image.height < 1 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height)) {
    if (error) *error = path + ": the image has no pixels or a wrong pixel count";
    return false;
  }
  return writeTextFileAtomic(path, encodeBmp(image), error);
}

}  // namespace klueng::core::io

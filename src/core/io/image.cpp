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

ReadResult<RgbImage> decodeBmp(std::string_view b, const std::string& fileName) {
  ReadResult<RgbImage> result;
  auto& diags = result.diagnostics;
  const auto damaged = [&](const char* what) {
    diags.push_back(fileError(codes::kBmpHeaderDamaged, fileName, {what}));
    return result;
  };
  if (b.size() < 14 + 12) {
    diags.push_back(fileError(codes::kImageTruncated, fileName));
    return result;
  }
  const std::uint32_t pixelOffset = readLe32(b, 10);
  const std::uint32_t headerSize = readLe32(b, 14);
  if (headerSize != 12 && headerSize != 40 && headerSize != 52 && headerSize != 56 && headerSize != 64 &&
      headerSize != 108 && headerSize != 124)
    return damaged("unknown header size");
  if (14 + static_cast<std::size_t>(headerSize) > b.size()) {
    diags.push_back(fileError(codes::kImageTruncated, fileName));
    return result;
  }

  std::int64_t width = 0, height = 0;
  int bitsPerPixel = 0;
  std::uint32_t compression = 0, colorsUsed = 0;
  int paletteEntrySize = 4;
  if (headerSize == 12) {  // OS/2 BITMAPCOREHEADER
    width = readLe16(b, 18);
    height = static_cast<std::int16_t>(readLe16(b, 20));
    if (readLe16(b, 22) != 1) return damaged("planes must be 1");
    bitsPerPixel = readLe16(b, 24);
    paletteEntrySize = 3;
  } else {
    width = static_cast<std::int32_t>(readLe32(b, 18));
    height = static_cast<std::int32_t>(readLe32(b, 22));
    if (readLe16(b, 26) != 1) return damaged("planes must be 1");
    bitsPerPixel = readLe16(b, 28);
    compression = readLe32(b, 30);
    colorsUsed = readLe32(b, 46);
  }
  const bool topDown = height < 0;
  if (topDown) height = -height;
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
    diags.push_back(fileError(codes::kImageSizeRefused, fileName, {std::to_string(width), std::to_string(height)}));
    return result;
  }

  constexpr std::uint32_t kRgb = 0, kBitfields = 3, kAlphaBitfields = 6;
  const bool indexed = bitsPerPixel == 1 || bitsPerPixel == 4 || bitsPerPixel == 8;
  const bool supported = (indexed && compression == kRgb) ||
                         ((bitsPerPixel == 16 || bitsPerPixel == 32) &&
                          (compression == kRgb || compression == kBitfields || compression == kAlphaBitfields)) ||
                         (bitsPerPixel == 24 && compression == kRgb);
  if (!supported) {
    diags.push_back(
        fileError(codes::kUnsupportedBmp, fileName, {std::to_string(bitsPerPixel), std::to_string(compression)}));
    return result;
  }

  // Channel masks: defaults for BI_RGB; after a 40-byte header they follow it,
  // in larger headers they are part of it.
  std::uint32_t masks[4] = {0, 0, 0, 0};
  std::size_t afterHeader = 14 + headerSize;
  if (bitsPerPixel == 16 && compression == kRgb) {
    masks[0] = 0x7C00;
    masks[1] = 0x03E0;
    masks[2] = 0x001F;
  } else if (bitsPerPixel == 32 && compression == kRgb) {
    masks[0] = 0xFF0000;
    masks[1] = 0x00FF00;
    masks[2] = 0x0000FF;
  } else if (compression == kBitfields || compression == kAlphaBitfields) {
    std::size_t at = 14 + 40;
    const int count = compression == kAlphaBitfields || headerSize >= 56 ? 4 : 3;
    if (headerSize == 40) afterHeader += static_cast<std::size_t>(count) * 4;
    if (at + static_cast<std::size_t>(count) * 4 > b.size()) {
      diags.push_back(fileError(codes::kImageTruncated, fileName));
      return result;
    }
    for (int i = 0; i < count; ++i) masks[i] = readLe32(b, at + static_cast<std::size_t>(i) * 4);
    if (masks[0] == 0 && masks[1] == 0 && masks[2] == 0) return damaged("colour masks are zero");
  }

  std::vector<std::uint32_t> palette;
  if (indexed) {
    const std::uint32_t maxColors = 1u << bitsPerPixel;
    const std::uint32_t count = colorsUsed == 0 ? maxColors : colorsUsed;
    if (count > maxColors) return damaged("too many palette colours");
    if (afterHeader + static_cast<std::size_t>(count) * paletteEntrySize > b.size()) {
      diags.push_back(fileError(codes::kImageTruncated, fileName));
      return result;
    }
    palette.resize(count);
    for (std::uint32_t i = 0; i < count; ++i) {
      const std::size_t at = afterHeader + static_cast<std::size_t>(i) * paletteEntrySize;
      palette[i] = static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
                   static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
                   static_cast<unsigned char>(b[at]);
    }
  }

  const std::size_t stride = ((static_cast<std::size_t>(width) * bitsPerPixel + 31) / 32) * 4;
  const std::size_t needed = static_cast<std::size_t>(pixelOffset) + stride * static_cast<std::size_t>(height);
  if (pixelOffset < afterHeader || pixelOffset > b.size()) return damaged("pixel data offset out of range");
  if (needed > b.size()) {
    diags.push_back(fileError(codes::kImageTruncated, fileName));
    return result;
  }

  RgbImage image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  const Channel red(masks[0]), green(masks[1]), blue(masks[2]), alpha(masks[3]);
  std::vector<std::uint8_t> alphas;
  if (alpha.mask) alphas.resize(image.pixels.size());

  for (int row = 0; row < image.height; ++row) {
    const int y = topDown ? row : image.height - 1 - row;
    const std::size_t rowStart = pixelOffset + stride * static_cast<std::size_t>(row);
    for (int x = 0; x < image.width; ++x) {
      std::uint32_t rgb = 0;
      const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      if (indexed) {
        const std::size_t bit = static_cast<std::size_t>(x) * bitsPerPixel;
        const auto byte = static_cast<unsigned char>(b[rowStart + bit / 8]);
        const unsigned shift = 8 - bitsPerPixel - static_cast<unsigned>(bit % 8);
        const std::uint32_t index = (byte >> shift) & ((1u << bitsPerPixel) - 1);
        if (index >= palette.size()) {
          diags.push_back(fileError(codes::kColourOutsidePalette, fileName,
                                    {std::to_string(index), std::to_string(palette.size())}));
          return result;
        }
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
  // Many programs write an alpha mask but leave every alpha at 0: then it means nothing.
  if (alpha.mask && std::any_of(alphas.begin(), alphas.end(), [](std::uint8_t a) { return a != 0; }))
    for (std::size_t i = 0; i < alphas.size(); ++i)
      if (alphas[i] < 128) image.pixels[i] = 0xFFFFFF;

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

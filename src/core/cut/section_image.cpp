#include "klueng/core/cut/section_image.h"
#include "klueng/core/io/program_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include <png.h>

namespace klueng::core::cut {

namespace {

constexpr std::uint32_t kBackground = 0xF7F8FA;
constexpr std::uint32_t kBarOutline = 0xC9D3DD;   // where the raw bar was
constexpr std::uint32_t kMaterial = 0xA9B4C0;
constexpr std::uint32_t kBore = 0xF7F8FA;
constexpr std::uint32_t kEdge = 0x2B3440;
constexpr std::uint32_t kJaw = 0x5A6470;
constexpr std::uint32_t kBody = 0x3A424C;
constexpr std::uint32_t kCentreLine = 0x2060C0;
constexpr std::uint32_t kNose = 0xD02020;
constexpr std::uint32_t kRapidPath = 0xD04040;
constexpr std::uint32_t kFeedPath = 0x2050D0;
constexpr std::uint32_t kThreadPath = 0x109040;

struct Canvas {
  io::RgbImage img;
  double z0 = 0.0;    // Z at the left edge
  double xTop = 0.0;  // signed radius at the top edge
  double ppm = 1.0;
  int px(double z) const { return static_cast<int>(std::floor((z - z0) * ppm)); }
  int py(double x) const { return static_cast<int>(std::floor((xTop - x) * ppm)); }
  void set(int x, int y, std::uint32_t c) {
    if (x >= 0 && y >= 0 && x < img.width && y < img.height) img.pixels[static_cast<std::size_t>(y) * img.width + x] = c;
  }
  // Fills the box z in [za, zb], signed radius in [xa, xb].
  void fill(double za, double zb, double xa, double xb, std::uint32_t c) {
    const int x0 = std::max(0, px(za)), x1 = std::min(img.width - 1, px(zb) - (std::fmod((zb - z0) * ppm, 1.0) == 0 ? 1 : 0));
    const int y0 = std::max(0, py(xb)), y1 = std::min(img.height - 1, py(xa) - (std::fmod((xTop - xa) * ppm, 1.0) == 0 ? 1 : 0));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) img.pixels[static_cast<std::size_t>(y) * img.width + x] = c;
  }
  void frame(double za, double zb, double xa, double xb, std::uint32_t c) {
    const int x0 = px(za), x1 = px(zb), y0 = py(xb), y1 = py(xa);
    for (int x = x0; x <= x1; ++x) {
      set(x, y0, c);
      set(x, y1, c);
    }
    for (int y = y0; y <= y1; ++y) {
      set(x0, y, c);
      set(x1, y, c);
    }
  }
};

}  // namespace

io::RgbImage renderSection(const SectionView& view) {
  Canvas cv;
  if (!view.stock) return cv.img;
  const Stock& stock = *view.stock;
  const double r = stock.diameter() / 2.0;
  double zMin = -stock.length() - 5.0, zMax = 5.0, xMax = r + 5.0;
  if (view.chuck) {
    zMin = std::min(zMin, view.chuck->bodyZMin() - 2.0);
    xMax = std::max(xMax, view.chuck->bodyXMax() + 2.0);
  }
  if (view.tool) {
    const Box& b = view.tool->bounds;
    zMin = std::min(zMin, view.toolPosition.x() + b.z0 - 2.0);
    zMax = std::max(zMax, view.toolPosition.x() + b.z1 + 2.0);
    xMax = std::max(xMax, view.toolPosition.y() + b.x1 + 2.0);
  }
  const double xMin = -std::max(r + 5.0, view.chuck ? view.chuck->bodyXMax() + 2.0 : 0.0);
  double ppm = view.pixelsPerMm;
  if (ppm <= 0.0) ppm = std::min(view.maxWidth / (zMax - zMin), view.maxHeight / (xMax - xMin));
  ppm = std::clamp(ppm, 0.05, 200.0);
  cv.ppm = ppm;
  cv.z0 = zMin;
  cv.xTop = xMax;
  cv.img.width = std::max(1, static_cast<int>(std::ceil((zMax - zMin) * ppm)));
  cv.img.height = std::max(1, static_cast<int>(std::ceil((xMax - xMin) * ppm)));
  cv.img.pixels.assign(static_cast<std::size_t>(cv.img.width) * cv.img.height, kBackground);

  // The raw bar (a tube: its ring), faintly, so the removed material shows.
  const double b = stock.bore() / 2.0;
  cv.fill(-stock.length(), 0.0, b, r, kBarOutline);
  cv.fill(-stock.length(), 0.0, -r, -b, kBarOutline);

  // The part, both halves: per image column, the material of the stock column under its centre.
  std::vector<std::uint8_t> mask(cv.img.pixels.size(), 0);
  for (int x = 0; x < cv.img.width; ++x) {
    const int i = stock.columnAt(zMin + (x + 0.5) / ppm);
    if (i < 0) continue;
    for (const Interval& in : stock.column(i)) {
      for (int sign : {1, -1}) {
        const double a = sign > 0 ? in.lo : -in.hi, b = sign > 0 ? in.hi : -in.lo;
        const int y0 = std::max(0, static_cast<int>(std::ceil((xMax - b) * ppm - 0.5)));
        const int y1 = std::min(cv.img.height - 1, static_cast<int>(std::floor((xMax - a) * ppm - 0.5)));
        for (int y = y0; y <= y1; ++y) mask[static_cast<std::size_t>(y) * cv.img.width + x] = 1;
      }
    }
  }
  for (int y = 0; y < cv.img.height; ++y)
    for (int x = 0; x < cv.img.width; ++x) {
      const std::size_t k = static_cast<std::size_t>(y) * cv.img.width + x;
      if (!mask[k]) continue;
      auto empty = [&](int xx, int yy) {
        return xx < 0 || yy < 0 || xx >= cv.img.width || yy >= cv.img.height ||
               !mask[static_cast<std::size_t>(yy) * cv.img.width + xx];
      };
      const bool edge = empty(x - 1, y) || empty(x + 1, y) || empty(x, y - 1) || empty(x, y + 1);
      cv.img.pixels[k] = edge ? kEdge : kMaterial;
    }
  (void)kBore;

  if (view.chuck) {
    const Chuck& c = *view.chuck;
    for (int sign : {1, -1}) {
      const double s = sign;
      cv.fill(c.jawZMin(), c.jawZMax(), std::min(s * c.jawXMin(), s * c.jawXMax()),
              std::max(s * c.jawXMin(), s * c.jawXMax()), kJaw);
      cv.frame(c.jawZMin(), c.jawZMax(), std::min(s * c.jawXMin(), s * c.jawXMax()),
               std::max(s * c.jawXMin(), s * c.jawXMax()), kEdge);
    }
    cv.fill(c.bodyZMin(), c.bodyZMax(), c.bodyXMin(), c.bodyXMax(), kBody);  // a ring around the spindle bore
    cv.fill(c.bodyZMin(), c.bodyZMax(), -c.bodyXMax(), -c.bodyXMin(), kBody);
  }

  // Centre line, dash-dot.
  const int yc = cv.py(0.0);
  for (int x = 0; x < cv.img.width; ++x) {
    const int phase = x % 24;
    if (phase < 14 || (phase >= 17 && phase < 20)) cv.set(x, yc, kCentreLine);
  }

  if (view.path) {
    for (const machine::Move& m : view.path->moves) {
      if (m.tStart > view.pathUntil || m.kind == machine::MoveKind::Dwell) break;
      const double sEnd = m.tEnd > view.pathUntil && m.tEnd > m.tStart
                              ? (view.pathUntil - m.tStart) / (m.tEnd - m.tStart)
                              : 1.0;
      const std::uint32_t colour = m.kind == machine::MoveKind::Rapid    ? kRapidPath
                                   : m.kind == machine::MoveKind::Thread ? kThreadPath
                                                                         : kFeedPath;
      const double len = m.path.length() * sEnd;
      const int steps = std::max(1, static_cast<int>(std::ceil(len * ppm * 2)));
      for (int k = 0; k <= steps; ++k) {
        const double along = static_cast<double>(k) / steps;
        if (m.kind == machine::MoveKind::Rapid && static_cast<int>(along * len * ppm / 4) % 2 == 1) continue;
        const Vec2 p = m.path.pointAt(along * sEnd);
        cv.set(cv.px(p.x()), cv.py(p.y()), colour);
      }
    }
  }

  if (view.tool) {
    const ToolShape& t = *view.tool;
    const double pixelMm = 1.0 / t.pixelsPerMm;
    // Bitmap pixel (col,row) -> local mm relative to the controlled point.
    for (int row = 0; row < t.image.height; ++row)
      for (int col = 0; col < t.image.width; ++col) {
        const std::uint32_t c = t.image.at(col, row) & 0xFFFFFFu;
        if (c == 0xFFFFFFu) continue;
        const double za = (col - t.controlPixelX) * pixelMm + view.toolPosition.x();
        const double xb = (t.controlPixelY - row) * pixelMm + view.toolPosition.y();
        cv.fill(za, za + pixelMm, xb - pixelMm, xb, c);
      }
    if (t.noseRadius > 0.0) {
      const Vec2 centre = view.toolPosition + t.noseCentre;
      const int steps = std::max(16, static_cast<int>(t.noseRadius * ppm * 8));
      for (int k = 0; k < steps; ++k) {
        const double a = 2.0 * 3.14159265358979 * k / steps;
        cv.set(cv.px(centre.x() + t.noseRadius * std::cos(a)), cv.py(centre.y() + t.noseRadius * std::sin(a)), kNose);
      }
    }
    // The controlled point.
    const int cx = cv.px(view.toolPosition.x()), cy = cv.py(view.toolPosition.y());
    for (int d = -3; d <= 3; ++d) {
      cv.set(cx + d, cy, kNose);
      cv.set(cx, cy + d, kNose);
    }
  }
  return cv.img;
}

namespace {
void appendToString(png_structp png, png_bytep data, png_size_t length) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
}
void flushNothing(png_structp) {}
}  // namespace

// Encoded in memory, then written atomically: a full disk never leaves a truncated PNG behind.
bool writePng(const std::string& path, const io::RgbImage& image, std::string* error) {
  auto fail = [&](const std::string& why) {
    if (error) *error = why;
    return false;
  };
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    return fail("empty image");
  std::string encoded;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return fail("libpng: out of memory");
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return fail("libpng: out of memory");
  }
  std::vector<png_byte> row(static_cast<std::size_t>(image.width) * 3);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return fail("libpng: error encoding " + path);
  }
  png_set_write_fn(png, &encoded, appendToString, flushNothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint32_t c = image.at(x, y);
      row[static_cast<std::size_t>(x) * 3 + 0] = static_cast<png_byte>((c >> 16) & 0xFF);
      row[static_cast<std::size_t>(x) * 3 + 1] = static_cast<png_byte>((c >> 8) & 0xFF);
      row[static_cast<std::size_t>(x) * 3 + 2] = static_cast<png_byte>(c & 0xFF);
    }
    png_write_row(png, row.data());
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::string why;
  if (!io::writeTextFileAtomic(path, encoded, &why)) return fail(why);
  return true;
}

}  // namespace klueng::core::cut

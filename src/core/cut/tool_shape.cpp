#include "klueng/core/cut/tool_shape.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>
#include "klueng/core/comp/nose_comp.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::cut {

namespace {

enum class PixelKind { Empty, Holder, Cutting };

PixelKind classify(std::uint32_t rgb) {
  rgb &= 0xFFFFFFu;
  if (rgb == 0x000000u) return PixelKind::Holder;
  if (rgb == 0xFFFFFFu) return PixelKind::Empty;
  return PixelKind::Cutting;
}

Diagnostic toolError(std::string code, std::vector<std::string> args) {
  Diagnostic d;
  d.severity = Severity::Error;
  d.code = std::move(code);
  d.args = std::move(args);
  return d;
}

// Rectangles covering the pixels of one kind: runs per row, merged with identical runs of the rows below.
std::vector<Box> boxesOf(const io::RgbImage& image, PixelKind kind, double originZ, double originX, double ppm) {
  struct Open {
    int c0, c1, rowTop, rowBottom;
  };
  std::vector<Box> out;
  std::vector<Open> open;
  const double px = 1.0 / ppm;
  auto close = [&](const Open& o) {
    Box b;
    b.z0 = o.c0 * px - originZ;
    b.z1 = (o.c1 + 1) * px - originZ;
    b.x1 = (image.height - o.rowTop) * px - originX;
    b.x0 = (image.height - o.rowBottom - 1) * px - originX;
    out.push_back(b);
  };
  for (int row = 0; row <= image.height; ++row) {
    std::vector<std::pair<int, int>> runs;
    if (row < image.height) {
      for (int col = 0; col < image.width;) {
        if (classify(image.at(col, row)) != kind) {
          ++col;
          continue;
        }
        int end = col;
        while (end + 1 < image.width && classify(image.at(end + 1, row)) == kind) ++end;
        runs.emplace_back(col, end);
        col = end + 1;
      }
    }
    std::vector<Open> next;
    for (const Open& o : open) {
      auto it = std::find(runs.begin(), runs.end(), std::make_pair(o.c0, o.c1));
      if (it != runs.end()) {
        next.push_back({o.c0, o.c1, o.rowTop, row});
        runs.erase(it);
      } else {
        close(o);
      }
    }
    for (const auto& r : runs) next.push_back({r.first, r.second, row, row});
    open = std::move(next);
  }
  return out;
}

// Sharp tools (R = 0): per pixel column with a single run of cutting pixels,
// bottom and top go straight from this column's centre to the neighbour's
// centre (when the neighbour also has a single run); elsewhere pixel boxes.
std::vector<Trapezoid> smoothedEdge(const io::RgbImage& image, double originZ, double originX, double ppm) {
  const double px = 1.0 / ppm;
  struct Run {
    bool single = false;
    double bottom = 0.0, top = 0.0;
  };
  std::vector<Run> runs(static_cast<std::size_t>(image.width));
  std::vector<Trapezoid> out;
  for (int col = 0; col < image.width; ++col) {
    int count = 0, rowTop = -1, rowBottom = -1;
    for (int row = 0; row < image.height; ++row) {
      const bool cut = classify(image.at(col, row)) == PixelKind::Cutting;
      const bool above = row > 0 && classify(image.at(col, row - 1)) == PixelKind::Cutting;
      if (cut && !above) {
        ++count;
        rowTop = row;
      }
      if (cut) rowBottom = row;
    }
    Run& r = runs[static_cast<std::size_t>(col)];
    r.single = count == 1;
    r.top = (image.height - rowTop) * px - originX;
    r.bottom = (image.height - rowBottom - 1) * px - originX;
  }
  // Columns with several runs keep their pixel boxes.
  for (const Box& b : boxesOf(image, PixelKind::Cutting, originZ, originX, ppm)) {
    const int col0 = static_cast<int>(std::lround((b.z0 + originZ) * ppm));
    const int col1 = static_cast<int>(std::lround((b.z1 + originZ) * ppm));
    for (int col = col0; col < col1; ++col)
      if (!runs[static_cast<std::size_t>(col)].single)
        out.push_back(Trapezoid::of(Box{col * px - originZ, (col + 1) * px - originZ, b.x0, b.x1}));
  }
  for (int col = 0; col < image.width; ++col) {
    const Run& r = runs[static_cast<std::size_t>(col)];
    if (!r.single) continue;
    const double zl = col * px - originZ, zc = zl + px / 2, zr = zl + px;
    auto joins = [&](int other) {
      if (other < 0 || other >= image.width) return false;
      const Run& o = runs[static_cast<std::size_t>(other)];
      return o.single && o.bottom < r.top && r.bottom < o.top;  // touching runs: one outline
    };
    auto half = [&](int other, double zFrom, double zTo, bool leftHalf) {
      double bottomEdge = r.bottom, topEdge = r.top;
      if (joins(other)) {
        const Run& o = runs[static_cast<std::size_t>(other)];
        bottomEdge = (r.bottom + o.bottom) / 2;
        topEdge = (r.top + o.top) / 2;
      }
      if (leftHalf)
        out.push_back({zFrom, zTo, bottomEdge, r.bottom, topEdge, r.top});
      else
        out.push_back({zFrom, zTo, r.bottom, bottomEdge, r.top, topEdge});
    };
    half(col - 1, zl, zc, true);
    half(col + 1, zc, zr, false);
  }
  return out;
}

// Box minus the nose square q: up to four boxes.
void subtract(const Box& b, const Box& q, std::vector<Box>& out) {
  if (b.z1 <= q.z0 || b.z0 >= q.z1 || b.x1 <= q.x0 || b.x0 >= q.x1) {
    out.push_back(b);
    return;
  }
  if (b.z0 < q.z0) out.push_back({b.z0, q.z0, b.x0, b.x1});
  if (b.z1 > q.z1) out.push_back({q.z1, b.z1, b.x0, b.x1});
  const double z0 = std::max(b.z0, q.z0), z1 = std::min(b.z1, q.z1);
  if (b.x0 < q.x0) out.push_back({z0, z1, b.x0, q.x0});
  if (b.x1 > q.x1) out.push_back({z0, z1, q.x1, b.x1});
}

void grow(Box& bounds, const Box& b, bool& first) {
  if (first) {
    bounds = b;
    first = false;
    return;
  }
  bounds.z0 = std::min(bounds.z0, b.z0);
  bounds.z1 = std::max(bounds.z1, b.z1);
  bounds.x0 = std::min(bounds.x0, b.x0);
  bounds.x1 = std::max(bounds.x1, b.x1);
}

}  // namespace

io::ReadResult<ToolShape> makeToolShape(const io::RgbImage& image, const std::string& fileName, double noseRadius,
                                        int tip, double pixelsPerMm) {
  io::ReadResult<ToolShape> result;
  const double ppm = pixelsPerMm > 0.0 ? pixelsPerMm : kPixelsPerMm;
  const int maxPixels = maxToolPixels(ppm);
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height)) {
    result.diagnostics.push_back(toolError(codes::kBitmapHasNoEdge, {fileName}));
    return result;
  }
  if (image.width > maxPixels || image.height > maxPixels) {
    result.diagnostics.push_back(
        toolError(codes::kBitmapTooLarge,
                  {fileName, std::to_string(image.width), std::to_string(image.height), std::to_string(maxPixels)}));
    return result;
  }
  int c0 = image.width, c1 = -1, r0 = image.height, r1 = -1;
  for (int row = 0; row < image.height; ++row)
    for (int col = 0; col < image.width; ++col)
      if (classify(image.at(col, row)) == PixelKind::Cutting) {
        c0 = std::min(c0, col);
        c1 = std::max(c1, col);
        r0 = std::min(r0, row);
        r1 = std::max(r1, row);
      }
  if (c1 < 0) {
    result.diagnostics.push_back(toolError(codes::kBitmapHasNoEdge, {fileName}));
    return result;
  }

  const double px = 1.0 / ppm;
  const double zMin = c0 * px, zMax = (c1 + 1) * px;
  const double xMin = (image.height - r1 - 1) * px, xMax = (image.height - r0) * px;
  const Vec2 t = comp::tipVector(tip);
  const double pz = t.x() < 0 ? zMin : t.x() > 0 ? zMax : (zMin + zMax) / 2;
  const double pxr = t.y() < 0 ? xMin : t.y() > 0 ? xMax : (xMin + xMax) / 2;

  ToolShape shape;
  shape.noseRadius = noseRadius > 0.0 ? noseRadius : 0.0;
  shape.tip = tip;
  shape.noseCentre = -shape.noseRadius * t;
  shape.image = image;
  shape.fileName = fileName;
  shape.pixelsPerMm = ppm;
  shape.controlPixelX = pz * ppm;
  shape.controlPixelY = image.height - pxr * ppm;

  shape.holder = boxesOf(image, PixelKind::Holder, pz, pxr, ppm);
  const double r = shape.noseRadius;
  if (r > 0.0) {
    // The nose square: where the exact circle, not the pixels, is the edge.
    const Vec2 c = shape.noseCentre;
    auto range = [r](double centre, double dir, double& lo, double& hi) {
      lo = dir > 0 ? centre : centre - r;
      hi = dir < 0 ? centre : centre + r;
    };
    Box q;
    range(c.x(), t.x(), q.z0, q.z1);
    range(c.y(), t.y(), q.x0, q.x1);
    std::vector<Box> boxes;
    for (const Box& b : boxesOf(image, PixelKind::Cutting, pz, pxr, ppm)) subtract(b, q, boxes);
    for (const Box& b : boxes) shape.cutting.push_back(Trapezoid::of(b));
  } else {
    shape.cutting = smoothedEdge(image, pz, pxr, ppm);
  }

  bool first = true;
  for (const Trapezoid& t : shape.cutting) grow(shape.bounds, t.bounds(), first);
  for (const Box& b : shape.holder) grow(shape.bounds, b, first);
  const Vec2 c = shape.noseCentre;
  grow(shape.bounds, Box{c.x() - r, c.x() + r, c.y() - r, c.y() + r}, first);
  result.value = std::move(shape);
  return result;
}

io::ReadResult<ToolShape> loadToolShape(const std::string& path, double noseRadius, int tip, double pixelsPerMm) {
  io::ReadResult<io::RgbImage> image = io::readImage(path);
  io::ReadResult<ToolShape> result;
  result.diagnostics = image.diagnostics;
  if (!image.value || hasErrors(image.diagnostics)) {
    if (!hasErrors(result.diagnostics)) result.diagnostics.push_back(toolError(codes::kBitmapHasNoEdge, {path}));
    return result;
  }
  io::ReadResult<ToolShape> shape = makeToolShape(*image.value, path, noseRadius, tip, pixelsPerMm);
  result.value = std::move(shape.value);
  result.diagnostics.insert(result.diagnostics.end(), shape.diagnostics.begin(), shape.diagnostics.end());
  return result;
}

}  // namespace klueng::core::cut

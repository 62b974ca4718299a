#include "klueng/core/cut/tool_shape.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

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
std::vector<Box> boxesOf(const io::RgbImage& image, PixelKind kind, double originZ, double originX) {
  struct Open {
    int c0, c1, rowTop, rowBottom;
  };
  std::vector<Box> out;
  std::vector<Open> open;
  const double px = 1.0 / kPixelsPerMm;
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
                                        int tip) {
  io::ReadResult<ToolShape> result;
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height)) {
    result.diagnostics.push_back(toolError("A310", {fileName}));
    return result;
  }
  if (image.width > kMaxToolPixels || image.height > kMaxToolPixels) {
    result.diagnostics.push_back(toolError(
        "A311", {fileName, std::to_string(image.width), std::to_string(image.height), std::to_string(kMaxToolPixels)}));
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
    result.diagnostics.push_back(toolError("A310", {fileName}));
    return result;
  }

  const double px = 1.0 / kPixelsPerMm;
  const double zMin = c0 * px, zMax = (c1 + 1) * px;
  const double xMin = (image.height - r1 - 1) * px, xMax = (image.height - r0) * px;
  const Vec2 t = tipVector(tip);
  const double pz = t.x() < 0 ? zMin : t.x() > 0 ? zMax : (zMin + zMax) / 2;
  const double pxr = t.y() < 0 ? xMin : t.y() > 0 ? xMax : (xMin + xMax) / 2;

  ToolShape shape;
  shape.noseRadius = noseRadius > 0.0 ? noseRadius : 0.0;
  shape.tip = tip;
  shape.noseCentre = -shape.noseRadius * t;
  shape.image = image;
  shape.fileName = fileName;
  shape.controlPixelX = pz * kPixelsPerMm;
  shape.controlPixelY = image.height - pxr * kPixelsPerMm;

  const std::vector<Box> cutting = boxesOf(image, PixelKind::Cutting, pz, pxr);
  shape.holder = boxesOf(image, PixelKind::Holder, pz, pxr);
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
    for (const Box& b : cutting) subtract(b, q, shape.cutting);
  } else {
    shape.cutting = cutting;
  }

  bool first = true;
  for (const Box& b : shape.cutting) grow(shape.bounds, b, first);
  for (const Box& b : shape.holder) grow(shape.bounds, b, first);
  const Vec2 c = shape.noseCentre;
  grow(shape.bounds, Box{c.x() - r, c.x() + r, c.y() - r, c.y() + r}, first);
  result.value = std::move(shape);
  return result;
}

io::ReadResult<ToolShape> loadToolShape(const std::string& path, double noseRadius, int tip) {
  io::ReadResult<io::RgbImage> image = io::readImage(path);
  io::ReadResult<ToolShape> result;
  result.diagnostics = image.diagnostics;
  if (!image.value || hasErrors(image.diagnostics)) {
    if (!hasErrors(result.diagnostics)) result.diagnostics.push_back(toolError("A310", {path}));
    return result;
  }
  io::ReadResult<ToolShape> shape = makeToolShape(*image.value, path, noseRadius, tip);
  result.value = std::move(shape.value);
  result.diagnostics.insert(result.diagnostics.end(), shape.diagnostics.begin(), shape.diagnostics.end());
  return result;
}

}  // namespace klueng::core::cut

#pragma once
// A cutting tool built from its bitmap (SPEC 11: 2 px/mm, or a library
// tool's own resolution; black 0x000000 =
// holder, white 0xFFFFFF = empty, any other colour = cutting edge) and the
// active offset's nose radius R and tip number.
//
// Local coordinates: mm, (z, x radius), origin at the CONTROLLED POINT, which is
// the corner / edge middle / centre of the cutting pixels' bounding box in the
// direction tipVector(tip). The nose is exact: a circle of radius R centred at
// -R * tipVector(tip). Cutting pixels inside the nose square (the R x R box(es)
// between the controlled point and the nose centre) are dropped so that only the
// circle cuts there; everywhere else the bitmap (0.5 mm pixels) is the edge.
// With R = 0 (e.g. a threading tool) the edge's bottom and top run straight
// between the centres of neighbouring pixel columns instead of in 0.5 mm steps,
// so a V drawn in pixels cuts a V, not a staircase; the bounding box and so the
// controlled point are unchanged.
#include <string>
#include <vector>

#include "klueng/core/geometry.h"
#include "klueng/core/io/image.h"
#include "klueng/core/io/result.h"
#include "klueng/core/io/tool_config.h"

namespace klueng::core::cut {

constexpr double kPixelsPerMm = io::kSeedPixelsPerMm;     // the seed's resolution (SPEC 11)
constexpr int kMaxToolPixels = io::kMaxToolBitmapPixels;  // a tool bitmap is at most 500 mm each way (at 2 px/mm)
// The pixel limit at a bitmap's own resolution: 500 mm each way.
constexpr int maxToolPixels(double pixelsPerMm) { return io::maxToolBitmapPixels(pixelsPerMm); }

struct Box {
  double z0 = 0.0, z1 = 0.0;  // z0 <= z1
  double x0 = 0.0, x1 = 0.0;  // x0 <= x1
};

// A vertical strip of cutting edge: z in [z0, z1], x between a straight bottom
// (bottom0 at z0 .. bottom1 at z1) and a straight top (top0 .. top1).
struct Trapezoid {
  double z0 = 0.0, z1 = 0.0;
  double bottom0 = 0.0, bottom1 = 0.0;
  double top0 = 0.0, top1 = 0.0;
  static Trapezoid of(const Box& b) { return {b.z0, b.z1, b.x0, b.x0, b.x1, b.x1}; }
  double bottomAt(double z) const { return z1 > z0 ? bottom0 + (bottom1 - bottom0) * (z - z0) / (z1 - z0) : bottom0; }
  double topAt(double z) const { return z1 > z0 ? top0 + (top1 - top0) * (z - z0) / (z1 - z0) : top0; }
  Box bounds() const { return {z0, z1, bottom0 < bottom1 ? bottom0 : bottom1, top0 > top1 ? top0 : top1}; }
};

struct ToolShape {
  double noseRadius = 0.0;
  int tip = 0;
  Vec2 noseCentre = Vec2::Zero();  // relative to the controlled point
  std::vector<Trapezoid> cutting;  // cutting-edge region minus the nose square
  std::vector<Box> holder;         // black pixels
  Box bounds;                      // of everything, including the nose circle
  // For drawing: the bitmap and the controlled point in pixel units
  // (x to the right from the image's left edge, y down from its top edge).
  io::RgbImage image;
  double controlPixelX = 0.0;
  double controlPixelY = 0.0;
  double pixelsPerMm = kPixelsPerMm;  // the bitmap's resolution
  std::string fileName;
};

// Refuses (A310) a bitmap with no cutting pixels and (A311) one larger than
// kMaxToolPixels; diagnostics name the file.
// pixelsPerMm: the bitmap's resolution (2 for the seed's plain bitmaps; a
// library tool's own, e.g. 10). Limit: maxToolPixels(pixelsPerMm).
io::ReadResult<ToolShape> makeToolShape(const io::RgbImage& image, const std::string& fileName, double noseRadius,
                                        int tip, double pixelsPerMm = kPixelsPerMm);
// readImage (F1xx for missing / malformed / oversized files) + makeToolShape.
io::ReadResult<ToolShape> loadToolShape(const std::string& path, double noseRadius, int tip,
                                        double pixelsPerMm = kPixelsPerMm);

}  // namespace klueng::core::cut

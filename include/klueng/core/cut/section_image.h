#pragma once
// The section view as a raster (no Qt): both halves of the part mirrored about
// the centre line, the chuck, and the tool at its position drawn from its
// bitmap. Used by `klueng-cli simulate --png`; the GUI draws with its own renderer.
#include <optional>
#include <string>

#include "klueng/core/cut/stock.h"
#include "klueng/core/cut/tool_shape.h"
#include "klueng/core/geometry.h"
#include "klueng/core/io/image.h"
#include "klueng/core/machine/timeline.h"

namespace klueng::core::cut {

struct SectionView {
  const Stock* stock = nullptr;
  const Chuck* chuck = nullptr;
  const ToolShape* tool = nullptr;   // may be null
  Vec2 toolPosition = Vec2::Zero();  // controlled point
  // Optional: the controlled point's path up to `pathUntil` seconds, drawn on the
  // upper half (rapids dashed red, feeds blue, threading green).
  const machine::Timeline* path = nullptr;
  double pathUntil = 1e300;
  double pixelsPerMm = 0.0;          // 0 = fit into maxWidth x maxHeight
  int maxWidth = 2400;
  int maxHeight = 1600;
};

io::RgbImage renderSection(const SectionView& view);

// 8-bit RGB PNG through libpng. Returns false and fills error on failure.
bool writePng(const std::string& path, const io::RgbImage& image, std::string* error = nullptr);

}  // namespace klueng::core::cut

#pragma once
// What the section picture shows (no Qt here: klueng-cli fills it and hands it
// to the picture module, which draws it with the output screen's painters,
// section_painter.h). Issue 12: one renderer for the screen, print and --png.
#include <cstddef>

#include "klueng/core/cut/stock.h"
#include "klueng/core/cut/tool_shape.h"
#include "klueng/core/machine/timeline.h"

namespace klueng::render {

struct SectionPicture {
  const core::cut::Stock* stock = nullptr;
  const core::cut::Chuck* chuck = nullptr;
  const core::cut::ToolShape* tool = nullptr;    // may be null
  core::Vec2 toolPosition = core::Vec2::Zero();  // controlled point
  const core::machine::Timeline* path = nullptr;
  double pathUntil = 1e300;  // seconds
  int maxWidth = 2400;       // pixels; the scene is fitted inside
  int maxHeight = 1600;
};

}  // namespace klueng::render

// The module's one entry point (klueng-png.so): PNG bytes of the picture in a
// malloc'ed buffer the caller frees; 0 when it cannot be drawn or encoded.
extern "C" int klueng_section_png(const klueng::render::SectionPicture* picture, char** bytes, std::size_t* size);
using KluengSectionPngFn = int (*)(const klueng::render::SectionPicture*, char**, std::size_t*);

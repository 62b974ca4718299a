// libFuzzer target: a tool bitmap (BMP or PNG bytes) as tools.cfg would name it,
// decoded and turned into a cutting tool for every tip and a few nose radii.
// The first byte picks the nose radius and tip, the second the resolution.
// Beyond "no crash": a shape lies inside its bounds, its nose sits where the
// tip says, and every refusal has a message in both languages.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "klueng/core/comp/nose_comp.h"
#include "klueng/core/cut/tool_shape.h"
#include "klueng/core/geometry.h"
#include "klueng/core/io/image.h"
#include "klueng/core/messages.h"

using namespace klueng::core;

namespace {

template <typename T>
void requireMessages(const io::ReadResult<T>& r) {
  for (const Diagnostic& d : r.diagnostics)
    if (!findMessage(d.code) || formatMessage(d, Lang::Th).empty()) std::abort();
}

bool inside(const cut::Box& b, const cut::Box& outer) {
  constexpr double e = 1e-9;
  return b.z0 >= outer.z0 - e && b.z1 <= outer.z1 + e && b.x0 >= outer.x0 - e && b.x1 <= outer.x1 + e && b.z0 <= b.z1 &&
         b.x0 <= b.x1;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const double noseRadius = (data[0] >> 4) * 0.2;  // 0 .. 3 mm
  const int tip = data[0] % 10;
  const double pixelsPerMm = data[1] % 2 ? 2.0 : 10.0;
  const std::string_view bytes(reinterpret_cast<const char*>(data + 2), size - 2);
  const auto image = io::decodeImage(bytes, size % 2 ? "tool.bmp" : "tool.png");
  requireMessages(image);
  if (!image.value) return 0;
  const io::RgbImage& img = *image.value;
  if (img.width <= 0 || img.height <= 0 ||
      img.pixels.size() != static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height))
    std::abort();

  const auto shape = cut::makeToolShape(img, "tool.bmp", noseRadius, tip, pixelsPerMm);
  requireMessages(shape);
  if (!shape.value) return 0;
  const cut::ToolShape& s = *shape.value;
  if (!std::isfinite(s.bounds.z0) || !std::isfinite(s.bounds.x1)) std::abort();
  for (const cut::Trapezoid& t : s.cutting)
    if (!inside(t.bounds(), s.bounds)) std::abort();
  for (const cut::Box& b : s.holder)
    if (!inside(b, s.bounds)) std::abort();
  // The nose circle is R from the controlled point, against the tip's direction.
  if ((s.noseCentre + noseRadius * comp::tipVector(tip)).norm() > 1e-9) std::abort();
  return 0;
}

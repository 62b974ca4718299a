#pragma once
// The shaded 3D view of the stock (issue 10, item 5), painted with QPainter so
// it runs the same on a desktop, under Xvfb and offscreen: the stock model's
// outside and bore profiles turned about the Z axis into flat-shaded quads, a
// quarter cut away so bores, grooves and thread teeth show in section; the
// chuck body and the tool (in the upper section plane, where the 2-D view
// draws it). Orthographic camera: yaw about the vertical, pitch, zoom, pan.
#include <QPainter>
#include <QPointF>
#include <QRectF>
#include <vector>

#include "klueng/core/cut/stock.h"
#include "klueng/core/geometry.h"

namespace klueng::render {

struct Camera3D {
  double yaw = 30.0;    // degrees about the vertical axis (0 = from the front, Z to the right; + shows the right end)
  double pitch = 24.0;  // degrees above the horizontal
  double zoom = 1.0;    // 1 = the whole scene fits the viewport
  QPointF pan;          // pixels
  bool cutaway = true;  // a quarter (up-front) removed
};

struct Scene3D {
  const core::cut::Stock* stock = nullptr;
  const core::cut::Chuck* chuck = nullptr;
  // The tool in the upper section plane: polygons in (z, radius) work units.
  std::vector<std::vector<core::Vec2>> toolCutting;
  std::vector<std::vector<core::Vec2>> toolHolder;
  int angularSteps = 48;  // around the full turn
};

// The stock's profile as a polyline (z, r) from its left end to its right end,
// simplified to within `tolerance` mm (corners, steps and thread teeth stay).
std::vector<core::Vec2> simplifiedProfile(const core::cut::Stock& stock, bool outer, double tolerance = 0.02);

// Paints the scene into `viewport` (device pixels); returns the quads drawn.
int paintPart3D(QPainter& painter, const QRectF& viewport, const Scene3D& scene, const Camera3D& camera);

}  // namespace klueng::render

#pragma once
// The drawing sheet's dimensions (issue 10, item 6), laid out from the core's
// part features: every diameter across the part, the bores, chained step
// lengths from the right face and the overall length below it, leaders for
// chamfers, radii, tapers, grooves and threads above it, and a note for the
// tool nose's radius in the inside corners. Page coordinates (device pixels).
#include <functional>
#include <vector>

#include <QFont>
#include <QLineF>
#include <QPainter>
#include <QRectF>
#include <QString>

#include "klueng/core/cut/part_features.h"
#include "klueng/core/design/part_design.h"
#include "klueng/core/units.h"

namespace klueng::render {

struct DimensionItem {
  QString text;
  QRectF textRect;                                  // where the text goes (before rotation: its box on the page)
  bool vertical = false;                            // text turned 90° (read from the right), as diameters are written
  std::vector<QLineF> lines;                        // dimension, extension and leader lines
  std::vector<std::pair<QPointF, QPointF>> arrows;  // tip, and a point the arrow points away from
};

// What the part's design says beyond its shape (issue 28 item 3): a tolerance
// written after a size ("h7", "±0.05") and a surface finish ("Ra 1.6") per
// feature. Empty functions or texts: nothing drawn. The drawing of a program
// has none; a design with tolerance fields fills these.
struct DesignMarks {
  std::function<QString(const core::cut::PartFeature&)> tolerance;
  std::function<QString(const core::cut::PartFeature&)> surfaceFinish;
};
// The marks a part design gives its drawing: its own tolerance after the Ø it
// belongs to (a general ISO 2768 class is the title block's, not each size's),
// and its roughness on the surface. `print --design` and the window's Export PDF
// of a program made in the Part Designer both use it.
DesignMarks designMarks(const core::design::PartDesign& design);

struct DimensionFrame {
  std::function<QPointF(double z, double radius)> toPage;  // part mm -> page
  double mm = 1.0;                                         // device pixels per paper millimetre
  QFont font;                                              // dimension text
  const QPaintDevice* device = nullptr;                    // for measuring text
  bool thai = false;
  QRectF bounds;                  // everything stays inside (empty: anywhere)
  std::vector<QLineF> partLines;  // the part's drawn lines on the page: labels keep off them
  DesignMarks marks;
  core::UnitFormat units;  // the dimensions' unit (the part stays in mm)
};

// A feature the drawing gives no callout: a thread's run-out, a drill's point,
// a sliver below 0.1 mm (the machine's leftovers, not the designer's sizes).
bool isMachiningTrace(const core::cut::PartFeature& f, const core::cut::PartFeatures& part);
// Does the rectangle touch any of the lines?
bool touchesAny(const QRectF& rect, const std::vector<QLineF>& lines);

std::vector<DimensionItem> layoutDimensions(const core::cut::PartFeatures& part, const DimensionFrame& frame);
void paintDimensions(QPainter& painter, const std::vector<DimensionItem>& items, const DimensionFrame& frame);
// The bounding box of everything an item draws.
QRectF dimensionBounds(const DimensionItem& item);

}  // namespace klueng::render

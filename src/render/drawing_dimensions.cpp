#include "render/drawing_dimensions.h"
#include "render/number_text.h"

#include <QFontMetricsF>

#include <algorithm>
#include <cmath>

namespace klueng::render {

namespace {

using core::cut::FeatureKind;
using core::cut::FeatureSide;
using core::cut::PartFeature;

// A size in the frame's unit: "30", "28.16" in mm; "1.750″" in inches (core/units.h).
QString num(double v, const core::UnitFormat& units) {
  return QString::fromStdString(units.size(v) + units.sizeMark());
}

QString label(const PartFeature& f, const DimensionFrame& frame) {
  return QString::fromStdString(core::cut::featureLabel(f, frame.thai ? core::Lang::Th : core::Lang::En, frame.units));
}

// The outside's largest radius at z (the faces' taller side there).
double outerRadiusAt(const core::cut::PartFeatures& part, double z) {
  double r = 0.0;
  for (const PartFeature& f : part.outside)
    if (f.zLeft - 1e-6 <= z && z <= f.zRight + 1e-6) r = std::max({r, f.diameterLeft / 2.0, f.diameterRight / 2.0});
  return r;
}

// A point of the feature on its profile (upper half), for a leader.
QPointF anchorOf(const PartFeature& f, const DimensionFrame& frame) {
  const double z = (f.zLeft + f.zRight) / 2.0;
  return frame.toPage(z, f.radiusAt(z));
}

}  // namespace

QRectF dimensionBounds(const DimensionItem& item) {
  QRectF box = item.textRect;
  for (const QLineF& l : item.lines) box = box.united(QRectF(l.p1(), l.p2()).normalized().adjusted(-1, -1, 1, 1));
  return box;
}

std::vector<DimensionItem> layoutDimensions(const core::cut::PartFeatures& part, const DimensionFrame& frame) {
  std::vector<DimensionItem> out;
  if (part.empty()) return out;
  const QFontMetricsF fm(frame.font, frame.device);
  const double mm = frame.mm;
  const double textH = fm.height();
  double maxR = 0.0;
  for (const PartFeature& f : part.outside) maxR = std::max({maxR, f.diameterLeft / 2.0, f.diameterRight / 2.0});
  const double topY = frame.toPage(part.zRight, maxR).y();
  const double bottomY = frame.toPage(part.zRight, -maxR).y();
  const auto pageX = [&](double z) { return frame.toPage(z, 0.0).x(); };

  // Diameters across the part: outside on the line's left, bores on its right.
  for (const auto* list : {&part.outside, &part.inside}) {
    for (const PartFeature& f : *list) {
      if (f.kind != FeatureKind::Cylinder && f.kind != FeatureKind::Thread) continue;
      if (std::abs(pageX(f.zRight) - pageX(f.zLeft)) < 2.5 * mm) continue;  // too short on paper to take a line
      const double zc = (f.zLeft + f.zRight) / 2.0, r = f.diameter / 2.0;
      const bool inside = f.side == FeatureSide::Inside;
      // A thread in a bore: the line spans the bore's material, its minor Ø.
      const double rLine = f.kind == FeatureKind::Thread && inside ? f.minorDiameter / 2.0 : r;
      DimensionItem d;
      d.text = f.kind == FeatureKind::Thread ? label(f, frame) : QStringLiteral("Ø") + num(f.diameter, frame.units);
      const QPointF top = frame.toPage(zc, rLine), bottom = frame.toPage(zc, -rLine);
      d.lines.emplace_back(top, bottom);
      d.arrows.emplace_back(top, bottom);
      d.arrows.emplace_back(bottom, top);
      d.vertical = true;
      const double w = fm.horizontalAdvance(d.text);
      const double centreY = frame.toPage(zc, rLine / 2.0).y();
      const double x = inside ? top.x() + 0.6 * mm : top.x() - 0.6 * mm - textH;
      d.textRect = QRectF(x, centreY - w / 2.0, textH, w);
      out.push_back(d);
    }
  }

  // Step lengths chained from the right face, and the overall length under them.
  const std::vector<double> shoulders = part.shoulderZ();
  const double row1 = bottomY + 7.0 * mm, row2 = bottomY + 15.0 * mm;
  const auto lengthItem = [&](double za, double zb, double rowY) {
    DimensionItem d;
    const double xa = pageX(za), xb = pageX(zb);
    for (const double z : {za, zb}) {
      const double from = frame.toPage(z, -outerRadiusAt(part, z)).y() + 1.0 * mm;
      d.lines.emplace_back(QPointF(pageX(z), from), QPointF(pageX(z), rowY + 1.5 * mm));
    }
    d.lines.emplace_back(QPointF(xa, rowY), QPointF(xb, rowY));
    d.arrows.emplace_back(QPointF(xa, rowY), QPointF(xb, rowY));
    d.arrows.emplace_back(QPointF(xb, rowY), QPointF(xa, rowY));
    d.text = num(za - zb, frame.units);
    const double w = fm.horizontalAdvance(d.text);
    d.textRect = QRectF((xa + xb) / 2.0 - w / 2.0, rowY - 0.3 * mm - textH, w, textH);
    return d;
  };
  for (std::size_t k = 0; k + 1 < shoulders.size() && shoulders.size() > 2; ++k)
    out.push_back(lengthItem(shoulders[k], shoulders[k + 1], row1));
  out.push_back(lengthItem(part.zRight, part.zLeft, shoulders.size() > 2 ? row2 : row1));

  // Leaders above the part: chamfers, radii, tapers, grooves; staggered so labels never overlap.
  std::vector<QRectF> placed;
  double noseRadius = 0.0;
  for (const auto* list : {&part.outside, &part.inside}) {
    for (const PartFeature& f : *list) {
      if (f.isNoseFillet()) {
        noseRadius = std::max(noseRadius, f.radius);
        continue;
      }
      if (f.kind != FeatureKind::Chamfer && f.kind != FeatureKind::Arc && f.kind != FeatureKind::Taper &&
          f.kind != FeatureKind::Groove)
        continue;
      DimensionItem d;
      d.text = label(f, frame);
      if (f.side == FeatureSide::Inside) d.text += frame.thai ? QStringLiteral(" (ใน)") : QStringLiteral(" (inside)");
      const QPointF anchor = anchorOf(f, frame);
      const double w = fm.horizontalAdvance(d.text);
      QRectF box;
      for (int level = 0; level < 12; ++level) {
        const double y = topY - 6.0 * mm - level * (textH + 1.0 * mm);
        box = QRectF(anchor.x() + 3.0 * mm, y - textH, w, textH);
        if (std::none_of(placed.begin(), placed.end(),
                         [&](const QRectF& p) { return p.adjusted(-1 * mm, 0, 1 * mm, 0).intersects(box); }))
          break;
      }
      placed.push_back(box);
      d.textRect = box;
      const QPointF knee(box.left() - 0.5 * mm, box.bottom() + 0.4 * mm);
      d.lines.emplace_back(anchor, knee);
      d.lines.emplace_back(knee, QPointF(box.right(), knee.y()));
      d.arrows.emplace_back(anchor, knee);
      out.push_back(d);
    }
  }
  if (noseRadius > 0.0) {
    DimensionItem d;
    d.text = (frame.thai ? QStringLiteral("มุมด้านในเป็นรัศมีจมูกมีด R") : QStringLiteral("Inside corners: tool nose R")) +
             num(noseRadius, frame.units);
    const double w = fm.horizontalAdvance(d.text);
    d.textRect = QRectF(pageX(part.zLeft), (shoulders.size() > 2 ? row2 : row1) + 3.0 * mm, w, textH);
    out.push_back(d);
  }
  return out;
}

void paintDimensions(QPainter& painter, const std::vector<DimensionItem>& items, const DimensionFrame& frame) {
  const double mm = frame.mm;
  painter.save();
  QPen thin(Qt::black, 0.18 * mm);
  thin.setCapStyle(Qt::FlatCap);
  painter.setFont(frame.font);
  for (const DimensionItem& d : items) {
    painter.setPen(thin);
    for (const QLineF& l : d.lines) painter.drawLine(l);
    painter.setPen(Qt::NoPen);
    painter.setBrush(Qt::black);
    for (const auto& [tip, from] : d.arrows) {
      const QPointF v = from - tip;
      const double len = std::hypot(v.x(), v.y());
      if (len <= 0.0) continue;
      const QPointF u = v / len * (2.2 * mm);
      const QPointF n(-u.y() * 0.28, u.x() * 0.28);
      painter.drawPolygon(QPolygonF({tip, tip + u + n, tip + u - n}));
    }
    painter.setBrush(Qt::NoBrush);
    painter.setPen(Qt::black);
    if (d.vertical) {
      painter.save();
      painter.translate(d.textRect.center());
      painter.rotate(-90);
      painter.drawText(QRectF(-d.textRect.height() / 2.0, -d.textRect.width() / 2.0, d.textRect.height(),
                              d.textRect.width()),
                       Qt::AlignCenter, d.text);
      painter.restore();
    } else {
      painter.drawText(d.textRect, Qt::AlignCenter, d.text);
    }
  }
  painter.restore();
}

}  // namespace klueng::render

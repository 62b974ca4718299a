#include "render/drawing_dimensions.h"
#include "render/number_text.h"
#include "render/report_text.h"

#include "klueng/core/cut/part_span.h"
#include "klueng/core/diagnostic_codes.h"

#include <QFontMetricsF>

#include <algorithm>
#include <functional>
#include <array>
#include <cmath>
#include <limits>

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

bool isMachiningTrace(const PartFeature& f, const core::cut::PartFeatures& part) {
  constexpr double kSliver = 0.1;  // mm
  switch (f.kind) {
    case FeatureKind::Chamfer:
    case FeatureKind::Taper:
      if (std::max(f.length(), std::abs(f.diameterRight - f.diameterLeft) / 2.0) < kSliver) return true;
      break;
    case FeatureKind::Arc:
      if (f.radius < kSliver) return true;
      break;
    default: return false;
  }
  if (f.kind == FeatureKind::Arc) return false;
  // A drill's point: a bevel in the bore that runs down to the axis, or one of
  // the bevels a point is fitted as, narrowing deeper down to the axis or to
  // the part's left end (a point left in the bar the part is cut from). A bevel
  // at the part's right face is the bore's mouth.
  const double smaller = std::min(f.diameterLeft, f.diameterRight);
  if (f.side == FeatureSide::Inside && smaller <= 2.0 * core::cut::kPipRadius + 0.1) return true;
  if (f.side == FeatureSide::Inside && f.diameterLeft < f.diameterRight && f.zRight < part.zRight - 0.01) {
    const auto at = std::find_if(part.inside.begin(), part.inside.end(), [&](const PartFeature& g) {
      return g.kind == f.kind && g.zLeft == f.zLeft && g.zRight == f.zRight;
    });
    for (auto g = at; g != part.inside.end(); ++g) {
      const bool narrowing =
          (g->kind == FeatureKind::Taper || g->kind == FeatureKind::Chamfer) && g->diameterLeft < g->diameterRight;
      const bool step = g->kind == FeatureKind::Cylinder && g->length() < kSliver;
      if (!narrowing && !step) break;
      if (std::min(g->diameterLeft, g->diameterRight) <= 2.0 * core::cut::kPipRadius + 0.1 ||
          g->zLeft <= part.zLeft + 0.01)
        return true;
    }
  }
  // A thread's run-out: a bevel within the thread's depth at its far end (the
  // lead-in chamfer at the start, which goes deeper than the root, is kept).
  const auto& list = f.side == FeatureSide::Inside ? part.inside : part.outside;
  for (const PartFeature& t : list) {
    if (t.kind != FeatureKind::Thread) continue;
    const double lo = std::min(t.diameter, t.minorDiameter) - 0.05, hi = std::max(t.diameter, t.minorDiameter) + 0.05;
    const bool withinDepth = smaller >= lo && std::max(f.diameterLeft, f.diameterRight) <= hi;
    const bool atFarEnd = f.zRight <= t.zLeft + t.pitch + 1e-6 && f.zRight >= t.zLeft - 3.0 * t.pitch;
    if (withinDepth && atFarEnd) return true;
  }
  return false;
}

namespace {

bool segmentTouches(const QRectF& r, const QLineF& l) {
  if (r.contains(l.p1()) || r.contains(l.p2())) return true;
  const QRectF box = QRectF(l.p1(), l.p2()).normalized();
  if (!box.adjusted(-0.5, -0.5, 0.5, 0.5).intersects(r)) return false;
  const std::array<QLineF, 4> edges = {QLineF(r.topLeft(), r.topRight()), QLineF(r.topRight(), r.bottomRight()),
                                       QLineF(r.bottomRight(), r.bottomLeft()), QLineF(r.bottomLeft(), r.topLeft())};
  return std::any_of(edges.begin(), edges.end(),
                     [&](const QLineF& e) { return l.intersects(e, nullptr) == QLineF::BoundedIntersection; });
}

// The surface-finish mark (ISO 21920-1: material removal required) standing on
// the profile at `foot`, its text over the long leg's bar.
DimensionItem finishMark(const QString& text, const QPointF& foot, double h, const QFontMetricsF& fm) {
  DimensionItem d;
  const QPointF shortTop = foot + QPointF(-h * 0.577, -h);
  const QPointF longTop = foot + QPointF(2.0 * h * 0.577, -2.0 * h);
  const double w = fm.horizontalAdvance(text);
  d.lines.emplace_back(foot, shortTop);
  d.lines.emplace_back(foot, longTop);
  d.lines.emplace_back(shortTop, foot + QPointF(h * 0.577, -h));  // the bar closing the V: machined
  d.lines.emplace_back(longTop, longTop + QPointF(w + 0.4 * h, 0.0));
  d.text = text;
  d.textRect = QRectF(longTop.x() + 0.2 * h, longTop.y() - fm.height(), w, fm.height());
  return d;
}

}  // namespace

bool touchesAny(const QRectF& rect, const std::vector<QLineF>& lines) {
  return std::any_of(lines.begin(), lines.end(), [&](const QLineF& l) { return segmentTouches(rect, l); });
}

QRectF dimensionBounds(const DimensionItem& item) {
  QRectF box = item.textRect;
  for (const QLineF& l : item.lines) box = box.united(QRectF(l.p1(), l.p2()).normalized().adjusted(-1, -1, 1, 1));
  return box;
}

namespace {

// A mark the frame's design gives a feature (its tolerance), or none.
QString designMarkOf(const std::function<QString(const PartFeature&)>& fn, const PartFeature& f) {
  return fn ? fn(f) : QString();
}

// One part's dimensions laid out on the page, a step at a time: the diameters
// across the part, the step lengths under it, the leaders above it, the surface
// finish marks and the note on the nose corners.
class DimensionLayout {
 public:
  DimensionLayout(const core::cut::PartFeatures& part, const DimensionFrame& frame)
      : part_(part),
        frame_(frame),
        fm_(frame.font, frame.device),
        mm_(frame.mm),
        textH_(fm_.height()),
        bounds_(frame.bounds.isEmpty() ? QRectF(-1e9, -1e9, 2e9, 2e9) : frame.bounds) {
    double maxR = 0.0;
    for (const PartFeature& f : part.outside) maxR = std::max({maxR, f.diameterLeft / 2.0, f.diameterRight / 2.0});
    topY_ = frame.toPage(part.zRight, maxR).y();
    bottomY_ = frame.toPage(part.zRight, -maxR).y();
  }

  std::vector<DimensionItem> layout() {
    std::vector<DimensionItem> out;
    const std::vector<QRectF> diameterTexts = addDiameters(out);
    const std::vector<double> stations = lengthStations();
    const double row1 = bottomY_ + 7.0 * mm_, row2 = bottomY_ + 15.0 * mm_;
    const double overallRow = stations.size() > 2 ? row2 : row1;
    addStepLengths(out, stations, row1, row2);
    out.push_back(lengthItem(part_.zRight, part_.zLeft, overallRow));
    addLeaders(out, diameterTexts);
    addSurfaceFinish(out);
    addNoseCornerNote(out, overallRow);
    return out;
  }

 private:
  double pageX(double z) const { return frame_.toPage(z, 0.0).x(); }

  // Diameters across the part: outside on the line's left, bores on its right;
  // each line where no other is near, each text off the part's lines and the other texts.
  // Returns where the texts went.
  std::vector<QRectF> addDiameters(std::vector<DimensionItem>& out) const {
    std::vector<double> lineXs;
    std::vector<QRectF> texts;
    for (const auto* list : {&part_.outside, &part_.inside})
      for (const PartFeature& f : *list)
        if (f.kind == FeatureKind::Cylinder || f.kind == FeatureKind::Thread) addDiameter(out, f, lineXs, texts);
    return texts;
  }

  void addDiameter(std::vector<DimensionItem>& out, const PartFeature& f, std::vector<double>& lineXs,
                   std::vector<QRectF>& texts) const {
    const double mm = mm_;
    // A step short on paper (a flange's 4 mm spigot at 1:5) still gets its Ø, on
    // its middle, unless another Ø line is drawn right there; a fin under 1 mm
    // (a ring of the bar a roughing pass stopped short of) gets none.
    const bool shortOnPaper = std::abs(pageX(f.zRight) - pageX(f.zLeft)) < 2.5 * mm;
    if (shortOnPaper && f.length() < 1.0) return;
    if (shortOnPaper && std::any_of(lineXs.begin(), lineXs.end(), [&](double x) {
          return std::abs(x - pageX((f.zLeft + f.zRight) / 2.0)) < 1.0 * mm;
        }))
      return;
    const double r = f.diameter / 2.0;
    const bool inside = f.side == FeatureSide::Inside;
    // A thread in a bore: the line spans the bore's material, its minor Ø.
    const double rLine = f.kind == FeatureKind::Thread && inside ? f.minorDiameter / 2.0 : r;
    DimensionItem d;
    d.text = f.kind == FeatureKind::Thread ? label(f, frame_) : QStringLiteral("Ø") + num(f.diameter, frame_.units);
    if (const QString tol = designMarkOf(frame_.marks.tolerance, f); !tol.isEmpty()) d.text += QLatin1Char(' ') + tol;
    double zc = (f.zLeft + f.zRight) / 2.0;
    for (const double at : {0.5, 0.3, 0.7, 0.15, 0.85}) {
      if (shortOnPaper) break;
      const double z = f.zLeft + at * f.length();
      if (std::none_of(lineXs.begin(), lineXs.end(), [&](double x) { return std::abs(x - pageX(z)) < 2.5 * mm; })) {
        zc = z;
        break;
      }
    }
    const QPointF top = frame_.toPage(zc, rLine), bottom = frame_.toPage(zc, -rLine);
    lineXs.push_back(top.x());
    d.lines.emplace_back(top, bottom);
    d.arrows.emplace_back(top, bottom);
    d.arrows.emplace_back(bottom, top);
    d.vertical = true;
    const QRectF best = placeDiameterText(d, top, bottom, inside, texts);
    d.textRect = best;
    texts.push_back(best);
    out.push_back(d);
  }

  // Where a diameter's text goes beside its line from `top` to `bottom`.
  QRectF placeDiameterText(DimensionItem& d, const QPointF& top, const QPointF& bottom, bool inside,
                           const std::vector<QRectF>& texts) const {
    const double mm = mm_, textH = textH_;
    const double w = fm_.horizontalAdvance(d.text);
    const double span = bottom.y() - top.y();
    QRectF first;
    for (const bool left : {!inside, inside}) {
      for (const double at : {0.25, 0.5, 0.75, 0.12, 0.88, 0.38, 0.62}) {
        const double x = left ? top.x() - 0.6 * mm - textH : top.x() + 0.6 * mm;
        const QRectF rect(x, top.y() + at * span - w / 2.0, textH, w);
        if (first.isNull()) first = rect;
        // Half a millimetre clear of the part's lines: a thread's teeth are close-set.
        if (!touchesAny(rect.adjusted(-0.5 * mm, -0.5 * mm, 0.5 * mm, 0.5 * mm), frame_.partLines) &&
            std::none_of(texts.begin(), texts.end(), [&](const QRectF& t) { return t.intersects(rect); }))
          return rect;
      }
    }
    // Beyond the line's upper end, the line carried on to it (a thread's teeth
    // leave no clear place across the part).
    if (!inside) {
      const QRectF above(top.x() - 0.6 * mm - textH, top.y() - 2.0 * mm - w, textH, w);
      if (!touchesAny(above, frame_.partLines) &&
          std::none_of(texts.begin(), texts.end(), [&](const QRectF& t) { return t.intersects(above); })) {
        d.lines.emplace_back(top, QPointF(top.x(), above.top()));
        return above;
      }
    }
    return first;  // nowhere clear (a part too small on paper): the usual place
  }

  // The Z stations the step lengths are chained between, from the right face to the left.
  std::vector<double> lengthStations() const {
    const core::cut::PartFeatures& part = part_;
    // A taper's ends are stations too: a cylinder running into a taper has no face,
    // and without them the drawing would not say where the taper starts.
    std::vector<double> shoulders = part.shoulderZ();
    for (const auto* list : {&part.outside, &part.inside})
      for (const PartFeature& f : *list)
        if (f.kind == FeatureKind::Taper && !isMachiningTrace(f, part)) {
          shoulders.push_back(f.zRight);
          shoulders.push_back(f.zLeft);
        }
    // Stations closer than a sliver are one (a face two columns from the part's end
    // is its end); the part's own ends are kept as they are. A groove is placed by
    // its near wall; its width is in its callout, so its far wall is no station.
    constexpr double kOneStation = 0.15;  // mm
    std::vector<double> farWalls;
    for (const auto* list : {&part.outside, &part.inside})
      for (const PartFeature& f : *list)
        if (f.kind == FeatureKind::Groove) farWalls.push_back(f.zLeft);
    std::erase_if(shoulders, [&](double z) {
      return z > part.zRight - kOneStation || z < part.zLeft + kOneStation ||
             std::any_of(farWalls.begin(), farWalls.end(), [&](double w) { return std::abs(w - z) < kOneStation; });
    });
    shoulders.push_back(part.zRight);
    shoulders.push_back(part.zLeft);
    std::sort(shoulders.begin(), shoulders.end(), std::greater<>());
    shoulders.erase(
        std::unique(shoulders.begin(), shoulders.end(), [](double a, double b) { return a - b < kOneStation; }),
        shoulders.end());
    if (shoulders.back() != part.zLeft) shoulders.back() = part.zLeft;
    return shoulders;
  }

  // A length from `za` to `zb` on the row at `rowY` under the part, its extension lines from the profile.
  DimensionItem lengthItem(double za, double zb, double rowY) const {
    const double mm = mm_;
    DimensionItem d;
    const double xa = pageX(za), xb = pageX(zb);
    for (const double z : {za, zb}) {
      const double from = frame_.toPage(z, -outerRadiusAt(part_, z)).y() + 1.0 * mm;
      d.lines.emplace_back(QPointF(pageX(z), from), QPointF(pageX(z), rowY + 1.5 * mm));
    }
    d.lines.emplace_back(QPointF(xa, rowY), QPointF(xb, rowY));
    d.arrows.emplace_back(QPointF(xa, rowY), QPointF(xb, rowY));
    d.arrows.emplace_back(QPointF(xb, rowY), QPointF(xa, rowY));
    d.text = num(za - zb, frame_.units);
    const double w = fm_.horizontalAdvance(d.text);
    d.textRect = QRectF((xa + xb) / 2.0 - w / 2.0, rowY - 0.3 * mm - textH_, w, textH_);
    return d;
  }

  // Step lengths chained from the right face (the overall length goes under them).
  void addStepLengths(std::vector<DimensionItem>& out, const std::vector<double>& shoulders, double row1,
                      double row2) const {
    std::vector<DimensionItem> chain;
    for (std::size_t k = 0; k + 1 < shoulders.size() && shoulders.size() > 2; ++k)
      chain.push_back(lengthItem(shoulders[k], shoulders[k + 1], row1));
    std::reverse(chain.begin(), chain.end());  // left to right on the page
    placeShortStepTexts(chain, row1, row2);
    for (const DimensionItem& d : chain) out.push_back(d);
  }

  // A step too short for its text gets the text beside it, left of its extension
  // lines where that is free, else under its dimension line; never on a neighbour's.
  void placeShortStepTexts(std::vector<DimensionItem>& chain, double row1, double row2) const {
    const double mm = mm_;
    const double gap = 0.8 * mm;
    std::vector<QRectF> taken;
    const auto isFree = [&](const QRectF& r) {
      return std::none_of(taken.begin(), taken.end(),
                          [&](const QRectF& t) { return t.adjusted(-gap, 0, gap, 0).intersects(r); });
    };
    for (std::size_t k = 0; k < chain.size(); ++k) {
      const double left = chain[k].lines[1].x1(), right = chain[k].lines[0].x1();  // zb is left of za
      if (chain[k].textRect.width() + 2.0 * gap > right - left) continue;          // placed in the second pass
      taken.push_back(chain[k].textRect);
    }
    for (std::size_t k = 0; k < chain.size(); ++k) {
      QRectF& box = chain[k].textRect;
      const double left = chain[k].lines[1].x1(), right = chain[k].lines[0].x1();
      if (box.width() + 2.0 * gap <= right - left) continue;
      QRectF beside = box;
      beside.moveRight(left - gap);
      QRectF besideRight = box;
      besideRight.moveLeft(right + gap);
      QRectF under = box, underLower = box;
      under.moveTop(row1 + 0.5 * mm);
      underLower.moveTop(under.bottom() + 0.3 * mm);
      if (isFree(beside))
        box = beside;
      else if (isFree(under))
        box = under;
      else if (isFree(underLower) && underLower.bottom() < row2 - 0.5 * mm)
        box = underLower;
      else if (isFree(besideRight))
        box = besideRight;
      else {
        while (!isFree(under)) under.translate(box.width() + gap, 0.0);
        box = under;
      }
      taken.push_back(box);
    }
  }

  // Leaders above the part: chamfers, radii, tapers, grooves; staggered so labels
  // never overlap, turned to the anchor's left where the frame ends on its right.
  void addLeaders(std::vector<DimensionItem>& out, const std::vector<QRectF>& diameterTexts) const {
    std::vector<QRectF> placed = diameterTexts;  // the diameters' texts too: a leader's label keeps off them
    for (const auto* list : {&part_.outside, &part_.inside}) {
      for (const PartFeature& f : *list) {
        if (f.isNoseFillet()) continue;
        if (f.kind != FeatureKind::Chamfer && f.kind != FeatureKind::Arc && f.kind != FeatureKind::Taper &&
            f.kind != FeatureKind::Groove)
          continue;
        if (isMachiningTrace(f, part_)) continue;
        out.push_back(leaderItem(f, placed));
      }
    }
  }

  // One feature's leader, its label on the lowest level clear of those `placed` (and added to them).
  DimensionItem leaderItem(const PartFeature& f, std::vector<QRectF>& placed) const {
    const double mm = mm_, textH = textH_;
    DimensionItem d;
    d.text = label(f, frame_);
    if (f.side == FeatureSide::Inside)
      d.text = reportText(core::codes::kReportInside, frame_.thai ? ReportLanguage::Thai : ReportLanguage::English,
                          {d.text});
    const QPointF anchor = anchorOf(f, frame_);
    const double w = fm_.horizontalAdvance(d.text);
    const bool toLeft = anchor.x() + 3.0 * mm + w > bounds_.right();
    QRectF box;
    for (int level = 0; level < 12; ++level) {
      const double y = topY_ - 6.0 * mm - level * (textH + 1.0 * mm);
      box = QRectF(toLeft ? anchor.x() - 3.0 * mm - w : anchor.x() + 3.0 * mm, y - textH, w, textH);
      if (box.top() < bounds_.top()) {  // no room higher up: the lowest level, beside the others
        box.moveTop(topY_ - 6.0 * mm - textH);
        break;
      }
      if (std::none_of(placed.begin(), placed.end(),
                       [&](const QRectF& p) { return p.adjusted(-3 * mm, 0, 3 * mm, 0).intersects(box); }))
        break;
    }
    box.moveLeft(std::clamp(box.left(), bounds_.left(), std::max(bounds_.left(), bounds_.right() - w)));
    placed.push_back(box);
    d.textRect = box;
    const QPointF knee(toLeft ? box.right() + 0.5 * mm : box.left() - 0.5 * mm, box.bottom() + 0.4 * mm);
    d.lines.emplace_back(anchor, knee);
    d.lines.emplace_back(knee, QPointF(toLeft ? box.left() : box.right(), knee.y()));
    d.arrows.emplace_back(anchor, knee);
    return d;
  }

  // Surface finish where the design gives one: on the upper profile of the feature.
  void addSurfaceFinish(std::vector<DimensionItem>& out) const {
    if (!frame_.marks.surfaceFinish) return;
    for (const auto* list : {&part_.outside, &part_.inside}) {
      for (const PartFeature& f : *list) {
        const QString ra = frame_.marks.surfaceFinish(f);
        if (ra.isEmpty()) continue;
        const double z = f.zLeft + 0.3 * f.length();
        const double r = f.side == FeatureSide::Inside ? -f.radiusAt(z) : f.radiusAt(z);
        out.push_back(finishMark(ra, frame_.toPage(z, r), 2.5 * mm_, fm_));
      }
    }
  }

  // The nose's fillets are no leaders: one note under the lengths gives their largest radius.
  void addNoseCornerNote(std::vector<DimensionItem>& out, double lastRow) const {
    double noseRadius = 0.0;
    for (const auto* list : {&part_.outside, &part_.inside})
      for (const PartFeature& f : *list)
        if (f.isNoseFillet()) noseRadius = std::max(noseRadius, f.radius);
    if (noseRadius <= 0.0) return;
    DimensionItem d;
    d.text = reportText(core::codes::kReportNoseCorners, frame_.thai ? ReportLanguage::Thai : ReportLanguage::English,
                        {num(noseRadius, frame_.units)});
    const double w = fm_.horizontalAdvance(d.text);
    d.textRect = QRectF(pageX(part_.zLeft), lastRow + 3.0 * mm_, w, textH_);
    out.push_back(d);
  }

  const core::cut::PartFeatures& part_;
  const DimensionFrame& frame_;
  const QFontMetricsF fm_;
  const double mm_;
  const double textH_;
  const QRectF bounds_;
  double topY_ = 0.0;
  double bottomY_ = 0.0;
};

}  // namespace

std::vector<DimensionItem> layoutDimensions(const core::cut::PartFeatures& part, const DimensionFrame& frame) {
  if (part.empty()) return {};
  return DimensionLayout(part, frame).layout();
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
      painter.drawText(
          QRectF(-d.textRect.height() / 2.0, -d.textRect.width() / 2.0, d.textRect.height(), d.textRect.width()),
          Qt::AlignCenter, d.text);
      painter.restore();
    } else {
      painter.drawText(d.textRect, Qt::AlignCenter, d.text);
    }
  }
  painter.restore();
}

DesignMarks designMarks(const core::design::PartDesign& design) {
  const std::vector<core::cut::DrawnDimension> drawn = core::design::drawnDimensions(design);
  struct Finish {
    core::cut::FeatureSide side;
    double diameter, zRight, zLeft, ra;
  };
  std::vector<Finish> finishes;
  for (const auto side : {core::cut::FeatureSide::Outside, core::cut::FeatureSide::Inside}) {
    double z = 0.0;
    for (const core::design::OutsideStep& s :
         side == core::cut::FeatureSide::Outside ? design.outside : design.inside) {
      if (s.kind == core::design::StepKind::Cylinder && s.roughness > 0.0)
        finishes.push_back({side, s.diameter, z, z - s.length, s.roughness});
      z -= s.length;
    }
  }
  DesignMarks marks;
  marks.surfaceFinish = [finishes](const core::cut::PartFeature& f) {
    if (f.kind != core::cut::FeatureKind::Cylinder) return QString();
    for (const Finish& s : finishes)
      if (s.side == f.side && std::abs(s.diameter - f.diameter) <= 0.02 &&
          std::min(s.zRight, f.zRight) > std::max(s.zLeft, f.zLeft))
        return QStringLiteral("Ra %1").arg(s.ra);
    return QString();
  };
  marks.tolerance = [drawn](const core::cut::PartFeature& f) {
    if (f.kind != core::cut::FeatureKind::Cylinder) return QString();
    for (const core::cut::DrawnDimension& d : drawn) {
      if (d.kind != core::cut::DimensionKind::Diameter || d.side != f.side || !d.tolerance.given() ||
          d.tolerance.text.rfind("ISO 2768", 0) == 0)
        continue;
      const bool overlaps = std::min(d.zRight, f.zRight) > std::max(d.zLeft, f.zLeft);
      if (overlaps && std::abs(d.nominal - f.diameter) <= 0.02) return QString::fromStdString(d.tolerance.text);
    }
    return QString();
  };
  return marks;
}

}  // namespace klueng::render

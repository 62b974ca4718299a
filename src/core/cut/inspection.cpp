// Measuring the cut part against the drawing's toleranced dimensions.
#include "klueng/core/cut/inspection.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace klueng::core::cut {

namespace {

constexpr double kZSlack = 0.1;  // mm: two stock columns, where a feature's ends are read

long long microns(double mm) { return std::llround(mm / kMeasureStep); }

std::string mm3(double v) {
  std::string s = fmt::format("{:.3f}", std::abs(v) < 5e-4 ? 0.0 : v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

std::string signedMm(double v) { return microns(v) == 0 ? std::string("0") : (v > 0 ? "+" : "") + mm3(v); }

// The diameter across the drawn span: the cylinders (or a thread's major Ø) of
// that side overlapping it, the one furthest from the zone's middle.
std::optional<double> measureDiameter(const std::vector<PartFeature>& side, const DrawnDimension& d) {
  const double middle = d.nominal + (d.tolerance.upper + d.tolerance.lower) / 2.0;
  std::optional<double> worst;
  for (const PartFeature& f : side) {
    if (f.kind != FeatureKind::Cylinder && f.kind != FeatureKind::Thread) continue;
    if (!(f.zLeft < d.zRight - kZSlack && f.zRight > d.zLeft + kZSlack)) continue;
    if (!worst || std::abs(f.diameter - middle) > std::abs(*worst - middle)) worst = f.diameter;
  }
  return worst;
}

// The Z of the part's edge nearest `z` within `window`: faces and the part's
// ends first, the ends of tapers and arcs (a shoulder without a face) else.
std::optional<double> nearestEdge(const PartFeatures& part, const std::vector<PartFeature>& side, double z,
                                  double window) {
  std::optional<double> best;
  const auto consider = [&](double at) {
    if (std::abs(at - z) <= window && (!best || std::abs(at - z) < std::abs(*best - z))) best = at;
  };
  consider(part.zRight);
  consider(part.zLeft);
  for (const PartFeature& f : side)
    if (f.kind == FeatureKind::Face) consider(f.zLeft);
  if (best) return best;
  for (const PartFeature& f : side)
    if (f.kind == FeatureKind::Taper || (f.kind == FeatureKind::Arc && !f.isNoseFillet())) {
      consider(f.zLeft);
      consider(f.zRight);
    }
  return best;
}

}  // namespace

double roundToMicron(double mm) { return static_cast<double>(microns(mm)) * kMeasureStep; }

double InspectedDimension::lowerLimit() const { return roundToMicron(drawn.nominal + drawn.tolerance.lower); }
double InspectedDimension::upperLimit() const { return roundToMicron(drawn.nominal + drawn.tolerance.upper); }

std::vector<InspectedDimension> inspectPart(const PartFeatures& part, const std::vector<DrawnDimension>& drawing) {
  std::vector<InspectedDimension> out;
  for (const DrawnDimension& d : drawing) {
    InspectedDimension row;
    row.drawn = d;
    const std::vector<PartFeature>& side = d.side == FeatureSide::Inside ? part.inside : part.outside;
    if (!part.empty()) {
      if (d.kind == DimensionKind::Diameter) {
        row.measured = measureDiameter(side, d);
      } else {
        const double window = std::min(5.0, std::max(2.0 * kZSlack, d.nominal / 2.0));
        const auto right = nearestEdge(part, side, d.zRight, window);
        const auto left = nearestEdge(part, side, d.zLeft, window);
        if (right && left && *right > *left) row.measured = *right - *left;
      }
    }
    if (row.measured) {
      row.measured = roundToMicron(*row.measured);
      const long long m = microns(*row.measured);
      row.verdict = m >= microns(row.lowerLimit()) && m <= microns(row.upperLimit()) ? Verdict::In : Verdict::Out;
    }
    out.push_back(std::move(row));
  }
  return out;
}

std::string dimensionLabel(const DrawnDimension& d, Lang lang) {
  const bool th = lang == Lang::Th;
  if (d.kind == DimensionKind::Diameter)
    return "Ø" + mm3(d.nominal) + (d.side == FeatureSide::Inside ? (th ? " รูใน" : " bore") : "");
  return (th ? "ยาว " : "L") + mm3(d.nominal) + " (Z" + mm3(d.zRight) + "/Z" + mm3(d.zLeft) + ")" +
         (d.side == FeatureSide::Inside ? (th ? " รูใน" : " bore") : "");
}

std::string toleranceLabel(const Tolerance& t) {
  const std::string limits = microns(t.upper) == -microns(t.lower) && microns(t.upper) != 0
                                 ? "±" + mm3(t.upper)
                                 : signedMm(t.upper) + "/" + signedMm(t.lower);
  if (t.text.empty() || t.text == limits) return limits;
  return t.text + " (" + limits + ")";
}

std::string verdictName(Verdict v, Lang lang) {
  const bool th = lang == Lang::Th;
  switch (v) {
    case Verdict::In: return th ? "อยู่ในพิกัด" : "in";
    case Verdict::Out: return th ? "นอกพิกัด" : "out";
    case Verdict::Missing: return th ? "ไม่มีบนชิ้นงาน" : "missing";
  }
  return {};
}

}  // namespace klueng::core::cut

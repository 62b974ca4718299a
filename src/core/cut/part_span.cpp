#include "klueng/core/cut/part_span.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace klueng::core::cut {

namespace {

bool isGap(const Stock& stock, int i) { return stock.outerRadius(i) <= kPipRadius + 1e-9; }

// The column still holds the bar as it came: one interval, bore to outside.
bool isUntouched(const Stock& stock, int i) {
  const auto col = stock.column(i);
  constexpr double eps = 1e-6;
  return col.size() == 1 && std::abs(col[0].hi - stock.diameter() / 2.0) < eps &&
         std::abs(col[0].lo - stock.bore() / 2.0) < eps;
}

}  // namespace

PartSpan finishedPartSpan(const Stock& stock) {
  PartSpan span;
  const int n = stock.columnCount();
  // The rightmost run of material: the part is on the Z0 side, the bar is held at the left.
  int last = n - 1;
  while (last >= 0 && isGap(stock, last)) --last;
  if (last < 0) return span;  // nothing left
  int first = last;
  while (first > 0 && !isGap(stock, first - 1)) --first;
  span.parted = first > 0;
  // Pieces left of a gap never count; a thin pip column is material but not the part's end.
  if (!span.parted) {
    int touched = first;
    while (touched <= last && isUntouched(stock, touched)) ++touched;
    // Nothing cut, or only a skim of the face: the drawing shows the bar.
    if (touched > first && stock.zRight(last) - stock.zLeft(touched) >= 1.0) {
      // The nose's fillet in the corner with the bar's face belongs to the bar
      // left on: the part ends where its last step runs level.
      int level = touched;
      while (level < last && stock.outerRadius(level) > stock.outerRadius(level + 1) + 1e-9 &&
             stock.zRight(level) - stock.zLeft(touched) <= kNoseFillet)
        ++level;
      if (level > touched && level < last &&
          std::abs(stock.outerRadius(level) - stock.outerRadius(level + 1)) <= 1e-9) {
        span.trimRadius = stock.outerRadius(level);
        span.trimUntil = stock.zLeft(level);
      }
      first = touched;
      span.stubLeftOut = true;
    }
  }
  span.zLeft = stock.zLeft(first);
  span.zRight = stock.zRight(last);
  return span;
}

Stock cropToSpan(const Stock& stock, const PartSpan& span) {
  Stock out = stock;
  const double all = stock.diameter();
  for (int i = 0; i < out.columnCount(); ++i) {
    const double zc = out.zCentre(i);
    if (zc < span.zLeft || zc > span.zRight)
      out.remove(i, 0.0, all);
    else if (zc < span.trimUntil)
      out.remove(i, span.trimRadius, all);
  }
  return out;
}

void addThreadLeadChamfers(const Stock& stock, PartFeatures& part) {
  for (std::size_t k = 0; k < part.outside.size(); ++k) {
    const PartFeature t = part.outside[k];
    if (t.kind != FeatureKind::Thread || t.pitch <= 0.0) continue;
    const double major = t.diameter / 2.0;
    // Crests (local maxima) from the thread's start, while they stay below the major radius.
    int first = 0, last = -1;
    stock.columnRange(t.zLeft, t.zRight, first, last);
    std::vector<std::pair<double, double>> crests;  // (z, radius): points on the chamfer's line
    // From the face in, the chamfer runs until the first groove's flank (its last column is on the flank).
    int run = last;
    while (run - 1 > first && stock.outerRadius(run - 1) > stock.outerRadius(run) + 1e-9) --run;
    for (int i = last; i > run + 1; --i)
      if (stock.outerRadius(i) < major - 0.02) crests.emplace_back(stock.zCentre(i), stock.outerRadius(i));
    for (int i = run - 1; i > first; --i) {
      const double r = stock.outerRadius(i);
      if (r >= major - 0.02) break;  // the full thread begins
      if (r >= stock.outerRadius(i - 1) && r > stock.outerRadius(i + 1)) crests.emplace_back(stock.zCentre(i), r);
    }
    if (crests.size() < 2) continue;
    // The chamfer's line through the crests (least squares).
    double sz = 0, sr = 0, szz = 0, szr = 0;
    for (const auto& [z, r] : crests) {
      sz += z;
      sr += r;
      szz += z * z;
      szr += z * r;
    }
    const double n = static_cast<double>(crests.size());
    const double den = n * szz - sz * sz;
    if (std::abs(den) < 1e-12) continue;
    const double b = (n * szr - sz * sr) / den;  // dr/dz: negative, the radius grows leftward
    const double a = (sr - b * sz) / n;
    if (b >= -1e-3) continue;
    const double zEnd = std::max(t.zLeft, (major - a) / b);
    const double rFace = a + b * t.zRight;
    PartFeature c;
    c.kind = FeatureKind::Chamfer;
    c.side = FeatureSide::Outside;
    c.zLeft = zEnd;
    c.zRight = t.zRight;
    c.axialLength = c.zRight - c.zLeft;
    c.radialHeight = major - rFace;
    if (c.axialLength < 0.2 || c.radialHeight < 0.2) continue;
    c.diameterLeft = 2.0 * major;
    c.diameterRight = 2.0 * rFace;
    c.angle = std::atan2(c.radialHeight, c.axialLength) * 180.0 / M_PI;
    // Sizes as a drawing gives them: to 0.05 mm, so a C1.5 reads C1.5.
    const auto round = [](double v) { return std::round(v * 20.0) / 20.0; };
    if (std::abs(c.angle - 45.0) <= 3.0) {
      c.angle = 45.0;
      c.axialLength = c.radialHeight = round((c.axialLength + c.radialHeight) / 2.0);
    }
    part.outside.insert(part.outside.begin() + static_cast<long>(k), c);
    ++k;
  }
}

}  // namespace klueng::core::cut

#include "klueng/core/cut/part_features.h"

#include <algorithm>
#include <cmath>

#include "profile_fit.h"

namespace klueng::core::cut {

namespace {

constexpr double kFitTolerance = 0.002;    // mm of radius: the stock's radii are exact
constexpr double kNoseFilletRadius = 1.6;  // a concave arc this small is the tool nose's print
constexpr double kMaxChamferLeg = 5.0;     // mm: a longer bevel is a taper
constexpr double kMaxGrooveWidth = 10.0;   // mm
constexpr double kMinGrooveDepth = 0.1;    // mm of radius
constexpr double kCylinderRise = 0.002;
constexpr double kSliverLength =
    0.15;  // mm: a bevel's end rolled by the nose, fitted apart       // mm of radius over the length

enum class ItemKind { Piece, Face, Thread };

struct Item {
  ItemKind kind = ItemKind::Piece;
  fit::Piece piece;                  // Piece
  double z = 0.0;                    // Face
  double jump = 0.0;                 // Face: radius step between its columns
  fit::ThreadRun thread;             // Thread
  double zLeft = 0.0, zRight = 0.0;  // Thread
};

// One side of the part: radius per column (0 where that side has nothing).
struct Side {
  const Stock& stock;
  std::vector<double> z;
  std::vector<double> r;
  double jumpLimit;
};

void addSmooth(const Side& s, int a, int b, bool wholeRun, std::vector<Item>& items) {
  if (a > b) return;
  // A point or two between two faces (the steep end of an arc) belongs to the faces.
  if (b - a + 1 < 3 && !wholeRun) return;
  for (const fit::Piece& p : fit::fitRun(s.z, s.r, a, b, kFitTolerance)) {
    Item it;
    it.piece = p;
    items.push_back(it);
  }
}

void addStretch(const Side& s, int a, int b, bool wholeRun, std::vector<Item>& items) {
  int start = a;
  for (int k = a; k < b; ++k) {
    const double jump = std::abs(s.r[k + 1] - s.r[k]);
    if (jump <= s.jumpLimit) continue;
    addSmooth(s, start, k, false, items);
    Item face;
    face.kind = ItemKind::Face;
    face.z = s.stock.zRight(k);
    face.jump = jump;
    // Faces a lone point apart are one face: the larger jump's place.
    if (!items.empty() && items.back().kind == ItemKind::Face) {
      if (jump > items.back().jump) items.back() = face;
    } else {
      items.push_back(face);
    }
    start = k + 1;
  }
  addSmooth(s, start, b, wholeRun && start == a, items);
}

// Items of the run of columns [first, last], left to right, with every join resolved.
std::vector<Item> readRun(const Side& s, int first, int last) {
  std::vector<Item> items;
  int pos = first;
  for (const fit::ThreadRun& t : fit::findThreads(s.z, s.r, first, last, s.stock.resolution())) {
    addStretch(s, pos, t.first - 1, false, items);
    Item it;
    it.kind = ItemKind::Thread;
    it.thread = t;
    it.zLeft = s.stock.zLeft(t.first);
    it.zRight = s.stock.zRight(t.last);
    items.push_back(it);
    pos = t.last + 1;
  }
  addStretch(s, pos, last, pos == first, items);

  // Joins: between pieces where they meet, else at the face, thread or run end beside them.
  auto leftBound = [&](std::size_t k) {
    if (k == 0) return s.stock.zLeft(first);
    const Item& prev = items[k - 1];
    return prev.kind == ItemKind::Face ? prev.z : prev.zRight;
  };
  auto rightBound = [&](std::size_t k) {
    if (k + 1 >= items.size()) return s.stock.zRight(last);
    const Item& next = items[k + 1];
    return next.kind == ItemKind::Face ? next.z : next.zLeft;
  };
  for (std::size_t k = 0; k < items.size();) {
    if (items[k].kind != ItemKind::Piece) {
      ++k;
      continue;
    }
    std::size_t e = k;
    while (e + 1 < items.size() && items[e + 1].kind == ItemKind::Piece) ++e;
    std::vector<fit::Piece> pieces;
    for (std::size_t m = k; m <= e; ++m) pieces.push_back(items[m].piece);
    fit::resolveJoins(pieces, s.z, leftBound(k), rightBound(e));
    for (std::size_t m = k; m <= e; ++m) items[m].piece = pieces[m - k];
    k = e + 1;
  }
  return items;
}

double radiusBeside(const std::vector<Item>& items, std::size_t k, int dir, double z, double fallback) {
  const long n = static_cast<long>(items.size());
  const long m = static_cast<long>(k) + dir;
  if (m < 0 || m >= n) return fallback;
  const Item& it = items[static_cast<std::size_t>(m)];
  if (it.kind == ItemKind::Piece) return it.piece.at(z);
  if (it.kind == ItemKind::Thread) return it.thread.crest;
  return fallback;
}

PartFeature toFeature(const Item& it, FeatureSide side) {
  PartFeature f;
  f.side = side;
  if (it.kind == ItemKind::Thread) {
    f.kind = FeatureKind::Thread;
    f.zLeft = it.zLeft;
    f.zRight = it.zRight;
    f.pitch = it.thread.pitch;
    // Outside or in a bore, the largest radius is the major Ø, the smallest the minor.
    f.diameter = 2.0 * it.thread.crest;
    f.minorDiameter = 2.0 * it.thread.root;
    f.diameterLeft = f.diameterRight = f.diameter;
    return f;
  }
  const fit::Piece& p = it.piece;
  f.zLeft = p.zLeft;
  f.zRight = p.zRight;
  f.diameterLeft = 2.0 * p.at(p.zLeft);
  f.diameterRight = 2.0 * p.at(p.zRight);
  if (p.arc) {
    f.kind = FeatureKind::Arc;
    f.radius = p.radius;
    f.centre = p.centre;
    // Material is below the outside profile and above the inside one.
    f.convex = (side == FeatureSide::Outside) == p.upper;
  } else if (std::abs(f.diameterRight - f.diameterLeft) <= 2.0 * kCylinderRise) {
    f.kind = FeatureKind::Cylinder;
    f.diameter = 2.0 * p.at((p.zLeft + p.zRight) / 2.0);
  } else {
    f.kind = FeatureKind::Taper;
    f.angle = std::atan(std::abs(p.b)) * 180.0 / M_PI;
    f.axialLength = f.length();
    f.radialHeight = std::abs(f.diameterRight - f.diameterLeft) / 2.0;
  }
  return f;
}

// The neighbour a chamfer's or groove's corner is measured to: the nose's fillets are passed over.
long neighbour(const std::vector<PartFeature>& fs, long k, int dir) {
  long m = k + dir;
  while (m >= 0 && m < static_cast<long>(fs.size()) && fs[static_cast<std::size_t>(m)].isNoseFillet()) m += dir;
  return m >= 0 && m < static_cast<long>(fs.size()) ? m : -1;
}

// The sharp corner a bevel's line makes with the feature beside it: (z, radius).
Vec2 sharpCorner(const PartFeature& taper, const PartFeature* other, bool leftEnd) {
  const double b = (taper.diameterRight - taper.diameterLeft) / 2.0 / std::max(1e-9, taper.length());
  const double a = taper.diameterLeft / 2.0 - b * taper.zLeft;
  const Vec2 own =
      leftEnd ? Vec2(taper.zLeft, taper.diameterLeft / 2.0) : Vec2(taper.zRight, taper.diameterRight / 2.0);
  if (other == nullptr) return own;
  if (other->kind == FeatureKind::Face) return Vec2(other->zLeft, a + b * other->zLeft);
  if (other->kind == FeatureKind::Cylinder || other->kind == FeatureKind::Taper) {
    const double ob = (other->diameterRight - other->diameterLeft) / 2.0 / std::max(1e-9, other->length());
    const double oa = other->diameterLeft / 2.0 - ob * other->zLeft;
    if (std::abs(ob - b) < 1e-9) return own;
    const double z = (oa - a) / (b - ob);
    if (std::abs(z - own.x()) > kMaxChamferLeg) return own;
    return Vec2(z, a + b * z);
  }
  return own;
}

// A bevel's end where the nose rolled over the corner it makes with a face (or
// a bore's mouth) is
// fitted as its own short line at another angle: it belongs to the bevel, whose
// line is carried on to it, so the chamfer is measured to its true sharp corner.
void absorbSlivers(std::vector<PartFeature>& fs) {
  for (std::size_t k = 0; k < fs.size(); ++k) {
    const PartFeature& f = fs[k];
    if (f.kind != FeatureKind::Taper || f.length() > kSliverLength) continue;
    for (const int dir : {-1, +1}) {
      const long o = static_cast<long>(k) + dir, face = static_cast<long>(k) - dir;
      if (o < 0 || o >= static_cast<long>(fs.size())) continue;
      // Beyond the sliver, a face (or the part's end: a bore's mouth face is listed with the outside).
      const bool byFace = face < 0 || face >= static_cast<long>(fs.size()) ||
                          fs[static_cast<std::size_t>(face)].kind == FeatureKind::Face;
      PartFeature& bevel = fs[static_cast<std::size_t>(o)];
      if (bevel.kind != FeatureKind::Taper || bevel.length() <= 4.0 * f.length() || !byFace) continue;
      const double slope = (bevel.diameterRight - bevel.diameterLeft) / bevel.length();
      if (dir > 0) {  // the bevel is to the sliver's right: carry its line left
        bevel.diameterLeft = bevel.diameterRight - slope * (bevel.zRight - f.zLeft);
        bevel.zLeft = f.zLeft;
      } else {
        bevel.diameterRight = bevel.diameterLeft + slope * (f.zRight - bevel.zLeft);
        bevel.zRight = f.zRight;
      }
      bevel.axialLength = bevel.length();
      bevel.radialHeight = std::abs(bevel.diameterRight - bevel.diameterLeft) / 2.0;
      fs.erase(fs.begin() + static_cast<long>(k));
      --k;
      break;
    }
  }
}

// Where the nose rolled over a shallow corner (a cylinder running into a 10°
// taper) it leaves an arc only a few columns long, whose fitted radius is noise
// (R7 for an R0.8 nose). A draughtsman draws the corner the program made: the
// two lines meet there, and the arc is dropped.
void absorbShallowFillets(std::vector<PartFeature>& fs) {
  constexpr double kShallowCorner = 35.0 * M_PI / 180.0;
  constexpr double kChordSlack = 0.15;  // mm: three columns either end
  const auto isLine = [](const PartFeature& f) {
    return (f.kind == FeatureKind::Cylinder || f.kind == FeatureKind::Taper) && f.length() > 0.0;
  };
  const auto slope = [](const PartFeature& f) { return (f.diameterRight - f.diameterLeft) / 2.0 / f.length(); };
  for (std::size_t k = 1; k + 1 < fs.size(); ++k) {
    const PartFeature& arc = fs[k];
    if (arc.kind != FeatureKind::Arc || arc.convex) continue;
    PartFeature& left = fs[k - 1];
    PartFeature& right = fs[k + 1];
    if (!isLine(left) || !isLine(right)) continue;
    const double bl = slope(left), br = slope(right);
    const double turn = std::abs(std::atan(bl) - std::atan(br));
    if (turn >= kShallowCorner || std::abs(bl - br) < 1e-9) continue;
    const double chord = std::hypot(arc.zRight - arc.zLeft, (arc.diameterRight - arc.diameterLeft) / 2.0);
    if (chord > 2.0 * kNoseFilletRadius * std::sin(turn / 2.0) + kChordSlack) continue;
    const double al = left.diameterLeft / 2.0 - bl * left.zLeft, ar = right.diameterLeft / 2.0 - br * right.zLeft;
    const double z = (ar - al) / (bl - br);
    if (z < arc.zLeft - kChordSlack || z > arc.zRight + kChordSlack || z <= left.zLeft || z >= right.zRight) continue;
    left.zRight = z;
    left.diameterRight = 2.0 * (al + bl * z);
    right.zLeft = z;
    right.diameterLeft = 2.0 * (ar + br * z);
    for (PartFeature* line : {&left, &right})
      if (line->kind == FeatureKind::Taper) {
        line->axialLength = line->length();
        line->radialHeight = std::abs(line->diameterRight - line->diameterLeft) / 2.0;
      }
    fs.erase(fs.begin() + static_cast<long>(k));
    --k;
  }
}

// Cylinders side by side whose Ø differ by a scratch (a thread pass that only
// grazed the surface, the next roughing level's step of a hundredth) are one
// cylinder on a drawing: no draughtsman gives Ø0.849 and Ø0.850 in turn.
void mergeScratchedCylinders(std::vector<PartFeature>& fs) {
  constexpr double kScratch = 0.03;  // mm on the Ø
  for (std::size_t k = 0; k + 1 < fs.size();) {
    PartFeature& a = fs[k];
    const PartFeature& b = fs[k + 1];
    if (a.kind != FeatureKind::Cylinder || b.kind != FeatureKind::Cylinder ||
        std::abs(a.diameter - b.diameter) > kScratch) {
      ++k;
      continue;
    }
    const double length = a.length() + b.length();
    a.diameter = length > 0.0 ? (a.diameter * a.length() + b.diameter * b.length()) / length : a.diameter;
    a.zLeft = std::min(a.zLeft, b.zLeft);
    a.zRight = std::max(a.zRight, b.zRight);
    a.diameterLeft = a.diameterRight = a.diameter;
    fs.erase(fs.begin() + static_cast<long>(k) + 1);
  }
}

void classify(std::vector<PartFeature>& fs) {
  absorbSlivers(fs);
  absorbShallowFillets(fs);
  mergeScratchedCylinders(fs);
  const long n = static_cast<long>(fs.size());
  for (long k = 0; k < n; ++k) {
    PartFeature& f = fs[static_cast<std::size_t>(k)];
    if (f.kind != FeatureKind::Taper) continue;
    const long l = neighbour(fs, k, -1), r = neighbour(fs, k, +1);
    const PartFeature* left = l >= 0 ? &fs[static_cast<std::size_t>(l)] : nullptr;
    const PartFeature* right = r >= 0 ? &fs[static_cast<std::size_t>(r)] : nullptr;
    // Nothing beside it is the part's end (a bore's mouth: the end face belongs to the outside).
    const bool byFace = !left || !right || left->kind == FeatureKind::Face || right->kind == FeatureKind::Face;
    const Vec2 a = sharpCorner(f, left, true), b = sharpCorner(f, right, false);
    const double axial = std::abs(b.x() - a.x()), radial = std::abs(b.y() - a.y());
    if (byFace && axial <= kMaxChamferLeg && radial <= kMaxChamferLeg) {
      f.kind = FeatureKind::Chamfer;
      f.axialLength = axial;
      f.radialHeight = radial;
    }
  }
  // Grooves: a cylinder sunk between two faces (into the material on either side).
  for (long k = 0; k < n; ++k) {
    PartFeature& c = fs[static_cast<std::size_t>(k)];
    if (c.kind != FeatureKind::Cylinder) continue;
    const long l = neighbour(fs, k, -1), r = neighbour(fs, k, +1);
    if (l < 0 || r < 0) continue;
    const PartFeature& fl = fs[static_cast<std::size_t>(l)];
    const PartFeature& fr = fs[static_cast<std::size_t>(r)];
    if (fl.kind != FeatureKind::Face || fr.kind != FeatureKind::Face) continue;
    const double sign = c.side == FeatureSide::Outside ? 1.0 : -1.0;
    const double depth = sign * (std::min(sign * fl.diameterLeft, sign * fr.diameterRight) - sign * c.diameter) / 2.0;
    const double width = fr.zLeft - fl.zLeft;
    if (sign * (fl.diameterLeft - fl.diameterRight) <= 0.0 || sign * (fr.diameterRight - fr.diameterLeft) <= 0.0)
      continue;
    if (width > kMaxGrooveWidth || depth < kMinGrooveDepth) continue;
    c.kind = FeatureKind::Groove;
    c.zLeft = fl.zLeft;  // wall to wall, the nose's corner radii included
    c.zRight = fr.zLeft;
    c.width = width;
    c.depth = depth;
  }
}

// Features of one side's run of columns, left to right; `ends` adds the part's end faces.
void readSide(const Side& s, int first, int last, FeatureSide side, const std::vector<double>& otherR, bool ends,
              std::vector<PartFeature>& out) {
  const std::vector<Item> items = readRun(s, first, last);
  if (items.empty()) return;
  const double zStart = s.stock.zLeft(first), zEnd = s.stock.zRight(last);
  auto face = [&](double z, double dLeft, double dRight) {
    PartFeature f;
    f.kind = FeatureKind::Face;
    f.side = side;
    f.zLeft = f.zRight = z;
    f.diameterLeft = dLeft;
    f.diameterRight = dRight;
    if (std::abs(dLeft - dRight) >= 0.01) out.push_back(f);
  };
  // At a run's end the outside meets the bore (or the centre line); a bore's
  // end inside the part meets solid material (Ø0 beyond it).
  const auto at = [](const std::vector<double>& v, int i) { return v[static_cast<std::size_t>(i)]; };
  const int n = static_cast<int>(s.r.size());
  if (ends || (first > 0 && at(otherR, first - 1) > 0.0))
    face(zStart, ends ? 2.0 * at(otherR, first) : 0.0, 2.0 * radiusBeside(items, 0, 0, zStart, at(s.r, first)));
  for (std::size_t k = 0; k < items.size(); ++k) {
    const Item& it = items[k];
    if (it.kind != ItemKind::Face) {
      out.push_back(toFeature(it, side));
      continue;
    }
    face(it.z, 2.0 * radiusBeside(items, k, -1, it.z, 0.0), 2.0 * radiusBeside(items, k, +1, it.z, 0.0));
  }
  if (ends || (last + 1 < n && at(otherR, last + 1) > 0.0))
    face(zEnd, 2.0 * radiusBeside(items, items.size() - 1, 0, zEnd, at(s.r, last)),
         ends ? 2.0 * at(otherR, last) : 0.0);
}

}  // namespace

bool PartFeature::isFortyFiveChamfer() const { return kind == FeatureKind::Chamfer && std::abs(angle - 45.0) <= 0.5; }

bool PartFeature::isNoseFillet() const { return kind == FeatureKind::Arc && !convex && radius <= kNoseFilletRadius; }

double PartFeature::radiusAt(double z) const {
  if (kind == FeatureKind::Groove) return diameter / 2.0;
  if (kind == FeatureKind::Arc) {
    const double dz = std::clamp(z - centre.x(), -radius, radius);
    const double h = std::sqrt(std::max(0.0, radius * radius - dz * dz));
    // Outside, material is below the profile; in a bore, above it.
    const bool upper = (side == FeatureSide::Outside) == convex;
    return centre.y() + (upper ? h : -h);
  }
  if (length() <= 0.0) return diameterLeft / 2.0;
  return (diameterLeft + (diameterRight - diameterLeft) * (z - zLeft) / length()) / 2.0;
}

std::vector<double> PartFeatures::shoulderZ() const {
  std::vector<double> zs{zRight, zLeft};
  for (const auto* list : {&outside, &inside})
    for (const PartFeature& f : *list)
      if (f.kind == FeatureKind::Face) zs.push_back(f.zLeft);
  std::sort(zs.begin(), zs.end(), std::greater<>());
  zs.erase(std::unique(zs.begin(), zs.end(), [](double a, double b) { return std::abs(a - b) < 1e-6; }), zs.end());
  return zs;
}

PartFeatures partFeatures(const Stock& stock) {
  PartFeatures out;
  const int n = stock.columnCount();
  const double jumpLimit = std::max(3.0 * stock.resolution(), 0.02);
  Side outer{stock, std::vector<double>(static_cast<std::size_t>(n)), std::vector<double>(static_cast<std::size_t>(n)),
             jumpLimit};
  Side inner{stock, outer.z, std::vector<double>(static_cast<std::size_t>(n)), jumpLimit};
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    outer.z[k] = inner.z[k] = stock.zCentre(i);
    outer.r[k] = stock.outerRadius(i);
    inner.r[k] = outer.r[k] > 0.0 ? stock.innerRadius(i) : 0.0;
  }
  bool first = true;
  for (const auto* side : {&outer, &inner}) {
    const bool isOuter = side == &outer;
    std::vector<PartFeature>& list = isOuter ? out.outside : out.inside;
    for (int i = 0; i < n;) {
      if (side->r[static_cast<std::size_t>(i)] <= 0.0) {
        ++i;
        continue;
      }
      int j = i;
      while (j + 1 < n && side->r[static_cast<std::size_t>(j + 1)] > 0.0) ++j;
      readSide(*side, i, j, isOuter ? FeatureSide::Outside : FeatureSide::Inside, isOuter ? inner.r : outer.r, isOuter,
               list);
      if (isOuter) {
        out.zLeft = first ? stock.zLeft(i) : out.zLeft;
        out.zRight = stock.zRight(j);
        first = false;
      }
      i = j + 1;
    }
    classify(list);
    for (PartFeature& f : list)
      if (f.kind == FeatureKind::Chamfer || f.kind == FeatureKind::Taper)
        f.angle = std::atan2(std::abs(f.diameterRight - f.diameterLeft) / 2.0, f.length()) * 180.0 / M_PI;
  }
  // The outside's end faces reach down to the bore where its features end.
  if (!out.inside.empty() && !out.outside.empty()) {
    PartFeature& leftEnd = out.outside.front();
    PartFeature& rightEnd = out.outside.back();
    if (leftEnd.kind == FeatureKind::Face && std::abs(out.inside.front().zLeft - leftEnd.zLeft) < 1e-9)
      leftEnd.diameterLeft = out.inside.front().diameterLeft;
    if (rightEnd.kind == FeatureKind::Face && std::abs(out.inside.back().zRight - rightEnd.zLeft) < 1e-9)
      rightEnd.diameterRight = out.inside.back().diameterRight;
  }
  std::reverse(out.outside.begin(), out.outside.end());
  std::reverse(out.inside.begin(), out.inside.end());
  return out;
}

}  // namespace klueng::core::cut

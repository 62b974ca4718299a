#include "profile_fit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace klueng::core::cut::fit {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMinLinePoints = 5;  // fewer collinear points than this start an arc instead
constexpr double kMaxArcRadius = 5000.0;
constexpr int kMaxCheckedPoints = 256;  // arc growth checks a spread of this many points at most

// Last point of the longest stretch from `i` that one line through point i
// keeps within tol (the feasible slopes narrow with every point).
int lineEnd(const std::vector<double>& z, const std::vector<double>& r, int i, int last, double tol) {
  double lo = -kInf, hi = kInf;
  int j = i;
  for (int k = i + 1; k <= last; ++k) {
    const double dz = z[k] - z[i];
    lo = std::max(lo, (r[k] - tol - r[i]) / dz);
    hi = std::min(hi, (r[k] + tol - r[i]) / dz);
    if (lo > hi) break;
    j = k;
  }
  return j;
}

bool circleThrough(const Vec2& p, const Vec2& q, const Vec2& s, Vec2& centre, double& radius) {
  const double d = 2.0 * (p.x() * (q.y() - s.y()) + q.x() * (s.y() - p.y()) + s.x() * (p.y() - q.y()));
  if (std::abs(d) < 1e-12) return false;
  const double p2 = p.squaredNorm(), q2 = q.squaredNorm(), s2 = s.squaredNorm();
  centre = Vec2((p2 * (q.y() - s.y()) + q2 * (s.y() - p.y()) + s2 * (p.y() - q.y())) / d,
                (p2 * (s.x() - q.x()) + q2 * (p.x() - s.x()) + s2 * (q.x() - p.x())) / d);
  radius = (p - centre).norm();
  return radius < kMaxArcRadius;
}

bool fitsCircle(const std::vector<double>& z, const std::vector<double>& r, int i, int k, const Vec2& c, double radius,
                double tol) {
  const int step = std::max(1, (k - i) / kMaxCheckedPoints);
  for (int m = i; m <= k; m += step)
    if (std::abs((Vec2(z[m], r[m]) - c).norm() - radius) > tol) return false;
  return std::abs((Vec2(z[k], r[k]) - c).norm() - radius) <= tol;
}

// Last point of the longest stretch from `i` on one circle, or i when none of 4+ points.
int arcEnd(const std::vector<double>& z, const std::vector<double>& r, int i, int last, double tol) {
  int best = i;
  for (int k = i + 3; k <= last; ++k) {
    Vec2 c;
    double radius = 0.0;
    const int m = (i + k) / 2;
    if (!circleThrough(Vec2(z[i], r[i]), Vec2(z[m], r[m]), Vec2(z[k], r[k]), c, radius) ||
        !fitsCircle(z, r, i, k, c, radius, tol))
      break;
    best = k;
  }
  return best;
}

void fitLine(const std::vector<double>& z, const std::vector<double>& r, Piece& p) {
  const int n = p.last - p.first + 1;
  double mz = 0.0, mr = 0.0;
  for (int k = p.first; k <= p.last; ++k) mz += z[k], mr += r[k];
  mz /= n;
  mr /= n;
  double szz = 0.0, szr = 0.0;
  for (int k = p.first; k <= p.last; ++k) szz += (z[k] - mz) * (z[k] - mz), szr += (z[k] - mz) * (r[k] - mr);
  p.b = szz > 0.0 ? szr / szz : 0.0;
  p.a = mr - p.b * mz;
}

// Algebraic (Kasa) least-squares circle, on points centred for conditioning.
void fitArc(const std::vector<double>& z, const std::vector<double>& r, Piece& p) {
  const int n = p.last - p.first + 1;
  const Vec2 o((z[p.first] + z[p.last]) / 2.0, (r[p.first] + r[p.last]) / 2.0);
  Eigen::MatrixXd a(n, 3);
  Eigen::VectorXd rhs(n);
  for (int k = 0; k < n; ++k) {
    const Vec2 q = Vec2(z[p.first + k], r[p.first + k]) - o;
    a(k, 0) = q.x();
    a(k, 1) = q.y();
    a(k, 2) = 1.0;
    rhs(k) = -q.squaredNorm();
  }
  const Eigen::Vector3d s = a.colPivHouseholderQr().solve(rhs);
  const Vec2 c(-s(0) / 2.0, -s(1) / 2.0);
  p.centre = c + o;
  p.radius = std::sqrt(std::max(0.0, c.squaredNorm() - s(2)));
  double above = 0.0;
  for (int k = p.first; k <= p.last; ++k) above += r[k] - p.centre.y();
  p.upper = above > 0.0;
}

// Where two pieces meet, near the window [lo, hi].
double joinZ(const Piece& A, const Piece& B, double lo, double hi) {
  const double mid = (lo + hi) / 2.0;
  auto inWindow = [&](double zz) { return std::isfinite(zz) && zz >= lo && zz <= hi; };
  if (!A.arc && !B.arc) {
    if (std::abs(A.b - B.b) > 1e-9) {
      const double zz = (B.a - A.a) / (A.b - B.b);
      if (inWindow(zz)) return zz;
    }
    return mid;
  }
  if (A.arc != B.arc) {
    const Piece& line = A.arc ? B : A;
    const Piece& arc = A.arc ? A : B;
    // Foot of the centre on the line: the tangent point when they touch.
    const Vec2 d = Vec2(1.0, line.b).normalized();
    const Vec2 p0(0.0, line.a);
    const Vec2 foot = p0 + d * (arc.centre - p0).dot(d);
    if (std::abs((foot - arc.centre).norm() - arc.radius) < 0.02 + 0.01 * arc.radius && inWindow(foot.x()))
      return foot.x();
  }
  // The closest approach of the two carriers across the window.
  double bestZ = mid, best = kInf;
  constexpr int kSteps = 200;
  for (int k = 0; k <= kSteps; ++k) {
    const double zz = lo + (hi - lo) * k / kSteps;
    const double gap = std::abs(A.at(zz) - B.at(zz));
    if (gap < best) best = gap, bestZ = zz;
  }
  return bestZ;
}

}  // namespace

double Piece::at(double z) const {
  if (!arc) return a + b * z;
  const double dz = std::clamp(z - centre.x(), -radius, radius);
  const double h = std::sqrt(std::max(0.0, radius * radius - dz * dz));
  return upper ? centre.y() + h : centre.y() - h;
}

std::vector<Piece> fitRun(const std::vector<double>& z, const std::vector<double>& r, int first, int last,
                          double tolerance) {
  std::vector<Piece> out;
  int i = first;
  while (i <= last) {
    Piece p;
    p.first = i;
    // The longer of a line and an arc from here: near its tangent an arc is
    // straight enough for a few points, so a short line must not win there.
    const int j = lineEnd(z, r, i, last, tolerance);
    const int k = j == last ? j : arcEnd(z, r, i, last, tolerance);
    p.arc = k > j + 1 || (k > j && j - i + 1 < kMinLinePoints);
    p.last = p.arc ? k : j;
    if (p.arc) {
      fitArc(z, r, p);
    } else {
      fitLine(z, r, p);
    }
    // A line after a line that the greedy split (an arc tried and refused in between): one line.
    if (!p.arc && !out.empty() && !out.back().arc) {
      Piece merged = out.back();
      merged.last = p.last;
      fitLine(z, r, merged);
      bool fits = true;
      for (int k = merged.first; k <= merged.last && fits; ++k) fits = std::abs(merged.at(z[k]) - r[k]) <= tolerance;
      if (fits) {
        out.back() = merged;
        i = p.last + 1;
        continue;
      }
    }
    out.push_back(p);
    i = p.last + 1;
  }
  return out;
}

void resolveJoins(std::vector<Piece>& pieces, const std::vector<double>& z, double zStart, double zEnd) {
  if (pieces.empty()) return;
  pieces.front().zLeft = zStart;
  pieces.back().zRight = zEnd;
  for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
    Piece& A = pieces[k];
    Piece& B = pieces[k + 1];
    // The window reaches a few points into both: a line may have taken the
    // start of the arc beside it (it lies within the tolerance of the tangent).
    // Joins go left to right: with pieces shorter than the window a join could
    // land left of the one before it and leave a piece of negative length.
    const double lo = std::max(z[std::max(A.first, A.last - 10)], A.zLeft);
    const double hi = std::max(z[std::min(B.last, B.first + 10)], lo);
    const double at = std::clamp(joinZ(A, B, lo, hi), A.zLeft, std::max(A.zLeft, zEnd));
    A.zRight = at;
    B.zLeft = at;
  }
}

// The mean spacing of the teeth of a chain of valleys (extremes v, v+2, …, w),
// read where each flank crosses the half-depth radius, interpolated between
// columns, so the pitch is not rounded to whole columns. Falling and rising
// flanks are measured apart (a column's sampling shifts each kind alike) and
// averaged by their count. 0 when fewer than two flanks of a kind are found.
template <class ExtremeAt>
double flankPitch(const std::vector<double>& z, const std::vector<double>& r, std::size_t v, std::size_t w,
                  std::size_t count, ExtremeAt extremeAt) {
  const double root = r[extremeAt(v).from];
  double crest = std::numeric_limits<double>::infinity();
  for (std::size_t e = v + 1; e < w; e += 2) crest = std::min(crest, r[extremeAt(e).from]);
  if (!std::isfinite(crest) || crest - root < 0.05) return 0.0;
  const double mid = (root + crest) / 2.0;
  // Where r crosses `mid` between columns a and b (a < b), interpolated.
  const auto crossing = [&](int a, int b) -> std::optional<double> {
    for (int k = a; k < b; ++k)
      if ((r[k] - mid) * (r[k + 1] - mid) <= 0.0 && r[k] != r[k + 1])
        return z[k] + (mid - r[k]) / (r[k + 1] - r[k]) * (z[k + 1] - z[k]);
    return std::nullopt;
  };
  std::vector<double> falling, rising;
  for (std::size_t e = v; e <= w; e += 2) {
    if (e > 0)
      if (const auto at = crossing(extremeAt(e - 1).to, extremeAt(e).from)) falling.push_back(*at);
    if (e + 1 < count)
      if (const auto at = crossing(extremeAt(e).to, extremeAt(e + 1).from)) rising.push_back(*at);
  }
  double sum = 0.0;
  std::size_t gaps = 0;
  for (const std::vector<double>* flanks : {&falling, &rising})
    if (flanks->size() >= 2) {
      sum += flanks->back() - flanks->front();
      gaps += flanks->size() - 1;
    }
  return gaps > 0 ? sum / static_cast<double>(gaps) : 0.0;
}

std::vector<ThreadRun> findThreads(const std::vector<double>& z, const std::vector<double>& r, int first, int last,
                                   double columnWidth) {
  constexpr double kHysteresis = 0.05;  // mm of radius a flank must fall or rise to count
  struct Extreme {
    bool valley;
    int from, to;  // plateau
  };
  std::vector<Extreme> ext;
  if (last - first < 8) return {};
  // Alternating maxima and minima, each a plateau of equal radii.
  int dir = 0;  // +1 rising (looking for a maximum), -1 falling
  int from = first, to = first;
  for (int k = first + 1; k <= last; ++k) {
    const double cand = r[from];
    if (std::abs(r[k] - cand) < 1e-6) {
      if (to == k - 1) to = k;
      continue;
    }
    if (dir >= 0 && r[k] > cand) {
      from = to = k;
      dir = 1;
    } else if (dir <= 0 && r[k] < cand) {
      from = to = k;
      dir = -1;
    } else if (std::abs(r[k] - cand) >= kHysteresis) {
      ext.push_back({dir < 0, from, to});
      dir = -dir;
      if (dir == 0) dir = r[k] > cand ? 1 : -1;
      from = to = k;
    }
  }
  ext.push_back({dir < 0, from, to});

  std::vector<ThreadRun> out;
  auto centreZ = [&](const Extreme& e) { return (z[e.from] + z[e.to]) / 2.0; };
  std::size_t v = 0;
  while (v < ext.size()) {
    if (!ext[v].valley) {
      ++v;
      continue;
    }
    // Grow a chain of valleys spaced alike, with the same root.
    std::size_t w = v;
    double pitch = 0.0;
    while (w + 2 < ext.size() && ext[w + 2].valley) {
      const double s = centreZ(ext[w + 2]) - centreZ(ext[w]);
      if (pitch == 0.0 && s > 12.0) break;
      if (pitch != 0.0 && std::abs(s - pitch) > 0.03 * pitch + columnWidth) break;
      if (std::abs(r[ext[w + 2].from] - r[ext[v].from]) > 0.05) break;
      if (pitch == 0.0) pitch = s;
      w += 2;
    }
    if ((w - v) / 2 + 1 < 3) {  // fewer than three teeth: try from the next valley
      v += 2;
      continue;
    }
    // A valley at the root just beyond either end, up to two pitches away, is
    // the run-out where the tool entered or left: part of the thread.
    const auto runout = [&](std::size_t a, std::size_t b) {
      const double s = std::abs(centreZ(ext[b]) - centreZ(ext[a]));
      return ext[b].valley && std::abs(r[ext[b].from] - r[ext[a].from]) <= 0.05 && s >= 0.97 * pitch - columnWidth &&
             s <= 2.0 * pitch;
    };
    std::size_t v0 = v, w0 = w;
    if (v0 >= 2 && runout(v0, v0 - 2)) v0 -= 2;
    if (w0 + 2 < ext.size() && runout(w0, w0 + 2)) w0 += 2;
    ThreadRun t;
    // The flanks beside the end valleys up to their crests; a tooth cut short
    // by the part's end (a flank running into the end) belongs to the thread.
    t.first = ext[v0].from;
    while (t.first > first && r[t.first - 1] > r[t.first] + 1e-9) --t.first;
    t.last = ext[w0].to;
    while (t.last < last && r[t.last + 1] > r[t.last] + 1e-9) ++t.last;
    auto fallsTo = [&](int from, int to, int step) {
      for (int k = from; k != to; k += step)
        if (r[k + step] > r[k] + 1e-9) return false;
      return true;
    };
    while (t.last < last && std::abs(r[t.last + 1] - r[t.last]) < 1e-9) ++t.last;  // the crest's flat
    if (t.last < last && fallsTo(t.last, last, 1))
      t.last = last;
    else
      while (t.last > ext[w0].to && std::abs(r[t.last] - r[t.last - 1]) < 1e-9) --t.last;
    int crestStart = t.first;
    while (crestStart > first && std::abs(r[crestStart - 1] - r[crestStart]) < 1e-9) --crestStart;
    if (crestStart > first && fallsTo(crestStart, first, -1)) t.first = first;
    t.pitch = pitch;
    t.root = r[ext[v].from];
    t.crest = t.root;
    bool sloping = true;
    for (int k = t.first; k <= t.last; ++k) {
      t.crest = std::max(t.crest, r[k]);
      // Square walls are grooves side by side, not a thread.
      if (k > t.first && std::abs(r[k] - r[k - 1]) > 3.0 * columnWidth) sloping = false;
    }
    if (sloping && t.crest - t.root >= 0.1) {
      // The pitch over every tooth, not just the first two: from where the flanks
      // cross mid-height, read between columns, so it is not rounded to whole columns.
      t.pitch = flankPitch(z, r, v, w, ext.size(), [&](std::size_t e) { return ext[e]; });
      if (t.pitch <= 0.0) t.pitch = (centreZ(ext[w]) - centreZ(ext[v])) / static_cast<double>((w - v) / 2);
      out.push_back(t);
      v = w0 + 2;
    } else {
      v += 2;
    }
  }
  return out;
}

}  // namespace klueng::core::cut::fit

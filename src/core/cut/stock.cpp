#include "klueng/core/cut/stock.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace klueng::core::cut {

namespace {
constexpr int kMaxColumns = 1 << 21;  // ~2 million columns: 0.05 mm over 100 m, 0.001 mm over 2 m
}

Stock::Stock(double diameter, double length, double resolution, double bore)
    : diameter_(diameter), bore_(bore), length_(length), dz_(resolution) {
  if (!(diameter_ > 0.0)) diameter_ = 0.0;
  if (!(bore_ > 0.0) || !(bore_ < diameter_)) bore_ = 0.0;
  if (!(length_ > 0.0)) length_ = 0.0;
  if (!(dz_ > 0.0)) dz_ = kDefaultResolution;
  if (length_ / dz_ > kMaxColumns) dz_ = length_ / kMaxColumns;
  const int n = length_ > 0.0 ? std::max(1, static_cast<int>(std::lround(std::ceil(length_ / dz_ - 1e-9)))) : 0;
  // Keep the columns exactly tiling [-length, 0].
  if (n > 0) dz_ = length_ / n;
  const double r = diameter_ / 2.0;
  columns_.assign(static_cast<std::size_t>(n), std::vector<Interval>{Interval{bore_ / 2.0, r}});
  if (r <= 0.0)
    for (auto& c : columns_) c.clear();
  outer_.assign(static_cast<std::size_t>(n), r);
  blockMax_.assign(static_cast<std::size_t>((n + kBlock - 1) / kBlock), r);
  superMax_.assign(static_cast<std::size_t>((n + kSuper - 1) / kSuper), r);
}

bool Stock::catchCutOffPart() {
  const int n = columnCount();
  int gap = 0;
  while (gap < n && (outer_[static_cast<std::size_t>(gap)] > 0.0 || caught(gap))) ++gap;
  bool any = false;
  for (int i = gap + 1; i < n && !any; ++i) any = outer_[static_cast<std::size_t>(i)] > 0.0 && !caught(i);
  if (!any) return false;
  if (caught_.empty()) caught_.assign(static_cast<std::size_t>(n), 0);
  for (int i = gap + 1; i < n; ++i)
    if (outer_[static_cast<std::size_t>(i)] > 0.0) caught_[static_cast<std::size_t>(i)] = 1;
  return true;
}

int Stock::columnAt(double z) const {
  const double f = (z + length_) / dz_;
  if (!(f >= 0.0) || f > columnCount()) return -1;
  return std::min(static_cast<int>(f), columnCount() - 1);
}

void Stock::columnRange(double z0, double z1, int& first, int& last) const {
  if (!std::isfinite(z0) || !std::isfinite(z1)) {
    first = 0;
    last = -1;
    return;
  }
  // Centre of column i is -L + (i + 0.5) dz; want z0 <= centre <= z1.
  const double f0 = std::ceil((z0 + length_) / dz_ - 0.5);
  const double f1 = std::floor((z1 + length_) / dz_ - 0.5);
  const double n = columnCount();
  first = static_cast<int>(std::clamp(f0, 0.0, n));
  last = static_cast<int>(std::clamp(f1, -1.0, n - 1));
}

std::span<const Interval> Stock::column(int i) const { return columns_[static_cast<std::size_t>(i)]; }

double Stock::innerRadius(int i) const {
  const auto& c = columns_[static_cast<std::size_t>(i)];
  return c.empty() ? 0.0 : c.front().lo;
}

namespace {
// Largest of p[0..n) (radii, so never below 0). Four running maxima: one
// would wait on each comparison before the next (this is a hot loop of the cut).
double maxOf(const double* p, int n) {
  int k = 0;
#if defined(__SSE2__)
  // Two doubles an instruction (maxpd): GCC will not turn std::max into it by itself.
  __m128d v0 = _mm_setzero_pd(), v1 = _mm_setzero_pd();
  for (; k + 4 <= n; k += 4) {
    v0 = _mm_max_pd(v0, _mm_loadu_pd(p + k));
    v1 = _mm_max_pd(v1, _mm_loadu_pd(p + k + 2));
  }
  v0 = _mm_max_pd(v0, v1);
  double m0 = std::max(_mm_cvtsd_f64(v0), _mm_cvtsd_f64(_mm_unpackhi_pd(v0, v0))), m1 = 0.0, m2 = 0.0, m3 = 0.0;
#else
  double m0 = 0.0, m1 = 0.0, m2 = 0.0, m3 = 0.0;
  for (; k + 4 <= n; k += 4) {
    m0 = std::max(m0, p[k]);
    m1 = std::max(m1, p[k + 1]);
    m2 = std::max(m2, p[k + 2]);
    m3 = std::max(m3, p[k + 3]);
  }
#endif
  for (; k < n; ++k) m0 = std::max(m0, p[k]);
  return std::max(std::max(m0, m1), std::max(m2, m3));
}
}  // namespace

double Stock::maxOuterRadius(int first, int last) const {
  first = std::max(first, 0);
  const int end = std::min(last, columnCount() - 1) + 1;
  if (first >= end) return 0.0;
  auto up = [](int v, int step) { return (v + step - 1) / step * step; };
  auto down = [](int v, int step) { return v / step * step; };
  // Columns up to a block, blocks up to a super-block, super-blocks, then back
  // down; each level's maxima of consecutive blocks lie side by side.
  int i = std::min(end, up(first, kBlock));
  double m = maxOf(outer_.data() + first, i - first);
  if (const int to = std::min(down(end, kBlock), up(i, kSuper)); to > i) {
    m = std::max(m, maxOf(blockMax_.data() + i / kBlock, (to - i) / kBlock));
    i = to;
  }
  if (i % kSuper == 0 && end - i >= kSuper) {
    const int supers = (end - i) / kSuper;
    m = std::max(m, maxOf(superMax_.data() + i / kSuper, supers));
    i += supers * kSuper;
  }
  if (const int to = down(end, kBlock); to > i) {
    m = std::max(m, maxOf(blockMax_.data() + i / kBlock, (to - i) / kBlock));
    i = to;
  }
  return std::max(m, maxOf(outer_.data() + i, end - i));
}

bool Stock::maxOuterAbove(int first, int last, double r) const {
  if (!(r >= 0.0)) return true;  // the maximum is never below 0
  first = std::max(first, 0);
  const int end = std::min(last, columnCount() - 1) + 1;
  if (first >= end) return false;
  auto any = [r](const double* p, int n) {
    for (int k = 0; k < n; ++k)
      if (p[k] > r) return true;
    return false;
  };
  auto up = [](int v, int step) { return (v + step - 1) / step * step; };
  auto down = [](int v, int step) { return v / step * step; };
  // The pieces of maxOuterRadius, in its order.
  int i = std::min(end, up(first, kBlock));
  if (any(outer_.data() + first, i - first)) return true;
  if (const int to = std::min(down(end, kBlock), up(i, kSuper)); to > i) {
    if (any(blockMax_.data() + i / kBlock, (to - i) / kBlock)) return true;
    i = to;
  }
  if (i % kSuper == 0 && end - i >= kSuper) {
    const int supers = (end - i) / kSuper;
    if (any(superMax_.data() + i / kSuper, supers)) return true;
    i += supers * kSuper;
  }
  if (const int to = down(end, kBlock); to > i) {
    if (any(blockMax_.data() + i / kBlock, (to - i) / kBlock)) return true;
    i = to;
  }
  return any(outer_.data() + i, end - i);
}

void Stock::updateOuter(int i) {
  const auto& c = columns_[static_cast<std::size_t>(i)];
  const double old = outer_[static_cast<std::size_t>(i)];
  const double now = c.empty() ? 0.0 : c.back().hi;
  outer_[static_cast<std::size_t>(i)] = now;
  if (deferMaxima_ && now <= old) {
    lowerInBatch(i, now);
    return;
  }
  // Each level's maximum is recomputed from the level below only when it held the old value.
  auto refresh = [&](double& top, int first, int count, int step, auto&& below) {
    const double was = top;
    if (now > top) top = now;
    if (!(now < old && old >= was)) return;
    top = 0.0;
    for (int k = first; k < first + count; k += step) top = std::max(top, below(k));
  };
  const int b0 = i / kBlock * kBlock;
  refresh(blockMax_[static_cast<std::size_t>(i / kBlock)], b0, std::min(kBlock, columnCount() - b0), 1,
          [&](int k) { return outer_[static_cast<std::size_t>(k)]; });
  const int s0 = i / kSuper * kSuper;
  refresh(superMax_[static_cast<std::size_t>(i / kSuper)], s0, std::min(kSuper, columnCount() - s0), kBlock,
          [&](int k) { return blockMax_[static_cast<std::size_t>(k / kBlock)]; });
}

void Stock::settleDirty() {
  const int n = columnCount();
  const int blocks = static_cast<int>(blockMax_.size());
  for (int b = dirtyFirst_; b <= dirtyLast_; ++b)
    blockMax_[static_cast<std::size_t>(b)] = maxOf(outer_.data() + b * kBlock, std::min(kBlock, n - b * kBlock));
  for (int s = dirtyFirst_ * kBlock / kSuper; s <= dirtyLast_ * kBlock / kSuper; ++s) {
    const int first = s * (kSuper / kBlock);
    superMax_[static_cast<std::size_t>(s)] = maxOf(blockMax_.data() + first, std::min(kSuper / kBlock, blocks - first));
  }
  dirtyFirst_ = 0;
  dirtyLast_ = -1;
}

void Stock::setTally(RemovalTally* tally) {
  tally_ = tally;
  if (tally_) {
    tally_->radial.assign(columns_.size(), 0.0);
    tally_->touched.clear();
    tally_->sectionArea = 0.0;
  }
}

namespace {
void addToTally(RemovalTally& t, int i, double radial, double dz) {
  double& r = t.radial[static_cast<std::size_t>(i)];
  if (r == 0.0) t.touched.push_back(i);
  r += radial;
  t.sectionArea += radial * dz;
}
}  // namespace

double Stock::removeFromMaterial(int i, double lo, double hi) {
  auto& c = columns_[static_cast<std::size_t>(i)];
  if (c.size() == 1 && hi >= c[0].hi && lo > c[0].lo) {
    // The common case: turning the outside of a solid or bored column down.
    const double area = c[0].hi * c[0].hi - lo * lo;
    if (tally_) addToTally(*tally_, i, c[0].hi - lo, dz_);
    c[0].hi = lo;
    if (deferMaxima_)
      lowerInBatch(i, lo);  // what updateOuter does for a lowered column, without its call
    else
      updateOuter(i);
    removed_ += std::numbers::pi * area * dz_;
    return std::numbers::pi * area * dz_;
  }
  double removedArea = 0.0;  // integral of 2*pi*r dr over the removed radii, / pi
  std::vector<Interval> kept;
  bool changed = false;
  for (const Interval& in : c) {
    if (in.hi <= lo || in.lo >= hi) {
      kept.push_back(in);
      continue;
    }
    changed = true;
    const double a = std::max(in.lo, lo);
    const double b = std::min(in.hi, hi);
    removedArea += b * b - a * a;
    if (tally_) addToTally(*tally_, i, b - a, dz_);
    if (in.lo < lo) kept.push_back({in.lo, lo});
    if (in.hi > hi) kept.push_back({hi, in.hi});
  }
  if (!changed) return 0.0;
  c = std::move(kept);
  updateOuter(i);
  removed_ += std::numbers::pi * removedArea * dz_;
  return std::numbers::pi * removedArea * dz_;
}

double Stock::overlapWithMaterial(int i, double lo, double hi) const {
  double best = 0.0;
  for (const Interval& in : columns_[static_cast<std::size_t>(i)])
    best = std::max(best, std::min(in.hi, hi) - std::max(in.lo, lo));
  return best;
}

double Stock::volume() const {
  double area = 0.0;
  for (const auto& c : columns_)
    for (const Interval& in : c) area += in.hi * in.hi - in.lo * in.lo;
  return std::numbers::pi * area * dz_;
}

double Stock::initialVolume() const {
  return std::numbers::pi * (diameter_ * diameter_ - bore_ * bore_) / 4.0 * length_;
}

}  // namespace klueng::core::cut

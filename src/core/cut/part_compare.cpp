#include "klueng/core/cut/part_compare.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace klueng::core::cut {

namespace {

// The smallest and largest value of f(j) for j in [i - k, i + k] (clamped),
// for every i: one pass with monotonic queues.
template <typename F>
void slidingRange(int n, int k, F f, std::vector<double>& lo, std::vector<double>& hi) {
  lo.assign(static_cast<std::size_t>(n), 0.0);
  hi.assign(static_cast<std::size_t>(n), 0.0);
  std::deque<int> minQ, maxQ;
  int added = 0;
  for (int i = 0; i < n; ++i) {
    for (; added < n && added <= i + k; ++added) {
      while (!minQ.empty() && f(minQ.back()) >= f(added)) minQ.pop_back();
      minQ.push_back(added);
      while (!maxQ.empty() && f(maxQ.back()) <= f(added)) maxQ.pop_back();
      maxQ.push_back(added);
    }
    while (minQ.front() < i - k) minQ.pop_front();
    while (maxQ.front() < i - k) maxQ.pop_front();
    lo[static_cast<std::size_t>(i)] = f(minQ.front());
    hi[static_cast<std::size_t>(i)] = f(maxQ.front());
  }
}

}  // namespace

PartDeviation compareParts(const Stock& student, const Stock& reference, double zTolerance) {
  PartDeviation d;
  const double same = 1e-6;
  d.sameBar = std::abs(student.diameter() - reference.diameter()) < same &&
              std::abs(student.length() - reference.length()) < same &&
              std::abs(student.bore() - reference.bore()) < same;
  const int n = reference.columnCount();
  if (n <= 0 || student.columnCount() <= 0) return d;
  const int k = std::max(0, static_cast<int>(std::ceil(zTolerance / reference.resolution() - 1e-9)));
  std::vector<double> outerLo, outerHi, innerLo, innerHi;
  slidingRange(
      n, k, [&](int j) { return reference.outerRadius(j); }, outerLo, outerHi);
  slidingRange(
      n, k, [&](int j) { return reference.innerRadius(j); }, innerLo, innerHi);
  auto note = [&d](double excess, double z, bool leftover) {
    double& worst = leftover ? d.leftover : d.gouge;
    if (2.0 * excess > worst) {
      worst = 2.0 * excess;
      (leftover ? d.leftoverZ : d.gougeZ) = z;
    }
  };
  for (int i = 0; i < n; ++i) {
    const double z = reference.zCentre(i);
    const int s = student.columnAt(z);
    const double outer = s >= 0 ? student.outerRadius(s) : 0.0;
    const double inner = s >= 0 && outer > 0.0 ? student.innerRadius(s) : 0.0;
    const std::size_t u = static_cast<std::size_t>(i);
    note(outer - outerHi[u], z, true);   // bigger than the reference anywhere near: left on
    note(outerLo[u] - outer, z, false);  // smaller than it anywhere near: cut away
    if (outer > 0.0 && outerLo[u] > 0.0) {
      note(innerLo[u] - inner, z, true);   // a bore smaller: left on
      note(inner - innerHi[u], z, false);  // a bore bigger: cut away
    }
  }
  return d;
}

}  // namespace klueng::core::cut

#include "klueng/core/machine/timeline.h"

#include <algorithm>

namespace klueng::core::machine {

int Timeline::moveAt(double t) const {
  if (moves.empty() || t < moves.front().tStart) return -1;
  auto it = std::upper_bound(moves.begin(), moves.end(), t,
                             [](double time, const Move& m) { return time < m.tEnd; });
  if (it == moves.end()) return static_cast<int>(moves.size()) - 1;
  return static_cast<int>(it - moves.begin());
}

Vec2 Timeline::positionAt(double t) const {
  const int i = moveAt(t);
  if (i < 0) return moves.empty() ? Vec2(Vec2::Zero()) : moves.front().path.start;
  const Move& m = moves[static_cast<std::size_t>(i)];
  const double span = m.tEnd - m.tStart;
  const double s = span > 0 ? std::clamp((t - m.tStart) / span, 0.0, 1.0) : 1.0;
  return m.path.pointAt(s);
}

}  // namespace klueng::core::machine

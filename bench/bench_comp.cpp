// Nose radius compensation kernel: one long compensated stretch of a stepped
// shaft profile (chamfers, G02/G03 R2 corners, steps), and sample 01's
// 12-move finishing stretch.
#include <benchmark/benchmark.h>

#include <vector>

#include "klueng/core/comp/nose_comp.h"

namespace {

using klueng::core::Segment;
using klueng::core::Vec2;
using namespace klueng::core::comp;

// Start-up, `steps` repetitions of (diameter, chamfer, diameter, G02 fillet,
// face, G03 corner), cancel: 6 * steps + 2 moves.
std::vector<Segment> steppedShaft(int steps) {
  std::vector<Segment> m;
  Vec2 at(5, 10);
  auto line = [&](double dz, double dx) {
    const Vec2 to = at + Vec2(dz, dx);
    m.push_back(Segment::line(at, to));
    at = to;
  };
  auto arc = [&](double dz, double dx, Vec2 centreOffset, bool ccw) {
    const Vec2 to = at + Vec2(dz, dx);
    m.push_back(Segment::arc(at, to, at + centreOffset, ccw));
    at = to;
  };
  line(-3, 0);  // start-up
  for (int i = 0; i < steps; ++i) {
    line(-2, 0);
    line(-0.5, 0.5);  // 45-degree chamfer
    line(-3, 0);
    arc(-1, 1, {0, 1}, false);  // G02 R1 fillet
    line(0, 0.5);               // face up
    arc(-1, 1, {-1, 0}, true);  // G03 R1 corner
  }
  line(50, 20);  // cancel
  return m;
}

void BM_CompensateSteppedShaft(benchmark::State& state) {
  const auto moves = steppedShaft(static_cast<int>(state.range(0)));
  const CompInput in{moves, Side::Right, 0.8, 3, true};
  for (auto _ : state) {
    CompOutput out = compensate(in);
    benchmark::DoNotOptimize(out.pieces.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(moves.size()));
}
BENCHMARK(BM_CompensateSteppedShaft)->Arg(2)->Arg(1000)->Arg(100000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();

#include "klueng/core/cut/comp_compare.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace klueng::core::cut {

namespace {

// The gap between the two parts at column i of the compensated one: the
// shortest distance from its surface point to the other's profile (square to
// the surfaces where they run alike), + where the other has material there, -
// where it was cut deeper.
double normalGap(const Stock& a, const Stock& b, int i) {
  const double z = a.zCentre(i), r = a.outerRadius(i);
  const double radial = b.outerRadius(i) - r;
  if (radial == 0.0) return 0.0;
  const int reach = static_cast<int>(std::ceil(std::abs(radial) / a.resolution())) + 1;
  double best = std::abs(radial);
  for (int j = std::max(0, i - reach); j < std::min(a.columnCount() - 1, i + reach); ++j) {
    // Segment between the other profile's column centres j and j + 1.
    const Vec2 p(b.zCentre(j), b.outerRadius(j)), q(b.zCentre(j + 1), b.outerRadius(j + 1));
    const Vec2 d = q - p;
    const double t = std::clamp((Vec2(z, r) - p).dot(d) / d.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (p + t * d - Vec2(z, r)).norm());
  }
  return radial > 0.0 ? best : -best;
}

}  // namespace

CompComparison compareCompensation(const gcode::Program& program, const machine::MachineSetup& setup,
                                   const machine::RunOptions& run, const CutSetup& cut, CompareWith with,
                                   double minimum) {
  CompComparison out;
  machine::RunOptions otherRun = run;
  machine::MachineSetup otherSetup = setup;
  CutSetup otherCut = cut;
  if (with == CompareWith::NoCompensation) {
    otherRun.noseCompensation = false;
  } else {
    for (io::Offset& o : otherSetup.offsets.offsets) o.r = 0.0;
    for (io::Offset& o : otherCut.offsets.offsets) o.r = 0.0;
  }
  machine::RunOptions quiet = run;
  quiet.persistentVariables = nullptr;  // two runs must not write #500-#999 twice
  otherRun.persistentVariables = nullptr;
  const machine::Timeline a = machine::interpret(program, setup, quiet);
  const machine::Timeline b = machine::interpret(program, otherSetup, otherRun);
  out.usesCompensation =
      std::any_of(a.moves.begin(), a.moves.end(), [](const machine::Move& m) { return m.compensated; });

  CutOptions options;
  options.checkpointBudgetBytes = 0;
  CutSimulator sa(a, cut, options);
  sa.runToEnd();
  CutSimulator sb(b, otherCut, options);
  sb.runToEnd();
  out.alarm = sa.stoppingAlarm();
  if (!out.alarm) out.alarm = sb.stoppingAlarm();
  const Stock& sta = sa.stock();
  const Stock& stb = sb.stock();
  out.compensated = sta;
  out.other = stb;

  // Runs of columns where the surfaces stand apart, one sign and one feature
  // of the compensated part each ("the chamfer", "the corner").
  const PartFeatures features = partFeatures(sta);
  const auto featureAt = [&](double z) -> int {
    for (std::size_t k = 0; k < features.outside.size(); ++k) {
      const PartFeature& f = features.outside[k];
      if (f.kind != FeatureKind::Face && z >= f.zLeft - 1e-9 && z <= f.zRight + 1e-9) return static_cast<int>(k);
    }
    return -1;
  };
  const auto gapAt = [&](int i) { return sta.outerRadius(i) > 0.0 ? normalGap(sta, stb, i) : 0.0; };
  for (int i = 0; i < sta.columnCount();) {
    const double g = gapAt(i);
    if (std::abs(g) < minimum) {
      ++i;
      continue;
    }
    const int feature = featureAt(sta.zCentre(i));
    CompDifference d;
    int j = i;
    for (; j < sta.columnCount(); ++j) {
      const double h = gapAt(j);
      if (std::abs(h) < minimum || (h > 0.0) != (g > 0.0) || featureAt(sta.zCentre(j)) != feature) break;
      if (std::abs(h) <= std::abs(d.normal)) continue;
      d.normal = h;
      d.z = sta.zCentre(j);
      d.radial = stb.outerRadius(j) - sta.outerRadius(j);
      d.diameter = 2.0 * sta.outerRadius(j);
    }
    d.zLeft = sta.zLeft(i);
    d.zRight = sta.zRight(j - 1);
    if (feature >= 0) {
      const PartFeature& f = features.outside[static_cast<std::size_t>(feature)];
      d.feature = f.kind;
      d.label = featureLabel(f, Lang::En);
    }
    out.differences.push_back(d);
    i = j;
  }
  if (out.differences.empty()) return out;

  // The block that cut each surface: the last move of the compensated run that
  // took material from the deepest column.
  CutSimulator replay(a, cut, options);
  const double end = sa.endTime();
  std::vector<double> before(out.differences.size());
  for (std::size_t k = 0; k < out.differences.size(); ++k)
    before[k] = replay.stock().outerRadius(replay.stock().columnAt(out.differences[k].z));
  for (std::size_t m = 0; m < a.moves.size() && a.moves[m].tStart < end; ++m) {
    replay.advanceTo(std::min(a.moves[m].tEnd, end));
    for (std::size_t k = 0; k < out.differences.size(); ++k) {
      const double now = replay.stock().outerRadius(replay.stock().columnAt(out.differences[k].z));
      if (now < before[k] - 1e-9) {
        out.differences[k].line = a.moves[m].line;
        out.differences[k].file = a.moves[m].file;
        out.differences[k].blockIndex = a.moves[m].blockIndex;
      }
      before[k] = now;
    }
  }
  std::sort(out.differences.begin(), out.differences.end(),
            [](const CompDifference& x, const CompDifference& y) { return std::abs(x.normal) > std::abs(y.normal); });
  return out;
}

std::string describeDifference(const CompDifference& d, const gcode::Program& program, CompareWith with, Lang lang,
                               const UnitFormat& units) {
  const bool th = lang == Lang::Th;
  std::string block = (th ? "บรรทัด " : "line ") + std::to_string(d.line);
  if (d.blockIndex >= 0 && static_cast<std::size_t>(d.blockIndex) < program.blocks.size()) {
    const gcode::Block& b = program.blocks[static_cast<std::size_t>(d.blockIndex)];
    if (const gcode::Word* n = b.find('N')) block = fmt::format("N{}", static_cast<long long>(std::llround(n->value)));
  }
  std::string what = featureKindName(d.feature, lang);
  if (!th) std::transform(what.begin(), what.end(), what.begin(), [](unsigned char c) { return std::tolower(c); });
  const std::string how = with == CompareWith::NoCompensation ? (th ? "เมื่อไม่ชดเชยรัศมีจมูกมีด" : "without compensation")
                                                              : (th ? "เมื่อจมูกมีดแหลม (R 0)" : "with a sharp nose (R 0)");
  const std::string amount =
      units.inch() ? fmt::format("{:.4f}", units.value(std::abs(d.normal))) : fmt::format("{:.2f}", std::abs(d.normal));
  const std::string unit = units.unitName(lang);
  if (th)
    return fmt::format("{} {} {}: {} {} {} {}", what, d.label, block, d.normal > 0.0 ? "เนื้อเหลือเกิน" : "กินลึกเกิน", amount,
                       unit, how);
  return fmt::format("{} {} {}: {} {} {} {}", what, d.label, block, amount, unit, d.normal > 0.0 ? "short" : "too deep",
                     how);
}

}  // namespace klueng::core::cut

// libFuzzer target: the whole pipeline a student's program goes through —
// parse, check, interpret (cycles, subprogram calls, nose radius compensation),
// cut on a small bar with the shipped tools — in the three dialects.
// Beyond "no crash": every diagnostic has its message, times never run
// backwards, positions stay finite, cutting only ever removes material.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/finished_part.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/messages.h"

using namespace klueng::core;

namespace {

// The shipped machine, tools and offsets, read once (KLUENG_SOURCE_DIR has them).
const machine::MachineSetup& shippedSetup() {
  static const machine::MachineSetup setup = [] {
    machine::MachineSetup s = machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
    s.machine.maxBlocks = 20000;  // endless loops end fast
    s.machine.maxRunTime = 36000.0;
    return s;
  }();
  return setup;
}

bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

void requireMessage(const Diagnostic& d) {
  if (!findMessage(d.code)) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 8000) return 0;  // long inputs are the parser's business (fuzz_gcode)
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const gcode::Program program = gcode::parse(text, 1);
  const gcode::Dialect dialect =
      size % 3 == 0 ? gcode::Dialect::Haas : (size % 3 == 1 ? gcode::Dialect::Fanuc : gcode::Dialect::Classic);
  gcode::CheckOptions check;
  check.dialect = dialect;
  for (const Diagnostic& d : gcode::check(program, check)) requireMessage(d);

  // The interpreter runs whatever the check says: it must be safe on programs the check refuses.
  machine::RunOptions run;
  run.dialect = dialect;
  const machine::MachineSetup& setup = shippedSetup();
  const machine::Timeline timeline = machine::interpret(program, setup, run);
  if (timeline.alarm) requireMessage(*timeline.alarm);
  for (const Diagnostic& n : timeline.flow.notices) requireMessage(n);
  double t = 0.0;
  for (const machine::Move& m : timeline.moves) {
    if (!(m.tStart >= t - 1e-9) || !(m.tEnd >= m.tStart) || !std::isfinite(m.tEnd)) std::abort();
    if (!finite(m.path.start) || !finite(m.path.end)) std::abort();
    t = m.tEnd;
  }

  // Cut the first moves on a Ø30 x 40 bar at a coarse resolution: the stock model's
  // invariants, not the run length, are what the fuzzer should explore.
  io::JobHeader header;
  header.diameter = 30.0;
  header.length = 40.0;
  cut::CutOptions options;
  options.resolution = 0.2;
  options.checkpointBudgetBytes = 1u << 20;
  cut::CutSimulator sim(timeline, cut::CutSetup::from(header, setup), options);
  const std::size_t limit = std::min<std::size_t>(timeline.moves.size(), 3000);
  if (limit > 0) sim.advanceTo(timeline.moves[limit - 1].tEnd);
  if (sim.alarm()) requireMessage(*sim.alarm());
  for (const Diagnostic& d : sim.toolDiagnostics()) requireMessage(d);
  const cut::Stock& stock = sim.stock();
  for (int i = 0; i < stock.columnCount(); ++i)
    if (!(stock.outerRadius(i) >= 0.0) || stock.outerRadius(i) > 15.0 + 1e-9) std::abort();
  if (stock.volume() > stock.initialVolume() + 1e-6) std::abort();
  const cut::FinishedPart part(stock);
  if (!part.empty() && !(part.maxDiameter() <= 30.0 + 1e-9)) std::abort();
  // The part's features (issue 10): on the part, finite, in order from the right face.
  const cut::PartFeatures features = cut::partFeatures(stock);
  for (const auto* list : {&features.outside, &features.inside})
    for (const cut::PartFeature& f : *list) {
      if (!std::isfinite(f.zLeft) || !std::isfinite(f.zRight) || f.zLeft > f.zRight + 1e-9) std::abort();
      if (f.zLeft < -40.0 - 1e-6 || f.zRight > 1e-6) std::abort();
      if (cut::describeFeature(f, Lang::Th).empty()) std::abort();
    }
  // Going back restores the bar exactly as it was.
  sim.advanceTo(0.0);
  if (std::abs(sim.stock().volume() - stock.initialVolume()) > 1e-6 * stock.initialVolume()) std::abort();
  return 0;
}

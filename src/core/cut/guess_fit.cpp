#include "klueng/core/cut/guess_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>
#include <string>

#include <fmt/format.h>

#include "klueng/core/cut/tool_shape.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::cut {

using io::ToolKind;

namespace {

// A guessed station's touch in one run.
struct Touch {
  int station = 0;
  bool chuck = false;  // the chuck, else the stock
  int line = 0;
  int severity = 0;  // 1 = a warning (the run went on), 2 = the alarm that stopped it
};

// The guessed stations' touches of a finished run, in the order they happened
// (warnings as the run met them, the stopping alarm last).
std::vector<Touch> touchesOf(const CutSimulator& sim, const machine::Timeline& timeline, const io::ToolTable& tools) {
  std::vector<Touch> out;
  for (const Diagnostic& w : sim.warnings()) {
    if (w.args.empty()) continue;
    const int station = std::atoi(w.args[0].c_str());
    out.push_back({station, w.code == std::string(codes::kGuessHitsChuck), w.range.line, 1});
  }
  if (const auto& alarm = sim.alarm()) {
    const bool stock =
        alarm->code == std::string(codes::kRapidIntoStock) || alarm->code == std::string(codes::kHolderHitsStock);
    const bool chuck = alarm->code == std::string(codes::kToolHitsChuck);
    const int i = sim.currentMove();
    if ((stock || chuck) && i >= 0) {
      const int station = timeline.moves[static_cast<std::size_t>(i)].tool;
      if (tools.isGuess(station)) out.push_back({station, chuck, alarm->range.line, 2});
    }
  }
  return out;
}

// How badly `station` fared in a run: 0 clean, 1 a warning, 2 it stopped the run.
int severityFor(const std::vector<Touch>& touches, int station) {
  int worst = 0;
  for (const Touch& t : touches)
    if (t.station == station) worst = std::max(worst, t.severity);
  return worst;
}

const io::LibraryTool* libraryToolAt(const io::ToolTable& tools, int station, const io::ToolLibrary& library) {
  const std::string id = tools.libraryId(station);
  return id.empty() ? nullptr : library.find(id);
}

std::string toolName(const io::ToolTable& tools, int station) {
  const std::string id = tools.libraryId(station);
  if (!id.empty()) return id;
  const std::string& line = tools.bitmap[static_cast<std::size_t>(station - 1)];
  return line.substr(line.find_last_of('/') + 1);
}

// Lowest point (radial distance above the controlled point) of a holder part
// wider in Z than the cutting edge: how deep the blade plunges before its holder
// meets the groove's walls. A narrow blade behind the insert is not counted.
double bladeReach(const ToolShape& s) {
  double z0 = std::numeric_limits<double>::infinity(), z1 = -z0;
  for (const Trapezoid& t : s.cutting) {
    const Box b = t.bounds();
    z0 = std::min(z0, b.z0);
    z1 = std::max(z1, b.z1);
  }
  double reach = std::numeric_limits<double>::infinity();
  for (const Box& h : s.holder)
    if (h.z0 < z0 - 1e-6 || h.z1 > z1 + 1e-6) reach = std::min(reach, h.x0);
  return reach;
}

}  // namespace

std::vector<const io::LibraryTool*> guessCandidates(const machine::Timeline& timeline,
                                                    const machine::MachineSetup& setup, int station,
                                                    const io::ToolLibrary& library) {
  std::vector<const io::LibraryTool*> out;
  // What the guess is: a library tool's kind and size, or what a table bitmap's file name says
  // (then its size is unknown: no drill or blade is put in its place).
  const io::LibraryTool* guess = libraryToolAt(setup.tools, station, library);
  const std::string& line = setup.tools.bitmap[static_cast<std::size_t>(station - 1)];
  const ToolKind kind = guess ? guess->kind : io::guessToolKind(line);
  if (kind == ToolKind::Unknown) return out;
  // The offset rows the station cuts with: the recorded path used their nose.
  std::set<int> rows;
  for (const machine::Move& m : timeline.moves)
    if (m.tool == station) rows.insert(m.offset >= 1 ? m.offset : station);
  const auto sameNose = [&](const io::LibraryTool& t) {
    for (int row : rows) {
      if (row < 1 || row > io::kOffsetCount) continue;
      const io::Offset& o = setup.offsets.at(row);
      if (o.r != t.noseRadius || o.tip != t.tip) return false;
    }
    return true;
  };
  const bool sized = kind == ToolKind::Drill || kind == ToolKind::CentreDrill || kind == ToolKind::Grooving ||
                     kind == ToolKind::Parting;
  if (sized && !guess) return out;
  for (const io::LibraryTool& t : library.tools) {
    if ((guess && t.id == guess->id) || !io::toolKindFits(t.kind, kind)) continue;
    // A drill's size and a blade's width are what the program's moves assume (the depth
    // of a hole, the Z steps across a groove): another size would cut another part.
    if (sized && std::abs(t.size - guess->size) > 1e-6) continue;
    if (!sameNose(t)) continue;
    out.push_back(&t);
  }
  // Order, from the tools' own drawings. A bar in a bore touches with the head below its
  // insert: the smaller its height (X extent), the more room it leaves. A blade in a
  // groove touches with the holder beside its blade: the deeper that holder starts, the
  // deeper it plunges. Other kinds keep the library's order. Ties keep the library's order.
  auto key = [&](const io::LibraryTool* t) {
    io::ReadResult<ToolShape> s = loadToolShape(library.bitmapPath(*t), t->noseRadius, t->tip, t->pixelsPerMm);
    if (!s.ok()) return std::numeric_limits<double>::infinity();  // an unreadable bitmap last
    if (kind == ToolKind::Boring) return s.value->bounds.x1 - s.value->bounds.x0;
    if (kind == ToolKind::Grooving || kind == ToolKind::Parting) return -bladeReach(*s.value);
    return 0.0;
  };
  std::vector<std::pair<double, const io::LibraryTool*>> keyed;
  for (const io::LibraryTool* t : out) keyed.emplace_back(key(t), t);
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  out.clear();
  for (const auto& [k, t] : keyed)
    if (std::isfinite(k) && out.size() < static_cast<std::size_t>(kMaxGuessCandidates)) out.push_back(t);
  return out;
}

GuessFit fitGuessedTools(const machine::Timeline& timeline, const io::JobHeader& header,
                         const machine::MachineSetup& setup, const io::ToolLibrary& library,
                         const CutOptions& options) {
  GuessFit out;
  out.setup = setup;
  // A whole cut; with giveUpOn, a trial that stops as soon as that station warns (when a
  // warning is no better than what the station already has, the rest of the run cannot help).
  const auto run = [&](const machine::MachineSetup& s, int giveUpOn = 0) {
    auto sim = std::make_unique<CutSimulator>(timeline, CutSetup::from(header, s), options);
    ++out.runs;
    if (giveUpOn > 0) {
      const std::string station = fmt::format("{:02}", giveUpOn);
      std::size_t seen = 0;
      for (const machine::Move& m : timeline.moves) {
        sim->advanceTo(m.tEnd);
        if (sim->alarm()) return sim;
        for (; seen < sim->warnings().size(); ++seen)
          if (!sim->warnings()[seen].args.empty() && sim->warnings()[seen].args[0] == station) return sim;
      }
    }
    sim->runToEnd();
    return sim;
  };
  out.cut = run(out.setup);
  // Terminates: every pass of the loop settles one more station (a station is fitted
  // once, in the order its touch happened), and fitting one costs at most
  // kMaxGuessCandidates runs; only stations that touched are ever fitted.
  std::set<int> settled;
  for (;;) {
    const std::vector<Touch> touches = touchesOf(*out.cut, timeline, out.setup.tools);
    const auto next = std::find_if(touches.begin(), touches.end(), [&](const Touch& t) {
      return t.station >= 1 && t.station <= io::kMaxStations && !settled.contains(t.station);
    });
    if (next == touches.end()) break;
    const Touch touch = *next;
    settled.insert(touch.station);
    int bestSeverity = touch.severity;
    const std::string firstGuess = toolName(out.setup.tools, touch.station);
    for (const io::LibraryTool* candidate : guessCandidates(timeline, out.setup, touch.station, library)) {
      machine::MachineSetup trial = out.setup;
      trial.tools.setLibraryTool(touch.station, candidate->id, library.bitmapPath(*candidate), candidate->pixelsPerMm);
      trial.tools.guessed[static_cast<std::size_t>(touch.station - 1)] = true;  // still Klueng's guess
      std::unique_ptr<CutSimulator> sim = run(trial, bestSeverity <= 1 ? touch.station : 0);
      const int severity = severityFor(touchesOf(*sim, timeline, trial.tools), touch.station);
      if (severity >= bestSeverity) continue;  // no better than what the station has
      bestSeverity = severity;
      Diagnostic note;
      note.severity = Severity::Note;
      note.code = touch.chuck ? codes::kGuessReplacedChuck : codes::kGuessReplacedStock;
      note.range = SourceRange{touch.line, 1, 0};
      note.args = {fmt::format("{:02}", touch.station), candidate->id, firstGuess, std::to_string(touch.line)};
      if (!out.notes.empty() && out.notes.back().args[0] == note.args[0]) out.notes.pop_back();  // a better one
      out.notes.push_back(std::move(note));
      out.setup = std::move(trial);
      out.cut = std::move(sim);
      if (severity == 0) break;  // the first that runs clean for the station
    }
  }
  return out;
}

}  // namespace klueng::core::cut

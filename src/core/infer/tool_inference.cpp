#include "klueng/core/infer/tool_inference.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "infer/tool_evidence.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/messages.h"

namespace klueng::core::machine {

namespace {

using io::ToolKind;

constexpr double kCentreDrillMaxMm = 5.0;  // a drill on centre no deeper than this is a centre drill
constexpr double kPartingBeyondMm = 2.0;   // a plunge to X0 deeper than this in Z is not facing
constexpr double kMinZRunMm = 0.5;         // a Z feed shorter than this says nothing about the side
constexpr double kMinPlungeMm = 2.0;       // a radial feed this deep (on the diameter) is a plunge
constexpr double kGroovingReachMm = 6.0;   // deeper (radius) than a grooving blade reaches: a parting blade

using detail::Evidence;
using detail::MotionUse;
using detail::StationUse;

std::string twoDigits(int n) { return fmt::format("{:02}", n); }

const char* noteCode(ToolReason r) {
  switch (r) {
    case ToolReason::Comment: return codes::kToolFromComment;
    case ToolReason::Threading: return codes::kToolForThreading;
    case ToolReason::ThreadingInside: return codes::kToolForInsideThreading;
    case ToolReason::Grooving: return codes::kToolForGrooving;
    case ToolReason::Drilling: return codes::kToolForDrilling;
    case ToolReason::Boring: return codes::kToolForBoring;
    case ToolReason::Parting: return codes::kToolForParting;
    case ToolReason::Turning: return codes::kToolForTurning;
    case ToolReason::Override: return codes::kToolSetForJob;
  }
  return codes::kToolForTurning;
}

// The library tool for a kind of work: the first of that kind, refined by the
// insert or drill size a comment names and by finishing.
const io::LibraryTool* pick(const io::ToolLibrary& lib, const Evidence& e) {
  const io::LibraryTool* best = nullptr;
  const std::string insert = e.insert.empty() ? "cnmg" : e.insert;  // the everyday insert unless named
  for (const io::LibraryTool& t : lib.tools) {
    if (t.kind != e.kind) continue;
    if (!best) best = &t;
    if (e.kind == ToolKind::Turning) {
      const bool insertMatch = t.id.rfind(insert, 0) == 0;
      const bool bestInsert = best->id.rfind(insert, 0) == 0;
      if (insertMatch && !bestInsert)
        best = &t;
      else if (insertMatch && bestInsert && e.finishing && t.noseRadius < best->noseRadius)
        best = &t;
    } else if (e.kind == ToolKind::Drill && e.drillMm > 0.0) {
      if (std::abs(t.size - e.drillMm) < std::abs(best->size - e.drillMm)) best = &t;
    }
  }
  return best;
}

// A note of the inference at a file line.
Diagnostic noteAt(const char* code, int line, std::vector<std::string> args) {
  Diagnostic d;
  d.severity = Severity::Note;
  d.code = code;
  d.range.line = line;
  d.args = std::move(args);
  return d;
}

bool offsetEmpty(const io::Offset& o) { return o.x == 0.0 && o.z == 0.0 && o.r == 0.0 && o.tip == 0; }

// What the station's current tool is: a library tool's kind, a library
// bitmap's, or what its file name says.
std::optional<ToolKind> currentKind(const io::ToolTable& tools, int station, const io::ToolLibrary& lib) {
  const std::string& line = tools.bitmap[static_cast<std::size_t>(station - 1)];
  if (line.empty()) return std::nullopt;
  if (const std::string id = tools.libraryId(station); !id.empty()) {
    const io::LibraryTool* t = lib.find(id);
    return t ? t->kind : ToolKind::Unknown;
  }
  return io::guessToolKind(line);
}

// What a tools.cfg line names: "02-outside-left-hand.bmp" is a left-hand turning tool.
bool namesLeftHand(std::string_view fileName) {
  std::string name(fileName);
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return name.find("left-hand") != std::string::npos || name.find("left_hand") != std::string::npos ||
         name.find("lefthand") != std::string::npos;
}
}  // namespace

Diagnostic ToolChoice::note() const {
  return noteAt(noteCode(reason), line, {twoDigits(station), libraryId, detail, std::to_string(line)});
}

std::vector<Diagnostic> ToolInference::notes() const {
  std::vector<Diagnostic> out;
  for (const ToolChoice& c : choices) out.push_back(c.note());
  out.insert(out.end(), offsetNotes.begin(), offsetNotes.end());
  return out;
}

const ToolChoice* ToolInference::choiceFor(int station) const {
  for (const ToolChoice& c : choices)
    if (c.station == station) return &c;
  return nullptr;
}

namespace {

// Which side of the centre the tools work: the user's choice for this file, else
// for a plain program the side its cuts are on, else the machine's setting.
bool toolsWorkBeyondCentre(const MachineSetup& setup, const InferenceContext& context, CutSide side) {
  if (context.toolsBeyondCentre) return *context.toolsBeyondCentre;
  if (context.fromProgram && side != CutSide::None) return side == CutSide::Beyond;
  return setup.machine.toolsBeyondCentre;
}

// The stations the run selects, those past the turret (or the dialect's T range)
// left out: they are the checker's business.
std::map<int, StationUse> stationsOnTheTurret(const detail::ProgramEvidence& evidence, int lastStation) {
  std::map<int, StationUse> uses = evidence.uses;
  std::erase_if(uses, [&](const auto& entry) { return entry.first > lastStation; });
  return uses;
}

// A plunge to X0 counts as parting only for one of the last two tools the program selects.
void creditPartingToLastTools(const detail::ProgramEvidence& evidence, std::map<int, StationUse>& uses) {
  std::vector<int> last;
  for (auto it = evidence.order.rbegin(); it != evidence.order.rend() && last.size() < 2; ++it)
    if (std::find(last.begin(), last.end(), *it) == last.end()) last.push_back(*it);
  for (const auto& [station, e] : evidence.partings)
    if (std::find(last.begin(), last.end(), station) != last.end() && uses.count(station) && !uses[station].cycle)
      uses[station].cycle = e;
}

// The offset rows of a station given a library tool take its nose radius and tip.
void takeLibraryNose(ToolInference& out, const io::LibraryTool& tool, int line, const std::set<int>& offsets,
                     bool fromProgram) {
  for (int n : offsets) {
    if (n < 1 || n > io::kOffsetCount) continue;
    io::Offset& o = out.setup.offsets.at(n);
    const bool empty = offsetEmpty(o);
    // A guessed tool brings its own nose: a row set for the table's tool is another tool's.
    if (!empty && !fromProgram) continue;
    if (!empty && o.r == tool.noseRadius && o.tip == tool.tip) continue;
    out.offsetNotes.push_back(noteAt(empty ? codes::kOffsetFromLibrary : codes::kOffsetReplacedByLibrary, line,
                                     {twoDigits(n), fmt::format("{:g}", tool.noseRadius), std::to_string(tool.tip),
                                      tool.id, fmt::format("{:g}", o.r), std::to_string(o.tip)}));
    o.r = tool.noseRadius;
    o.tip = tool.tip;
  }
}

// The station gets the library tool: its bitmap, the choice's note, its nose in the offset rows.
void fitLibraryTool(ToolInference& out, const io::ToolLibrary& library, int station, const io::LibraryTool& tool,
                    ToolReason reason, std::string detail, int line, const std::set<int>& offsets, bool fromProgram) {
  out.setup.tools.setLibraryTool(station, tool.id, library.bitmapPath(tool), tool.pixelsPerMm);
  out.choices.push_back({station, tool.id, reason, std::move(detail), line});
  takeLibraryNose(out, tool, line, offsets, fromProgram);
}

// The tools the user set for this job (--tool 03=vnmg): they win over any evidence.
// Returns the stations they set.
std::set<int> fitOverrides(ToolInference& out, const io::ToolLibrary& library,
                           const std::vector<StationOverride>& overrides, const std::map<int, StationUse>& uses,
                           int lastStation, bool fromProgram) {
  std::set<int> overridden;
  for (const StationOverride& o : overrides) {
    const io::LibraryTool* tool = library.find(o.libraryId);
    if (!tool || o.station < 1 || o.station > lastStation) continue;
    overridden.insert(o.station);
    const auto it = uses.find(o.station);
    fitLibraryTool(out, library, o.station, *tool, ToolReason::Override, {}, 0,
                   it == uses.end() ? std::set<int>{} : it->second.offsets, fromProgram);
  }
  return overridden;
}

// A thread cut outward from inside a bore, as its passes retract (unless a comment named its side).
void readThreadSide(StationUse& use) {
  if (use.cycle && use.cycle->reason == ToolReason::Threading && use.motion.threadInside > use.motion.threadOutside) {
    use.cycle->kind = ToolKind::ThreadingId;
    use.cycle->reason = ToolReason::ThreadingInside;
  }
}

// A plain program: the sums of its moves decide what no single block tells
// (a hand-written thread in a loop, a blade that only plunges, a drill fed by G01).
void readMoveSums(StationUse& use, const MotionUse& m, const detail::ProgramEvidence& evidence) {
  if (use.cycle || use.drillLine) return;
  Evidence e;
  e.strong = true;
  if (m.threadLine) {
    const bool inside = insideWork(m);
    e.kind = inside ? ToolKind::ThreadingId : ToolKind::ThreadingOd;
    e.reason = inside ? ToolReason::ThreadingInside : ToolReason::Threading;
    e.line = m.threadLine;
    e.detail = evidence.blockText(m.threadLine);
    use.cycle = e;
  } else if (m.drillLine && m.aboveZero + m.belowZero < 1.0) {  // it only ever feeds on the centre line
    use.drillLine = m.drillLine;
    use.drillDepthMm = m.drillDepth;
    use.drillCode = evidence.blockText(m.drillLine);
  } else if (m.plunge >= kMinPlungeMm && m.towardChuck + m.towardTail < kMinZRunMm && m.plungeZ < -kPartingBeyondMm) {
    // It only plunges straight in, behind the face: a blade's work (a groove, or a cut-off
    // into a bore); deep plunges need the parting blade's reach.
    const bool deep = m.plunge / 2.0 > kGroovingReachMm;
    e.kind = deep ? ToolKind::Parting : ToolKind::Grooving;
    e.reason = deep ? ToolReason::Parting : ToolReason::Grooving;
    e.line = m.plungeLine;
    e.detail = evidence.blockText(m.plungeLine);
    use.cycle = e;
  }
}

// Drilling on centre: a centre drill when shallow, else a drill.
void readDrilling(StationUse& use) {
  if (!use.drillLine || use.cycle) return;
  Evidence e;
  e.kind = -use.drillDepthMm <= kCentreDrillMaxMm ? ToolKind::CentreDrill : ToolKind::Drill;
  e.reason = ToolReason::Drilling;
  e.detail = use.drillCode;
  e.line = use.drillLine;
  e.strong = true;
  use.cycle = e;
}

// The run retracts inward after its Z feeds: the tool works inside a bore (a boring bar,
// an inside thread), unless a comment said otherwise.
void readInsideWork(Evidence& want, const MotionUse& m, const detail::ProgramEvidence& evidence) {
  if (want.kind == ToolKind::Turning || want.kind == ToolKind::Unknown) {
    const bool named = want.reason == ToolReason::Comment && want.kind == ToolKind::Turning;
    if (!named || m.outside == 0.0) {
      want.kind = ToolKind::Boring;
      want.reason = ToolReason::Boring;
      want.detail = evidence.blockText(m.insideLine);
      want.line = m.insideLine;
      want.strong = true;
    }
  } else if (want.kind == ToolKind::ThreadingOd && want.reason != ToolReason::Comment) {
    want.kind = ToolKind::ThreadingId;
    want.reason = ToolReason::ThreadingInside;
  }
}

// The tool the evidence asks for: a comment's, refined by a telling cycle or move, else
// a turning tool's; `moved` (a plain program's move sums) may put it inside a bore.
std::optional<Evidence> wantedTool(const StationUse& use, const MotionUse* moved,
                                   const detail::ProgramEvidence& evidence) {
  std::optional<Evidence> want = use.comment;
  if (use.cycle) {
    const bool refine = !want || want->kind == ToolKind::Turning ||
                        (want->kind == ToolKind::ThreadingOd && use.cycle->kind == ToolKind::ThreadingId);
    if (refine) want = use.cycle;
  }
  if (!want) want = use.turning;
  if (want && moved && insideWork(*moved)) readInsideWork(*want, *moved, evidence);
  return want;
}

// Whether the station keeps the tool the setup gives it.
bool keepsItsTool(const Evidence& want, int station, const MotionUse* moved, const MachineSetup& setup,
                  const io::ToolLibrary& library, bool fromProgram) {
  const std::optional<ToolKind> have = currentKind(setup.tools, station, library);
  if (!fromProgram) return have && (io::toolKindFits(*have, want.kind) || !want.strong);
  // The shop's program decides; the table only breaks ties: a tool of the right
  // kind (and hand, for turning) stays, anything else gives way to the evidence.
  // A comment naming the insert (VBMT, CNMG 120408) names a standard right-hand holder:
  // its feeds toward the tailstock are a profile's (a G72 shape's hub), not a left-hand tool's.
  const bool namedInsert = want.reason == ToolReason::Comment && !want.insert.empty();
  const bool left = moved && leftHandWork(*moved) && !namedInsert;
  const bool haveLeft = namesLeftHand(setup.tools.bitmap[static_cast<std::size_t>(station - 1)]);
  const bool known = have && *have != ToolKind::Unknown;
  const bool handFits = want.kind != ToolKind::Turning || left == haveLeft;
  if (known && io::toolKindFits(*have, want.kind) && handFits) return true;
  return want.kind == ToolKind::Turning && left;  // the library has no left-hand tool: the table's stays
}

// Each station the user did not set: what its evidence says it does, and the library
// tool for that unless the station's own tool already fits.
void fitToolsByEvidence(ToolInference& out, std::map<int, StationUse>& uses, const std::set<int>& overridden,
                        const detail::ProgramEvidence& evidence, const MachineSetup& setup,
                        const io::ToolLibrary& library, bool fromProgram) {
  for (auto& [station, use] : uses) {
    if (overridden.count(station)) continue;
    readThreadSide(use);
    const MotionUse* moved = fromProgram ? &use.motion : nullptr;
    if (moved) readMoveSums(use, *moved, evidence);
    readDrilling(use);
    const std::optional<Evidence> want = wantedTool(use, moved, evidence);
    if (!want || want->kind == ToolKind::Unknown) continue;
    if (keepsItsTool(*want, station, moved, setup, library, fromProgram)) continue;
    const io::LibraryTool* tool = pick(library, *want);
    if (!tool) continue;
    fitLibraryTool(out, library, station, *tool, want->reason, want->detail, want->line, use.offsets, fromProgram);
  }
}

// A plain program that works beyond the centre line (X < 0): its tools are there
// (unless the user said where they are for this file).
void placeToolsBySide(ToolInference& out, const InferenceContext& context, CutSide side,
                      const detail::ProgramEvidence& evidence) {
  if (context.toolsBeyondCentre) {
    out.setup.machine.toolsBeyondCentre = *context.toolsBeyondCentre;
  } else if (context.fromProgram) {
    if (side == CutSide::Beyond) {
      int line = 0;  // the first feed beyond the centre, for the note
      for (const auto& [station, use] : evidence.uses)
        if (use.motion.belowZero > 0.0 && (!line || use.motion.belowLine < line)) line = use.motion.belowLine;
      out.setup.machine.toolsBeyondCentre = true;
      out.offsetNotes.push_back(noteAt(codes::kToolsBeyondCentre, line, {std::to_string(line)}));
    } else if (side == CutSide::Front) {
      out.setup.machine.toolsBeyondCentre = false;  // in front, whatever the machine's setting says
    }
  }
}

// The nose radius a station's comment states ("(PROXODNOI R0.4)", "(OD TURN CNMG 431)") is the
// shop's insert: it wins over the guessed insert's and the shipped table's (issue 38 item 7).
void takeStatedNoseRadii(ToolInference& out, const std::map<int, StationUse>& uses, const std::set<int>& overridden) {
  constexpr double kFinishingNoseMm = 0.4;
  for (const auto& [station, use] : uses) {
    // A finishing tool whose comment states no radius: the library's finishing insert's (R0.4),
    // not the roughing R0.8 a table row or the everyday insert would give.
    const bool finishing =
        use.comment && use.comment->finishing && !use.comment->roughing && use.comment->kind == ToolKind::Turning;
    const double stated = use.noseRadiusMm > 0.0 ? use.noseRadiusMm : finishing ? kFinishingNoseMm : 0.0;
    if (!(stated > 0.0) || overridden.count(station)) continue;
    bool changed = false;
    for (int n : use.offsets.empty() ? std::set<int>{station} : use.offsets) {
      if (n < 1 || n > io::kOffsetCount) continue;
      io::Offset& o = out.setup.offsets.at(n);
      // (CNMG 432 is 0.794 mm: the R0.8 row is that insert.) Drills and threads have no nose.
      if (std::abs(o.r - stated) < 0.02 || o.tip == 0 || o.tip == 7 || o.tip == 8) continue;
      if (!(use.noseRadiusMm > 0.0) && o.r <= stated) continue;  // a finishing guess only makes a nose smaller
      o.r = stated;
      changed = true;
    }
    if (!changed) continue;
    out.offsetNotes.push_back(noteAt(codes::kNoseRadiusFromComment,
                                     use.noseRadiusMm > 0.0 ? use.noseRadiusLine : use.comment->line,
                                     {twoDigits(station), fmt::format("{:g}", std::round(stated * 1000.0) / 1000.0)}));
  }
}

// The highest Z another tool fed to within a blade's width above the Z it plunges to
// (zPlunge itself when none did).
double turnedBesidePlunge(const Timeline& record, int bladeStation, double zPlunge, double bladeWidth) {
  double turnedTo = zPlunge;
  record.forEachMove([&](const auto& m) {
    if (m.tool == bladeStation || m.tool < 1 || m.kind == MoveKind::Rapid || m.kind == MoveKind::Dwell) return;
    for (const Vec2& p : {m.path.start, m.path.end})
      // (A pass that ends at the cut-off's Z, its end shifted by a nose radius, is not a feature.)
      if (p.x() > zPlunge + std::max(0.5, bladeWidth / 4.0) && p.x() < zPlunge + bladeWidth - 0.05 &&
          std::abs(p.y()) > 0.01)
        turnedTo = std::max(turnedTo, p.x());
  });
  return turnedTo;
}

// A guessed blade's controlled corner (issue 38): the library's blades are set on their left
// (chuck-side) corner; where that blade, at the Z it plunges to, would cut into what the other
// tools turned (a back chamfer, a head up to the cut-off), the shop sets it on its right corner.
void setBladesOnRightCorner(ToolInference& out, const std::map<int, StationUse>& uses, const std::set<int>& overridden,
                            const io::ToolLibrary& library) {
  for (const ToolChoice& c : out.choices) {
    const io::LibraryTool* tool = library.find(c.libraryId);
    const auto use = uses.find(c.station);
    if (!tool || overridden.count(c.station) || use == uses.end() || tool->tip != 3 || !(tool->size > 0.0) ||
        (tool->kind != ToolKind::Parting && tool->kind != ToolKind::Grooving) || use->second.motion.plunge <= 0.0)
      continue;
    const double zPlunge = use->second.motion.plungeZ;
    if (turnedBesidePlunge(*out.record, c.station, zPlunge, tool->size) <= zPlunge) continue;
    for (int n : use->second.offsets)
      if (n >= 1 && n <= io::kOffsetCount) out.setup.offsets.at(n).tip = 4;
    out.offsetNotes.push_back(noteAt(codes::kBladeOnItsRightCorner, use->second.motion.plungeLine,
                                     {twoDigits(c.station), fmt::format("{:g}", tool->size)}));
  }
}

// A bar puller or bar stop cuts nothing, whoever chose the station's picture.
void markBarTools(ToolInference& out, const std::map<int, StationUse>& uses) {
  for (const auto& [station, use] : uses)
    if (use.holdsBar) {
      out.setup.tools.holdsBar[static_cast<std::size_t>(station - 1)] = true;
      out.setup.tools.pullsBarOut[static_cast<std::size_t>(station - 1)] = use.pullsBar;
    }
}

// Every station of a plain program the user did not set is a guess.
void markGuesses(ToolInference& out, const std::map<int, StationUse>& uses, const std::set<int>& overridden) {
  for (const auto& [station, use] : uses)
    if (!overridden.count(station)) out.setup.tools.guessed[static_cast<std::size_t>(station - 1)] = true;
}

}  // namespace

ToolInference inferTools(const gcode::Program& program, std::string_view gcodeText, int gcodeFirstLine,
                         const MachineSetup& setup, const io::ToolLibrary& library,
                         const std::vector<StationOverride>& overrides, int stations, const InferenceContext& context) {
  ToolInference out;
  out.setup = setup;
  out.fromProgram = context.fromProgram;
  // One recorded run is the evidence: the blocks each tool really runs, after
  // macros, subprograms, cycles, offsets and the power-on units.
  out.record = std::make_shared<const Timeline>(recordRun(program, setup, context.run));
  const CutSide side = sideOfCuts(*out.record);
  const detail::ProgramEvidence evidence =
      detail::gatherEvidence(program, gcodeText, gcodeFirstLine, *out.record, context.run.dialect,
                             toolsWorkBeyondCentre(setup, context, side));
  const int lastStation = std::clamp(stations > 0 ? stations : setup.tools.stations, 1, io::kMaxStations);
  std::map<int, StationUse> uses = stationsOnTheTurret(evidence, lastStation);
  creditPartingToLastTools(evidence, uses);

  const std::set<int> overridden = fitOverrides(out, library, overrides, uses, lastStation, context.fromProgram);
  fitToolsByEvidence(out, uses, overridden, evidence, setup, library, context.fromProgram);
  placeToolsBySide(out, context, side, evidence);
  if (context.fromProgram) {
    takeStatedNoseRadii(out, uses, overridden);
    setBladesOnRightCorner(out, uses, overridden, library);
  }
  markBarTools(out, uses);
  if (context.fromProgram) markGuesses(out, uses, overridden);
  std::sort(out.choices.begin(), out.choices.end(),
            [](const ToolChoice& a, const ToolChoice& b) { return a.station < b.station; });
  return out;
}

bool recordIsTheRun(const Timeline& record, const MachineSetup& recordedWith, const RunOptions& recorded,
                    const MachineSetup& setup, const RunOptions& run) {
  if (record.alarm || record.recordStandIns || (record.recordCompensates && run.noseCompensation)) return false;
  if (!record.marks.empty()) return false;  // a record of marks keeps no states to show
  if (run.throughAlarms || run.dialect != recorded.dialect || run.powerOnUnits != recorded.powerOnUnits ||
      run.optionalStop != recorded.optionalStop || run.blockSkip != recorded.blockSkip ||
      run.stopAtM00 != recorded.stopAtM00)
    return false;
  // The run reads the offsets, the machine and the turret's size; a tool's bitmap and the
  // tool side are the cut's (the side is decided from this very record).
  io::MachineConfig machine = setup.machine;
  machine.toolsBeyondCentre = recordedWith.machine.toolsBeyondCentre;
  return machine == recordedWith.machine && setup.offsets.offsets == recordedWith.offsets.offsets &&
         setup.tools.bitmap.size() == recordedWith.tools.bitmap.size();
}

bool parseStationOverride(std::string_view text, int stations, const io::ToolLibrary& library, StationOverride& out,
                          std::string& error, Lang lang) {
  const std::size_t eq = text.find('=');
  const std::string_view number = eq == std::string_view::npos ? std::string_view() : text.substr(0, eq);
  const std::string_view id = eq == std::string_view::npos ? std::string_view() : text.substr(eq + 1);
  int station = 0;
  bool digits = !number.empty() && number.size() <= 2;
  for (char c : number) {
    if (c < '0' || c > '9')
      digits = false;
    else
      station = station * 10 + (c - '0');
  }
  const auto say = [&](const char* code, std::vector<std::string> args) {
    error = formatMessage(Diagnostic{Severity::Error, code, {}, std::move(args)}, lang);
    return false;
  };
  if (eq == std::string_view::npos || !digits || id.empty())
    return say(codes::kCliToolForm, {std::string(text), library.idList()});
  if (station < 1 || station > stations)
    return say(codes::kCliToolStation, {std::string(text), std::to_string(station), std::to_string(stations)});
  if (!library.find(id)) return say(codes::kCliToolUnknown, {std::string(text), std::string(id), library.idList()});
  out.station = station;
  out.libraryId = std::string(id);
  return true;
}

}  // namespace klueng::core::machine

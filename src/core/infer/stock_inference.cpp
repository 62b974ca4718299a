#include "klueng/core/infer/stock_inference.h"

#include <cctype>
#include <cstdlib>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "klueng/core/geometry.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/infer/point_reading.h"

namespace klueng::core::machine {

namespace {

constexpr double kMmPerInch = 25.4;
constexpr double kOnCentre = 0.5;          // mm of diameter: a feed at X0 (drill, face to centre)
constexpr double kBeyondTheDrillMm = 1.0;  // an inside pass this much deeper than the hole needs a bore
constexpr double kBelowWall = 0.005;       // mm of diameter: a retract this far below a pass leaves its wall

// (A Move, or a RecordMove of a record of marks: the same names.)
template <typename M>
bool isFeed(const M& m) {
  return m.kind == MoveKind::Line || m.kind == MoveKind::Arc || m.kind == MoveKind::Thread;
}

// A pass along -Z: mostly axial, going left.
template <typename M>
bool isZPass(const M& m) {
  const Vec2 d = m.path.end - m.path.start;
  return isFeed(m) && d.x() < -1e-6 && std::abs(d.x()) > 5.0 * std::abs(d.y());
}

bool isCycleBlock(const gcode::Block& b) {
  for (const gcode::Word* g : b.all('G')) {
    const int c = g->code();
    if (!g->hasDecimalPoint && ((c >= 70 && c <= 76) || c == 90 || c == 92 || c == 94)) return true;
  }
  return false;
}

template <typename M>
const gcode::Block* blockOf(const gcode::Program& program, const M& m) {
  return m.blockIndex >= 0 && static_cast<std::size_t>(m.blockIndex) < program.blocks.size()
             ? &program.blocks[static_cast<std::size_t>(m.blockIndex)]
             : nullptr;
}

// A -Z pass inside the part that the tool leaves through a hole: after it the
// tool moves toward the centre while still behind the face (the boring
// retract), never comes back up to the pass's diameter, never feeds to the
// centre line (a step in Z, then facing down to X0, is a face cut), and then
// leaves the part in front of the face, along Z, below the pass's diameter
// (G01 Z-20. at X96., X94., G00 Z2.). Turning outside cannot do that without
// running through the part: a neck, a groove or a taper after an outside pass
// (X44 Z-10, X40 Z-15, X44 Z-20, Z-30) comes back up to the pass's diameter
// before the tool leaves, and a return home across the part (G28 to X0) does
// not start below it. Everything else — however it moves in X — is outside work.
template <typename Moves>
bool leavesThroughTheHole(const Moves& moves, std::size_t i) {
  const auto& m = moves[i];
  if (!isZPass(m) || zOf(m.path.end) >= 0.0 || diameterOf(m.path.start) < kOnCentre) return false;
  const double wall = diameterOf(m.path.end) - kBelowWall;
  for (std::size_t k = i + 1; k < moves.size(); ++k) {
    const auto& n = moves[k];
    if (zOf(n.path.end) >= -1e-9) {  // leaves in front of the face
      const Vec2 d = n.path.end - n.path.start;
      const bool alongZ = std::abs(d.x()) > 5.0 * std::abs(d.y());
      // Out below the pass: from below it, or from the wall slanting inward (G01 X94. Z2.).
      const bool below = diameterOf(n.path.start) < wall || (d.y() < 0.0 && diameterOf(n.path.end) < wall);
      return alongZ && below && diameterOf(n.path.end) >= kOnCentre;
    }
    if (diameterOf(n.path.end) >= wall - 1e-9) return false;            // back up to the wall: outside
    if (isFeed(n) && diameterOf(n.path.end) < kOnCentre) return false;  // faced to the centre
  }
  return false;
}

// Which moves are inside passes. A canned cycle's pass counts only when the
// cycle works outward from its start point (G71 U-0.4 from X86 roughing out
// to Ø100: boring); one that cuts down below its start is outside work, even
// where its retract returns below a pass (a Haas G76 started at X0.9414 under
// the thread's first passes).
template <typename Moves>
std::vector<char> insidePasses(const gcode::Program& program, const Moves& moves) {
  std::vector<char> inside(moves.size(), 0);
  for (std::size_t first = 0; first < moves.size();) {
    std::size_t last = first;
    while (last + 1 < moves.size() && moves[last + 1].blockIndex == moves[first].blockIndex) ++last;
    const gcode::Block* block = blockOf(program, moves[first]);
    bool outward = true;
    if (block && isCycleBlock(*block)) {
      const double start = diameterOf(moves[first].path.start);
      double lowest = start, highest = start;
      for (std::size_t k = first; k <= last; ++k) {
        if (!isFeed(moves[k])) continue;
        lowest = std::min({lowest, diameterOf(moves[k].path.start), diameterOf(moves[k].path.end)});
        highest = std::max({highest, diameterOf(moves[k].path.start), diameterOf(moves[k].path.end)});
      }
      outward = highest - start > start - lowest;
    }
    for (std::size_t k = first; k <= last; ++k) inside[k] = outward && leavesThroughTheHole(moves, k);
    first = last + 1;
  }
  return inside;
}

double roundUp(double value, double step) { return std::ceil(value / step - 1e-9) * step; }
double roundDown(double value, double step) { return std::floor(value / step + 1e-9) * step; }

std::string lineText(std::string_view gcode, int firstLine, int line) {
  int n = firstLine;
  std::size_t pos = 0;
  while (n < line && pos < gcode.size()) {
    const std::size_t nl = gcode.find('\n', pos);
    if (nl == std::string_view::npos) return {};
    pos = nl + 1;
    ++n;
  }
  if (n != line || pos > gcode.size()) return {};
  std::string_view s = gcode.substr(pos, gcode.find('\n', pos) - pos);
  // Drop the comment and trailing blanks: "N20 G00 X52. Z2." is the block.
  s = s.substr(0, std::min(s.find('('), s.find(';')));
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  return std::string(s);
}

std::string number(double v) {
  std::string s = fmt::format("{:.4f}", v + 0.0);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

Diagnostic note(const char* code, int line, std::vector<std::string> args) {
  Diagnostic d;
  d.severity = Severity::Note;
  d.code = code;
  d.range = SourceRange{line, line > 0 ? 1 : 0, 0};
  d.args = std::move(args);
  return d;
}

}  // namespace

double metricBarSize(double d, bool above) {
  if (above) {
    for (const double s : kMetricBarSizes)
      if (s > d + 1e-9) return s;
    return roundUp(d + 1e-9, 10.0);
  }
  double best = 0.0;
  for (const double s : kMetricBarSizes)
    if (s <= d + 1e-9) best = s;
  return best > 0.0 ? best : std::max(1.0, std::floor(d));
}

double inchBarSize(double d, bool above) {
  if (above) return roundDown(d, 0.125) + 0.125;
  const double s = roundDown(d, 0.125);
  return s > 0.0 ? s : std::max(0.0625, roundDown(d, 0.0625));
}

void StockInference::applyTo(io::JobHeader& h) const {
  const io::LengthUnit unit = inch ? io::LengthUnit::Inch : io::LengthUnit::Millimetre;
  h.diameter = diameter;
  h.length = length;
  h.bore = bore;
  h.diameterUnit = unit;
  h.lengthUnit = unit;
  h.stockSource = io::StockSource::Inferred;
}

StockInference inferStock(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options,
                          const InferenceOptions& inference) {
  return inferStock(program, recordRun(program, setup, options), setup, inference);
}

namespace {

// The bar, from the moves of tl (its moves, or a record's: `moves` is one of the two lists).
template <typename Moves>
StockInference inferFromMoves(const gcode::Program& program, const Timeline& tl, const Moves& moves,
                              const MachineSetup& setup, const InferenceOptions& inference) {
  StockInference r;
  const std::vector<char> inside = insidePasses(program, moves);
  // The units a block ran in: its last run's (a search from the end, for the one block asked;
  // a map of every block's was a node a block, 64 bytes each, issue 42 item 3).
  const auto inchBlock = [&tl](int blockIndex) {
    for (std::size_t k = tl.blockCount(); k-- > 0;)
      if (const BlockMark mark = tl.blockMark(k); mark.blockIndex == blockIndex) return mark.units == Units::Inch;
    return false;
  };

  // Ø: the first feeding block off the centre that is not inside work. An
  // approach comes from in front of the face (not a drill, not a retract inside
  // the part); a program that only works behind the face (a cut-off on its own,
  // a groove) has the bar below where its first cut starts.
  std::size_t decider = moves.size();
  for (int pass = 0; pass < 2 && decider == moves.size(); ++pass)
    for (std::size_t i = 0; i < moves.size() && decider == moves.size(); ++i) {
      const auto& m = moves[i];
      if (!isFeed(m) || inside[i]) continue;
      std::size_t first = i;  // the block's first move starts where the block started
      while (first > 0 && moves[first - 1].blockIndex == m.blockIndex) --first;
      if (diameterOf(moves[first].path.start) < kOnCentre) continue;
      if (pass == 0 && zOf(moves[first].path.start) < -1e-6) continue;
      if (pass == 1 && diameterOf(m.path.end) >= diameterOf(moves[first].path.start)) continue;  // a plunge inward only
      decider = i;
      // Quote the block that brought the tool there (N30 G00 X52. Z2.), not the cut.
      r.diameterLine = first > 0 ? moves[first - 1].line : m.line;
      const gcode::Block* block = blockOf(program, m);
      r.cycleStart = block && isCycleBlock(*block);
      r.inch = inchBlock(m.blockIndex);
      const double unit = r.inch ? kMmPerInch : 1.0;
      // A plain first cut along -Z is a pass inside the bar; anything else starts above it.
      // (A feed that only reaches the face, `G01 Z0.` at the approach's X, is no pass inside it.)
      const bool insideBar = !r.cycleStart && first == i && isZPass(m) && zOf(m.path.end) < -1e-6;
      r.approachDiameter = diameterOf(moves[first].path.start) / unit;
      r.diameter = r.inch ? inchBarSize(r.approachDiameter, insideBar) : metricBarSize(r.approachDiameter, insideBar);
    }
  if (decider == moves.size()) return r;
  r.found = true;
  const double unit = r.inch ? kMmPerInch : 1.0;

  // The bar holds what the program turns outside: a plain pass along -Z behind
  // the face (not inside work, not a canned cycle's) was cut from the bar, so
  // the bar is no smaller than it, whatever the approach looked like (a CAM
  // lead-in from X44.8 to X43.6 Z1. reads as a Ø40 bar for a part turned to Ø44).
  double largestTurned = 0.0;
  int largestTurnedLine = 0;
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const auto& m = moves[i];
    if (!isZPass(m) || zOf(m.path.end) >= 0.0 || diameterOf(m.path.start) < kOnCentre || inside[i]) continue;
    const gcode::Block* block = blockOf(program, m);
    if (block && isCycleBlock(*block)) continue;
    const double d = std::max(diameterOf(m.path.start), diameterOf(m.path.end)) / unit;
    if (d > largestTurned + 1e-9) {
      largestTurned = d;
      largestTurnedLine = m.line;
    }
  }
  if (largestTurned > r.diameter + 1e-6) {
    r.diameter = r.inch ? inchBarSize(largestTurned, true) : metricBarSize(largestTurned, true);
    r.largestTurnedDiameter = largestTurned;
    r.diameterLine = largestTurnedLine;
    r.cycleStart = false;
  }

  // Length: the deepest Z while feeding, the cut-off margin and the chuck grip.
  double deepest = 0.0;
  for (const auto& m : moves) {
    if (!isFeed(m)) continue;
    const double z = std::min(zOf(m.path.start), zOf(m.path.end));
    if (z < deepest - 1e-9) {
      deepest = z;
      r.lengthLine = m.line;
    }
  }
  r.deepestZ = deepest / unit;
  r.cutOffMargin = r.inch ? roundUp(inference.cutOffMarginMm / kMmPerInch, 0.05) : inference.cutOffMarginMm;
  r.chuckGrip = std::max(0.0, setup.machine.chuckGrip) / unit;
  r.length = roundUp(-r.deepestZ + r.cutOffMargin + r.chuckGrip, r.inch ? 0.25 : 5.0);

  // Bore: inside passes where no drill on centre has been before them (a shallow drill, a 1" insert
  // drill .25 deep, leaves the boring bar's deeper passes in the tube's own bore).
  double drilledTo = 0.0;  // the deepest Z drilled on centre so far
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const auto& m = moves[i];
    if (isZPass(m) && diameterOf(m.path.start) < kOnCentre && zOf(m.path.end) < 0.0) {
      drilledTo = std::min(drilledTo, zOf(m.path.end));
      continue;
    }
    if (!inside[i] || (drilledTo < 0.0 && zOf(m.path.end) > drilledTo - kBeyondTheDrillMm)) continue;
    const double d = diameterOf(m.path.start) / unit;
    if (r.insidePassDiameter == 0.0 || d < r.insidePassDiameter) {
      r.insidePassDiameter = d;
      r.boreLine = m.line;
    }
  }
  // ID work on a tube: when the "approach" was inside what the program cuts,
  // the bar must be larger than everything cut, with a wall around it.
  if (r.insidePassDiameter > 0.0) {
    double largest = 0.0, largestInside = 0.0;
    for (std::size_t i = 0; i < moves.size(); ++i) {
      const auto& m = moves[i];
      if (!isFeed(m)) continue;
      largest = std::max({largest, diameterOf(m.path.start), diameterOf(m.path.end)});
      if (inside[i]) largestInside = std::max(largestInside, diameterOf(m.path.start));
    }
    largest /= unit;
    if (r.diameter <= largestInside / unit + 1e-6) {
      const double wall = r.inch ? 0.5 : 10.0;
      r.outsideFromInside = true;
      r.largestCutDiameter = largest;
      r.diameter = r.inch ? inchBarSize(largest + wall, true) : metricBarSize(largest + wall, true);
    }
  }
  if (r.insidePassDiameter > 0.0) {
    const double bore =
        r.inch ? roundDown(r.insidePassDiameter - 0.0625, 0.0625) : std::floor(r.insidePassDiameter - 1.0 + 1e-9);
    if (bore > 0.0 && bore < r.diameter)
      r.bore = bore;
    else
      r.boreLine = 0;
  }
  return r;
}

}  // namespace

StockInference inferStock(const gcode::Program& program, const Timeline& run, const MachineSetup& setup,
                          const InferenceOptions& inference) {
  // Tools beyond the centre line (X < 0) measure the same round bar: read the run as from the front.
  std::optional<Timeline> mirrored;
  if (setup.machine.toolsBeyondCentre || sideOfCuts(run) == CutSide::Beyond) {
    mirrored = run;
    for (Move& m : mirrored->moves) m = mirroredAcrossCentre(m);
    if (!run.recordMoves.empty()) {
      mirrored->recordMoves = RecordMoveList();
      mirrored->recordMoves.reserve(run.recordMoves.size());
      for (const RecordMove& m : run.recordMoves)
        mirrored->recordMoves.push_back(RecordMove::of(mirroredAcrossCentre(m.move())));
    }
  }
  const Timeline& tl = mirrored ? *mirrored : run;
  if (tl.moves.empty() && !tl.recordMoves.empty()) return inferFromMoves(program, tl, tl.recordMoves, setup, inference);
  return inferFromMoves(program, tl, tl.moves, setup, inference);
}

namespace {

bool stockWordIn(const std::string& up) {
  for (const char* w : {"MATERIAL", "STOCK", "BAR", "TUBING", "TUBE", "BLANK", "ROHTEIL", "BRUT", "BARRA", "BARRE",
                        "MATERIA", "TARUGO", "\xD0\x97\xD0\x90\xD0\x93\xD0\x9E\xD0\xA2\xD0\x9E\xD0\x92\xD0\x9A\xD0\x90",
                        "\xE0\xB8\x8A\xE0\xB8\xB4\xE0\xB9\x89\xE0\xB8\x99\xE0\xB8\x87\xE0\xB8\xB2\xE0\xB8\x99"})
    if (up.find(w) != std::string::npos) return true;
  return false;
}

// The next word after position i (letters only, upper case), skipping blanks and an inch mark.
std::string wordAfter(const std::string& up, std::size_t i) {
  while (i < up.size() && (up[i] == ' ' || up[i] == '"')) ++i;
  std::size_t e = i;
  while (e < up.size() && std::isalpha(static_cast<unsigned char>(up[e]))) ++e;
  return up.substr(i, e - i);
}

// The letters (or Ø) right before position i, skipping blanks, '=' and ':'.
std::string wordBefore(const std::string& up, std::size_t i) {
  while (i > 0 && (up[i - 1] == ' ' || up[i - 1] == '=' || up[i - 1] == ':')) --i;
  if (i >= 2 && up.compare(i - 2, 2, "\xC3\x98") == 0) return "DIA";  // Ø
  std::size_t b = i;
  while (b > 0 && std::isalpha(static_cast<unsigned char>(up[b - 1]))) --b;
  return up.substr(b, i - b);
}

// A tool list's line ("(T08 ID TURN 3/4" SHANK BORING BAR)") names a tool, not the bar.
bool namesATool(const std::string& up) {
  for (const char* w : {"TOOL", "BORING", "SHANK", "HOLDER", "INSERT", "PULLER", "PULER", "DRILL", "FEEDER"})
    if (up.find(w) != std::string::npos) return true;
  for (std::size_t i = 0; i + 1 < up.size(); ++i)
    if (up[i] == 'T' && std::isdigit(static_cast<unsigned char>(up[i + 1])) &&
        (i == 0 || !std::isalpha(static_cast<unsigned char>(up[i - 1]))))
      return true;
  return false;
}

}  // namespace

bool readStockComment(StockInference& r, std::string_view gcode, int firstLine) {
  int line = firstLine;
  for (std::size_t pos = 0; pos < gcode.size(); ++line) {
    std::size_t end = gcode.find('\n', pos);
    if (end == std::string_view::npos) end = gcode.size();
    const std::string_view text = gcode.substr(pos, end - pos);
    pos = end + 1;
    const std::size_t open = text.find('(');
    if (open == std::string_view::npos) continue;
    std::string up(text.substr(open + 1));
    for (char& c : up) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (!stockWordIn(up) || namesATool(up)) continue;
    double od = 0.0, id = 0.0, length = 0.0;
    std::vector<double> plain;  // numbers without a mark, in order
    bool sizedPair = false;     // a number followed by "X" (50 X 100)
    bool inchMark = up.find('"') != std::string::npos;
    for (std::size_t i = 0; i < up.size();) {
      const bool startsNumber =
          std::isdigit(static_cast<unsigned char>(up[i])) ||
          (up[i] == '.' && i + 1 < up.size() && std::isdigit(static_cast<unsigned char>(up[i + 1])));
      if (!startsNumber) {
        ++i;
        continue;
      }
      // Glued to a word ("G54", "1018CRS", "IC20"), not a size; D50 and L100 are.
      const bool glued = i > 0 && (std::isalnum(static_cast<unsigned char>(up[i - 1])) || up[i - 1] == '.') &&
                         wordBefore(up, i) != "D" && wordBefore(up, i) != "L" && wordBefore(up, i) != "X";
      if (glued) {
        while (i < up.size() && (std::isalnum(static_cast<unsigned char>(up[i])) || up[i] == '.')) ++i;
        continue;
      }
      std::size_t e = i;
      while (e < up.size() && (std::isdigit(static_cast<unsigned char>(up[e])) || up[e] == '.')) ++e;
      if ((e < up.size() && up[e] == '/') || (i > 0 && up[i - 1] == '/')) {  // 3/4": a fraction, not read
        i = e + 1;
        continue;
      }
      const double v = std::atof(up.substr(i, e - i).c_str());
      const std::string after = wordAfter(up, e), before = wordBefore(up, i);
      if (after == "IN" || after == "INCH") inchMark = true;
      if (after == "OD" || before == "OD" || before == "DIA" || before == "D" || after == "DIA")
        od = v;
      else if (after == "ID" || before == "ID")
        id = v;
      else if (after == "L" || after == "LG" || after == "LONG" || after == "LENGTH" || before == "L" ||
               before == "LG" || before == "LENGTH")
        length = v;
      else if (std::isalpha(static_cast<unsigned char>(e < up.size() ? up[e] : ' ')))
        ;  // "1018CRS", "3003Y": a name, not a size
      else if (before == "X" && od > 0.0 && length == 0.0)
        length = v;  // Ø32x60: the length after the diameter's x
      else
        plain.push_back(v);
      // "50 X 100": the sizes are written as a size is, or there is no unmarked size at all.
      const std::string next = wordAfter(up, e);
      sizedPair = sizedPair || next == "X";
      i = e;
    }
    // "DIA 50 X 100", "1.750 BAR": unmarked numbers are the diameter, then the length.
    std::size_t k = 0;
    if (sizedPair) {
      if (od == 0.0 && k < plain.size()) od = plain[k++];
      if (length == 0.0 && k < plain.size()) length = plain[k++];
    }
    if (!(od > 0.0) || (id > 0.0 && id >= od) || (!r.found && !(length > 0.0))) continue;
    const bool inch = inchMark || (r.inch && up.find("MM") == std::string::npos);
    const double toUnit = inch == r.inch ? 1.0 : (inch ? kMmPerInch : 1.0 / kMmPerInch);
    // A bar the program could not have come from (half the size its moves show, or twice) is another number.
    if (r.found && (od * toUnit < 0.8 * r.diameter || od * toUnit > 2.0 * r.diameter)) continue;
    r.diameter = od * toUnit;
    if (id > 0.0) r.bore = id * toUnit;
    if (length > 0.0) r.length = length * toUnit;
    r.commentLine = line;
    const std::string_view shown = text.substr(open);
    r.commentText = std::string(shown.substr(0, std::min<std::size_t>(shown.size(), 60)));
    while (!r.commentText.empty() && (r.commentText.back() == ' ' || r.commentText.back() == '\r'))
      r.commentText.pop_back();
    r.found = true;
    return true;
  }
  return false;
}

std::vector<Diagnostic> stockNotes(const io::JobHeader& stock, const StockInference* inference, std::string_view gcode,
                                   int firstLine) {
  const std::string size = io::stockSizeText(stock);
  switch (stock.stockSource) {
    case io::StockSource::Header: return {note(codes::kStockFromHeader, 0, {size})};
    case io::StockSource::CommandLine: return {note(codes::kStockFromCommandLine, 0, {size})};
    case io::StockSource::JobDetails: return {note(codes::kStockFromJobDetails, 0, {size})};
    case io::StockSource::Default: return {note(codes::kStockDefault, 0, {size})};
    case io::StockSource::Inferred: break;
  }
  if (!inference || !inference->found) return {note(codes::kStockDefault, 0, {size})};
  const StockInference& r = *inference;
  std::vector<Diagnostic> notes;
  if (r.commentLine > 0) {
    notes.push_back(note(codes::kStockFromComment, r.commentLine, {size, r.commentText}));
    return notes;
  }
  if (r.outsideFromInside)
    notes.push_back(note(codes::kStockInferredFromBore, r.boreLine, {size, number(r.largestCutDiameter)}));
  else if (r.largestTurnedDiameter > 0.0)
    notes.push_back(
        note(codes::kStockFromLargestTurned, r.diameterLine, {size, lineText(gcode, firstLine, r.diameterLine)}));
  else
    notes.push_back(note(r.cycleStart ? codes::kStockFromCycleStart : codes::kStockFromFirstApproach, r.diameterLine,
                         {size, lineText(gcode, firstLine, r.diameterLine)}));
  if (r.lengthLine > 0)
    notes.push_back(note(codes::kStockLengthFromDeepestCut, r.lengthLine,
                         {number(r.length), number(r.deepestZ), lineText(gcode, firstLine, r.lengthLine),
                          number(r.cutOffMargin), number(r.chuckGrip)}));
  if (r.bore > 0.0)
    notes.push_back(note(codes::kBoreInferred, r.boreLine, {number(r.bore), lineText(gcode, firstLine, r.boreLine)}));
  return notes;
}

StockInference inferStockFromText(std::string_view gcode, int firstLine, const MachineSetup& setup,
                                  const RunOptions& options, std::optional<bool> chosenCalculatorInput) {
  gcode::Program program = gcode::parse(gcode, firstLine);
  const PointReading reading =
      readDecimalPoints(program, firstLine <= 1, chosenCalculatorInput, setup.machine.calculatorInput,
                        gcode::powerOnUnitsOf(options.dialect, options.powerOnUnits), options.dialect);
  if (reading.calculatorInput == setup.machine.calculatorInput) return inferStock(program, setup, options);
  MachineSetup readSetup = setup;
  readSetup.machine.calculatorInput = reading.calculatorInput;
  return inferStock(program, readSetup, options);
}

}  // namespace klueng::core::machine

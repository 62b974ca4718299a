// Cutting data of a recorded run (issue 39): cut/cutting_data.h, docs/cutting-data.md.
#include "klueng/core/cut/cutting_data.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <tuple>

#include "klueng/core/diagnostic_codes.h"
#include "io/text_util.h"
#include "klueng/core/io/file_read.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/cut/part_features.h"

namespace klueng::core::cut {

namespace {

constexpr double kFeetPerMetre = 1.0 / 0.3048;
constexpr std::size_t kMaxMaterialsFileBytes = 1 << 20;  // a table of a few dozen rows

std::vector<std::string_view> cdSplit(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = s.find(sep, start);
    out.push_back(
        io::detail::trim(s.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start)));
    if (at == std::string_view::npos) return out;
    start = at + 1;
  }
}

// Lower case (ASCII) without spaces: "Al 6061" and "al6061" name the same row.
std::string cdKey(std::string_view s) {
  std::string out;
  for (const char c : s)
    if (!std::isspace(static_cast<unsigned char>(c)))
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// A number of 0 or more, as the setup files write numbers.
std::optional<double> cdNumber(std::string_view s) {
  const std::optional<double> v = io::detail::parseNumber(s);
  if (!v || !std::isfinite(*v) || *v < 0.0) return std::nullopt;
  return v;
}

bool cdRange(std::string_view s, double& lo, double& hi) {
  const std::size_t dash = s.find('-');
  if (dash == std::string_view::npos) return false;
  const auto a = cdNumber(io::detail::trim(s.substr(0, dash)));
  const auto b = cdNumber(io::detail::trim(s.substr(dash + 1)));
  if (!a || !b || *a > *b) return false;
  lo = *a;
  hi = *b;
  return true;
}

Diagnostic cdFileError(const char* code, int line, std::vector<std::string> args) {
  return Diagnostic{Severity::Error, code, SourceRange{line, 1, 0, 0}, std::move(args)};
}

}  // namespace

std::string_view toolMaterialId(ToolMaterial m) {
  switch (m) {
    case ToolMaterial::Hss: return "hss";
    case ToolMaterial::Carbide: return "carbide";
    case ToolMaterial::CoatedCarbide: return "coated-carbide";
    case ToolMaterial::Unknown: break;
  }
  return "";
}

bool parseToolMaterialId(std::string_view id, ToolMaterial& out) {
  for (const ToolMaterial m : {ToolMaterial::Hss, ToolMaterial::Carbide, ToolMaterial::CoatedCarbide})
    if (id == toolMaterialId(m)) {
      out = m;
      return true;
    }
  return false;
}

const Material* MaterialTable::find(std::string_view headerMaterial) const {
  const std::string key = cdKey(headerMaterial);
  if (key.empty()) return nullptr;
  for (const Material& m : rows)
    for (const std::string& name : m.names)
      if (cdKey(name) == key) return &m;
  // As teachers write it, with more words ("Steel S45C", "Aluminium 6061"): a name the header holds,
  // the most specific first (a row lists its names from its grade to its generic words).
  const Material* best = nullptr;
  std::size_t bestRank = 0;
  std::size_t bestLength = 0;
  for (const Material& m : rows)
    for (std::size_t rank = 0; rank < m.names.size(); ++rank) {
      const std::string k = cdKey(m.names[rank]);
      if (k.size() < 3 || key.find(k) == std::string::npos) continue;  // "pom", "304" at least
      if (!best || rank < bestRank || (rank == bestRank && k.size() > bestLength)) {
        best = &m;
        bestRank = rank;
        bestLength = k.size();
      }
    }
  return best;
}

std::string MaterialTable::idList() const {
  std::string out;
  for (const Material& m : rows) out += (out.empty() ? "" : ", ") + m.id;
  return out;
}

io::ReadResult<MaterialTable> parseMaterials(std::string_view text, const std::string& fileName) {
  io::ReadResult<MaterialTable> result;
  MaterialTable table;
  int lineNo = 0;
  for (const std::string_view line : io::detail::splitLines(text)) {
    ++lineNo;
    const std::string_view content = io::detail::trim(line);
    if (content.empty() || content.front() == '#') continue;
    const std::vector<std::string_view> f = cdSplit(content, '|');
    if (f.size() != 9) {
      result.diagnostics.push_back(
          cdFileError(codes::kMaterialLineFields, lineNo, {fileName, std::to_string(f.size())}));
      continue;
    }
    Material m;
    m.id = std::string(f[0]);
    for (const std::string_view name : cdSplit(f[1], ','))
      if (!name.empty()) m.names.push_back(std::string(name));
    if (std::find(m.names.begin(), m.names.end(), m.id) == m.names.end()) m.names.insert(m.names.begin(), m.id);
    m.nameEn = std::string(f[2]);
    m.nameTh = std::string(f[3]);
    bool ok = true;
    const auto bad = [&](const char* what, std::string_view text) {
      result.diagnostics.push_back(cdFileError(codes::kMaterialBadNumber, lineNo, {fileName, what, std::string(text)}));
      ok = false;
    };
    if (!cdRange(f[4], m.hssMin, m.hssMax)) bad("HSS Vc", f[4]);
    if (!cdRange(f[5], m.carbideMin, m.carbideMax)) bad("carbide Vc", f[5]);
    if (const auto v = cdNumber(f[6]))
      m.kc11 = *v;
    else
      bad("kc1.1", f[6]);
    if (const auto v = cdNumber(f[7]); v && *v < 1.0)
      m.mc = *v;
    else
      bad("mc", f[7]);
    m.source = std::string(f[8]);
    m.line = lineNo;
    if (ok) table.rows.push_back(std::move(m));
  }
  result.value = std::move(table);
  return result;
}

io::ReadResult<MaterialTable> readMaterials(const std::string& path) {
  // Read as every setup file is: a missing file, a folder, a FIFO or an endless device is said so.
  io::ReadResult<std::string> bytes = io::readFileLimited(path, kMaxMaterialsFileBytes);
  if (!bytes.value) {
    io::ReadResult<MaterialTable> r;
    r.diagnostics = std::move(bytes.diagnostics);
    return r;
  }
  return parseMaterials(*bytes.value, path);
}

std::string shippedMaterialsPath() {
  return (std::filesystem::path(io::shippedConfigDir()) / "resources" / "parts" / "materials.cfg").string();
}

const MaterialTable& shippedMaterials() {
  static const MaterialTable table = readMaterials(shippedMaterialsPath()).value.value_or(MaterialTable{});
  return table;
}

CuttingDataOptions cuttingDataOptions(const std::string& headerMaterial, const io::ToolTable& tools,
                                      const io::MachineConfig& machine, const MaterialTable& materials,
                                      const io::ToolLibrary* library) {
  CuttingDataOptions o;
  o.material = materials.find(headerMaterial);
  o.spindlePowerKw = machine.spindlePowerKw;
  o.spindleTorqueNm = machine.spindleTorqueNm;
  o.chuckMaxRpm = machine.chuckMaxRpm;
  if (!library) library = &io::shippedToolLibrary();
  for (int tool = 1; tool <= io::kToolCount; ++tool) {
    const std::size_t k = static_cast<std::size_t>(tool - 1);
    const std::string id = tools.libraryId(tool);
    const io::LibraryTool* t = id.empty() ? nullptr : library->find(id);
    // The station's own word (tools.cfg, Tool Select) wins over the library's.
    if (!parseToolMaterialId(tools.material[k], o.toolMaterial[k]) && t)
      parseToolMaterialId(t->material, o.toolMaterial[k]);
    if (!t) continue;
    o.edgeLength[k] = t->edge;
    o.noseRadius[k] = t->noseRadius;
    if (t->kind == io::ToolKind::Drill || t->kind == io::ToolKind::CentreDrill) o.drillDiameter[k] = t->size;
  }
  return o;
}

double roughnessRz(double feed, double noseRadius) {
  return noseRadius > 0.0 ? feed * feed / (8.0 * noseRadius) * 1000.0 : 0.0;
}

double roughnessRa(double feed, double noseRadius) {
  return noseRadius > 0.0 ? feed * feed / (32.0 * noseRadius) * 1000.0 : 0.0;
}

double specificCuttingForce(double kc11, double mc, double h) { return h > 0.0 ? kc11 * std::pow(h, -mc) : 0.0; }

namespace {

struct WarningKeeper {
  const CuttingDataOptions& options;
  std::vector<Diagnostic>& out;
  std::map<std::tuple<std::string, int, int>, bool> said;
  std::map<std::string, int> perCode;
  void add(const char* code, const machine::Move& m, std::vector<std::string> args) {
    if (!said.emplace(std::make_tuple(std::string(code), m.file, m.line), true).second) return;
    if (++perCode[code] > options.warningsPerCode) return;
    out.push_back(Diagnostic{Severity::Warning, code, SourceRange{m.line, 1, 0, m.file}, std::move(args)});
  }
};

std::string_view toolMaterialEn(ToolMaterial m) {
  switch (m) {
    case ToolMaterial::Hss: return "HSS";
    case ToolMaterial::Carbide: return "carbide";
    case ToolMaterial::CoatedCarbide: return "coated carbide";
    case ToolMaterial::Unknown: break;
  }
  return "";
}

std::string_view toolMaterialTh(ToolMaterial m) {
  switch (m) {
    case ToolMaterial::Hss: return "ไฮสปีด (HSS)";
    case ToolMaterial::Carbide: return "คาร์ไบด์";
    case ToolMaterial::CoatedCarbide: return "คาร์ไบด์เคลือบผิว";
    case ToolMaterial::Unknown: break;
  }
  return "";
}

// Numbers in the program's units.
struct CdUnits {
  bool inch = false;
  double length(double mm) const { return inch ? mm / kMmPerInch : mm; }
  double speed(double mPerMin) const { return inch ? mPerMin * kFeetPerMetre : mPerMin; }
  std::string len(double mm) const { return inch ? fmt::format("{:.4f}", length(mm)) : fmt::format("{:.2f}", mm); }
  std::string feed(double mm) const { return inch ? fmt::format("{:.4f}", length(mm)) : fmt::format("{:.3f}", mm); }
  std::string vc(double mPerMin) const { return fmt::format("{:.0f}", speed(mPerMin)); }
  const char* vcUnit() const { return inch ? "ft/min" : "m/min"; }
  const char* unitArg() const { return inch ? kUnitArgInch : kUnitArgMm; }
};

}  // namespace

double finishLimit(const CuttingDataOptions& options, bool inside, double diameter, double zA, double zB,
                   const FinishMark** mark) {
  // A mark lies under the cut when their Z ranges overlap and the path runs on its diameters
  // (within 0.5 mm: the imaginary tip of a finishing pass is on the surface, the nose centre off it).
  constexpr double kOnSurface = 0.5;
  const double zLo = std::min(zA, zB), zHi = std::max(zA, zB);
  for (const FinishMark& f : options.finishMarks)
    if (f.inside == inside && f.ra > 0.0 && std::min(zHi, f.zRight) >= std::max(zLo, f.zLeft) - 1e-9 &&
        diameter >= f.dMin - kOnSurface && diameter <= f.dMax + kOnSurface) {
      if (mark) *mark = &f;
      return f.ra;
    }
  if (mark) *mark = nullptr;
  return options.finishRa;
}

namespace {

// The numbers of a cutting move that need no stock: speed, feed, nose, roughness.
CutNumbers cdStockFree(const machine::Move& m, std::size_t index, const CutSetup& setup,
                       const CuttingDataOptions& options) {
  const std::size_t k = static_cast<std::size_t>(m.tool - 1);
  CutNumbers c;
  c.move = index;
  c.line = m.line;
  c.file = m.file;
  c.blockIndex = m.blockIndex;
  c.tool = m.tool;
  c.tStart = m.tStart;
  c.tEnd = m.tEnd;
  c.thread = m.kind == machine::MoveKind::Thread;
  c.z0 = m.path.start.x();
  c.z1 = m.path.end.x();
  c.d0 = 2.0 * std::abs(m.path.start.y());
  c.d1 = 2.0 * std::abs(m.path.end.y());
  c.facing = std::abs(c.z1 - c.z0) < std::abs(m.path.end.y() - m.path.start.y());
  // Where the edge cuts fastest: the larger of the move's two ends (a drill at its rim).
  const double drill = options.drillDiameter[k];
  const double d0 = drill > 0.0 ? drill : c.d0;
  const double d1 = drill > 0.0 ? drill : c.d1;
  const double vc0 = std::numbers::pi * d0 * m.rpm / 1000.0;
  const double vc1 = std::numbers::pi * d1 * m.rpmEnd / 1000.0;
  c.diameter = vc1 > vc0 ? d1 : d0;
  c.rpm = vc1 > vc0 ? m.rpmEnd : m.rpm;
  c.vc = std::max(vc0, vc1);
  c.feed = c.thread ? m.lead : m.feed / m.rpm;
  const int row = m.offset >= 1 ? m.offset : m.tool;
  const double offsetR = row >= 1 && row <= io::kOffsetCount ? setup.offsets.at(row).r : 0.0;
  c.noseRadius = offsetR > 0.0 ? offsetR : options.noseRadius[k];
  if (!c.thread && drill <= 0.0 && c.noseRadius > 0.0) {
    c.rz = roughnessRz(c.feed, c.noseRadius);
    c.ra = roughnessRa(c.feed, c.noseRadius);
  }
  return c;
}

bool cdCutting(const machine::Move& m) {
  return (m.kind == machine::MoveKind::Line || m.kind == machine::MoveKind::Arc ||
          m.kind == machine::MoveKind::Thread) &&
         m.rpm > 0.0 && m.tool >= 1 && m.tool <= io::kToolCount;
}

bool cdOverChuck(const machine::Move& m, const CuttingDataOptions& options) {
  return options.chuckMaxRpm > 0.0 && m.spindle != machine::SpindleDir::Stopped &&
         std::max(m.rpm, m.rpmEnd) > options.chuckMaxRpm + 0.5;
}

// The Vc range of the tool's material in the job's material; false when either is not known.
bool cdSpeedRange(const CuttingDataOptions& options, ToolMaterial tm, double& lo, double& hi) {
  const Material* material = options.material;
  if (!material || tm == ToolMaterial::Unknown) return false;
  const bool hss = tm == ToolMaterial::Hss;
  lo = hss ? material->hssMin : material->carbideMin;
  hi = hss ? material->hssMax : material->carbideMax;
  return true;
}

// Whether a move might warn, whatever depth it turns out to cut (a superset of the warnings
// measureCuts gives it), from the move alone: what the check measures. Lean, since it is asked of
// every move of a long program: no CutNumbers, the stations' facts worked out once.
class CdCandidates {
 public:
  CdCandidates(const CutSetup& setup, const CuttingDataOptions& options) : setup_(setup), options_(options) {
    const Material* material = options.material;
    const bool limits = options.spindlePowerKw > 0.0 || options.spindleTorqueNm > 0.0;
    for (std::size_t k = 0; k < io::kToolCount; ++k) {
      speedJudged_[k] = cdSpeedRange(options, options.toolMaterial[k], lo_[k], hi_[k]);
      const bool force = material && material->kc11 > 0.0 && options.drillDiameter[k] <= 0.0;
      always_[k] = options.edgeLength[k] > 0.0 || (force && limits);  // the depth decides
    }
  }

  bool couldWarn(const machine::Move& m) const {
    if (m.kind == machine::MoveKind::Rapid || m.kind == machine::MoveKind::Dwell) return cdOverChuck(m, options_);
    if (m.tool < 1 || m.tool > io::kToolCount) return false;
    const std::size_t k = static_cast<std::size_t>(m.tool - 1);
    if (always_[k] || cdOverChuck(m, options_)) return true;
    if (m.kind == machine::MoveKind::Thread || m.rpm <= 0.0) return false;  // a thread's speed and finish: not judged
    const double drill = options_.drillDiameter[k];
    const bool marks = !options_.finishMarks.empty();
    double diameter = drill;
    if (speedJudged_[k] || marks) {
      const double d0 = drill > 0.0 ? drill : 2.0 * std::abs(m.path.start.y());
      const double d1 = drill > 0.0 ? drill : 2.0 * std::abs(m.path.end.y());
      const double vc0 = d0 * m.rpm, vc1 = d1 * m.rpmEnd;  // x pi / 1000 below
      diameter = vc1 > vc0 ? d1 : d0;
      const double vc = std::numbers::pi * std::max(vc0, vc1) / 1000.0;
      if (speedJudged_[k] &&
          ((hi_[k] > 0.0 && vc > hi_[k] * 1.005) || (lo_[k] > 0.0 && vc < lo_[k] * 0.995 && diameter > 0.0)))
        return true;
    }
    if (drill > 0.0) return false;
    const int row = m.offset >= 1 ? m.offset : m.tool;
    const double offsetR = row >= 1 && row <= io::kOffsetCount ? setup_.offsets.at(row).r : 0.0;
    const double r = offsetR > 0.0 ? offsetR : options_.noseRadius[k];
    if (r <= 0.0) return false;
    // Ra = f^2 / (32 r) * 1000 above the limit, f = feed / rpm, without a division a move.
    const double limit = !marks ? options_.finishRa
                                : std::min(finishLimit(options_, false, diameter, m.path.start.x(), m.path.end.x()),
                                           finishLimit(options_, true, diameter, m.path.start.x(), m.path.end.x()));
    return limit > 0.0 && m.feed * m.feed > limit * 1.005 * 32.0 * r / 1000.0 * m.rpm * m.rpm;
  }

 private:
  const CutSetup& setup_;
  const CuttingDataOptions& options_;
  std::array<bool, io::kToolCount> speedJudged_{}, always_{};
  std::array<double, io::kToolCount> lo_{}, hi_{};
};

// The codes the run could raise at all, from its tools and the machine (a superset): once each has
// been said warningsPerCode times, the check has nothing more to say and stops measuring.
std::vector<const char*> cdPossibleCodes(const CuttingDataOptions& options) {
  std::vector<const char*> out = {codes::kFinishTooRough};
  const bool force = options.material && options.material->kc11 > 0.0;
  bool speed = false, edge = false;
  for (std::size_t k = 0; k < io::kToolCount; ++k) {
    double lo = 0.0, hi = 0.0;
    speed = speed || cdSpeedRange(options, options.toolMaterial[k], lo, hi);
    edge = edge || options.edgeLength[k] > 0.0;
  }
  if (speed) out.insert(out.end(), {codes::kCutSpeedHigh, codes::kCutSpeedLow});
  if (edge) out.push_back(codes::kDepthOverEdge);
  if (force && options.spindlePowerKw > 0.0) out.push_back(codes::kPowerOverSpindle);
  if (force && options.spindleTorqueNm > 0.0) out.push_back(codes::kTorqueOverSpindle);
  if (options.chuckMaxRpm > 0.0) out.push_back(codes::kRpmOverChuck);
  return out;
}

// The last move that might warn, +1; 0 when none might (looked for from the end).
std::size_t cdMovesToMeasure(const machine::Timeline& timeline, const CutSetup& setup,
                             const CuttingDataOptions& options, std::size_t end) {
  const CdCandidates candidates(setup, options);
  for (std::size_t i = end; i > 0; --i)
    if (candidates.couldWarn(timeline.moves[i - 1])) return i;
  return 0;
}

// The path's radius at z (a line's or an arc's chord; the nearer end outside its Z range).
double cdPathRadiusAt(const CutNumbers& c, double z) {
  if (std::abs(c.z1 - c.z0) < 1e-9) return std::min(c.d0, c.d1) / 2.0;
  const double t = std::clamp((z - c.z0) / (c.z1 - c.z0), 0.0, 1.0);
  return (c.d0 + t * (c.d1 - c.d0)) / 2.0;
}

}  // namespace

CuttingData measureCuts(const machine::Timeline& timeline, const CutSetup& setup, const CuttingDataOptions& options) {
  CuttingData data;
  const std::size_t end = std::min(options.moveEnd, timeline.moves.size());
  // The check measures only as far as a warning could come; a sound program not at all.
  const std::size_t measured = options.warningsOnly ? cdMovesToMeasure(timeline, setup, options, end) : end;
  if (measured == 0) return data;
  CutOptions cutOptions;
  cutOptions.checkpointBudgetBytes = 0;
  CutSimulator sim(timeline, setup, cutOptions);
  RemovalTally tally;
  sim.setRemovalTally(&tally);
  const double sinKr = std::sin(kEnteringAngleDeg * std::numbers::pi / 180.0);
  const Material* material = options.material;
  const CdUnits u{options.units == DisplayUnits::Inch};
  WarningKeeper warn{options, data.warnings, {}, {}};
  const Stock& stock = sim.stock();
  std::vector<double> radials;  // the radial cut of each column a move touched
  if (!options.warningsOnly) {
    data.lastOutside.assign(static_cast<std::size_t>(stock.columnCount()), -1);
    data.lastInside.assign(static_cast<std::size_t>(stock.columnCount()), -1);
  }

  const std::vector<const char*> possible =
      options.warningsOnly ? cdPossibleCodes(options) : std::vector<const char*>{};
  const auto saidAll = [&] {
    return std::all_of(possible.begin(), possible.end(),
                       [&](const char* code) { return warn.perCode[code] >= options.warningsPerCode; });
  };
  const auto& moves = timeline.moves;
  for (std::size_t i = 0; i < measured && !(options.warningsOnly && saidAll()); ++i) {
    const machine::Move& m = moves[i];
    tally.clear();
    sim.advanceTo(m.tEnd);
    if (sim.alarm()) {
      data.stoppedByAlarm = true;
      break;
    }
    if (cdOverChuck(m, options))
      warn.add(codes::kRpmOverChuck, m,
               {fmt::format("{:.0f}", std::max(m.rpm, m.rpmEnd)), fmt::format("{:.0f}", options.chuckMaxRpm)});
    if (!cdCutting(m) || tally.sectionArea <= 1e-9) continue;
    const std::size_t k = static_cast<std::size_t>(m.tool - 1);
    CutNumbers c = cdStockFree(m, i, setup, options);
    const bool thread = c.thread;
    const double drill = options.drillDiameter[k];
    // The depth, across the feed: along Z (turning, boring, drilling) the radial cut over most of
    // the length engaged (the median of the columns: a finishing pass that also takes the sliver a
    // roughing pass left at a shoulder is 0.2 mm deep, not the shoulder's height); along X (facing,
    // grooving) the half section removed over the radial length engaged.
    // Outside or in the bore: the side of the column's material its path runs nearer.
    double deepest = 0.0;
    int insideColumns = 0;
    radials.clear();
    for (const int col : tally.touched) {
      const std::size_t ci = static_cast<std::size_t>(col);
      deepest = std::max(deepest, tally.radial[ci]);
      radials.push_back(tally.radial[ci]);
      const double r = cdPathRadiusAt(c, stock.zCentre(col));
      const bool inside =
          stock.outerRadius(col) > 0.0 && std::abs(r - stock.innerRadius(col)) < std::abs(r - stock.outerRadius(col));
      insideColumns += inside ? 1 : 0;
      if (!options.warningsOnly) (inside ? data.lastInside : data.lastOutside)[ci] = static_cast<int>(data.cuts.size());
    }
    c.inside = insideColumns * 2 > static_cast<int>(tally.touched.size());
    double median = 0.0;
    if (!radials.empty()) {
      const auto mid = radials.begin() + static_cast<std::ptrdiff_t>(radials.size() / 2);
      std::nth_element(radials.begin(), mid, radials.end());
      median = *mid;
    }
    c.depth = !c.facing ? median : (deepest > 0.0 ? tally.sectionArea / deepest : 0.0);
    c.chipWidth = c.depth / sinKr;
    c.chipThickness = c.feed * sinKr;
    c.removalRate = c.vc * c.depth * c.feed;
    if (material && material->kc11 > 0.0 && !thread && drill <= 0.0) {
      c.kc = specificCuttingForce(material->kc11, material->mc, c.chipThickness);
      c.force = c.kc * c.depth * c.feed;
      c.power = c.force * c.vc / 60000.0;
      c.torque = c.force * c.diameter / 2000.0;
    }

    // The teacher's warnings, once a block each.
    const ToolMaterial tm = options.toolMaterial[k];
    if (double lo = 0.0, hi = 0.0; !thread && cdSpeedRange(options, tm, lo, hi)) {
      const double mid = (lo + hi) / 2.0;
      const std::string rpmFix =
          c.diameter > 0.0 ? fmt::format("{:.0f}", mid * 1000.0 / (std::numbers::pi * c.diameter)) : "?";
      const std::vector<std::string> common = {
          u.vc(c.vc),       u.vcUnit(),      std::string(toolMaterialEn(tm)), std::string(toolMaterialTh(tm)),
          material->nameEn, material->nameTh};
      if (hi > 0.0 && c.vc > hi * 1.005) {
        std::vector<std::string> args = common;
        args.push_back(u.vc(hi));
        args.push_back(rpmFix);
        warn.add(codes::kCutSpeedHigh, m, std::move(args));
      } else if (lo > 0.0 && c.vc < lo * 0.995 && c.diameter > 0.0) {
        std::vector<std::string> args = common;
        args.push_back(u.vc(lo));
        args.push_back(rpmFix);
        warn.add(codes::kCutSpeedLow, m, std::move(args));
      }
    }
    const FinishMark* mark = nullptr;
    const double finishRa = finishLimit(options, c.inside, c.diameter, c.z0, c.z1, &mark);
    if (c.ra && c.depth <= options.finishingDepth && finishRa > 0.0 && *c.ra > finishRa * 1.005) {
      const double fmax = std::sqrt(finishRa * 32.0 * c.noseRadius / 1000.0);
      // Where the limit comes from: the drawing's mark on this surface, or the default.
      std::string whyEn, whyTh;
      if (mark) {
        const std::string d =
            mark->dMin == mark->dMax ? u.len(mark->dMin) : u.len(mark->dMin) + "-" + u.len(mark->dMax);
        whyEn = fmt::format("the drawing's mark for {} {} from Z{} to Z{}", mark->inside ? "the bore" : "diameter", d,
                            u.len(mark->zRight), u.len(mark->zLeft));
        whyTh = fmt::format("ตามสัญลักษณ์ความหยาบผิวในแบบงานของ{} {} จาก Z{} ถึง Z{}", mark->inside ? "รูเจาะ Ø" : "Ø", d,
                            u.len(mark->zRight), u.len(mark->zLeft));
      } else {
        const bool n8 = std::abs(finishRa - 3.2) < 1e-9;  // ISO 1302's N8, the usual turned finish
        whyEn = n8 ? "the default, N8: the drawing gives no mark here" : "the default: the drawing gives no mark here";
        whyTh = n8 ? "ค่าปกติ N8 เพราะแบบงานไม่ได้กำหนดความหยาบผิวตรงนี้" : "ค่าปกติ เพราะแบบงานไม่ได้กำหนดความหยาบผิวตรงนี้";
      }
      warn.add(codes::kFinishTooRough, m,
               {u.feed(c.feed), u.len(c.noseRadius), fmt::format("{:.1f}", *c.ra), fmt::format("{:.1f}", *c.rz),
                fmt::format("{:.1f}", finishRa), u.feed(fmax), u.unitArg(), whyEn, whyTh});
    }
    const double edge = options.edgeLength[k];
    if (edge > 0.0 && c.depth > edge * 2.0 / 3.0 * 1.005)
      warn.add(codes::kDepthOverEdge, m, {u.len(c.depth), u.len(edge), u.len(edge * 2.0 / 3.0), u.unitArg()});
    if (options.spindlePowerKw > 0.0 && c.power > options.spindlePowerKw * 1.005)
      warn.add(codes::kPowerOverSpindle, m,
               {fmt::format("{:.1f}", c.power), fmt::format("{:.1f}", options.spindlePowerKw), u.len(c.depth),
                u.feed(c.feed), u.unitArg()});
    if (options.spindleTorqueNm > 0.0 && c.torque > options.spindleTorqueNm * 1.005)
      warn.add(codes::kTorqueOverSpindle, m,
               {fmt::format("{:.0f}", c.torque), fmt::format("{:.0f}", options.spindleTorqueNm), u.len(c.diameter),
                u.unitArg()});
    if (!options.warningsOnly) data.cuts.push_back(c);
  }
  return data;
}

std::size_t movesBeforeAlarm(const machine::Timeline& record) {
  if (!record.alarm) return record.moveCount();
  const SourceRange& at = record.alarm->range;
  std::size_t before = 0;
  for (std::size_t k = 0; k < record.blockCount(); ++k) {
    const machine::BlockMark s = record.blockMark(k);
    if (s.file == at.file && s.line == at.line) return before;
    before = static_cast<std::size_t>(s.moveEnd);
  }
  return record.moveCount();
}

std::vector<Diagnostic> checkCuttingData(const machine::Timeline& record, const io::JobHeader& header,
                                         const machine::MachineSetup& setup, DisplayUnits units,
                                         std::vector<FinishMark> finishMarks) {
  if (header.diameter <= 0.0 || header.length <= 0.0 || record.moveCount() == 0) return {};
  // A record of marks keeps its moves' feeds and speeds only when asked (RunOptions::recordSpeeds).
  if (record.moves.empty() && record.recordSpeeds.size() != record.recordMoves.size()) return {};
  CuttingDataOptions options = cuttingDataOptions(header.material, setup.tools, setup.machine, shippedMaterials());
  options.units = units;
  options.finishMarks = std::move(finishMarks);
  options.warningsOnly = true;
  options.moveEnd = movesBeforeAlarm(record);
  const CutSetup cutSetup = CutSetup::from(header, setup);
  if (!record.moves.empty()) return measureCuts(record, cutSetup, options).warnings;
  // A record of marks: its moves made whole again, as far as a warning could come (a sound program
  // none), for the cut that measures them (the record's moves are what the run's would be but for
  // the call level, program, nose centre and compensation, which neither reads).
  const CdCandidates candidates(cutSetup, options);
  std::size_t measured = std::min(options.moveEnd, record.recordMoves.size());
  while (measured > 0 && !candidates.couldWarn(record.recordedMove(measured - 1))) --measured;
  if (measured == 0) return {};
  machine::Timeline moves;
  moves.moves.reserve(measured);
  for (std::size_t i = 0; i < measured; ++i) moves.moves.push_back(record.recordedMove(i));
  options.moveEnd = measured;
  return measureCuts(moves, cutSetup, options).warnings;
}

std::optional<SurfaceFinish> surfaceFinishOf(const CuttingData& data, const Stock& stock, const PartFeature& f) {
  if (data.lastOutside.size() != static_cast<std::size_t>(stock.columnCount()) || f.kind == FeatureKind::Thread)
    return std::nullopt;
  const bool inside = f.side == FeatureSide::Inside;
  const CutNumbers* left = nullptr;
  if (f.kind == FeatureKind::Face) {
    // A face: the last cut across X at its Z (within the nose and two columns) over its diameters.
    const double dLo = std::min(f.diameterLeft, f.diameterRight), dHi = std::max(f.diameterLeft, f.diameterRight);
    for (const CutNumbers& c : data.cuts) {
      const double reach = c.noseRadius + 2.0 * stock.columnWidth();
      if (c.facing && c.inside == inside && std::abs(c.z0 - f.zLeft) <= reach &&
          std::min(std::max(c.d0, c.d1), dHi) > std::max(std::min(c.d0, c.d1), dLo))
        left = &c;
    }
  } else {
    // Along Z: the cut that last reached most of its columns (the rougher one on a tie).
    std::map<int, int> count;
    int first = 0, last = -1;
    stock.columnRange(f.zLeft, f.zRight, first, last);
    const std::vector<int>& lastCut = inside ? data.lastInside : data.lastOutside;
    for (int col = first; col <= last; ++col)
      if (const int cut = lastCut[static_cast<std::size_t>(col)]; cut >= 0) ++count[cut];
    int best = -1, bestCount = 0;
    for (const auto& [cut, n] : count) {
      const double ra = data.cuts[static_cast<std::size_t>(cut)].ra.value_or(0.0);
      if (best < 0 || n > bestCount ||
          (n == bestCount && ra > data.cuts[static_cast<std::size_t>(best)].ra.value_or(0.0))) {
        best = cut;
        bestCount = n;
      }
    }
    // A surface mostly as the bar came (a cut only brushed its end) got no roughness from a cut.
    if (best >= 0 && 2 * bestCount > last - first + 1) left = &data.cuts[static_cast<std::size_t>(best)];
  }
  if (!left || !left->ra) return std::nullopt;
  SurfaceFinish s;
  s.inside = inside;
  s.zLeft = f.zLeft;
  s.zRight = f.zRight;
  s.dMin = std::min(f.diameterLeft, f.diameterRight);
  s.dMax = std::max(f.diameterLeft, f.diameterRight);
  s.line = left->line;
  s.file = left->file;
  s.feed = left->feed;
  s.noseRadius = left->noseRadius;
  s.ra = *left->ra;
  s.rz = left->rz.value_or(0.0);
  s.face = f.kind == FeatureKind::Face;
  return s;
}

std::vector<SurfaceFinish> surfaceFinishes(const CuttingData& data, const Stock& stock) {
  std::vector<SurfaceFinish> out;
  const PartFeatures features = partFeatures(stock);
  for (const auto* list : {&features.outside, &features.inside})
    for (const PartFeature& f : *list)
      if (std::optional<SurfaceFinish> s = surfaceFinishOf(data, stock, f)) out.push_back(*s);
  return out;
}

CuttingData measureRun(const machine::Timeline& timeline, const io::JobHeader& header,
                       const machine::MachineSetup& setup, DisplayUnits units, std::vector<FinishMark> finishMarks) {
  CuttingDataOptions options = cuttingDataOptions(header.material, setup.tools, setup.machine, shippedMaterials());
  options.units = units;
  options.finishMarks = std::move(finishMarks);
  return measureCuts(timeline, CutSetup::from(header, setup), options);
}

namespace {

void mergeCut(CutNumbers& into, const CutNumbers& c) {
  into.tEnd = c.tEnd;
  into.diameter = std::max(into.diameter, c.diameter);
  into.rpm = std::max(into.rpm, c.rpm);
  into.vc = std::max(into.vc, c.vc);
  into.feed = std::max(into.feed, c.feed);
  into.depth = std::max(into.depth, c.depth);
  into.chipWidth = std::max(into.chipWidth, c.chipWidth);
  into.chipThickness = std::max(into.chipThickness, c.chipThickness);
  into.removalRate = std::max(into.removalRate, c.removalRate);
  into.noseRadius = std::max(into.noseRadius, c.noseRadius);
  if (c.rz) into.rz = std::max(into.rz.value_or(0.0), *c.rz);
  if (c.ra) into.ra = std::max(into.ra.value_or(0.0), *c.ra);
  into.kc = std::max(into.kc, c.kc);
  into.force = std::max(into.force, c.force);
  into.power = std::max(into.power, c.power);
  into.torque = std::max(into.torque, c.torque);
}

}  // namespace

std::optional<CutNumbers> CuttingData::ofLine(int file, int line) const {
  std::optional<CutNumbers> out;
  for (const CutNumbers& c : cuts) {
    if (c.file != file || c.line != line) continue;
    if (!out)
      out = c;
    else
      mergeCut(*out, c);
  }
  return out;
}

std::string formatCuttingDataCsv(const CuttingData& data, DisplayUnits units) {
  const bool inch = units == DisplayUnits::Inch;
  const CdUnits u{inch};
  std::string out = inch ? "line,file,tool,t_start_s,t_end_s,moves,diameter_in,rpm,vc_ft_min,f_in_rev,ap_in,"
                           "chip_width_in,chip_thickness_in,q_in3_min,nose_radius_in,rz_um,ra_um,kc_n_mm2,fc_n,pc_kw,"
                           "torque_nm,warnings\n"
                         : "line,file,tool,t_start_s,t_end_s,moves,diameter_mm,rpm,vc_m_min,f_mm_rev,ap_mm,"
                           "chip_width_mm,chip_thickness_mm,q_cm3_min,nose_radius_mm,rz_um,ra_um,kc_n_mm2,fc_n,pc_kw,"
                           "torque_nm,warnings\n";
  const auto codesOf = [&](int file, int line) {
    std::string s;
    for (const Diagnostic& d : data.warnings)
      if (d.range.file == file && d.range.line == line && s.find(d.code) == std::string::npos)
        s += (s.empty() ? "" : " ") + d.code;
    return s;
  };
  const double q = inch ? 1.0 / 16.387064 : 1.0;  // cm^3 -> in^3
  std::size_t i = 0;
  while (i < data.cuts.size()) {
    CutNumbers b = data.cuts[i];
    std::size_t j = i + 1;
    for (; j < data.cuts.size() && data.cuts[j].line == b.line && data.cuts[j].file == b.file; ++j)
      mergeCut(b, data.cuts[j]);
    const auto opt = [](const std::optional<double>& v) { return v ? fmt::format("{:.2f}", *v) : std::string(); };
    out += fmt::format(
        "{},{},{},{:.3f},{:.3f},{},{},{:.0f},{},{},{},{},{},{:.2f},{},{},{},{:.0f},{:.0f},{:.3f},{:.1f},{}\n", b.line,
        b.file, b.tool, b.tStart, b.tEnd, j - i, u.len(b.diameter), b.rpm, u.vc(b.vc), u.feed(b.feed), u.len(b.depth),
        u.len(b.chipWidth), u.feed(b.chipThickness), b.removalRate * q, u.len(b.noseRadius), opt(b.rz), opt(b.ra), b.kc,
        b.force, b.power, b.torque, codesOf(b.file, b.line));
    i = j;
  }
  return out;
}

}  // namespace klueng::core::cut

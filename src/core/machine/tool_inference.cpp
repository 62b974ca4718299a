#include "klueng/core/machine/tool_inference.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "machine/tool_words.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine {

namespace {

using io::ToolKind;

constexpr double kOnCentreMm = 0.01;     // |X| below this (diameter) is on the centre line
constexpr double kCentreDrillMaxMm = 5.0;  // a drill on centre no deeper than this is a centre drill
constexpr double kPartingBeyondMm = 2.0;   // a plunge to X0 deeper than this in Z is not facing

struct Evidence {
  ToolKind kind = ToolKind::Unknown;
  ToolReason reason = ToolReason::Turning;
  std::string detail;
  int line = 0;
  bool strong = false;
  bool finishing = false;
  std::string insert;
  double drillMm = 0.0;
  double depthMm = 0.0;  // drilling: deepest Z (negative)
};

struct StationUse {
  int firstLine = 0;              // the first T block selecting it
  std::set<int> offsets;          // offset numbers used with it (1..)
  std::optional<Evidence> comment;
  std::optional<Evidence> cycle;  // the first telling cycle / move
  std::optional<Evidence> turning;
  double drillDepthMm = 0.0;      // deepest drilling on centre
  int drillLine = 0;
  std::string drillCode;
  std::optional<double> approachX;  // first rapid X after selection (mm, diameter)
};

std::string twoDigits(int n) { return fmt::format("{:02}", n); }

// The text of ( ) and ; comments on one raw line.
std::string commentOf(std::string_view line) {
  std::string out;
  int depth = 0;
  std::string cur;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (depth == 0 && c == ';') {
      if (!out.empty()) out += ' ';
      out += std::string(line.substr(i + 1));
      break;
    }
    if (c == '(') {
      if (depth++ == 0) continue;
    } else if (c == ')' && depth > 0) {
      if (--depth == 0) {
        if (!out.empty()) out += ' ';
        out += cur;
        cur.clear();
        continue;
      }
    }
    if (depth > 0) cur += c;
  }
  if (depth > 0) out += (out.empty() ? "" : " ") + cur;
  // Trim.
  const auto b = out.find_first_not_of(" \t");
  const auto e = out.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : out.substr(b, e - b + 1);
}

std::vector<std::string_view> splitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  lines.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1);
  if (std::memchr(text.data(), '\r', text.size()) == nullptr) {
    // LF only (the usual case): memchr from line end to line end.
    const char* p = text.data();
    const char* const end = p + text.size();
    while (p < end) {
      const char* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
      if (!nl) {
        lines.emplace_back(p, static_cast<std::size_t>(end - p));
        break;
      }
      lines.emplace_back(p, static_cast<std::size_t>(nl - p));
      p = nl + 1;
    }
    return lines;
  }
  std::size_t start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || text[i] == '\r') {
      lines.push_back(text.substr(start, i - start));
      if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      start = i + 1;
    }
  }
  if (start < text.size()) lines.push_back(text.substr(start));
  return lines;
}

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
      if (insertMatch && !bestInsert) best = &t;
      else if (insertMatch && bestInsert && e.finishing && t.noseRadius < best->noseRadius) best = &t;
    } else if (e.kind == ToolKind::Drill && e.drillMm > 0.0) {
      if (std::abs(t.size - e.drillMm) < std::abs(best->size - e.drillMm)) best = &t;
    }
  }
  return best;
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

// Walks the blocks once, collecting per station what it does.
class Scanner {
 public:
  Scanner(const gcode::Program& program, std::string_view text, int firstLine, double powerOnUnit)
      : program_(program), lines_(splitLines(text)), firstLine_(firstLine), unit_(powerOnUnit) {}

  std::map<int, StationUse> scan() {
    // Lines that hold words other than N: a comment above such a line belongs to it.
    // (A flag per line of the program's own text: a set of 100,000 lines cost most of the scan.)
    isBlockLine_.assign(lines_.size(), false);
    for (const gcode::Block& b : program_.blocks)
      if (b.file == 0 && b.line >= firstLine_ && b.line - firstLine_ < static_cast<int>(lines_.size()) &&
          std::any_of(b.words.begin(), b.words.end(), [](const gcode::Word& w) { return w.letter != 'N'; }))
        isBlockLine_[static_cast<std::size_t>(b.line - firstLine_)] = true;
    readToolList();
    for (std::size_t bi = 0; bi < program_.blocks.size(); ++bi) {
      const gcode::Block& b = program_.blocks[bi];
      for (const gcode::Word* g : b.all('G'))
        if (!g->hasDecimalPoint && (g->code() == 20 || g->code() == 21)) unit_ = g->code() == 20 ? 25.4 : 1.0;
      if (const gcode::Word* t = b.find('T'); t && !t->hasDecimalPoint && t->expr < 0) select(b, *t);
      if (station_ > 0) motion(b);
      // Past the main program's end (M02/M30) or into another program (O...): the
      // blocks are subprograms, whose tool is whoever calls them (the recorded run knows).
      const bool ends = std::any_of(b.words.begin(), b.words.end(), [](const gcode::Word& w) {
        return (w.letter == 'M' && !w.hasDecimalPoint && (w.code() == 2 || w.code() == 30 || w.code() == 99)) ||
               w.letter == 'O';
      });
      if (ends) station_ = 0;
    }
    return std::move(uses_);
  }
  const std::vector<int>& order() const { return order_; }
  // The words of a file line, for a note ("G01 Z-51.4"), without its comment.
  std::string blockText(int fileLine) const {
    const int i = fileLine - firstLine_;
    if (i < 0 || i >= static_cast<int>(lines_.size())) return {};
    const std::string_view line = lines_[static_cast<std::size_t>(i)];
    std::string words(line.substr(0, line.find_first_of("(;")));
    while (!words.empty() && (words.back() == ' ' || words.back() == '\t' || words.back() == '\r')) words.pop_back();
    return words.size() > 40 ? words.substr(0, 40) : words;
  }

  std::map<int, Evidence> partings_;  // station -> its plunge to X0 (kept when among the last tools)

 private:
  const gcode::Program& program_;
  std::vector<std::string_view> lines_;
  int firstLine_;
  std::map<int, StationUse> uses_;
  StationUse* current_ = nullptr;  // uses_[station_] (a map's elements stay put)
  std::vector<int> order_;  // station of every T selection, in program order
  int station_ = 0;
  double unit_ = 1.0;  // mm per program unit: the power-on units until G20/G21
  int motion_ = 0;
  std::optional<double> x_, z_;  // mm (x diameter)
  bool afterSelect_ = false;
  std::map<int, int> toolList_;  // station -> file line of its entry in a tool list comment
  std::vector<bool> isBlockLine_;  // per text line: it holds words other than N

  // A tool list, as real programs write one at the top: comment-only lines
  // that start with a T word, "(T9 VNMG 332 - 35 DEG)", "(T0303 THREAD)".
  // Station: 1-2 digits as written, 3-4 digits = station and offset.
  bool blockLine(int line) const {
    const int i = line - firstLine_;
    return i >= 0 && i < static_cast<int>(isBlockLine_.size()) && isBlockLine_[static_cast<std::size_t>(i)];
  }

  void readToolList() {
    for (std::size_t i = 0; i < lines_.size(); ++i) {
      const int line = firstLine_ + static_cast<int>(i);
      if (blockLine(line)) continue;
      const std::string text = commentOf(lines_[i]);
      std::size_t k = 0;
      while (k < text.size() && text[k] == ' ') ++k;
      if (k >= text.size() || (text[k] != 'T' && text[k] != 't')) continue;
      // "(T1 OD TURN, T3 THREAD)" lists two stations.
      for (const detail::CommentToolWord& w : detail::toolWordsIn(std::string_view(text).substr(k)))
        if (w.station >= 1 && w.station <= io::kMaxStations && !toolList_.count(w.station)) toolList_[w.station] = line;
    }
  }

  std::string rawComment(int fileLine) const {
    const int i = fileLine - firstLine_;
    if (i < 0 || i >= static_cast<int>(lines_.size())) return {};
    return commentOf(lines_[static_cast<std::size_t>(i)]);
  }

  void select(const gcode::Block& b, const gcode::Word& t) {
    const int code = t.code();
    const int station = code / 100, offset = code % 100;
    if (station < 1 || station > io::kMaxStations) return;
    station_ = station;
    afterSelect_ = true;
    order_.push_back(station);
    StationUse& u = uses_[station];
    current_ = &u;
    if (!u.firstLine) u.firstLine = b.line;
    if (offset > 0) u.offsets.insert(offset);
    if (u.comment) return;
    // The T block's comment, then comment lines just before it (up to 3; an
    // `N1 (OD ROUGH)` line is one, as Haas programs write them), then just after it.
    std::vector<int> candidates = {b.line};
    for (int l = b.line - 1; l >= b.line - 3 && !blockLine(l); --l) candidates.push_back(l);
    for (int l = b.line + 1; l <= b.line + 2 && !blockLine(l); ++l) candidates.push_back(l);
    if (auto listed = toolList_.find(station); listed != toolList_.end()) candidates.push_back(listed->second);
    for (int l : candidates) {
      const std::string whole = rawComment(l);
      const std::string text(detail::commentForStation(whole, station));  // its part of "(T1 OD, T3 THREAD)"
      if (text.empty()) continue;
      const detail::CommentTool c = detail::classifyComment(text, unit_);
      if (c.kind == ToolKind::Unknown) continue;
      Evidence e;
      e.kind = c.kind;
      e.reason = ToolReason::Comment;
      e.detail = text.size() > 60 ? text.substr(0, 60) : text;
      e.line = l;
      e.strong = true;
      e.finishing = c.finishing;
      e.insert = c.insert;
      e.drillMm = c.drillMm;
      // "(FINISHING)" above T0202 and "(T02 = 35* FINISH TURNING TOOL ...)" in the tool
      // list: the insert comes from whichever comment of this station names it.
      if (e.insert.empty() && e.kind == ToolKind::Turning)
        for (int other : candidates) {
          const std::string more(detail::commentForStation(rawComment(other), station));
          const detail::CommentTool named = detail::classifyComment(more, unit_);
          if (!named.insert.empty() && (named.kind == ToolKind::Turning || named.kind == ToolKind::Unknown)) {
            e.insert = named.insert;
            break;
          }
        }
      u.comment = e;
      return;
    }
  }

  void note(ToolKind kind, ToolReason reason, const std::string& detail, int line, bool strong = true,
            bool finishing = false) {
    StationUse& u = *current_;
    if (strong ? u.cycle.has_value() : u.turning.has_value()) return;  // the first of each kind is kept
    Evidence e;
    e.kind = kind;
    e.reason = reason;
    e.detail = detail;
    e.line = line;
    e.strong = strong;
    e.finishing = finishing;
    if (strong && !u.cycle) u.cycle = e;
    if (!strong && !u.turning) u.turning = e;
  }

  static std::string gText(int g) { return fmt::format("G{:02}", g); }

  void motion(const gcode::Block& b) {
    StationUse& u = *current_;
    int cycle = -1;
    for (const gcode::Word* g : b.all('G')) {
      if (g->hasDecimalPoint) continue;
      const int n = g->code();
      if (n == 27 || n == 28 || n == 29 || n == 30 || n == 53) {
        x_.reset();  // to the reference / machine position: not a work position
        z_.reset();
        return;
      }
      if (n == 50 && (b.has('X') || b.has('Z'))) {
        if (const gcode::Word* w = b.find('X')) x_ = w->expr < 0 ? std::optional<double>(w->value * unit_) : std::nullopt;
        if (const gcode::Word* w = b.find('Z')) z_ = w->expr < 0 ? std::optional<double>(w->value * unit_) : std::nullopt;
        return;
      }
      if (n == 0 || n == 1 || n == 2 || n == 3 || n == 32 || n == 90 || n == 92 || n == 94) motion_ = n;
      if ((n >= 70 && n <= 76) || (n >= 81 && n <= 83) || n == 90 || n == 92 || n == 94) cycle = n;
      if (n == 80) motion_ = 0;
    }
    const gcode::Word* xw = b.find('X');
    const gcode::Word* uw = b.find('U');
    const gcode::Word* zw = b.find('Z');
    const gcode::Word* ww = b.find('W');
    std::optional<double> x = x_, z = z_;
    // A macro expression (X#100) is known only when the program runs: the position becomes unknown.
    if (xw) x = xw->expr < 0 ? std::optional<double>(xw->value * unit_) : std::nullopt;
    else if (uw && x) x = uw->expr < 0 ? std::optional<double>(*x + uw->value * unit_) : std::nullopt;
    if (zw) z = zw->expr < 0 ? std::optional<double>(zw->value * unit_) : std::nullopt;
    else if (ww && z) z = ww->expr < 0 ? std::optional<double>(*z + ww->value * unit_) : std::nullopt;

    if (cycle == 76 || cycle == 92 || motion_ == 32) {
      if (cycle == 76 && !xw && !zw && !uw && !ww) return;  // the first G76 block of the two
      // Inside when it cuts outward from its approach, or when the thread's own comment says
      // so ("G76 X36.2 Z-22. ... (ID THREAD)", "(INTERNAL)").
      const detail::CommentTool said = detail::classifyComment(rawComment(b.line), unit_);
      const bool inside = (u.approachX && x && *x > *u.approachX + kOnCentreMm) || said.kind == ToolKind::ThreadingId ||
                          said.kind == ToolKind::Boring;
      const int code = cycle >= 0 ? cycle : 32;
      note(inside ? ToolKind::ThreadingId : ToolKind::ThreadingOd,
           inside ? ToolReason::ThreadingInside : ToolReason::Threading, gText(code), b.line);
    } else if ((cycle == 75 || cycle == 74) && !xw && !zw && !uw && !ww) {
      return;  // the first G74/G75 block of the two (retract R only)
    } else if (cycle == 75) {
      if (x && *x <= kOnCentreMm) note(ToolKind::Parting, ToolReason::Parting, "G75 X0", b.line);
      else note(ToolKind::Grooving, ToolReason::Grooving, "G75", b.line);
    } else if (cycle == 74 || (cycle >= 81 && cycle <= 83)) {
      if (cycle == 74 && xw && std::abs(xw->value) > kOnCentreMm) {
        note(ToolKind::Grooving, ToolReason::Grooving, "G74", b.line);
      } else if (zw || ww) {
        drilling(u, z.value_or(0.0), gText(cycle), b.line);
      }
    } else if (cycle >= 71 && cycle <= 73) {
      const gcode::Word* allowance = b.find('U');
      if (b.find('P') && allowance && allowance->value < 0.0)
        note(ToolKind::Boring, ToolReason::Boring, fmt::format("{} U{}", gText(cycle), allowance->number.view()), b.line);
      else if (b.find('P'))
        note(ToolKind::Turning, ToolReason::Turning, gText(cycle), b.line, false);
    } else if (cycle == 70 || cycle == 90 || cycle == 94) {
      note(ToolKind::Turning, ToolReason::Turning, gText(cycle), b.line, false, cycle == 70);
    } else if (motion_ == 0 && (xw || uw) && afterSelect_ && !u.approachX) {
      u.approachX = x;
    } else if ((motion_ == 1 || motion_ == 2 || motion_ == 3) && (xw || uw || zw || ww)) {
      const bool onCentre = x_ && std::abs(*x_) <= kOnCentreMm && x && std::abs(*x) <= kOnCentreMm;
      if (onCentre && (zw || ww) && z && *z < 0.0) {
        drilling(u, *z, motion_ == 1 ? "G01 X0" : gText(motion_), b.line);
      } else if (x && *x <= kOnCentreMm && !zw && !ww && z && *z < -kPartingBeyondMm && x_ && *x_ > *x) {
        Evidence e;
        e.kind = ToolKind::Parting;
        e.reason = ToolReason::Parting;
        e.detail = xw ? "X" + xw->number : "U" + uw->number;
        e.line = b.line;
        e.strong = true;
        partings_[station_] = e;
      } else if (!u.turning) {  // only the first turning move is kept: no text for the others
        note(ToolKind::Turning, ToolReason::Turning, gText(motion_), b.line, false);
      }
    }
    x_ = x;
    z_ = z;
  }

  void drilling(StationUse& u, double depth, const std::string& code, int line) {
    if (depth < u.drillDepthMm || !u.drillLine) {
      u.drillDepthMm = std::min(depth, u.drillDepthMm);
      if (!u.drillLine) {
        u.drillLine = line;
        u.drillCode = code;
      }
    }
  }
};


// ---- Evidence of motion: one recorded run of the interpreter --------------------------------
// What each tool really does after macros, subprograms, cycles and offsets.
struct MotionUse {
  double towardChuck = 0.0;  // mm fed along -Z (a right-hand tool's work)
  double towardTail = 0.0;   // mm fed along +Z (a left-hand tool's)
  double inside = 0.0;       // mm of Z feeds left by a retract inward (boring)
  double outside = 0.0;      // mm of Z feeds left by a retract outward
  double belowZero = 0.0;    // mm fed at X < 0 (a tool beyond the centre)
  double aboveZero = 0.0;    // mm fed at X > 0
  int insideLine = 0;        // the first Z feed left inward
  int belowLine = 0;         // the first feed at X < 0
  int threadLine = 0;        // the first thread pass (G32/G76/G92 after macros and calls)
  double drillDepth = 0.0;   // deepest feed along -Z on the centre line (mm, Z < 0)
  int drillLine = 0;
  double plunge = 0.0;       // deepest straight radial feed toward the centre off it (mm, on the diameter)
  double plungeEndX = 0.0;   // the X it ended at (diameter, mm)
  double plungeZ = 0.0;      // and its Z
  int plungeLine = 0;
};

constexpr double kMinZRunMm = 0.5;  // a Z feed shorter than this says nothing about the side
constexpr double kMinPlungeMm = 2.0;       // a radial feed this deep (on the diameter) is a plunge
constexpr double kGroovingReachMm = 6.0;   // deeper (radius) than a grooving blade reaches: a parting blade

std::map<int, MotionUse> recordMotion(const Timeline& timeline) {
  std::map<int, MotionUse> uses;
  struct Pending {
    int tool = 0;  // 0 = none
    double length = 0.0;
    int line = 0;
  };
  // The last feed along Z toward the chuck, until X moves: a tool feeds into its
  // work toward the chuck and leaves it across X, outward from a diameter,
  // inward from a bore. (A feed toward the tailstock ends a face profile or a
  // back cut, and what follows it says nothing about the side.)
  Pending zRun;
  for (const Move& m : timeline.moves) {
    if (m.tool < 1 || m.kind == MoveKind::Dwell) continue;
    const Vec2 d = m.path.end - m.path.start;  // (z, x radius)
    const double dz = d.x(), dx = d.y();
    MotionUse& u = uses[m.tool];
    if (zRun.tool != m.tool) zRun = {};
    if (zRun.tool && std::abs(dx) > 1e-3) {
      (dx < 0.0 ? u.inside : u.outside) += zRun.length;
      if (dx < 0.0 && !u.insideLine) u.insideLine = zRun.line;
      zRun = {};
    }
    if (m.kind == MoveKind::Rapid) continue;
    if (m.kind == MoveKind::Thread && !u.threadLine) u.threadLine = m.line;
    if (std::abs(m.path.start.y()) <= kOnCentreMm && std::abs(m.path.end.y()) <= kOnCentreMm && dz < 0.0 &&
        m.path.end.x() < u.drillDepth) {
      u.drillDepth = m.path.end.x();
      if (!u.drillLine) u.drillLine = m.line;
    }
    const double length = d.norm();
    const double xMid = (m.path.start.y() + m.path.end.y()) / 2.0;
    if (xMid < -kOnCentreMm) {
      u.belowZero += length;
      if (!u.belowLine) u.belowLine = m.line;
    }
    else if (xMid > kOnCentreMm) u.aboveZero += length;
    if (std::abs(dz) >= kMinZRunMm && std::abs(dz) >= 2.0 * std::abs(dx)) {
      (dz < 0.0 ? u.towardChuck : u.towardTail) += std::abs(dz);
      zRun = dz < 0.0 ? Pending{m.tool, std::abs(dz), m.line} : Pending{};
    }
    // A plunge: a straight feed toward the centre with no Z travel, ending off the centre line.
    if (m.kind == MoveKind::Line && std::abs(dz) < 1e-3 && dx < 0.0 && m.path.end.y() > kOnCentreMm &&
        -2.0 * dx > u.plunge) {
      u.plunge = -2.0 * dx;
      u.plungeEndX = 2.0 * m.path.end.y();
      u.plungeZ = m.path.end.x();
      u.plungeLine = m.line;
    }
  }
  return uses;
}

// Right-hand (feeds toward the chuck) or left-hand: by what the run shows.
bool leftHandWork(const MotionUse& m) { return m.towardTail > 2.0 * m.towardChuck && m.towardTail >= 1.0; }
bool insideWork(const MotionUse& m) { return m.inside > m.outside && m.inside >= 1.0; }

// What a tools.cfg line names: "02-outside-left-hand.bmp" is a left-hand turning tool.
bool namesLeftHand(std::string_view fileName) {
  std::string name(fileName);
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return name.find("left-hand") != std::string::npos || name.find("left_hand") != std::string::npos ||
         name.find("lefthand") != std::string::npos;
}
}  // namespace

Diagnostic ToolChoice::note() const {
  Diagnostic d;
  d.severity = Severity::Note;
  d.code = noteCode(reason);
  d.range.line = line;
  d.args = {twoDigits(station), libraryId, detail, std::to_string(line)};
  return d;
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

ToolInference inferTools(const gcode::Program& program, std::string_view gcodeText, int gcodeFirstLine,
                         const MachineSetup& setup, const io::ToolLibrary& library,
                         const std::vector<StationOverride>& overrides, int stations,
                         const InferenceContext& context) {
  ToolInference out;
  out.setup = setup;
  out.fromProgram = context.fromProgram;
  const gcode::InputUnits powerOn =
      gcode::powerOnUnitsOf(context.run.dialect, context.run.powerOnUnits);
  Scanner scanner(program, gcodeText, gcodeFirstLine, powerOn == gcode::InputUnits::Inch ? 25.4 : 1.0);
  std::map<int, StationUse> uses = scanner.scan();
  // Stations past the turret (or the dialect's T range) are the checker's business.
  const int lastStation = std::clamp(stations > 0 ? stations : setup.tools.stations, 1, io::kMaxStations);
  std::erase_if(uses, [&](const auto& entry) { return entry.first > lastStation; });

  // A plain program: what each tool really does, from one recorded run.
  std::map<int, MotionUse> motion;
  if (context.fromProgram) {
    RunOptions run = context.run;
    run.persistentVariables = nullptr;  // the record changes nothing the user keeps
    out.record = std::make_shared<const Timeline>(interpret(program, setup, run));
    motion = recordMotion(*out.record);
  }

  // Parting counts only for one of the last two tools the program selects.
  std::vector<int> last;
  for (auto it = scanner.order().rbegin(); it != scanner.order().rend() && last.size() < 2; ++it)
    if (std::find(last.begin(), last.end(), *it) == last.end()) last.push_back(*it);
  for (const auto& [station, e] : scanner.partings_)
    if (std::find(last.begin(), last.end(), station) != last.end() && !uses[station].cycle) uses[station].cycle = e;

  const auto assign = [&](int station, const io::LibraryTool& tool, ToolReason reason, std::string detail, int line,
                          const std::set<int>& offsets) {
    out.setup.tools.setLibraryTool(station, tool.id, library.bitmapPath(tool), tool.pixelsPerMm);
    out.choices.push_back({station, tool.id, reason, std::move(detail), line});
    for (int n : offsets) {
      if (n < 1 || n > io::kOffsetCount) continue;
      io::Offset& o = out.setup.offsets.at(n);
      const bool empty = offsetEmpty(o);
      // A guessed tool brings its own nose: a row set for the table's tool is another tool's.
      if (!empty && !context.fromProgram) continue;
      if (!empty && o.r == tool.noseRadius && o.tip == tool.tip) continue;
      Diagnostic d;
      d.severity = Severity::Note;
      d.code = empty ? codes::kOffsetFromLibrary : codes::kOffsetReplacedByLibrary;
      d.range.line = line;
      d.args = {twoDigits(n), fmt::format("{:g}", tool.noseRadius), std::to_string(tool.tip), tool.id,
                fmt::format("{:g}", o.r), std::to_string(o.tip)};
      o.r = tool.noseRadius;
      o.tip = tool.tip;
      out.offsetNotes.push_back(std::move(d));
    }
  };

  std::set<int> overridden;
  for (const StationOverride& o : overrides) {
    const io::LibraryTool* tool = library.find(o.libraryId);
    if (!tool || o.station < 1 || o.station > lastStation) continue;
    overridden.insert(o.station);
    const auto it = uses.find(o.station);
    assign(o.station, *tool, ToolReason::Override, {}, 0, it == uses.end() ? std::set<int>{} : it->second.offsets);
  }

  for (auto& [station, use] : uses) {
    if (overridden.count(station)) continue;
    const auto moved = motion.find(station);
    if (moved != motion.end() && !use.cycle && !use.drillLine) {
      // What the scan of the text could not see (macros, subprograms, X#100): the run's own moves.
      const MotionUse& m = moved->second;
      Evidence e;
      e.strong = true;
      if (m.threadLine) {
        const bool inside = insideWork(m);
        e.kind = inside ? ToolKind::ThreadingId : ToolKind::ThreadingOd;
        e.reason = inside ? ToolReason::ThreadingInside : ToolReason::Threading;
        e.line = m.threadLine;
        e.detail = scanner.blockText(m.threadLine);
        use.cycle = e;
      } else if (m.drillLine && m.aboveZero + m.belowZero < 1.0) {  // it only ever feeds on the centre line
        use.drillLine = m.drillLine;
        use.drillDepthMm = m.drillDepth;
        use.drillCode = scanner.blockText(m.drillLine);
      } else if (m.plunge >= kMinPlungeMm && m.towardChuck + m.towardTail < kMinZRunMm &&
                 m.plungeZ < -kPartingBeyondMm) {
        // It only plunges straight in, behind the face: a blade's work (a groove, or a cut-off
        // into a bore); deep plunges need the parting blade's reach.
        const bool deep = m.plunge / 2.0 > kGroovingReachMm;
        e.kind = deep ? ToolKind::Parting : ToolKind::Grooving;
        e.reason = deep ? ToolReason::Parting : ToolReason::Grooving;
        e.line = m.plungeLine;
        e.detail = scanner.blockText(m.plungeLine);
        use.cycle = e;
      }
    }
    // Drilling on centre: a centre drill when shallow, else a drill.
    if (use.drillLine && !use.cycle) {
      Evidence e;
      e.kind = -use.drillDepthMm <= kCentreDrillMaxMm ? ToolKind::CentreDrill : ToolKind::Drill;
      e.reason = ToolReason::Drilling;
      e.detail = use.drillCode;
      e.line = use.drillLine;
      e.strong = true;
      use.cycle = e;
    }
    std::optional<Evidence> want = use.comment;
    if (use.cycle) {
      const bool refine = !want || want->kind == ToolKind::Turning ||
                          (want->kind == ToolKind::ThreadingOd && use.cycle->kind == ToolKind::ThreadingId);
      if (refine) want = use.cycle;
    }
    if (!want) want = use.turning;
    if (want && moved != motion.end() && insideWork(moved->second)) {
      // The run retracts inward after its Z feeds: the tool works inside a bore.
      const MotionUse& m = moved->second;
      if (want->kind == ToolKind::Turning || want->kind == ToolKind::Unknown) {
        const bool named = want->reason == ToolReason::Comment && want->kind == ToolKind::Turning;
        if (!named || m.outside == 0.0) {
          want->kind = ToolKind::Boring;
          want->reason = ToolReason::Boring;
          want->detail = scanner.blockText(m.insideLine);
          want->line = m.insideLine;
          want->strong = true;
        }
      } else if (want->kind == ToolKind::ThreadingOd && want->reason != ToolReason::Comment) {
        want->kind = ToolKind::ThreadingId;
        want->reason = ToolReason::ThreadingInside;
      }
    }
    if (!want || want->kind == ToolKind::Unknown) continue;
    const std::optional<ToolKind> have = currentKind(setup.tools, station, library);
    if (context.fromProgram) {
      // The shop's program decides; the table only breaks ties: a tool of the right
      // kind (and hand, for turning) stays, anything else gives way to the evidence.
      // A comment naming the insert (VBMT, CNMG 120408) names a standard right-hand holder:
      // its feeds toward the tailstock are a profile's (a G72 shape's hub), not a left-hand tool's.
      const bool namedInsert = want->reason == ToolReason::Comment && !want->insert.empty();
      const bool left = moved != motion.end() && leftHandWork(moved->second) && !namedInsert;
      const std::string& line = setup.tools.bitmap[static_cast<std::size_t>(station - 1)];
      const bool haveLeft = namesLeftHand(line);
      const bool known = have && *have != ToolKind::Unknown;
      const bool handFits = want->kind != ToolKind::Turning || left == haveLeft;
      if (known && io::toolKindFits(*have, want->kind) && handFits) continue;
      if (want->kind == ToolKind::Turning && left) continue;  // the library has no left-hand tool: the table's stays
    } else if (have && (io::toolKindFits(*have, want->kind) || !want->strong)) {
      continue;  // keeps its tool
    }
    const io::LibraryTool* tool = pick(library, *want);
    if (!tool) continue;
    assign(station, *tool, want->reason, want->detail, want->line, use.offsets);
  }
  // A plain program that works beyond the centre line (X < 0): its tools are there
  // (unless the user said where they are for this file).
  if (context.toolsBeyondCentre) {
    out.setup.machine.toolsBeyondCentre = *context.toolsBeyondCentre;
  } else if (context.fromProgram && out.record) {
    const CutSide side = sideOfCuts(*out.record);
    if (side == CutSide::Beyond) {
      int line = 0;  // the first feed beyond the centre, for the note
      for (const auto& [station, m] : motion)
        if (m.belowZero > 0.0 && (!line || m.belowLine < line)) line = m.belowLine;
      out.setup.machine.toolsBeyondCentre = true;
      Diagnostic d;
      d.severity = Severity::Note;
      d.code = codes::kToolsBeyondCentre;
      d.range.line = line;
      d.args = {std::to_string(line)};
      out.offsetNotes.push_back(std::move(d));
    } else if (side == CutSide::Front) {
      out.setup.machine.toolsBeyondCentre = false;  // in front, whatever the machine's setting says
    }
  }
  // Every station of a plain program the user did not set is a guess.
  if (context.fromProgram)
    for (const auto& [station, use] : uses)
      if (!overridden.count(station)) out.setup.tools.guessed[static_cast<std::size_t>(station - 1)] = true;
  std::sort(out.choices.begin(), out.choices.end(),
            [](const ToolChoice& a, const ToolChoice& b) { return a.station < b.station; });
  return out;
}

bool parseStationOverride(std::string_view text, int stations, const io::ToolLibrary& library, StationOverride& out,
                          std::string& error) {
  const std::size_t eq = text.find('=');
  const std::string_view number = eq == std::string_view::npos ? std::string_view() : text.substr(0, eq);
  const std::string_view id = eq == std::string_view::npos ? std::string_view() : text.substr(eq + 1);
  int station = 0;
  bool digits = !number.empty() && number.size() <= 2;
  for (char c : number) {
    if (c < '0' || c > '9') digits = false;
    else station = station * 10 + (c - '0');
  }
  if (eq == std::string_view::npos || !digits || id.empty()) {
    error = fmt::format("--tool wants N=ID (a station and a library tool, e.g. 3=threading-60), not '{}'; "
                        "library tools: {}", text, library.idList());
    return false;
  }
  if (station < 1 || station > stations) {
    error = fmt::format("--tool {}: station {} is not on the turret (1 to {})", text, station, stations);
    return false;
  }
  if (!library.find(id)) {
    error = fmt::format("--tool {}: no library tool '{}'; library tools: {}", text, id, library.idList());
    return false;
  }
  out.station = station;
  out.libraryId = std::string(id);
  return true;
}

}  // namespace klueng::core::machine

#include "tool_evidence.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>

#include "infer/tool_words.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/comment.h"

namespace klueng::core::machine::detail {

namespace {

using io::ToolKind;

constexpr double kOnCentreMm = 0.01;      // |X| below this (diameter) is on the centre line
constexpr double kPartingBeyondMm = 2.0;  // a plunge to X0 deeper than this in Z is not facing
constexpr double kMinZRunMm = 0.5;        // a Z feed shorter than this says nothing about the side

// The text of ( ) and ; comments on one raw line.
std::string commentOf(std::string_view line) {
  std::string out;
  const auto append = [&out](std::string_view text) {
    if (!out.empty()) out += ' ';
    out += text;
  };
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == ';') {
      append(line.substr(i + 1));
      break;
    }
    if (line[i] != '(') continue;
    const std::size_t close = gcode::commentClose(line, i);
    append(line.substr(i + 1, close == std::string_view::npos ? std::string_view::npos : close - i - 1));
    if (close == std::string_view::npos) break;
    i = close;
  }
  const auto b = out.find_first_not_of(" \t");
  const auto e = out.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : out.substr(b, e - b + 1);
}

std::string gText(int g) { return fmt::format("G{:02}", g); }

// The G number of a modal motion, as the notes quote it, in the machine's G-code system (G33 in system B).
int motionCode(MotionMode mode, gcode::Dialect dialect) {
  switch (mode) {
    case MotionMode::Rapid: return 0;
    case MotionMode::Line: return 1;
    case MotionMode::ArcCw: return 2;
    case MotionMode::ArcCcw: return 3;
    case MotionMode::Thread: return gcode::numberInSystem('G', 32, dialect);
  }
  return 1;
}

// A move's ends as (z, x radius), seen from the front when the tools work beyond the centre.
struct Ends {
  Vec2 start, end;
};
template <typename M>  // a Move or a RecordMove
Ends endsOf(const M& m, bool mirror) {
  if (!mirror) return {m.path.start, m.path.end};
  return {Vec2(m.path.start.x(), -m.path.start.y()), Vec2(m.path.end.x(), -m.path.end.y())};
}

// What each tool's moves show, summed over the run: the moves are added in run order, a
// block's at a time (the gatherer reads each block's moves once, while they are in the cache).
class MotionRecorder {
 public:
  explicit MotionRecorder(bool mirror) : mirror_(mirror) {}
  template <typename M>
  void add(std::span<const M> moves) {
    for (const M& m : moves) addMove(m);
  }
  const std::map<int, MotionUse>& uses() const { return uses_; }

 private:
  struct Pending {
    int tool = 0;  // 0 = none
    double length = 0.0;
    int line = 0;
    bool thread = false;
  };
  std::map<int, MotionUse> uses_;
  bool mirror_ = false;
  MotionUse* last_ = nullptr;  // uses_[lastTool_] (a map's elements stay put)
  int lastTool_ = 0;
  // The last feed along Z toward the chuck, until X moves: a tool feeds into its
  // work toward the chuck and leaves it across X, outward from a diameter,
  // inward from a bore. (A feed toward the tailstock ends a face profile or a
  // back cut, and what follows it says nothing about the side.)
  Pending zRun;
  // A straight feed outward off the centre line, then straight back in: an inside groove's plunge
  // from a bore (an outside tool never feeds out into the wall and drops back in).
  Pending outward;

  template <typename M>
  void addMove(const M& m) {
    if (m.tool < 1 || m.kind == MoveKind::Dwell) return;
    const Ends p = endsOf(m, mirror_);
    const Vec2 d = p.end - p.start;  // (z, x radius)
    const double dz = d.x(), dx = d.y();
    if (!last_ || lastTool_ != m.tool) {
      last_ = &uses_[m.tool];
      lastTool_ = m.tool;
    }
    MotionUse& u = *last_;
    if (zRun.tool != m.tool) zRun = {};
    // (A feed on down to the centre line after it is a face cut, not a bore's wall.)
    const bool facesToCentre = m.kind != MoveKind::Rapid && dx < 0.0 && 2.0 * p.end.y() <= kOnCentreMm;
    if (zRun.tool && std::abs(dx) > 1e-3 && facesToCentre) zRun = {};
    if (zRun.tool && std::abs(dx) > 1e-3) {
      (dx < 0.0 ? u.inside : u.outside) += zRun.length;
      if (zRun.thread) (dx < 0.0 ? u.threadInside : u.threadOutside) += zRun.length;
      if (dx < 0.0 && !u.insideLine) u.insideLine = zRun.line;
      zRun = {};
    }
    if (outward.tool && (outward.tool != m.tool || std::abs(dz) > 1e-3 || dx > 1e-3)) outward = {};
    if (outward.tool && dx < -1e-3) {
      u.inside += outward.length;
      if (!u.insideLine) u.insideLine = outward.line;
      outward = {};
    }
    if (m.kind == MoveKind::Line && std::abs(dz) < 1e-3 && dx > 0.0 && p.start.y() > kOnCentreMm)
      outward = Pending{m.tool, dx, m.line, false};
    if (m.kind == MoveKind::Rapid) return;
    if (m.kind == MoveKind::Thread && !u.threadLine) u.threadLine = m.line;
    if (std::abs(p.start.y()) <= kOnCentreMm && std::abs(p.end.y()) <= kOnCentreMm && dz < 0.0 &&
        p.end.x() < u.drillDepth) {
      u.drillDepth = p.end.x();
      if (!u.drillLine) u.drillLine = m.line;
    }
    const double length = d.norm();
    // Which side of the centre the tool really is on: the unmirrored move.
    const double xMid = (m.path.start.y() + m.path.end.y()) / 2.0;
    if (xMid < -kOnCentreMm) {
      u.belowZero += length;
      if (!u.belowLine) u.belowLine = m.line;
    } else if (xMid > kOnCentreMm) {
      u.aboveZero += length;
    }
    if (std::abs(dz) >= kMinZRunMm && std::abs(dz) >= 2.0 * std::abs(dx)) {
      (dz < 0.0 ? u.towardChuck : u.towardTail) += std::abs(dz);
      zRun = dz < 0.0 ? Pending{m.tool, std::abs(dz), m.line, m.kind == MoveKind::Thread} : Pending{};
    }
    // A plunge: a straight feed toward the centre with no Z travel, ending off the centre line.
    if (m.kind == MoveKind::Line && std::abs(dz) < 1e-3 && dx < 0.0 && p.end.y() > kOnCentreMm &&
        -2.0 * dx > u.plunge) {
      u.plunge = -2.0 * dx;
      u.plungeEndX = 2.0 * p.end.y();
      u.plungeZ = p.end.x();
      u.plungeLine = m.line;
    }
  }
};

template <typename M>
bool isFeed(const M& m) {
  return m.kind != MoveKind::Rapid && m.kind != MoveKind::Dwell;
}

// The cycle a block runs, or its motion code: what its G words do in the dialect.
struct BlockCodes {
  gcode::CodeAction cycle = gcode::CodeAction::None;
  int cycleNumber = -1;  // the G number as written
};
BlockCodes codesOf(const gcode::Block& b, gcode::Dialect dialect) {
  BlockCodes out;
  for (const gcode::Word* g : b.all('G')) {
    if (g->hasDecimalPoint || g->expr >= 0) continue;
    const gcode::CodeInfo* row = gcode::findCode('G', g->code(), dialect);
    if (!row) continue;
    switch (row->action) {
      case gcode::CodeAction::Thread:
      case gcode::CodeAction::BoxThreading:
      case gcode::CodeAction::ThreadCutting:
      case gcode::CodeAction::Grooving:
      case gcode::CodeAction::FacePecking:
      case gcode::CodeAction::Drilling:
      case gcode::CodeAction::SpotDrilling:
      case gcode::CodeAction::PeckDrilling:
      case gcode::CodeAction::TurnRoughing:
      case gcode::CodeAction::FaceRoughing:
      case gcode::CodeAction::PatternRepeating:
      case gcode::CodeAction::Finishing:
      case gcode::CodeAction::BoxTurning:
      case gcode::CodeAction::BoxFacing:
        out.cycle = row->action;
        out.cycleNumber = g->code();
        break;
      default: break;
    }
  }
  return out;
}

// Reads the run block by block, collecting per station what it does.
class Gatherer {
 public:
  Gatherer(const gcode::Program& program, ProgramEvidence& out, gcode::Dialect dialect)
      : program_(program), out_(out), dialect_(dialect) {}

  void gather(const Timeline& run) {
    markBlockLines();
    readToolList();
    // The run's own moves where they lie, or a record's unpacked a block's at a time.
    if (!run.moves.empty() || run.recordMoves.empty()) {
      const std::span<const Move> all(run.moves);
      gatherMoves(run, all.size(), [&](std::size_t from, std::size_t to) { return all.subspan(from, to - from); });
      return;
    }
    std::vector<RecordMove> scratch;
    auto next = run.recordMoves.begin();  // the record read once, in order
    gatherMoves(run, run.recordMoves.size(), [&](std::size_t from, std::size_t to) {
      scratch.clear();
      for (std::size_t i = from; i < to; ++i, ++next) scratch.push_back(*next);
      return std::span<const RecordMove>(scratch);
    });
  }

 private:
  // movesOf(from, to): the moves [from, to) as a span, asked for in order.
  template <typename MovesOf>
  void gatherMoves(const Timeline& run, std::size_t moveCount, MovesOf movesOf) {
    MotionRecorder motion(out_.beyondCentre);
    std::size_t begin = 0;
    for (std::size_t k = 0; k < run.blockCount(); ++k) {
      const BlockMark s = run.blockMark(k);
      const std::size_t end =
          std::clamp<std::size_t>(static_cast<std::size_t>(std::max(s.moveEnd, 0)), begin, moveCount);
      const auto moves = movesOf(begin, end);
      begin = end;
      motion.add(moves);  // every move once, in run order
      if (s.blockIndex < 0 || static_cast<std::size_t>(s.blockIndex) >= program_.blocks.size()) continue;
      const gcode::Block& b = program_.blocks[static_cast<std::size_t>(s.blockIndex)];
      const int station = s.tool;
      if (station < 1 || station > io::kMaxStations) continue;
      if (const gcode::Word* t = b.find('T'); t && (t->expr >= 0 || t->code() != 0))
        select(b, station, s.offset, s.units == Units::Inch ? 25.4 : 1.0);
      if (!current_ || currentStation_ != station) {
        current_ = &out_.uses[station];  // a tool in use before any T block of the run selects it
        currentStation_ = station;
      }
      block(b, moves, station, motionCode(s.motion, dialect_));
    }
    motion.add(movesOf(begin, moveCount));  // after the last block
    for (auto& [station, use] : out_.uses)
      if (const auto it = motion.uses().find(station); it != motion.uses().end()) use.motion = it->second;
  }

  const gcode::Program& program_;
  ProgramEvidence& out_;
  gcode::Dialect dialect_;
  StationUse* current_ = nullptr;  // out_.uses[currentStation_] (a map's elements stay put)
  int currentStation_ = 0;
  std::map<int, int> toolList_;    // station -> file line of its entry in a tool list comment
  std::vector<bool> isBlockLine_;  // per text line: it holds words other than N

  int lineCount() const { return static_cast<int>(out_.lines.size()); }

  // Lines that hold words other than N: a comment above such a line belongs to it.
  // (A flag per line of the program's own text: a set of 100,000 lines cost most of the scan.)
  void markBlockLines() {
    isBlockLine_.assign(out_.lines.size(), false);
    const auto holdsMoreThanN = [](const gcode::Block& b) {
      // A parsed block's letters are exact (no bit past 'Z'): its words need no visit (a cache miss each).
      if ((b.letters >> 26) == 0) return (b.letters & ~gcode::Block::letterBit('N')) != 0;
      return std::any_of(b.words.begin(), b.words.end(), [](const gcode::Word& w) { return w.letter != 'N'; });
    };
    for (const gcode::Block& b : program_.blocks)
      if (b.file == 0 && b.line >= out_.firstLine && b.line - out_.firstLine < lineCount() && holdsMoreThanN(b))
        isBlockLine_[static_cast<std::size_t>(b.line - out_.firstLine)] = true;
  }

  bool blockLine(int line) const {
    const int i = line - out_.firstLine;
    return i >= 0 && i < lineCount() && isBlockLine_[static_cast<std::size_t>(i)];
  }

  std::string rawComment(int fileLine) const {
    const int i = fileLine - out_.firstLine;
    if (i < 0 || i >= lineCount()) return {};
    return commentOf(out_.lines[static_cast<std::size_t>(i)]);
  }

  // A tool list, as real programs write one at the top: comment-only lines
  // that start with a T word, "(T9 VNMG 332 - 35 DEG)", "(T0303 THREAD)".
  void readToolList() {
    for (int i = 0; i < lineCount(); ++i) {
      const int line = out_.firstLine + i;
      if (blockLine(line)) continue;
      const std::string text = commentOf(out_.lines[static_cast<std::size_t>(i)]);
      std::size_t k = 0;
      while (k < text.size() && text[k] == ' ') ++k;
      if (k >= text.size() || (text[k] != 'T' && text[k] != 't')) continue;
      // "(T1 OD TURN, T3 THREAD)" lists two stations.
      for (const CommentToolWord& w : toolWordsIn(std::string_view(text).substr(k)))
        if (w.station >= 1 && w.station <= io::kMaxStations && !toolList_.count(w.station)) toolList_[w.station] = line;
    }
  }

  void select(const gcode::Block& b, int station, int offset, double unitMm) {
    out_.order.push_back(station);
    StationUse& u = out_.uses[station];
    current_ = &u;
    currentStation_ = station;
    if (!u.firstLine) u.firstLine = b.line;
    if (offset > 0) u.offsets.insert(offset);
    if (u.comment) return;
    // The T block's comment, then comment lines just before it (up to 3; an
    // `N1 (OD ROUGH)` line is one, as Haas programs write them), then just after
    // it, then the tool list. (Lines of the program's own file: a subprogram
    // file's T block has only its own comment.)
    std::vector<std::string> texts = {std::string(b.comment())};
    std::vector<int> lines = {b.line};
    if (b.file == 0) {
      for (int l = b.line - 1; l >= b.line - 3 && !blockLine(l); --l) lines.push_back(l);
      for (int l = b.line + 1; l <= b.line + 2 && !blockLine(l); ++l) lines.push_back(l);
      if (auto listed = toolList_.find(station); listed != toolList_.end()) lines.push_back(listed->second);
      for (std::size_t k = 1; k < lines.size(); ++k) texts.push_back(rawComment(lines[k]));
    }
    // A radius any of them states (the tool list's "CNMG 432" as well as the T line's "R0.4").
    for (std::size_t k = 0; k < texts.size() && !u.noseRadiusMm; ++k) {
      const std::string text(commentForStation(texts[k], station));
      if (text.empty()) continue;
      if (const double r = classifyComment(text, unitMm).noseRadiusMm; r > 0.0) {
        u.noseRadiusMm = r;
        u.noseRadiusLine = lines[k];
      }
    }
    for (std::size_t k = 0; k < texts.size(); ++k) {
      const std::string text(commentForStation(texts[k], station));  // its part of "(T1 OD, T3 THREAD)"
      if (text.empty()) continue;
      const CommentTool c = classifyComment(text, unitMm);
      if (c.holdsBar) u.holdsBar = true;
      if (c.pullsBar) u.pullsBar = true;
      if (c.kind == ToolKind::Unknown) continue;
      Evidence e;
      e.kind = c.kind;
      e.reason = ToolReason::Comment;
      e.detail = text.size() > 60 ? text.substr(0, 60) : text;
      e.line = lines[k];
      e.strong = true;
      e.finishing = c.finishing;
      e.roughing = c.roughing;
      e.insert = c.insert;
      e.drillMm = c.drillMm;
      // "(FINISHING)" above T0202 and "(T02 = 35* FINISH TURNING TOOL ...)" in the tool
      // list: the insert comes from whichever comment of this station names it.
      if (e.insert.empty() && e.kind == ToolKind::Turning)
        for (const std::string& other : texts) {
          const CommentTool named = classifyComment(commentForStation(other, station), unitMm);
          if (!named.insert.empty() && (named.kind == ToolKind::Turning || named.kind == ToolKind::Unknown)) {
            e.insert = named.insert;
            break;
          }
        }
      u.comment = e;
      return;
    }
  }

  void note(ToolKind kind, ToolReason reason, std::string detail, int line, bool strong = true,
            bool finishing = false) {
    StationUse& u = *current_;
    std::optional<Evidence>& slot = strong ? u.cycle : u.turning;
    if (slot) return;  // the first of each kind is kept
    Evidence e;
    e.kind = kind;
    e.reason = reason;
    e.detail = std::move(detail);
    e.line = line;
    e.strong = strong;
    e.finishing = finishing;
    slot = std::move(e);
  }

  void drilling(double depth, const std::string& code, int line) {
    StationUse& u = *current_;
    if (depth < u.drillDepthMm || !u.drillLine) {
      u.drillDepthMm = std::min(depth, u.drillDepthMm);
      if (!u.drillLine) {
        u.drillLine = line;
        u.drillCode = code;
      }
    }
  }

  // What one executed block of the station shows: its cycle, or its feeds.
  template <typename M>
  void block(const gcode::Block& b, std::span<const M> moves, int station, int motionCode) {
    const bool feeds = std::any_of(moves.begin(), moves.end(), [](const M& m) { return isFeed(m); });
    if (!feeds) return;  // a rapid, a selection, the first block of a two-block cycle
    double deepestZ = 0.0, smallestX = 1e300;
    bool offCentre = false, threads = false;
    for (const M& m : moves) {
      if (!isFeed(m)) continue;
      const Ends p = endsOf(m, out_.beyondCentre);
      deepestZ = std::min({deepestZ, p.start.x(), p.end.x()});
      smallestX = std::min({smallestX, 2.0 * p.start.y(), 2.0 * p.end.y()});
      if (std::abs(p.start.y()) * 2.0 > kOnCentreMm || std::abs(p.end.y()) * 2.0 > kOnCentreMm) offCentre = true;
      threads = threads || m.kind == MoveKind::Thread;
    }
    const BlockCodes codes = codesOf(b, dialect_);
    using gcode::CodeAction;
    switch (codes.cycle) {
      case CodeAction::Thread:
      case CodeAction::BoxThreading:
      case CodeAction::ThreadCutting: {
        if (!threads) break;
        // Inside when its own comment says so ("G76 X36.2 Z-22. ... (ID THREAD)", "(INTERNAL)");
        // else the station's passes decide, once the run is read (tool_inference.cpp).
        const CommentTool said = classifyComment(b.comment());
        const bool inside = said.kind == ToolKind::ThreadingId || said.kind == ToolKind::Boring;
        note(inside ? ToolKind::ThreadingId : ToolKind::ThreadingOd,
             inside ? ToolReason::ThreadingInside : ToolReason::Threading, gText(codes.cycleNumber), b.line);
        return;
      }
      case CodeAction::Grooving:
        if (smallestX <= kOnCentreMm)
          note(ToolKind::Parting, ToolReason::Parting, gText(codes.cycleNumber) + " X0", b.line);
        else
          note(ToolKind::Grooving, ToolReason::Grooving, gText(codes.cycleNumber), b.line);
        return;
      case CodeAction::FacePecking:
        if (offCentre)
          note(ToolKind::Grooving, ToolReason::Grooving, gText(codes.cycleNumber), b.line);
        else
          drilling(deepestZ, gText(codes.cycleNumber), b.line);
        return;
      case CodeAction::Drilling:
      case CodeAction::SpotDrilling:
      case CodeAction::PeckDrilling: drilling(deepestZ, gText(codes.cycleNumber), b.line); return;
      case CodeAction::TurnRoughing:
      case CodeAction::FaceRoughing:
      case CodeAction::PatternRepeating: {
        // A negative finishing allowance leaves stock inside a bore (outside, for tools beyond the centre).
        const gcode::Word* allowance = b.find('U');
        const bool inward = allowance && allowance->expr < 0 && (allowance->value < 0.0) != out_.beyondCentre &&
                            allowance->value != 0.0;
        if (inward)
          note(ToolKind::Boring, ToolReason::Boring,
               fmt::format("{} U{}", gText(codes.cycleNumber), allowance->number.view()), b.line);
        else
          note(ToolKind::Turning, ToolReason::Turning, gText(codes.cycleNumber), b.line, false);
        return;
      }
      case CodeAction::Finishing:
      case CodeAction::BoxTurning:
      case CodeAction::BoxFacing:
        note(ToolKind::Turning, ToolReason::Turning, gText(codes.cycleNumber), b.line, false,
             codes.cycle == CodeAction::Finishing);
        return;
      default: break;
    }
    // Plain feeds (G01, G02, G03 and whatever a macro or a subprogram moves).
    for (const M& m : moves) {
      if (!isFeed(m)) continue;
      const Ends p = endsOf(m, out_.beyondCentre);
      const double dz = p.end.x() - p.start.x();
      const bool startOnCentre = 2.0 * std::abs(p.start.y()) <= kOnCentreMm;
      const bool endOnCentre = 2.0 * std::abs(p.end.y()) <= kOnCentreMm;
      if (startOnCentre && endOnCentre && dz < 0.0 && p.end.x() < 0.0) {
        drilling(p.end.x(), motionCode == 1 ? "G01 X0" : gText(motionCode), b.line);
        return;
      }
      if (m.kind == MoveKind::Line && 2.0 * p.end.y() <= kOnCentreMm && std::abs(dz) < 1e-3 &&
          p.end.x() < -kPartingBeyondMm && p.start.y() > p.end.y()) {
        Evidence e;
        e.kind = ToolKind::Parting;
        e.reason = ToolReason::Parting;
        const gcode::Word* xw = b.find('X');
        const gcode::Word* uw = b.find('U');
        e.detail = xw ? xw->text() : uw ? uw->text() : "X0";
        e.line = b.line;
        e.strong = true;
        out_.partings[station] = e;
        return;
      }
    }
    if (!current_->turning) note(ToolKind::Turning, ToolReason::Turning, gText(motionCode), b.line, false);
  }
};

}  // namespace

TextLines::TextLines(std::string_view text) : text_(text) {
  const std::size_t n = std::min<std::size_t>(text.size(), std::numeric_limits<std::uint32_t>::max());
  const bool lfOnly = std::memchr(text.data(), '\r', text.size()) == nullptr;
  starts_.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1);
  std::size_t start = 0;
  while (start < n) {
    starts_.push_back(static_cast<std::uint32_t>(start));
    if (lfOnly) {
      // (memchr from line end to line end: the usual case)
      const void* nl = std::memchr(text.data() + start, '\n', text.size() - start);
      if (!nl) break;
      start = static_cast<std::size_t>(static_cast<const char*>(nl) - text.data()) + 1;
      continue;
    }
    std::size_t i = text.find_first_of("\r\n", start);
    if (i == std::string_view::npos) break;
    if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;  // CRLF ends one line
    start = i + 1;
  }
}

std::string_view TextLines::operator[](std::size_t i) const {
  const std::string_view rest = text_.substr(starts_[i]);
  return rest.substr(0, rest.find_first_of("\r\n"));
}

std::string ProgramEvidence::blockText(int fileLine) const {
  const int i = fileLine - firstLine;
  if (i < 0 || i >= static_cast<int>(lines.size())) return {};
  const std::string_view line = lines[static_cast<std::size_t>(i)];
  std::string words(line.substr(0, line.find_first_of("(;")));
  while (!words.empty() && (words.back() == ' ' || words.back() == '\t' || words.back() == '\r')) words.pop_back();
  return words.size() > 40 ? words.substr(0, 40) : words;
}

ProgramEvidence gatherEvidence(const gcode::Program& program, std::string_view gcodeText, int gcodeFirstLine,
                               const Timeline& run, gcode::Dialect dialect, bool beyondCentre) {
  ProgramEvidence out;
  out.lines = TextLines(gcodeText);
  out.firstLine = gcodeFirstLine;
  out.beyondCentre = beyondCentre;
  Gatherer(program, out, dialect).gather(run);
  return out;
}

bool leftHandWork(const MotionUse& m) { return m.towardTail > 2.0 * m.towardChuck && m.towardTail >= 1.0; }
bool insideWork(const MotionUse& m) { return m.inside > m.outside && m.inside >= 1.0; }

}  // namespace klueng::core::machine::detail

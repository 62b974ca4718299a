// Fanuc 0i-TF lathe canned cycles expanded into simple moves (see cycles.h).
#include "machine/cycles.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace klueng::core::machine::cycles {

namespace {

using gcode::Block;
using gcode::Word;

constexpr double kEps = 1e-6;
constexpr double kArcTolerance = 0.01;  // mm, as the interpreter's arcs
constexpr double kMaxPasses = 10000;    // more passes than this is a typing slip, not a program

std::string num(double v) {
  if (std::abs(v) < 0.0005) v = 0.0;
  return fmt::format("{:.3f}", v);
}

double sign(double v) { return v > kEps ? 1.0 : v < -kEps ? -1.0 : 0.0; }

Step rapid(const Vec2& a, const Vec2& b) { return Step{StepKind::Rapid, Segment::line(a, b), 0.0, 0.0, {}, {}}; }
Step feedLine(const Vec2& a, const Vec2& b) { return Step{StepKind::Feed, Segment::line(a, b), 0.0, 0.0, {}, {}}; }
Step thread(const Vec2& a, const Vec2& b, double lead) {
  return Step{StepKind::Thread, Segment::line(a, b), lead, 0.0, {}, {}};
}

CycleAlarm alarmAt(const char* code, const Word* w, const Block& b, std::vector<std::string> args) {
  return CycleAlarm{code, w ? w->range : SourceRange{b.line, 1, 0}, std::move(args)};
}

// P/Q of G74-G76 without a decimal point are in the least input increment
// (0.001 mm, 0.0001 inch); with one they are lengths.
double increment(const Word& w, double unit) {
  if (w.hasDecimalPoint) return w.value * unit;
  return w.value * (unit > 1.0 ? 0.0001 * unit : 0.001);
}

bool hasAxis(const Block& b) { return b.has('X') || b.has('Z') || b.has('U') || b.has('W'); }

// Target of an X/Z/U/W block from `from`, as the interpreter's axisTarget.
Vec2 axisTarget(const Block& b, const Vec2& from, const Vec2& offset, double unit) {
  Vec2 p = from;
  if (const Word* w = b.find('X')) p.y() = w->value * unit / 2.0 + offset.y();
  if (const Word* w = b.find('U')) p.y() += w->value * unit / 2.0;
  if (const Word* w = b.find('Z')) p.x() = w->value * unit + offset.x();
  if (const Word* w = b.find('W')) p.x() += w->value * unit;
  return p;
}

// Mirror (z, x) -> (x, z): G72 and G75 are G71 and G74 with the axes swapped.
// A mirror reverses the sense of rotation.
Vec2 swapped(const Vec2& p) { return Vec2(p.y(), p.x()); }
Segment swapped(const Segment& s) {
  if (s.isArc()) return Segment::arc(swapped(s.start), swapped(s.end), swapped(s.centre), !s.ccw);
  return Segment::line(swapped(s.start), swapped(s.end));
}
void swapAll(std::vector<Step>& steps) {
  for (Step& s : steps) s.path = swapped(s.path);
}

// ---- the profile N(P)..N(Q) ----------------------------------------------------

int findSequence(const gcode::Program& p, int n, int from) {
  const int count = static_cast<int>(p.blocks.size());
  for (int pass = 0; pass < 2; ++pass)
    for (int i = pass == 0 ? from : 0; i < (pass == 0 ? count : from); ++i) {
      const Word* w = p.blocks[static_cast<std::size_t>(i)].find('N');
      if (w && w->code() == n) return i;
    }
  return -1;
}

std::optional<CycleAlarm> arcSegment(const Block& b, const Vec2& start, const Vec2& end, bool ccw, double unit,
                                     Segment& out) {
  if (const Word* rw = b.find('R')) {
    const double r = rw->value * unit;
    const double chord = (end - start).norm();
    if (chord < 1e-9) {
      out = Segment::line(start, end);
      return std::nullopt;
    }
    const double half = chord / 2.0;
    if (std::abs(r) < half - kArcTolerance) return alarmAt("A114", rw, b, {num(std::abs(r)), num(half)});
    const double d = std::sqrt(std::max(0.0, r * r - half * half));
    const Vec2 dir = (end - start) / chord;
    const Vec2 left(-dir.y(), dir.x());
    const double side = (ccw ? 1.0 : -1.0) * (r > 0 ? 1.0 : -1.0);
    out = Segment::arc(start, end, 0.5 * (start + end) + side * d * left, ccw);
    return std::nullopt;
  }
  const Word* iw = b.find('I');
  const Word* kw = b.find('K');
  const Vec2 centre = start + Vec2(kw ? kw->value * unit : 0.0, iw ? iw->value * unit : 0.0);
  const double r0 = (start - centre).norm(), r1 = (end - centre).norm();
  if (r0 < 1e-9 || std::abs(r0 - r1) > kArcTolerance)
    return alarmAt("A113", iw ? iw : kw, b, {num(r0), num(r1)});
  out = Segment::arc(start, end, centre, ccw);
  return std::nullopt;
}

struct Profile {
  std::vector<Step> moves;   // moves[0] starts at the cycle's start point
  std::vector<int> blockOf;  // program block index of each move
  int ns = -1, nf = -1;
};

// Reads N(P)..N(Q) from the cycle's start point. `withFeed`: F, G40-G42 inside
// apply (G70); roughing cycles ignore them (Fanuc).
std::optional<CycleAlarm> readProfile(const CycleInput& in, const Block& cycle, bool withFeed, Profile& out) {
  const Word* pw = cycle.find('P');
  const Word* qw = cycle.find('Q');
  const std::string gText = in.gWord ? std::string(1, in.gWord->letter) + in.gWord->number : "G7x";
  const char* g = gText.c_str();
  if (!pw || !qw) return alarmAt("A126", in.gWord, cycle, {g});
  out.ns = findSequence(*in.program, pw->code(), in.blockIndex + 1);
  if (out.ns < 0) return alarmAt("A120", pw, cycle, {g, "P", pw->number});
  out.nf = -1;
  for (int i = out.ns; i < static_cast<int>(in.program->blocks.size()); ++i) {
    const Word* w = in.program->blocks[static_cast<std::size_t>(i)].find('N');
    if (w && w->code() == qw->code()) {
      out.nf = i;
      break;
    }
  }
  if (out.nf < 0) return alarmAt("A120", qw, cycle, {g, "Q", qw->number});

  MotionMode motion = in.motion;
  Vec2 pos = in.start;
  Vec2 offset = in.offset;
  double pendingFeed = 0.0;  // F, S, T of the profile apply from the next move on (G70)
  const Word* pendingS = nullptr;
  const Word* pendingT = nullptr;
  for (int i = out.ns; i <= out.nf; ++i) {
    const Block& b = in.program->blocks[static_cast<std::size_t>(i)];
    if (b.blockSkip && in.blockSkip) continue;
    const Word* motionWord = nullptr;
    for (const Word& w : b.words) {
      if (w.letter != 'G' || w.hasDecimalPoint) continue;
      const int n = w.code();
      if (n == 0) motion = MotionMode::Rapid;
      else if (n == 1) motion = MotionMode::Line;
      else if (n == 2) motion = MotionMode::ArcCw;
      else if (n == 3) motion = MotionMode::ArcCcw;
      else if (withFeed && (n == 40 || n == 41 || n == 42)) {
        Step c;
        c.kind = StepKind::Compensation;
        c.comp = n == 41 ? NoseCompMode::Left : n == 42 ? NoseCompMode::Right : NoseCompMode::Off;
        c.path = Segment::line(pos, pos);
        out.moves.push_back(c);
        out.blockOf.push_back(i);
        continue;
      } else {
        continue;
      }
      motionWord = &w;
    }
    if (withFeed) {
      if (const Word* f = b.find('F')) pendingFeed = f->value * in.unit;
      if (const Word* sw = b.find('S')) pendingS = sw;
      if (const Word* tw = b.find('T')) {
        pendingT = tw;
        // The new offset counts from this block's own target on (as in the interpreter).
        const int number = tw->code() % 100;
        if (number == 0) offset = Vec2::Zero();
        else if (in.offsets && number <= io::kOffsetCount) {
          const io::Offset& o = in.offsets->at(number);
          offset = Vec2(o.z, o.x / 2.0);
        }
      }
    }
    if (!hasAxis(b)) continue;  // an F alone applies to the next move
    const Vec2 end = axisTarget(b, pos, offset, in.unit);
    Step s;
    s.feed = pendingFeed;
    s.sWord = pendingS;
    s.tWord = pendingT;
    pendingFeed = 0.0;
    pendingS = pendingT = nullptr;
    s.where = motionWord ? motionWord->range : b.words.front().range;
    switch (motion) {
      case MotionMode::Rapid: s.kind = StepKind::Rapid; s.path = Segment::line(pos, end); break;
      case MotionMode::Line:
      case MotionMode::Thread: s.kind = StepKind::Feed; s.path = Segment::line(pos, end); break;
      case MotionMode::ArcCw:
      case MotionMode::ArcCcw:
        s.kind = StepKind::Feed;
        if (auto a = arcSegment(b, pos, end, motion == MotionMode::ArcCcw, in.unit, s.path)) return a;
        break;
    }
    out.moves.push_back(s);
    out.blockOf.push_back(i);
    pos = end;
  }
  // Only moves count for the roughing cycles.
  std::size_t moves = 0;
  for (const Step& s : out.moves)
    if (s.kind != StepKind::Compensation) ++moves;
  if (moves < 2) return alarmAt("A125", pw, cycle, {g, pw->number, qw->number});
  return std::nullopt;
}

// Keeps only the moves (roughing cycles ignore G40-G42 inside the profile).
void movesOnly(Profile& p) {
  std::vector<Step> moves;
  std::vector<int> blocks;
  for (std::size_t i = 0; i < p.moves.size(); ++i)
    if (p.moves[i].kind != StepKind::Compensation) {
      moves.push_back(p.moves[i]);
      blocks.push_back(p.blockOf[i]);
    }
  p.moves = std::move(moves);
  p.blockOf = std::move(blocks);
}

// ---- G71 / G72 stock removal (in the frame where passes run along the first coordinate) --

// Points along a piece, for the monotony check of arcs.
std::vector<Vec2> samples(const Segment& s) {
  std::vector<Vec2> pts;
  const int n = s.isArc() ? 32 : 1;
  for (int i = 0; i <= n; ++i) pts.push_back(s.pointAt(static_cast<double>(i) / n));
  return pts;
}

// Where the depth line b = level, travelled along the pass direction, first
// meets the contour (a of the crossing); nullopt when the contour never reaches it.
std::optional<double> crossing(const std::vector<Step>& contour, double level, double sb) {
  for (const Step& s : contour) {
    const double b0 = s.path.start.y(), b1 = s.path.end.y();
    if ((level - b0) * sb < -kEps || (b1 - level) * sb < -kEps) continue;
    if (!s.path.isArc()) {
      if (std::abs(b1 - b0) < kEps) return s.path.start.x();
      const double t = (level - b0) / (b1 - b0);
      return s.path.start.x() + t * (s.path.end.x() - s.path.start.x());
    }
    // Arc: the point of the circle at b = level that lies on the swept part,
    // nearest to the arc's start along it.
    const Segment& a = s.path;
    const double r = a.radius();
    const double db = level - a.centre.y();
    if (std::abs(db) > r + kEps) continue;
    const double da = std::sqrt(std::max(0.0, r * r - db * db));
    const Vec2 rel0 = a.start - a.centre;
    const double phi0 = std::atan2(rel0.y(), rel0.x());
    double best = -1.0, bestA = 0.0;
    for (const double cand : {a.centre.x() - da, a.centre.x() + da}) {
      const double phi = std::atan2(db, cand - a.centre.x());
      double u = (a.ccw ? 1.0 : -1.0) * (phi - phi0);
      u = std::fmod(u, 2.0 * std::numbers::pi);
      if (u < 0) u += 2.0 * std::numbers::pi;
      if (u <= a.sweep() + 1e-9 && (best < 0 || u < best)) {
        best = u;
        bestA = cand;
      }
    }
    if (best >= 0) return bestA;
  }
  return std::nullopt;
}

std::optional<CycleAlarm> stockRemoval(const CycleInput& in, Profile& profile, double depth,
                                       double retract, const Vec2& allowance, bool swap, std::vector<Step>& out) {
  const std::string g = in.gWord ? "G" + in.gWord->number : "G71";
  movesOnly(profile);
  std::vector<Step> moves = profile.moves;
  Vec2 start = in.start;
  Vec2 shift = allowance;
  if (swap) {
    swapAll(moves);
    start = swapped(start);
    shift = swapped(shift);
  }
  // Type I: the first profile block moves only across the passes (X for G71).
  const Step& first = moves.front();
  const Block& nsBlock = in.program->blocks[static_cast<std::size_t>(profile.blockOf.front())];
  if (std::abs(first.path.end.x() - first.path.start.x()) > kEps)
    return alarmAt("A124", nsBlock.words.empty() ? nullptr : &nsBlock.words.front(), nsBlock,
                   {g, swap ? "Z" : "X"});
  const Vec2 aPrime = first.path.end;
  std::vector<Step> contour(moves.begin() + 1, moves.end());
  const double sb = sign(start.y() - aPrime.y());           // towards the stock
  const double sa = sign(contour.back().path.end.x() - aPrime.x());  // along the passes
  // The profile must move steadily away from A' in both axes.
  for (std::size_t i = 0; i < contour.size(); ++i) {
    const auto pts = samples(contour[i].path);
    bool ok = sa != 0.0 && sb != 0.0;
    for (std::size_t j = 1; ok && j < pts.size(); ++j)
      ok = (pts[j].y() - pts[j - 1].y()) * sb >= -1e-4 && (pts[j].x() - pts[j - 1].x()) * sa >= -1e-4;
    if (!ok) {
      const Block& b = in.program->blocks[static_cast<std::size_t>(profile.blockOf[i + 1])];
      return alarmAt("A121", b.words.empty() ? nullptr : &b.words.front(), b, {g, std::to_string(b.line)});
    }
  }
  std::vector<Step> shifted;
  for (const Step& s : contour) {
    Step t = s;
    t.path = s.path.translated(shift);
    shifted.push_back(t);
  }
  const Vec2 aShift = aPrime + shift;
  if (std::abs(start.y() - aShift.y()) / depth > kMaxPasses) {
    const std::string passes = fmt::format("{:.0f}", std::ceil(std::abs(start.y() - aShift.y()) / depth));
    return CycleAlarm{"A127", in.gWord ? in.gWord->range : SourceRange{}, {g, passes, num(depth)}};
  }
  const bool infeedRapid = first.kind == StepKind::Rapid;
  std::vector<Step> steps;
  Vec2 pos = start;
  for (int k = 1;; ++k) {
    const double level = start.y() - sb * k * depth;
    if ((level - aShift.y()) * sb <= kEps) break;
    const Vec2 in0(start.x(), level);
    steps.push_back(infeedRapid ? rapid(pos, in0) : feedLine(pos, in0));
    const double aEnd = crossing(shifted, level, sb).value_or(shifted.back().path.end.x());
    pos = in0;
    if ((aEnd - start.x()) * sa > kEps) {
      const Vec2 cutEnd(aEnd, level);
      steps.push_back(feedLine(pos, cutEnd));
      pos = cutEnd;
    }
    // 45-degree retract by e, then back to the start along the passes.
    const Vec2 away(pos.x() - sa * retract, level + sb * retract);
    steps.push_back(rapid(pos, away));
    steps.push_back(rapid(away, Vec2(start.x(), away.y())));
    pos = Vec2(start.x(), away.y());
  }
  // The last pass follows the profile offset by the finishing allowance.
  steps.push_back(infeedRapid ? rapid(pos, aShift) : feedLine(pos, aShift));
  for (const Step& s : shifted) steps.push_back(s);
  steps.push_back(rapid(shifted.back().path.end, start));
  for (Step& s : steps) s.feed = 0.0, s.where = {};
  if (swap) swapAll(steps);
  out = std::move(steps);
  return std::nullopt;
}

// ---- G74 / G75 peck cycles (frame: pecks along the first coordinate) ------------

std::vector<Step> pecks(const Vec2& start, const Vec2& target, double peck, double shiftStep, double retract) {
  std::vector<Step> steps;
  const double sa = sign(target.x() - start.x());
  const double sb = sign(target.y() - start.y());
  const double depth = std::abs(target.x() - start.x());
  const double across = std::abs(target.y() - start.y());
  Vec2 pos = start;
  double b = start.y();
  for (;;) {
    if (std::abs(b - pos.y()) > kEps) {
      steps.push_back(rapid(pos, Vec2(pos.x(), b)));
      pos = Vec2(pos.x(), b);
    }
    if (sa != 0.0) {
      double done = 0.0;
      for (;;) {
        done = peck > kEps ? std::min(depth, done + peck) : depth;
        const Vec2 bottom(start.x() + sa * done, b);
        steps.push_back(feedLine(pos, bottom));
        pos = bottom;
        if (done >= depth - kEps) break;
        const Vec2 back(bottom.x() - sa * retract, b);
        steps.push_back(rapid(pos, back));
        pos = back;
      }
      steps.push_back(rapid(pos, Vec2(start.x(), b)));
      pos = Vec2(start.x(), b);
    }
    const double moved = std::abs(b - start.y());
    if (sb == 0.0 || moved >= across - kEps) break;
    b = shiftStep > kEps ? start.y() + sb * std::min(across, moved + shiftStep) : target.y();
  }
  if ((pos - start).norm() > kEps) steps.push_back(rapid(pos, start));
  return steps;
}

std::string gName(const CycleInput& in, int g) { return in.gWord ? "G" + in.gWord->number : fmt::format("G{}", g); }

}  // namespace

std::vector<double> threadDepths(double k, double d1, double dmin, double d, int m) {
  std::vector<double> depths;
  const double rough = k - d;
  double prev = 0.0;
  for (int n = 1; rough > kEps && prev < rough - kEps; ++n) {
    double next = d1 * std::sqrt(static_cast<double>(n));
    if (next - prev < dmin) next = prev + dmin;
    next = std::min(next, rough);
    depths.push_back(next);
    prev = next;
    if (n > 10000) break;  // d1 and dmin both ~0 are refused before; a safety net
  }
  for (int i = 0; i < std::max(1, m); ++i) depths.push_back(k);
  return depths;
}

std::vector<Step> singleCycle(int g, const Vec2& start, const Vec2& target, double taper, double lead) {
  std::vector<Step> s;
  if (g == 94) {
    // Rapid in Z to the face (taper: Z at the start of the cut), face to X, back along Z, rapid out.
    const Vec2 p1(target.x() + taper, start.y());
    const Vec2 p3(start.x(), target.y());
    s.push_back(rapid(start, p1));
    s.push_back(feedLine(p1, target));
    s.push_back(feedLine(target, p3));
    s.push_back(rapid(p3, start));
    return s;
  }
  const Vec2 p1(start.x(), target.y() + taper);
  const Vec2 p3(target.x(), start.y());
  s.push_back(rapid(start, p1));
  if (g == 92) {
    s.push_back(thread(p1, target, lead));
    s.push_back(rapid(target, p3));
  } else {
    s.push_back(feedLine(p1, target));
    s.push_back(feedLine(target, p3));
  }
  s.push_back(rapid(p3, start));
  return s;
}

Expansion expand(int g, const CycleInput& in, CycleMemory& memory) {
  Expansion e;
  const Block& b = in.program->blocks[static_cast<std::size_t>(in.blockIndex)];
  const double u = in.unit;
  const std::string name = gName(in, g);
  const bool secondBlock = (g >= 70 && g <= 73) ? (b.has('P') || b.has('Q')) : hasAxis(b);
  auto value = [&](char letter, double fallback) {
    const Word* w = b.find(letter);
    return w ? w->value * u : fallback;
  };

  if (!secondBlock) {
    switch (g) {
      case 71:
      case 72: {
        const char depthLetter = g == 71 ? 'U' : 'W';
        const Word* dw = b.find(depthLetter);
        if (!dw || dw->value <= 0.0)
          e.alarm = alarmAt("A122", dw ? dw : in.gWord, b, {name, std::string(1, depthLetter)});
        else if (g == 71) memory.g71Depth = dw->value * u, memory.g71Retract = value('R', memory.g71Retract);
        else memory.g72Depth = dw->value * u, memory.g72Retract = value('R', memory.g72Retract);
        break;
      }
      case 73:
        memory.g73ReliefX = value('U', memory.g73ReliefX);
        memory.g73ReliefZ = value('W', memory.g73ReliefZ);
        if (const Word* r = b.find('R')) memory.g73Count = static_cast<int>(std::lround(r->value));
        break;
      case 74: memory.g74Retract = value('R', memory.g74Retract); break;
      case 75: memory.g75Retract = value('R', memory.g75Retract); break;
      case 76:
        if (const Word* p = b.find('P')) {
          const int mra = p->code();
          memory.g76Finishing = mra / 10000;
          memory.g76Chamfer = (mra / 100) % 100;
          memory.g76Angle = mra % 100;
        }
        if (const Word* q = b.find('Q')) memory.g76MinDepth = increment(*q, u);
        memory.g76Allowance = value('R', memory.g76Allowance);
        break;
      case 70:
        e.alarm = alarmAt("A126", in.gWord, b, {name});
        break;
      default: break;
    }
    return e;
  }

  switch (g) {
    case 70: {
      Profile p;
      if (auto a = readProfile(in, b, true, p)) {
        e.alarm = a;
        return e;
      }
      e.steps = p.moves;
      Vec2 end = in.start;
      for (const Step& s : p.moves)
        if (s.kind != StepKind::Compensation) end = s.path.end;
      e.steps.push_back(rapid(end, in.start));
      return e;
    }
    case 71:
    case 72: {
      const double depth = g == 71 ? memory.g71Depth : memory.g72Depth;
      if (depth <= 0.0) {
        e.alarm = alarmAt("A122", in.gWord, b, {name, g == 71 ? "U" : "W"});
        return e;
      }
      Profile p;
      if (auto a = readProfile(in, b, false, p)) {
        e.alarm = a;
        return e;
      }
      const Vec2 allowance(value('W', 0.0), value('U', 0.0) / 2.0);
      if (auto a = stockRemoval(in, p, depth, g == 71 ? memory.g71Retract : memory.g72Retract, allowance,
                                g == 72, e.steps)) {
        e.alarm = a;
        return e;
      }
      if (p.ns > in.blockIndex) e.resumeAfter = p.nf;
      return e;
    }
    case 73: {
      if (memory.g73Count > kMaxPasses) {
        e.alarm = alarmAt("A127", in.gWord, b, {name, std::to_string(memory.g73Count), "R"});
        return e;
      }
      if (memory.g73Count < 1) {
        e.alarm = alarmAt("A122", in.gWord, b, {name, "R"});
        return e;
      }
      Profile p;
      if (auto a = readProfile(in, b, false, p)) {
        e.alarm = a;
        return e;
      }
      movesOnly(p);
      const Vec2 allowance(value('W', 0.0), value('U', 0.0) / 2.0);
      const Vec2 relief(memory.g73ReliefZ, memory.g73ReliefX);
      const int d = memory.g73Count;
      Vec2 pos = in.start;
      for (int j = 0; j < d; ++j) {
        // Pass j: the profile moved by the allowance plus the part of the relief still left.
        const double frac = d > 1 ? static_cast<double>(d - 1 - j) / (d - 1) : 0.0;
        const Vec2 shift = allowance + frac * relief;
        const Step& first = p.moves.front();
        const Vec2 a1 = first.path.end + shift;
        e.steps.push_back(first.kind == StepKind::Rapid ? rapid(pos, a1) : feedLine(pos, a1));
        for (std::size_t i = 1; i < p.moves.size(); ++i) {
          Step s = p.moves[i];
          s.path = s.path.translated(shift);
          s.feed = 0.0;
          s.where = {};
          e.steps.push_back(s);
        }
        pos = p.moves.back().path.end + shift;
        e.steps.push_back(rapid(pos, in.start));
        pos = in.start;
      }
      if (p.ns > in.blockIndex) e.resumeAfter = p.nf;
      return e;
    }
    case 74:
    case 75: {
      const Vec2 target = axisTarget(b, in.start, in.offset, u);
      const Word* pw = b.find('P');
      const Word* qw = b.find('Q');
      const double across = pw ? increment(*pw, u) : 0.0;  // Δi: X step (G74) or X peck (G75)
      const double along = qw ? increment(*qw, u) : 0.0;   // Δk: Z peck (G74) or Z step (G75)
      const double drill = std::abs(g == 74 ? zOf(target) - zOf(in.start) : xOf(target) - xOf(in.start));
      const double peck = g == 74 ? along : across;
      if (peck > kEps && drill / peck > kMaxPasses) {
        e.alarm = alarmAt("A127", g == 74 ? qw : pw, b,
                          {name, fmt::format("{:.0f}", std::ceil(drill / peck)), num(peck)});
        return e;
      }
      if (g == 74) {
        e.steps = pecks(in.start, target, along, across, memory.g74Retract);
      } else {
        e.steps = pecks(swapped(in.start), swapped(target), across, along, memory.g75Retract);
        swapAll(e.steps);
      }
      return e;
    }
    case 76: {
      const Vec2 target = axisTarget(b, in.start, in.offset, u);
      const Word* pw = b.find('P');
      const Word* qw = b.find('Q');
      const double height = pw ? increment(*pw, u) : 0.0;
      const double first = qw ? increment(*qw, u) : 0.0;
      if (height <= 0.0) {
        e.alarm = alarmAt("A122", pw ? pw : in.gWord, b, {name, "P"});
        return e;
      }
      if (first <= 0.0 && memory.g76MinDepth <= 0.0) {
        e.alarm = alarmAt("A122", qw ? qw : in.gWord, b, {name, "Q"});
        return e;
      }
      const double taper = value('R', 0.0);  // R(i): radius difference, start minus end
      const double sx = sign(in.start.y() - target.y());  // towards the crest (outside: +1)
      const double sz = sign(target.x() - in.start.x());
      const double flank = std::tan(memory.g76Angle / 2.0 * std::numbers::pi / 180.0);
      const auto depths = threadDepths(height, first, memory.g76MinDepth, memory.g76Allowance,
                                       memory.g76Finishing);
      const Vec2& a = in.start;
      for (const double depth : depths) {
        // One-flank infeed: each pass starts depth·tan(a/2) further along the thread.
        const double xPass = target.y() + sx * (height - depth);
        const Vec2 s0(a.x() + sz * depth * flank, a.y());
        const Vec2 s1(s0.x(), xPass + taper);
        const Vec2 s2(target.x(), xPass);
        const Vec2 s3(target.x(), a.y());
        if ((s0 - a).norm() > kEps) e.steps.push_back(rapid(a, s0));
        e.steps.push_back(rapid(s0, s1));
        const double length = std::abs(s2.x() - s1.x());
        const double chamfer = std::min(memory.g76Chamfer / 10.0 * in.feed, length);
        if (chamfer > kEps) {
          // Pull-out at 45 degrees over the last r/10 leads, still threading.
          const Vec2 c0 = s1 + (s2 - s1) * ((length - chamfer) / length);
          const Vec2 c1(target.x(), c0.y() + sx * chamfer);
          e.steps.push_back(thread(s1, c0, in.feed));
          e.steps.push_back(thread(c0, c1, in.feed));
          e.steps.push_back(rapid(c1, s3));
        } else {
          e.steps.push_back(thread(s1, s2, in.feed));
          e.steps.push_back(rapid(s2, s3));
        }
        e.steps.push_back(rapid(s3, a));
      }
      return e;
    }
    default: break;
  }
  return e;
}

}  // namespace klueng::core::machine::cycles
